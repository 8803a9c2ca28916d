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
use crate::report::{ChapterReport, Claim, Verdict};

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

/// Adds the chapter's claims.
pub fn add(
    r: &mut ChapterReport,
    scene: &Scene,
    _ctx: &crate::chapters::Context,
    _g1: f64,
    sweep: &[(f64, f64, f64)],
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
    r.claim(Claim::judged(
        "non-sliding-needs-mu-g",
        "3.1.1",
        "Non-sliding (v_rel = 0) can only occur while mu g >= |delta_x omega^2 sin(omega t)| (no bias force): largest |a_support|/(mu g) over every sticking instant of exact runs at Gamma_x = 0.5, 0.9, 1.5 and the chapter's.",
        1.0,
        worst,
        "<= 1 + 1e-9",
        sticks > 0 && worst <= 1.0 + 1e-9,
        Verdict::Confirmed,
    ));

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
    r.claim(Claim::judged(
        "fast-shaking-zero-mean-friction",
        "3.1.1",
        &format!(
            "For any given object velocity the average friction tends to zero as the frequency grows: mean friction / (mu m g) on a block drifting at 0.1 V (exact periodic state) at 1, 3, 10, 30 x the frequency: {}.",
            biases.iter().map(|b| format!("{b:.4}")).collect::<Vec<_>>().join(", ")
        ),
        0.0,
        last,
        0.01,
        decreasing && last.abs() <= 0.01,
        Verdict::Confirmed,
    ));

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
    // At Gamma_x = 100 the averaged law is within ~1.4/Gamma_x^2 = 1.4e-4 (see the sweep),
    // so 1e-3 of c bounds the check.
    r.claim(Claim::judged(
        "remaining-friction-viscous",
        "3.1.1",
        &format!(
            "As printed: the friction that remains is viscous, growing with velocity and falling with frequency or amplitude. Holds for v << V = delta_x omega and Gamma_x >> 1: the mean friction is -(2/pi) mu m g arcsin(v/V), linear with c = 2 mu m g/(pi V) only at small v; at F = 0.9 mu m g the linear law overestimates the drift by {:.0} % (Gamma_x = 100).",
            100.0 * departure
        ),
        c_law,
        c_exact,
        1e-3 * c_law,
        (c_exact - c_law).abs() <= 1e-3 * c_law && departure > 0.1,
        Verdict::Approximation,
    ));

    // 4. The averaged arcsin law in its limit (largest Gamma_x of the sweep).
    let (g_hi, e_hi, _) = sweep[sweep.len() - 1];
    // The error decays like C / Gamma_x^2 with C ~ 1.4-1.7 over 0 < b < 0.8: 10/Gamma_x^2 bounds it.
    r.claim(Claim::judged(
        "arcsin-law-large-gamma",
        "3.1.1 (derived)",
        &format!("The cycle-averaged law v = V sin(pi F/(2 mu m g)) matches the exact periodic drift at Gamma_x = {g_hi:.0} (relative error)."),
        0.0,
        e_hi,
        10.0 / (g_hi * g_hi),
        e_hi <= 10.0 / (g_hi * g_hi),
        Verdict::Confirmed,
    ));

    // 5. Booktop: the slip tilt is arctan(mu), about 20 deg.
    let tilt = critical_tilt_deg(mu, g);
    let atan = mu.atan().to_degrees();
    r.claim(Claim::close(
        "booktop-slip-tilt-arctan-mu",
        "3.1.1 booktop",
        &format!("The tilt needed for the coin to slip on a still book is arctan(mu) (about 20 deg for mu = 0.36; here {atan:.2} deg): bisection on the model's stick/slip outcome."),
        atan,
        tilt,
        1e-9,
    ));

    // 6. Booktop: shaken hard enough, the coin slides at a tilt well below arctan(mu).
    // On the book the friction must supply a_p - b mu g' with |a_p| <= delta omega^2, so
    // sticking breaks somewhere in the cycle iff Gamma_x' = delta omega^2/(mu g') > 1 - b.
    let small = 0.25 * atan;
    let book = booktop(scene, small);
    let still_slides = critical_tilt_deg(mu, g) < small;
    let drift = steady_drift(&book).drift_mps;
    let rapid = book.gamma_x() > 1.0 - book.bias;
    let slides = !still_slides && drift > 1e-12 * book.velocity_amplitude_mps();
    r.claim(Claim::judged(
        "booktop-slides-at-small-tilt",
        "3.1.1 booktop",
        &format!(
            "Shaken rapidly (Gamma_x > 1 - F/(mu m g), here {:.2} vs {:.2}) at {} Hz, the coin slides down a tilt of {small:.1} deg (a quarter of arctan(mu)), where it sticks on a still book: exact drift {:.4} m/s (averaged law {:.4} m/s).",
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
    ));
    r.result("booktop_tilt_deg", small);
    r.result("booktop_drift_mps", drift);
    Ok(())
}
