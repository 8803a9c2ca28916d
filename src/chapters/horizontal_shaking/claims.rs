//! The claims of section 3.1.1, each checked by the exact hybrid simulation.

use super::drift::{steady_drift, Scene};
use crate::error::Result;
use crate::numerics::events::illinois;
use crate::numerics::hybrid::Segment;
use crate::physics::block::{
    simulate_block, simulate_block_observed, BlockMode, BlockOptions, BlockParams, Observer,
};
use crate::physics::friction::effective_viscous_coefficient;
use crate::physics::plate::{Axis, Harmonic, PlateMotion};
use crate::report::{ChapterReport, Check, Claim, Mutation, Verdict};
use std::f64::consts::PI;

/// Largest `|a_xp| / (mu g)` over the sticking instants of a run (11 samples per
/// segment) and the number of sticking segments.
struct StickWatch<'a> {
    plate: &'a Harmonic,
    mu_g: f64,
    worst: f64,
    sticks: usize,
}

impl Observer<BlockMode, 4> for StickWatch<'_> {
    fn segment(&mut self, mode: BlockMode, seg: &Segment<'_, 4>) {
        if mode == BlockMode::Stick && seg.t1 > seg.t0 {
            self.sticks += 1;
            for k in 0..=10 {
                let t = seg.t0 + (seg.t1 - seg.t0) * k as f64 / 10.0;
                self.worst = self.worst.max(self.plate.ax_mps2(t).abs() / self.mu_g);
            }
        }
    }
}

/// The bias (fraction of mu g) that makes the exact drift equal `v_target` (m/s).
fn bias_for_drift(scene: &Scene, v_target: f64) -> f64 {
    let f = |b: f64| steady_drift(&Scene { bias: b, ..*scene }).drift_mps - v_target;
    let (a, b) = (0.0, 0.999);
    let (fa, fb) = (f(a), f(b));
    if fa.signum() == fb.signum() {
        return f64::NAN;
    }
    illinois(f, a, b, fa, fb, 1e-12).0
}

/// The tilt (deg) at which a coin on an unshaken book starts to slide: bisection on the
/// model's outcome (moves or not after 0.1 s).
fn critical_tilt_deg(mu: f64, g: f64) -> f64 {
    let still = Harmonic::sine(Axis::X, 0.0, 5.0);
    let slides = |deg: f64| {
        let a = deg.to_radians();
        let p = BlockParams::coulomb(g * a.cos(), mu, g * a.sin());
        let run = simulate_block(
            &p,
            &still,
            0.1,
            &BlockOptions {
                transient_periods: 0,
                record_events: false,
                ..BlockOptions::default()
            },
        );
        run.y_end[0] > 0.0
    };
    let (mut lo, mut hi) = (0.0, 89.9);
    for _ in 0..60 {
        let m = 0.5 * (lo + hi);
        if slides(m) {
            hi = m;
        } else {
            lo = m;
        }
    }
    hi
}

/// Booktop scene at `tilt_deg`: gravity splits into g cos(tilt) normal to the book and a
/// bias g sin(tilt) along it; the book shakes in its own plane.
pub fn booktop(scene: &Scene, tilt_deg: f64) -> Scene {
    let a = tilt_deg.to_radians();
    let g = scene.g_mps2;
    Scene {
        g_mps2: g * a.cos(),
        bias: a.tan() / scene.mu,
        ..*scene
    } // formula: b = tan(alpha)/mu
}

/// The document's statements of section 3.1.1 (and the workbook's derived law), as
/// data, so that a falsification test can feed the checks a wrong variant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Doc {
    /// Non-sliding only while |a_support| <= k mu g (printed k = 1).
    pub stick_factor: f64,
    /// The limit of the mean friction (fraction of mu m g) for fast shaking (printed 0).
    pub fast_limit: f64,
    /// The remaining friction grows like v^p (printed: viscous, p = 1).
    pub friction_exponent: f64,
    /// The workbook's averaged law v = V sin(k pi F/(2 mu m g)) (derived k = 1).
    pub arcsin_factor: f64,
    /// Booktop: the slip tilt is atan(k mu) (printed k = 1).
    pub tilt_factor: f64,
    /// Booktop: the shaken coin slides down the tilt (`true`, printed) or up.
    pub slides_down: bool,
}

impl Doc {
    /// The document as printed.
    pub const PRINTED: Doc = Doc {
        stick_factor: 1.0,
        fast_limit: 0.0,
        friction_exponent: 1.0,
        arcsin_factor: 1.0,
        tilt_factor: 1.0,
        slides_down: true,
    };
}

/// The falsification mutations: each statement's coefficient off by 10 % (or more
/// where the statement has slack), the direction reversed.
pub fn mutations() -> Vec<Mutation> {
    type Edit = fn(&mut Doc);
    let list: Vec<(&'static str, &'static str, Edit)> = vec![
        (
            "fast-shaking-zero-mean-friction",
            "mean friction -> 0 replaced by -> 0.05 mu m g",
            |d| d.fast_limit = 0.05,
        ),
        (
            "remaining-friction-viscous",
            "viscous F ~ v -> F ~ v^1.1",
            |d| d.friction_exponent = 1.1,
        ),
        (
            "arcsin-law-large-gamma",
            "sin(pi F/(2 mu m g)) -> sin(1.1 pi F/(2 mu m g))",
            |d| d.arcsin_factor = 1.1,
        ),
        (
            "booktop-slides-at-small-tilt",
            "slides down the tilt -> up the tilt",
            |d| d.slides_down = false,
        ),
    ];
    Mutation::from_edits(Doc::PRINTED, list, |id, d| {
        crate::chapters::quick_claim(id, d, super::run_with)
    })
}

/// Adds the chapter's claims under the document's statements `doc`.
pub fn add(
    r: &mut ChapterReport,
    scene: &Scene,
    _ctx: &crate::chapters::Context,
    _g1: f64,
    sweep: &[(f64, f64, f64)],
    doc: &Doc,
) -> Result<()> {
    let (mu, g) = (scene.mu, scene.g_mps2);

    // 1. Non-sliding needs mu g >= |support acceleration| (no bias, as in the document).
    let mut worst = 0.0f64;
    let mut sticks = 0;
    for gx in [0.5, 0.9, 1.5, scene.gamma_x()] {
        let s = Scene {
            bias: 0.0,
            ..scene.at_gamma_x(gx)
        };
        let plate = s.plate();
        let mut w = StickWatch {
            plate: &plate,
            mu_g: mu * g,
            worst: 0.0,
            sticks: 0,
        };
        let opts = BlockOptions {
            transient_periods: 0,
            record_events: false,
            ..BlockOptions::default()
        };
        simulate_block_observed(&s.params(), &plate, 20.0 * plate.period_s(), &opts, &mut w);
        worst = worst.max(w.worst);
        sticks += w.sticks;
    }
    // The cone guard is located to a few ulps of t, and the stick segment ends just past
    // the crossing: |a_xp| exceeds mu g there by (slope x bracket) ~ Gamma_x omega x 1e-15 s,
    // far below 1e-9.
    let k = doc.stick_factor;
    r.claim(Claim::judged(
        "non-sliding-needs-mu-g",
        "3.1.1",
        "Non-sliding (v_rel = 0) can only occur while μ g >= |δₓ ω² sin(ω t)| (no bias force): largest |a_support|/(μ g) over every sticking instant of exact runs at Γₓ = 0.5, 0.9, 1.5 and the chapter's. Consistency check: the block model sticks exactly while |a_support| <= μ g (its own guard), so the sticking instants satisfy the inequality by construction; no document could fail it here (issue 21), so it is not counted as confirmation.",
        k,
        worst,
        "<= k (1 + 1e-9): events located to ulps",
        sticks > 0 && worst <= k * (1.0 + 1e-9),
        Verdict::Confirmed,
    ).with_check(Check::Consistency));

    // 2. The mean friction at a given object velocity tends to zero for fast shaking.
    let v_target = 0.1 * scene.velocity_amplitude_mps();
    let factors = [1.0, 3.0, 10.0, 30.0];
    let biases: Vec<f64> = factors
        .iter()
        .map(|k| {
            bias_for_drift(
                &Scene {
                    frequency_hz: k * scene.frequency_hz,
                    ..*scene
                },
                v_target,
            )
        })
        .collect();
    let decreasing = biases.windows(2).all(|w| w[1] < w[0]);
    let last = biases[biases.len() - 1];
    // Tolerance: twice the averaged law's mean friction at the last frequency,
    // (2/pi) asin(v/V_30) (the law is within 10/Gamma_x^2 of the exact drift there).
    let v_last = factors[factors.len() - 1] * scene.velocity_amplitude_mps();
    let tol2 = 2.0 * (2.0 / PI) * (v_target / v_last).asin(); // formula: F/(mu m g) = (2/pi) asin(v/V)
    r.claim(Claim::judged(
        "fast-shaking-zero-mean-friction",
        "3.1.1",
        &format!(
            "For any given object velocity the average friction tends to zero as the frequency grows: mean friction / (μ m g) on a block drifting at 0.1 V (exact periodic state) at 1, 3, 10, 30 x the frequency: {}.",
            biases.iter().map(|b| format!("{b:.4}")).collect::<Vec<_>>().join(", ")
        ),
        doc.fast_limit,
        last,
        tol2,
        decreasing && (last - doc.fast_limit).abs() <= tol2,
        Verdict::Confirmed,
    ).with_check(Check::Simulation));

    // 3. The remaining friction is viscous: only for v << V (and Gamma_x >> 1).
    let fast = scene.at_gamma_x(100.0);
    let vamp = fast.velocity_amplitude_mps();
    let b_small = 0.02;
    let v_small = steady_drift(&Scene {
        bias: b_small,
        ..fast
    })
    .drift_mps;
    let c_exact = b_small * mu * g / v_small; // formula: c = F/(m v) (per unit mass)
    let c_law = effective_viscous_coefficient(vamp, mu, g);
    let b_big = 0.9;
    let v_big = steady_drift(&Scene {
        bias: b_big,
        ..fast
    })
    .drift_mps;
    let linear_big = b_big * mu * g / c_law;
    let departure = linear_big / v_big - 1.0;
    // The law's exponent: doubling a small force doubles a viscous drift. The averaged
    // law gives v2/v1 = sin(2x)/sin(x) = 2 cos(x), x = pi b/2: tolerance twice its
    // departure from 2 plus 10/Gamma_x^2 (the averaged law's own error).
    let v_double = steady_drift(&Scene {
        bias: 2.0 * b_small,
        ..fast
    })
    .drift_mps;
    let doubling = v_double / v_small;
    let x = PI * b_small / 2.0;
    let tol_exp = 2.0 * (2.0 - 2.0 * x.cos()) + 10.0 / (100.0 * 100.0);
    let expected_doubling = 2f64.powf(1.0 / doc.friction_exponent); // formula: F ~ v^p -> v2/v1 = 2^(1/p)
                                                                    // At Gamma_x = 100 the averaged law is within ~1.4/Gamma_x^2 = 1.4e-4 (see the sweep),
                                                                    // so 1e-3 of c bounds the check.
    r.claim(Claim::judged(
        "remaining-friction-viscous",
        "3.1.1",
        &format!(
            "As printed: the friction that remains is viscous, growing with velocity and falling with frequency or amplitude. Holds for v << V = δₓ ω and Γₓ >> 1: the mean friction is -(2/π) μ m g arcsin(v/V), linear with c = 2 μ m g/(π V) only at small v (exact c within 1e-3 of it at F = 0.02 μ m g, Γₓ = 100); at F = 0.9 μ m g the linear law overestimates the drift by {:.0} %. Expected/computed: the drift ratio when the force doubles from 0.02 to 0.04 μ m g (2 for a viscous law, 2^(1/p) for F ~ v^p); tolerance 2 (2 - 2 cos(π b/2)) + 10/Γₓ².",
            100.0 * departure
        ),
        expected_doubling,
        doubling,
        tol_exp,
        (doubling - expected_doubling).abs() <= tol_exp
            && (c_exact - c_law).abs() <= 1e-3 * c_law
            && departure > 0.1,
        Verdict::Approximation,
    ).with_check(Check::Simulation));

    // 4. The averaged arcsin law in its limit (largest Gamma_x of the sweep).
    let (g_hi, _, exact_hi) = sweep[sweep.len() - 1];
    let b_sweep = if scene.bias > 0.0 { scene.bias } else { 0.01 };
    let v_hi = scene.at_gamma_x(g_hi).velocity_amplitude_mps();
    let law_hi = v_hi * (doc.arcsin_factor * PI * b_sweep / 2.0).sin(); // formula: v = V sin(pi F/(2 mu m g))
    let e_hi = (law_hi / exact_hi - 1.0).abs();
    // The error decays like C / Gamma_x^2 with C ~ 1.4-1.7 over 0 < b < 0.8: 10/Gamma_x^2 bounds it.
    r.claim(Claim::judged(
        "arcsin-law-large-gamma",
        "3.1.1 (derived)",
        &format!("The cycle-averaged law v = V sin(π F/(2 μ m g)) matches the exact periodic drift at Γₓ = {g_hi:.0} (relative error)."),
        0.0,
        e_hi,
        10.0 / (g_hi * g_hi),
        e_hi <= 10.0 / (g_hi * g_hi),
        Verdict::Confirmed,
    ).with_check(Check::Simulation));

    // 5. Booktop: the slip tilt is arctan(mu), about 20 deg.
    let tilt = critical_tilt_deg(mu, g);
    let atan = (doc.tilt_factor * mu).atan().to_degrees();
    r.claim(Claim::close(
        "booktop-slip-tilt-arctan-mu",
        "3.1.1 booktop",
        &format!("The tilt needed for the coin to slip on a still book is arctan(μ) (about 20 deg for μ = 0.36; here {atan:.2} deg): bisection on the model's stick/slip outcome (60 halvings of 90 deg: bracket ~1e-16 deg; 1e-9 deg allows the rounding of tan at the threshold). Consistency check: the model's stick test on a still tilted book is tan(tilt) <= μ, so the bisection returns arctan(μ) by construction; no document could fail it here (issue 21), so it is not counted as confirmation."),
        atan,
        tilt,
        1e-9,
    ).with_check(Check::Consistency));

    // 6. Booktop: shaken hard enough, the coin slides at a tilt well below arctan(mu).
    // On the book the friction must supply a_p - b mu g' with |a_p| <= delta omega^2, so
    // sticking breaks somewhere in the cycle iff Gamma_x' = delta omega^2/(mu g') > 1 - b.
    let small = 0.25 * mu.atan().to_degrees();
    let book = booktop(scene, small);
    let still_slides = critical_tilt_deg(mu, g) < small;
    let drift = steady_drift(&book).drift_mps;
    let rapid = book.gamma_x() > 1.0 - book.bias;
    let moved = drift.abs() > 1e-12 * book.velocity_amplitude_mps();
    let down = drift > 0.0; // the bias, gravity's component along the book, points to +x
    let slides = !still_slides && moved && down == doc.slides_down;
    r.claim(Claim::judged(
        "booktop-slides-at-small-tilt",
        "3.1.1 booktop",
        &format!(
            "Shaken rapidly (Γₓ > 1 - F/(μ m g), here {:.2} vs {:.2}) at {} Hz, the coin slides down a tilt of {small:.1} deg (a quarter of arctan(μ)), where it sticks on a still book: exact drift {:.4} m/s (averaged law {:.4} m/s).",
            book.gamma_x(),
            1.0 - book.bias,
            scene.frequency_hz,
            drift,
            book.averaged_drift_mps()
        ),
        rapid,
        slides,
        "exact",
        rapid == slides,
        Verdict::Confirmed,
    ).with_check(Check::Simulation));
    r.result("booktop_tilt_deg", small);
    r.result("booktop_drift_mps", drift);
    Ok(())
}
