//! Guard crossings and their location.
//!
//! A guard is a scalar function `g(t, y)`; an event fires when `g` crosses zero in the
//! guard's [`Direction`]. Crossings are bracketed between two points where the sign
//! changes and refined with the Illinois variant of regula falsi on the step's dense
//! output (superlinear, never leaves the bracket). The returned time is the *right*
//! end of the final bracket: the first point known to lie past the crossing, so a
//! mode started there does not fire the same guard again.

/// The crossing direction that makes a guard fire.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    /// From negative to zero or positive.
    Rising,
    /// From positive to zero or negative.
    Falling,
    /// Either way.
    Either,
}

impl Direction {
    /// Does the change `g0 -> g1` fire a guard with this direction? A guard that starts
    /// at exactly zero does not fire (it was just handled by the event that put it there).
    pub fn fires(self, g0: f64, g1: f64) -> bool {
        let rising = g0 < 0.0 && g1 >= 0.0;
        let falling = g0 > 0.0 && g1 <= 0.0;
        match self {
            Direction::Rising => rising,
            Direction::Falling => falling,
            Direction::Either => rising || falling,
        }
    }
}

/// Default time tolerance of event location: a few ulps of `t` (s).
pub fn time_tolerance(t: f64) -> f64 {
    4.0 * f64::EPSILON * t.abs().max(1.0)
}

/// Locates the crossing of `f` in `[a, b]` given `fa = f(a)` and `fb = f(b)` on the
/// two sides of zero (or `fb == 0`). Returns `(t, evaluations)` with `t` the right
/// end of a final bracket no wider than `t_tol`.
///
/// Illinois: regula falsi, halving the weight of an end that is retained twice in a row.
pub fn illinois(
    mut f: impl FnMut(f64) -> f64,
    a: f64,
    b: f64,
    fa: f64,
    fb: f64,
    t_tol: f64,
) -> (f64, u32) {
    // Invariant: fa != 0 (a lies before the crossing) and b lies at or past it.
    let (mut a, mut b, mut fa, mut fb) = (a, b, fa, fb);
    let mut evals = 0;
    let mut side = 0i8;
    for _ in 0..200 {
        if b - a <= t_tol {
            break;
        }
        // formula: c = (a fb - b fa)/(fb - fa)
        let mut c = (a * fb - b * fa) / (fb - fa);
        if !(c > a && c < b) {
            c = 0.5 * (a + b);
        }
        // Never closer than half the tolerance to an end (as in Brent's method): once
        // the estimate has converged onto one end, the next point lands just across the
        // crossing and closes the bracket, instead of creeping up on it.
        let nudge = 0.5 * t_tol;
        if b - a > 2.0 * t_tol {
            c = c.clamp(a + nudge, b - nudge);
        }
        let fc = f(c);
        evals += 1;
        if fc == 0.0 || (fc > 0.0) != (fa > 0.0) {
            // c is past the crossing (same side as b): move b.
            b = c;
            fb = fc;
            if side == -1 {
                fa *= 0.5; // formula: Illinois halving of the retained end
            }
            side = -1;
        } else {
            a = c;
            fa = fc;
            if side == 1 {
                fb *= 0.5;
            }
            side = 1;
        }
    }
    (b, evals)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn directions() {
        assert!(Direction::Rising.fires(-1.0, 1.0));
        assert!(Direction::Rising.fires(-1.0, 0.0));
        assert!(!Direction::Rising.fires(1.0, -1.0));
        assert!(!Direction::Rising.fires(0.0, 1.0));
        assert!(Direction::Falling.fires(1.0, -1.0));
        assert!(Direction::Either.fires(1.0, -1.0) && Direction::Either.fires(-1.0, 1.0));
    }

    #[test]
    fn illinois_finds_roots_to_machine_precision() {
        // cos(t) = 0 at pi/2 (rising from negative side of -cos)
        let f = |t: f64| -t.cos();
        let (t, n) = illinois(f, 0.0, 3.0, f(0.0), f(3.0), time_tolerance(2.0));
        assert!((t - std::f64::consts::FRAC_PI_2).abs() < 1e-15, "{t}");
        assert!(t >= std::f64::consts::FRAC_PI_2 - 1e-15);
        assert!(n < 20, "{n} evaluations");
        // a steep, lopsided function where plain regula falsi stalls
        let g = |t: f64| t.powi(9) - 1e-9;
        let (t, n) = illinois(g, 0.0, 1.0, g(0.0), g(1.0), time_tolerance(1.0));
        let root = 1e-1f64;
        assert!((t - root).abs() < 1e-15, "{t}");
        assert!(n < 60, "{n} evaluations");
    }

    #[test]
    fn returned_time_is_past_the_crossing() {
        let f = |t: f64| t - 0.3;
        let (t, _) = illinois(f, 0.0, 1.0, f(0.0), f(1.0), 1e-15);
        assert!(f(t) >= 0.0);
    }
}
