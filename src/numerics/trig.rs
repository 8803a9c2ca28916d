//! Sine and cosine together, by a table and angle addition: the inner loop's trigonometry.
//!
//! A contact evaluation of the stick needs two sine-cosine pairs (the plate's phase and
//! the rod's angle), and the C library's `sincos` cost a third of the simulator's time.
//! Here the angle, in turns `x` (`2 pi x` radians), is split as `x = i/1024 + d/(2 pi)`
//! with `i` the nearest table point and `|d| <= pi/1024`; then
//!
//! $$\sin(a + d) = \sin a \cos d + \cos a \sin d, \qquad
//!   \cos(a + d) = \cos a \cos d - \sin a \sin d,$$
//!
//! with `sin a`, `cos a` from a 1024-point table (16 KiB, of which a slowly turning
//! phase touches a few cache lines) and `sin d`, `cos d` from their Taylor series,
//! which at `|d| <= 0.0031` reach round-off after three terms (the first omitted
//! terms, `d^7/7!` and `d^6/6!`, are below `5e-22` and `2e-18`). No branches, no division, no range
//! reduction beyond one rounding: the error stays within a few units in the last place
//! (tests: against `f64::sin_cos` on a dense grid and at the table points, and relative
//! accuracy near zero, where `sin x` is tiny).
//!
//! Valid for `|x| < 2^42` turns (`2^50` table intervals); beyond that (and for non-finite input) it falls back
//! to `f64::sin_cos`.

use std::f64::consts::TAU;
use std::sync::LazyLock;

/// Table points per turn (a power of two: the index wraps with a bit mask).
const SIZE: usize = 1024;

/// `1.5 * 2^52`: adding and subtracting it rounds a float of magnitude below `2^51`
/// to the nearest integer (ties to even) without a library call.
const ROUND: f64 = 6_755_399_441_055_744.0;

/// `(sin, cos)` of `2 pi i / SIZE`, `i = 0 .. SIZE`.
static TABLE: LazyLock<[(f64, f64); SIZE]> = LazyLock::new(|| {
    // Each point from its angle within the first quadrant (smaller, so more accurately
    // represented), then turned by whole quarter turns, which is exact.
    let mut t = [(0.0, 1.0); SIZE];
    for (i, e) in t.iter_mut().enumerate() {
        let (q, r) = (i / (SIZE / 4), i % (SIZE / 4));
        let (s, c) = (TAU * r as f64 / SIZE as f64).sin_cos();
        *e = match q {
            0 => (s, c),
            1 => (c, -s),
            2 => (-s, -c),
            _ => (-c, s),
        };
    }
    t
});

/// The table, held by reference: a caller that keeps one (a model that evaluates the
/// plate's phase on every right-hand side) skips the lazy initialisation's check on
/// every call ([`Table::sin_cos_turns`]; the same arithmetic as [`sin_cos_turns`]).
#[derive(Clone, Copy)]
pub struct Table(&'static [(f64, f64); SIZE]);

impl std::fmt::Debug for Table {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Table({SIZE} points)")
    }
}

/// The table (initialised on first use).
pub fn table() -> Table {
    Table(&TABLE)
}

impl Table {
    /// `(sin(2 pi x), cos(2 pi x))` for an angle `x` in turns, as [`sin_cos_turns`].
    #[inline]
    pub(crate) fn sin_cos_turns(self, x: f64) -> (f64, f64) {
        let u = x * SIZE as f64; // exact: SIZE is a power of two
        if in_range(u) {
            lookup(self.0, u)
        } else {
            (TAU * x).sin_cos()
        }
    }
}

/// `(sin(2 pi x), cos(2 pi x))` for an angle `x` in turns.
#[inline]
pub fn sin_cos_turns(x: f64) -> (f64, f64) {
    table().sin_cos_turns(x)
}

/// `(sin(x), cos(x))` for an angle `x` in radians.
#[inline]
pub fn sin_cos(x_rad: f64) -> (f64, f64) {
    let u = x_rad * (SIZE as f64 / TAU);
    if in_range(u) {
        lookup(&TABLE, u)
    } else {
        x_rad.sin_cos()
    }
}

/// `|u| < 2^50` table intervals, where the rounding trick is exact (false for NaN and
/// infinities).
#[inline]
fn in_range(u: f64) -> bool {
    u.abs() < (1u64 << 50) as f64
}

/// The sine and cosine of `2 pi u / SIZE` from the table `t`.
#[inline]
fn lookup(t: &[(f64, f64); SIZE], u: f64) -> (f64, f64) {
    let n = (u + ROUND) - ROUND; // formula: n = round(u), the nearest table point
    let d = (u - n) * (TAU / SIZE as f64); // formula: d = 2 pi (u - n)/SIZE, |d| <= pi/SIZE
    let (sa, ca) = t[(n as i64 as usize) & (SIZE - 1)];
    let d2 = d * d;
    // formula: sin d = d (1 - d^2/6 (1 - d^2/20)), cos d = 1 - d^2/2 (1 - d^2/12)
    // (multiplications by the reciprocals: a division costs several of them)
    let sd = d * (1.0 - d2 * (1.0 / 6.0) * (1.0 - d2 * (1.0 / 20.0)));
    let cm1 = -0.5 * d2 * (1.0 - d2 * (1.0 / 12.0)); // cos d - 1, kept apart for accuracy
    (
        sa + (sa * cm1 + ca * sd), // formula: sin(a + d) = sin a + (sin a (cos d - 1) + cos a sin d)
        ca + (ca * cm1 - sa * sd), // formula: cos(a + d) = cos a + (cos a (cos d - 1) - sin a sin d)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Largest error against `f64::sin_cos` (itself within 1 ulp) over `xs`, in units of
    /// the bound `4e-16 + 2 |x| eps`: a few roundings of numbers below 1, plus the
    /// rounding of the radians-to-turns conversion, about 1 ulp of `x` (the library
    /// reduces with an extended-precision pi instead).
    fn worst(xs: impl Iterator<Item = f64>) -> f64 {
        let mut w: f64 = 0.0;
        for x in xs {
            let (s, c) = sin_cos(x);
            let (s0, c0) = x.sin_cos();
            let bound = 4e-16 + 2.0 * x.abs() * f64::EPSILON;
            w = w.max((s - s0).abs() / bound).max((c - c0).abs() / bound);
        }
        w
    }

    #[test]
    fn agrees_with_the_library_to_a_few_ulps() {
        // A grid not commensurate with the table, over two turns each way; the table
        // points themselves; and many turns (a plate phase after thousands of cycles).
        let grid = (-40_000..=40_000).map(|k| k as f64 * 3.3e-4);
        assert!(worst(grid) <= 1.0);
        let points = (0..SIZE).map(|i| TAU * i as f64 / SIZE as f64);
        assert!(worst(points) <= 1.0);
        assert!(worst([1e3, 12_345.678, 1e5].into_iter()) <= 1.0);
        // In turns there is no conversion: 4e-16 flat, at the table points and between.
        for k in -3000..3000 {
            let x = k as f64 / 1024.0 + 1e-4;
            let (s, c) = sin_cos_turns(x);
            let (s0, c0) = (TAU * x).sin_cos();
            let conv = 2.0 * (TAU * x).abs() * f64::EPSILON; // the reference's own argument rounding
            assert!(
                (s - s0).abs() <= 4e-16 + conv && (c - c0).abs() <= 4e-16 + conv,
                "{x}"
            );
        }
    }

    #[test]
    fn keeps_relative_accuracy_near_zero() {
        // sin x ~ x for tiny x of either sign: the table point is 0 there, so the
        // result is the series in d = x alone, relative error a few ulps.
        for x in [1e-300, -1e-20, 3e-9, -2.5e-3] {
            let (s, c) = sin_cos(x);
            assert!(((s - x.sin()) / x.sin()).abs() < 4e-16, "{x}: {s}");
            assert!((c - x.cos()).abs() < 2e-16);
        }
        assert_eq!(sin_cos(0.0), (0.0, 1.0));
    }

    #[test]
    fn turns_and_fallback() {
        let (s, c) = sin_cos_turns(0.25);
        assert!((s - 1.0).abs() < 1e-16 && c.abs() < 1e-16);
        let (s, c) = sin_cos_turns(-0.125);
        let h = std::f64::consts::FRAC_1_SQRT_2;
        assert!((s + h).abs() < 2e-16 && (c - h).abs() < 2e-16);
        // beyond 2^42 turns and for non-finite input: the library's answer
        assert_eq!(sin_cos(1e20), 1e20_f64.sin_cos());
        let (s, c) = sin_cos(f64::NAN);
        assert!(s.is_nan() && c.is_nan());
    }
}
