//! What every run of the chapter's evidence shares: the sizes of the quick and full
//! runs, the scene and the flags.

use super::block_scene::BlockScene;
use super::measure::{drift_block_model, Measured};
use super::work_precision::WpPoint;
use super::Args;
use crate::numerics::hybrid::Options;

/// Sizes of the quick and full runs.
pub(super) struct Plan {
    pub(super) transient: u32,
    pub(super) cycles: u32,
    pub(super) steps: Vec<u32>,
    pub(super) tols: Vec<f64>,
    pub(super) mj_steps: Vec<u32>,
    pub(super) repeats: u32,
    pub(super) gammas: Vec<f64>,
}

impl Plan {
    pub(super) fn new(quick: bool) -> Self {
        if quick {
            Plan {
                transient: 5,
                cycles: 10,
                steps: vec![20, 320, 1280],
                tols: vec![1e-4, 1e-8, 1e-12],
                mj_steps: vec![20, 200, 2000],
                repeats: 1,
                gammas: vec![1.5, 2.5, 6.0],
            }
        } else {
            Plan {
                transient: 10,
                cycles: 40,
                steps: vec![20, 40, 80, 160, 320, 640, 1280, 2560, 5120],
                tols: (3..=12).map(|k| 10f64.powi(-k)).collect(),
                mj_steps: vec![20, 40, 80, 160, 320, 640, 1280, 2560, 5120, 10240, 20480],
                repeats: 3,
                gammas: (0..=68).map(|i| 1.2 + 0.1 * f64::from(i)).collect(),
            }
        }
    }
}

/// The largest ratio `e(h) / (e(h0) (h/h0)^p)` over the completed points of `label`
/// (h0 the coarsest step), and the number of points: `<= 2` means the errors lie under
/// an order-`p` envelope through the coarsest point.
pub fn envelope(points: &[WpPoint], label: &str, p: f64) -> (f64, usize) {
    let pts: Vec<(f64, f64)> = points
        .iter()
        .filter(|q| q.setting.label() == label && q.completed)
        .map(|q| (q.setting.knob(), q.error))
        .collect();
    let Some(&(h0, e0)) = pts.iter().max_by(|a, b| a.0.total_cmp(&b.0)) else {
        return (f64::NAN, 0);
    };
    let worst = pts
        .iter()
        .map(|&(h, e)| e / (e0 * (h / h0).powf(p))) // formula: e(h) <= C e0 (h/h0)^p
        .fold(0.0f64, f64::max);
    (worst, pts.len())
}

/// The scene, the flags and the sizes every run of the evidence uses.
pub(super) struct Setup<'a> {
    pub(super) args: &'a Args,
    pub(super) plan: Plan,
    /// g of the block scene (m/s^2).
    pub(super) g: f64,
    pub(super) scene: BlockScene,
    /// The averaging window `(t_a, t_b)` (s).
    pub(super) win: (f64, f64),
    pub(super) quick: bool,
}

impl Setup<'_> {
    /// The block's drift over the plan's window, 20 guard samples per period:
    /// integrated by `opts`, or in closed form between located events (`closed`).
    pub(super) fn block(&self, opts: &Options, closed: bool) -> Measured {
        let (tr, cy) = (self.plan.transient, self.plan.cycles);
        drift_block_model(&self.scene, opts, closed, 20, tr, cy)
    }
}
