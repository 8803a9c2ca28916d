//! Independent checks of block runs, for unit and integration tests to assert on:
//! [`ContactInvariants`], an [`Observer`] that measures how far a run strays from the
//! contact laws (friction cone, dissipation, impacts, a plate that only pushes), and
//! [`ballistic_flight_s`], a hop's flight time found without the driver.

use super::{BlockMode, BlockParams, BlockSystem};
use crate::numerics::hybrid::{Observer, Segment};
use crate::physics::plate::PlateMotion;

/// Intervals each segment is cut into: the invariants are sampled at its 11 evenly
/// spaced instants, both ends included.
const INTERVALS_PER_SEGMENT: usize = 10;

/// Observes a block run (pass it to [`super::simulate_block_observed`]) and keeps the
/// worst sampled value of each contact invariant. The maxima start at `f64::MIN`, the
/// minimum at `f64::MAX`: a field that never saw a sample keeps its start value.
#[derive(Debug, Clone)]
pub struct ContactInvariants<'a, P: PlateMotion + ?Sized> {
    /// The block whose contact forces are evaluated.
    pub sys: BlockSystem<'a, P>,
    /// Largest `|f| - mu n` (m/s^2) over the samples: at most round-off while friction
    /// stays inside the Coulomb cone (not sampled for a law without a Coulomb `mu`).
    pub worst_cone_mps2: f64,
    /// Largest friction power per unit mass `f w` (W/kg) over the samples: at most
    /// round-off while friction only dissipates (`w` is 0 in stick).
    pub worst_power_w_per_kg: f64,
    /// Largest gain of `w^2 + vh^2` (m^2/s^2, twice the relative kinetic energy per
    /// unit mass) across a landing: at most round-off if impacts never create energy.
    pub worst_impact_gain_m2ps2: f64,
    /// Smallest normal force per unit mass (m/s^2) sampled outside flight: not below
    /// round-off, since the plate can only push.
    pub least_contact_normal_mps2: f64,
    /// Number of segments in [`BlockMode::Stick`].
    pub stick_segments: usize,
}

impl<'a, P: PlateMotion + ?Sized> ContactInvariants<'a, P> {
    /// An observer of the block `params` on `plate` that has seen nothing yet.
    pub fn new(params: BlockParams, plate: &'a P) -> Self {
        ContactInvariants {
            sys: BlockSystem::new(params, plate),
            worst_cone_mps2: f64::MIN,
            worst_power_w_per_kg: f64::MIN,
            worst_impact_gain_m2ps2: f64::MIN,
            least_contact_normal_mps2: f64::MAX,
            stick_segments: 0,
        }
    }
}

impl<P: PlateMotion + ?Sized> Observer<BlockMode, 4> for ContactInvariants<'_, P> {
    fn segment(&mut self, mode: BlockMode, seg: &Segment<'_, 4>) {
        if mode == BlockMode::Stick {
            self.stick_segments += 1;
        }
        let mu = self.sys.params.friction.mu();
        let n = INTERVALS_PER_SEGMENT as f64;
        for k in 0..=INTERVALS_PER_SEGMENT {
            let t = seg.t0 + (seg.t1 - seg.t0) * k as f64 / n;
            let y = seg.eval(t);
            let c = self.sys.contact_force(mode, t, &y);
            if let Some(mu) = mu {
                self.worst_cone_mps2 = self
                    .worst_cone_mps2
                    .max(c.tangential_mps2.abs() - mu * c.normal_mps2);
            }
            self.worst_power_w_per_kg = self.worst_power_w_per_kg.max(c.tangential_mps2 * y[1]);
            if mode != BlockMode::Flight {
                self.least_contact_normal_mps2 = self.least_contact_normal_mps2.min(c.normal_mps2);
            }
        }
    }

    fn event(
        &mut self,
        _t_s: f64,
        from: BlockMode,
        _guard: usize,
        before: &[f64; 4],
        after: Option<(BlockMode, &[f64; 4])>,
    ) {
        if let (BlockMode::Flight, Some((_, a))) = (from, after) {
            let gain =
                (a[1] * a[1] + a[3] * a[3]) - (before[1] * before[1] + before[3] * before[3]);
            self.worst_impact_gain_m2ps2 = self.worst_impact_gain_m2ps2.max(gain);
        }
    }
}

/// Flight time (s) of a block that leaves `plate` at `t0_s` with the plate's velocity and
/// falls under `g_mps2` (m/s^2): the first positive root of the ballistic gap
/// `z_p(t0) + v0 s - g s^2/2 - z_p(t0 + s)`, bracketed by a scan in steps of one
/// `scan_steps_per_period`-th of the plate's period and bisected 200 times (to
/// round-off). Independent of the block driver's event location, which it checks.
pub fn ballistic_flight_s<P: PlateMotion + ?Sized>(
    plate: &P,
    t0_s: f64,
    g_mps2: f64,
    scan_steps_per_period: u32,
) -> f64 {
    let v0 = plate.vz_mps(t0_s);
    let gap = |s: f64| plate.z_m(t0_s) + v0 * s - 0.5 * g_mps2 * s * s - plate.z_m(t0_s + s);
    let ds = plate.period_s() / f64::from(scan_steps_per_period);
    let mut a = ds;
    while gap(a + ds) > 0.0 {
        a += ds;
    }
    let mut b = a + ds;
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if gap(m) > 0.0 {
            a = m;
        } else {
            b = m;
        }
    }
    b
}
