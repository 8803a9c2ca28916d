//! Fuzz test of the input contract (issue 13): every flag of every chapter, drawn from
//! inside its documented range, just inside and just outside its ends, and the special
//! values NaN, +-inf, -1, 0, 1e-308, 1e-6, 1e6, 1e308. Each case runs the built binary in
//! `--quick` mode as a subprocess, under a memory limit (`ulimit -v`, 2 GB) and a time
//! limit, and asserts the contract of README and DESIGN.md:
//!
//! - exit code 0 or 2 (1 would be a failed claim on an accepted input, 101 a panic,
//!   a signal a crash or the memory limit);
//! - exit 2 prints exactly one stderr line and nothing on stdout; exit 0 prints nothing
//!   on stderr but lines starting with `note: ` (a fallback taken, a start that was not
//!   possible; progress bars hide themselves when stderr is not a terminal);
//! - stdout carries no NaN, inf or JSON null;
//! - a value just outside a flag's documented range (the flag alone) is refused (exit 2).
//!
//! Seeded per chapter: each chapter draws from the printed seed mixed with its own id
//! (adding a chapter shifts no other chapter's draws); `WORKBOOK_FUZZ_SEED=<u64>` draws
//! another set and `WORKBOOK_FUZZ_CASES=<n>` changes the number of cases per chapter
//! (default 20; vertical-shaking 40 % of it and stick-with-inertia 50 %, their quick
//! runs cost seconds). `long_fuzz_has_no_exit_1` (ignored; `scripts/fuzz-long.sh`) runs
//! thousands of accepted inputs in process, through the CLI's own entry point, each
//! chapter within its own time budget, and counts per chapter the runs, accepted, exit
//! 0/1/2, `invalid`, panics and non-finite outputs (docs/fuzz.md).

use std::io::Read;
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

use common::Rng;

use crate::common;

/// Documented range of one flag: `lo`/`hi` with openness. `relative` marks a range that
/// depends on another flag (its "outside" is only outside at the other's default).
#[derive(Clone, Copy)]
struct Flag {
    name: &'static str,
    lo: f64,
    hi: f64,
    lo_open: bool,
    hi_open: bool,
    relative: bool,
}

/// The documented ranges, chapter by chapter: the library's flag table (the registry's
/// `ChapterInfo::flags`, which also writes the `--help` lines and validates the values).
fn table() -> Vec<(&'static str, Vec<Flag>)> {
    locomotion_workbook::chapters::CHAPTERS
        .iter()
        .map(|c| {
            let flags = c
                .flags
                .iter()
                .map(|f| Flag {
                    name: f.name,
                    lo: f.range.lo,
                    hi: f.range.hi,
                    lo_open: f.range.lo_open,
                    hi_open: f.range.hi_open,
                    relative: f.coupled,
                })
                .collect();
            (c.id, flags)
        })
        .collect()
}

const SPECIAL: [&str; 9] = [
    "NaN", "inf", "-inf", "-1", "0", "1e-308", "1e-6", "1e6", "1e308",
];

#[derive(Clone, Copy, PartialEq, Debug)]
enum Kind {
    Inside,
    JustInside,
    JustOutside,
    Special,
}

/// A value of `f` of the given kind, as text.
fn draw(f: &Flag, kind: Kind, rng: &mut Rng) -> String {
    let (lo, hi) = (f.lo, f.hi);
    let nudge = |x: f64, up: bool, rel: f64| {
        let d = if x == 0.0 { rel } else { x.abs() * rel };
        if up {
            x + d
        } else {
            x - d
        }
    };
    let v = match kind {
        Kind::Special => return rng.pick(&SPECIAL).to_string(),
        Kind::Inside => {
            let u = rng.unit();
            if lo > 0.0 && hi / lo > 100.0 {
                (lo.ln() + u * (hi.ln() - lo.ln())).exp() // log-uniform over decades
            } else {
                lo + u * (hi - lo)
            }
        }
        Kind::JustInside => {
            if rng.unit() < 0.5 {
                nudge(lo, true, if f.lo_open { 1e-6 } else { 0.0 })
            } else {
                nudge(hi, false, if f.hi_open { 1e-6 } else { 0.0 })
            }
        }
        Kind::JustOutside => {
            if rng.unit() < 0.5 {
                nudge(lo, false, if f.lo_open { 0.0 } else { 1e-6 })
            } else {
                nudge(hi, true, if f.hi_open { 0.0 } else { 1e-6 })
            }
        }
    };
    format!("{v:e}")
}

/// One case: the arguments and whether it must be refused.
#[derive(Debug, Clone)]
struct Case {
    args: Vec<String>,
    must_refuse: bool,
}

fn pair_value(f: &Flag, kind: Kind, rng: &mut Rng) -> String {
    let a = draw(f, kind, rng);
    let b = if rng.unit() < 0.5 {
        "0".to_string()
    } else {
        draw(f, Kind::Inside, rng)
    };
    let neg = if rng.unit() < 0.3 { "-" } else { "" };
    format!("{neg}{a},{b}")
}

/// The enumerated flags of `chapter` (`--method`, `--scene`, ...) with their values,
/// from the clap definition itself.
fn enum_flags(chapter: &str) -> Vec<(String, Vec<String>)> {
    let cmd = locomotion_workbook::cli::command();
    let Some(sub) = cmd.find_subcommand(chapter) else {
        return Vec::new();
    };
    sub.get_arguments()
        .filter(|a| !a.is_global_set() && !a.get_possible_values().is_empty())
        .filter_map(|a| {
            let values: Vec<String> = a
                .get_possible_values()
                .iter()
                .map(|v| v.get_name().to_string())
                .collect();
            Some((format!("--{}", a.get_long()?), values))
        })
        .collect()
}

/// One to four numeric flags of `chapter` (each drawn inside, at an end, just outside
/// or special; only inside or at an end when `valid_only`), sometimes an enumerated
/// flag and, for the stick, an rtol decade from 1e-2 to 1e-14; values written
/// `--flag=value` or `--flag value` (negative numbers included).
fn make_case(rng: &mut Rng, chapter: &str, flags: &[Flag], valid_only: bool) -> Case {
    let n = if rng.unit() < 0.4 {
        1
    } else {
        2 + (rng.next() % 3) as usize
    };
    let mut args = vec![
        chapter.to_string(),
        "--quick".to_string(),
        "--no-figures".into(),
    ];
    if rng.unit() < 0.8 {
        args.push("--json".into());
    }
    let mut must_refuse = false;
    let mut used: Vec<&str> = Vec::new();
    let push = |args: &mut Vec<String>, rng: &mut Rng, name: &str, value: String| {
        if rng.unit() < 0.5 {
            args.push(format!("{name}={value}"));
        } else {
            args.push(name.to_string());
            args.push(value);
        }
    };
    for _ in 0..n {
        let f = rng.pick(flags);
        if used.contains(&f.name) {
            continue;
        }
        used.push(f.name);
        let kinds: &[Kind] = if valid_only {
            &[Kind::Inside, Kind::Inside, Kind::JustInside]
        } else {
            &[
                Kind::Inside,
                Kind::Inside,
                Kind::JustInside,
                Kind::JustOutside,
                Kind::Special,
            ]
        };
        let kind = rng.pick(kinds);
        let value = if chapter == "locomotion-definition" {
            pair_value(&f, kind, rng)
        } else if f.name == "--rtol" && kind == Kind::Inside {
            format!("1e-{}", 2 + rng.next() % 13) // every decade 1e-2 .. 1e-14
        } else {
            draw(&f, kind, rng)
        };
        // outside a range that depends on no other flag: refused whatever the others
        if kind == Kind::JustOutside && !f.relative {
            must_refuse = true;
        }
        push(&mut args, rng, f.name, value);
    }
    if rng.unit() < 0.4 {
        let enums = enum_flags(chapter);
        if !enums.is_empty() {
            let (name, values) = &enums[(rng.next() % enums.len() as u64) as usize];
            let v = values[(rng.next() % values.len() as u64) as usize].clone();
            push(&mut args, rng, name, v);
        }
    }
    Case { args, must_refuse }
}

/// The seed of one chapter's draws: the base seed mixed with an FNV-1a hash of the
/// chapter's id (then a splitmix64 round), so that adding, removing or reordering a
/// chapter shifts no other chapter's draws.
fn chapter_seed(base: u64, id: &str) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in id.bytes() {
        h = (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
    }
    let mut z = (base ^ h).wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    (z ^ (z >> 31)).max(1)
}

/// `per_chapter` cases of every chapter, each chapter drawn from its own seed
/// ([`chapter_seed`]), interleaved chapter by chapter (so a time budget cuts every
/// chapter alike). The two chapters whose accepted quick run costs seconds get a share
/// of the cases (the first ones of their own draws, so no draw moves): vertical-shaking
/// 40 % (5 to 11 s a run), stick-with-inertia 50 % (3 to 8 s); together they took 40 of
/// the 50 CPU seconds of the fuzz at 20 and 40 % (measured 27 November 2026). The long
/// fuzz (`scripts/fuzz-long.sh`) gives them their own time budgets.
fn cases(base: u64, per_chapter: usize, valid_only: bool) -> Vec<Case> {
    let per_chapter_cases: Vec<Vec<Case>> = table()
        .iter()
        .filter(|(_, flags)| !flags.is_empty()) // a chapter without value flags has none to draw
        .map(|(chapter, flags)| {
            let mut rng = Rng(chapter_seed(base, chapter));
            let n = match *chapter {
                "vertical-shaking" => (per_chapter * 2).div_ceil(5),
                "stick-with-inertia" => per_chapter.div_ceil(2),
                _ => per_chapter,
            };
            (0..n)
                .map(|_| make_case(&mut rng, chapter, flags, valid_only))
                .collect()
        })
        .collect();
    let longest = per_chapter_cases.iter().map(Vec::len).max().unwrap_or(0);
    (0..longest)
        .flat_map(|i| {
            per_chapter_cases
                .iter()
                .filter_map(move |c| c.get(i).cloned())
        })
        .collect()
}

/// Runs one case under `ulimit -v` (2 GB) and a time limit; returns (code, stdout,
/// stderr, seconds). A killed run returns code -1.
fn run_case(bin: &str, case: &Case, limit: Duration) -> (i32, String, String, f64) {
    let start = Instant::now();
    let mut child = Command::new("sh")
        .arg("-c")
        .arg("ulimit -v 2000000 && exec \"$0\" \"$@\"")
        .arg(bin)
        .args(&case.args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn workbook");
    let mut out_pipe = child.stdout.take().expect("stdout");
    let mut err_pipe = child.stderr.take().expect("stderr");
    let out_t = std::thread::spawn(move || {
        let mut s = String::new();
        let _ = out_pipe.read_to_string(&mut s);
        s
    });
    let err_t = std::thread::spawn(move || {
        let mut s = String::new();
        let _ = err_pipe.read_to_string(&mut s);
        s
    });
    let code = loop {
        if let Some(status) = child.try_wait().expect("wait") {
            break status.code().unwrap_or(-2);
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            break -1;
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let out = out_t.join().unwrap_or_default();
    let err = err_t.join().unwrap_or_default();
    (code, out, err, start.elapsed().as_secs_f64())
}

/// JSON: any null (serde_json writes NaN and inf as null) or the text "non-finite";
/// a table: the words NaN, inf, -inf.
fn has_non_finite(out: &str) -> bool {
    fn walk(v: &serde_json::Value) -> bool {
        match v {
            serde_json::Value::Null => true,
            serde_json::Value::String(s) => s == "non-finite",
            serde_json::Value::Array(a) => a.iter().any(walk),
            serde_json::Value::Object(o) => o.values().any(walk),
            _ => false,
        }
    }
    if let Ok(v) = serde_json::from_str::<serde_json::Value>(out.trim()) {
        return walk(&v);
    }
    out.split(|c: char| !(c.is_ascii_alphanumeric() || c == '-' || c == '_' || c == '.'))
        .any(|w| w == "NaN" || w == "inf" || w == "-inf")
}

/// What is wrong with a case's outcome, if anything.
fn violation(case: &Case, code: i32, out: &str, err: &str) -> Option<String> {
    match code {
        0 => {
            if case.must_refuse {
                return Some("accepted a value outside the documented range".into());
            }
            if err.lines().any(|l| !l.starts_with("note: ")) {
                return Some(format!("exit 0 with stderr other than notes: {err}"));
            }
            if has_non_finite(out) {
                return Some("NaN, inf or null on stdout".into());
            }
            None
        }
        2 => {
            if !out.is_empty() {
                return Some(format!("exit 2 with stdout: {}", head(out, 200)));
            }
            if err.trim_end().lines().count() != 1 {
                return Some(format!("exit 2 without exactly one stderr line: {err}"));
            }
            None
        }
        -1 => Some("timed out".into()),
        1 => Some(format!(
            "exit code 1: {}{}",
            failed_claims(out),
            head(err, 300)
        )),
        c => Some(format!("exit code {c}: {}", head(err, 300))),
    }
}

/// The first `n` characters of `s` (whole characters: the notes print θ and μ), without
/// the trailing newline.
fn head(s: &str, n: usize) -> String {
    s.chars().take(n).collect::<String>().trim_end().to_string()
}

/// The failed claims in a run's JSON, each as `id: expected E, computed C, tolerance T`
/// (with `; ` after each), or nothing when the output is not JSON.
fn failed_claims(out: &str) -> String {
    fn walk(v: &serde_json::Value, found: &mut String) {
        match v {
            serde_json::Value::Object(o) => {
                if o.get("verdict").and_then(|x| x.as_str()) == Some("failed") {
                    let field = |k: &str| o.get(k).map_or("-".into(), |x| x.to_string());
                    found.push_str(&format!(
                        "failed claim {}: expected {}, computed {}, tolerance {}; ",
                        field("id"),
                        field("expected"),
                        field("computed"),
                        field("tolerance")
                    ));
                }
                o.values().for_each(|x| walk(x, found));
            }
            serde_json::Value::Array(a) => a.iter().for_each(|x| walk(x, found)),
            _ => {}
        }
    }
    let mut found = String::new();
    if let Ok(v) = serde_json::from_str::<serde_json::Value>(out.trim()) {
        walk(&v, &mut found);
    }
    found
}

#[test]
fn every_flag_of_every_chapter_is_in_the_fuzz_table() {
    let chapters: Vec<&str> = table().iter().map(|(c, _)| *c).collect();
    for c in locomotion_workbook::chapters::CHAPTERS.iter() {
        assert!(
            chapters.contains(&c.id),
            "{}: missing from the fuzz table",
            c.id
        );
    }
    let cmd = locomotion_workbook::cli::command();
    for (chapter, flags) in table() {
        let sub = cmd.find_subcommand(chapter).expect("chapter subcommand");
        for a in sub.get_arguments() {
            let Some(long) = a.get_long() else { continue };
            let enumerated = !a.get_possible_values().is_empty();
            // output paths (`--events FILE`) are tested in cli.rs, not fuzzed
            let path = a.get_value_hint() == clap::ValueHint::FilePath;
            if a.is_global_set() || !a.get_action().takes_values() || enumerated || path {
                continue;
            }
            let name = format!("--{long}");
            assert!(
                flags.iter().any(|f| f.name == name),
                "{chapter}: {name} missing from the fuzz table"
            );
        }
    }
}

/// A number from the environment variable `name`, or `default`.
fn env_or<T: std::str::FromStr>(name: &str, default: T) -> T {
    std::env::var(name)
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(default)
}

/// What a batch of cases did: accepted, refused, slowest (ms), and the violations.
#[derive(Default)]
struct Tally {
    accepted: usize,
    refused: usize,
    slowest_ms: usize,
    failures: Vec<String>,
    /// Per chapter: cases, accepted, and the seconds they took (wall, summed).
    per_chapter: std::collections::BTreeMap<String, (usize, usize, f64)>,
}

/// Runs `cases` on `bin` (each a subprocess) with `jobs` workers, each case under `limit`.
fn run_all(bin: &str, cases: &[Case], jobs: usize, limit: Duration) -> Tally {
    let next = AtomicUsize::new(0);
    let tally = Mutex::new(Tally::default());
    std::thread::scope(|s| {
        for _ in 0..jobs.max(1) {
            s.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::SeqCst);
                let Some(case) = cases.get(i) else { break };
                let (code, out, err, secs) = run_case(bin, case, limit);
                let why = violation(case, code, &out, &err);
                let mut t = tally.lock().unwrap();
                t.accepted += usize::from(code == 0 || code == 1);
                t.refused += usize::from(code == 2);
                t.slowest_ms = t.slowest_ms.max((secs * 1e3) as usize);
                let c = t.per_chapter.entry(case.args[0].clone()).or_default();
                *c = (
                    c.0 + 1,
                    c.1 + usize::from(code == 0 || code == 1),
                    c.2 + secs,
                );
                if let Some(why) = why {
                    t.failures
                        .push(format!("workbook {}: {why}", case.args.join(" ")));
                }
            });
        }
    });
    tally.into_inner().unwrap()
}

/// The contract on every chapter's own draws (`WORKBOOK_FUZZ_SEED`, default fixed;
/// `WORKBOOK_FUZZ_CASES` per chapter, default 20).
#[test]
fn fuzzed_inputs_keep_the_contract() {
    let seed: u64 = env_or("WORKBOOK_FUZZ_SEED", 0x5eed_2026_1123);
    let n: usize = env_or("WORKBOOK_FUZZ_CASES", 20);
    eprintln!("fuzz: seed {seed} ({n} cases per chapter; WORKBOOK_FUZZ_SEED to change)");
    let cases = cases(seed, n, false);
    let bin = env!("CARGO_BIN_EXE_workbook");
    let t = run_all(bin, &cases, 2, Duration::from_secs(90));
    eprintln!(
        "fuzz: {} accepted, {} refused, slowest case {} ms",
        t.accepted, t.refused, t.slowest_ms
    );
    for (chapter, (runs, accepted, secs)) in &t.per_chapter {
        eprintln!("fuzz: {chapter:<22} {runs:>3} cases, {accepted:>3} accepted, {secs:>6.1} s");
    }
    assert!(
        t.failures.is_empty(),
        "seed {seed}: {} of {} cases broke the contract:\n{}",
        t.failures.len(),
        cases.len(),
        t.failures.join("\n")
    );
}

/// The long fuzz's time budget of one chapter, as a multiple of the base budget
/// (`WORKBOOK_FUZZ_CHAPTER_SECONDS`). A chapter whose quick run is cheap runs all its
/// draws well inside the base; three chapters pay for evidence sweeps that every run
/// repeats whatever its flags (no flag selects a smaller piece of them), so they get
/// more time to reach a useful number of draws: vertical-shaking (a quick run costs
/// 5 to 11 s: the flight-time, law and viscous sweeps up to Gamma = 32768),
/// stick-with-inertia (3 to 8 s: the evidence scenes and the rod-mass ladder; the
/// reader's `--duration-s` is not where the time goes) and speed-vs-accuracy (1 to 3 s:
/// its work-precision ladders).
fn budget_factor(chapter: &str) -> f64 {
    match chapter {
        "vertical-shaking" => 6.0,
        "stick-with-inertia" => 3.0,
        "speed-vs-accuracy" => 2.0,
        _ => 1.0,
    }
}

/// One chapter's share of the long fuzz: its own draws (seeded by [`chapter_seed`]),
/// its time budget and how much of it the runs took (thread seconds), and the counts
/// by outcome.
struct Lane {
    chapter: &'static str,
    cases: Vec<Case>,
    next: usize,
    budget_s: f64,
    busy_s: f64,
    /// Runs that ended with exit code 0, 1 and 2.
    exits: [usize; 3],
    /// Runs that panicked (101) or ended with another code.
    other: usize,
    /// Exit-0 runs whose JSON says `invalid` somewhere (a run that could not vouch).
    invalid: usize,
    /// Exit-0 runs with NaN, inf or null on stdout.
    non_finite: usize,
    /// The slowest run: seconds and command line.
    slowest: (f64, String),
}

impl Lane {
    fn new(chapter: &'static str, cases: Vec<Case>, base_s: f64) -> Self {
        Lane {
            chapter,
            cases,
            next: 0,
            budget_s: base_s * budget_factor(chapter),
            busy_s: 0.0,
            exits: [0; 3],
            other: 0,
            invalid: 0,
            non_finite: 0,
            slowest: (0.0, String::new()),
        }
    }

    /// Counts one run of `case`.
    fn record(&mut self, case: &Case, code: i32, out: &str, secs: f64) {
        self.busy_s += secs;
        match code {
            0..=2 => self.exits[code as usize] += 1,
            _ => self.other += 1,
        }
        self.invalid += usize::from(code == 0 && says_invalid(out));
        self.non_finite += usize::from(code == 0 && has_non_finite(out));
        if secs > self.slowest.0 {
            self.slowest = (secs, command_line(case));
        }
    }

    /// The summary line: runs, accepted (exit 0 or 1), exit 0/1/2, invalid, the other
    /// breaches, the slowest run, the time used of the budget and why the lane stopped.
    fn summary(&self) -> String {
        let [e0, e1, e2] = self.exits;
        let stop = if self.next == self.cases.len() {
            "all draws run"
        } else if self.busy_s >= self.budget_s {
            "budget spent"
        } else {
            "stopped"
        };
        format!(
            "{:<22} {:>4} runs: {:>4} accepted, exit 0/1/2 = {}/{}/{}, {} invalid, {} panic or other, {} non-finite; slowest {:.2} s; {:.0} of {:.0} s ({}, {} of {} draws)",
            self.chapter, self.next, e0 + e1, e0, e1, e2, self.invalid, self.other,
            self.non_finite, self.slowest.0, self.busy_s, self.budget_s, stop, self.next,
            self.cases.len()
        )
    }
}

/// Whether a run's JSON says that it could not vouch for its answer: an outcome (of
/// the main run or an evidence run) whose value is the word `invalid`.
fn says_invalid(out: &str) -> bool {
    fn walk(v: &serde_json::Value) -> bool {
        match v {
            serde_json::Value::String(s) => s == "invalid",
            serde_json::Value::Array(a) => a.iter().any(walk),
            serde_json::Value::Object(o) => o.values().any(walk),
            _ => false,
        }
    }
    serde_json::from_str::<serde_json::Value>(out.trim()).is_ok_and(|v| walk(&v))
}

/// One case in this process: the CLI's own entry point (`cli::run_cli`, the code the
/// binary's `main` calls), its stdout and stderr captured; a panic is caught and
/// reported as exit 101, as the process would end. Returns (code, stdout, stderr).
fn run_in_process(case: &Case) -> (i32, String, String) {
    let (mut out, mut err) = (Vec::new(), Vec::new());
    let argv = std::iter::once("workbook".to_string()).chain(case.args.iter().cloned());
    let code = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        locomotion_workbook::cli::run_cli(argv, &mut out, &mut err)
    }))
    .unwrap_or(101);
    (
        code,
        String::from_utf8_lossy(&out).into_owned(),
        String::from_utf8_lossy(&err).into_owned(),
    )
}

/// The command line of a case as a shell would take it (each argument quoted).
fn command_line(case: &Case) -> String {
    let quoted: Vec<String> = case.args.iter().map(|a| format!("'{a}'")).collect();
    format!("workbook {}", quoted.join(" "))
}

/// The lane a free worker takes next: among the chapters with draws and budget left,
/// the one that has used the smallest fraction of its budget (so the chapters are
/// interleaved, the cheap ones run all their draws early and each costly one gets
/// its own budget, not what the others left).
fn next_case(lanes: &mut [Lane]) -> Option<(usize, Case)> {
    let i = (0..lanes.len())
        .filter(|&i| lanes[i].next < lanes[i].cases.len() && lanes[i].busy_s < lanes[i].budget_s)
        .min_by(|&a, &b| {
            let used = |l: &Lane| l.busy_s / l.budget_s;
            used(&lanes[a]).total_cmp(&used(&lanes[b]))
        })?;
    let lane = &mut lanes[i];
    lane.next += 1;
    Some((i, lane.cases[lane.next - 1].clone()))
}

/// The long fuzz's draws: accepted values only (inside the documented ranges and at
/// their ends), every chapter from its own seed, each with `--json`; only the chapters
/// named in `only` (comma-separated ids) when it is not empty.
fn long_lanes(seed: u64, n: usize, base_s: f64, only: &str) -> Vec<Lane> {
    let wanted = |id: &str| only.is_empty() || only.split(',').any(|c| c.trim() == id);
    table()
        .into_iter()
        .filter(|(id, flags)| !flags.is_empty() && wanted(id))
        .map(|(chapter, flags)| {
            let mut rng = Rng(chapter_seed(seed, chapter));
            let cases = (0..n)
                .map(|_| {
                    let mut c = make_case(&mut rng, chapter, &flags, true);
                    if !c.args.iter().any(|a| a == "--json") {
                        c.args.push("--json".into());
                    }
                    c
                })
                .collect();
            Lane::new(chapter, cases, base_s)
        })
        .collect()
}

/// Appends one breach to the findings file (`WORKBOOK_FUZZ_FINDINGS`, if set): the
/// UTC time of day, the command line and what went wrong, tab-separated, on one line.
fn log_finding(line: &str) {
    let Ok(path) = std::env::var("WORKBOOK_FUZZ_FINDINGS") else {
        return;
    };
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let (h, m, s) = (secs / 3600 % 24, secs / 60 % 60, secs % 60);
    let text = format!("{h:02}:{m:02}:{s:02} UTC\t{}\n", line.replace('\n', " | "));
    let file = std::fs::OpenOptions::new()
        .create(true)
        .append(true)
        .open(path);
    if let Ok(mut f) = file {
        use std::io::Write;
        let _ = f.write_all(text.as_bytes());
    }
}

/// One worker of the long fuzz: takes cases ([`next_case`]) until no lane has draws
/// and budget left, runs each in process, counts it in its lane and reports every
/// breach at once (stderr and the findings file). `slot` shows the watchdog the case
/// it is running.
fn long_worker(
    lanes: &Mutex<Vec<Lane>>,
    failures: &Mutex<Vec<String>>,
    slot: &Mutex<Option<(Instant, String)>>,
) {
    loop {
        let Some((i, case)) = next_case(&mut lanes.lock().unwrap()) else {
            break;
        };
        *slot.lock().unwrap() = Some((Instant::now(), command_line(&case)));
        let t0 = Instant::now();
        let (code, out, err) = run_in_process(&case);
        let secs = t0.elapsed().as_secs_f64();
        *slot.lock().unwrap() = None;
        lanes.lock().unwrap()[i].record(&case, code, &out, secs);
        if let Some(why) = violation(&case, code, &out, &err) {
            let line = format!("{}: {why}", command_line(&case));
            eprintln!("long fuzz: {line}");
            log_finding(&line);
            failures.lock().unwrap().push(line);
        }
    }
}

/// The long fuzz (`scripts/fuzz-long.sh`): accepted values only, every chapter from
/// its own seed, run in this process through the CLI's entry point (`--quick`,
/// `--json`, no figures) on `WORKBOOK_FUZZ_JOBS` threads (default 2). Each chapter
/// runs until it has run its `WORKBOOK_FUZZ_CASES` draws (default 500) or spent its
/// time budget, `WORKBOOK_FUZZ_CHAPTER_SECONDS` (default 45 thread seconds) times its
/// [`budget_factor`] (`WORKBOOK_FUZZ_CHAPTERS=id,id` runs those chapters only); the
/// chapters are interleaved ([`next_case`]), so the wall time
/// is at most the sum of the budgets over the threads plus one run. Prints one line per
/// chapter (runs, accepted, exit 0/1/2, invalid, panics, non-finite, slowest run) and
/// the command line of every breach; any exit 1, panic, non-finite output or other
/// breach of the contract fails it. A case still running 120 s after it started ends
/// the test with its command line.
#[test]
#[ignore = "minutes long: scripts/fuzz-long.sh"]
fn long_fuzz_has_no_exit_1() {
    let seed: u64 = env_or("WORKBOOK_FUZZ_SEED", 0x10c0_2026);
    let n: usize = env_or("WORKBOOK_FUZZ_CASES", 500);
    let base_s: f64 = env_or("WORKBOOK_FUZZ_CHAPTER_SECONDS", 45.0);
    let jobs: usize = env_or::<usize>("WORKBOOK_FUZZ_JOBS", 2).max(1);
    let only: String = env_or("WORKBOOK_FUZZ_CHAPTERS", String::new());
    let lanes = long_lanes(seed, n, base_s, &only);
    assert!(
        !lanes.is_empty(),
        "WORKBOOK_FUZZ_CHAPTERS={only}: no such chapter"
    );
    let bound_s: f64 = lanes.iter().map(|l| l.budget_s).sum::<f64>() / jobs as f64;
    eprintln!(
        "long fuzz: seed {seed}, {n} draws per chapter, {} chapters, {base_s} s per chapter (x{} vertical-shaking, x{} stick-with-inertia, x{} speed-vs-accuracy), {jobs} threads, in process; at most {bound_s:.0} s of wall time",
        lanes.len(),
        budget_factor("vertical-shaking"),
        budget_factor("stick-with-inertia"),
        budget_factor("speed-vs-accuracy")
    );
    let start = Instant::now();
    let lanes = Mutex::new(lanes);
    let failures = Mutex::new(Vec::<String>::new());
    let running: Vec<Mutex<Option<(Instant, String)>>> =
        (0..jobs).map(|_| Mutex::new(None)).collect();
    let done = AtomicUsize::new(0);
    std::thread::scope(|s| {
        for slot in &running {
            let (lanes, failures, done) = (&lanes, &failures, &done);
            s.spawn(move || {
                long_worker(lanes, failures, slot);
                done.fetch_add(1, Ordering::SeqCst);
            });
        }
        watchdog(&running, &done);
    });
    let wall_s = start.elapsed().as_secs_f64();
    let lanes = lanes.into_inner().unwrap();
    let failures = failures.into_inner().unwrap();
    let exit_1 = report_lanes(&lanes, wall_s);
    assert!(
        failures.is_empty(),
        "seed {seed}: {} cases broke the contract ({exit_1} exit 1):\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// Ends the process when a case has run past 120 s (naming it), until every worker
/// is done.
fn watchdog(running: &[Mutex<Option<(Instant, String)>>], done: &AtomicUsize) {
    while done.load(Ordering::SeqCst) < running.len() {
        std::thread::sleep(Duration::from_millis(200));
        for slot in running {
            if let Some((t0, line)) = slot.lock().unwrap().as_ref() {
                if t0.elapsed() > Duration::from_secs(120) {
                    eprintln!("long fuzz: {line}: still running after 120 s");
                    std::process::exit(1);
                }
            }
        }
    }
}

/// Prints the per-chapter lines, each chapter's slowest command and the totals;
/// returns the number of exit-1 runs.
fn report_lanes(lanes: &[Lane], wall_s: f64) -> usize {
    let mut total = [0usize; 6];
    for l in lanes {
        eprintln!("long fuzz: {}", l.summary());
        for (t, x) in total.iter_mut().zip([
            l.next,
            l.exits[0] + l.exits[1],
            l.exits[1],
            l.exits[2],
            l.invalid,
            l.other + l.non_finite,
        ]) {
            *t += x;
        }
    }
    for l in lanes {
        eprintln!("long fuzz: slowest {}: {}", l.chapter, l.slowest.1);
    }
    eprintln!(
        "long fuzz: {} runs, {} accepted, {} exit 1, {} refused (exit 2), {} invalid, {} panics, other codes or non-finite outputs, in {wall_s:.0} s wall",
        total[0], total[1], total[2], total[3], total[4], total[5]
    );
    total[2]
}

/// Each chapter's draws depend on its id and the seed only.
#[test]
fn each_chapter_draws_from_its_own_seed() {
    let a = chapter_seed(7, "horizontal-shaking");
    assert_eq!(a, chapter_seed(7, "horizontal-shaking"));
    assert_ne!(a, chapter_seed(7, "vertical-shaking"));
    assert_ne!(a, chapter_seed(8, "horizontal-shaking"));
    let first = |cs: &[Case], id: &str| {
        cs.iter()
            .find(|c| c.args[0] == id)
            .map(|c| c.args.clone())
            .expect("a case of the chapter")
    };
    let all = cases(7, 3, false);
    let mut rng = Rng(chapter_seed(7, "horizontal-shaking"));
    let flags = table()
        .into_iter()
        .find(|(c, _)| *c == "horizontal-shaking")
        .expect("chapter")
        .1;
    let alone = make_case(&mut rng, "horizontal-shaking", &flags, false);
    assert_eq!(first(&all, "horizontal-shaking"), alone.args);
}

#[test]
fn the_checker_sees_what_it_must_refuse() {
    // The oracle itself can fail: a panic, a NaN, two stderr lines, an accepted
    // out-of-range value are all reported.
    let case = Case {
        args: vec![],
        must_refuse: false,
    };
    assert!(violation(&case, 101, "", "panicked").is_some());
    assert!(violation(&case, 1, "", "").is_some());
    assert!(violation(&case, 0, "{\"x\":null}", "").is_some());
    assert!(violation(&case, 0, "x = inf\n", "").is_some());
    assert!(violation(&case, 2, "", "a\nb\n").is_some());
    // a long stderr of two-byte characters (θ) is cut between characters
    assert!(violation(&case, 1, "", &"θ".repeat(400)).is_some());
    assert!(violation(&case, 0, "{\"x\":1}", "").is_none());
    let refuse = Case {
        args: vec![],
        must_refuse: true,
    };
    assert!(violation(&refuse, 0, "{}", "").is_some());
    assert!(violation(&refuse, 2, "", "error: x\n").is_none());
}

#[test]
fn the_long_fuzz_interleaves_chapters_within_their_budgets() {
    let case = |c: &str| Case {
        args: vec![c.to_string()],
        must_refuse: false,
    };
    let lane = |c: &'static str| Lane::new(c, vec![case(c); 3], 10.0);
    let mut lanes = vec![lane("vertical-shaking"), lane("effective-mass")];
    // equal use (none): the first; then the one that has used the smaller fraction
    assert_eq!(next_case(&mut lanes).map(|(i, _)| i), Some(0));
    lanes[0].busy_s = 30.0; // half of its 60 s
    lanes[1].busy_s = 6.0; // 60 % of its 10 s
    assert_eq!(next_case(&mut lanes).map(|(i, _)| i), Some(0));
    lanes[0].busy_s = 60.0; // budget spent: the other lane takes its draws, then none
    assert_eq!(next_case(&mut lanes).map(|(i, _)| i), Some(1));
    assert_eq!(next_case(&mut lanes).map(|(i, _)| i), Some(1));
    assert_eq!(next_case(&mut lanes).map(|(i, _)| i), Some(1));
    assert!(
        next_case(&mut lanes).is_none(),
        "all draws run or budgets spent"
    );
    let json = r#"{"claims":[{"id":"x","expected":1.0,"computed":2.0,"tolerance":0.1,"verdict":"failed"}]}"#;
    assert!(violation(&case("x"), 1, json, "")
        .is_some_and(|w| w.contains("failed claim \"x\": expected 1.0, computed 2.0")));
}
