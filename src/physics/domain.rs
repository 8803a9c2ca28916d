//! Intervals of accepted values. A model's constructor checks each parameter against
//! its domain (where the model is defined) and returns a [`DomainError`] naming the
//! parameter, the value and the interval instead of building a model that would
//! compute NaN; the command line's flag table (`crate::flags`) states, with the same
//! type, the narrower box over which a chapter's checks are validated.

use crate::error::num;
use std::fmt;

/// An interval of real numbers; an infinite end is unbounded. Only finite values are
/// ever inside.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Interval {
    /// Lower end.
    pub lo: f64,
    /// Upper end.
    pub hi: f64,
    /// Whether `lo` itself is excluded.
    pub lo_open: bool,
    /// Whether `hi` itself is excluded.
    pub hi_open: bool,
}

impl Interval {
    /// `[lo, hi]`.
    pub const fn closed(lo: f64, hi: f64) -> Self {
        Interval {
            lo,
            hi,
            lo_open: false,
            hi_open: false,
        }
    }

    /// `(lo, hi)`.
    pub const fn open(lo: f64, hi: f64) -> Self {
        Interval {
            lo,
            hi,
            lo_open: true,
            hi_open: true,
        }
    }

    /// `[lo, inf)`.
    pub(crate) const fn at_least(lo: f64) -> Self {
        Interval::closed(lo, f64::INFINITY)
    }

    /// `(lo, inf)`.
    pub const fn above(lo: f64) -> Self {
        Interval::open(lo, f64::INFINITY)
    }

    /// The same interval without its lower end.
    pub(crate) const fn open_below(self) -> Self {
        Interval {
            lo_open: true,
            ..self
        }
    }

    /// The same interval without its upper end.
    pub(crate) const fn open_above(self) -> Self {
        Interval {
            hi_open: true,
            ..self
        }
    }

    /// Whether `v` is finite and inside.
    pub fn contains(&self, v: f64) -> bool {
        let above_lo = if self.lo_open {
            v > self.lo
        } else {
            v >= self.lo
        };
        let below_hi = if self.hi_open {
            v < self.hi
        } else {
            v <= self.hi
        };
        v.is_finite() && above_lo && below_hi
    }

    /// Whether every value of `inner` is inside this interval.
    pub fn includes(&self, inner: &Interval) -> bool {
        let lo_ok = inner.lo > self.lo || (inner.lo == self.lo && (inner.lo_open || !self.lo_open));
        let hi_ok = inner.hi < self.hi || (inner.hi == self.hi && (inner.hi_open || !self.hi_open));
        lo_ok && hi_ok
    }

    /// As text, `lo <= value < hi`, an unbounded end left out (`0 < value`).
    pub fn text(&self) -> String {
        let lo_sign = if self.lo_open { "<" } else { "<=" };
        let hi_sign = if self.hi_open { "<" } else { "<=" };
        match (self.lo.is_finite(), self.hi.is_finite()) {
            (true, true) => format!(
                "{} {lo_sign} value {hi_sign} {}",
                num(self.lo),
                num(self.hi)
            ),
            (true, false) => format!("{} {lo_sign} value", num(self.lo)),
            (false, true) => format!("value {hi_sign} {}", num(self.hi)),
            (false, false) => "any finite value".to_string(),
        }
    }
}

/// A model parameter outside its domain.
#[derive(Debug, Clone, PartialEq)]
pub struct DomainError {
    /// The parameter's name (as in the model's struct, units in the name).
    pub parameter: &'static str,
    /// The refused value.
    pub value: f64,
    /// The parameter's domain.
    pub domain: Interval,
    /// Its unit (`1` when dimensionless).
    pub unit: &'static str,
}

impl fmt::Display for DomainError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} = {} is outside the model's domain {} ({})",
            self.parameter,
            num(self.value),
            self.domain.text(),
            self.unit
        )
    }
}

impl std::error::Error for DomainError {}

/// `value` if it lies in `domain`, else the error naming `parameter`.
pub fn within(
    parameter: &'static str,
    value: f64,
    domain: Interval,
    unit: &'static str,
) -> Result<f64, DomainError> {
    if domain.contains(value) {
        Ok(value)
    } else {
        Err(DomainError {
            parameter,
            value,
            domain,
            unit,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ends_open_and_closed_are_kept() {
        let i = Interval::closed(0.0, 1.0).open_above();
        assert!(i.contains(0.0) && i.contains(0.999) && !i.contains(1.0));
        assert!(!i.contains(f64::NAN) && !Interval::at_least(0.0).contains(f64::INFINITY));
        assert_eq!(i.text(), "0 <= value < 1");
        assert_eq!(Interval::above(0.0).text(), "0 < value");
    }

    #[test]
    fn inclusion_respects_open_ends() {
        let outer = Interval::closed(0.0, 1.0).open_below();
        assert!(outer.includes(&Interval::closed(0.5, 1.0)));
        assert!(!outer.includes(&Interval::closed(0.0, 1.0)));
        assert!(outer.includes(&Interval::open(0.0, 1.0)));
        assert!(Interval::at_least(0.0).includes(&Interval::closed(0.0, 1e300)));
    }

    #[test]
    fn the_error_names_parameter_value_and_domain() {
        let e = within("length_m", -1.0, Interval::above(0.0), "m").unwrap_err();
        assert_eq!(
            e.to_string(),
            "length_m = -1 is outside the model's domain 0 < value (m)"
        );
    }
}
