//! A minimal block on a horizontally moving plate, as a [`HybridSystem`]: Coulomb
//! (stick / slip forward / slip back) or linear viscous friction, absolute state
//! `y = [x (m), v (m/s)]`, no flight (the plate only moves horizontally).
//!
//! Why not `physics::block`: on the two-velocity sawtooth that model skips stroke
//! changes (a step that lands an ulp before a breakpoint makes the plate answer the
//! *next* breakpoint) and evaluates the plate's one-sided velocity 1e-9 T away from a
//! segment's start, which crosses a breakpoint when the segment is an ulp long. This
//! model (i) reads the plate through [`Snapped`], whose breakpoints survive rounding,
//! and (ii) carries the current smooth piece of the plate's motion (between two
//! breakpoints) in its mode, so the plate's velocity of a segment is always the one of
//! its own piece, whatever the rounding of its ends.
//!
//! | mode | flow (closed form) | guards |
//! |---|---|---|
//! | `Stick` | `v = v_p`, `x - x_p` constant | `mu g - a_p` falls to 0 -> SlipBack; `mu g + a_p` falls to 0 -> SlipFwd |
//! | `SlipFwd` (`v > v_p`) | `v' = -mu g` | `v - v_p` falls to 0 -> Stick if `|a_p| <= mu g`, else SlipBack |
//! | `SlipBack` (`v < v_p`) | `v' = +mu g` | `v - v_p` rises to 0 -> Stick or SlipFwd |
//! | `Viscous` | `v' = -c (v - v_p)` (integrated) | none |
//!
//! At a breakpoint the absolute velocity is continuous; the contact mode follows the
//! sign of `v - v_p` in the new piece.

use super::Snapped;
use crate::numerics::events::Direction;
use crate::numerics::hybrid::{HybridSystem, Transition};
use crate::physics::plate::PlateMotion;

/// The friction law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Law {
    /// Coulomb friction: slip deceleration bound `k = mu g` (m/s^2).
    Coulomb {
        /// `mu g` (m/s^2).
        k_mps2: f64,
    },
    /// Linear viscous friction `F/m = -c (v - v_p)`.
    Viscous {
        /// `c` (1/s).
        c_per_s: f64,
    },
}

/// Contact state.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Contact {
    /// Moving with the plate (Coulomb).
    Stick,
    /// Faster than the plate (`v > v_p`): friction `-mu g`.
    SlipFwd,
    /// Slower than the plate (`v < v_p`): friction `+mu g`.
    SlipBack,
    /// Linear viscous contact.
    Viscous,
}

/// A mode: the contact state and the smooth piece `[start_s, end_s)` of the plate's
/// motion (between two of its breakpoints; `end_s` infinite for a smooth plate).
///
/// Two modes are equal when their contact states are: the piece is bookkeeping (so the
/// driver counts contact changes as events and sums time per contact state).
#[derive(Debug, Clone, Copy)]
pub struct Mode {
    /// Contact state.
    pub contact: Contact,
    /// Start of the plate's current piece (s).
    pub start_s: f64,
    /// End of the plate's current piece (s).
    pub end_s: f64,
}

impl PartialEq for Mode {
    fn eq(&self, other: &Mode) -> bool {
        self.contact == other.contact
    }
}

/// The block on `plate` with friction `law`.
pub struct Block<'a, P: PlateMotion + ?Sized> {
    plate: Snapped<'a, P>,
    /// Friction law.
    pub law: Law,
    /// Use closed forms for stick and Coulomb slip (true) or integrate every flow.
    pub closed_forms: bool,
    /// Guard sampling interval of closed-form modes and longest step (s); infinite
    /// for a plate with piecewise-constant velocity (see [`Block::new`]).
    pub sample_s: f64,
    /// True if the plate has breakpoints and no acceleration between them.
    pub piecewise_constant: bool,
}

impl<'a, P: PlateMotion + ?Sized> Block<'a, P> {
    /// A block with closed forms and 64 guard samples per period, or no sampling at all
    /// when the plate's velocity is piecewise constant (the sawtooth: checked on 64
    /// points of a period): then every guard is linear in time within a piece and
    /// crosses zero at most once, and the steps end on the breakpoints anyway.
    pub fn new(plate: &'a P, law: Law) -> Self {
        let period = plate.period_s();
        let piecewise_constant = plate.breakpoint_after(0.0).is_some()
            && (0..64).all(|i| plate.ax_mps2((i as f64 + 0.5) * period / 64.0) == 0.0);
        let sample_s = if piecewise_constant {
            f64::INFINITY
        } else {
            period / 64.0
        };
        Block {
            plate: Snapped(plate),
            law,
            closed_forms: true,
            sample_s,
            piecewise_constant,
        }
    }

    /// The plate, read through [`Snapped`].
    pub fn plate(&self) -> &Snapped<'a, P> {
        &self.plate
    }

    /// `t` moved inside the mode's piece (by `1e-12 T` plus a few ulps at its ends).
    fn inside(&self, m: Mode, t: f64) -> f64 {
        let d = 1e-12 * self.plate.period_s() + 32.0 * f64::EPSILON * t.abs();
        if m.end_s - m.start_s <= 2.0 * d {
            0.5 * (m.start_s + m.end_s)
        } else {
            t.clamp(m.start_s + d, m.end_s - d)
        }
    }

    /// Plate velocity (m/s) at `t` in the mode's piece.
    pub fn vp(&self, m: Mode, t: f64) -> f64 {
        self.plate.vx_mps(self.inside(m, t))
    }

    /// Plate acceleration (m/s^2) at `t` in the mode's piece.
    pub fn ap(&self, m: Mode, t: f64) -> f64 {
        self.plate.ax_mps2(self.inside(m, t))
    }

    fn k(&self) -> f64 {
        match self.law {
            Law::Coulomb { k_mps2 } => k_mps2,
            Law::Viscous { .. } => 0.0,
        }
    }

    /// The contact state for relative velocity `w = v - v_p` with plate acceleration `a`.
    fn contact_for(&self, w: f64, a: f64) -> Contact {
        match self.law {
            Law::Viscous { .. } => Contact::Viscous,
            Law::Coulomb { k_mps2 } => {
                if w > 0.0 {
                    Contact::SlipFwd
                } else if w < 0.0 {
                    Contact::SlipBack
                } else if a.abs() <= k_mps2 {
                    Contact::Stick
                } else if a > 0.0 {
                    Contact::SlipBack // formula: the plate outruns friction forwards
                } else {
                    Contact::SlipFwd
                }
            }
        }
    }

    /// The mode of a block with velocity `v` (m/s) at `t` (s).
    pub fn start_mode(&self, t: f64, v: f64) -> Mode {
        // The piece that contains t (a start on a breakpoint belongs to the new piece).
        let end_s = self.plate.breakpoint_after(t).unwrap_or(f64::INFINITY);
        let probe = Mode {
            contact: Contact::Stick,
            start_s: t,
            end_s,
        };
        Mode {
            contact: self.contact_for(v - self.vp(probe, t), self.ap(probe, t)),
            ..probe
        }
    }
}

impl<P: PlateMotion + ?Sized> HybridSystem<2> for Block<'_, P> {
    type Mode = Mode;
    type Stop = ();

    fn flow(&self, m: Mode, t: f64, y: &[f64; 2]) -> [f64; 2] {
        let k = self.k();
        match (m.contact, self.law) {
            (Contact::Stick, _) => [self.vp(m, t), self.ap(m, t)],
            (Contact::SlipFwd, _) => [y[1], -k], // formula: v' = -mu g
            (Contact::SlipBack, _) => [y[1], k], // formula: v' = +mu g
            (Contact::Viscous, Law::Viscous { c_per_s }) => {
                [y[1], -c_per_s * (y[1] - self.vp(m, t))]
            } // formula: v' = -c (v - v_p)
            (Contact::Viscous, _) => [y[1], 0.0],
        }
    }

    fn exact(&self, m: Mode, t0: f64, y0: &[f64; 2], t: f64) -> Option<[f64; 2]> {
        if !self.closed_forms {
            return None;
        }
        let s = t - t0;
        let k = self.k();
        match m.contact {
            // formula: x = x0 + x_p(t) - x_p(t0), v = v_p(t)
            Contact::Stick => Some([
                y0[0] + self.plate.x_m(t) - self.plate.x_m(t0),
                self.vp(m, t),
            ]),
            Contact::SlipFwd => Some([y0[0] + y0[1] * s - 0.5 * k * s * s, y0[1] - k * s]), // formula: x0 + v0 s - k s^2/2
            Contact::SlipBack => Some([y0[0] + y0[1] * s + 0.5 * k * s * s, y0[1] + k * s]), // formula: x0 + v0 s + k s^2/2
            Contact::Viscous => None,
        }
    }

    fn guard_count(&self, m: Mode) -> usize {
        match m.contact {
            Contact::Stick => 2,
            Contact::SlipFwd | Contact::SlipBack => 1,
            Contact::Viscous => 0,
        }
    }

    fn guard(&self, m: Mode, i: usize, t: f64, y: &[f64; 2]) -> f64 {
        let k = self.k();
        match (m.contact, i) {
            (Contact::Stick, 0) => k - self.ap(m, t), // formula: mu g - a_p
            (Contact::Stick, _) => k + self.ap(m, t), // formula: mu g + a_p
            _ => y[1] - self.vp(m, t),                // formula: w = v - v_p
        }
    }

    fn direction(&self, m: Mode, _i: usize) -> Direction {
        match m.contact {
            Contact::SlipBack => Direction::Rising,
            _ => Direction::Falling,
        }
    }

    fn on_event(&self, m: Mode, i: usize, t: f64, y: &[f64; 2]) -> Transition<Mode, (), 2> {
        let vp = self.vp(m, t);
        let contact = match (m.contact, i) {
            (Contact::Stick, 0) => Contact::SlipBack,
            (Contact::Stick, _) => Contact::SlipFwd,
            (from, _) => {
                // w reached 0: stick inside the friction cone, else reverse.
                let a = self.ap(m, t);
                if a.abs() <= self.k() {
                    Contact::Stick
                } else if from == Contact::SlipFwd {
                    Contact::SlipBack
                } else {
                    Contact::SlipFwd
                }
            }
        };
        // At a switch the block moves with the plate: v = v_p exactly.
        Transition::To {
            mode: Mode { contact, ..m },
            state: [y[0], vp],
        }
    }

    fn max_step(&self, m: Mode, t: f64, _y: &[f64; 2]) -> f64 {
        if m.contact == Contact::Viscous {
            // No guards to sample: the step control alone decides.
            return f64::INFINITY;
        }
        // Guards are sampled every sample_s; a step that would end within a hair of the
        // next breakpoint goes all the way to it (no sliver step of a few ulps, which
        // an adaptive integrator refuses).
        match self.plate.breakpoint_after(t) {
            Some(b) if b - t <= self.sample_s * (1.0 + 1e-6) => 2.0 * self.sample_s,
            _ => self.sample_s,
        }
    }

    fn breakpoint_after(&self, t: f64) -> Option<f64> {
        self.plate.breakpoint_after(t)
    }

    fn on_breakpoint(&self, m: Mode, t: f64, y: &[f64; 2]) -> Transition<Mode, (), 2> {
        let end_s = self.plate.breakpoint_after(t).unwrap_or(f64::INFINITY);
        let piece = Mode {
            start_s: t,
            end_s,
            ..m
        };
        let contact = match m.contact {
            Contact::Viscous => Contact::Viscous,
            _ => self.contact_for(y[1] - self.vp(piece, t), self.ap(piece, t)),
        };
        Transition::To {
            mode: Mode { contact, ..piece },
            state: *y,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::hybrid::{simulate, Options};
    use crate::physics::plate::Sawtooth;

    #[test]
    fn sawtooth_block_changes_mode_at_every_stroke_change() {
        // Default scene: after the lock (t = 0.054 s) each period is stick (slow stroke)
        // -> slip forward (fast stroke) -> slip back (slow stroke) -> stick: the run
        // over 100 periods ends stuck in a slow stroke, exactly at the plate's speed.
        let s = Sawtooth {
            slow_velocity_mps: 0.1,
            fast_velocity_mps: 0.3,
            slow_duration_s: 0.03,
        };
        let b = Block::new(&s, Law::Coulomb { k_mps2: 0.3 * 9.81 });
        let m0 = b.start_mode(0.0, 0.0);
        assert_eq!(m0.contact, Contact::SlipBack);
        let run = simulate(
            &b,
            m0,
            0.0,
            [0.0, 0.0],
            100.0 * 0.04 + 0.025,
            &Options::default(),
            &mut (),
        );
        assert_eq!(run.mode_end.contact, Contact::Stick);
        assert_eq!(run.y_end[1], 0.1);
        // one stick event per period after the first (slip back -> stick), one per
        // stroke change: 3 per period, about 300 in all
        assert!(
            (295..=305).contains(&run.event_count),
            "{}",
            run.event_count
        );
    }
}
