//! The claims of section 3.1.2 and the cost of each approximation of the bias law.

use super::doc::Doc;
use super::regimes::Boundary;
use super::scene::{run, Model, Scene};
use crate::physics::block::{simulate_block, BlockOptions, BlockParams};
use crate::physics::plate::PlateMotion;
use crate::report::{ChapterReport, Check, Claim, Verdict};
use std::f64::consts::PI;

/// Gamma_n = sqrt(1 + (n pi)^2): a flight from rest lasts exactly n periods.
pub fn gamma_n(n: f64) -> f64 {
    (1.0 + (n * PI).powi(2)).sqrt() // formula: Gamma_n = sqrt(1 + (n pi)^2)
}

/// Adds the claims under the document's statements `doc`.
pub fn add(
    r: &mut ChapterReport,
    scene: &Scene,
    takeoff_phase: f64,
    bounds: &[Boundary],
    quick: bool,
    doc: &Doc,
) {
    r.claim(flight_needs_gamma(scene, doc));
    r.claim(takeoff(scene, takeoff_phase, doc));
    let (fraction, viscous) = fast_limits(scene, quick, doc);
    r.claim(fraction);
    r.claim(viscous);
    r.claim(sliding_contact(scene, doc));
    r.claim(small_force(scene, doc));
    let (flight, law) = bias_law(scene, quick, doc);
    r.claim(flight);
    r.claim(law);
    r.claim(period_doublings(scene, quick, doc));
    r.claim(flight_boundaries(bounds, quick, doc));
}

/// Flight needs delta omega^2 > g: no take-off just below the printed threshold, take-off
/// just above it.
pub fn flight_needs_gamma(scene: &Scene, doc: &Doc) -> Claim {
    let leaves = |gamma: f64| {
        run(&scene.at_gamma(gamma), Model::Exact, 0, 50)
            .run
            .total_counts
            .takeoffs
            > 0
    };
    let gc = doc.flight_gamma;
    let (below, above) = (leaves(gc * 0.999), leaves(gc * 1.001));
    Claim::exact(
        "flight-needs-gamma-above-1",
        "3.1.2",
        "Flight needs a peak plate acceleration δ_z ω² > g: no take-off in 50 periods at Γ = 0.999, take-off at Γ = 1.001 (of the printed threshold). Consistency check: the block model's take-off guard is the plate acceleration reaching -g, the stated inequality itself; no document could fail it here (issue 21), so it is not counted as confirmation.",
        "false, true",
        format!("{below}, {above}").as_str(),
    )
    .with_check(Check::Consistency)
}

/// The take-off phase sin(omega t) = 1/Gamma (the workbook's derivation).
pub fn takeoff(scene: &Scene, takeoff_phase: f64, doc: &Doc) -> Claim {
    // The take-off is a located guard crossing (to ~1e-15 s, i.e. ~1e-13 rad): 1e-9 rad
    // leaves room for the rounding of asin near its argument.
    Claim::close(
        "takeoff-phase",
        "3.1.2 (derived)",
        "The block leaves the plate when the plate's acceleration reaches -g: sin(ω t) = 1/Γ (first take-off from rest; located event; 1e-9 rad: event located to ~1e-13 rad). Consistency check: the located take-off is the zero of the model's guard g + z_s'' = 0, i.e. sin(ω t) = 1/Γ by construction; no document could fail it here (issue 21), so it is not counted as confirmation.",
        (doc.takeoff_factor / scene.gamma).asin(),
        takeoff_phase,
        1e-9,
    )
    .with_check(Check::Consistency)
}

/// Contact fraction -> 0 and c -> 0 as omega grows at fixed delta_z: from the amplitude
/// of Gamma = 2 at the chapter's frequency, with a bias of at least 0.05.
pub fn fast_limits(scene: &Scene, quick: bool, doc: &Doc) -> (Claim, Claim) {
    let (transient, observe) = super::budget(quick);
    let lawb = if scene.bias > 0.0 { scene.bias } else { 0.1 };
    let base = Scene {
        gamma: 2.0,
        bias: lawb,
        ..*scene
    };
    let factors = [1.0, 2.0, 4.0, 8.0];
    let mut fractions = Vec::new();
    let mut cs = Vec::new();
    for k in factors {
        let s = Scene {
            frequency_hz: k * base.frequency_hz,
            gamma: base.gamma * k * k,
            ..base
        };
        let stk = run(&s, Model::Exact, transient, 4 * observe);
        fractions.push(stk.run.contact_fraction);
        cs.push(s.bias * s.mu * s.g_mps2 / stk.cycle_velocity_mps); // formula: c = F/(m v_ave)
    }
    // the viscous constant further out, where the law's windows (up to +-15 % of
    // error, issue 21) weigh less against the change in c: to 64 x the frequency
    for k in [16.0, 32.0] {
        let s = Scene {
            frequency_hz: k * base.frequency_hz,
            gamma: base.gamma * k * k,
            ..base
        };
        // a flight lasts ~ 2 v_z/g = Gamma/pi periods: the window holds 40 of them
        let flight_periods = (s.gamma / PI).ceil() as usize;
        let stk = run(
            &s,
            Model::Exact,
            transient.max(5 * flight_periods),
            (4 * observe).max(40 * flight_periods),
        );
        cs.push(s.bias * s.mu * s.g_mps2 / stk.cycle_velocity_mps); // formula: c = F/(m v_ave)
    }
    let last = fractions[fractions.len() - 1];
    // The document's own estimate: contact ~ pi/omega, flight ~ 2 v_z/g = 2 Gamma/omega,
    // so the fraction is below pi/(2 Gamma): the tolerance at the last Gamma (128).
    let g_last = base.gamma * 64.0;
    let tol_f = PI / (2.0 * g_last); // formula: fraction <= (pi/omega)/(2 Gamma/omega)
    let decreasing = fractions.windows(2).all(|w| w[1] < w[0]);
    let fraction = Claim::judged(
        "contact-fraction-to-zero",
        "3.1.2",
        &format!(
            "As ω grows at fixed δ_z the fraction of time in contact goes to 0: from Γ = 2 at 1, 2, 4, 8 x the frequency (Γ = 2, 8, 32, 128) it is {} (tolerance π/(2 Γ) at Γ = 128: the document's contact ~ π/ω over flight ~ 2 v_z/g).",
            fractions.iter().map(|f| format!("{f:.3}")).collect::<Vec<_>>().join(", ")
        ),
        doc.contact_limit,
        last,
        tol_f,
        decreasing && (last - doc.contact_limit).abs() <= tol_f,
        Verdict::Confirmed,
    )
    .with_check(Check::Simulation);
    // The document's law v_ave = F v_z/(m g) gives c = g/v_z ~ omega^(-1) at fixed
    // delta_z. The law itself is off by +14.4 % at Gamma = 2 and by up to 15 % in
    // windows of Gamma in [10, 40] (issue 21), which bends the slope there (1/omega^1.1
    // passed a test over 1 to 8 x); from Gamma = 128 on it is within 1 %. So the
    // exponent is fitted between 8 and 32 x the frequency (Gamma = 128 and 2048):
    // p = -ln(c_32/c_8)/ln 4, tolerance ln(1.01^2)/ln 4 = 0.0144 (1 % at either end);
    // a law off by 10 % in the exponent is 0.1 away.
    let ratio = cs[5] / cs[3];
    let p_fit = -ratio.ln() / 4f64.ln(); // formula: p = -ln(c_32/c_8)/ln 4
    let expected = doc.c_exponent;
    let tol_c = (1.01f64 * 1.01).ln() / 4f64.ln();
    let viscous = Claim::judged(
        "viscous-constant-to-zero",
        "3.1.2",
        &format!(
            "The effective viscous constant c = F/v_ave goes to zero as ω grows at fixed δ_z, as 1/ω by the document's law (c = g/v_z): c (1/s) from Γ = 2 at 1, 2, 4, 8, 16, 32 x the frequency (Γ up to 2048, windows of 40 flights) = {}; the exponent p of c ~ ω^-p fitted between 8 and 32 x (Γ = 128 to 2048, where the law is within 1 %; below, its +14.4 % at Γ = 2 and windows of up to 15 % for Γ in [10, 40] bend the slope) against 1, tolerance ln(1.01²)/ln 4 = 0.0144.",
            cs.iter().map(|c| format!("{c:.4}")).collect::<Vec<_>>().join(", ")
        ),
        expected,
        p_fit,
        tol_c,
        cs.windows(2).all(|w| w[1] < w[0]) == (doc.c_exponent > 0.0)
            && (p_fit - expected).abs() <= tol_c,
        Verdict::Confirmed,
    )
    .with_check(Check::Simulation);
    (fraction, viscous)
}

/// Sliding contact: the mean friction is mu times the mean normal force.
pub fn sliding_contact(scene: &Scene, doc: &Doc) -> Claim {
    let plate = scene.plate();
    let t_end = 60.0 * plate.period_s();
    let p = BlockParams::coulomb(scene.g_mps2, scene.mu, 0.0);
    let v0 = 2.0 * scene.mu * scene.g_mps2 * t_end; // fast enough never to stop
    let opts = BlockOptions {
        start: (0.0, [0.0, v0, 0.0, 0.0]),
        transient_periods: 0,
        ..BlockOptions::default()
    };
    let sl = simulate_block(&p, &plate, t_end, &opts);
    let friction = (sl.y_end[1] - v0) / t_end; // formula: <f> = delta v_x / t
    let normal = scene.g_mps2 + sl.y_end[3] / t_end; // formula: <N>/m = g + delta v_z / t
    let ratio = -friction / (scene.mu * normal);
    let always_slides = sl.total_counts.slip_to_stick == 0
        && sl.total_counts.reversals == 0
        && sl.total_counts.landings > 0;
    // Closed-form phases and located events: the impulse balance holds to round-off
    // (~1e-13 relative over 60 periods); 1e-9 leaves room for the events' ulps.
    Claim::judged(
        "sliding-contact-full-friction",
        "3.1.2",
        "If the block slides during contact, the average horizontal force is μ times the average vertical force m g (flights and impacts included): vertical vibration does not reduce sliding friction. Mean friction / (μ x mean normal force) of a block kept sliding over 60 periods (1e-9: round-off of closed-form phases and located events): Consistency check: the model's sliding friction is μ N at every instant, so its averages are in ratio μ by construction; no document could fail it here (issue 21), so it is not counted as confirmation.",
        doc.sliding_factor,
        ratio,
        1e-9,
        always_slides && (ratio - doc.sliding_factor).abs() <= 1e-9,
        Verdict::Confirmed,
    )
    .with_check(Check::Consistency)
}

/// Arbitrarily small forces move the block once Gamma > 1: three decades of force just
/// above the printed threshold, none just below it.
pub fn small_force(scene: &Scene, doc: &Doc) -> Claim {
    let v = |gamma: f64, bias: f64| {
        let s = Scene {
            bias,
            ..scene.at_gamma(gamma)
        };
        run(&s, Model::Exact, 0, 50).cycle_velocity_mps
    };
    let gc = doc.flight_gamma_small_force;
    let forces = [1e-2, 1e-3, 1e-4];
    let above: Vec<f64> = forces.iter().map(|&b| v(1.05 * gc, b)).collect();
    let below = v(0.95 * gc, 1e-3);
    let moves = above.iter().all(|&x| x > 0.0) && below == 0.0;
    Claim::judged(
        "small-force-moves-block",
        "3.1.2",
        &format!(
            "So long as δ_z ω² > g, an arbitrarily small sideways force moves the block: F = 0.01, 0.001, 0.0001 μ m g give {} m/s at Γ = 1.05 (the drift scales with F: no threshold force), and F = 0.001 μ m g gives {below:.1e} m/s at Γ = 0.95 (below 1 - F/(μ m g): friction holds).",
            above.iter().map(|x| format!("{x:.2e}")).collect::<Vec<_>>().join(", ")
        ),
        true,
        moves,
        "exact",
        moves,
        Verdict::Confirmed,
    )
    .with_check(Check::Simulation)
}

/// Mean flight time and drift just below Gamma_n (the block rests between flights of
/// n periods, the limit the document's law assumes): `(t_f g/v_z, (v_ave/v_z)/(F/m g))`
/// at Gamma_n (1 - eps).
fn at_gamma_n(scene: &Scene, n: f64, eps: f64, model: Model, quick: bool) -> (f64, f64) {
    let (transient, observe) = super::budget(quick);
    let lawb = if scene.bias > 0.0 { scene.bias } else { 0.1 };
    let s = Scene {
        bias: lawb,
        ..scene.at_gamma(gamma_n(n) * (1.0 - eps))
    };
    let st = run(&s, model, transient, observe);
    let tf = st.mean_flight_s() * s.g_mps2 / s.vz_mps(); // formula: t_f / (v_z/g)
    let law = (st.cycle_velocity_mps / s.vz_mps()) / (s.bias * s.mu); // formula: (v_ave/v_z)/mu_eff
    (tf, law)
}

/// Where the laws hold: over Gamma = 2, 3, ..., 40 (every second value in quick mode),
/// the simulated t_f g/v_z against 2 and (v_ave/v_z)/mu_eff against 1: the share of the
/// Gamma values at which each is within 10 %, the largest error and where it occurs.
fn law_range(scene: &Scene, quick: bool) -> (String, String) {
    let (transient, observe) = super::budget(quick);
    let b = if scene.bias > 0.0 { scene.bias } else { 0.1 };
    let step = if quick { 2 } else { 1 };
    let (mut tf_in, mut law_in, mut n) = (0usize, 0usize, 0usize);
    let (mut tf_worst, mut law_worst) = ((0.0f64, 0.0f64), (0.0f64, 0.0f64));
    let (mut tf_out, mut law_out) = (Vec::new(), Vec::new());
    for gi in (2..=40).step_by(step) {
        let gamma = gi as f64;
        let s = Scene {
            gamma,
            bias: b,
            ..*scene
        };
        // flights of up to ~Gamma/pi periods: windows of 10 of them at least
        let fp = (gamma / PI).ceil() as usize;
        let st = run(
            &s,
            Model::Exact,
            transient.max(5 * fp),
            observe.max(10 * fp),
        );
        let tf_err = st.mean_flight_s() * s.g_mps2 / s.vz_mps() / 2.0 - 1.0; // formula: t_f/(2 v_z/g) - 1
        let law_err = (s.bias * s.mu) / (st.cycle_velocity_mps / s.vz_mps()) - 1.0; // formula: mu_eff/(v_ave/v_z) - 1
        n += 1;
        for (err, inside, worst, out) in [
            (tf_err, &mut tf_in, &mut tf_worst, &mut tf_out),
            (law_err, &mut law_in, &mut law_worst, &mut law_out),
        ] {
            if err.abs() <= 0.1 {
                *inside += 1;
            } else {
                out.push(gi);
            }
            if err.is_finite() && err.abs() > worst.0.abs() {
                *worst = (err, gamma);
            }
        }
    }
    let text = |inside: usize, worst: (f64, f64), out: &[i32]| {
        format!(
            "over Γ = 2 to 40 (step {step}) it is within 10 % at {inside} of {n} values, largest error {:+.0} % at Γ = {}; off by more than 10 % at Γ = {}",
            100.0 * worst.0,
            worst.1,
            if out.is_empty() { "none".to_string() } else { out.iter().map(|g| g.to_string()).collect::<Vec<_>>().join(", ") }
        )
    };
    (
        text(tf_in, tf_worst, &tf_out),
        text(law_in, law_worst, &law_out),
    )
}

/// t_f = 2 v_z/g and mu_eff = v_ave/v_z: approximations, exact in the limit of flights of
/// n whole periods with n -> infinity, where the closed forms are 2 n pi/Gamma_n and
/// n pi/Gamma_n. Simulated at n = 1, 2, 3 against them.
pub fn bias_law(scene: &Scene, quick: bool, doc: &Doc) -> (Claim, Claim) {
    let (transient, observe) = super::budget(quick);
    let mut tf_ok = true;
    let mut law_ok = true;
    let (mut rows_tf, mut rows_law) = (Vec::new(), Vec::new());
    let mut last = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    for n in [1.0, 2.0, 3.0] {
        let (tf, law) = at_gamma_n(scene, n, 1e-6, Model::Exact, quick);
        let (tf10, law10) = at_gamma_n(scene, n, 1e-5, Model::Exact, quick);
        let (_, law_noslip) = at_gamma_n(scene, n, 1e-6, Model::NoContactSlip, quick);
        let gn = gamma_n(n);
        let tf_cf = 2.0 * n * PI / gn; // formula: t_f g/v_z = 2 n pi/Gamma_n
        let law_cf = n * PI / gn; // formula: (v_ave/v_z)/mu_eff = n pi/Gamma_n
                                  // Error estimates: the offset eps = 1e-6 below Gamma_n moves the landing
                                  // linearly in eps (a transversal crossing): (value(1e-5) - value(1e-6))/9 per
                                  // 1e-6; the drift also carries the slip before take-off (Exact against
                                  // NoContactSlip). Twice their sum, plus 1e-9 for the located events.
        let tol_tf = 2.0 * (tf10 - tf).abs() / 9.0 + 1e-9;
        let tol_law = 2.0 * ((law10 - law).abs() / 9.0 + (law - law_noslip).abs()) + 1e-9;
        tf_ok &= (tf - tf_cf).abs() <= tol_tf;
        law_ok &= (law - law_cf).abs() <= tol_law;
        // The document's coefficients are the limit: 1 - (1 + u)^(-1/2) <= u/2 with
        // u = 1/(n pi)^2 bounds the closed forms' distance to it.
        let bound = 1.0 / (2.0 * (n * PI).powi(2));
        tf_ok &= (tf_cf - doc.flight_coeff).abs() <= doc.flight_coeff * bound;
        law_ok &= (law_cf - doc.law_coeff).abs() <= doc.law_coeff * bound;
        rows_tf.push(format!("n = {n}: {tf:.5} (closed form {tf_cf:.5})"));
        rows_law.push(format!("n = {n}: {law:.5} (closed form {law_cf:.5})"));
        last = (tf, tf_cf, law, law_cf, tol_tf, tol_law);
    }
    let here = run(scene, Model::Exact, transient, observe);
    let tf_here = here.mean_flight_s() * scene.g_mps2 / scene.vz_mps();
    let law_here = if scene.bias > 0.0 {
        let ratio = (here.cycle_velocity_mps / scene.vz_mps()) / (scene.bias * scene.mu);
        format!(
            "{ratio:.3} (the law off by {:+.1} %)",
            100.0 * (1.0 / ratio - 1.0)
        )
    } else {
        "not defined (no bias)".to_string()
    };
    let (table, table_law) = (rows_tf.join("; "), rows_law.join("; "));
    let (range_tf, range_law) = law_range(scene, quick);
    let flight = Claim::judged(
        "flight-time-2vz-over-g",
        "3.1.2",
        &format!(
            "As printed: each flight starts at v_z = ω δ_z and lasts t_f = 2 v_z/g. An approximation: exact in the limit of flights of n whole periods from rest, n -> infinity, where t_f g/v_z = 2 n π/Γₙ at Γₙ = sqrt(1 + (n π)²) (within 2/(2 (n π)²) of 2). Simulated t_f g/v_z just below Γₙ and the closed form: {table}; at the chapter's Γ = {:.2}: {tf_here:.3}. Where it holds: {range_tf}. Tolerance per n: twice the error estimate of the offset below Γₙ (runs at 1e-6 and 1e-5 below it) plus 1e-9.",
            scene.gamma
        ),
        last.1,
        last.0,
        last.4,
        tf_ok,
        Verdict::Approximation,
    )
    .with_check(Check::Simulation);
    let law = Claim::judged(
        "bias-law-mu-eff",
        "3.1.2",
        &format!(
            "As printed: F = m g v_ave/v_z, μ_eff = v_ave/v_z for F < μ m g. An approximation: exact in the same limit, where (v_ave/v_z)/μ_eff = n π/Γₙ (take-off speed δ_z ω overestimated by Γₙ/(n π)); simulated just below Γₙ and closed form: {table_law}; at the chapter's Γ = {:.2} the ratio is {law_here}. Where it holds: {range_law}. Tolerance per n: twice the error estimate of the offset below Γₙ plus the slip before take-off (exact against no-contact-slip runs), plus 1e-9.",
            scene.gamma
        ),
        last.3,
        last.2,
        last.5,
        law_ok,
        Verdict::Approximation,
    )
    .with_check(Check::Simulation);
    (flight, law)
}

/// Period doublings from the multiplier, checked by the classifier.
pub fn period_doublings(scene: &Scene, quick: bool, doc: &Doc) -> Claim {
    let (pd_ok, pd_n) = check_period_doublings(scene, quick, doc.pd_scale);
    Claim::judged(
        "period-doubling-multiplier",
        "3.1.2 (derived)",
        "Beyond Γₙ the block never rests and flies exactly n periods per flight (touch-and-go at cos(φ) = n π/Γ); this orbit period-doubles where the multiplier of the one-flight map reaches -1 (Γ = 3.7242, 6.5938, 9.6346 for n = 1, 2, 3). Check: after a long transient the classifier finds P1 just below and P2 just above each located value.",
        true,
        pd_ok && pd_n > 0,
        "exact",
        pd_ok && pd_n > 0,
        Verdict::Confirmed,
    )
    .with_check(Check::SecondMethod)
}

/// The located boundaries where resting between flights is lost, against Gamma_n.
pub fn flight_boundaries(bounds: &[Boundary], quick: bool, doc: &Doc) -> Claim {
    let mut worst = 0.0f64;
    let mut found = 0;
    for n in 1..=3 {
        let gn = (1.0 + (doc.gamma_n_factor * n as f64 * PI).powi(2)).sqrt(); // formula: Gamma_n = sqrt(1 + (n pi)^2)
        if let Some(b) = bounds
            .iter()
            .filter(|b| b.below.starts_with("rest") && b.above.starts_with("no-rest"))
            .min_by(|a, b| (a.gamma - gn).abs().total_cmp(&(b.gamma - gn).abs()))
        {
            worst = worst.max((b.gamma - gn).abs());
            found += 1;
        }
    }
    // Bisection brackets of 0.05/2^16 = 7.6e-7 (full) or 0.5/2^10 = 4.9e-4 (quick) on a
    // boundary that needs no transient (a rest resets the motion).
    let tol = if quick { 5e-4 } else { 1e-6 };
    Claim::judged(
        "flight-period-boundaries",
        "3.1.2 (derived)",
        "A flight from rest lasts exactly n periods at Γₙ = sqrt(1 + (n π)²) (3.297, 6.362, 9.477): the located boundaries where resting between flights is lost agree (largest difference, n = 1, 2, 3; tolerance: the bisection bracket).",
        0.0,
        worst,
        tol,
        found == 3 && worst <= tol,
        Verdict::Confirmed,
    )
    .with_check(Check::SecondMethod)
}

/// Checks the multiplier-located period doublings (n = 1, 2, 3) with the classifier
/// after a long transient just below and above; returns `(all consistent, count)`.
fn check_period_doublings(scene: &Scene, quick: bool, scale: f64) -> (bool, usize) {
    // Near the doubling the multiplier falls like ~5 per unit Gamma, so at 0.01 away
    // |lambda| < 0.96 and 2000 flights-worth of transient leave < 1e-30 of a deviation.
    let (d, long) = if quick { (0.01, 2000) } else { (0.005, 4000) };
    let mut ok = true;
    let mut n = 0;
    for k in 1..=3u32 {
        let pd = scale * super::regimes::period_doubling_gamma(f64::from(k));
        let below = super::regimes::regime_at(scene, pd - d, long, 60).label();
        let above = super::regimes::regime_at(scene, pd + d, long, 60).label();
        ok &= below == format!("no-rest P1/{k}T") && above == format!("no-rest P2/{}T", 2 * k);
        n += 1;
    }
    (ok, n)
}

/// The law's error taken apart: each approximation switched on in turn.
pub fn decomposition(scene: &Scene, transient: usize, observe: usize) -> String {
    let mut gammas = vec![1.5, 2.0, 3.0, 5.0, 8.0, gamma_n(3.0) * (1.0 - 1e-6)];
    if !gammas.iter().any(|g| (g - scene.gamma).abs() < 1e-9) {
        gammas.push(scene.gamma);
    }
    gammas.sort_by(f64::total_cmp);
    let mut s = String::from(
        "| Γ | law / exact - 1 | sticking impacts | no slip before take-off | contact time neglected | flight-time spread | flight on a fixed floor | take-off speed = δ_z ω |\n|---|---|---|---|---|---|---|---|\n",
    );
    for g in gammas {
        let sc = scene.at_gamma(g);
        let b = sc.bias * sc.mu * sc.g_mps2;
        let va = run(&sc, Model::Exact, transient, observe).cycle_velocity_mps;
        let vb = run(&sc, Model::StickingImpacts, transient, observe).cycle_velocity_mps;
        let c = run(&sc, Model::NoContactSlip, transient, observe);
        let vc = c.cycle_velocity_mps;
        let vd = 0.5 * b * c.flight_weighted_s(); // formula: v = b sum t_f^2 / (2 sum t_f)
        let ve = 0.5 * b * c.mean_flight_s(); // formula: v = b <t_f>/2
        let vf = sc.bias * sc.mu * c.mean_takeoff_speed_mps(); // formula: t_f = 2 v_to/g
        let vl = sc.law_velocity_mps();
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
