//! The chapter's work-precision table (full mode only; also a figure): the sawtooth
//! against its closed-form drift, the bi-harmonic drive against the closed-form-flow run.

use super::sims::{biharmonic, run_block, slip_transient, transient, Law, Numerics, Window};
use crate::ladder::{self, Run, Timing};
use crate::physics::plate::{PlateMotion, Sawtooth};
use crate::report::fmt_num;

/// The two drives of the table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Drive {
    /// The document's two-velocity sawtooth: its error against the closed-form drift.
    Sawtooth,
    /// The smooth bi-harmonic drive in the stick-slip band (no closed form): its error
    /// against the run with closed-form flows.
    Biharmonic,
}

impl Drive {
    /// Both, in the table's order.
    pub const ALL: [Drive; 2] = [Drive::Sawtooth, Drive::Biharmonic];

    /// The name in the table and the chart.
    pub fn label(self) -> &'static str {
        match self {
            Drive::Sawtooth => "sawtooth",
            Drive::Biharmonic => "bi-harmonic",
        }
    }

    /// What its drift's error is measured against.
    pub fn reference(self) -> &'static str {
        match self {
            Drive::Sawtooth => "closed-form drift",
            Drive::Biharmonic => "closed-form-flow run",
        }
    }
}

/// The three ways of running the block.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// The closed-form flows with located events (the sawtooth only: for the
    /// bi-harmonic drive it is the reference).
    ClosedForms,
    /// Dormand-Prince 5(4) at a tolerance, located events.
    Dopri5,
    /// Classical Runge-Kutta at a fixed step, no event location.
    Rk4Fixed,
}

impl Method {
    /// The name in the table.
    pub fn label(self) -> &'static str {
        match self {
            Method::ClosedForms => "closed forms, located events",
            Method::Dopri5 => "DP5, located events",
            Method::Rk4Fixed => "RK4 fixed step, no location",
        }
    }
}

/// One row of the work-precision table.
#[derive(Debug, Clone)]
pub struct WorkRow {
    /// The drive.
    pub drive: Drive,
    /// The method.
    pub method: Method,
    /// Right-hand-side evaluations of the run.
    pub rhs_evals: u64,
    /// |drift - reference| (m/s).
    pub error_mps: f64,
}

/// The table `work_precision` (markdown) and the rows of the figure, for the sawtooth
/// `saw` (friction `k` = mu g, m/s^2; closed-form drift `v_formula`, m/s) and the
/// bi-harmonic drive of velocity amplitude `vb` (m/s).
pub fn work_precision(
    saw: &Sawtooth,
    k: f64,
    vb: f64,
    v_formula: f64,
    num: &Numerics,
) -> (String, Vec<WorkRow>) {
    let mut work = Vec::new();
    let saw = *saw;
    let coul = Law::Coulomb { k_mps2: k };
    let mut rows = String::from("| drive | method | setting | rhs evaluations | event-location evaluations | error of the drift (m/s) |\n|---|---|---|---|---|---|\n");
    // Sawtooth: reference the closed-form drift. Bi-harmonic in the stick-slip band
    // (Gamma = 1.5, eps = 0.1; no closed form): reference the closed-form-flow run.
    let wb = biharmonic(vb, 1.5, 0.1, k);
    let plates: [(Drive, &dyn PlateMotion, Window); 2] = [
        (
            Drive::Sawtooth,
            &saw,
            Window {
                transient: transient(&saw, k),
                measured: 10,
            },
        ),
        (
            Drive::Biharmonic,
            &wb,
            Window {
                transient: slip_transient(1.5),
                measured: 10,
            },
        ),
    ];
    for (drive, plate, win) in plates {
        let reference = match drive {
            Drive::Sawtooth => v_formula,
            Drive::Biharmonic => {
                run_block(coul, plate, 0.0, win, num, (0.0, 0.0), 0.0).mean_velocity_mps
            }
        };
        let mut settings: Vec<(Method, String, Numerics)> = Vec::new();
        if drive == Drive::Sawtooth {
            settings.push((Method::ClosedForms, "-".into(), Numerics::default()));
        }
        for tol in [1e-3, 1e-6, 1e-9, 1e-12] {
            settings.push((
                Method::Dopri5,
                format!("tol {tol:.0e}"),
                Numerics::dopri(tol),
            ));
        }
        // Odd step counts: a grid of T/4^j would hit the stick time (T_f = T/4 after a
        // slow stroke's start) exactly and hide the late switch by luck.
        for n in [15, 63, 255, 1023] {
            settings.push((
                Method::Rk4Fixed,
                format!("T/{n}"),
                Numerics::fixed_rk4(n, plate.period_s()),
            ));
        }
        // The one work-precision ladder (`crate::ladder`): error |v_d - reference| against
        // rhs evaluations; the event-location count is this table's own column.
        let mut locate_evals = Vec::new();
        let error = |r: &Run| (r.value - reference).abs(); // formula: |v_d - v_ref| (m/s)
        let rungs = ladder::climb(settings, Timing::MinOf(1), error, |(_, _, n)| {
            let d = run_block(coul, plate, 0.0, win, n, (0.0, 0.0), 0.0);
            locate_evals.push(d.locate_evals);
            Run {
                value: d.mean_velocity_mps,
                rhs_evals: d.stats.rhs_evals,
                steps: d.stats.accepted,
                completed: d.mean_velocity_mps.is_finite(),
            }
        });
        for (rung, located) in rungs.iter().zip(locate_evals) {
            let (method, setting, _) = &rung.setting;
            rows.push_str(&format!(
                "| {} | {} | {setting} | {} | {located} | {} |\n",
                drive.label(),
                method.label(),
                rung.cost.rhs_evals,
                fmt_num(rung.error)
            ));
            work.push(WorkRow {
                drive,
                method: *method,
                rhs_evals: rung.cost.rhs_evals,
                error_mps: rung.error,
            });
        }
    }
    (rows, work)
}
