//! The [`HybridSystem`] implementation: flows, guards and their transitions.
//!
//! Guards, by mode, in priority order (ties go to the lower index):
//! - Flight: 0 `h_c` falling (landing); 1 `-h_c - tol` rising (a missed landing: invalid).
//! - Pivot: 0 `F_z` falling (lift-off); 1 `mu F_z - F_x` falling and 2 `mu F_z + F_x`
//!   falling (friction cone's edges); 3 `pi/2 - |theta|` falling (fell).
//! - Slides: 0 `theta - sigma atan(mu)`, the zero of the slide denominator (jam); 1 `Q sign(den)` falling, `Q = k (theta -
//!   theta_0) + gamma theta'` (normal force reaching zero: lift-off); 2 `-sigma xdot_c + 1e-12`
//!   falling (slip stops); 3 `pi/2 - |theta|` falling (fell); 4 `theta` (C.14 singular:
//!   invalid); 5 `sigma xdot_c - tol` rising (slip against friction: invalid).

use super::rules::Next;
use super::{
    InvalidReason, Mode, State, StickModel, StickStop, D_DAMP, D_FRIC, D_IMPACT, FLOW_ARGS, NSTATE,
    OM, ROD_X, ROD_Z, TH, VXC, W_PLATE, XC,
};
use crate::numerics::events::Direction;
use crate::numerics::hybrid::{HybridSystem, Transition};
use std::f64::consts::FRAC_PI_2;

impl StickModel {
    /// The transition to `next` decided at `(t, y)` (`y` the state the event was found
    /// at, made canonical). The energy accumulators restart from zero in every mode
    /// (keeping them small keeps their share of the error control honest); the new state
    /// carries only what the reset itself added (impulse work, impact loss), and the run's
    /// observer sums them. The carried plate height and rod direction start every mode
    /// exact. Shared by the physical rules and the printed ones.
    pub(super) fn transition(
        &self,
        next: Next,
        t: f64,
        y: &State,
    ) -> Transition<Mode, StickStop, NSTATE> {
        match next {
            Next::To(mode, mut state) => {
                for k in W_PLATE..=D_IMPACT {
                    state[k] -= y[k];
                }
                Transition::To {
                    mode,
                    state: self.canonical(mode, t, &state),
                }
            }
            Next::Stop(x) => Transition::Stop(x),
        }
    }
}

impl HybridSystem<NSTATE> for StickModel {
    type Mode = Mode;
    type Stop = StickStop;
    const FLOW_ARGS: usize = FLOW_ARGS;
    // The contact modes' guards read theta, theta', xdot_c and the rod's direction only
    // (the flight's height guard reads z_c, but flight has its closed form).
    const GUARD_ARGS: usize = FLOW_ARGS;

    fn flow(&self, mode: Mode, t: f64, y: &State) -> State {
        let p = &self.p;
        // The plate's phase by the table (it depends on t alone, so it runs beside the
        // rest); the rod's direction is carried in the state (see the module's table).
        let (_, vs, a_s) = self.plate(t);
        let e = match mode {
            Mode::Flight => return [0.0; NSTATE], // flight uses the closed form
            Mode::Pivot => self.pivot_eval_carried(a_s, y),
            Mode::SlideLeft | Mode::SlideRight => self.slide_eval_carried(mode.sigma(), a_s, y),
        };
        // Friction loss -F_x xdot_c = -sigma mu F_z xdot_c (zero in pivot): it equals
        // mu F_z |xdot_c| while C slips in the slide's direction, but has no kink where the
        // slip stops. With |xdot_c| the step that brackets the stop integrated a kink:
        // its error estimate rejected it (1 in 7 steps) and the accepted step's dense
        // output carried up to 1e-5 of the budget into the located stop.
        let friction = -e.fx * y[VXC];
        let mut d = [0.0; NSTATE]; // z_c and zdot_c follow the plate: not integrated (see StickModel::canonical)
        d[TH] = y[OM];
        d[OM] = e.theta_dd;
        d[VXC] = e.xc_dd;
        d[ROD_X] = y[OM] * y[ROD_Z]; // formula: (sin theta)' = theta' cos theta
        d[ROD_Z] = -y[OM] * y[ROD_X]; // formula: (cos theta)' = -theta' sin theta
        d[XC] = y[VXC];
        d[W_PLATE] = e.fz * vs; // formula: plate power F_z zdot_s
        d[D_FRIC] = friction; // formula: friction loss -F_x xdot_c
        d[D_DAMP] = p.damping_nms_per_rad * y[OM] * y[OM]; // formula: damper loss gamma theta'^2
        d
    }

    fn exact(&self, mode: Mode, t0: f64, y0: &State, t: f64) -> Option<State> {
        (mode == Mode::Flight).then(|| self.flight_state(t0, y0, t))
    }

    fn guard_count(&self, mode: Mode) -> usize {
        match mode {
            Mode::Flight => 2,
            Mode::Pivot => 4,
            Mode::SlideLeft | Mode::SlideRight => 6,
        }
    }

    fn guard(&self, mode: Mode, i: usize, t: f64, y: &State) -> f64 {
        self.with_guards(mode, t, y, |g| g[i])
    }

    fn guards(&self, mode: Mode, t: f64, y: &State, out: &mut Vec<f64>) {
        out.clear();
        self.with_guards(mode, t, y, |g| out.extend_from_slice(g));
    }

    fn guard_rates(&self, mode: Mode, t: f64, y: &State, f: &State, out: &mut Vec<f64>) -> bool {
        self.contact_guard_rates(mode, t, y, f, out)
    }

    fn direction(&self, mode: Mode, i: usize) -> Direction {
        match (mode, i) {
            (Mode::Flight, 1) => Direction::Rising,
            (Mode::SlideLeft | Mode::SlideRight, 0 | 4) => Direction::Either,
            (Mode::SlideLeft | Mode::SlideRight, 5) => Direction::Rising,
            _ => Direction::Falling,
        }
    }

    fn on_event(
        &self,
        mode: Mode,
        i: usize,
        t: f64,
        y: &State,
    ) -> Transition<Mode, StickStop, NSTATE> {
        let y = &self.canonical(mode, t, y);
        let next = match (mode, i) {
            (Mode::Flight, 0) => self.landing(t, y),
            (Mode::Flight, _) => Next::Stop(StickStop::invalid(format!(
                "C went below the plate in flight at t = {t:.6} s (a landing was missed)"
            ))),
            (Mode::Pivot, 3) => Next::Stop(StickStop::Fell),
            (Mode::Pivot, _) => self.select_contact_from(t, y, false),
            (_, 0) => self.jam(t, y),
            (_, 1) => self.takeoff(t, y),
            (_, 2) => self.select_contact(t, y),
            (_, 3) => Next::Stop(StickStop::Fell),
            (_, 4) => Next::Stop(StickStop::Invalid(InvalidReason::SingularSlide {
                t_s: t,
                entering: false,
            })),
            _ => Next::Stop(StickStop::invalid(format!(
                "C slips against the friction force at t = {t:.6} s: no consistent slide"
            ))),
        };
        self.transition(next, t, y)
    }

    fn max_step(&self, mode: Mode, t: f64, y: &State) -> f64 {
        match mode {
            Mode::Flight => self.flight_step(t, y),
            _ => self.max_contact_step_s,
        }
    }
}

impl StickModel {
    /// All guards of `mode` at `(t, y)`, in the module's order, handed to `f`: one force
    /// evaluation serves the pivot's three force guards, and a single guard costs no
    /// more than all of them (they share their terms).
    #[inline]
    fn with_guards<R>(&self, mode: Mode, t: f64, y: &State, f: impl FnOnce(&[f64]) -> R) -> R {
        let p = &self.p;
        match mode {
            Mode::Flight => {
                let h = self.h_c(t, y);
                // A flight that starts on the plate starts its height guard at zero, and
                // a guard never fires from zero: count that start as "above" (as the
                // block's flight does), so a grazing lift-off whose foot comes straight
                // back lands at once instead of sinking through the plate.
                let landing = if h == 0.0 { f64::MIN_POSITIVE } else { h };
                f(&[landing, -h - self.penetration_tol_m])
            }
            Mode::Pivot => {
                let e = self.pivot_eval_carried(self.plate(t).2, y); // the flow's own force
                f(&[
                    e.fz,
                    p.mu * e.fz - e.fx,
                    p.mu * e.fz + e.fx,
                    FRAC_PI_2 - y[TH].abs(),
                ])
            }
            Mode::SlideLeft | Mode::SlideRight => {
                let sigma = mode.sigma();
                // same zeros and sign as L (sin - sigma mu cos) = L cos (tan - sigma mu), no trig
                let edge = y[TH] - sigma * self.atan_mu;
                let q =
                    p.stiffness_nm_per_rad * (y[TH] - p.theta0_rad) + p.damping_nms_per_rad * y[OM];
                f(&[
                    edge,
                    q * edge.signum(),
                    // slip speed + 1e-12 m/s: a slide entered from rest starts at +1e-12,
                    // not at 0, so a slip that reverses within the first step is still seen
                    -sigma * y[VXC] + 1e-12,
                    FRAC_PI_2 - y[TH].abs(),
                    y[TH],
                    sigma * y[VXC] - 1e-9,
                ])
            }
        }
    }
}
