//! `workbook lab`: the stick of chapter 6 in the browser, driven by the real simulator.
//!
//! A local web server (bound to 127.0.0.1 unless `--host` says otherwise) serves one
//! self-contained page ([`assets`]) with sliders for the stick's parameters, the gait
//! animated from the simulator's trajectory, the run's numbers, its downloads and the
//! (theta_0, mu) speed map. The page posts its parameters as JSON to `/api/run`
//! ([`simulate`]) and `/api/map` ([`map`]); [`api`] turns them into the flags of
//! `workbook stick-state-machine` and validates them with the CLI's own parser and
//! ranges, so that the lab and the CLI accept the same values, refuse the others with
//! the same line, and compute the same numbers (tests/lab.rs). [`server`] and [`http`]
//! bound every request (tests/lab_attacks.rs) and run the simulations on worker threads. The lab writes no file.

pub mod api;
pub mod assets;
pub mod http;
pub mod map;
pub mod server;
pub mod simulate;

use crate::error::{Result, WorkbookError};
use std::io::Write;

pub use crate::grammar::{LabArgs as Args, DEFAULT_PORT};

/// Runs the lab until interrupted (Ctrl-C). Prints the address on `out`; all printing
/// happens on the calling thread.
pub fn run(args: &Args, out: &mut dyn Write) -> Result<i32> {
    let lab = server::Lab::bind(args.host, args.port).map_err(|e| {
        WorkbookError::Io(format!(
            "cannot listen on {}:{} (--host, --port): {e}",
            args.host, args.port
        ))
    })?;
    let addr = lab.addr();
    // the address bound, as a URL (`http://[::1]:8023/` for IPv6)
    let url = format!("http://{addr}/");
    if !args.host.is_loopback() {
        eprintln!(
            "warning: the lab listens on {addr}, reachable from other computers on the network, with no authentication"
        );
    }
    writeln!(out, "workbook lab: open {url} (Ctrl-C stops the lab)")?;
    out.flush()?;
    if args.open {
        if let Err(e) = open_browser(&url) {
            writeln!(
                out,
                "(could not open a browser: {e}; open the address by hand)"
            )?;
            out.flush()?;
        }
    }
    lab.serve();
    Ok(0)
}

/// Opens `url` in the system's browser.
fn open_browser(url: &str) -> std::io::Result<()> {
    use std::process::{Command, Stdio};
    let mut cmd = if cfg!(target_os = "macos") {
        Command::new("open")
    } else if cfg!(windows) {
        let mut c = Command::new("cmd");
        c.args(["/C", "start", ""]);
        c
    } else {
        Command::new("xdg-open")
    };
    cmd.arg(url)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .map(drop)
}
