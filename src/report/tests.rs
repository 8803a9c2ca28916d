//! Unit tests of the report module.
use super::*;

#[test]
fn verdict_follows_the_check() {
    let ok = Claim::close("a", "2", "x is one", 1.0, 1.0 + 1e-13, 1e-12);
    assert_eq!(ok.verdict, Verdict::Confirmed);
    let bad = Claim::close("b", "2", "x is one", 1.0, 1.1, 1e-12);
    assert_eq!(bad.verdict, Verdict::Failed);
    let nan = Claim::close("c", "2", "x is one", 1.0, f64::NAN, 1e-12);
    assert_eq!(nan.verdict, Verdict::Failed);
    assert_eq!(nan.computed, Value::String("non-finite".into()));
    let e = Claim::judged("d", "3", "s", 1.0, 2.0, 0.1, true, Verdict::Erratum);
    assert_eq!(e.verdict, Verdict::Erratum);
}

#[test]
fn json_has_exactly_the_contract_keys() {
    let mut r = ChapterReport::new("x", "T", "1");
    r.param("mu", 0.4);
    r.result("ratio", 0.6);
    r.claim(Claim::exact("k", "1", "s", true, true));
    r.table("t", "|a|".into());
    let j = r.to_json();
    let keys: Vec<&String> = j.as_object().unwrap().keys().collect();
    assert_eq!(
        keys,
        ["chapter", "title", "section", "params", "claims", "results", "figures"]
    );
    let ck: Vec<&String> = j["claims"][0].as_object().unwrap().keys().collect();
    assert_eq!(
        ck,
        [
            "id",
            "section",
            "statement",
            "expected",
            "computed",
            "tolerance",
            "verdict",
            "check"
        ]
    );
}

#[test]
fn nan_results_fail_loudly() {
    let mut r = ChapterReport::new("x", "T", "1");
    r.result("speed_mps", f64::NAN);
    assert!(r.has_failures());
    assert_eq!(r.results["speed_mps"], Value::String("non-finite".into()));
    assert!(!r.to_json().to_string().contains("NaN"));
}

#[test]
fn numbers_format_stably() {
    assert_eq!(fmt_num(0.6), "0.6");
    assert_eq!(fmt_num(45.0), "45");
    assert_eq!(fmt_num(0.599999999999), "0.6");
    assert_eq!(fmt_num(1.23456e-7), "1.235e-7");
    assert_eq!(fmt_num(-0.00001), "-1.000e-5");
    assert_eq!(fmt_num(1234.5678), "1235");
    assert_eq!(fmt_num(1.23456), "1.235");
}
