//! `workbook`: the command-line entry point. Parse, dispatch, map errors to exit codes.

fn main() {
    let code = locomotion_workbook::cli::run_cli(
        std::env::args_os(),
        &mut std::io::stdout(),
        // Not locked: progress bars draw on stderr from other threads (rayon workers,
        // the spinner's ticker); a lock held for the whole run deadlocks them on a
        // terminal (tests/pty.rs). Stdout is locked per write, as stderr.
        &mut std::io::stderr(),
    );
    std::process::exit(code);
}
