//! The gait as a limit cycle: the stroboscopic Poincare map at plate phase 0, its fixed
//! points (period 1 or n), and their Floquet multipliers by finite differences.
//!
//! The section is `t = k T` (plate phase `omega t = 0 mod 2 pi`, the plate at its top).
//! A point of it is the mode there and the mode's free coordinates (the horizontal
//! position `x_c` is left out: the model does not depend on it, so it is cyclic, and a
//! walking gait is periodic only up to a shift of `x_c`):
//!
//! | mode | coordinates |
//! |---|---|
//! | pivot | `theta` (rad), `theta'` (rad/s) |
//! | slides | `theta`, `theta'`, `x_c'` (m/s) |
//! | flight | `theta`, `h_c` (m), `x_c'`, `z_c'` (m/s); `theta'` follows `theta` (C.3) |
//!
//! One application of the map is one call of the simulator
//! ([`crate::physics::stick::run::simulate_system`]) from `t = 0` to `n T`: the plate
//! is `T`-periodic, so every drive period is the same map, started at phase 0.

use crate::numerics::hybrid::Options;
use crate::physics::stick::rules::Next;
use crate::physics::stick::run::{simulate_system, Recording, StickOutcome};
use crate::physics::stick::{Mode, State, StickModel, NSTATE, OM, TH, VXC, VZC, ZC};
use nalgebra::DMatrix;

/// A point of the stroboscopic section: the mode at plate phase 0 and its coordinates
/// (see the module table).
#[derive(Debug, Clone, PartialEq)]
pub struct Point {
    /// The mode at the section.
    pub mode: Mode,
    /// The mode's free coordinates (SI units, module table).
    pub s: Vec<f64>,
}

/// Number of free coordinates of `mode` at the section.
pub fn dim(mode: Mode) -> usize {
    match mode {
        Mode::Pivot => 2,
        Mode::SlideLeft | Mode::SlideRight => 3,
        Mode::Flight => 4,
    }
}

/// Scale of each coordinate of `mode` (same units): 1 rad for `theta`, `omega` for
/// `theta'`, the plate's peak velocity `delta omega` for velocities, `delta` for `h_c`.
/// Distances on the section are measured in these units.
pub fn scales(model: &StickModel, mode: Mode) -> Vec<f64> {
    let w = model.p.plate.omega_rad_s;
    let d = model.p.plate.amplitude_m.max(1e-9 * model.p.length_m);
    let v = d * w;
    [1.0, w, v, v][..dim(mode)]
        .iter()
        .copied()
        .enumerate()
        .map(|(i, x)| if mode == Mode::Flight && i == 1 { d } else { x })
        .collect()
}

/// The section coordinates of the state `y` in `mode` at time `t` (a multiple of `T`).
pub fn coords(model: &StickModel, mode: Mode, t: f64, y: &State) -> Vec<f64> {
    match mode {
        Mode::Pivot => vec![y[TH], y[OM]],
        Mode::SlideLeft | Mode::SlideRight => vec![y[TH], y[OM], y[VXC]],
        Mode::Flight => vec![y[TH], model.h_c(t, y), y[VXC], y[VZC]],
    }
}

/// The full state at `t = 0` of a section point (`x_c = 0`, energy accounts zero).
pub fn embed(model: &StickModel, x: &Point) -> State {
    let mut y = [0.0; NSTATE];
    let s = &x.s;
    y[TH] = s[0];
    match x.mode {
        Mode::Pivot => y[OM] = s[1],
        Mode::SlideLeft | Mode::SlideRight => (y[OM], y[VXC]) = (s[1], s[2]),
        Mode::Flight => {
            let d = s[0] - model.p.theta0_rad;
            y[OM] = if model.rate.is_finite() {
                -model.rate * d // formula: C.3 theta' = -(k/gamma)(theta - theta_0)
            } else {
                0.0
            };
            y[ZC] = s[1] + model.plate(0.0).0;
            (y[VXC], y[VZC]) = (s[2], s[3]);
        }
    }
    model.canonical(x.mode, 0.0, &y)
}

// ANCHOR: strobe
/// The map `P^n`: the section point `n` drive periods after `x`, or the outcome that
/// ended the run first (fell, invalid, ...).
pub fn strobe(
    model: &StickModel,
    opts: &Options,
    x: &Point,
    n: usize,
) -> std::result::Result<Point, StickOutcome> {
    let y0 = embed(model, x);
    let t_end = n as f64 * model.period_s;
    let r = simulate_system(
        model,
        model,
        Next::To(x.mode, y0),
        0.0,
        y0,
        t_end,
        opts,
        Recording::default(),
    );
    if r.outcome != StickOutcome::Completed {
        return Err(r.outcome);
    }
    let s = coords(model, r.mode_end, r.end_time_s, &r.y_end);
    if s.iter().all(|v| v.is_finite()) {
        Ok(Point {
            mode: r.mode_end,
            s,
        })
    } else {
        Err(StickOutcome::Invalid("non-finite section point".into()))
    }
}
// ANCHOR_END: strobe

/// Largest coordinate difference of two points in units of [`scales`]; infinite when
/// their modes differ.
pub fn distance(model: &StickModel, a: &Point, b: &Point) -> f64 {
    if a.mode != b.mode {
        return f64::INFINITY;
    }
    let sc = scales(model, a.mode);
    a.s.iter()
        .zip(&b.s)
        .zip(&sc)
        .map(|((x, y), k)| (x - y).abs() / k)
        .fold(0.0, f64::max)
}

/// How a finite-difference Jacobian is formed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Difference {
    /// `(P(s + h e_j) - P(s - h e_j)) / 2h`: error `O(h^2)`.
    Central,
    /// `(P(s + h e_j) - P(s)) / h`: error `O(h)`.
    Forward,
}

/// The Jacobian of `P^n` at `x` by finite differences with step `h` times each
/// coordinate's scale; `None` if a perturbed run leaves the section's mode or stops.
pub fn jacobian(
    model: &StickModel,
    opts: &Options,
    x: &Point,
    n: usize,
    h: f64,
    how: Difference,
) -> Option<DMatrix<f64>> {
    let d = x.s.len();
    let sc = scales(model, x.mode);
    let centre = match how {
        Difference::Forward => Some(strobe(model, opts, x, n).ok()?),
        Difference::Central => None,
    };
    let mut j = DMatrix::zeros(d, d);
    for c in 0..d {
        let step = h * sc[c];
        let shifted = |sign: f64| {
            let mut p = x.clone();
            p.s[c] += sign * step;
            strobe(model, opts, &p, n).ok().filter(|q| q.mode == x.mode)
        };
        let plus = shifted(1.0)?;
        let (minus, width) = match &centre {
            Some(c0) => (c0.clone(), step),
            None => (shifted(-1.0)?, 2.0 * step),
        };
        for r in 0..d {
            j[(r, c)] = (plus.s[r] - minus.s[r]) / width; // formula: dP_r/ds_c by differences
        }
    }
    Some(j)
}

/// The eigenvalues of a square matrix (the Floquet multipliers of a monodromy),
/// sorted by decreasing modulus, as `(re, im)`.
pub fn multipliers(j: &DMatrix<f64>) -> Vec<(f64, f64)> {
    let mut v: Vec<(f64, f64)> = j
        .clone()
        .complex_eigenvalues()
        .iter()
        .map(|z| (z.re, z.im))
        .collect();
    v.sort_by(|a, b| b.0.hypot(b.1).total_cmp(&a.0.hypot(a.1)));
    v
}

/// The moduli of multipliers, in the same order.
pub fn moduli(m: &[(f64, f64)]) -> Vec<f64> {
    m.iter().map(|z| z.0.hypot(z.1)).collect()
}

/// Newton's method on `P^n(s) - s = 0` from `x`, with the central-difference Jacobian
/// at step `h`: at most `iters` steps, stopping when the residual (in units of the
/// scales) is below `tol`. Returns the point and its last residual.
pub fn newton(
    model: &StickModel,
    opts: &Options,
    x: &Point,
    n: usize,
    (h, tol, iters): (f64, f64, usize),
) -> Option<(Point, f64)> {
    let mut x = x.clone();
    let d = x.s.len();
    for _ in 0..iters {
        let px = strobe(model, opts, &x, n).ok()?;
        if px.mode != x.mode {
            return None; // P^n leaves the mode: not near a fixed point of this mode
        }
        let res = distance(model, &px, &x);
        if res < tol {
            return Some((x, res));
        }
        let j = jacobian(model, opts, &x, n, h, Difference::Central)?;
        let a = j - DMatrix::identity(d, d); // formula: D(P^n - id) = J - I
        let f = nalgebra::DVector::from_iterator(d, px.s.iter().zip(&x.s).map(|(p, s)| p - s));
        let dx = a.lu().solve(&(-f))?; // formula: (J - I) dx = -(P^n(s) - s)
        for (s, v) in x.s.iter_mut().zip(dx.iter()) {
            *s += v;
        }
    }
    let px = strobe(model, opts, &x, n).ok()?;
    let res = distance(model, &px, &x);
    (res < tol).then_some((x, res))
}

/// The gait a run settles into.
#[derive(Debug, Clone, PartialEq)]
pub enum Gait {
    /// A periodic gait of this many drive periods (1: period-1), with its section point.
    Periodic(usize, Point),
    /// Still no period up to the largest tried after the transient: chaotic, quasi-
    /// periodic or a slow transient (the section cannot tell them apart at this length);
    /// the orbit's last point.
    NotSettled(Point),
    /// The stick fell.
    Fell,
    /// The run stopped otherwise (invalid state, Zeno): the outcome's label.
    Stopped(&'static str),
}

impl Gait {
    /// Short label for tables and figures.
    pub fn label(&self) -> String {
        match self {
            Gait::Periodic(n, _) => format!("period-{n}"),
            Gait::NotSettled(_) => "not settled".into(),
            Gait::Fell => "fell".into(),
            Gait::Stopped(why) => (*why).into(),
        }
    }
}

/// The gait from `x`: `transient` periods of the map, then the smallest period
/// `n <= max_period` whose orbit closes to `tol` (units of the scales) on each of its
/// last `n` points.
pub fn settle(
    model: &StickModel,
    opts: &Options,
    x: &Point,
    (transient, max_period, tol): (usize, usize, f64),
) -> Gait {
    let mut orbit = vec![x.clone()];
    for _ in 0..transient + 2 * max_period {
        match strobe(model, opts, orbit.last().expect("non-empty"), 1) {
            Ok(p) => orbit.push(p),
            Err(StickOutcome::Fell) => return Gait::Fell,
            Err(o) => return Gait::Stopped(o.label()),
        }
    }
    let last = orbit.len() - 1;
    for n in 1..=max_period {
        let closes = (0..n).all(|k| distance(model, &orbit[last - k], &orbit[last - k - n]) < tol);
        if closes {
            return Gait::Periodic(n, orbit[last].clone());
        }
    }
    Gait::NotSettled(orbit[last].clone())
}

/// The section point of the static start (at rest at the static angle, or at `theta_0`
/// when the spring cannot hold the stick), in the mode the contact rules choose.
pub fn static_start(model: &StickModel) -> Option<Point> {
    let p = &model.p;
    let y = crate::physics::stick::run::initial_state(
        model,
        0.0,
        p.static_angle().unwrap_or(p.theta0_rad),
    );
    let start = if model.h_c(0.0, &y) > 0.0 {
        Next::To(Mode::Flight, y)
    } else {
        model.select_contact(0.0, &y)
    };
    match start {
        Next::To(mode, y) => Some(Point {
            mode,
            s: coords(model, mode, 0.0, &model.canonical(mode, 0.0, &y)),
        }),
        Next::Stop(_) => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::stick::jamming_scene;

    #[test]
    fn coordinates_round_trip_through_the_state_in_every_mode() {
        let m = StickModel::new(jamming_scene(9.81));
        let cases = [
            (Mode::Pivot, vec![0.35, -0.4]),
            (Mode::SlideRight, vec![0.35, -0.4, 0.3]),
            (Mode::SlideLeft, vec![0.35, 0.2, -0.1]),
            (Mode::Flight, vec![0.31, 1e-4, 0.2, 0.05]),
        ];
        for (mode, s) in cases {
            let x = Point { mode, s };
            let y = embed(&m, &x);
            let back = coords(&m, mode, 0.0, &y);
            assert_eq!(back.len(), dim(mode));
            for (a, b) in back.iter().zip(&x.s) {
                assert!((a - b).abs() < 1e-15, "{mode:?}: {back:?} vs {:?}", x.s);
            }
            // C on the plate in contact modes; in flight theta' follows C.3
            if mode == Mode::Flight {
                let w = -m.rate * (x.s[0] - m.p.theta0_rad);
                assert!((y[OM] - w).abs() < 1e-12);
            } else {
                assert_eq!(m.h_c(0.0, &y), 0.0);
            }
        }
        let a = Point {
            mode: Mode::Pivot,
            s: vec![0.3, 0.0],
        };
        let b = Point {
            mode: Mode::SlideRight,
            s: vec![0.3, 0.0, 0.0],
        };
        assert!(distance(&m, &a, &b).is_infinite());
    }
}
