//! The workbook as a person runs it: on a terminal, interrupted with Ctrl-C, several
//! runs at once.
//!
//! Every other test runs the workbook with stdout and stderr on pipes, where the progress
//! bars hide themselves; a lock held on stderr while the bars drew from other threads
//! once hung every chapter on a real terminal and no test saw it. Here the built binary
//! runs under a pseudo-terminal made by `script` (util-linux, on every Debian), with a
//! time limit: a hang fails the test instead of stalling it.

use std::io::Read;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const BIN: &str = env!("CARGO_BIN_EXE_workbook");

/// Quotes `s` for `sh`.
fn sh_quote(s: &str) -> String {
    format!("'{}'", s.replace('\'', r"'\''"))
}

/// Runs `workbook <args>` with stdin, stdout and stderr on a pseudo-terminal; returns the
/// exit code (`None`: killed at the time limit) and everything the terminal showed.
fn on_terminal(args: &[&str], limit: Duration) -> (Option<i32>, String) {
    let line: Vec<String> = std::iter::once(BIN)
        .chain(args.iter().copied())
        .map(sh_quote)
        .collect();
    let mut child = Command::new("script")
        .args(["-q", "-e", "-c", &line.join(" "), "/dev/null"])
        .stdin(Stdio::piped()) // kept open: a closed stdin would end the session
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("`script` (util-linux) runs the workbook on a pseudo-terminal");
    let mut pipe = child.stdout.take().expect("stdout");
    let reader = std::thread::spawn(move || {
        let mut bytes = Vec::new();
        let _ = pipe.read_to_end(&mut bytes);
        String::from_utf8_lossy(&bytes).into_owned()
    });
    let start = Instant::now();
    let code = loop {
        if let Some(status) = child.try_wait().expect("wait") {
            break status.code();
        }
        if start.elapsed() > limit {
            let _ = Command::new("pkill").args(["-KILL", "-f", BIN]).status();
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    drop(child.stdin.take());
    (code, reader.join().unwrap_or_default())
}

/// The largest `pos` of progress bars drawn as `] pos/len` on the terminal.
fn progress_positions(screen: &str) -> Vec<(u64, u64)> {
    screen
        .split("] ")
        .skip(1)
        .filter_map(|rest| {
            let (pos, tail) = rest.split_once('/')?;
            let len: String = tail.chars().take_while(char::is_ascii_digit).collect();
            Some((pos.trim().parse().ok()?, len.parse().ok()?))
        })
        .collect()
}

#[test]
fn all_quick_finishes_on_a_terminal_and_its_progress_bars_advance() {
    let (code, screen) = on_terminal(
        &["all", "--quick", "--no-figures"],
        Duration::from_secs(600),
    );
    assert_eq!(code, Some(0), "hung or failed on a terminal:\n{screen}");
    let bars = progress_positions(&screen);
    assert!(
        bars.iter().any(|&(pos, len)| pos > 0 && pos < len),
        "no progress bar advanced on the terminal: {bars:?}"
    );
    assert!(screen.contains("All chapters:"), "no totals:\n{screen}");
}

#[test]
fn each_chapter_and_render_check_finish_on_a_terminal() {
    for c in locomotion_workbook::chapters::CHAPTERS.iter() {
        let (code, screen) =
            on_terminal(&[c.id, "--quick", "--no-figures"], Duration::from_secs(300));
        assert_eq!(code, Some(0), "{}: hung or failed:\n{screen}", c.id);
        assert!(screen.contains("Verdicts:"), "{}:\n{screen}", c.id);
    }
    let (code, screen) = on_terminal(&["render", "--check"], Duration::from_secs(900));
    assert_eq!(code, Some(0), "render --check on a terminal:\n{screen}");
}

/// Why a written figure file is not whole, if it is not.
fn torn(path: &Path) -> Option<String> {
    let bytes = std::fs::read(path).ok()?;
    let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
    let whole = match ext {
        "png" => bytes.starts_with(b"\x89PNG") && bytes.ends_with(&[0xAE, 0x42, 0x60, 0x82]),
        "gif" => bytes.starts_with(b"GIF8") && bytes.ends_with(b";"),
        "svg" => String::from_utf8_lossy(&bytes)
            .trim_end()
            .ends_with("</svg>"),
        _ => !bytes.is_empty(),
    };
    (!whole).then(|| format!("{} ({} bytes)", path.display(), bytes.len()))
}

/// Every file below `dir`, recursively.
fn files(dir: &Path) -> Vec<std::path::PathBuf> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).into_iter().flatten().flatten() {
        let p = e.path();
        if p.is_dir() {
            out.extend(files(&p));
        } else {
            out.push(p);
        }
    }
    out
}

#[test]
fn ctrl_c_never_leaves_a_torn_figure() {
    // Interrupted at several moments of a run that writes figures (SIGINT, as Ctrl-C
    // sends): every figure on disk is whole, and what a killed run leaves is only its
    // hidden temporary, which .gitignore lists.
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path().to_str().unwrap();
    for delay_ms in [150, 400, 900, 1600, 2500] {
        let mut child = Command::new(BIN)
            .args(["all", "--quick", "--figures", root])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        std::thread::sleep(Duration::from_millis(delay_ms));
        let _ = Command::new("kill")
            .args(["-INT", &child.id().to_string()])
            .status();
        let _ = child.wait();
    }
    let mut bad = Vec::new();
    for f in files(dir.path()) {
        let name = f.file_name().unwrap().to_string_lossy().into_owned();
        if name.starts_with('.') && name.contains(".tmp.") {
            continue; // an interrupted temporary: never the figure itself
        }
        bad.extend(torn(&f));
    }
    assert!(bad.is_empty(), "torn figures after Ctrl-C: {bad:?}");
}

#[test]
fn concurrent_runs_share_a_figures_folder() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path().to_str().unwrap();
    let children: Vec<_> = (0..6)
        .map(|_| {
            Command::new(BIN)
                .args(["effective-mass", "--figures", root])
                .stdout(Stdio::null())
                .stderr(Stdio::piped())
                .spawn()
                .unwrap()
        })
        .collect();
    for c in children {
        let out = c.wait_with_output().unwrap();
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let bad: Vec<String> = files(dir.path()).iter().filter_map(|f| torn(f)).collect();
    assert!(bad.is_empty(), "{bad:?}");
}
