//! `workbook`: the command-line entry point. Parse, dispatch, map errors to exit codes.

fn main() {
    // Progress bars on stderr when it is a terminal: the top-level run only (the library
    // and the tests that run the CLI in-process stay quiet).
    locomotion_workbook::sweep::show_progress(true);
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
