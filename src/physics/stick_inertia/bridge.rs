//! Handing a segment to Moreau-Jean: where the rules stop (a Painleve case they cannot
//! resolve, or no consistent contact mode), the run goes on with the chapter's own
//! time-stepper ([`super::timestepping`]) at a fine step, until the contact state is
//! consistent again: the time-stepper's contact case (stuck, sliding, free) has held for
//! [`HOLD_STEPS`] steps and the rules, asked from its state, choose the same mode without
//! a Painleve case or an impact. Then the event-driven run takes over.
//!
//! The bridge is first order in its step `h = T/`[`STEPS_PER_PERIOD`]; its error is
//! estimated by running the same bridge at `h/2` to the hand-back time and taking the
//! difference of C's position (order one: the error of the `h` run is about twice that
//! difference). The energy of the bridge is booked as the plate's impulse work and,
//! as a loss, the rest of the mechanical energy change (the time-stepper does not split
//! friction from damping).

use super::system::Next;
use super::timestepping::MjStick;
use super::{InertiaModel, InertiaStop, Mode, State, NSTATE, OM, TH, VXC, VZC, XC, ZC};
use crate::numerics::hybrid::Transition;
use crate::numerics::timestepping::{step, ContactStatus};

/// Most bridges in one run.
pub const MAX_BRIDGES: usize = 200;
/// Steps per drive period of a bridge.
pub const STEPS_PER_PERIOD: f64 = 20_000.0;
/// Steps the time-stepper's contact case must hold before the hand-back.
pub const HOLD_STEPS: usize = 3;

/// Lift-off/landing pairs in a row, each flight below the run's resolution
/// ([`InertiaModel::chatter_flight_s`]), that hand the run to the bridge. One such pair
/// is a lift-off the run could not resolve; the second in a row, from the state the first
/// left, shows the rules repeating the same unresolvable decision: the accumulation the
/// rigid rules cannot end (chapter 8). On the map's mu = 1.83 run the third landing of
/// the chain already bounces on its grown rounding residual, from below the plate.
pub const CHATTER_PAIRS: usize = 2;

/// One bridge.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bridge {
    /// Start and end time (s).
    pub t0_s: f64,
    /// See `t0_s`.
    pub t1_s: f64,
    /// Step (s).
    pub h_s: f64,
    /// State at the hand-back.
    pub y1: State,
    /// Plate work, friction, damper and impact-like losses of the bridge (J).
    pub acc: [f64; 4],
    /// Estimated error of C's position at the hand-back (m).
    pub error_xc_m: f64,
}

impl InertiaModel {
    /// The event-driven state of Moreau-Jean's `(q, v)` (accumulators zero).
    pub fn from_mj(&self, q: &[f64; 3], v: &[f64; 3]) -> State {
        let l = self.geo.l_g_m;
        let (s, c) = q[2].sin_cos();
        let mut y = [0.0; NSTATE];
        y[TH] = q[2];
        y[OM] = v[2];
        y[XC] = q[0] - l * s; // formula: r_C = r_G - l_G e_r
        y[ZC] = q[1] - l * c;
        y[VXC] = v[0] - l * v[2] * c; // formula: v_C = v_G - l_G theta' e_theta
        y[VZC] = v[1] + l * v[2] * s;
        y
    }
}

impl InertiaModel {
    /// The shortest flight a run with penetration bound `eps_m` resolves (s). A flight
    /// that starts at rest relative to the plate with relative normal acceleration `a`
    /// under the plate's jerk `j = delta omega^3` has height `a tau^2/2 - j tau^3/6`: it
    /// lands at `tau_f = 3a/j` and rises at most `(2/81) j tau_f^3`. That rise stays
    /// within `eps` (where the run cannot tell flight from contact) iff
    /// `tau_f <= (81 eps/(2 j))^(1/3)`. Zero (the check off) on a still plate.
    pub fn chatter_flight_s(&self, eps_m: f64) -> f64 {
        let plate = &self.p.base.plate;
        let jerk = plate.peak_acceleration_mps2() * plate.omega_rad_s; // formula: j = delta omega^3
        if jerk > 0.0 {
            (81.0 * eps_m / (2.0 * jerk)).cbrt() // formula: tau_res = (81 eps / (2 j))^(1/3)
        } else {
            0.0
        }
    }

    /// A lift-off chosen by the rules at `t` (for the chatter count).
    pub(super) fn note_lift_off(&self, t: f64) {
        self.log.borrow_mut().lifted_s = Some(t);
    }

    /// A landing at `t`: counts it when its flight began with a lift-off at the landing
    /// before and lasted at most `chatter_flight_s`; the stop that hands the run to the
    /// bridge after [`CHATTER_PAIRS`] in a row.
    pub(super) fn note_landing(&self, t: f64) -> Option<Next> {
        let mut log = self.log.borrow_mut();
        let chained = log.lifted_s.is_some() && log.lifted_s == log.landed_s;
        let short = chained && t - log.lifted_s.unwrap_or(t) <= log.chatter_flight_s;
        log.chatter_pairs = if short { log.chatter_pairs + 1 } else { 0 };
        log.landed_s = Some(t);
        if log.chatter_pairs < CHATTER_PAIRS {
            return None;
        }
        log.chatter_pairs = 0;
        Some(Transition::Stop(InertiaStop::NoMode(format!(
            "lift-offs and landings accumulate at t = {t:.7} s ({CHATTER_PAIRS} flights in a row shorter than {:.2e} s)",
            log.chatter_flight_s
        ))))
    }
}

/// Moreau-Jean from `(t0, y0)` with step `h` for `n` steps (or to `t_stop`), calling
/// `each(t, y, status)` after every step; stops early when `each` returns `Some`.
fn march<R>(
    md: &InertiaModel,
    t0: f64,
    y0: &State,
    h: f64,
    t_stop: f64,
    mut each: impl FnMut(f64, &State, ContactStatus, f64) -> Option<R>,
) -> Result<(f64, State, Option<R>), String> {
    let (mut q, mut v) = md.to_mj(y0);
    let (mut t, mut k) = (t0, 0u64);
    let mut y = *y0;
    while t < t_stop {
        let t1 = (t0 + (k + 1) as f64 * h).min(t_stop);
        let (q1, v1, imp) = step(&MjStick(md), t, &q, &v, t1 - t, 0.5)
            .map_err(|e| format!("the Moreau-Jean bridge failed: {e}"))?;
        (q, v, t, k) = (q1, v1, t1, k + 1);
        y = md.from_mj(&q, &v);
        let work = imp.p_n * md.plate(t).1; // formula: plate work of the step's impulse P_n zdot_s
        if let Some(r) = each(t, &y, imp.status, work) {
            return Ok((t, y, Some(r)));
        }
    }
    Ok((t, y, None))
}

/// The mode the rules choose from the time-stepper's state `y` at `t` with contact case
/// `status`, if it is the same mode and no Painleve case or impact was needed.
fn hand_back(md: &InertiaModel, t: f64, y: &State, status: ContactStatus) -> Option<Next> {
    let (want, next) = match status {
        ContactStatus::Inactive | ContactStatus::Open => {
            if md.h_c(t, y) <= 0.0 {
                return None;
            }
            (Mode::Flight, md.takeoff(t, y))
        }
        ContactStatus::Stick => {
            let mut y = md.canonical(Mode::Pivot, t, y);
            y[VXC] = 0.0;
            (Mode::Pivot, md.select_contact(t, &y, true, usize::MAX - 8))
        }
        ContactStatus::SlidePositive | ContactStatus::SlideNegative => {
            let y = md.canonical(Mode::Pivot, t, y);
            let want = if y[VXC] < 0.0 {
                Mode::SlideLeft
            } else {
                Mode::SlideRight
            };
            (want, md.enter_slide(t, &y, usize::MAX - 8))
        }
    };
    match next {
        Transition::To { mode, .. } if mode == want => Some(next),
        _ => None,
    }
}

/// The bridge from `(t0, y0)` (C on the plate) to the first consistent hand-back, at
/// most one drive period and not past `t_end`: the bridge and the transition that
/// restarts the event-driven run.
pub fn bridge(
    md: &InertiaModel,
    t0: f64,
    y0: &State,
    t_end: f64,
) -> Result<(Bridge, Next), String> {
    let h = md.period_s / STEPS_PER_PERIOD;
    let t_stop = (t0 + md.period_s).min(t_end);
    let e0 = md.mechanical_energy(y0);
    let (mut work, mut last, mut held) = (0.0, None, 0usize);
    let (t1, y1, next) = march(md, t0, y0, h, t_stop, |t, y, status, w| {
        work += w;
        held = if last == Some(status) { held + 1 } else { 1 };
        last = Some(status);
        if held < HOLD_STEPS {
            return None;
        }
        let saved = md.log.borrow().clone();
        let next = hand_back(md, t, y, status);
        if next.is_none() {
            *md.log.borrow_mut() = saved;
        }
        next
    })?;
    let next = match next {
        Some(n) => n,
        None if t1 >= t_end => Transition::To {
            mode: Mode::Flight,
            state: y1,
        },
        None => {
            return Err(format!(
                "the rules stopped at t = {t0:.6} s and Moreau-Jean found no consistent contact state within one drive period"
            ))
        }
    };
    let (_, y_half, _) = march(md, t0, y0, 0.5 * h, t1, |_, _, _, _| None::<()>)?;
    let loss = work - (md.mechanical_energy(&y1) - e0); // formula: W_plate - Delta E
    Ok((
        Bridge {
            t0_s: t0,
            t1_s: t1,
            h_s: h,
            y1,
            acc: [work, 0.0, 0.0, loss],
            error_xc_m: 2.0 * (y1[XC] - y_half[XC]).abs(), // formula: order one, err(h) ~ 2 |x_h - x_{h/2}|
        },
        next,
    ))
}
