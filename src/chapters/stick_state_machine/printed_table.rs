//! The errata of sections 4 and 5 by their consequences: the scenes run under the
//! printed rules with one erratum corrected at a time, and under the corrected rules
//! with one erratum left as printed (`physics::stick::printed`).

use super::evidence::Evidence;
use super::run_printed;
use crate::numerics::hybrid::Options;
use crate::numerics::ode::StepControl;
use crate::physics::stick::printed::{Erratum, Printed, Semantics};
use crate::physics::stick::run::{Recording, RunSummary, StickOutcome};
use crate::physics::stick::{Mode, StickParams};
use crate::report::fmt_num;

/// First time (s) at which `run`'s history leaves `reference`'s: an event with other
/// modes or more than 1e-6 s away (events are located to ~1e-15 s; two histories that
/// agree to 1e-6 s are the same history), or the run's early stop. `None`: no divergence.
pub fn first_divergence(run: &RunSummary, reference: &RunSummary) -> Option<f64> {
    let key = |e: &(f64, Mode, Option<Mode>)| (e.1, e.2);
    for (a, b) in run.events.iter().zip(&reference.events) {
        if key(a) != key(b) || (a.0 - b.0).abs() > 1e-6 {
            return Some(a.0.min(b.0));
        }
    }
    let (na, nb) = (run.events.len(), reference.events.len());
    if na < nb {
        return Some(reference.events[na].0.min(run.end_time_s));
    }
    if na > nb {
        return Some(run.events[nb].0);
    }
    (run.end_time_s < reference.end_time_s).then_some(run.end_time_s)
}

/// One cell: outcome, mean speed (over runs of one drive period or more), divergence.
fn cell(run: &RunSummary, reference: &RunSummary, p: &StickParams) -> String {
    let speed = if run.end_time_s >= p.period_s() {
        format!(
            "{} m/s",
            fmt_num((run.mean_velocity_mps * 1e4).round() / 1e4)
        )
    } else {
        "-".to_string()
    };
    let div = match first_divergence(run, reference) {
        None => "none".to_string(),
        Some(t) => format!("{} s", fmt_num((t * 1e4).round() / 1e4)),
    };
    let outcome = match &run.outcome {
        StickOutcome::Completed => run.outcome.label().to_string(),
        other => format!(
            "{} at {} s",
            other.label(),
            fmt_num((run.end_time_s * 1e4).round() / 1e4)
        ),
    };
    format!("{outcome}; {speed}; diverges {div}")
}

/// The rows: (label, rule set).
fn rule_sets() -> Vec<(String, Printed)> {
    let printed = Printed::AS_PRINTED;
    let fixed = printed.all_fixed();
    let mut v = vec![
        ("all printed".to_string(), printed),
        (
            "all printed, first assert wins".to_string(),
            printed.with_semantics(Semantics::FirstWins),
        ),
        (
            "all printed, r_CP read from P to C".to_string(),
            printed
                .with_fix(Erratum::A2ShorteningBranch)
                .with_fix(Erratum::A2ThetaDotSign),
        ),
        ("all corrected".to_string(), fixed),
    ];
    for e in Erratum::ALL {
        v.push((
            format!("printed, only `{}` corrected", e.id()),
            printed.with_fix(e),
        ));
        v.push((
            format!("corrected, only `{}` printed", e.id()),
            fixed.without_fix(e),
        ));
    }
    v
}

/// The Markdown table (block `stick-printed-errata`): both scenes, every rule set.
pub fn errata_table(ev: &Evidence, opts: &Options) -> String {
    let tight = Options {
        control: StepControl::tol(1e-10, 1e-10),
        ..*opts
    };
    let rec = Recording {
        sequence_cap: 100_000, // the phase sequence only: no trace, no checks, default lists
        ..Recording::default()
    };
    let sets = rule_sets();
    let scenes = [(&ev.params[0], &ev.authors), (&ev.params[1], &ev.jamming)];
    let jobs: Vec<(usize, usize)> = (0..sets.len())
        .flat_map(|i| (0..scenes.len()).map(move |k| (i, k)))
        .collect();
    let cells = crate::sweep::par_map(&jobs, "printed rules", |&(i, k)| {
        let (p, reference) = scenes[k];
        let (run, _) = run_printed(p, sets[i].1, ev.duration_s, &tight, rec);
        cell(&run, reference, p)
    });
    let mut s = String::from(
        "| rule set | authors' scene (main_rod.m) | self-locking scene |\n|---|---|---|\n",
    );
    for (i, (label, _)) in sets.iter().enumerate() {
        s.push_str(&format!(
            "| {label} | {} | {} |\n",
            cells[2 * i],
            cells[2 * i + 1]
        ));
    }
    s.push_str(&format!(
        "\nEach cell: outcome; mean speed (runs of at least one drive period); first time the history leaves the physical rules' run (an event of other modes or 1e-6 s away, or a stop). Runs of {} s from the static angle, rtol 1e-10.\n",
        ev.duration_s
    ));
    s
}
