//! Guard crossings and their location.
//!
//! A guard is a scalar function `g(t, y)`; an event fires when `g` crosses zero in the
//! guard's [`Direction`]. Crossings are bracketed between two points where the sign
//! changes and refined with the Illinois variant of regula falsi on the step's dense
//! output (superlinear, never leaves the bracket). The returned time is the *right*
//! end of the final bracket: the first point known to lie past the crossing, so a
//! mode started there does not fire the same guard again.
//!
//! A sign check at the ends of a step cannot see a guard that crosses zero and comes
//! back inside the step (an even number of crossings: a short lift-off). The certified
//! search [`hidden_crossing`] closes that gap: from the guard's values and rates at the
//! ends it builds the cubic Hermite model of the guard over the step and subdivides the
//! step, sampling the dense output, until on every piece the model stays farther from
//! zero than its own error allowance (then no crossing can hide there), or a sample on
//! the far side of zero brackets a crossing for [`illinois`].

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
    pub(crate) fn fires(self, g0: f64, g1: f64) -> bool {
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
pub(crate) fn time_tolerance(t: f64) -> f64 {
    4.0 * f64::EPSILON * t.abs().max(1.0)
}

/// Locates the crossing of `f` in `[a, b]` given `fa = f(a)` and `fb = f(b)` on the
/// two sides of zero (or `fb == 0`). Returns `(t, evaluations)` with `t` the right
/// end of a final bracket no wider than `t_tol`.
///
/// Illinois: regula falsi, halving the weight of an end that is retained twice in a row.
pub(crate) fn illinois(
    f: impl FnMut(f64) -> f64,
    a: f64,
    b: f64,
    fa: f64,
    fb: f64,
    t_tol: f64,
) -> (f64, u32) {
    illinois_loop(f, (a, b, fa, fb), t_tol, 0)
}

/// [`illinois`] started from an estimate of the crossing: `start = (c, slope)`, a time
/// `c` inside `(a, b)` and the guard's rate there (from a model of the guard, such as
/// [`hermite_root`]). The guard is evaluated at `c`, then one and a half model-Newton
/// steps from it, `c - 1.5 f(c) / slope`, which lands just across the crossing when
/// the model is good, so the bracket is a small multiple of the estimate's error wide;
/// Illinois closes it. A poor estimate costs at most these two evaluations.
pub(crate) fn illinois_from(
    mut f: impl FnMut(f64) -> f64,
    a: f64,
    b: f64,
    fa: f64,
    fb: f64,
    t_tol: f64,
    start: (f64, f64),
) -> (f64, u32) {
    let mut br = (a, b, fa, fb);
    let mut evals = 0;
    let (c, slope) = start;
    let nudge = 0.5 * t_tol;
    if b - a > 2.0 * t_tol && c > a + nudge && c < b - nudge {
        let fc = f(c);
        evals += 1;
        br = shrink(br, c, fc);
        if slope.is_finite() && slope != 0.0 && fc != 0.0 {
            let c2 = c - 1.5 * fc / slope; // formula: c - 1.5 f(c) / g'(c)
            let (a, b, ..) = br;
            if b - a > 2.0 * t_tol && c2 > a + nudge && c2 < b - nudge {
                let f2 = f(c2);
                evals += 1;
                br = shrink(br, c2, f2);
            }
        }
    }
    illinois_loop(f, br, t_tol, evals)
}

/// The bracket `(a, b, fa, fb)` with `c` (value `fc`) put in place of the end on its
/// side of the crossing.
fn shrink((a, b, fa, fb): (f64, f64, f64, f64), c: f64, fc: f64) -> (f64, f64, f64, f64) {
    if fc == 0.0 || (fc > 0.0) != (fa > 0.0) {
        (a, c, fa, fc)
    } else {
        (c, b, fc, fb)
    }
}

// ANCHOR: illinois
/// The Illinois iteration on the bracket `(a, b, fa, fb)`, `evals` evaluations spent.
fn illinois_loop(
    mut f: impl FnMut(f64) -> f64,
    (a, b, fa, fb): (f64, f64, f64, f64),
    t_tol: f64,
    evals: u32,
) -> (f64, u32) {
    // Invariant: fa != 0 (a lies before the crossing) and b lies at or past it.
    let (mut a, mut b, mut fa, mut fb) = (a, b, fa, fb);
    let mut evals = evals;
    let mut side = 0i8;
    for _ in 0..200 {
        if b - a <= t_tol {
            break;
        }
        // formula: c = (a fb - b fa)/(fb - fa)
        let mut c = (a * fb - b * fa) / (fb - fa);
        // Never closer than half the tolerance to an end (as in Brent's method): once
        // the estimate has converged onto one end, the next point lands just across the
        // crossing and closes the bracket, instead of creeping up on it. A secant root
        // on or past an end (rounding, when that end's value is tiny) is such a
        // convergence too, and goes to the same place, not to the midpoint: bisecting
        // from the far end instead took up to 14 more evaluations.
        let nudge = 0.5 * t_tol;
        if b - a > 2.0 * t_tol && !c.is_nan() {
            c = c.clamp(a + nudge, b - nudge);
        } else if !(c > a && c < b) {
            c = 0.5 * (a + b);
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
// ANCHOR_END: illinois

/// A guard's value and rate (s^-1 times its unit) at one time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GuardPoint {
    /// Time (s).
    pub t: f64,
    /// Guard value.
    pub g: f64,
    /// Time derivative of the guard along the trajectory.
    pub rate: f64,
}

/// A cheap sufficient test that a guard with the same sign at both ends of a step of
/// length `h` keeps it, allowance included. With slopes `d = h g'` in `u = (t - t0)/h`
/// and `sigma` the sign at the start, the Hermite model regroups as
/// `sigma p = (1-u)^2 [(1+2u) sigma g0 + u sigma d0] + u^2 [(3-2u) sigma g1 - (1-u) sigma d1]`.
/// Taking half the allowance `16 A u^2 (1-u)^2` (see `hidden_crossing`, `A = |c3|/4`)
/// into each bracket leaves two expressions bounded below by functions linear in `u`,
/// positive on `[0, 1]` when they are positive at both ends:
/// `sigma g0 > 0`, `3 sigma g0 + sigma d0 > 8 A`, `3 sigma g1 - sigma d1 > 8 A`, `sigma g1 > 0`.
/// Most steps pass here; the others go to the exact least value of the model.
#[inline]
pub(crate) fn clearly_one_sided(a: &GuardPoint, b: &GuardPoint) -> bool {
    let h = b.t - a.t;
    let sign = if a.g > 0.0 { 1.0 } else { -1.0 };
    let (g0, g1) = (sign * a.g, sign * b.g);
    let (d0, d1) = (sign * h * a.rate, sign * h * b.rate);
    let a8 = 2.0 * (2.0 * (g0 - g1) + d0 + d1).abs(); // formula: 8 A = 2 |c3|
    (g0 > 0.0) & (g1 > 0.0) & (3.0 * g0 + d0 > a8) & (3.0 * g1 - d1 > a8)
}

/// The crossing of the cubic Hermite model of a guard between `a` and `b`, whose
/// values have opposite signs (or `b.g == 0`): `(t, rate)`, the model's root and its
/// slope there, from Newton's method on the cubic started at the secant's root and kept
/// inside the bracket. `None` when the iteration leaves it or does not settle.
pub(crate) fn hermite_root(a: &GuardPoint, b: &GuardPoint) -> Option<(f64, f64)> {
    let h = b.t - a.t;
    if h <= 0.0 || a.g == b.g {
        return None;
    }
    let c = hermite_coefficients(a, b);
    let mut u = a.g / (a.g - b.g); // formula: the secant's root in u
    for _ in 0..8 {
        let p = c[0] + u * (c[1] + u * (c[2] + u * c[3]));
        let dp = c[1] + u * (2.0 * c[2] + u * 3.0 * c[3]); // formula: p'(u)
        if dp == 0.0 || !dp.is_finite() {
            return None;
        }
        let step = p / dp; // formula: Newton, u <- u - p / p'
        u -= step;
        if !(u > 0.0 && u < 1.0) {
            return None;
        }
        if step.abs() <= 1e-12 {
            return Some((a.t + u * h, dp / h)); // formula: dg/dt = p'(u) / h
        }
    }
    None
}

/// Power-basis coefficients in `u = (t - a)/(b - a)` of the cubic Hermite model of a
/// guard on `[a, b]`: `p(u) = c0 + c1 u + c2 u^2 + c3 u^3`.
fn hermite_coefficients(a: &GuardPoint, b: &GuardPoint) -> [f64; 4] {
    let h = b.t - a.t;
    let (d0, d1) = (h * a.rate, h * b.rate); // formula: slopes in u are h g'
    [
        a.g,
        d0,
        3.0 * (b.g - a.g) - 2.0 * d0 - d1, // formula: c2 = 3 (g1 - g0) - 2 h g0' - h g1'
        2.0 * (a.g - b.g) + d0 + d1,       // formula: c3 = 2 (g0 - g1) + h g0' + h g1'
    ]
}

/// Least value of `sign * p(u)` over `u` in `[0, 1]` for the cubic `c`.
fn least_on_unit(c: &[f64; 4], sign: f64) -> f64 {
    let p = |u: f64| sign * (c[0] + u * (c[1] + u * (c[2] + u * c[3])));
    let mut least = p(0.0).min(p(1.0));
    // formula: p'(u) = c1 + 2 c2 u + 3 c3 u^2 = 0
    let (qa, qb, qc) = (3.0 * c[3], 2.0 * c[2], c[1]);
    let mut consider = |u: f64| {
        if u > 0.0 && u < 1.0 {
            least = least.min(p(u));
        }
    };
    if qa.abs() <= 1e-14 * (qb.abs() + qc.abs()) {
        if qb != 0.0 {
            consider(-qc / qb);
        }
    } else {
        let disc = qb * qb - 4.0 * qa * qc;
        if disc >= 0.0 {
            // formula: the stable pair of roots, q = -(b + sign(b) sqrt(disc))/2
            let sb = if qb >= 0.0 { 1.0 } else { -1.0 };
            let q = -0.5 * (qb + sb * disc.sqrt());
            if q != 0.0 {
                consider(q / qa);
                consider(qc / q);
            } else {
                consider(0.0);
            }
        }
    }
    least
}

/// Is `sign * g > 0` certain on the piece whose Hermite model is `c`, when `|g - p|`
/// is at most `allow` at the middle? The Hermite error vanishes at the ends (it is
/// `c4 u^2 (1-u)^2` for a quartic part `c4 u^4`), so the allowance is `16 allow u^2
/// (1-u)^2`. First the uniform test `min sign p > allow`; failing that, the least value
/// of the quartic `q(u) = sign p(u) - 16 allow u^2 (1-u)^2` on `[0, 1]`.
fn certified(c: &[f64; 4], sign: f64, allow: f64) -> bool {
    if least_on_unit(c, sign) > allow {
        return true;
    }
    let w = 16.0 * allow; // formula: u^2 (1-u)^2 = u^2 - 2 u^3 + u^4
    let q = [
        sign * c[0],
        sign * c[1],
        sign * c[2] - w,
        sign * c[3] + 2.0 * w,
        -w,
    ];
    least_of_quartic(&q) > 0.0
}

/// Least value on `[0, 1]` of `q0 + q1 u + q2 u^2 + q3 u^3 + q4 u^4`: at an end or at a
/// root of `q'`. The roots of `q''` (a quadratic, closed form) cut `[0, 1]` into pieces
/// on which `q'` is monotone, so each piece holds at most one root of `q'`, found by
/// bisection where `q'` changes sign.
fn least_of_quartic(q: &[f64; 5]) -> f64 {
    let val = |u: f64| q[0] + u * (q[1] + u * (q[2] + u * (q[3] + u * q[4])));
    let d1 = |u: f64| q[1] + u * (2.0 * q[2] + u * (3.0 * q[3] + u * 4.0 * q[4])); // formula: q'
                                                                                   // [0, 1] and the roots of q'' inside it, in order (a fixed array: no allocation).
    let mut cuts = [0.0, 1.0, 1.0, 1.0];
    let mut n = 1;
    // formula: q'' = 2 q2 + 6 q3 u + 12 q4 u^2 = 0
    let (a, b, c) = (12.0 * q[4], 6.0 * q[3], 2.0 * q[2]);
    let mut roots = [f64::NAN; 2];
    if a.abs() > 1e-300 {
        let disc = b * b - 4.0 * a * c;
        if disc >= 0.0 {
            let r = disc.sqrt();
            let (r1, r2) = ((-b - r) / (2.0 * a), (-b + r) / (2.0 * a));
            roots = [r1.min(r2), r1.max(r2)];
        }
    } else if b != 0.0 {
        roots[0] = -c / b;
    }
    for u in roots {
        if u > 0.0 && u < 1.0 {
            cuts[n] = u;
            n += 1;
        }
    }
    cuts[n] = 1.0;
    let cuts = &cuts[..=n];
    let mut least = val(0.0).min(val(1.0));
    for w in cuts.windows(2) {
        let (mut l, mut r) = (w[0], w[1]);
        let (dl, dr) = (d1(l), d1(r));
        if dl == 0.0 || dr == 0.0 || (dl > 0.0) == (dr > 0.0) {
            least = least.min(val(l)).min(val(r));
            continue;
        }
        // 24 halvings: the root of q' to 2^-24 of the piece, where q is off its least
        // value by at most max|q''| 2^-48 / 2 (the slack subtracted below).
        for _ in 0..24 {
            let m = 0.5 * (l + r);
            if (d1(m) > 0.0) == (dl > 0.0) {
                l = m;
            } else {
                r = m;
            }
        }
        least = least.min(val(0.5 * (l + r)));
    }
    let slack = (2.0 * q[2].abs() + 6.0 * q[3].abs() + 12.0 * q[4].abs()) * 2f64.powi(-49); // formula: max|q''| du^2 / 2
    least - slack
}

/// Most interior samples one search may take: past it the remaining pieces are a
/// tangency to zero within the guard's round-off (their models' minima lie within the
/// floor of 64 ulps) and are counted as unresolved.
pub const MAX_SAMPLES: u64 = 256;

/// Work of certified searches (for the cost table of chapter 7).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct CertifyStats {
    /// Guards whose step could not be certified from the ends alone (subdivided).
    pub subdivided: u64,
    /// Interior samples taken (each a dense-output value and rate of one guard).
    pub samples: u64,
    /// Crossings found that the end-point sign test missed.
    pub hidden_found: u64,
    /// Pieces narrower than the resolution left uncertified (a tangency to zero).
    pub unresolved: u64,
}

/// Searches `[a.t, b.t]` for a zero of a guard that has the same strict sign at both
/// ends, so the end-point test sees no crossing (a guard that starts at zero up to
/// round-off, `|g(a)| <= 64 eps |g(b)|`, is left to the end-point test). `at(t)` gives the guard's value and
/// rate at an interior time (on the step's dense output).
///
/// On each piece the cubic Hermite model `p` of the guard (values and rates at its
/// ends) is compared with zero. The piece is certified free of crossings when
/// `min sign * p > allowance`, the allowance bounding `|g - p|`:
/// - before any interior sample, a quarter of the model's cubic coefficient `|c3|`.
///   If the guard's Taylor coefficients in `u` shrink like `(h/tau)^k / k!` (a step
///   that resolves the guard's time scale `tau`), the Hermite error `c4 u^2 (1-u)^2
///   <= c4/16` is about `|c3| (h/tau)/64`: the quarter is a 16-fold margin for `h <= tau`;
/// - after a sample at the midpoint, whose Hermite error `e_mid` is measured, the
///   halves' errors scale as `h^4`, so `e_mid/16`; the allowance is `e_mid/4` (4-fold).
///
/// The allowance is the bound at the middle of a piece; towards its ends it shrinks as
/// `u^2 (1-u)^2` (see `certified`), so a guard that starts a step at a small offset
/// from zero and moves away (a slide entered from rest) certifies without subdividing.
///
/// Both also get a floor of 64 ulps of the guard's scale. Pieces are searched left to
/// right. Returns the first sample found on the far side of zero with the ends of its
/// piece, `[(t_l, g_l), (t_m, g_m), (t_r, g_r)]`: the guard crosses zero in both halves,
/// once each way, so either direction of firing has its bracket there. `None`: no
/// crossing can hide; the search stops refining pieces narrower than `t_tol` (a
/// tangency below the time resolution), or `2^-32` of the step, and gives up after
/// [`MAX_SAMPLES`] samples (a tangency within round-off), counting it as unresolved.
pub(crate) fn hidden_crossing(
    mut at: impl FnMut(f64) -> (f64, f64),
    a: GuardPoint,
    b: GuardPoint,
    t_tol: f64,
    stats: &mut CertifyStats,
) -> Option<[(f64, f64); 3]> {
    let sign = a.g.signum();
    if a.g == 0.0 || b.g == 0.0 || b.g.signum() != sign {
        return None; // not this function's case: the end-point test decides
    }
    if a.g.abs() <= 64.0 * f64::EPSILON * b.g.abs() {
        // The guard starts the step at zero up to round-off: the event that put it there
        // was just handled (a take-off from the plate starts its height guard at zero,
        // and the first step's dense output may dip by round-off before it rises), and a
        // guard never fires from zero (see `Direction::fires`).
        return None;
    }
    let floor = 64.0 * f64::EPSILON * a.g.abs().max(b.g.abs());
    let c = hermite_coefficients(&a, &b);
    let allowance = (0.25 * c[3].abs()).max(floor);
    if certified(&c, sign, allowance) {
        return None;
    }
    stats.subdivided += 1;
    // Depth-first, left piece first: (left end, right end, allowance).
    let min_width = t_tol.max((b.t - a.t) * 2f64.powi(-32));
    let mut pieces = vec![(a, b, allowance)];
    let mut taken = 0;
    while let Some((l, r, allow)) = pieces.pop() {
        let c = hermite_coefficients(&l, &r);
        if certified(&c, sign, allow) {
            continue;
        }
        if r.t - l.t <= min_width || taken == MAX_SAMPLES {
            stats.unresolved += 1;
            break;
        }
        taken += 1;
        let tm = 0.5 * (l.t + r.t);
        let (g, rate) = at(tm);
        stats.samples += 1;
        if g == 0.0 || g.signum() != sign {
            stats.hidden_found += 1;
            return Some([(l.t, l.g), (tm, g), (r.t, r.g)]);
        }
        let e_mid = (g - (c[0] + 0.5 * (c[1] + 0.5 * (c[2] + 0.5 * c[3])))).abs();
        let allow_half = (0.25 * e_mid).max(floor); // formula: e/16 per half, 4-fold margin
        let m = GuardPoint { t: tm, g, rate };
        pieces.push((m, r, allow_half));
        pieces.push((l, m, allow_half));
    }
    None
}

#[cfg(test)]
mod tests;
