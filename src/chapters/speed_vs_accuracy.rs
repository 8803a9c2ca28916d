//! Chapter `speed-vs-accuracy`: work-precision charts, failing methods, and peers.

pub mod block_scene;
pub mod measure;

use super::Context;
use crate::error::Result;
use crate::report::ChapterReport;

/// Flags of the chapter (none yet).
#[derive(clap::Args, Debug, Clone, Default)]
pub struct Args {}

/// Runs the chapter: not built yet, so it reports no claims.
pub fn run(_args: &Args, _ctx: &Context) -> Result<ChapterReport> {
    Ok(super::not_built("speed-vs-accuracy"))
}

#[cfg(test)]
mod explore {
    use super::block_scene::BlockScene;
    use super::measure::*;
    use crate::numerics::hybrid::Options;
    use crate::numerics::ode::{Method, StepControl};

    #[test]
    fn explore() {
        use crate::numerics::hybrid::{simulate, Outcome};
        use super::block_scene::BlockMode;
        use crate::physics::plate::PlateMotion;
        for gamma in [1.5, 2.0, 2.5, 3.0, 4.0] {
          for e in [0.3, 0.5, 0.8] {
            let mut sc = BlockScene::new(30.0, gamma, 0.4, 0.1, 9.81);
            sc.e = e;
            sc.closed_form = true;
            let y0 = [0.0, 0.0, sc.plate.z_m(0.0), sc.plate.vz_mps(0.0)];
            let run = simulate(&sc, BlockMode::Stick, 0.0, y0, 20.0 * sc.period_s(), &Options::default(), &mut ());
            eprintln!("gamma {gamma} e {e}: {:?} events {}", run.outcome, run.event_count);
            sc.stick_below_mps = 1e-4;
            let run = simulate(&sc, BlockMode::Stick, 0.0, y0, 20.0 * sc.period_s(), &Options::default(), &mut ());
            eprintln!("   stick transition: {:?} events {}", run.outcome, run.event_count);
            let w = window(&sc, 5, 15);
            eprintln!("   drift {:?} mj {:?}", drift_hybrid(&sc, &Options::default(), w), drift_mj(&sc, 2000, w));
          }
        }
    }
}
