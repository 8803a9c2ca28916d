//! The claims' error bounds (`rounding.rs`) against independent higher-precision values
//! (double-double arithmetic at the doubles the run holds), and statements off by a
//! small relative amount (far below 10 %, just above what each bound resolves) that
//! must fail their claims.

use super::evidence::{self, painleve_boundary, painleve_min, rig, BOUNDARY_THETAS, RODS};
use super::rounding::{self, gamma};
use super::statements::PRINTED;
use crate::numerics::double_double::Dd;
use crate::report::Verdict;

/// atan(1/2) by its Taylor series (60 terms: 0.25^60 is 1e-36).
fn atan_half() -> Dd {
    let (mut sum, mut pow) = (Dd::new(0.0), Dd::new(0.5));
    for k in 0..60 {
        let t = pow.div(Dd::new((2 * k + 1) as f64));
        sum = if k % 2 == 0 { sum.add(t) } else { sum.sub(t) };
        pow = pow.mul(Dd::new(0.25));
    }
    sum
}

/// The exact `D = 0` of the stored rod `(m_r, m)` at the double `theta`:
/// `tan θ + I_G/(M l_G^2 sin θ cos θ)` in double-double.
fn exact_boundary(m_r: f64, m: f64, theta: f64) -> Dd {
    let g = rig(m_r, m, theta, 1.0, 0.0).geo;
    let (s, c) = Dd::sin_cos(theta);
    let ml2 = Dd::new(g.total_kg).mul(Dd::new(g.l_g_m)).mul(Dd::new(g.l_g_m));
    s.div(c).add(Dd::new(g.i_g).div(ml2.mul(s).mul(c)))
}

#[test]
fn boundary_bounds_cover_the_exact_switch() {
    for (m_r, m) in RODS {
        for th in BOUNDARY_THETAS {
            let b = painleve_boundary(m_r, m, th);
            let exact = exact_boundary(m_r, m, th);
            let (actual, bound) = (exact.dist(b.mu), rounding::switch_error(&b));
            eprintln!("switch at {th} rad, alpha {:.3}: error {actual:.2e}, bound {bound:.2e}", b.alpha);
            assert!(actual <= bound, "{m_r} {m} {th}: {actual:e} > {bound:e}");
            // the closed form as the claim evaluates it, against the same exact value
            let closed = PRINTED.mu_painleve(th, b.alpha);
            let rel = (b.mu - closed).abs() / b.mu;
            assert!(exact.dist(closed) <= gamma(12) * closed, "{th}");
            assert!(rel <= rounding::boundary_tol(&b), "{th}: {rel:e}");
        }
    }
}

#[test]
fn least_boundary_bounds_cover_four_thirds_at_atan_one_half() {
    let lb = painleve_min(0.1, 0.0);
    let c = &lb.centre;
    let (value, angle) = ((c.mu - 4.0 / 3.0).abs(), atan_half().dist(c.theta_rad));
    let (tv, ta) = (rounding::min_tol(&lb), rounding::min_angle_tol(&lb));
    eprintln!("least boundary: error {value:.2e} (bound {tv:.2e}), angle {angle:.2e} rad (bound {ta:.2e})");
    assert!(value <= tv && angle <= ta, "{lb:?}");
    // the points beside: certainly higher, as the bound requires
    for p in [&lb.left, &lb.right] {
        assert!(p.mu - rounding::switch_error(p) > c.mu + rounding::switch_error(c));
    }
}

#[test]
fn drop_ratio_bounds_cover_the_exact_quotient() {
    for (m_r, m) in [(0.1, 0.0), (0.05, 0.05), (0.01, 0.1), (1e-11, 0.1)] {
        for q in evidence::DROP_Q {
            let theta = q.atan();
            let (ratio, alpha, landing) = evidence::drop_ratio(m_r, m, theta);
            // the exact -W_tn/W_tt = α s c/(1 + α c^2) at the landing angle and the run's α
            let (s, c) = Dd::sin_cos(landing);
            let a = Dd::new(alpha);
            let exact = a.mul(s).mul(c).div(Dd::new(1.0).add(a.mul(c).mul(c)));
            let rel = exact.dist(ratio) / ratio;
            eprintln!("drop q = {q}, alpha {alpha:.3e}: quotient error {rel:.2e} (bound γ_18 = {:.2e})", gamma(18));
            assert!(rel <= gamma(18), "{m_r} {q}: {rel:e}");
        }
    }
}

#[test]
fn kinetic_energy_rounding_is_within_the_counted_bound() {
    // T^ against T in double-double at pseudo-random states: |T^ - T| <= γ_14 T~ and
    // T~ <= (1 + 8 α) T (energy_gain_bound's two steps)
    let mut x = 0x2545f4914f6cdd1du64;
    let mut rnd = || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    for (m_r, m) in [(0.1, 0.0), (0.01, 1.0)] {
        let md = rig(m_r, m, 0.3, 1.0, 1.0);
        let (mm, l, ig) = (md.geo.total_kg, md.geo.l_g_m, md.geo.i_g);
        for _ in 0..2000 {
            let mut y = [0.0; crate::physics::stick_inertia::NSTATE];
            y[crate::physics::stick_inertia::TH] = 1.5 * rnd();
            y[crate::physics::stick_inertia::OM] = 20.0 * rnd();
            y[crate::physics::stick_inertia::VXC] = 3.0 * rnd();
            y[crate::physics::stick_inertia::VZC] = 3.0 * rnd();
            let (s, c) = Dd::sin_cos(y[0]);
            let w = Dd::new(y[1]);
            let vx = Dd::new(y[2]).add(Dd::new(l).mul(c).mul(w));
            let vz = Dd::new(y[5]).sub(Dd::new(l).mul(s).mul(w));
            let t = Dd::new(0.5 * mm)
                .mul(vx.mul(vx).add(vz.mul(vz)))
                .add(Dd::new(0.5 * ig).mul(w).mul(w));
            let ax = y[2].abs() + l * (c.0 * y[1]).abs();
            let az = y[5].abs() + l * (s.0 * y[1]).abs();
            let t_abs = 0.5 * mm * (ax * ax + az * az) + 0.5 * ig * y[1] * y[1];
            let err = t.dist(md.kinetic_energy(&y));
            assert!(err <= gamma(14) * t_abs, "{y:?}: {err:e}");
            assert!(t_abs <= (1.0 + 8.0 * md.geo.alpha()) * t.0 * (1.0 + 1e-12), "{y:?}");
        }
    }
}

#[test]
fn local_orders_bracket_the_fitted_order() {
    // a power law with a next term and noise: the least-squares slope lies within the
    // local orders' range; a pure power gives a zero tolerance
    let pts: Vec<(f64, f64)> = (0..6)
        .map(|i| {
            let h = 10f64.powi(i - 5);
            (h, h * (1.0 + 0.3 * h) * (1.0 + 1e-3 * ((i * 7 % 5) as f64 - 2.0)))
        })
        .collect();
    let local = super::claims::local_orders(&pts);
    let logs: Vec<(f64, f64)> = pts.iter().map(|p| (p.0.ln(), p.1.ln())).collect();
    let fit = crate::numerics::fit::slope(&logs);
    let (lo, hi) = local.iter().fold((9.0f64, -9.0f64), |(a, b), &p| (a.min(p), b.max(p)));
    assert!(lo <= fit && fit <= hi, "{fit} {local:?}");
    let pure: Vec<(f64, f64)> = (0..5).map(|i| (2f64.powi(-i), 3.0 * 2f64.powi(-i))).collect();
    assert!(super::claims::order_tol(&super::claims::local_orders(&pure)) < 1e-12);
}

#[test]
fn statements_off_by_what_the_bounds_resolve_fail() {
    let ev = evidence::gather();
    let impacts = evidence::impact_energy(PRINTED.restitution_max);
    let verdict = |doc: &super::Statements, id: &str| {
        let claims = super::claims::all(doc, &ev, impacts);
        claims.into_iter().find(|c| c.id == id).map(|c| c.verdict)
    };
    for c in super::claims::all(&PRINTED, &ev, impacts) {
        assert_ne!(c.verdict, Verdict::Failed, "{}", c.id);
    }
    type Edit = fn(&mut super::Statements);
    let edits: [(&str, Edit); 10] = [
        ("painleve-boundary", |d| d.painleve_scale = 1.0 + 1e-12),
        ("painleve-minimum-uniform", |d| d.painleve_min *= 1.0 + 1e-12),
        ("painleve-minimum-angle", |d| d.painleve_min_tan *= 1.0 + 1e-6),
        ("impulse-ratio-uniform", |d| d.uniform_num *= 1.0 + 1e-13),
        ("impulse-ratio-between", |d| d.between_scale = 1.0 + 1e-13),
        ("impulse-ratio-massless", |d| d.massless_factor = 1.0 + 1e-12),
        ("massless-limit", |d| d.massless_order = 1.03),
        ("moreau-jean", |d| d.mj_order = 1.05),
        ("painleve-compliant-limit", |d| d.iwc_scale = 1.0 + 1e-4),
        ("painleve-compliant-limit", |d| d.iwc_scale = 1.0 - 1e-4),
    ];
    for (id, edit) in edits {
        let mut doc = PRINTED;
        edit(&mut doc);
        assert_eq!(verdict(&doc, id), Some(Verdict::Failed), "{id}");
    }
}
