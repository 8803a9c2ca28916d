//! Chapter `effective-mass` (document section 2): the effective mass matrix of the
//! contact point of a leaning stick, and the sideways impulse a vertical collision
//! produces (dynamic jamming).
//!
//! The mass matrices come from rigid-body mechanics ([`crate::physics::rigid`]): the
//! mobility `W = Id/m + perp(r) perp(r)^T / I_G` of the contact point, inverted with
//! nalgebra. A second method (the Newton-Euler impulse equations, solved as a 5x5
//! linear system) checks every impulse ratio; the document's closed forms are checked
//! against both.

mod sketch;

use super::{info, Context};
use crate::error::{open_interval, range, Result};
use crate::physics::rigid::{
    contact_acceleration, effective_mass, impulse_for_velocity_change, in_stick_frame, jam_ratio,
    rod_contact_offset, stick_normal, tip_contact_offset, RigidBody,
};
use crate::plot::{save_chart, save_drawing, Chart, Legend, Series};
use crate::report::{fmt_num, ChapterReport, Claim, Verdict};
use nalgebra::{Matrix2, Vector2};

/// Flags of the chapter.
#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// Lean angle theta of the stick from the vertical, in degrees (-90 < theta < 90;
    /// positive leans towards +x). Default 45 (the document's example, q = tan(theta) = 1).
    #[arg(long, default_value_t = 45.0)]
    pub angle_deg: f64,
    /// Coulomb friction coefficient mu at the contact point C (dimensionless, 0 <= mu <= 2:
    /// dry contacts; the point-mass-limit check at I_G = 1e-6 m L^2 has a gap growing
    /// like mu^3 that stays under its 1e-5 tolerance up to 2). Default 0.4 (the authors' scene).
    #[arg(long, default_value_t = 0.4)]
    pub mu: f64,
}

/// Largest accepted friction coefficient (dimensionless).
pub const MU_MAX: f64 = 2.0;

/// Stick mass (kg) and length (m) of the authors' scene. Every ratio in this chapter
/// is independent of them (checked in the tests); they only set the units.
pub const MASS_KG: f64 = 1.0;
/// Stick length (m).
pub const LENGTH_M: f64 = 0.15;

/// Rounding tolerance of a 2x2 inversion and a 5x5 LU solve of well-conditioned
/// systems (condition number <= ~20 here): a few hundred ulps, relative.
const TOL_LINALG: f64 = 1e-12;

/// The uniform rod of the scene.
fn rod() -> RigidBody {
    RigidBody::uniform_rod(MASS_KG, LENGTH_M)
}

/// Mass matrices (world frame) of the uniform rod and of the point-mass model.
fn matrices(theta: f64) -> (Matrix2<f64>, Matrix2<f64>) {
    let m_rod = effective_mass(&rod(), rod_contact_offset(theta, LENGTH_M));
    let m_pm = effective_mass(
        &RigidBody::point_mass(MASS_KG),
        tip_contact_offset(theta, LENGTH_M),
    );
    (m_rod, m_pm)
}

/// `J_l / J_v` of the uniform rod from its mass matrix.
pub fn rod_ratio(theta: f64) -> f64 {
    jam_ratio(&matrices(theta).0)
}

/// Golden-section search for the maximum of a unimodal `f` on `[a, b]`, stopped when
/// the bracket is below `tol`. Returns the abscissa.
pub fn golden_max(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64, tol: f64) -> f64 {
    let g = (5f64.sqrt() - 1.0) / 2.0;
    let (mut c, mut d) = (b - g * (b - a), a + g * (b - a));
    let (mut fc, mut fd) = (f(c), f(d));
    while b - a > tol {
        if fc > fd {
            b = d;
            (d, fd) = (c, fc);
            c = b - g * (b - a);
            fc = f(c);
        } else {
            a = c;
            (c, fc) = (d, fd);
            d = a + g * (b - a);
            fd = f(d);
        }
    }
    0.5 * (a + b)
}

/// Bisection for the root of `f` on `[a, b]` (a sign change required), to `tol`.
pub fn bisect(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64, tol: f64) -> f64 {
    let fa = f(a);
    while b - a > tol {
        let m = 0.5 * (a + b);
        if (f(m) > 0.0) == (fa > 0.0) {
            a = m;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

/// Angles (rad) where the rod's impulse ratio equals mu, from the closed form
/// `3q/(4+q^2) = mu`, i.e. `q = (3 -+ sqrt(9 - 16 mu^2)) / (2 mu)`. None for
/// `mu >= 3/4` (the rod then never slips under a vertical impulse) and for `mu = 0`.
pub fn rod_lock_angles_closed_form(mu: f64) -> Option<(f64, f64)> {
    let disc = 9.0 - 16.0 * mu * mu;
    if mu <= 0.0 || disc <= 0.0 {
        return None;
    }
    // formula: smaller root of mu q^2 - 3 q + 4 mu = 0, (3 - sqrt(D))/(2 mu), written
    // as 8 mu/(3 + sqrt(D)) (the same number without the cancellation at small mu)
    let q1 = 8.0 * mu / (3.0 + disc.sqrt());
    let q2 = 4.0 / q1; // formula: the product of the roots is 4
    Some((q1.atan(), q2.atan()))
}

/// Runs the chapter.
pub fn run(args: &Args, ctx: &Context) -> Result<ChapterReport> {
    let angle_deg = open_interval("--angle-deg", args.angle_deg, -90.0, 90.0, "degrees")?;
    super::refuse_g("effective-mass", ctx)?;
    let mu = range(
        "--mu",
        args.mu,
        0.0,
        MU_MAX,
        "dimensionless",
        "dry contacts; the point-mass-limit check at I_G = 1e-6 m L^2 (gap ~ mu^3) holds to its 1e-5 tolerance up to 2",
    )?;
    let mut r = info("effective-mass").expect("registered").report();
    r.param("angle_deg", angle_deg);
    r.param("mu", mu);
    r.param("mass_kg", MASS_KG);
    r.param("length_m", LENGTH_M);

    let theta = angle_deg.to_radians();
    let q = theta.tan(); // formula: slope 1/q, q = tan(theta)
    let (m_rod, m_pm) = matrices(theta);
    let stick = in_stick_frame(&m_rod, theta);
    let ratio_pm = jam_ratio(&m_pm);
    let ratio_rod = jam_ratio(&m_rod);

    // (A.1): the rod's mass matrix in stick coordinates.
    let sec = "2, eq. (A.1)";
    let rel = |x: f64| TOL_LINALG * x.abs().max(1.0);
    r.claim(Claim::close(
        "rod-mass-along",
        sec,
        "Effective mass of C along the uniform stick: m (kg).",
        MASS_KG,
        stick[(0, 0)],
        rel(MASS_KG),
    ));
    r.claim(Claim::close(
        "rod-mass-across",
        sec,
        "Effective mass of C across the uniform stick: m/4 (kg).",
        MASS_KG / 4.0,
        stick[(1, 1)],
        rel(MASS_KG),
    ));
    r.claim(Claim::close(
        "rod-mass-diagonal",
        sec,
        "[m]' is diagonal in stick coordinates x'-z' (off-diagonal entry, kg).",
        0.0,
        stick[(0, 1)],
        rel(MASS_KG),
    ));

    // The document's step-by-step derivation with a unit force across the stick at C.
    let f = 1.0;
    let (a_g, omega_dot, a_c) = contact_acceleration(
        &rod(),
        rod_contact_offset(theta, LENGTH_M),
        f * stick_normal(theta),
    );
    let i_g = rod().inertia_kgm2;
    let sec = "2, text after (A.1)";
    r.claim(Claim::close(
        "derivation-a-g",
        sec,
        "a_G = F/m (m/s^2 for F = 1 N across the stick).",
        f / MASS_KG,
        a_g.norm(),
        rel(f / MASS_KG),
    ));
    let wd = f * LENGTH_M / 2.0 / i_g;
    r.claim(Claim::close(
        "derivation-omega-dot",
        sec,
        "omega_dot = (F L/2)/I (rad/s^2 for F = 1 N).",
        wd,
        omega_dot.abs(),
        rel(wd),
    ));
    let a_cg = (a_c - a_g).dot(&stick_normal(theta));
    r.claim(Claim::close(
        "derivation-a-c-g",
        sec,
        "a_C/G = omega_dot L/2 (m/s^2 for F = 1 N).",
        wd * LENGTH_M / 2.0,
        a_cg,
        rel(wd),
    ));
    r.claim(Claim::close(
        "derivation-a-c",
        sec,
        "a_C = F/(m/4): effective mass m/4 across the stick (m/s^2 for F = 1 N).",
        4.0 * f / MASS_KG,
        a_c.dot(&stick_normal(theta)),
        rel(4.0),
    ));

    // The impulse ratios against the closed forms and against the Newton-Euler solve.
    let sec = "2, J_l formula";
    let rod_cf = 3.0 * q / (4.0 + q * q); // formula: J_l/J_v = 3q/(4+q^2)
    r.claim(Claim::close(
        "ratio-point-mass",
        sec,
        "Point-mass model: J_l = q J_v (ratio at the given angle).",
        q,
        ratio_pm,
        rel(q),
    ));
    r.claim(Claim::close(
        "ratio-uniform-rod",
        sec,
        "Uniform rod: J_l = (3q/(4+q^2)) J_v (ratio at the given angle).",
        rod_cf,
        ratio_rod,
        rel(rod_cf),
    ));
    let up = Vector2::new(0.0, 1.0);
    let ne = |b: RigidBody, off: Vector2<f64>| {
        impulse_for_velocity_change(&b, off, up)
            .map(|i| i.impulse.x / i.impulse.y)
            .unwrap_or(f64::NAN)
    };
    let ne_rod = ne(rod(), rod_contact_offset(theta, LENGTH_M));
    let ne_pm = ne(
        RigidBody::point_mass(MASS_KG),
        tip_contact_offset(theta, LENGTH_M),
    );
    r.claim(Claim::close(
        "ratio-rod-newton-euler",
        sec,
        "Second method (Newton-Euler impulse equations) gives the rod's ratio 3q/(4+q^2).",
        rod_cf,
        ne_rod,
        rel(rod_cf),
    ));
    r.claim(Claim::close(
        "ratio-point-mass-newton-euler",
        sec,
        "Second method (Newton-Euler, I_G = 0) gives the point-mass ratio q.",
        q,
        ne_pm,
        rel(q),
    ));

    let (m45_rod, m45_pm) = matrices(std::f64::consts::FRAC_PI_4);
    let sec = "2, 45 degree example";
    r.claim(Claim::close("example-45-point-mass", sec, "At 45 degrees (q = 1) the point-mass model gives a horizontal impulse equal to the vertical one (J_l/J_v).", 1.0, jam_ratio(&m45_pm), TOL_LINALG));
    r.claim(Claim::close(
        "example-45-rod-60-percent",
        sec,
        "At 45 degrees the uniform rod gives 60 % of the point mass's sideways impulse.",
        0.6,
        jam_ratio(&m45_rod) / jam_ratio(&m45_pm),
        TOL_LINALG,
    ));

    // The angle of largest sideways impulse of the rod: golden section on the mass
    // matrix ratio, against the closed form d/dq [3q/(4+q^2)] = 0 -> q = 2.
    let tol_rad = 1e-12;
    let best = golden_max(rod_ratio, 0.0, std::f64::consts::FRAC_PI_2 - 1e-9, tol_rad);
    let best_cf = 2f64.atan(); // formula: q* = 2, theta* = atan 2

    // Near a smooth maximum the ratio is flat to second order, so rounding in the ratio
    // (~1e-16) moves the argmax by ~sqrt(1e-16) ~ 1e-8 rad: tolerance 1e-6 degrees.
    r.claim(Claim::close(
        "rod-best-angle",
        "2 (workbook)",
        "The uniform rod's sideways impulse is largest at q = 2, theta = atan 2 (degrees).",
        best_cf.to_degrees(),
        best.to_degrees(),
        1e-6,
    ));
    r.claim(Claim::close(
        "rod-best-ratio",
        "2 (workbook)",
        "The largest ratio of the uniform rod is 3/4 (J_l/J_v at q = 2).",
        0.75,
        rod_ratio(best),
        1e-12,
    ));

    // Self-locking: the document's bound against the rod's own impulse condition.
    let self_locking = theta.tan().abs() < mu; // formula: tan(theta) < mu (document)
    self_locking_claim(&mut r, mu);

    r.result("ratio_point_mass", ratio_pm);
    r.result("ratio_uniform_rod", ratio_rod);
    r.result("m_parallel_over_m", stick[(0, 0)] / MASS_KG);
    r.result("m_perp_over_m", stick[(1, 1)] / MASS_KG);
    r.result("best_angle_uniform_rod_deg", best.to_degrees());
    r.result("self_locking", self_locking);
    r.table("jamming", jamming_table(mu, angle_deg));

    if let Some(dir) = ctx.figure_dir("effective-mass") {
        let n = if ctx.quick { 90 } else { 891 };
        let angles: Vec<f64> = (0..n).map(|i| 89.0 * i as f64 / (n - 1) as f64).collect();
        let pm: Vec<(f64, f64)> = angles
            .iter()
            .map(|&a| (a, jam_ratio(&matrices(a.to_radians()).1)))
            .collect();
        let rd: Vec<(f64, f64)> = angles
            .iter()
            .map(|&a| (a, rod_ratio(a.to_radians())))
            .collect();
        let lock = mu.atan().to_degrees();
        let chart = Chart::new(
            "Sideways impulse of a vertical collision at C",
            "lean angle theta from vertical (degrees)",
            "J_l / J_v (1)",
        )
        .band(
            0.0,
            lock,
            &format!("self-locking: tan theta < mu = {}", fmt_num(mu)),
        )
        .series(Series::line("point mass: q", pm).color(0))
        .series(Series::line("uniform rod: 3q/(4+q^2)", rd).color(1))
        .series(Series::points("45 degrees: 1 and 0.6", vec![(45.0, 1.0), (45.0, 0.6)]).color(6))
        .series(
            Series::points(
                "rod maximum: 0.75 at 63.43 degrees",
                vec![(best.to_degrees(), 0.75)],
            )
            .color(2),
        )
        .series(
            Series::points(
                "rod jams up to / beyond: 3q/(4+q^2) = mu",
                rod_lock_angles_closed_form(mu)
                    .map(|(a, b)| vec![(a.to_degrees(), mu), (b.to_degrees(), mu)])
                    .unwrap_or_default(),
            )
            .color(4),
        )
        .hline(mu, &format!("mu = {}", fmt_num(mu)))
        .vline(lock, "")
        .x_range(0.0, 90.0)
        .y_range(0.0, 2.0)
        .legend(Legend::UpperLeft);
        r.figures.extend(save_chart(&chart, &dir, "impulse-ratio")?);
        let sketch = sketch::Sketch {
            theta_rad: theta,
            mu,
            ratio_point_mass: ratio_pm,
            ratio_rod,
        };
        r.figures
            .extend(save_drawing(&sketch, &dir, "impulse-sketch", (900, 700))?);
    }
    Ok(r)
}

/// The claim on the self-locking bound tan(theta) < mu.
fn self_locking_claim(r: &mut ChapterReport, mu: f64) {
    // Numerically: where the rod's mass-matrix ratio crosses mu (bisection to 1e-13 rad
    // on each side of the maximum), against the closed-form roots.
    let best = 2f64.atan();
    let crossings = if rod_ratio(best) > mu && mu > 0.0 {
        let f = |t: f64| rod_ratio(t) - mu;
        Some((
            bisect(f, 0.0, best, 1e-13),
            bisect(f, best, std::f64::consts::FRAC_PI_2 - 1e-12, 1e-13),
        ))
    } else {
        None
    };
    let cf = rod_lock_angles_closed_form(mu);
    // Point-mass limit: the ratio of a body with I_G = 1e-6 m L^2 tends to q: the gap is
    // O(I_G) ~ 5e-7, far above the inversion's rounding (cond ~1e6 x 2.2e-16 ~ 2e-10).
    let t = mu.atan();
    let thin = RigidBody {
        mass_kg: MASS_KG,
        inertia_kgm2: 1e-6 * MASS_KG * LENGTH_M * LENGTH_M,
    };
    let limit_gap =
        (jam_ratio(&effective_mass(&thin, tip_contact_offset(t, LENGTH_M))) - t.tan()).abs();
    let deg = |x: f64| fmt_num(x.to_degrees());
    let (expected, computed, holds, detail) = match (cf, crossings) {
        (Some((a1, a2)), Some((b1, b2))) => {
            // Bisection to 1e-13 rad; a 1e-9 degree tolerance leaves room for the
            // rounding of the ratio near the crossings (slope ~1, error ~1e-16).
            let ok = (a1 - b1).abs().to_degrees() < 1e-9
                && (a2 - b2).abs().to_degrees() < 1e-9
                && a1 > t;
            (
                format!("rod jams for theta <= {} or theta >= {} degrees", deg(a1), deg(a2)),
                format!("rod jams for theta <= {} or theta >= {} degrees", deg(b1), deg(b2)),
                ok,
                format!("for mu = {} the rod also jams for {} < theta <= {} degrees and for theta >= {} degrees", fmt_num(mu), deg(t), deg(a1), deg(a2)),
            )
        }
        (None, None) if mu > 0.0 => (
            "rod jams at every angle (mu >= 3/4)".to_string(),
            format!("largest rod ratio {} <= mu", fmt_num(rod_ratio(best))),
            true,
            format!(
                "for mu = {} >= 3/4 the rod never slips under a vertical impulse",
                fmt_num(mu)
            ),
        ),
        (None, None) => (
            "only theta = 0 jams (mu = 0)".to_string(),
            "only theta = 0 jams (mu = 0)".to_string(),
            true,
            "with mu = 0 only the upright stick jams".to_string(),
        ),
        _ => (
            "consistent closed form and bisection".to_string(),
            "inconsistent".to_string(),
            false,
            String::new(),
        ),
    };
    let statement = format!(
        "As printed (Fig. 1): theta < atan(mu) puts the stick in the self-locking regime. This is exact for a force along the stick (the point-mass model, the limit I_G -> 0: ratio gap {limit_gap:.1e} at I_G = 1e-6 m L^2). For the uniform rod a vertical impulse has |J_l|/J_v = 3q/(4+q^2) <= q, so C holds whenever 3q/(4+q^2) <= mu: tan(theta) < mu is sufficient, not necessary ({detail})."
    );
    let holds = holds && limit_gap < 1e-5;
    r.claim(Claim::judged(
        "self-locking-bound",
        "2, Fig. 1 caption",
        &statement,
        expected,
        computed,
        "1e-9 degrees",
        holds,
        Verdict::Approximation,
    ));
}

/// Markdown table of the impulse ratios and jamming at a few angles.
fn jamming_table(mu: f64, angle_deg: f64) -> String {
    let mut angles = vec![10.0, 20.0, 30.0, 45.0, 2f64.atan().to_degrees(), 75.0, 85.0];
    if !angles
        .iter()
        .any(|a: &f64| (a - angle_deg.abs()).abs() < 1e-9)
    {
        angles.push(angle_deg.abs());
        angles.sort_by(|a, b| a.total_cmp(b));
    }
    let mut t = format!(
        "| theta (deg) | q = tan theta | J_l/J_v point mass | J_l/J_v uniform rod | point mass jams (q <= {mu}) | rod jams (3q/(4+q^2) <= {mu}) |\n|---|---|---|---|---|---|\n",
        mu = fmt_num(mu)
    );
    for a in angles {
        let th = f64::to_radians(a);
        let (m_rod, m_pm) = matrices(th);
        let (pm, rd) = (jam_ratio(&m_pm), jam_ratio(&m_rod));
        t.push_str(&format!(
            "| {} | {} | {} | {} | {} | {} |\n",
            fmt_num(a),
            fmt_num(th.tan()),
            fmt_num(pm),
            fmt_num(rd),
            pm <= mu,
            rd <= mu
        ));
    }
    t
}

/// The falsification mutations of this chapter's claims (see [`crate::report::Mutation`]).
pub fn mutations() -> Vec<crate::report::Mutation> {
    Vec::new()
}
