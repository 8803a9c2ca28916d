//! Chapter 8 `stick-with-inertia`: claims, falsification, energy, CLI.

use locomotion_workbook::chapters::{self, Context};
use locomotion_workbook::numerics::hybrid::Options;
use locomotion_workbook::numerics::ode::{Method, StepControl};
use locomotion_workbook::physics::stick::jamming_scene;
use locomotion_workbook::physics::stick_inertia::run::run_from_rest;
use locomotion_workbook::physics::stick_inertia::{InertiaModel, InertiaParams};
use locomotion_workbook::report::Verdict;

#[test]
fn falsification_mutations_flip_every_claim() {
    let r = chapters::run_default("stick-with-inertia", &Context::headless(true)).unwrap();
    assert!(
        r.claims.iter().all(|c| c.verdict == Verdict::Confirmed),
        "{:?}",
        r.claims
    );
    let muts = chapters::mutations("stick-with-inertia");
    for c in r
        .claims
        .iter()
        .filter(|c| c.check != locomotion_workbook::report::Check::Consistency)
    {
        assert!(
            muts.iter().any(|m| m.claim_id == c.id),
            "no mutation for {}",
            c.id
        );
    }
    for m in muts {
        let c = (m.run)();
        assert_eq!(
            c.verdict,
            Verdict::Failed,
            "{} ({}) did not flip: {:?}",
            m.claim_id,
            m.description,
            c
        );
    }
}

#[test]
fn explore() {
    use locomotion_workbook::physics::stick::authors_scene;
    use locomotion_workbook::physics::stick::run::{initial_state, simulate_stick, Recording};
    use locomotion_workbook::physics::stick::StickModel;
    let opts = Options {
        method: Method::Dop853,
        control: StepControl::tol(1e-10, 1e-10),
        ..Options::default()
    };
    for (name, base0) in [
        ("jam", jamming_scene(9.81)),
        ("authors", authors_scene(10.0)),
    ] {
        for (m, m_r, k, g) in [
            (1.0, 0.0, 10.0, 0.01),
            (1.0, 1e-6, 10.0, 0.01),
            (1.0, 1e-5, 10.0, 0.01),
            (1.0, 1e-4, 10.0, 0.01),
            (1.0, 1e-3, 10.0, 0.01),
            (1.0, 1e-2, 10.0, 0.01),
            (1.0, 0.1, 10.0, 0.01),
            (0.0, 1.0, 10.0, 0.01),
            (0.0, 1.0, 0.0, 0.0),
            (0.0, 0.01, 10.0, 0.01),
        ] {
            let mut base = base0;
            base.mass_kg = m + m_r;
            base.stiffness_nm_per_rad = k;
            base.damping_nms_per_rad = g;
            let t = std::time::Instant::now();
            let v6 = if g > 0.0 {
                let md6 = StickModel::new(base);
                simulate_stick(
                    &md6,
                    0.0,
                    initial_state(&md6, 0.0, base.static_angle().unwrap_or(base.theta0_rad)),
                    10.0,
                    &opts,
                    Recording::default(),
                )
                .mean_velocity_mps
            } else {
                f64::NAN
            };
            if m_r == 0.0 {
                println!("{name} massless v6 {v6:.6}");
                continue;
            }
            base.mass_kg = m;
            let p = InertiaParams {
                base,
                rod_mass_kg: m_r,
                restitution: 0.0,
            };
            let md = InertiaModel::new(p);
            let r = run_from_rest(&md, 10.0, &opts, 0.0);
            println!("{name} m {m} m_r {m_r} k {k}: {:?} v {:.6} v6 {v6:.6} rel {:.2e} ratio {:.3e} imp {} pain {} sw {} budget {:.2e} rhs {} {:?}", r.outcome, r.mean_velocity_mps, (r.mean_velocity_mps - v6) / v6, p.inertia_ratio(), r.impact_count, r.painleve.len(), r.switches, r.budget.relative_residual(), r.rhs_evals, t.elapsed());
        }
    }
}
