//! The [`HybridSystem`] implementation and the transition rules.
//!
//! Guards, by mode, in priority order:
//! - Flight: 0 `h_c` falling (landing); 1 `pi/2 - |theta|` falling (fell).
//! - Pivot: 0 `F_z` falling (lift-off); 1 `mu F_z - F_x` and 2 `mu F_z + F_x` falling
//!   (the cone's edges); 3 `pi/2 - |theta|` falling (fell).
//! - Slides: 0 `D` either way (the Painleve coefficient crosses zero); 1 `N sign(D)`
//!   falling (normal force reaching zero); 2 `-sigma xdot_c + 1e-12` falling (slip
//!   stops); 3 `pi/2 - |theta|` falling (fell).
//!
//! Rules: C on the plate and not slipping -> the pivot reaction test, then the slide the
//! missing tangential force drives, the flight, the other slide (each if consistent).
//! Landing -> the impact ([`super::impact`]), then by C's velocity after it: flight
//! (bounce), pivot test (stuck), or the slide of its slip. Entering a slide checks its
//! Painleve coefficient and applies the rules of [`super::painleve`].

use super::impact::darboux_keller;
use super::painleve::mu_painleve;
use super::{
    ImpactRecord, InertiaModel, InertiaStop, Mode, PainleveCase, PainleveEvent, State, D_DAMP,
    D_FRIC, D_IMPACT, FLOW_ARGS, NSTATE, OM, TH, VXC, VZC, W_PLATE, XC,
};
use crate::numerics::events::Direction;
use crate::numerics::hybrid::{HybridSystem, Transition};
use std::f64::consts::FRAC_PI_2;

/// A transition decided by the rules.
pub type Next = Transition<Mode, InertiaStop, NSTATE>;

impl HybridSystem<NSTATE> for InertiaModel {
    type Mode = Mode;
    type Stop = InertiaStop;
    const FLOW_ARGS: usize = FLOW_ARGS;
    const GUARD_ARGS: usize = FLOW_ARGS;

    fn flow(&self, mode: Mode, t: f64, y: &State) -> State {
        let Some(e) = self.contact_eval(mode, t, y) else {
            return [0.0; NSTATE]; // flight uses the closed form
        };
        let (_, vs, _) = self.plate(t);
        let mut d = [0.0; NSTATE];
        d[TH] = y[OM];
        d[OM] = e.theta_dd;
        d[VXC] = e.xc_dd;
        d[XC] = y[VXC];
        d[W_PLATE] = e.fz * vs; // formula: plate power F_z zdot_s
        d[D_FRIC] = -e.fx * y[VXC]; // formula: friction loss -F_x xdot_c
        d[D_DAMP] = self.p.base.damping_nms_per_rad * y[OM] * y[OM]; // formula: damper loss gamma theta'^2
        d
    }

    fn exact(&self, mode: Mode, t0: f64, y0: &State, t: f64) -> Option<State> {
        (mode == Mode::Flight).then(|| self.flight_state(t0, y0, t))
    }

    fn guard_count(&self, mode: Mode) -> usize {
        match mode {
            Mode::Flight => 2,
            _ => 4,
        }
    }

    fn guard(&self, mode: Mode, i: usize, t: f64, y: &State) -> f64 {
        self.with_guards(mode, t, y, |g| g[i])
    }

    fn guards(&self, mode: Mode, t: f64, y: &State, out: &mut Vec<f64>) {
        out.clear();
        self.with_guards(mode, t, y, |g| out.extend_from_slice(g));
    }

    fn direction(&self, mode: Mode, i: usize) -> Direction {
        match (mode, i) {
            (Mode::SlideLeft | Mode::SlideRight, 0) => Direction::Either,
            _ => Direction::Falling,
        }
    }

    fn on_event(&self, mode: Mode, i: usize, t: f64, y: &State) -> Next {
        let y = &self.canonical(mode, t, y);
        let next = match (mode, i) {
            (Mode::Flight, 0) => self.landing(t, y),
            (Mode::Flight, _) | (_, 3) => Transition::Stop(InertiaStop::Fell),
            (Mode::Pivot, _) => self.select_contact(t, y, false, 0),
            (_, 0) => self.painleve(mode, t, y, None, 0),
            (_, 1) => self.takeoff(t, y),
            _ => {
                let mut y = *y;
                y[VXC] = 0.0;
                self.select_contact(t, &y, true, 0)
            }
        };
        self.restart_accumulators(next, y)
    }

    fn max_step(&self, mode: Mode, t: f64, y: &State) -> f64 {
        match mode {
            Mode::Flight => self.flight_step(t, y),
            _ => self.max_contact_step_s,
        }
    }
}

impl InertiaModel {
    /// All guards of `mode` at `(t, y)` (the module's order), handed to `f`: one force
    /// evaluation serves them all.
    fn with_guards<R>(&self, mode: Mode, t: f64, y: &State, f: impl FnOnce(&[f64]) -> R) -> R {
        let mu = self.p.base.mu;
        let fell = FRAC_PI_2 - y[TH].abs();
        match mode {
            Mode::Flight => {
                let h = self.h_c(t, y);
                // a flight that starts on the plate starts its guard at zero: count it as above
                f(&[if h == 0.0 { f64::MIN_POSITIVE } else { h }, fell])
            }
            Mode::Pivot => {
                let e = self.pivot_eval(t, y);
                f(&[e.fz, mu * e.fz - e.fx, mu * e.fz + e.fx, fell])
            }
            _ => {
                let e = self.slide_eval(mode.sigma(), t, y);
                f(&[
                    e.d,
                    e.n * e.d.signum(),
                    -mode.sigma() * y[VXC] + 1e-12,
                    fell,
                ])
            }
        }
    }

    /// Energy accumulators restart at zero in every mode; the new state carries only
    /// what the reset added (the run's observer sums them).
    fn restart_accumulators(&self, next: Next, y: &State) -> Next {
        match next {
            Transition::To { mode, mut state } => {
                for k in W_PLATE..=D_IMPACT {
                    state[k] -= y[k];
                }
                Transition::To { mode, state }
            }
            stop => stop,
        }
    }

    /// C on the plate, not slipping (`xdot_c = 0`): the pivot reaction test, then the
    /// first consistent of the driven slide, the flight, the other slide. `depth` counts
    /// nested impacts without collision (a bound, so a rule can never loop).
    pub fn select_contact(&self, t: f64, y: &State, allow_pivot: bool, depth: usize) -> Next {
        let mu = self.p.base.mu;
        let e = self.pivot_eval(t, y);
        let eta_f = self.force_rounding(y);
        // inside the cone up to the force's rounding (see super::rounding)
        if allow_pivot && e.fz >= -eta_f && e.fx.abs() <= mu * e.fz + eta_f {
            return Transition::To {
                mode: Mode::Pivot,
                state: *y,
            };
        }
        let drive = if e.fx > 0.0 {
            Mode::SlideLeft
        } else {
            Mode::SlideRight
        };
        let other = if drive == Mode::SlideLeft {
            Mode::SlideRight
        } else {
            Mode::SlideLeft
        };
        let order = if e.fz >= 0.0 {
            [drive, Mode::Flight, other]
        } else {
            [Mode::Flight, drive, other]
        };
        for m in order {
            let next = if m == Mode::Flight {
                self.takeoff(t, y)
            } else {
                self.slide_from_rest(m, t, y, depth)
            };
            if let Transition::To { .. } = next {
                return next;
            }
        }
        Transition::Stop(InertiaStop::NoMode(format!(
            "no consistent contact mode at t = {t:.6} s (theta = {:.4} rad, pivot F = ({:.3e}, {:.3e}) N)",
            y[TH], e.fx, e.fz
        )))
    }

    /// A slide from rest, if consistent: a compressive normal force (`D > 0`) and a slip
    /// that starts in the slide's direction (seen a moment ahead along its flow: on the
    /// cone's edge the slip acceleration starts at zero).
    fn slide_from_rest(&self, mode: Mode, t: f64, y: &State, _depth: usize) -> Next {
        let sigma = mode.sigma();
        let e = self.slide_eval(sigma, t, y);
        let no = Transition::Stop(InertiaStop::Invalid(format!(
            "{} inconsistent",
            mode.name()
        )));
        // D zero to rounding is no slide: its normal force would be rounding divided by it
        if e.d <= self.coefficient_rounding(y[TH]) || e.fz < 0.0 || !e.fz.is_finite() {
            return no;
        }
        let h = 1e-6 * self.period_s;
        let mut y1 = *y;
        y1[TH] += h * y[OM];
        y1[OM] += h * e.theta_dd;
        y1[VXC] += h * e.xc_dd;
        let e1 = self.slide_eval(sigma, t + h, &y1);
        if sigma * (y1[VXC] + h * e1.xc_dd) > 0.0 {
            return no;
        }
        Transition::To { mode, state: *y }
    }

    /// C on the plate slipping at `y[VXC] != 0`: the slide of that slip if its contact
    /// problem has one solution with `F_z >= 0`; lift-off if that solution is tensile;
    /// the Painleve rules otherwise.
    pub(crate) fn enter_slide(&self, t: f64, y: &State, depth: usize) -> Next {
        // a slip below the rounding of C's velocity is no slip: C is stuck (a 1e-13 m/s
        // remainder of a sticking impact is not a slide, let alone a Painleve case)
        if y[VXC].abs() <= self.velocity_rounding([y[VXC], 0.0]) {
            let mut y = *y;
            y[VXC] = 0.0;
            return self.select_contact(t, &y, true, depth);
        }
        let mode = if y[VXC] < 0.0 {
            Mode::SlideLeft
        } else {
            Mode::SlideRight
        };
        let e = self.slide_eval(mode.sigma(), t, y);
        if e.d > self.coefficient_rounding(y[TH]) {
            if e.fz >= 0.0 {
                return Transition::To { mode, state: *y };
            }
            return self.takeoff(t, y);
        }
        self.painleve(mode, t, y, Some(e.n), depth)
    }

    /// A Painleve case of the slide `mode` at `(t, y)` (`n`: the slide's numerator, or
    /// `None` when the coefficient crossed zero during the slide, where the normal force
    /// grew without bound: inconsistent beyond). Recorded, then resolved by the rules.
    fn painleve(&self, mode: Mode, t: f64, y: &State, n: Option<f64>, depth: usize) -> Next {
        let case = match n {
            Some(n) if n < 0.0 => PainleveCase::Indeterminate,
            _ => PainleveCase::Inconsistent,
        };
        let ev = PainleveEvent {
            t_s: t,
            theta_rad: y[TH],
            mu: self.p.base.mu,
            mu_p: mu_painleve(y[TH], self.geo.alpha()),
            case,
            sigma: mode.sigma(),
        };
        self.log.borrow_mut().painleve.push(ev);
        if depth > 4 {
            return Transition::Stop(InertiaStop::PainleveUnresolved(ev));
        }
        if n.is_none() && self.painleve_rule == super::PainleveRule::PreferSeparation {
            // the comparison rule: the zero-impulse solution, as a time-stepper that
            // prefers separation picks it where its step's contact problem has two
            return Transition::To {
                mode: Mode::Flight,
                state: *y,
            };
        }
        match case {
            PainleveCase::Indeterminate => self.takeoff(t, y),
            PainleveCase::Inconsistent => match self.impact(t, y, false) {
                Some(a) => self.after_impact(t, y, &a, depth + 1),
                None => Transition::Stop(InertiaStop::PainleveUnresolved(ev)),
            },
        }
    }

    /// Lift-off with the state continuous (the rod's rate does not jump: it has inertia);
    /// consistent when the free motion moves C away from the plate (`N <= 0`).
    pub(crate) fn takeoff(&self, t: f64, y: &State) -> Next {
        let e = self.slide_eval(1.0, t, y); // N does not depend on the slide's direction
        let b = &self.p.base;
        let scale = self.geo.i_g * (b.g_mps2 + b.plate.peak_acceleration_mps2())
            + self.geo.l_g_m * self.couple(y[TH], y[OM]).abs();
        if e.n > 1e-9 * scale {
            return Transition::Stop(InertiaStop::Invalid(format!(
                "lift-off at t = {t:.6} s would drive C into the plate"
            )));
        }
        self.note_lift_off(t);
        Transition::To {
            mode: Mode::Flight,
            state: *y,
        }
    }

    /// Landing: the impact, then the mode its outcome selects (or, at the end of a chain
    /// of unresolvably short flights, the stop that hands the run to Moreau-Jean).
    pub fn landing(&self, t: f64, y: &State) -> Next {
        if let Some(stop) = self.note_landing(t) {
            return stop;
        }
        match self.impact(t, y, true) {
            Some(a) => self.after_impact(t, y, &a, 0),
            None => Transition::Stop(InertiaStop::Invalid(format!(
                "the landing impact at t = {t:.6} s has no finite impulse"
            ))),
        }
    }

    /// The mode after an impact from `y` to `a`: a bounce (flight) only when C leaves
    /// the plate faster than the rounding of its velocity, `eta_v = C u (1 + alpha) V`
    /// ([`super::rounding`]); otherwise C is on the plate (its normal velocity, a
    /// rounding remainder, is set to the plate's and logged as the impact's
    /// complementarity residual), stuck if its slip is below `eta_v` too.
    fn after_impact(&self, t: f64, y: &State, a: &State, depth: usize) -> Next {
        let (_, vs, _) = self.plate(t);
        let u0 = self.relative_velocity(t, y);
        let eta = self.velocity_rounding(u0);
        let un = a[VZC] - vs;
        let plastic = self.p.restitution == 0.0;
        let bounce = un > eta;
        {
            // complementarity after the impact, relative to eta: a plastic impact ends
            // with u_n = 0; a contact decision discards u_n
            let mut log = self.log.borrow_mut();
            let r = if bounce && !plastic { 0.0 } else { un.abs() };
            log.max_normal_residual_mps = log.max_normal_residual_mps.max(r);
            log.max_residual_ratio = log.max_residual_ratio.max(r / eta); // formula: |u_n+| / eta_v
        }
        if bounce {
            return Transition::To {
                mode: Mode::Flight,
                state: *a,
            };
        }
        let mut a = self.canonical(Mode::Pivot, t, a);
        if a[VXC].abs() <= eta {
            a[VXC] = 0.0;
        }
        if a[VXC] == 0.0 {
            self.select_contact(t, &a, true, depth)
        } else {
            self.enter_slide(t, &a, depth)
        }
    }

    /// The impact at C from `(t, y)` (a landing, or an impact without collision): the
    /// state after it, with the plate's impulse work and the loss booked, and the impact
    /// logged with its energy check. `None`: no finite impulse.
    pub fn impact(&self, t: f64, y: &State, landing: bool) -> Option<State> {
        let b = &self.p.base;
        let u0 = self.relative_velocity(t, y);
        let r = match self.impact_law {
            super::ImpactLaw::DarbouxKeller => {
                darboux_keller(self.mobility(y[TH]), b.mu, self.p.restitution, u0, !landing).ok()?
            }
            super::ImpactLaw::VelocityCoulomb => self.velocity_coulomb(u0, y[TH])?,
        };
        let (m, l, ig) = (self.geo.total_kg, self.geo.l_g_m, self.geo.i_g);
        let (s, c) = y[TH].sin_cos();
        let [_, _, vxg, vzg] = self.centre(y);
        let (vxg, vzg) = (vxg + r.p_t / m, vzg + r.p_n / m); // formula: M dv_G = P
        let om = y[OM] - l * (r.p_t * c - r.p_n * s) / ig; // formula: I_G d theta' = -l_G P . e_theta
        let mut a = *y;
        a[OM] = om;
        a[VXC] = vxg - l * om * c; // formula: v_C = v_G - l_G theta' e_theta
        a[VZC] = vzg + l * om * s;
        let (_, vs, _) = self.plate(t);
        a[W_PLATE] += r.p_n * vs; // formula: plate work of the impulse P_n zdot_s
        a[D_IMPACT] += r.loss_j;
        // the slip may stop exactly: clear rounding so that the rules see C stuck
        if r.u_after[0] == 0.0 {
            a[VXC] = 0.0;
        }
        let gain = self.kinetic_energy(&a) - self.kinetic_energy(y) - r.p_n * vs; // formula: dT - P_n zdot_s = -loss
        let mut log = self.log.borrow_mut();
        log.impact_count += 1;
        log.max_energy_gain_j = log.max_energy_gain_j.max(gain);
        if log.impacts.len() < super::Log::CAP {
            log.impacts.push(ImpactRecord {
                t_s: t,
                theta_rad: y[TH],
                j_t_ns: r.p_t,
                j_n_ns: r.p_n,
                loss_j: r.loss_j,
                energy_change_j: gain,
                slip_before_mps: u0[0],
                slip_after_mps: a[VXC],
                normal_after_mps: a[VZC] - vs,
                landing,
            });
        }
        Some(a)
    }

    /// Moreau-Jean's velocity-level impact law ([`super::ImpactLaw::VelocityCoulomb`]).
    fn velocity_coulomb(&self, u0: [f64; 2], theta: f64) -> Option<super::impact::ImpulseResult> {
        use crate::numerics::timestepping::{solve_contact, ContactStatus};
        let w = self.mobility(theta);
        let wn = [[w[1][1], w[1][0]], [w[0][1], w[0][0]]]; // (n, t) order
        let s0 = self.p.restitution * u0[1].min(0.0); // formula: Newton, u_n+ >= -e u_n-
        let imp = solve_contact(wn, [u0[1], u0[0]], s0, self.p.base.mu)?;
        let u1 = [
            u0[0] + w[0][0] * imp.p_t + w[0][1] * imp.p_n,
            u0[1] + w[1][0] * imp.p_t + w[1][1] * imp.p_n,
        ];
        // formula: -int u . dP along the straight path P(s) = s P (u linear in s)
        let loss = -(0.5 * (u0[0] + u1[0]) * imp.p_t + 0.5 * (u0[1] + u1[1]) * imp.p_n);
        let stuck = imp.status == ContactStatus::Stick;
        Some(super::impact::ImpulseResult {
            p_t: imp.p_t,
            p_n: imp.p_n,
            u_after: [if stuck { 0.0 } else { u1[0] }, u1[1]],
            loss_j: loss,
        })
    }
}
