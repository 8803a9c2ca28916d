//! `workbook`: the command-line entry point. Parse, dispatch, map errors to exit codes.
//!
//! Standard output is watched (issue 28): a write to it that fails (`> /dev/full`) ends
//! the command with exit code 3 and the line `error: cannot write to stdout: ...`, for
//! every command, `--help` included; a reader that closed the pipe (`| head -1`, EPIPE)
//! ends it quietly with the command's own exit code (0 for a run that went well), as
//! Unix filters do: no panic, no error line.

use std::io::{self, ErrorKind, Write};

/// Standard output, remembering its first failed write; its errors name stdout.
struct Stdout {
    inner: io::Stdout,
    failed: Option<io::Error>,
}

impl Stdout {
    fn fail(&mut self, e: io::Error) -> io::Error {
        let named = io::Error::new(e.kind(), format!("cannot write to stdout: {e}"));
        if self.failed.is_none() {
            self.failed = Some(io::Error::new(e.kind(), named.to_string()));
        }
        named
    }
}

impl Write for Stdout {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.inner.write(buf).map_err(|e| self.fail(e))
    }

    fn flush(&mut self) -> io::Result<()> {
        self.inner.flush().map_err(|e| self.fail(e))
    }
}

fn main() {
    let mut out = Stdout {
        inner: io::stdout(),
        failed: None,
    };
    // Progress bars on stderr when it is a terminal: the top-level run only (the library
    // and the tests that run the CLI in-process stay quiet).
    locomotion_workbook::sweep::show_progress(true);
    let code = locomotion_workbook::cli::run_cli(
        std::env::args_os(),
        &mut out,
        // Not locked: progress bars draw on stderr from other threads (rayon workers,
        // the spinner's ticker); a lock held for the whole run deadlocks them on a
        // terminal (tests/pty.rs). Stdout is locked per write, as stderr.
        &mut io::stderr(),
    );
    let _ = out.flush();
    let code = match out.failed {
        None => code,
        Some(e) if e.kind() == ErrorKind::BrokenPipe => code,
        // the command already said so (its error line names stdout) and exits 3
        Some(_) if code == 3 => code,
        Some(e) => {
            let _ = writeln!(io::stderr(), "error: {e}");
            3
        }
    };
    std::process::exit(code);
}
