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
//! Seeded: the seed is printed; `WORKBOOK_FUZZ_SEED=<u64>` draws another set and
//! `WORKBOOK_FUZZ_CASES=<n>` changes the number of cases (default 160).

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

/// One to four numeric flags (each drawn inside, at an end, just outside or special),
/// sometimes an enumerated flag and, for the stick, an rtol decade from 1e-2 to 1e-14;
/// values written `--flag=value` or `--flag value` (negative numbers included).
fn make_case(rng: &mut Rng, table: &[(&'static str, Vec<Flag>)]) -> Case {
    let mut i = (rng.next() % table.len() as u64) as usize;
    if table[i].0 == "vertical-shaking" && rng.unit() < 0.6 {
        // an accepted quick run of this chapter takes ~5 s (debug build), 20 times
        // the others: drawn less often to keep the test near 30 s on 2 cores
        i = (rng.next() % table.len() as u64) as usize;
    }
    let (chapter, flags) = &table[i];
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
        let kind = rng.pick(&[
            Kind::Inside,
            Kind::Inside,
            Kind::JustInside,
            Kind::JustOutside,
            Kind::Special,
        ]);
        let value = if chapter == &"locomotion-definition" {
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

/// Runs one case under `ulimit -v` (2 GB) and a time limit; returns (code, stdout,
/// stderr, seconds). A killed run returns code -1.
fn run_case(case: &Case, limit: Duration) -> (i32, String, String, f64) {
    let bin = env!("CARGO_BIN_EXE_workbook");
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
                return Some(format!(
                    "exit 2 with stdout: {}",
                    &out[..out.len().min(200)]
                ));
            }
            if err.trim_end().lines().count() != 1 {
                return Some(format!("exit 2 without exactly one stderr line: {err}"));
            }
            None
        }
        -1 => Some("timed out".into()),
        c => Some(format!("exit code {c}: {}", &err[..err.len().min(300)])),
    }
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

#[test]
fn fuzzed_inputs_keep_the_contract() {
    let seed: u64 = std::env::var("WORKBOOK_FUZZ_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(0x5eed_2026_1123);
    let n: usize = std::env::var("WORKBOOK_FUZZ_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(160);
    eprintln!("fuzz: seed {seed} ({n} cases; WORKBOOK_FUZZ_SEED to change)");
    // a chapter without value flags has none to draw
    let table: Vec<_> = table().into_iter().filter(|(_, f)| !f.is_empty()).collect();
    let mut rng = Rng(seed.max(1));
    let cases: Vec<Case> = (0..n).map(|_| make_case(&mut rng, &table)).collect();
    let next = AtomicUsize::new(0);
    let failures = Mutex::new(Vec::new());
    let counts = Mutex::new([0usize; 3]); // accepted, refused, slowest (ms)
    let limit = Duration::from_secs(90);
    std::thread::scope(|s| {
        for _ in 0..2 {
            s.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::SeqCst);
                let Some(case) = cases.get(i) else { break };
                let (code, out, err, secs) = run_case(case, limit);
                {
                    let mut c = counts.lock().unwrap();
                    c[usize::from(code != 0)] += 1;
                    c[2] = c[2].max((secs * 1e3) as usize);
                }
                if let Some(why) = violation(case, code, &out, &err) {
                    failures
                        .lock()
                        .unwrap()
                        .push(format!("workbook {}: {why}", case.args.join(" ")));
                }
            });
        }
    });
    let c = counts.into_inner().unwrap();
    eprintln!(
        "fuzz: {} accepted, {} refused, slowest case {} ms",
        c[0], c[1], c[2]
    );
    let failures = failures.into_inner().unwrap();
    assert!(
        failures.is_empty(),
        "seed {seed}: {} of {n} cases broke the contract:\n{}",
        failures.len(),
        failures.join("\n")
    );
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
    assert!(violation(&case, 0, "{\"x\":1}", "").is_none());
    let refuse = Case {
        args: vec![],
        must_refuse: true,
    };
    assert!(violation(&refuse, 0, "{}", "").is_some());
    assert!(violation(&refuse, 2, "", "error: x\n").is_none());
}
