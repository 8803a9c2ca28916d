use super::*;
use crate::numerics::hybrid::Options;
use crate::physics::stick::run::{initial_state, simulate_stick, Recording, StickOutcome};
use crate::physics::stick::{authors_scene, jamming_scene};

fn run(
    p: crate::physics::stick::StickParams,
    rules: Printed,
    t: f64,
) -> (StickOutcome, f64, BTreeMap<&'static str, u64>) {
    let m = StickModel::new(p);
    let y0 = initial_state(&m, 0.0, p.static_angle().unwrap_or(p.theta0_rad));
    let (s, f) = simulate_printed(
        &m,
        rules,
        0.0,
        y0,
        t,
        &Options::default(),
        Recording::default(),
    );
    (s.outcome, s.mean_velocity_mps, f)
}

#[test]
fn every_rule_set_ends_without_panic() {
    // all printed, all corrected, and each single correction, both scenes: a typed outcome
    for p in [authors_scene(10.0), jamming_scene(9.81)] {
        let mut sets = vec![Printed::AS_PRINTED, Printed::AS_PRINTED.all_fixed()];
        sets.extend(
            Erratum::ALL
                .iter()
                .map(|&e| Printed::AS_PRINTED.with_fix(e)),
        );
        for r in sets {
            let (o, v, _) = run(p, r, 0.5);
            assert!(v.is_finite(), "{r:?}: {o:?}");
        }
    }
}

#[test]
fn all_corrected_follows_the_physical_rules_on_both_scenes() {
    // with every erratum corrected, the printed rules choose as the contact conditions do:
    // the same mode sequence and the same mean speed to 1e-9 relative (both runs share
    // flows and event location; only the decisions could differ)
    for p in [authors_scene(10.0), jamming_scene(9.81)] {
        let m = StickModel::new(p);
        let y0 = initial_state(&m, 0.0, p.static_angle().unwrap());
        let rec = Recording {
            sequence_cap: 10_000,
            ..Recording::default()
        };
        let opts = Options::default();
        let (s, _) = simulate_printed(
            &m,
            Printed::AS_PRINTED.all_fixed(),
            0.0,
            y0,
            1.0,
            &opts,
            rec,
        );
        let phys = simulate_stick(&m, 0.0, y0, 1.0, &opts, rec);
        assert_eq!(s.outcome, StickOutcome::Completed);
        assert_eq!(s.sequence, phys.sequence);
        let (v, w) = (s.mean_velocity_mps, phys.mean_velocity_mps);
        assert!((v - w).abs() <= 1e-9 * w.abs(), "{v} vs {w}");
    }
}
