//! Flight in closed form: no contact force, so G is ballistic and the angle obeys
//! `I_G theta'' = -k (theta - theta_0) - gamma theta'` (the couple is the only moment
//! about G): a damped linear oscillator in `d = theta - theta_0`. With `I_G = 0` it is
//! chapter 6's first-order relaxation `gamma d' = -k d` (C.3).

use super::{InertiaModel, State, D_DAMP, OM, TH, VXC, VZC, XC, ZC};

/// The oscillator `I d'' + c d' + k d = 0` from `(d0, v0)`: its solution, in a form that
/// gives the state at any later time and bounds on `|d'|`, `|d''|` over all later times.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Oscillator {
    /// `d = a e^{s1 t} + b e^{s2 t}` (overdamped, or `I = 0` with `b = 0`).
    TwoExp {
        /// Amplitudes.
        a: f64,
        /// See `a`.
        b: f64,
        /// Rates (1/s, <= 0).
        s1: f64,
        /// See `s1`.
        s2: f64,
    },
    /// `d = (a + b t) e^{s t}` (critical damping).
    Critical {
        /// Amplitudes.
        a: f64,
        /// See `a`.
        b: f64,
        /// Rate (1/s).
        s: f64,
    },
    /// `d = e^{r t} (a cos(w t) + b sin(w t))` (underdamped).
    Damped {
        /// Amplitudes.
        a: f64,
        /// See `a`.
        b: f64,
        /// Decay rate (1/s, <= 0).
        r: f64,
        /// Angular frequency (rad/s).
        w: f64,
    },
    /// `d = d0 + v0 t` (no spring, no damper, no inertia to speak of).
    Free {
        /// Start value.
        d0: f64,
        /// Rate.
        v0: f64,
    },
}

impl Oscillator {
    /// The solution with inertia `i` (kg m^2), damping `c` (N m s/rad), stiffness `k`
    /// (N m/rad), from `d(0) = d0`, `d'(0) = v0` (`v0` ignored when `i = 0`).
    pub fn new(i: f64, c: f64, k: f64, d0: f64, v0: f64) -> Self {
        if i == 0.0 {
            let s1 = if c > 0.0 { -k / c } else { 0.0 }; // formula: C.3 gamma d' = -k d
            return Oscillator::TwoExp {
                a: d0,
                b: 0.0,
                s1,
                s2: 0.0,
            };
        }
        let disc = c * c - 4.0 * i * k; // formula: roots of I s^2 + c s + k = 0
        if disc > 1e-12 * c * c && c > 0.0 {
            let q = -0.5 * (c + disc.sqrt());
            let (s1, s2) = (k / q, q / i); // slow and fast roots, without cancellation
            let a = (v0 - s2 * d0) / (s1 - s2); // formula: a + b = d0, s1 a + s2 b = v0
            Oscillator::TwoExp {
                a,
                b: d0 - a,
                s1,
                s2,
            }
        } else if disc < -1e-12 * c * c || (c == 0.0 && k > 0.0) {
            let (r, w) = (-c / (2.0 * i), (-disc).sqrt() / (2.0 * i));
            Oscillator::Damped {
                a: d0,
                b: (v0 - r * d0) / w,
                r,
                w,
            }
        } else if c == 0.0 {
            Oscillator::Free { d0, v0 }
        } else {
            let s = -c / (2.0 * i);
            Oscillator::Critical {
                a: d0,
                b: v0 - s * d0,
                s,
            }
        }
    }

    /// `(d, d', d'')` at time `t` (s) after the start.
    pub fn at(&self, t: f64) -> (f64, f64, f64) {
        match *self {
            Oscillator::TwoExp { a, b, s1, s2 } => {
                let (e1, e2) = (a * (s1 * t).exp(), b * (s2 * t).exp());
                (e1 + e2, s1 * e1 + s2 * e2, s1 * s1 * e1 + s2 * s2 * e2)
            }
            Oscillator::Critical { a, b, s } => {
                let e = (s * t).exp();
                let d = (a + b * t) * e;
                let v = (b + s * (a + b * t)) * e;
                (d, v, (2.0 * s * b + s * s * (a + b * t)) * e)
            }
            Oscillator::Damped { a, b, r, w } => {
                let (sn, cs) = (w * t).sin_cos();
                let e = (r * t).exp();
                let d = e * (a * cs + b * sn);
                let dd = e * (b * cs - a * sn) * w; // derivative of the bracket
                let v = r * d + dd;
                let acc = r * v + r * dd + e * w * w * -(a * cs + b * sn);
                (d, v, acc)
            }
            Oscillator::Free { d0, v0 } => (d0 + v0 * t, v0, 0.0),
        }
    }

    /// Bounds on `|d'|` and `|d''|` over all `t >= 0`.
    pub(crate) fn bounds(&self) -> (f64, f64) {
        match *self {
            Oscillator::TwoExp { a, b, s1, s2 } => (
                (a * s1).abs() + (b * s2).abs(),
                (a * s1 * s1).abs() + (b * s2 * s2).abs(),
            ),
            Oscillator::Critical { a, b, s } => (
                (a * s).abs() + 1.4 * b.abs(),
                (a * s * s).abs() + 2.4 * (b * s).abs(),
            ),
            Oscillator::Damped { a, b, r, w } => {
                let amp = a.hypot(b);
                let m2 = r * r + w * w;
                (amp * m2.sqrt(), amp * m2)
            }
            Oscillator::Free { v0, .. } => (v0.abs(), 0.0),
        }
    }
}

impl InertiaModel {
    /// The angle's oscillator for a flight starting at `y0`.
    pub(crate) fn flight_oscillator(&self, y0: &State) -> Oscillator {
        let b = &self.p.base;
        Oscillator::new(
            self.geo.i_g,
            b.damping_nms_per_rad,
            b.stiffness_nm_per_rad,
            y0[TH] - b.theta0_rad,
            y0[OM],
        )
    }

    /// The flight state at `t` of a flight that starts at `(t0, y0)`.
    pub(crate) fn flight_state(&self, t0: f64, y0: &State, t: f64) -> State {
        let b = &self.p.base;
        let tau = t - t0;
        let [xg, zg, vxg, vzg] = self.centre(y0);
        let osc = self.flight_oscillator(y0);
        let (d, w, _) = osc.at(tau);
        let th = b.theta0_rad + d;
        let (s, c) = th.sin_cos();
        let l = self.geo.l_g_m;
        let mut y = *y0;
        y[TH] = th;
        y[OM] = w;
        y[XC] = xg + vxg * tau - l * s; // formula: x_C = x_G(t) - l_G sin, G ballistic
        y[ZC] = zg + vzg * tau - 0.5 * b.g_mps2 * tau * tau - l * c; // formula: z_C = z_G(t) - l_G cos
        y[VXC] = vxg - l * w * c; // formula: v_C = v_G - l_G theta' e_theta
        y[VZC] = vzg - b.g_mps2 * tau + l * w * s;
        let d0 = y0[TH] - b.theta0_rad;
        let rot =
            |d: f64, w: f64| 0.5 * b.stiffness_nm_per_rad * d * d + 0.5 * self.geo.i_g * w * w;
        y[D_DAMP] = y0[D_DAMP] + rot(d0, y0[OM]) - rot(d, w); // formula: damper loss = drop of I_G theta'^2/2 + k d^2/2
        y
    }

    /// Height of C above the plate (m).
    pub(crate) fn h_c(&self, t: f64, y: &State) -> f64 {
        y[ZC] - self.plate(t).0
    }

    /// Longest flight step over which `h_c` provably stays positive, from
    /// `|h_c''| <= A = g + delta omega^2 + l_G (max|theta''| + max theta'^2)`; never
    /// shorter than `min_flight_sample_s`.
    pub(crate) fn flight_step(&self, t: f64, y: &State) -> f64 {
        let b = &self.p.base;
        let (_, vs, _) = self.plate(t);
        let h = self.h_c(t, y).max(0.0);
        let v = y[VZC] - vs;
        let (v_max, a_max) = self.flight_oscillator(y).bounds();
        let a =
            b.g_mps2 + b.plate.peak_acceleration_mps2() + self.geo.l_g_m * (a_max + v_max * v_max);
        let safe = (v + (v * v + 2.0 * a * h).sqrt()) / a; // formula: root of h + v s - A s^2/2
        safe.max(self.min_flight_sample_s).min(self.period_s)
    }
}

#[cfg(test)]
mod tests {
    use super::Oscillator;

    #[test]
    fn oscillator_solves_its_equation_in_every_regime() {
        for (i, c, k) in [
            (1e-3, 0.01, 10.0),
            (1e-5, 0.01, 10.0),
            (2.5e-6, 0.01, 10.0),
            (1.0, 0.01, 10.0),
            (1.0, 0.0, 0.0),
            (1e-3, 0.0, 10.0),
        ] {
            let o = Oscillator::new(i, c, k, 0.1, -2.0);
            let (d0, v0, _) = o.at(0.0);
            assert!((d0 - 0.1).abs() < 1e-9 && (v0 + 2.0).abs() < 1e-6, "{o:?}");
            for t in [1e-4, 3e-3, 0.05] {
                let (d, v, a) = o.at(t);
                let res = i * a + c * v + k * d;
                assert!(
                    res.abs() < 1e-8 * (k * d.abs() + c * v.abs() + i * a.abs() + 1e-12),
                    "{o:?} {t} {res}"
                );
                let h = 1e-7;
                let fd = (o.at(t + h).0 - o.at(t - h).0) / (2.0 * h);
                assert!((fd - v).abs() < 1e-5 * (v.abs() + 1e-3), "{o:?} {fd} {v}");
                let (vb, ab) = o.bounds();
                assert!(v.abs() <= vb * (1.0 + 1e-12) && a.abs() <= ab * (1.0 + 1e-12));
            }
        }
    }
}
