//! The command line as typed, before and after clap: arguments that are not UTF-8, a
//! negative number after a value flag, and clap's error as the CLI's one line.

use std::ffi::OsString;

/// The one line the CLI prints for a clap error: clap's first paragraph (the error,
/// naming the flag and the value), its indented continuation lines (such as
/// `[possible values: ...]`) joined with a space, a line break inside the value shown as
/// `\n`, and a pointer to `--help`. The lab answers with the same line.
pub fn clap_error_line(e: &clap::Error) -> String {
    let rendered = e.render().to_string();
    let first = rendered.trim_start().split("\n\n").next().unwrap_or("");
    let mut line = String::new();
    for (i, l) in first.trim_end().lines().enumerate() {
        if i > 0 {
            let continuation = l.starts_with(' ') || l.starts_with('\t');
            line.push_str(if continuation { " " } else { "\\n" });
        }
        line.push_str(if i > 0 { l.trim_start() } else { l });
    }
    if line.is_empty() {
        line = "error: bad arguments".into();
    }
    format!("{} (see --help)", line.replace('\r', "\\r"))
}

/// The error line for an argument that is not UTF-8, naming its flag (`--x VALUE` or
/// `--x=VALUE`); clap's own message names none.
pub(crate) fn non_utf8_value(args: &[OsString]) -> Option<String> {
    let i = args.iter().skip(1).position(|a| a.to_str().is_none())? + 1;
    let bytes = args[i].as_encoded_bytes();
    let flag = if bytes.starts_with(b"--") {
        let end = bytes.iter().position(|&b| b == b'=').unwrap_or(bytes.len());
        String::from_utf8_lossy(&bytes[..end]).into_owned()
    } else {
        match args[i - 1].to_str() {
            Some(prev) if prev.starts_with("--") => prev.to_string(),
            _ => "an argument".to_string(),
        }
    };
    Some(format!(
        "error: invalid value {:?} for {flag}: not valid UTF-8 text (see --help)",
        args[i].to_string_lossy()
    ))
}

/// Joins a value flag and a following negative number into one argument
/// (`--theta0-rad -.3` into `--theta0-rad=-.3`): clap takes a leading `-` for a flag
/// unless the text looks like a plain decimal, and refuses `-.5` or `-3e-1`. Only a
/// token that parses as a number is joined, so no flag can be swallowed.
pub(crate) fn join_negative_values(cmd: &clap::Command, args: Vec<OsString>) -> Vec<OsString> {
    fn value_flags(cmd: &clap::Command, names: &mut Vec<String>) {
        for a in cmd.get_arguments() {
            if let (Some(long), true) = (a.get_long(), a.get_action().takes_values()) {
                names.push(format!("--{long}"));
            }
        }
        for sub in cmd.get_subcommands() {
            value_flags(sub, names);
        }
    }
    let mut names = Vec::new();
    value_flags(cmd, &mut names);
    let mut out: Vec<OsString> = Vec::with_capacity(args.len());
    let mut it = args.into_iter().peekable();
    while let Some(a) = it.next() {
        let is_value_flag = a.to_str().is_some_and(|s| names.iter().any(|n| n == s));
        let next_is_negative = it
            .peek()
            .and_then(|n| n.to_str())
            .is_some_and(|n| n.starts_with('-') && n.len() > 1 && n.parse::<f64>().is_ok());
        match (is_value_flag, next_is_negative, it.peek().cloned()) {
            (true, true, Some(v)) => {
                let mut joined = a.clone();
                joined.push("=");
                joined.push(&v);
                it.next();
                out.push(joined);
            }
            _ => out.push(a),
        }
    }
    out
}
