//! Errors of the workbook and the validation of user input.
//!
//! Every flag a reader can set is checked before a chapter computes anything. A bad
//! value gives one line naming the flag, the value, the valid range and why, and the
//! command exits with code 2; so does a run whose estimated work is beyond the budget.
//! Output that cannot be written (a `--figures` folder, checked first) exits with code 3, a run that produced a
//! non-finite number with 1 (a defect), a closed stdout quietly with 0 (see
//! [`WorkbookError::exit_code`]).

use std::fmt;

/// Everything that can stop a chapter before it produces a report.
#[derive(Debug, Clone, PartialEq)]
pub enum WorkbookError {
    /// A flag's value is outside its valid range (exit code 2).
    BadInput {
        /// The flag as the user typed it, for example `--angle-deg`.
        flag: String,
        /// The offending value, as text.
        value: String,
        /// The valid range in words, for example `-90 < angle < 90 (degrees)`.
        valid: String,
    },
    /// A run whose estimated work is beyond the stated budget (exit code 2): the line
    /// names the flag to lower and the override flag.
    OverBudget {
        /// The flag to lower, for example `--duration-s`.
        flag: String,
        /// The estimate in words, for example `3e7 drive cycles (about 50 min)`.
        estimate: String,
        /// The budget in words.
        budget: String,
    },
    /// `--figures` (or another output path) cannot be written (exit code 3), found
    /// before any computation starts.
    Output {
        /// The flag, for example `--figures`.
        flag: String,
        /// The path as given.
        path: String,
        /// Why it cannot be written.
        why: String,
    },
    /// A run produced a non-finite number (outcome `invalid`; exit code 1: a defect of
    /// the workbook, since every accepted input is validated not to).
    Invalid(String),
    /// The reader closed standard output (`workbook all | head`): end quietly, exit 0.
    BrokenPipe,
    /// Writing a figure or a file failed (exit code 3, like [`WorkbookError::Output`]).
    Io(String),
}

impl WorkbookError {
    /// Builds a [`WorkbookError::BadInput`].
    pub fn bad_input(flag: &str, value: impl fmt::Display, valid: &str) -> Self {
        WorkbookError::BadInput {
            flag: flag.to_string(),
            value: value.to_string(),
            valid: valid.to_string(),
        }
    }

    /// The process exit code for this error: 2 for bad input or a run over budget, 3
    /// for output that cannot be written (the `--figures` folder, checked first, or a
    /// write failing later), 0 for a closed stdout pipe, 1 for a run ended invalid.
    pub fn exit_code(&self) -> i32 {
        match self {
            WorkbookError::BadInput { .. } | WorkbookError::OverBudget { .. } => 2,
            WorkbookError::Output { .. } | WorkbookError::Io(_) => 3,
            WorkbookError::BrokenPipe => 0,
            WorkbookError::Invalid(_) => 1,
        }
    }
}

impl fmt::Display for WorkbookError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            WorkbookError::BadInput { flag, value, valid } => {
                write!(
                    f,
                    "error: invalid value {value} for {flag}: valid range is {valid}"
                )
            }
            WorkbookError::OverBudget {
                flag,
                estimate,
                budget,
            } => write!(
                f,
                "error: the run needs {estimate}, beyond the budget of {budget}: lower {flag} (or pass --allow-long-runs)"
            ),
            WorkbookError::Output { flag, path, why } => {
                let what = if flag == "--figures" { "figures to " } else { "" };
                write!(f, "error: cannot write {what}{path} given by {flag}: {why}")
            }
            WorkbookError::Invalid(why) => write!(
                f,
                "error: the run ended invalid: {why} (a defect of the workbook: accepted inputs must not produce it)"
            ),
            WorkbookError::BrokenPipe => Ok(()),
            WorkbookError::Io(msg) => write!(f, "error: {msg}"),
        }
    }
}

impl std::error::Error for WorkbookError {}

impl From<std::io::Error> for WorkbookError {
    fn from(e: std::io::Error) -> Self {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            WorkbookError::BrokenPipe
        } else {
            WorkbookError::Io(e.to_string())
        }
    }
}

/// Result type of the workbook.
pub type Result<T> = std::result::Result<T, WorkbookError>;

/// Checks that `value` is finite and satisfies `ok`; otherwise a bad-input error
/// naming `flag` and the range `valid`.
///
/// ```
/// use locomotion_workbook::error::check;
/// assert!(check("--mu", 0.4, |m| m >= 0.0, "mu >= 0").is_ok());
/// assert!(check("--mu", f64::NAN, |m| m >= 0.0, "mu >= 0").is_err());
/// ```
pub fn check(flag: &str, value: f64, ok: impl Fn(f64) -> bool, valid: &str) -> Result<f64> {
    if value.is_finite() && ok(value) {
        Ok(value)
    } else {
        Err(WorkbookError::bad_input(flag, num(value), valid))
    }
}

/// `value > 0` and finite.
pub fn positive(flag: &str, value: f64, unit: &str) -> Result<f64> {
    check(
        flag,
        value,
        |v| v > 0.0,
        &format!("a finite number > 0 ({unit})"),
    )
}

/// `lo <= value <= hi` and finite; the error line gives the range, the unit and why.
///
/// ```
/// use locomotion_workbook::error::range;
/// assert!(range("--mu", 0.4, 0.0, 2.0, "dimensionless", "dry friction").is_ok());
/// assert!(range("--mu", 2.5, 0.0, 2.0, "dimensionless", "dry friction").is_err());
/// ```
pub fn range(flag: &str, value: f64, lo: f64, hi: f64, unit: &str, why: &str) -> Result<f64> {
    check(
        flag,
        value,
        |v| v >= lo && v <= hi,
        &format!("{} <= value <= {} ({unit}; {why})", num(lo), num(hi)),
    )
}

/// A number as a reader types it: plain between 1e-3 and 1e4, else scientific.
pub fn num(x: f64) -> String {
    if x == 0.0 || !x.is_finite() || (1e-3..1e4).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// Parses a velocity pair `X,Y` (m/s) for clap; both parts must be finite numbers.
pub fn parse_pair(s: &str) -> std::result::Result<[f64; 2], String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    if parts.len() != 2 {
        return Err(format!(
            "expected X,Y (two finite numbers in m/s, comma-separated), got '{s}'"
        ));
    }
    let mut out = [0.0; 2];
    for (o, p) in out.iter_mut().zip(&parts) {
        let v: f64 = p.parse().map_err(|_| {
            format!("expected X,Y (two finite numbers in m/s), '{p}' is not a number")
        })?;
        if !v.is_finite() {
            return Err(format!(
                "expected X,Y (two finite numbers in m/s), '{p}' is not finite"
            ));
        }
        *o = v;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checks_reject_nan_infinities_and_out_of_range() {
        assert!(positive("--length-m", 0.0, "m").is_err());
        assert!(positive("--length-m", f64::INFINITY, "m").is_err());
        assert!(range("--mu", -0.1, 0.0, 2.0, "1", "dry friction").is_err());
        assert!(range("--mu", f64::NAN, 0.0, 2.0, "1", "dry friction").is_err());
        assert_eq!(range("--mu", 2.0, 0.0, 2.0, "1", "dry friction"), Ok(2.0));
        let e = range("--angle-deg", 95.0, -90.0, 90.0, "degrees", "a leaning rod").unwrap_err();
        assert_eq!(
            e.to_string(),
            "error: invalid value 95 for --angle-deg: valid range is -90 <= value <= 90 (degrees; a leaning rod)"
        );
        assert_eq!(e.exit_code(), 2);
    }

    #[test]
    fn new_errors_have_their_exit_codes_and_one_line() {
        let e = range("--mu", 3.0, 0.0, 2.0, "dimensionless", "dry friction").unwrap_err();
        assert_eq!(
            e.to_string(),
            "error: invalid value 3 for --mu: valid range is 0 <= value <= 2 (dimensionless; dry friction)"
        );
        let o = WorkbookError::Output {
            flag: "--figures".into(),
            path: "/x".into(),
            why: "read-only".into(),
        };
        assert_eq!(o.exit_code(), 3);
        let b = WorkbookError::OverBudget {
            flag: "--duration-s".into(),
            estimate: "e".into(),
            budget: "b".into(),
        };
        assert_eq!(b.exit_code(), 2);
        assert!(b.to_string().contains("--duration-s") && !b.to_string().contains('\n'));
        let pipe: WorkbookError = std::io::Error::from(std::io::ErrorKind::BrokenPipe).into();
        assert_eq!((pipe.exit_code(), pipe.to_string()), (0, String::new()));
    }

    #[test]
    fn pairs_parse_strictly() {
        assert_eq!(parse_pair("1.5,-2"), Ok([1.5, -2.0]));
        assert_eq!(parse_pair(" 1 , 2 "), Ok([1.0, 2.0]));
        for bad in ["1", "1,2,3", "a,1", "nan,1", "1,inf", ""] {
            assert!(parse_pair(bad).is_err(), "{bad}");
        }
    }
}
