//! Issue 28: every attack of a hostile local client, against a live lab on 127.0.0.1 (an
//! ephemeral port, loopback only, a bounded number of connections and seconds), each
//! followed by a normal request that must still be answered; and the file and stdout
//! faults of the command line (`--events` at a FIFO or a link, a killed run's
//! temporaries, stdout on a full device or a closed pipe).

use locomotion_workbook::cli::run_cli;
use locomotion_workbook::lab::http::{Deadlines, MAX_HEAD_BYTES, MAX_URL_BYTES};
use locomotion_workbook::lab::server::{Lab, MAX_CONNECTIONS};
use serde_json::{json, Value};
use std::io::{Read, Write};
use std::net::{IpAddr, Ipv4Addr, Shutdown, SocketAddr, TcpStream};
use std::time::{Duration, Instant};

const BIN: &str = env!("CARGO_BIN_EXE_workbook");

/// A lab on an ephemeral loopback port with 1 s deadlines, served on a thread; stopped
/// when dropped.
struct Live {
    addr: SocketAddr,
    stop: Option<Box<dyn Fn()>>,
    serving: Option<std::thread::JoinHandle<()>>,
}

impl Live {
    fn start() -> Live {
        let second = Duration::from_secs(1);
        let lab = Lab::bind(IpAddr::V4(Ipv4Addr::LOCALHOST), 0)
            .expect("bind")
            .with_deadlines(Deadlines {
                head: second,
                idle: second,
                body: second,
                write: second,
            });
        let addr = lab.addr();
        let stop = lab.stopper();
        let serving = std::thread::spawn(move || lab.serve());
        Live {
            addr,
            stop: Some(Box::new(stop)),
            serving: Some(serving),
        }
    }

    fn connect(&self) -> TcpStream {
        let s = TcpStream::connect(self.addr).expect("connect");
        s.set_read_timeout(Some(Duration::from_secs(5))).unwrap();
        s.set_write_timeout(Some(Duration::from_secs(5))).unwrap();
        s
    }

    /// Sends `raw`, reads to the end: (status, head, body).
    fn raw(&self, raw: &[u8]) -> (u16, String, String) {
        let mut s = self.connect();
        let _ = s.write_all(raw);
        read_answer(&mut s)
    }

    /// A normal `GET /` must be answered 200 with the page within a second.
    fn still_answers(&self) {
        let t0 = Instant::now();
        let (status, _, body) = self.raw(
            format!(
                "GET / HTTP/1.1\r\nHost: 127.0.0.1:{}\r\nConnection: close\r\n\r\n",
                self.addr.port()
            )
            .as_bytes(),
        );
        assert_eq!(status, 200);
        assert!(body.contains("<canvas id=\"anim\""));
        let dt = t0.elapsed();
        assert!(dt < Duration::from_secs(1), "answered after {dt:?}");
    }

    /// A normal run.
    fn post_run(&self) -> (u16, String) {
        let b = run_body();
        let head = format!(
            "POST /api/run HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: {}\r\nConnection: close\r\n\r\n",
            b.len()
        );
        let (status, _, body) = self.raw(&[head.as_bytes(), b.as_bytes()].concat());
        (status, body)
    }
}

impl Drop for Live {
    fn drop(&mut self) {
        if let Some(stop) = self.stop.take() {
            stop();
        }
        if let Some(h) = self.serving.take() {
            let _ = h.join();
        }
    }
}

/// A short run of the jamming scene.
fn run_body() -> String {
    json!({
        "scene": "jamming", "theta0_rad": 0.3, "mu": 0.4, "gamma": 3, "frequency_hz": 30,
        "stiffness": 10, "damping": 0.01, "length_m": 0.15, "mass_kg": 1, "duration_s": 0.5,
    })
    .to_string()
}

/// One answer read to the end of the connection: (status, head, body).
fn read_answer(s: &mut TcpStream) -> (u16, String, String) {
    let mut bytes = Vec::new();
    let _ = s.read_to_end(&mut bytes);
    let text = String::from_utf8_lossy(&bytes).into_owned();
    let (head, body) = text.split_once("\r\n\r\n").unwrap_or((&text, ""));
    let status = head
        .split(' ')
        .nth(1)
        .and_then(|c| c.parse().ok())
        .unwrap_or(0);
    (status, head.to_string(), body.to_string())
}

/// A refusal: `status`, `Connection: close`, one JSON line `{"error": "error: ..."}`
/// containing `why`; the connection was closed (read to its end).
fn assert_refused(answer: &(u16, String, String), status: u16, why: &str, what: &str) {
    let (s, head, body) = answer;
    assert_eq!(*s, status, "{what}: {head}\n{body}");
    assert!(head.contains("Connection: close"), "{what}: {head}");
    let v: Value = serde_json::from_str(body).unwrap_or_else(|_| panic!("{what}: {body}"));
    let reason = v["error"].as_str().expect("a reason");
    assert!(
        reason.starts_with("error: ") && !reason.contains('\n') && reason.contains(why),
        "{what}: {reason}"
    );
}

#[test]
fn a_huge_content_length_is_refused_before_it_is_read() {
    let lab = Live::start();
    for route in ["GET /", "POST /api/run", "POST /api/map"] {
        for n in [
            "1000000000000",
            "30000000000",
            "16385",
            "18446744073709551615",
        ] {
            let req = format!("{route} HTTP/1.1\r\nHost: localhost\r\nContent-Length: {n}\r\n\r\n");
            let t0 = Instant::now();
            let a = lab.raw(req.as_bytes());
            assert_refused(&a, 413, "limit of 16384", &format!("{route} {n}"));
            assert!(t0.elapsed() < Duration::from_secs(1));
        }
    }
    // beyond u64: as refused; not a number: malformed
    let req =
        "POST /api/run HTTP/1.1\r\nHost: localhost\r\nContent-Length: 99999999999999999999\r\n\r\n";
    assert_refused(&lab.raw(req.as_bytes()), 413, "limit of 16384", "20 digits");
    let req = "POST /api/run HTTP/1.1\r\nHost: localhost\r\nContent-Length: -1\r\n\r\n";
    assert_refused(&lab.raw(req.as_bytes()), 400, "Content-Length", "negative");
    lab.still_answers();
    assert_eq!(lab.post_run().0, 200);
}

#[test]
fn a_greedy_pipelining_client_stalls_only_itself() {
    let lab = Live::start();
    let mut greedy = lab.connect();
    let one = "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n";
    greedy
        .write_all(one.repeat(200).as_bytes())
        .expect("pipelined");
    // the greedy client reads nothing; its connection's thread fills the socket
    std::thread::sleep(Duration::from_millis(200));
    for _ in 0..3 {
        lab.still_answers();
    }
    assert_eq!(lab.post_run().0, 200);
    // and the pipelined requests themselves are answered in order, to whoever reads
    let mut polite = lab.connect();
    polite.write_all(one.repeat(3).as_bytes()).unwrap();
    polite
        .write_all(b"GET /nothing HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n")
        .unwrap();
    let mut all = Vec::new();
    let _ = polite.read_to_end(&mut all);
    let all = String::from_utf8_lossy(&all);
    assert_eq!(all.matches("HTTP/1.1 200 OK").count(), 3);
    assert!(
        all.trim_end().ends_with("no such page: the lab is at /\"}"),
        "{}",
        &all[all.len() - 200..]
    );
    drop(greedy);
    lab.still_answers();
}

#[test]
fn slow_bodies_hold_no_run_slot_and_time_out() {
    let lab = Live::start();
    let b = run_body();
    let mut slow: Vec<TcpStream> = (0..4)
        .map(|_| {
            let mut s = lab.connect();
            let head = format!(
                "POST /api/run HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: {}\r\n\r\n{}",
                b.len(),
                &b[..1]
            );
            s.write_all(head.as_bytes()).unwrap();
            s
        })
        .collect();
    // a fifth, normal run gets a slot while the four trickle
    let t0 = Instant::now();
    let (status, body) = lab.post_run();
    assert_eq!(status, 200, "{body}");
    assert!(t0.elapsed() < Duration::from_secs(1));
    // one more byte each: the body's deadline counts from its head, not from the last byte
    for s in &mut slow {
        let _ = s.write_all(&b.as_bytes()[1..2]);
    }
    for mut s in slow {
        assert_refused(
            &read_answer(&mut s),
            408,
            "did not arrive within 1 s",
            "slow body",
        );
    }
    lab.still_answers();
}

#[test]
fn unbounded_headers_and_urls_are_refused() {
    let lab = Live::start();
    // an unfinished header line far beyond the limit: refused at the limit
    let mut s = lab.connect();
    let head = format!(
        "GET / HTTP/1.1\r\nHost: localhost\r\nX-Long: {}",
        "a".repeat(4 * MAX_HEAD_BYTES)
    );
    let _ = s.write_all(head.as_bytes());
    assert_refused(
        &read_answer(&mut s),
        431,
        "header block",
        "long header line",
    );
    // many short header lines
    let many = format!(
        "GET / HTTP/1.1\r\nHost: localhost\r\n{}\r\n",
        "X-A: b\r\n".repeat(100)
    );
    assert_refused(&lab.raw(many.as_bytes()), 431, "64 lines", "many headers");
    // a long URL, finished or not
    let url = format!(
        "GET /{} HTTP/1.1\r\nHost: localhost\r\n\r\n",
        "a".repeat(MAX_URL_BYTES)
    );
    assert_refused(&lab.raw(url.as_bytes()), 414, "request line", "long URL");
    let open = format!("GET /{}", "a".repeat(4 * MAX_URL_BYTES));
    assert_refused(
        &lab.raw(open.as_bytes()),
        414,
        "request line",
        "unfinished URL",
    );
    // a header block that never ends: refused at its deadline
    let t0 = Instant::now();
    let a = lab.raw(b"GET / HTTP/1.1\r\nHost: localhost\r\n");
    assert_refused(&a, 408, "header block did not arrive", "unfinished head");
    assert!(t0.elapsed() < Duration::from_secs(3));
    lab.still_answers();
}

#[test]
fn malformed_requests_get_a_status_a_reason_and_a_close() {
    let lab = Live::start();
    let cases: [(&str, u16, &str); 11] = [
        ("GARBAGE\r\n\r\n", 400, "malformed request line \\\"GARBAGE\\\""),
        ("GARBAGE\r\n", 400, "malformed request line"),
        ("GET\r\n\r\n", 400, "malformed request line"),
        ("GET HTTP/1.1\r\n\r\n", 400, "malformed request line"),
        ("GET / HTTP/9.9\r\nHost: localhost\r\n\r\n", 505, "HTTP/9.9"),
        ("GET / HTTP/1.1\r\nHost: localhost\r\nNoColonHere\r\n\r\n", 400, "without a colon"),
        ("GET / HTTP/1.1\r\nHost: localhost\r\nHost: evil.example\r\n\r\n", 400, "two Host"),
        ("GET / HTTP/1.1\r\nHost: evil.example\r\nHost: localhost\r\n\r\n", 400, "two Host"),
        ("GET / HTTP/1.1\r\n\r\n", 400, "needs a Host"),
        ("POST /api/run HTTP/1.1\r\nHost: localhost\r\nTransfer-Encoding: chunked\r\n\r\n0\r\n\r\n", 501, "Content-Length"),
        ("\u{1}\u{2}\u{3} / HTTP/1.1\r\n\r\n", 400, "malformed request line"),
    ];
    for (raw, status, why) in cases {
        let a = lab.raw(raw.as_bytes());
        let body = a.2.replace("\\\\", "\\");
        assert_refused(&(a.0, a.1.clone(), a.2.clone()), status, "error: ", raw);
        assert!(body.contains(why), "{raw:?}: {body}");
        lab.still_answers();
    }
    // the Host guard reads the only Host header
    let a = lab.raw(b"GET / HTTP/1.1\r\nHost: evil.example\r\nConnection: close\r\n\r\n");
    assert_eq!(a.0, 403);
}

#[test]
fn connections_beyond_the_limit_are_refused_at_once() {
    let lab = Live::start();
    let idle: Vec<TcpStream> = (0..MAX_CONNECTIONS).map(|_| lab.connect()).collect();
    std::thread::sleep(Duration::from_millis(100));
    let a = lab.raw(b"GET / HTTP/1.1\r\nHost: localhost\r\n\r\n");
    assert_refused(&a, 503, "connections at once", "one too many");
    drop(idle);
    std::thread::sleep(Duration::from_millis(100));
    lab.still_answers();
}

#[test]
fn lab_host_ipv6_prints_the_address_bound() {
    if std::net::TcpListener::bind("[::1]:0").is_err() {
        eprintln!("no IPv6 loopback here: skipped");
        return;
    }
    let mut child = std::process::Command::new(BIN)
        .args(["lab", "--host", "::1", "--port", "0"])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::null())
        .spawn()
        .expect("the lab starts");
    let mut out = child.stdout.take().expect("stdout");
    let mut line = Vec::new();
    let mut byte = [0u8; 1];
    let t0 = Instant::now();
    while !line.ends_with(b"\n") && t0.elapsed() < Duration::from_secs(10) {
        if out.read(&mut byte).unwrap_or(0) == 0 {
            break;
        }
        line.push(byte[0]);
    }
    let line = String::from_utf8_lossy(&line).into_owned();
    let url = line
        .split_whitespace()
        .find(|w| w.starts_with("http://"))
        .unwrap_or_else(|| panic!("no address in {line:?}"));
    let hostport = url.trim_start_matches("http://").trim_end_matches('/');
    assert!(hostport.starts_with("[::1]:"), "{line}");
    let addr: SocketAddr = hostport.parse().expect("an address");
    let mut s =
        TcpStream::connect_timeout(&addr, Duration::from_secs(2)).expect("something listens there");
    s.set_read_timeout(Some(Duration::from_secs(5))).unwrap();
    let req = format!("GET / HTTP/1.1\r\nHost: {hostport}\r\nConnection: close\r\n\r\n");
    s.write_all(req.as_bytes()).unwrap();
    let (status, _, _) = read_answer(&mut s);
    let _ = child.kill();
    let _ = child.wait();
    assert_eq!(status, 200);
}

/// The CLI in-process: (exit code, stdout, stderr).
fn cli(args: &[&str]) -> (i32, String, String) {
    let (mut out, mut err) = (Vec::new(), Vec::new());
    let argv: Vec<&str> = std::iter::once("workbook")
        .chain(args.iter().copied())
        .collect();
    let code = run_cli(argv, &mut out, &mut err);
    (
        code,
        String::from_utf8_lossy(&out).into_owned(),
        String::from_utf8_lossy(&err).into_owned(),
    )
}

/// A short stick run writing `--events path`.
fn events_run(path: &std::path::Path) -> (i32, String, String) {
    let p = path.to_str().expect("a UTF-8 path");
    cli(&[
        "stick-state-machine",
        "--duration-s",
        "0.5",
        "--json",
        "--no-figures",
        "--events",
        p,
    ])
}

fn mkfifo(path: &std::path::Path) {
    let ok = std::process::Command::new("mkfifo")
        .arg(path)
        .status()
        .is_ok_and(|s| s.success());
    assert!(ok, "mkfifo {}", path.display());
}

#[test]
fn events_never_replace_what_is_not_a_regular_file() {
    use std::os::unix::fs::{symlink, FileTypeExt};
    let dir = tempfile::tempdir().expect("a temporary folder");
    let fifo = dir.path().join("fifo.csv");
    mkfifo(&fifo);
    let folder = dir.path().join("folder.csv");
    std::fs::create_dir(&folder).unwrap();
    let to_fifo = dir.path().join("to-fifo.csv");
    symlink(&fifo, &to_fifo).unwrap();
    for (path, what) in [
        (&fifo, "a FIFO"),
        (&folder, "a folder"),
        (&to_fifo, "a FIFO"),
    ] {
        let (code, out, err) = events_run(path);
        assert_eq!(code, 3, "{}: {err}", path.display());
        assert!(out.is_empty());
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(
            err.contains("--events")
                && err.contains(&path.display().to_string())
                && err.contains(what),
            "{err}"
        );
    }
    assert!(std::fs::symlink_metadata(&fifo)
        .unwrap()
        .file_type()
        .is_fifo());
    assert!(std::fs::symlink_metadata(&to_fifo)
        .unwrap()
        .file_type()
        .is_symlink());
    assert!(folder.is_dir());
    // a link to a regular file and a dangling link: written through, the links stay
    let target = dir.path().join("real.csv");
    std::fs::write(&target, "old").unwrap();
    let link = dir.path().join("link.csv");
    symlink("real.csv", &link).unwrap();
    let (code, _, err) = events_run(&link);
    assert_eq!(code, 0, "{err}");
    assert!(std::fs::read_to_string(&target)
        .unwrap()
        .starts_with("t_s,from,to"));
    assert!(std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
    let dangling = dir.path().join("dangling.csv");
    symlink("made.csv", &dangling).unwrap();
    assert_eq!(events_run(&dangling).0, 0);
    assert!(std::fs::read_to_string(dir.path().join("made.csv"))
        .unwrap()
        .starts_with("t_s,"));
    // nothing else was left in the folder (no temporary)
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 7);
}

#[test]
fn a_killed_runs_temporaries_are_removed_by_the_next_run() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    // a run killed between its write and its rename (SIGKILL: nothing of it runs after)
    let mut child = std::process::Command::new(BIN)
        .args([
            "stick-state-machine",
            "--duration-s",
            "2000",
            "--allow-long-runs",
            "--no-figures",
            "--events",
        ])
        .arg(dir.path().join("events.csv"))
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let dead = child.id();
    child.kill().unwrap();
    child.wait().unwrap();
    // its temporary, as it would have been left
    let stale = dir.path().join(format!(".events.csv.{dead}-0.tmp.csv"));
    std::fs::write(&stale, "t_s,from,to\n0.1,").unwrap();
    let (code, _, err) = events_run(&dir.path().join("events.csv"));
    assert_eq!(code, 0, "{err}");
    assert!(!stale.exists(), "the killed run's temporary is left");
    let names: Vec<String> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(names, ["events.csv"]);
}

/// `workbook args` with stdout on `stdout`: (exit code, stderr).
fn with_stdout(args: &[&str], stdout: std::process::Stdio) -> (Option<i32>, String) {
    let out = std::process::Command::new(BIN)
        .args(args)
        .stdout(stdout)
        .stderr(std::process::Stdio::piped())
        .output()
        .expect("runs");
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn a_failed_write_to_stdout_is_exit_3_and_names_stdout() {
    if !std::path::Path::new("/dev/full").exists() {
        eprintln!("no /dev/full here: skipped");
        return;
    }
    for args in [
        &["--help"][..],
        &["render", "--help"],
        &["list"],
        &["effective-mass", "--quick", "--no-figures", "--json"],
        &["effective-mass", "--quick", "--no-figures"],
    ] {
        let full = std::fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .unwrap();
        let (code, err) = with_stdout(args, full.into());
        assert_eq!(code, Some(3), "{args:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(
            err.starts_with("error: cannot write to stdout"),
            "{args:?}: {err}"
        );
    }
}

#[test]
fn a_closed_stdout_pipe_ends_quietly_for_every_command() {
    for args in [
        &["--help"][..],
        &["list"],
        &["effective-mass", "--quick", "--no-figures", "--json"],
    ] {
        let mut child = std::process::Command::new(BIN)
            .args(args)
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        drop(child.stdout.take()); // the reader goes away before anything is written
        let out = child.wait_with_output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(0), "{args:?}: {err}");
        assert!(err.is_empty(), "{args:?}: {err}");
    }
}

#[test]
fn render_help_states_the_exit_code_check_uses() {
    let (code, out, _) = cli(&["render", "--help"]);
    assert_eq!(code, 0);
    let stale = locomotion_workbook::render::STALE_EXIT;
    assert!(
        out.contains(&format!("exit {stale} and name each stale table")),
        "{out}"
    );
    // (tests/cli.rs checks that --check on a stale text exits with STALE_EXIT)
}

#[test]
fn a_half_closed_client_gets_its_answer() {
    // a client that sends its request and shuts its sending side still gets the answer
    let lab = Live::start();
    let mut s = lab.connect();
    s.write_all(b"GET /api/scenes HTTP/1.1\r\nHost: localhost\r\n\r\n")
        .unwrap();
    s.shutdown(Shutdown::Write).unwrap();
    let (status, _, body) = read_answer(&mut s);
    assert_eq!(status, 200);
    assert!(body.contains("jamming"));
}
