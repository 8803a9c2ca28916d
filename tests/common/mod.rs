//! Helpers shared by the integration tests: the command line run in-process, and the
//! bad-input contract (exit code 2, nothing on stdout, one stderr line naming the flag).
#![allow(dead_code)] // each test binary uses its own subset

use locomotion_workbook::cli::run_cli;

/// Runs `workbook <args...>` in-process; returns (exit code, stdout, stderr).
pub fn run(args: &[&str]) -> (i32, String, String) {
    let (mut out, mut err) = (Vec::new(), Vec::new());
    let full = std::iter::once("workbook").chain(args.iter().copied());
    let code = run_cli(full, &mut out, &mut err);
    (
        code,
        String::from_utf8(out).expect("utf-8 stdout"),
        String::from_utf8(err).expect("utf-8 stderr"),
    )
}

/// Runs `workbook <prefix...> <args...>`.
pub fn run_with(prefix: &[&str], args: &[&str]) -> (i32, String, String) {
    let all: Vec<&str> = prefix.iter().chain(args).copied().collect();
    run(&all)
}

/// Asserts the bad-input contract for `workbook <args...>`: exit code 2, empty stdout,
/// exactly one stderr line, and that line names `flag`.
pub fn assert_bad_input(args: &[&str], flag: &str) {
    let (code, out, err) = run(args);
    assert_eq!(code, 2, "{args:?}: exit code");
    assert!(out.is_empty(), "{args:?}: stdout {out}");
    assert_eq!(
        err.trim_end().lines().count(),
        1,
        "{args:?}: one line, got {err}"
    );
    assert!(err.contains(flag), "{args:?}: {err} should name {flag}");
}

/// Every registered chapter's quick report (default flags, headless, the document's
/// statements), in registry order, run once per test process.
pub fn quick_reports() -> &'static [locomotion_workbook::report::ChapterReport] {
    use locomotion_workbook::chapters::{run_default, Context, CHAPTERS};
    static R: std::sync::OnceLock<Vec<locomotion_workbook::report::ChapterReport>> =
        std::sync::OnceLock::new();
    R.get_or_init(|| {
        CHAPTERS
            .iter()
            .map(|c| {
                run_default(c.id, &Context::headless(true))
                    .unwrap_or_else(|e| panic!("{}: the quick run with default flags: {e}", c.id))
            })
            .collect()
    })
}

/// `workbook <chapter> --quick --json --no-figures`, parsed (asserts exit code 0).
pub fn quick_json(chapter: &str) -> serde_json::Value {
    let (code, out, err) = run(&[chapter, "--quick", "--json", "--no-figures"]);
    assert_eq!(code, 0, "{chapter}: {err}");
    serde_json::from_str(out.trim()).expect("one JSON object on stdout")
}

/// One line `id<sep>verdict` per claim of a report: the discrete part of a snapshot.
pub fn verdict_lines(report: &serde_json::Value, sep: &str) -> String {
    let claims = report["claims"].as_array().expect("claims array");
    claims
        .iter()
        .map(|c| {
            format!(
                "{}{sep}{}\n",
                c["id"].as_str().unwrap(),
                c["verdict"].as_str().unwrap()
            )
        })
        .collect()
}

/// One line `key = value` per named numeric result, formatted by
/// [`locomotion_workbook::report::fmt_num`] (4 significant digits).
pub fn result_lines(report: &serde_json::Value, keys: &[&str]) -> String {
    keys.iter()
        .map(|k| {
            let x = report["results"][*k]
                .as_f64()
                .unwrap_or_else(|| panic!("result {k} is a number"));
            format!("{k} = {}\n", locomotion_workbook::report::fmt_num(x))
        })
        .collect()
}

/// `quick_json(chapter)` and its snapshot head: `id: verdict` lines, then `keys` as `key = value`.
pub fn quick_summary(chapter: &str, keys: &[&str]) -> (serde_json::Value, String) {
    let v = quick_json(chapter);
    let s = verdict_lines(&v, ": ") + &result_lines(&v, keys);
    (v, s)
}

/// Checks that every result named in `keys` is a number and that no claim failed.
pub fn assert_numbers_and_no_failed_claim(report: &serde_json::Value, keys: &[&str]) {
    for key in keys {
        assert!(report["results"][*key].is_number(), "{key}");
    }
    assert!(report["claims"]
        .as_array()
        .unwrap()
        .iter()
        .all(|c| c["verdict"] != "failed"));
}

/// xorshift64*: small, seeded, reproducible (the fuzz and accuracy-sweep tests' draws).
pub struct Rng(pub u64);

impl Rng {
    /// The next 64 random bits.
    pub fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// One element of `xs`.
    pub fn pick<T: Copy>(&mut self, xs: &[T]) -> T {
        xs[(self.next() % xs.len() as u64) as usize]
    }
    /// Uniform in [lo, hi).
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + self.unit() * (hi - lo)
    }
    /// Log-uniform in [lo, hi) (both > 0).
    pub fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + self.unit() * (hi.ln() - lo.ln())).exp()
    }
}
