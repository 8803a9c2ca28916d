//! `workbook`: the command-line entry point. Parse, dispatch, map errors to exit codes.

fn main() {
    let code = locomotion_workbook::cli::run_cli(
        std::env::args_os(),
        &mut std::io::stdout().lock(),
        &mut std::io::stderr().lock(),
    );
    std::process::exit(code);
}
