//! The chapter's generated tables, from the evidence: the located regime boundaries
//! and the bias law's error taken apart.

use super::regimes::Boundary;

/// The located regime boundaries (markdown).
pub fn regime_boundaries(bounds: &[Boundary]) -> String {
    let mut t = String::from("| Γ | below | above | located by | bracket | shift with 4x transient | accuracy |\n|---|---|---|---|---|---|---|\n");
    for b in bounds {
        t.push_str(&format!(
            "| {:.6} | {} | {} | {} | {:.1e} | {:.1e} | {:.1e} |\n",
            b.gamma,
            b.below.label(),
            b.above.label(),
            match b.band {
                Some((lo, hi)) => format!("multiplier = -1 (classifier band {lo:.3} to {hi:.3})"),
                None => "classifier".to_string(),
            },
            b.bracket,
            (b.gamma - b.gamma_long).abs(),
            b.accuracy()
        ));
    }
    t
}

/// The law's error taken apart, each approximation switched on in turn (markdown), from
/// the rows of [`super::evidence::Evidence::decomposition`].
pub fn decomposition(rows: &[[f64; 8]]) -> String {
    let mut s = String::from(
        "| Γ | law / exact - 1 | sticking impacts | no slip before take-off | contact time neglected | flight-time spread | flight on a fixed floor | take-off speed = δ_z ω |\n|---|---|---|---|---|---|---|---|\n",
    );
    for &[g, va, vb, vc, vd, ve, vf, vl] in rows {
        let pct = |a: f64, b: f64| format!("{:+.2} %", 100.0 * (a / b - 1.0));
        s.push_str(&format!(
            "| {:.3} | {} | {} | {} | {} | {} | {} | {} |\n",
            g,
            pct(vl, va),
            pct(vb, va),
            pct(vc, vb),
            pct(vd, vc),
            pct(ve, vd),
            pct(vf, ve),
            pct(vl, vf)
        ));
    }
    s
}
