//! `workbook lab` (issue 23): the endpoint computes what the CLI computes, refuses what
//! the CLI refuses with the CLI's own line, and answers every malformed request with a
//! 400 (or 413, 404, 405, 403) and a reason, over real HTTP.

use locomotion_workbook::cli::run_cli;
use locomotion_workbook::lab::{api, server::Lab, simulate};
use serde_json::{json, Value};
use std::io::{Read, Write};
use std::net::{IpAddr, Ipv4Addr, SocketAddr, TcpStream};

/// The jamming scene as a full request, with `over` merged in.
fn body(over: Value) -> Value {
    let mut b = json!({
        "scene": "jamming", "theta0_rad": 0.3, "mu": 0.4, "gamma": 3, "frequency_hz": 30,
        "stiffness": 10, "damping": 0.01, "length_m": 0.15, "mass_kg": 1, "duration_s": 2,
    });
    for (k, v) in over.as_object().expect("an object") {
        b[k] = v.clone();
    }
    b
}

/// The CLI's flags for the same request.
fn flags(b: &Value) -> Vec<String> {
    let mut argv = vec!["workbook".to_string(), "stick-state-machine".to_string()];
    for (k, v) in b.as_object().expect("an object") {
        let fields = api::fields();
        let f = fields.iter().find(|f| f.key == *k).expect("a field");
        let text = v.as_str().map_or(v.to_string(), str::to_string);
        argv.push(f.flag.clone());
        argv.push(text);
    }
    argv.extend(["--json", "--no-figures"].map(String::from));
    argv
}

/// The CLI's exit code, stdout and stderr, in-process.
fn cli(argv: &[String]) -> (i32, String, String) {
    let (mut out, mut err) = (Vec::new(), Vec::new());
    let code = run_cli(argv, &mut out, &mut err);
    (
        code,
        String::from_utf8(out).expect("utf-8"),
        String::from_utf8(err).expect("utf-8"),
    )
}

/// The lab's answer to a request body, in-process: `Ok(json)` or the error.
fn lab_run(b: &Value) -> Result<Value, api::ApiError> {
    let req = api::parse_run(b.to_string().as_bytes())?;
    Ok(simulate::run(&req))
}

#[test]
fn the_endpoint_computes_the_clis_numbers_on_several_scenes() {
    let scenes = [
        json!({}),
        json!({"scene": "authors", "theta0_rad": 0.4280861692, "gamma": 10}),
        json!({"theta0_rad": 0.5, "mu": 0.6, "gamma": 4.5}),
        json!({"scene": "authors", "theta0_rad": 0.35, "gamma": 8, "method": "dopri5", "rtol": 1e-8}),
        json!({"stiffness": 0.5, "duration_s": 1}), // a spring too weak: the stick falls
        json!({"frequency_hz": 55, "length_m": 0.3, "mass_kg": 2.5, "damping": 0.03, "rules": "printed"}),
    ];
    let mut outcomes = Vec::new();
    for over in scenes {
        let b = body(over);
        let lab = lab_run(&b).unwrap_or_else(|e| panic!("{b}: {e:?}"));
        let (code, out, err) = cli(&flags(&b));
        assert!(code == 0 || code == 1, "{b}: CLI exit {code}: {err}");
        let cli: Value = serde_json::from_str(&out).expect("the CLI's JSON");
        let report = &lab["report"];
        // every parameter and every result of the lab is the CLI's, to the last digit
        let params = report["params"].as_object().expect("params");
        assert_eq!(params.len(), 16, "{b}: {params:?}");
        for (k, v) in params {
            assert_eq!(v, &cli["params"][k], "{b}: params.{k}");
        }
        let results = report["results"].as_object().expect("results");
        assert!(results.len() >= 8, "{b}: {results:?}");
        for (k, v) in results {
            assert_eq!(v, &cli["results"][k], "{b}: results.{k}");
        }
        // the download is the same object, as the CLI's line
        let text: Value = serde_json::from_str(lab["report_text"].as_str().expect("text"))
            .expect("report_text is JSON");
        assert_eq!(&text, report);
        outcomes.push(results["outcome"].as_str().expect("outcome").to_string());
    }
    assert!(outcomes.iter().any(|o| o == "completed"), "{outcomes:?}");
    assert!(outcomes.iter().any(|o| o == "fell"), "{outcomes:?}");
}

#[test]
fn the_frames_follow_the_run() {
    let lab = lab_run(&body(json!({}))).expect("a run");
    let f = &lab["frames"];
    let t: Vec<f64> = serde_json::from_value(f["t_s"].clone()).expect("times");
    let x: Vec<f64> = serde_json::from_value(f["x_c_m"].clone()).expect("x_c");
    let modes = f["mode"].as_str().expect("modes");
    // 40 frames per drive cycle over 2 s at 30 Hz, evenly spaced, starting at 0
    assert!((2390..=2410).contains(&t.len()), "{} frames", t.len());
    assert_eq!(modes.chars().count(), t.len());
    assert_eq!(t[0], 0.0);
    let dt = 1.0 / 30.0 / 40.0;
    // (times are sent to 7 significant digits: 1e-7 s here)
    assert!(t.windows(2).all(|w| (w[1] - w[0] - dt).abs() < 1e-6));
    // the CLI's mean speed from the trace's own positions (over whole cycles)
    let v = lab["report"]["results"]["mean_velocity_mps"]
        .as_f64()
        .expect("v");
    let n = t.len() - 1;
    let v_frames = (x[n] - x[0]) / (t[n] - t[0]);
    assert!((v_frames - v).abs() < 2e-3 * v.abs(), "{v_frames} vs {v}");
    // all four letters are modes, and the jamming scene uses flight, pivot and a slide
    assert!(modes.chars().all(|c| "FPLR".contains(c)));
    for c in ['F', 'P', 'R'] {
        assert!(modes.contains(c), "no {c}");
    }
}

#[test]
fn out_of_range_values_get_the_clis_own_line() {
    for over in [
        json!({"mu": 5}),
        json!({"mu": "abc"}),
        json!({"mu": "NaN"}),
        json!({"mu": "inf"}),
        json!({"theta0_rad": 1.6}),
        json!({"gamma": 1e300}),
        json!({"duration_s": 2000}),
        json!({"duration_s": -1}),
        json!({"scene": "mars"}),
        json!({"method": "euler"}),
        json!({"rtol": 0.5}),
        json!({"g_mps2": 100}),
    ] {
        let b = body(over.clone());
        let e = lab_run(&b).expect_err("refused");
        let (code, _, err) = cli(&flags(&b));
        assert_eq!(code, 2, "{over}: CLI exit");
        assert_eq!(e.status, 400, "{over}");
        assert_eq!(
            e.reason,
            err.trim_end(),
            "{over}: the lab's line is the CLI's"
        );
        assert!(!e.reason.contains('\n'), "{over}: one line");
    }
}

#[test]
fn the_lab_bounds_its_runs_by_drive_cycles() {
    // 40 s at 30 Hz: within the CLI's budget, beyond the lab's 1000 cycles
    let e = lab_run(&body(json!({"duration_s": 40}))).expect_err("refused");
    assert_eq!(e.status, 400);
    assert!(
        e.reason.contains("--duration-s") && e.reason.contains("1000"),
        "{}",
        e.reason
    );
    assert!(lab_run(&body(json!({"duration_s": 30}))).is_ok());
}

/// One HTTP/1.0 request to the lab (so that the answer is not chunked): (status, body).
fn http(addr: SocketAddr, head: &str, payload: &[u8]) -> (u16, String) {
    let mut s = TcpStream::connect(addr).expect("connect");
    let req = format!(
        "{head}\r\nContent-Type: application/json\r\nContent-Length: {}\r\nConnection: close\r\n\r\n",
        payload.len()
    );
    s.write_all(req.as_bytes()).expect("write");
    let _ = s.write_all(payload);
    let mut text = String::new();
    s.read_to_string(&mut text).expect("read");
    let status = text
        .split(' ')
        .nth(1)
        .and_then(|c| c.parse().ok())
        .unwrap_or(0);
    let body = text.split("\r\n\r\n").nth(1).unwrap_or("").to_string();
    (status, body)
}

fn post(addr: SocketAddr, path: &str, payload: &[u8]) -> (u16, String) {
    http(
        addr,
        &format!("POST {path} HTTP/1.0\r\nHost: 127.0.0.1:{}", addr.port()),
        payload,
    )
}

/// The reason of an error answer.
fn reason(body: &str) -> String {
    let v: Value = serde_json::from_str(body).unwrap_or_else(|_| panic!("not JSON: {body}"));
    v["error"].as_str().expect("an error line").to_string()
}

#[test]
fn bad_requests_get_a_status_and_a_reason_over_http() {
    let lab = Lab::bind(IpAddr::V4(Ipv4Addr::LOCALHOST), 0).expect("bind");
    let addr = lab.addr();
    let stop = lab.stopper();
    let serving = std::thread::spawn(move || lab.serve());
    let good = body(json!({"seq": 7})).to_string();
    let nan = good.replace("\"mu\":0.4", "\"mu\":NaN");
    let huge = good.replace("\"mu\":0.4", "\"mu\":1e999");
    let huge_finite = good.replace("\"mu\":0.4", "\"mu\":1e300");
    let missing = body(json!({})).to_string().replace("\"mu\":0.4,", "");
    let unknown = body(json!({"colour": "red"})).to_string();
    let wrong_type = body(json!({"mu": [0.4]})).to_string();
    let too_big = format!("{{\"scene\": \"{}\"}}", "x".repeat(api::MAX_BODY_BYTES));
    let cases: [(&[u8], u16, &str); 10] = [
        (b"{\"mu\": 0.4", 400, "malformed JSON"),
        (b"", 400, "malformed JSON"),
        (b"[1, 2]", 400, "JSON object"),
        (nan.as_bytes(), 400, "malformed JSON"),
        (huge.as_bytes(), 400, "number out of range"),
        (huge_finite.as_bytes(), 400, "invalid value 1e300 for --mu"),
        (missing.as_bytes(), 400, "missing field `mu`"),
        (unknown.as_bytes(), 400, "unknown field `colour`"),
        (wrong_type.as_bytes(), 400, "field `mu`"),
        (too_big.as_bytes(), 413, "limit"),
    ];
    for (payload, status, why) in cases {
        let (s, b) = post(addr, "/api/run", payload);
        let text = String::from_utf8_lossy(&payload[..payload.len().min(60)]).to_string();
        assert_eq!(s, status, "{text}: {b}");
        let r = reason(&b);
        assert!(r.starts_with("error: ") && r.contains(why), "{text}: {r}");
    }
    // a good run, with the page's sequence number echoed
    let (s, b) = post(addr, "/api/run", good.as_bytes());
    assert_eq!(s, 200, "{b}");
    let v: Value = serde_json::from_str(&b).expect("JSON");
    assert_eq!(v["seq"], 7);
    assert_eq!(v["report"]["results"]["outcome"], "completed");
    // the page, the scenes, wrong methods and paths, a foreign Host header
    let get =
        |path: &str, host: &str| http(addr, &format!("GET {path} HTTP/1.0\r\nHost: {host}"), b"");
    let local = format!("127.0.0.1:{}", addr.port());
    let (s, page) = get("/?mu=0.5", &local);
    assert_eq!(s, 200);
    assert!(page.contains("<canvas id=\"anim\"") && !page.contains("LAB-SCRIPT"));
    assert!(
        !page.contains("http://") && !page.contains("https://"),
        "the page loads nothing from elsewhere"
    );
    let (s, scenes) = get("/api/scenes", &local);
    assert_eq!(s, 200);
    let scenes: Value = serde_json::from_str(&scenes).expect("JSON");
    assert_eq!(scenes["authors"]["gamma"], 10.0);
    assert_eq!(get("/api/run", &local).0, 405);
    assert_eq!(get("/nothing", &local).0, 404);
    assert_eq!(get("/", &format!("evil.example:{}", addr.port())).0, 403);
    assert_eq!(get("/", &format!("localhost:{}", addr.port())).0, 200);
    stop();
    serving.join().expect("the server thread ends");
}

#[test]
fn the_map_is_chapter_6s_late_speed_and_is_kept() {
    let req = api::parse_run(body(json!({})).to_string().as_bytes()).expect("valid");
    let cache = locomotion_workbook::lab::map::MapCache::default();
    let m = cache.get(&req);
    let n = locomotion_workbook::lab::map::CELLS;
    let rows = m["speed_mps"].as_array().expect("rows");
    assert_eq!(rows.len(), n);
    assert!(rows
        .iter()
        .all(|r| r.as_array().is_some_and(|r| r.len() == n)));
    // the same scene again: the kept map, not a new computation
    assert!(std::sync::Arc::ptr_eq(&m, &cache.get(&req)));
    // another theta_0 and mu: the same map; another Gamma: another map
    let moved = api::parse_run(
        body(json!({"mu": 0.7, "theta0_rad": 0.6}))
            .to_string()
            .as_bytes(),
    )
    .expect("valid");
    assert!(std::sync::Arc::ptr_eq(&m, &cache.get(&moved)));
    // self-locking (mu > tan theta_0) at small theta_0 walks forward on the jamming
    // scene; the chapter's map shows the same (figures/stick-state-machine/speed-map)
    let forward = rows
        .iter()
        .flat_map(|r| r.as_array().expect("row"))
        .filter(|v| v.as_f64().is_some_and(|v| v > 0.0))
        .count();
    assert!(forward > n * n / 10, "{forward} forward cells");
}

/// A small deterministic generator (64-bit LCG, Knuth's constants).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.0 >> 11
    }
    fn pick<'a, T>(&mut self, xs: &'a [T]) -> &'a T {
        &xs[(self.next() % xs.len() as u64) as usize]
    }
}

#[test]
fn no_request_body_panics_the_endpoint() {
    // mutated requests: each field set to an edge value, a wrong type or a stray string;
    // fields dropped, renamed, duplicated; bytes flipped. Every answer is a run or a 4xx
    // with a one-line reason; the valid ones (a few) are run to the end.
    let values: Vec<Value> = vec![
        json!(0),
        json!(-0.0),
        json!(-1),
        json!(1e-320),
        json!(1e300),
        json!(-1e300),
        json!(std::f64::consts::FRAC_PI_2),
        json!(2),
        json!(50),
        json!(1000),
        json!(1e-14),
        json!("NaN"),
        json!("-inf"),
        json!(""),
        json!(" 0.4 "),
        json!("0x10"),
        json!("1e999"),
        json!("--json"),
        json!("jamming"),
        json!("authors"),
        json!("dopri5"),
        json!(null),
        json!(true),
        json!([]),
        json!({}),
        json!("\u{0}"),
        json!("é".repeat(70)),
        json!(u64::MAX),
        json!(i64::MIN),
    ];
    let fields = api::fields();
    let keys: Vec<&str> = fields
        .iter()
        .map(|f| f.key.as_str())
        .chain(["seq", "x", "a\nb"])
        .collect();
    let mut rng = Lcg(23);
    let (mut ran, mut refused) = (0, 0);
    for i in 0..3000 {
        let mut b = body(json!({"duration_s": 0.2}));
        for _ in 0..=(rng.next() % 3) {
            let k = *rng.pick(&keys);
            match rng.next() % 4 {
                0 => {
                    b.as_object_mut().expect("object").remove(k);
                }
                _ => b[k] = rng.pick(&values).clone(),
            }
        }
        let mut bytes = b.to_string().into_bytes();
        if i % 5 == 0 && !bytes.is_empty() {
            let at = (rng.next() % bytes.len() as u64) as usize;
            bytes[at] = (rng.next() % 256) as u8;
        }
        match api::parse_run(&bytes) {
            Ok(req) => {
                if ran < 25 {
                    let v = simulate::run(&req);
                    assert!(v["report"]["results"]["outcome"].is_string(), "{v}");
                }
                ran += 1;
            }
            Err(e) => {
                assert!(e.status == 400 || e.status == 413, "{e:?}");
                assert!(
                    e.reason.starts_with("error: ") && !e.reason.contains('\n'),
                    "{e:?}"
                );
                refused += 1;
            }
        }
    }
    assert!(ran > 25 && refused > 1000, "{ran} ran, {refused} refused");
}

#[test]
fn the_lab_subcommand_refuses_bad_flags_in_one_line() {
    for (args, why) in [
        (&["lab", "--json"][..], "--json"),
        (&["lab", "--port", "99999"][..], "--port"),
        (&["lab", "--host", "nope"][..], "--host"),
        (&["lab", "--g-mps2", "9"][..], "--g-mps2"),
    ] {
        let argv: Vec<String> = std::iter::once("workbook")
            .chain(args.iter().copied())
            .map(String::from)
            .collect();
        let (code, out, err) = cli(&argv);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(out.is_empty(), "{args:?}: {out}");
        assert!(
            err.contains(why) && err.trim_end().lines().count() == 1,
            "{args:?}: {err}"
        );
    }
}

#[test]
fn the_events_download_is_the_clis_events_file() {
    let b = body(json!({"scene": "authors", "theta0_rad": 0.4280861692, "gamma": 10}));
    let lab = lab_run(&b).expect("a run");
    let dir = tempfile::tempdir().expect("a temporary folder");
    let path = dir.path().join("events.csv");
    let mut argv = flags(&b);
    argv.extend(["--events".to_string(), path.display().to_string()]);
    let (code, _, err) = cli(&argv);
    assert_eq!(code, 0, "{err}");
    let file = std::fs::read_to_string(&path).expect("the CLI's events file");
    assert!(file.lines().count() > 50, "{file}");
    assert_eq!(lab["events_csv"].as_str().expect("csv"), file);
}

#[test]
fn the_pages_controls_are_the_flag_tables_entries() {
    // the page builds its sliders and menus from /api/scenes `controls`: the flag
    // table's lab entries, with their ranges (or the lab's own ends) and reasons
    use locomotion_workbook::flags::{main_run, Scale};
    let controls = api::scenes()["controls"].clone();
    let controls = controls.as_array().expect("a list");
    let shown: Vec<_> = main_run::LAB
        .iter()
        .filter(|f| f.control.is_some())
        .collect();
    assert_eq!(controls.len(), shown.len());
    let fields = api::fields();
    for (c, f) in controls.iter().zip(shown) {
        let ctl = f.control.expect("a control");
        let key = c["key"].as_str().expect("a key");
        assert_eq!(c["flag"], f.name, "{key}");
        let (lo, hi) = ctl.ends.unwrap_or((f.range.lo, f.range.hi));
        assert_eq!(c["min"].as_f64(), Some(lo), "{key}");
        assert_eq!(c["max"].as_f64(), Some(hi), "{key}");
        assert_eq!(c["reason"], f.reason, "{key}");
        // every control but the rod's is a field of a request, required as it is shown
        if key != api::ROD_MASS_FIELD {
            let field = fields.iter().find(|x| x.key == key).expect("a field");
            assert_eq!(
                api::required(field),
                !matches!(ctl.scale, Scale::Menu(_)),
                "{key}"
            );
        }
    }
    let by = |k: &str| controls.iter().find(|c| c["key"] == k).expect(k).clone();
    assert_eq!(by("mu")["max"].as_f64(), Some(2.0));
    assert_eq!(by("theta0_rad")["min_open"].as_bool(), Some(true));
    assert_eq!(by("rtol")["default"].as_f64(), Some(1e-10));
    assert_eq!(by("duration_s")["own"].as_bool(), Some(true));
    // the menus' choices are the scenes' own
    let m = &api::scenes()["choices"]["method"];
    assert_eq!(m[0]["name"], "dop853");
}
