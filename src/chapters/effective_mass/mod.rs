//! Chapter `effective-mass` (document section 2): the effective mass matrix of the
//! contact point of a leaning stick, and the sideways impulse a vertical collision
//! produces (dynamic jamming).
//!
//! The mass matrices come from rigid-body mechanics ([`crate::physics::rigid`]): the
//! mobility `W = Id/m + perp(r) perp(r)^T / I_G` of the contact point, inverted with
//! nalgebra. A second method (the Newton-Euler impulse equations, solved as a 5x5
//! linear system) checks every impulse ratio; the document's closed forms are checked
//! against both.

mod claims;
mod sketch;

use super::{info, Context};
use crate::error::Result;
use crate::flags::Flag;
use crate::physics::domain::Interval;
use crate::physics::rigid::{
    effective_mass, in_stick_frame, jam_ratio, rod_contact_offset, tip_contact_offset, RigidBody,
};
use crate::plot::{save_chart, save_drawing, Chart, Legend, Series};
use crate::report::{fmt_num, ChapterReport};
use nalgebra::Matrix2;

/// Flags of the chapter (their help lines: [`FLAGS`]).
#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// Lean angle theta of the stick from the vertical (degrees), [`ANGLE_DEG`].
    #[arg(long, default_value_t = 45.0)]
    pub angle_deg: f64,
    /// Coulomb friction coefficient mu at the contact point C, [`MU`].
    #[arg(long, default_value_t = 0.4)]
    pub mu: f64,
}

/// Largest accepted friction coefficient (dimensionless).
pub const MU_MAX: f64 = 2.0;

/// `--angle-deg`.
pub const ANGLE_DEG: Flag = Flag::new(
    "--angle-deg",
    "Lean angle theta of the stick from the vertical, positive towards +x; default 45, the document's example (q = tan(theta) = 1)",
    "degrees",
    Interval::open(-90.0, 90.0),
)
.why("a stick leaning on its foot C: at 90 degrees it lies on the plate");

/// `--mu`.
pub const MU: Flag = Flag::new(
    "--mu",
    "Coulomb friction coefficient mu at the contact point C; default 0.4, the authors' scene",
    "dimensionless",
    Interval::closed(0.0, MU_MAX),
)
.why("dry contacts; the point-mass-limit check at I_G = 1e-6 m L^2 (gap ~ mu^3) holds to its 1e-5 tolerance up to 2");

/// The table of the chapter's physical flags (no `--g-mps2`: every ratio here is
/// independent of g, and the chapter refuses the flag).
pub const FLAGS: &[Flag] = &[ANGLE_DEG, MU];

/// Stick mass (kg) and length (m) of the authors' scene. Every ratio in this chapter
/// is independent of them (checked in the tests); they only set the units.
pub const MASS_KG: f64 = 1.0;
/// Stick length (m).
pub const LENGTH_M: f64 = 0.15;

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

/// Golden-section search for the maximum (moved down to the numerics layer).
pub use crate::numerics::search::golden_max;

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
    let angle_deg = ANGLE_DEG.check(args.angle_deg)?;
    super::refuse_g("effective-mass", ctx)?;
    let mu = MU.check(args.mu)?;
    let mut r = info("effective-mass").expect("registered").report();
    r.param("angle_deg", angle_deg);
    r.param("mu", mu);
    r.param("mass_kg", MASS_KG);
    r.param("length_m", LENGTH_M);

    let theta = angle_deg.to_radians();
    let (m_rod, m_pm) = matrices(theta);
    let stick = in_stick_frame(&m_rod, theta);
    let ratio_pm = jam_ratio(&m_pm);
    let ratio_rod = jam_ratio(&m_rod);

    for claim in claims::all(theta, mu, &claims::Doc::PRINTED) {
        r.claim(claim);
    }
    let best = golden_max(rod_ratio, 0.0, std::f64::consts::FRAC_PI_2 - 1e-9, 1e-12);
    // Both criteria of C holding under a vertical impulse: the document's bound
    // tan(theta) < mu (exact for the point-mass model) and the uniform rod's own cone
    // test 3q/(4+q^2) <= mu (from its mass matrix).
    let self_locking = theta.tan().abs() < mu; // formula: tan(theta) < mu (document)
    let rod_jams = ratio_rod.abs() <= mu; // formula: |J_l|/J_v <= mu (uniform rod)

    r.result("ratio_point_mass", ratio_pm);
    r.result("ratio_uniform_rod", ratio_rod);
    r.result("m_parallel_over_m", stick[(0, 0)] / MASS_KG);
    r.result("m_perp_over_m", stick[(1, 1)] / MASS_KG);
    r.result("best_angle_uniform_rod_deg", best.to_degrees());
    r.result("self_locking", self_locking);
    r.result("rod_jams_under_vertical_impulse", rod_jams);
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
            "lean angle θ from the vertical (degrees)",
            "J_ℓ / J_v (1)",
        )
        .band(
            0.0,
            lock,
            &format!("self-locking: tan θ < μ = {}", fmt_num(mu)),
        )
        .series(Series::line("point mass: q", pm).color(0))
        .series(Series::line("uniform rod: 3q/(4+q²)", rd).color(1))
        .series(Series::points("45°: 1 and 0.6", vec![(45.0, 1.0), (45.0, 0.6)]).color(6))
        .series(
            Series::points(
                "rod maximum: 0.75 at 63.43°",
                vec![(best.to_degrees(), 0.75)],
            )
            .color(2),
        )
        .series(
            Series::points(
                "rod jams up to / beyond: 3q/(4+q²) = μ",
                rod_lock_angles_closed_form(mu)
                    .map(|(a, b)| vec![(a.to_degrees(), mu), (b.to_degrees(), mu)])
                    .unwrap_or_default(),
            )
            .color(4),
        )
        .hline(mu, &format!("μ = {}", fmt_num(mu)))
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
        "| θ (deg) | q = tan θ | J_ℓ/J_v point mass | J_ℓ/J_v uniform rod | point mass jams (q <= {mu}) | rod jams (3q/(4+q²) <= {mu}) |\n|---|---|---|---|---|---|\n",
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
    claims::mutations()
}
