//! The command-line contract of DESIGN.md, checked in-process for every chapter:
//! `list`, `all --quick --json`, `render --check`, exit codes, and one clear stderr line
//! for bad global input. Chapter-specific flags are tested in each chapter's own file.

use common::{assert_bad_input, run};
use locomotion_workbook::chapters::{ChapterInfo, CHAPTERS};
use locomotion_workbook::cli::WIDTH;
use locomotion_workbook::flags::Flag;
use serde_json::Value;

use crate::common;

const CONTRACT_KEYS: [&str; 7] = [
    "chapter", "title", "section", "params", "claims", "results", "figures",
];
const CLAIM_KEYS: [&str; 8] = [
    "id",
    "section",
    "statement",
    "expected",
    "computed",
    "tolerance",
    "verdict",
    "check",
];

fn assert_contract(report: &Value) {
    let keys: Vec<&str> = report
        .as_object()
        .expect("object")
        .keys()
        .map(String::as_str)
        .collect();
    assert_eq!(keys, CONTRACT_KEYS, "report keys");
    for c in report["claims"].as_array().expect("claims array") {
        let ck: Vec<&str> = c.as_object().unwrap().keys().map(String::as_str).collect();
        assert_eq!(ck, CLAIM_KEYS, "claim keys");
        let v = c["verdict"].as_str().unwrap();
        assert!(
            ["confirmed", "erratum", "approximation", "failed"].contains(&v),
            "{v}"
        );
        let k = c["check"].as_str().unwrap();
        assert!(
            locomotion_workbook::report::Check::ALL
                .iter()
                .any(|x| x.as_str() == k),
            "{k}"
        );
    }
    assert!(
        report["params"].is_object()
            && report["results"].is_object()
            && report["figures"].is_array()
    );
}

#[test]
fn list_names_every_chapter_once() {
    let (code, out, err) = run(&["list"]);
    assert_eq!(code, 0);
    assert!(err.is_empty());
    assert_eq!(out.lines().count(), CHAPTERS.len());
    for c in CHAPTERS.iter() {
        assert_eq!(
            out.lines()
                .filter(|l| l.starts_with(&format!("{} ", c.id)))
                .count(),
            1,
            "{}",
            c.id
        );
    }
    let (code, out, _) = run(&["list", "--json"]);
    assert_eq!(code, 0);
    let v: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v.as_array().unwrap().len(), CHAPTERS.len());
}

#[test]
fn all_quick_json_is_one_array_of_contract_objects_and_no_claim_fails() {
    let (code, out, err) = run(&["all", "--quick", "--json", "--no-figures"]);
    assert!(err.is_empty(), "stderr: {err}");
    let v: Value = serde_json::from_str(out.trim()).expect("stdout is exactly one JSON value");
    let arr = v.as_array().expect("array");
    assert_eq!(arr.len(), CHAPTERS.len());
    for (r, c) in arr.iter().zip(CHAPTERS.iter()) {
        assert_contract(r);
        assert_eq!(r["chapter"], c.id);
        let failed: Vec<&Value> = r["claims"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|c| c["verdict"] == "failed")
            .collect();
        assert!(failed.is_empty(), "{}: failed claims {failed:?}", c.id);
    }
    assert!(
        !out.contains("NaN") && !out.contains("null"),
        "no NaN or null in output"
    );
    assert_eq!(code, 0);
}

#[test]
fn each_chapter_prints_one_json_object_in_quick_mode() {
    for c in CHAPTERS.iter() {
        let (code, out, err) = run(&[c.id, "--quick", "--json", "--no-figures"]);
        assert_eq!(code, 0, "{}: {err}", c.id);
        let v: Value = serde_json::from_str(out.trim()).expect("one JSON object");
        assert_contract(&v);
        assert_eq!(v["chapter"], c.id);
    }
}

/// The widest line of `text`, in characters, and the line.
fn widest(text: &str) -> (usize, String) {
    text.lines()
        .map(|l| (l.chars().count(), l.to_string()))
        .max()
        .unwrap_or_default()
}

#[test]
fn a_chapter_run_leads_with_the_physics_and_the_claim_table_is_one_flag_away() {
    let (code, out, _) = run(&["effective-mass", "--quick", "--no-figures"]);
    assert_eq!(code, 0);
    let first: Vec<&str> = out.lines().take(12).collect();
    assert!(first[0].starts_with("2. Effective mass"), "{out}");
    // the question, then the answer with its numbers (J_l/J_v of both sticks at 45 deg)
    let answer = first
        .iter()
        .position(|l| l.contains("Answer:"))
        .expect("an answer");
    assert!(first.iter().position(|l| l.contains("Question:")) < Some(answer));
    let said = first[answer..].join(" ");
    assert!(
        said.contains("0.6 for a uniform rod") && said.contains("1 for a point mass"),
        "{said}"
    );
    assert!(
        first
            .iter()
            .any(|l| l.contains("Verdicts: 17 claims: 13 confirmed")),
        "{out}"
    );
    assert!(
        first
            .iter()
            .any(|l| l.contains("chapters/02-effective-mass.md")),
        "{out}"
    );
    assert!(
        !out.contains("expected") && !out.contains("summary: "),
        "no claim table:\n{out}"
    );
    assert!(widest(&out).0 <= WIDTH, "{:?}", widest(&out));
    // --claims: the same lead, then the full table ending in its summary line
    let (code, full, _) = run(&["effective-mass", "--quick", "--no-figures", "--claims"]);
    assert_eq!(code, 0);
    assert!(
        full.starts_with(&out[..out.find("\n\n").unwrap()]),
        "{full}"
    );
    assert!(
        full.contains("verdict") && full.contains("tolerance"),
        "{full}"
    );
    assert!(full.lines().last().unwrap().starts_with("summary: "));
    // and --claims means nothing beside --json (the JSON contract is unchanged)
    assert_eq!(run(&["effective-mass", "--json", "--claims"]).0, 2);
}

/// `all` on the terminal: every chapter's question, answer, errata and verdicts in lines
/// of at most 100 columns; the first screen (40 lines) holds chapter 1 and 2 whole; the
/// walking stick's answer gives its speed, its step and its gait.
#[test]
fn all_teaches_first_in_lines_that_fit_a_terminal() {
    let (code, out, err) = run(&["all", "--quick", "--no-figures"]);
    assert_eq!(code, 0, "{err}");
    assert!(widest(&out).0 <= WIDTH, "{:?}", widest(&out));
    assert!(out.len() < 12_000, "{} bytes", out.len());
    let screen: Vec<&str> = out.lines().take(40).collect();
    for n in ["1. What counts", "2. Effective mass"] {
        assert!(
            screen.iter().any(|l| l.starts_with(n)),
            "{n}:\n{}",
            screen.join("\n")
        );
    }
    for label in ["Question:", "Answer:", "Errata:", "Verdicts:", "More:"] {
        let per_chapter = format!("\n   {label}");
        assert_eq!(
            out.matches(&per_chapter).count(),
            CHAPTERS.len(),
            "{label}:\n{out}"
        );
    }
    // a block's words, line breaks and indents as single spaces
    let flat = |b: &str| b.split_whitespace().collect::<Vec<_>>().join(" ");
    let stick = out
        .split("\n\n")
        .find(|b| b.starts_with("6. "))
        .expect("the stick chapter");
    for word in [
        "the stick walks at 0.2",
        "mm per drive cycle",
        "limit cycle, stable",
        "statements are wrong",
    ] {
        assert!(flat(stick).contains(word), "{word}:\n{stick}");
    }
    let inertia = out
        .split("\n\n")
        .find(|b| b.starts_with("8. "))
        .expect("chapter 8");
    assert!(
        flat(inertia).contains("the massless model at 0.2"),
        "{inertia}"
    );
    assert!(out.contains("All chapters: "), "{out}");
    assert!(
        out.contains("workbook lab") && out.contains("--claims"),
        "{out}"
    );
    assert!(
        !out.contains("tolerance"),
        "no claim table without --claims"
    );
}

/// Each chapter alone also fits 100 columns (its parameters wrapped, its results clipped).
#[test]
fn every_chapter_run_fits_a_terminal() {
    for c in CHAPTERS.iter() {
        let (code, out, err) = run(&[c.id, "--quick", "--no-figures"]);
        assert_eq!(code, 0, "{}: {err}", c.id);
        assert!(
            out.starts_with(&format!("{}. {}", c.number, c.title)),
            "{out}"
        );
        assert!(widest(&out).0 <= WIDTH, "{}: {:?}", c.id, widest(&out));
    }
}

#[test]
fn unknown_chapter_is_bad_input() {
    let (code, out, err) = run(&["no-such-chapter"]);
    assert_eq!(code, 2);
    assert!(out.is_empty());
    assert_eq!(err.trim_end().lines().count(), 1, "one line: {err}");
    assert!(err.contains("no-such-chapter"), "{err}");
}

#[test]
fn bad_gravity_is_rejected_with_one_line_naming_the_flag() {
    for bad in ["NaN", "-9.81", "0", "inf", "abc"] {
        assert_bad_input(
            &["effective-mass", "--g-mps2", bad, "--no-figures"],
            "--g-mps2",
        );
    }
}

#[test]
fn help_teaches_and_exits_zero() {
    let (code, out, _) = run(&["--help"]);
    assert_eq!(code, 0);
    for c in CHAPTERS.iter() {
        assert!(out.contains(c.id), "{} in help", c.id);
    }
    assert!(out.contains("--g-mps2") && out.contains("Exit codes"));
    for c in CHAPTERS.iter() {
        let (code, out, _) = run(&[c.id, "--help"]);
        assert_eq!(code, 0, "{}", c.id);
        assert!(
            out.contains("--quick") && out.contains("--json"),
            "{}",
            c.id
        );
    }
}

#[test]
fn course_text_tables_are_up_to_date() {
    // `workbook render --check` regenerates every table from the chapters (full mode, no
    // figures) and compares: a stale table in chapters/*.md fails here.
    let (code, out, err) = run(&["render", "--check"]);
    assert_eq!(code, 0, "stale course text:\n{out}{err}");
}

/// Runs `workbook <args>` and asserts exit 0, no failed claim, no NaN/null on stdout.
fn assert_runs_clean(args: &[&str]) {
    let mut full = args.to_vec();
    full.extend(["--quick", "--json", "--no-figures"]);
    let (code, out, err) = run(&full);
    assert_clean(&full, code, &out, &err);
}

/// The checks of [`assert_runs_clean`] on a finished run `full`.
fn assert_clean(full: &[&str], code: i32, out: &str, err: &str) {
    assert_eq!(code, 0, "{full:?}: {err}");
    // notes for the reader (a start that was not the one asked for, a fallback taken)
    // are the one thing stderr may carry, as in tests/fuzz.rs
    assert!(
        err.lines().all(|l| l.starts_with("note: ")),
        "{full:?}: stderr {err}"
    );
    let v: Value = serde_json::from_str(out.trim()).expect("one JSON object");
    assert!(
        !out.contains("null") && !out.contains("non-finite"),
        "{full:?}"
    );
    let failed: Vec<&Value> = v["claims"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|c| c["verdict"] == "failed")
        .collect();
    assert!(failed.is_empty(), "{full:?}: {failed:?}");
}

/// A value just inside an end of `f`'s range: the end itself where it is closed, else
/// one millionth of the range's scale inside.
fn inside_end(f: &Flag, high: bool) -> f64 {
    let r = f.range;
    let (end, open, inward) = if high {
        (r.hi, r.hi_open, -1.0)
    } else {
        (r.lo, r.lo_open, 1.0)
    };
    if open {
        end + inward * 1e-6 * end.abs().max((r.hi - r.lo).abs().min(1.0))
    } else {
        end
    }
}

/// The corners of a chapter's flag table: every entry that is neither coupled nor
/// budgeted at its low end, then all at their high ends (coupled and budgeted entries
/// keep their defaults: their ranges hold at the defaults, and the work at a corner is
/// a quick run's). A pair entry (`X,Y`) gets the end in both parts, of both signs.
fn table_corners(c: &ChapterInfo) -> Vec<Vec<String>> {
    [false, true]
        .iter()
        .map(|&high| {
            let mut argv = vec![c.id.to_string()];
            for f in c.flags.iter().filter(|f| !f.coupled && !f.budgeted) {
                let v = inside_end(f, high);
                let text = if f.range_text().starts_with("X,Y") {
                    format!("{v},{}", -v)
                } else {
                    v.to_string()
                };
                argv.push(format!("{}={text}", f.name));
            }
            argv
        })
        .collect()
}

/// Every chapter at the corners of its flag table ([`table_corners`], generated: a new
/// chapter or flag is covered without a line here): exit 0, no failed claim, no NaN; or,
/// where the corner leaves the range that a coupled check (`Flag::check_coupled`) gives
/// the values together, that check's one line (exit 2). The couplings' own corners are
/// the hand-picked ones below.
#[test]
fn every_chapter_holds_at_the_corners_of_its_flag_table() {
    let (mut ran, mut refused) = (0, Vec::new());
    for c in CHAPTERS {
        for argv in table_corners(c) {
            let mut full: Vec<&str> = argv.iter().map(String::as_str).collect();
            full.extend(["--quick", "--json", "--no-figures"]);
            let (code, out, err) = run(&full);
            if code == 2 {
                // only a coupled check refuses a point inside every range: its line
                // names a flag of the table with a range that is not the entry's own
                let named: Vec<&Flag> = c
                    .flags
                    .iter()
                    .filter(|f| err.contains(&format!(" for {}: valid range is ", f.name)))
                    .collect();
                assert!(
                    named.len() == 1
                        && !err.contains(&format!("is {} (", named[0].range_text()))
                        && err.trim_end().lines().count() == 1,
                    "{full:?}: {err}"
                );
                refused.push(format!("{full:?}: {err}"));
                continue;
            }
            assert_clean(&full, code, &out, &err);
            ran += 1;
        }
    }
    // most corners run (a refused one is listed on failure)
    assert!(
        ran >= CHAPTERS.len() + 2,
        "{ran} corners ran; refused:\n{}",
        refused.join("")
    );
}

/// Each chapter at the hand-picked corners the table's own corners do not reach (mixed
/// ends where a coupled check joins the flags, the coupled flags at their ends, and
/// special points): exit 0, no failed claim, no NaN. With the table's corners
/// (`every_chapter_holds_at_the_corners_of_its_flag_table`) this is what makes the
/// accepted ranges validated ranges.
#[test]
fn every_chapter_holds_at_the_corners_of_its_ranges() {
    const CORNERS: &[&str] = &[
        "locomotion-definition --object-velocity=1e-100,1e100 --medium-velocity=-1e100,0 --medium-velocity=1e-100,-1e-100",
        "effective-mass --mu 1e-308 --angle-deg 1e-308",
        "effective-mass --mu 0.75 --angle-deg 63.43494882",
        // Gamma_x just above 2e-3, and Gamma_x omega just below 1e6 1/s
        "horizontal-shaking --amplitude-m 7.6e-6",
        "horizontal-shaking --amplitude-m 1.4e-5 --frequency-hz 1000",
        "horizontal-shaking --amplitude-m 10 --frequency-hz 0.01 --mu 0.01 --g-mps2 1 --bias 0.999999",
        "horizontal-shaking --amplitude-m 1e-6 --frequency-hz 1000 --mu 1.999 --g-mps2 25 --bias 0",
        "vertical-shaking --gamma 1.000001 --frequency-hz 1000 --mu 1.999 --bias 0.999999 --g-mps2 25",
        "vertical-shaking --gamma 100 --frequency-hz 0.1 --mu 0.01 --bias 0 --g-mps2 1",
        "asymmetric-shaking --slow-velocity-mps 1e-4 --fast-velocity-mps 0.1 --slow-duration-s 10 --mu 10 --g-mps2 25",
        "asymmetric-shaking --slow-velocity-mps 10 --fast-velocity-mps 20 --slow-duration-s 1e-4 --mu 10 --g-mps2 25 --viscous-c 1000",
        "asymmetric-shaking --slow-velocity-mps 1e-4 --fast-velocity-mps 3e-4 --slow-duration-s 1e-4 --mu 1e-3 --g-mps2 1 --viscous-c 1000",
        "stick-state-machine --length-m 0.015 --mass-kg 0.1 --stiffness 0 --damping 0 --mu 0 --theta0-rad -1.5707 --gamma 0 --frequency-hz 1 --g-mps2 1 --rtol 1e-14",
        "stick-state-machine --length-m 1.5 --mass-kg 10 --stiffness 100 --damping 0.1 --mu 2 --theta0-rad 1.5707 --gamma 50 --frequency-hz 1000 --g-mps2 25 --rtol 1e-2 --duration-s 0.47",
        "stick-state-machine --scene authors --length-m 0.015 --mass-kg 10 --stiffness 100 --mu 2 --theta0-rad 1e-308 --gamma 50 --frequency-hz 1 --g-mps2 25",
        "stick-state-machine --scene authors --duration-s 79",
        "stick-state-machine --duration-s 264",
        "speed-vs-accuracy --frequency-hz 1 --gamma 1.5001 --mu 0.01 --bias 0.3 --restitution 1e-6 --g-mps2 1",
        "speed-vs-accuracy --frequency-hz 100 --gamma 49.999 --mu 1.999 --bias 0.99 --restitution 0.8 --g-mps2 25",
    ];
    for c in CORNERS {
        assert_runs_clean(&c.split_whitespace().collect::<Vec<_>>());
    }
}

/// The cases, each refused with one line naming the flag the user typed.
#[test]
fn out_of_range_inputs_name_the_flag_the_user_typed() {
    const CASES: &[(&str, &str)] = &[
        ("stick-state-machine --g-mps2 1e6", "--g-mps2"),
        ("stick-state-machine --g-mps2 94", "--g-mps2"),
        ("speed-vs-accuracy --g-mps2 1e-20", "--g-mps2"),
        ("speed-vs-accuracy --g-mps2 0.5", "--g-mps2"),
        ("horizontal-shaking --frequency-hz 1e-308", "--frequency-hz"),
        ("vertical-shaking --frequency-hz 1e-308", "--frequency-hz"),
        ("speed-vs-accuracy --frequency-hz 1e-308", "--frequency-hz"),
        ("speed-vs-accuracy --bias 1e-4", "--bias"),
        ("horizontal-shaking --amplitude-m 1e-308", "--amplitude-m"),
        ("horizontal-shaking --amplitude-m 1e6", "--amplitude-m"),
        ("horizontal-shaking --mu 1e-308", "--mu"),
        // derived Gamma_x: blamed on the flag that was set
        ("horizontal-shaking --amplitude-m 1e-6", "--amplitude-m"),
        ("horizontal-shaking --frequency-hz 1000", "--frequency-hz"),
        (
            "horizontal-shaking --g-mps2 25 --amplitude-m 1e-5",
            "--amplitude-m",
        ),
        ("vertical-shaking --gamma 1.0000000001", "--gamma"),
        ("effective-mass --mu 1e6", "--mu"),
        ("effective-mass --g-mps2 9.81", "--g-mps2"),
        ("locomotion-definition --g-mps2 9.81", "--g-mps2"),
        ("stick-state-machine --duration-s 1000", "--duration-s"),
        (
            "stick-state-machine --scene authors --duration-s 80",
            "--duration-s",
        ),
        (
            "stick-state-machine --frequency-hz 1e4 --duration-s 10000",
            "--frequency-hz",
        ),
        ("all --g-mps2 1e-6", "--g-mps2"),
        ("all --g-mps2 30", "--g-mps2"),
        (
            "asymmetric-shaking --slow-duration-s 1e-9",
            "--slow-duration-s",
        ),
        // the lock condition (five flags) names the one that was set
        (
            "asymmetric-shaking --slow-duration-s 2e-4 --fast-velocity-mps 0.1001",
            "--slow-duration-s",
        ),
        ("asymmetric-shaking --mu 1e-7", "--mu"),
    ];
    for (args, flag) in CASES {
        let mut full: Vec<&str> = args.split_whitespace().collect();
        full.extend(["--quick", "--no-figures"]);
        assert_bad_input(&full, flag);
    }
}

#[test]
fn render_check_of_an_empty_folder_fails() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path().to_str().unwrap();
    assert_bad_input(&["render", "--check", "--dir", d], "--dir");
    assert_bad_input(
        &["render", "--check", "--dir", "/nonexistent-folder"],
        "--dir",
    );
}

/// A release build simulates the stick about eight times faster than a debug build
/// (`SECONDS_PER_CYCLE`), so its largest accepted run (1e7 drive cycles, about 150 s)
/// stays inside the 10-minute budget: only a debug build (`cargo test`, the dev profile)
/// has a valid input to refuse; the README's `cargo test --release` skips these checks.
const BUDGET_REFUSES_VALID_INPUT: bool = cfg!(debug_assertions);

#[test]
#[cfg_attr(
    not(debug_assertions),
    ignore = "a release build's largest run is inside the work budget (BUDGET_REFUSES_VALID_INPUT)"
)]
fn runs_beyond_the_budget_are_refused_unless_allowed() {
    // Gamma = 0 lifts the rounding bound: 1e4 s at 1 kHz is 1e7 drive cycles (~20 min
    // in a debug build).
    let args = [
        "stick-state-machine",
        "--gamma",
        "0",
        "--frequency-hz",
        "1000",
        "--duration-s",
        "10000",
        "--quick",
        "--no-figures",
    ];
    let (code, out, err) = run(&args);
    assert_eq!(code, 2, "{err}");
    assert!(out.is_empty());
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(
        err.contains("--duration-s") && err.contains("--allow-long-runs"),
        "{err}"
    );
}

#[test]
fn figures_that_cannot_be_written_exit_3_before_computing() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("a-file");
    std::fs::write(&file, "x").unwrap();
    let under_file = file.join("sub");
    for target in [
        file.to_str().unwrap(),
        under_file.to_str().unwrap(),
        "/proc/workbook-figures",
    ] {
        let t0 = std::time::Instant::now();
        let (code, out, err) = run(&["vertical-shaking", "--quick", "--figures", target]);
        assert_eq!(code, 3, "{target}: {err}");
        assert!(out.is_empty());
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(err.contains("--figures") && err.contains(target), "{err}");
        // refused before the chapter ran (it takes seconds)
        assert!(t0.elapsed().as_secs_f64() < 1.0);
    }
}

#[test]
fn a_closed_stdout_pipe_ends_quietly() {
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_workbook"))
        .args(["effective-mass", "--quick", "--no-figures"])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take()); // the reader goes away before the table is written
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn the_report_layer_refuses_non_finite_numbers() {
    use locomotion_workbook::report::{ChapterReport, Check, Claim};
    let mut r = ChapterReport::new("x", "t", "s");
    r.param("ok_m", 1.0);
    assert_eq!(r.first_non_finite(), None);
    r.param("length_m", f64::NAN);
    assert_eq!(r.first_non_finite().as_deref(), Some("params.length_m"));
    let mut r = ChapterReport::new("x", "t", "s");
    r.result("speed_mps", vec![1.0, f64::INFINITY]);
    assert_eq!(r.first_non_finite().as_deref(), Some("results.speed_mps"));
    let mut r = ChapterReport::new("x", "t", "s");
    r.claim(Claim::draft(Check::Simulation, "c", "s", "st").close(1.0, f64::NAN, 1e-3));
    assert!(r.first_non_finite().unwrap().contains("claims[0]"));
}

#[test]
fn params_echo_what_was_used() {
    let (code, out, err) = run(&[
        "stick-state-machine",
        "--theta0-rad=1e-308",
        "--quick",
        "--json",
        "--no-figures",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(out.trim()).unwrap();
    assert_eq!(v["params"]["theta0_rad"].as_f64(), Some(1e-308));
    let v = common::quick_json("speed-vs-accuracy");
    assert_eq!(v["params"]["g_mps2"].as_f64(), Some(9.81));
    assert_eq!(v["params"]["stick_g_mps2"].as_f64(), Some(10.0));
}

#[test]
fn global_flags_are_refused_where_they_mean_nothing() {
    assert_bad_input(&["list", "--g-mps2", "9.81"], "--g-mps2");
    assert_bad_input(&["list", "--quick"], "--quick");
    assert_bad_input(&["render", "--check", "--json"], "--json");
    assert_bad_input(
        &["effective-mass", "--allow-long-runs", "--no-figures"],
        "--allow-long-runs",
    );
    assert_bad_input(
        &["effective-mass", "--figures", "x", "--no-figures"],
        "--no-figures",
    );
    let (code, _, err) = run(&["list", "--json"]);
    assert_eq!(code, 0, "{err}");
}

#[test]
fn a_near_vertical_stick_falls_back_to_dopri5_and_never_prints_a_nan() {
    // theta_0 = 1e-6 rad: the rod stands almost vertical, where the slide equations
    // divide by sin(theta). DOP853's state turns non-finite there (for theta_0 from 1e-9
    // to 1e-3 rad); the chapter repeats the main run with DOPRI5 at the same tolerance,
    // says so in `contact_method_fallback` (and on stderr), and prints no NaN. (The NaN
    // guard itself is unit-tested in main_run.rs.)
    let (code, out, err) = run(&[
        "stick-state-machine",
        "--theta0-rad=1e-6",
        "--quick",
        "--json",
        "--no-figures",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(out.trim()).unwrap();
    assert_eq!(v["results"]["outcome"], "completed");
    assert!(v["results"]["contact_method_fallback"]
        .as_str()
        .unwrap()
        .contains("DOPRI5"));
    assert!(!out.contains("null") && !out.contains("non-finite number"));
}

#[test]
fn events_csv_of_the_authors_scene_has_its_83_transitions() {
    // The authors' scene over 1 s from the static start: 83 mode switches (the authors'
    // own code under Octave, with the first-step event fix and from the same state, makes
    // the same 83 in the same order: benches/peers/authors_octave.py). The file has a
    // header and one line per switch.
    let dir = tempfile::tempdir().expect("temp dir");
    let path = dir.path().join("events.csv");
    let p = path.to_str().expect("utf-8 path");
    let (code, _, err) = run(&[
        "stick-state-machine",
        "--scene",
        "authors",
        "--duration-s",
        "1",
        "--events",
        p,
        "--quick",
        "--json",
        "--no-figures",
    ]);
    assert_eq!(code, 0, "{err}");
    let csv = std::fs::read_to_string(&path).expect("events file");
    let mut lines = csv.lines();
    assert_eq!(
        lines.next(),
        Some("t_s,from,to,theta_rad,theta_dot_rad_s,x_c_m,f_x_n,f_z_n")
    );
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), 83);
    assert!(rows.iter().all(|r| r.split(',').count() == 8));
    // an unwritable path fails before the run, naming the flag, with exit code 3
    let (code, _, err) = run(&[
        "stick-state-machine",
        "--events",
        "/nonexistent-dir/x.csv",
        "--quick",
        "--no-figures",
    ]);
    assert_eq!(code, 3, "{err}");
    assert!(
        err.contains("--events") && err.lines().count() == 1,
        "{err}"
    );
}

#[test]
fn bare_workbook_prints_its_usage_on_stderr_and_exits_2() {
    let (code, out, err) = run(&[]);
    assert_eq!(code, 2);
    assert!(out.is_empty(), "{out}");
    assert!(err.contains("Usage: workbook"), "{err}");
}

#[test]
fn negative_numbers_are_values_in_every_spelling() {
    for v in ["-3e-1", "-1e-3", "-.5", "-30"] {
        let (code, out, err) = run(&["effective-mass", "--angle-deg", v, "--json", "--no-figures"]);
        assert_eq!(code, 0, "--angle-deg {v}: {err}");
        let j: Value = serde_json::from_str(out.trim()).unwrap();
        let given: f64 = v.parse().unwrap();
        assert_eq!(j["params"]["angle_deg"].as_f64(), Some(given), "{v}");
    }
    let (code, _, err) = run(&[
        "stick-state-machine",
        "--theta0-rad",
        "-.3",
        "--quick",
        "--no-figures",
    ]);
    assert_eq!(code, 0, "{err}");
    // a negative number outside the range is refused by the range, naming the flag
    assert_bad_input(
        &["effective-mass", "--angle-deg", "-1e3", "--no-figures"],
        "--angle-deg",
    );
    // a value with a line break or invalid UTF-8 still gets one line naming the flag
    assert_bad_input(&["effective-mass", "--angle-deg", "1\n2"], "--angle-deg");
    let bad: std::ffi::OsString = std::os::unix::ffi::OsStringExt::from_vec(b"\xff".to_vec());
    let mut out = Vec::new();
    let mut err = Vec::new();
    let args: Vec<std::ffi::OsString> = vec![
        "workbook".into(),
        "effective-mass".into(),
        "--mu".into(),
        bad,
    ];
    let code = locomotion_workbook::cli::run_cli(args, &mut out, &mut err);
    let err = String::from_utf8_lossy(&err);
    assert_eq!(code, 2);
    assert!(
        err.trim_end().lines().count() == 1 && err.contains("--mu"),
        "{err}"
    );
}

#[test]
fn help_ranges_are_the_accepted_ranges() {
    // horizontal-shaking --bias: 0, or 1e-6 <= bias < 1 (the help says so)
    let (_, help, _) = run(&["horizontal-shaking", "--help"]);
    assert!(help.contains("1e-6 <= bias < 1"), "{help}");
    assert_bad_input(
        &["horizontal-shaking", "--bias", "1e-7", "--no-figures"],
        "--bias",
    );
    // stick-state-machine --duration-s: omega t Gamma <= 1.5e5, exactly (265 s meets it
    // at 30 Hz and Gamma = 3: 1.4992e5; 265.3 does not: 1.5009e5)
    let (code, _, err) = run(&[
        "stick-state-machine",
        "--duration-s",
        "265",
        "--quick",
        "--no-figures",
    ]);
    assert_eq!(code, 0, "{err}");
    assert_bad_input(
        &[
            "stick-state-machine",
            "--duration-s",
            "265.3",
            "--quick",
            "--no-figures",
        ],
        "--duration-s",
    );
}

#[test]
fn a_refused_run_leaves_an_existing_events_file_untouched() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("events.csv");
    std::fs::write(&path, "keep me\n").unwrap();
    let p = path.to_str().unwrap();
    // bad input, and (in a debug build) a run over the work budget: both refused before the run
    assert_bad_input(&["stick-state-machine", "--events", p, "--mu", "5"], "--mu");
    let over_budget = [
        "stick-state-machine",
        "--events",
        p,
        "--gamma",
        "0",
        "--frequency-hz",
        "1000",
        "--duration-s",
        "10000",
        "--no-figures",
    ];
    if BUDGET_REFUSES_VALID_INPUT {
        let (code, _, err) = run(&over_budget);
        assert_eq!(code, 2, "{err}");
    }
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "keep me\n");
    // an accepted run replaces it whole and says how many switches it holds
    let (code, out, err) = run(&[
        "stick-state-machine",
        "--events",
        p,
        "--quick",
        "--json",
        "--no-figures",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(out.trim()).unwrap();
    let rows = std::fs::read_to_string(&path).unwrap().lines().count() - 1;
    assert_eq!(v["results"]["events_written"].as_f64(), Some(rows as f64));
    assert_eq!(v["results"]["events_total"], v["results"]["events_written"]);
    // a folder is not a file: exit 3 naming --events and the path, not "figures"
    let d = dir.path().to_str().unwrap();
    let (code, _, err) = run(&[
        "stick-state-machine",
        "--events",
        d,
        "--quick",
        "--no-figures",
    ]);
    assert_eq!(code, 3, "{err}");
    assert!(
        err.contains("--events") && err.contains(d) && !err.contains("figures"),
        "{err}"
    );
}

#[test]
fn exploring_writes_figures_outside_the_committed_folder() {
    // Run from a scratch folder: the default run writes figures/<id>/, a run with a
    // non-default flag or --quick writes out/<id>/ and says so, --figures DIR wins.
    let dir = tempfile::tempdir().unwrap();
    let bin = env!("CARGO_BIN_EXE_workbook");
    let go = |args: &[&str]| {
        let o = std::process::Command::new(bin)
            .args(args)
            .current_dir(dir.path())
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(0), "{args:?}");
        String::from_utf8_lossy(&o.stderr).into_owned()
    };
    let err = go(&["effective-mass", "--angle-deg", "30"]);
    assert!(err.contains("out/"), "{err}");
    assert!(dir.path().join("out/effective-mass").is_dir());
    assert!(!dir.path().join("figures").exists());
    go(&["effective-mass", "--quick"]);
    assert!(!dir.path().join("figures").exists());
    let err = go(&["effective-mass", "--json"]);
    assert!(err.is_empty(), "{err}");
    assert!(dir.path().join("figures/effective-mass").is_dir());
    go(&["effective-mass", "--quick", "--figures", "mine"]);
    assert!(dir.path().join("mine/effective-mass").is_dir());
}

#[test]
fn render_says_stale_with_its_own_exit_code_and_names_a_read_only_file() {
    use locomotion_workbook::render::STALE_EXIT;
    // The appendix holds the chapters' claims tables; a copy that keeps only the first
    // chapter's section needs only that chapter's run.
    let dir = tempfile::tempdir().unwrap();
    let src = std::fs::read_to_string("chapters/errata.md").unwrap();
    let copy = dir.path().join("errata.md");
    let marker = format!("<!-- BEGIN generated:{}:claims -->\n", CHAPTERS[0].id);
    let start = src
        .find(&marker)
        .expect("the first chapter's claims in the appendix");
    let end = start + src[start..].find("<!-- END -->").unwrap() + "<!-- END -->".len();
    std::fs::write(
        &copy,
        format!(
            "# Appendix\n\n{marker}stale row\n{}\n",
            &src[start + marker.len()..end]
        ),
    )
    .unwrap();
    let d = dir.path().to_str().unwrap();
    let (code, out, _) = run(&["render", "--check", "--dir", d]);
    assert_eq!(code, STALE_EXIT, "{out}");
    assert_ne!(STALE_EXIT, 1);
    assert!(out.contains("stale:"), "{out}");
    let mut perm = std::fs::metadata(&copy).unwrap().permissions();
    perm.set_readonly(true);
    std::fs::set_permissions(&copy, perm).unwrap();
    let (code, _, err) = run(&["render", "--dir", d]);
    assert_eq!(code, 3, "{err}");
    assert!(err.contains(copy.to_str().unwrap()), "{err}");
    assert!(std::fs::read_to_string(&copy)
        .unwrap()
        .contains("stale row"));
}
