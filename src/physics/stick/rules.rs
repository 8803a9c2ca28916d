//! Transition rules: which mode follows a landing, a lift-off, a stop of the slip or a
//! jam. Decided by the contact conditions of Table 1, not by habit:
//!
//! - C on the plate and not slipping: compute the pivot reaction F (C.6, C.7). `F_z < 0`:
//!   lift off. `|F_x| <= mu F_z`: pivot. Otherwise slide the way the missing tangential
//!   force drives: `F_x > mu F_z` (the plate would have to push C towards +x harder than
//!   friction can) -> slide left; `F_x < -mu F_z` -> slide right.
//! - Lift-off: the rod's rate becomes the flight rate `-(k/gamma)(theta - theta_0)`
//!   (continuous when F = 0) and the flight must move C away from the plate.
//! - Landing: a sticking impact (C.15) when the along-rod impulse is compressive
//!   (`w < 0`) and inside the friction cone (`|tan(theta)| <= mu`); otherwise no impulse
//!   can act and C lands sliding.
//! - A slide whose angle reaches the self-locking edge `tan(theta) = sigma mu` jams: the
//!   moment balance would need an infinite normal force; a sticking impulse along the
//!   rod (on the cone's edge) stops the slip.

use crate::numerics::hybrid::HybridSystem;

use super::contact::ContactEval;
use super::{
    CollisionAngle, InvalidReason, Mode, State, StickModel, StickStop, OM, TH, VXC, VZC, ZC,
};

/// The next mode and state, or a stop.
#[derive(Debug, Clone, PartialEq)]
pub enum Next {
    /// Continue in this mode from this state.
    To(Mode, State),
    /// Stop the run.
    Stop(StickStop),
}

impl StickModel {
    /// Mode for a state with C on the plate and not slipping. The pivot reaction test
    /// first: `F_z >= 0` and `|F_x| <= mu F_z` keeps the pivot. Otherwise the first
    /// consistent mode of: the slide the tangential force drives (if `F_z >= 0`) or the
    /// flight (if `F_z < 0`), then either slide, then the flight. A slide from rest is
    /// consistent when its normal force is compressive and its slip accelerates in its own
    /// direction; a flight when it moves C away from the plate. None: invalid.
    pub fn select_contact(&self, t: f64, y: &State) -> Next {
        self.select_contact_from(t, y, true)
    }

    /// [`StickModel::select_contact`] with the pivot excluded when `allow_pivot` is false:
    /// a pivot guard that fired at the edge of the cone (or at `F_z = 0`) must leave the
    /// pivot even if rounding puts the reaction back on the edge.
    pub(crate) fn select_contact_from(&self, t: f64, y: &State, allow_pivot: bool) -> Next {
        let mut y = *y;
        y[VXC] = 0.0;
        let e = self.pivot_eval(t, &y);
        let mu = self.p.mu;
        if allow_pivot
            && e.fz >= 0.0
            && e.fx.abs() <= mu * e.fz
            && !self.pivot_leaves_at_once(t, &y, &e)
        {
            return Next::To(Mode::Pivot, y);
        }
        let (drive, other) = if e.fx > 0.0 {
            (Mode::SlideLeft, Mode::SlideRight)
        } else {
            (Mode::SlideRight, Mode::SlideLeft)
        };
        let order: [Mode; 3] = if e.fz >= 0.0 {
            [drive, Mode::Flight, other]
        } else {
            [Mode::Flight, drive, other]
        };
        for mode in order {
            let next = if mode == Mode::Flight {
                self.takeoff(t, &y)
            } else {
                self.try_slide(mode, t, &y)
            };
            if let Next::To(..) = next {
                return next;
            }
        }
        Next::Stop(StickStop::invalid(format!(
            "no consistent contact mode at t = {t:.6} s (theta = {:.4} rad, pivot F = ({:.3e}, {:.3e}) N)",
            y[TH], e.fx, e.fz
        )))
    }

    /// Whether a pivot entered at `(t, y)` would leave its conditions at once, unseen: a
    /// pivot guard (`F_z`, `mu F_z -+ F_x`) that starts on its zero within rounding and
    /// falls. A guard never fires from its start, so such a pivot would run on with the
    /// reaction outside the cone (a rod with k = gamma = 0 carries its force along its
    /// axis, so at `tan(theta) = mu` the pivot's cone edge and the slide's self-locking
    /// edge coincide, and a jam there hands back a pivot about to leave the cone). The
    /// zero is judged against the rounding of the guard's own terms: 16 eps (|F_x| + mu
    /// |F_z|), a few roundings of each (larger margins fall through zero in a later step,
    /// which the event search sees); the sign of the fall from the guards' closed-form
    /// rates ([`StickModel::contact_guard_rates`]).
    /// `e` is the pivot's reaction at `(t, y)`.
    fn pivot_leaves_at_once(&self, t: f64, y: &State, e: &ContactEval) -> bool {
        let mut g = Vec::with_capacity(4);
        self.guards(Mode::Pivot, t, y, &mut g);
        let tol = 16.0 * f64::EPSILON * (e.fx.abs() + self.p.mu * e.fz.abs()); // formula: 16 eps (|F_x| + mu |F_z|)
        let f = self.flow(Mode::Pivot, t, y);
        let mut rates = Vec::with_capacity(4);
        self.contact_guard_rates(Mode::Pivot, t, y, &f, &mut rates);
        (0..3).any(|i| g[i] <= tol && rates[i] < 0.0)
    }

    /// The slide `mode` from rest at `(t, y)` if it is consistent (see
    /// [`StickModel::select_contact`]); a stop with the reason otherwise.
    pub(crate) fn try_slide(&self, mode: Mode, t: f64, y: &State) -> Next {
        if y[TH].sin().abs() < 1e-9 {
            return Next::Stop(StickStop::Invalid(InvalidReason::SingularSlide {
                t_s: t,
                entering: true,
            }));
        }
        let sigma = mode.sigma();
        let e = self.slide_eval(sigma, t, y);
        // From rest on the cone's edge the slip acceleration is zero (pivot and slide share
        // the force there): look a moment ahead along the slide's flow to see which way the
        // slip goes (the sign of its jerk).
        let h = 1e-6 * self.period_s;
        let mut y1 = *y;
        y1[TH] += h * y[OM];
        y1[OM] += h * e.theta_dd;
        y1[VXC] += h * e.xc_dd;
        let e1 = self.slide_eval(sigma, t + h, &y1);
        let ahead = y1[VXC] + h * e1.xc_dd; // slip velocity after 2h
        if e.fz < 0.0 || !e.fz.is_finite() || sigma * ahead > 0.0 {
            return Next::Stop(StickStop::invalid(format!(
                "{} inconsistent at t = {t:.6} s",
                mode.name()
            )));
        }
        Next::To(mode, *y)
    }

    fn enter_slide(&self, mode: Mode, t: f64, y: State) -> Next {
        if y[TH].sin().abs() < 1e-9 {
            return Next::Stop(StickStop::Invalid(InvalidReason::SingularSlide {
                t_s: t,
                entering: true,
            }));
        }
        let n = self.slide_eval(mode.sigma(), t, &y).fz;
        if n < 0.0 {
            // The slide would need a tensile force: C leaves the plate.
            return self.takeoff(t, &y);
        }
        Next::To(mode, y)
    }

    /// Lift-off: flight rate of the rod, C's velocity from P's (continuous) velocity;
    /// invalid if the flight would drive C into the plate.
    pub(crate) fn takeoff(&self, t: f64, y: &State) -> Next {
        let p = &self.p;
        if !self.rate.is_finite() {
            return Next::Stop(StickStop::invalid(
                "gamma = 0 with k > 0: the massless rod's angle in flight is undetermined"
                    .to_string(),
            ));
        }
        let l = p.length_m;
        let [_, _, vxp, vzp] = self.tip(y);
        let (zs, vs, a_s) = self.plate(t);
        let (s, c) = y[TH].sin_cos();
        let w = -self.rate * (y[TH] - p.theta0_rad); // formula: C.3
        let mut a = *y;
        a[ZC] = zs;
        a[OM] = w;
        a[VXC] = vxp - l * w * c; // formula: C.3
        a[VZC] = vzp + l * w * s; // formula: C.3
        let h_d = a[VZC] - vs;
        let h_dd = -p.g_mps2 + l * (c * w * w - s * self.rate * w) - a_s; // formula: C.4 with theta'' = -(k/gamma) theta'
                                                                          // A lift-off at F = 0 located to the event tolerance leaves C with a relative
                                                                          // velocity of order (F/gamma) L: zero up to about 1e-9 m/s at rtol 1e-10. 1e-6 of
                                                                          // the velocity scale is far above that and far below any real approach.
        let tol_v = 1e-6 * p.plate.peak_velocity_mps().max((p.g_mps2 * l).sqrt());
        if h_d < -tol_v || (h_d <= tol_v && h_dd < 0.0) {
            return Next::Stop(StickStop::invalid(format!(
                "lift-off at t = {t:.6} s would drive C into the plate (h_c' = {h_d:.3e} m/s, h_c'' = {h_dd:.3e} m/s^2): no consistent mode"
            )));
        }
        Next::To(Mode::Flight, a)
    }

    /// Along-rod velocity of P relative to the plate, `w = (v_P - zdot_s e_z) . e_r` (m/s).
    pub(crate) fn approach_velocity(&self, t: f64, y: &State) -> f64 {
        let [_, _, vxp, vzp] = self.tip(y);
        let (_, vs, _) = self.plate(t);
        let (s, c) = y[TH].sin_cos();
        vxp * s + (vzp - vs) * c
    }

    /// Landing (C reaches the plate in flight).
    pub fn landing(&self, t: f64, y: &State) -> Next {
        let mut y = *y;
        let lever = match self.p.collision_angle {
            CollisionAngle::Actual => y[TH],
            CollisionAngle::Reset => self.p.theta0_rad,
        };
        let w = self.approach_velocity(t, &y);
        if y[TH].tan().abs() <= self.p.mu && w < 0.0 {
            let imp = self.sticking_impact(t, &y, lever);
            return self.select_contact(t, &imp.after);
        }
        if self.p.collision_angle == CollisionAngle::Reset {
            y[TH] = lever; // the document's "after collision theta = theta_0", C kept in place
        }
        match self.impulse_free_landing(t, &y) {
            None => Next::Stop(StickStop::invalid(format!(
                "landing at t = {t:.6} s with the rod vertical outside the friction cone"
            ))),
            Some(a) => {
                if a[VXC] < 0.0 {
                    self.enter_slide(Mode::SlideLeft, t, a)
                } else if a[VXC] > 0.0 {
                    self.enter_slide(Mode::SlideRight, t, a)
                } else {
                    self.select_contact(t, &a)
                }
            }
        }
    }

    /// A slide reaching the self-locking edge: sticking impulse along the rod (on the
    /// cone's edge), then the pivot reaction test.
    pub fn jam(&self, t: f64, y: &State) -> Next {
        let imp = self.sticking_impact(t, y, y[TH]);
        if imp.lambda_ns < 0.0 {
            return Next::Stop(StickStop::invalid(format!(
                "jam at t = {t:.6} s would need a tensile impulse (w = {:.3e} m/s)",
                imp.w_mps
            )));
        }
        self.select_contact(t, &imp.after)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::hybrid::Options;
    use crate::physics::stick::run::{initial_state, simulate_stick, Recording};
    use crate::physics::stick::StickParams;

    /// The fuzz's scene (issue 29): a rod with neither spring nor damper carries its
    /// force along its axis, so its pivot reaches the cone's edge at tan(theta) = mu,
    /// where the slide jams at once. The pivot must not be handed back there.
    fn strut() -> StickModel {
        let p = StickParams::new(0.015, 1.0, 0.0, 0.0, 0.4, 0.3, 9.81, 3.0, 58.02453827466382);
        StickModel::new(p.expect("in the domain"))
    }

    #[test]
    fn a_pivot_about_to_leave_the_cone_is_not_chosen() {
        let m = strut();
        let t = 0.5 * m.period_s; // the plate accelerates upwards: a compressive reaction
        let at_edge = |om: f64| {
            let mut y = initial_state(&m, t, m.atan_mu);
            y[OM] = om;
            m.canonical(Mode::Pivot, t, &y)
        };
        let rising = at_edge(10.0); // past the edge: the reaction turns outside the cone
        assert!(m.pivot_eval(t, &rising).fz > 0.0);
        assert!(m.pivot_leaves_at_once(t, &rising, &m.pivot_eval(t, &rising)));
        assert!(!matches!(
            m.select_contact(t, &rising),
            Next::To(Mode::Pivot, _)
        ));
        // Falling back into the cone: the pivot holds.
        let back = at_edge(-10.0);
        assert!(!m.pivot_leaves_at_once(t, &back, &m.pivot_eval(t, &back)));
    }

    #[test]
    fn no_accepted_pivot_step_lies_outside_the_cone() {
        let m = strut();
        let y0 = initial_state(&m, 0.0, 0.3);
        let rec = Recording {
            check_invariants: true,
            ..Recording::default()
        };
        let s = simulate_stick(&m, 0.0, y0, 0.2, &Options::default(), rec);
        let mg = m.p.mass_kg * m.p.g_mps2;
        // Before: 5.5e-2 m g outside the cone (a pivot run on past its edge unseen).
        assert!(s.violations.cone_n <= 1e-9 * mg, "{:?}", s.violations);
    }
}
