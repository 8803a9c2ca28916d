//! The vertical-shaking scene and runs of the block on it.

use crate::physics::block::{
    simulate_block, BlockMode, BlockOptions, BlockParams, BlockRun, EventKind,
};
use crate::physics::friction::{FrictionLaw, ImpactFriction};
use crate::physics::plate::{Axis, Harmonic, PlateMotion};
use std::f64::consts::TAU;

/// A block on a vertically vibrating plate `u_z = delta_z sin(omega t)` (per unit mass).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scene {
    /// Gamma = delta_z omega^2 / g.
    pub gamma: f64,
    /// Frequency (Hz).
    pub frequency_hz: f64,
    /// Coulomb coefficient mu.
    pub mu: f64,
    /// Bias F / (mu m g).
    pub bias: f64,
    /// g (m/s^2).
    pub g_mps2: f64,
}

/// Which of the document's approximations are switched on in the model.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Model {
    /// Coulomb friction in contact and at impacts (the exact model).
    Exact,
    /// Every impact sticks (the document's "instantaneous sticking collisions").
    StickingImpacts,
    /// Sticking impacts and no slip while in contact (no slip before take-off).
    NoContactSlip,
}

impl Scene {
    /// omega (rad/s).
    pub fn omega(&self) -> f64 {
        TAU * self.frequency_hz
    }
    /// delta_z (m).
    pub fn amplitude_m(&self) -> f64 {
        self.gamma * self.g_mps2 / self.omega().powi(2) // formula: delta_z = Gamma g / omega^2
    }
    /// Peak plate velocity v_z = delta_z omega (m/s).
    pub fn vz_mps(&self) -> f64 {
        self.amplitude_m() * self.omega()
    }
    /// The plate.
    pub fn plate(&self) -> Harmonic {
        Harmonic::sine(Axis::Z, self.amplitude_m(), self.frequency_hz)
    }
    /// Block parameters for `model`.
    pub fn params(&self, model: Model) -> BlockParams {
        let mut p = BlockParams::coulomb(self.g_mps2, self.mu, self.bias * self.mu * self.g_mps2);
        match model {
            Model::Exact => {}
            Model::StickingImpacts => p.impact = ImpactFriction::Sticking,
            Model::NoContactSlip => {
                p.impact = ImpactFriction::Sticking;
                p.friction = FrictionLaw::NoSlip;
            }
        }
        p
    }
    /// The document's law: v_ave = (F / m g) v_z = b mu delta_z omega (m/s).
    pub fn law_velocity_mps(&self) -> f64 {
        self.bias * self.mu * self.vz_mps() // formula: v_ave = F v_z/(m g)
    }
    /// The same scene at another Gamma (amplitude changed, frequency kept).
    pub fn at_gamma(&self, gamma: f64) -> Scene {
        Scene { gamma, ..*self }
    }
}

/// Statistics of a run over its window (flights wholly inside it).
#[derive(Debug, Clone)]
pub struct Stats {
    /// The run.
    pub run: BlockRun,
    /// Flight durations in the window, in drive periods, in order.
    pub flights: Vec<f64>,
    /// For each landing in the window: did it lead to a contact phase (true) or
    /// straight back into flight (a touch-and-go)?
    pub rests: Vec<bool>,
    /// Take-off speeds (absolute vertical velocity when leaving the plate, m/s) of the
    /// flights in `flights`.
    pub takeoff_speeds_mps: Vec<f64>,
    /// Phase of the plate's sine (rad, in [0, 2 pi)) at each take-off from rest.
    pub rest_takeoff_phases_rad: Vec<f64>,
    /// Mean velocity over whole cycles (m/s): between the first and the last take-off
    /// from rest in the window when there are two or more (a rest resets the motion,
    /// so this spans whole cycles), else over the window's whole periods.
    pub cycle_velocity_mps: f64,
}

impl Stats {
    /// Mean flight duration (s), NaN without flights.
    pub fn mean_flight_s(&self) -> f64 {
        self.flights.iter().sum::<f64>() / self.flights.len() as f64 * self.run.period_s
    }
    /// `sum t_f^2 / sum t_f` (s), NaN without flights.
    pub fn flight_weighted_s(&self) -> f64 {
        let p = self.run.period_s;
        self.flights.iter().map(|f| (f * p).powi(2)).sum::<f64>()
            / self.flights.iter().map(|f| f * p).sum::<f64>()
    }
    /// Mean take-off speed (m/s), NaN without flights.
    pub fn mean_takeoff_speed_mps(&self) -> f64 {
        self.takeoff_speeds_mps.iter().sum::<f64>() / self.takeoff_speeds_mps.len() as f64
    }
}

/// Runs `model` for `transient + observe` periods from rest at t = 0.
pub fn run(scene: &Scene, model: Model, transient: usize, observe: usize) -> Stats {
    let plate = scene.plate();
    let period = plate.period_s();
    let opts = BlockOptions {
        transient_periods: transient,
        ..BlockOptions::default()
    };
    let run = simulate_block(
        &scene.params(model),
        &plate,
        (transient + observe) as f64 * period,
        &opts,
    );
    let mut st = Stats {
        run: run.clone(),
        flights: Vec::new(),
        rests: Vec::new(),
        takeoff_speeds_mps: Vec::new(),
        rest_takeoff_phases_rad: Vec::new(),
        cycle_velocity_mps: run.mean_velocity_mps,
    };
    let mut rest_takeoffs: Vec<(f64, f64)> = Vec::new();
    let mut start: Option<(f64, f64)> = None;
    for e in &run.events {
        if e.kind == EventKind::Landing {
            if let Some((t0, v0)) = start.take() {
                st.flights.push((e.t_s - t0) / period);
                st.takeoff_speeds_mps.push(v0);
            }
            st.rests.push(e.to != BlockMode::Flight);
        }
        let leaves = e.kind == EventKind::Takeoff
            || (e.kind == EventKind::Landing && e.to == BlockMode::Flight);
        if leaves {
            // The block leaves with the plate's velocity plus its own relative one.
            start = Some((e.t_s, plate.vz_mps(e.t_s) + e.after[3]));
        }
        if e.kind == EventKind::Takeoff {
            rest_takeoffs.push((e.t_s, e.before[0] + plate.x_m(e.t_s)));
            st.rest_takeoff_phases_rad
                .push((scene.omega() * e.t_s).rem_euclid(TAU));
        }
    }
    if let (Some(a), Some(b)) = (rest_takeoffs.first(), rest_takeoffs.last()) {
        if b.0 > a.0 {
            st.cycle_velocity_mps = (b.1 - a.1) / (b.0 - a.0); // formula: <v> over whole cycles
        }
    }
    st
}
