//! The flags checked and turned into the run's parameters, duration and options.

use super::{scene_params, Args, Context};
use crate::error::{check, range, Result, WorkbookError};
use crate::numerics::hybrid::Options;
use crate::numerics::ode::StepControl;
use crate::physics::stick::StickParams;

/// Largest `omega t Gamma` accepted: the plate phase `omega t` is rounded to `eps omega
/// t`, which moves the plate acceleration, and the contact forces with it, by about
/// `3 eps omega t Gamma m g` (the factor 3 measured: 2.3e-10 m g at omega t Gamma =
/// 5.7e5); the cone check allows 1e-10 m g, so `omega t Gamma <= 1e-10 / (3 eps)`.
pub const PHASE_ROUNDING_MAX: f64 = 1.5e5;

/// Longest accepted duration (s) at frequency `f_hz` and `gamma`: `omega t Gamma <=`
/// [`PHASE_ROUNDING_MAX`] and at most 1e4 s.
pub fn max_duration_s(f_hz: f64, gamma: f64) -> f64 {
    let omega = 2.0 * std::f64::consts::PI * f_hz;
    if gamma > 0.0 {
        (PHASE_ROUNDING_MAX / (omega * gamma)).min(1e4) // formula: omega t Gamma <= 1e-10/(3 eps)
    } else {
        1e4
    }
}

/// `x` (> 0) rounded down to `digits` significant digits, as text: a bound printed in
/// an error line that is never above the bound checked.
fn floor_digits(x: f64, digits: i32) -> String {
    let scale = 10f64.powi(digits - 1 - x.log10().floor() as i32);
    crate::error::num((x * scale).floor() / scale)
}

/// Measured cost of one drive cycle of the main run (s), for the build that runs: the
/// test (dev) build takes 3.3 s for 3e4 cycles of the jamming scene (2 cores), rounded
/// up to 1.2e-4; the release build about 1e-5 (criterion: about 100k cycles/s on the
/// jamming scene; 3 s for 2e5 cycles of a gently shaken plate at 1 kHz), rounded up to
/// 1.5e-5, so that the budget's estimate is the time a reader will wait.
pub const SECONDS_PER_CYCLE: f64 = if cfg!(debug_assertions) {
    1.2e-4
} else {
    1.5e-5
};

/// Validated parameters, duration (s) and options from the flags.
pub fn setup(args: &Args, ctx: &Context) -> Result<(StickParams, f64, Options)> {
    let base = scene_params(args.scene, ctx.g_mps2);
    let (l, m, k, c, mu, th0) = rod_flags(args, &base)?;
    let (gam, f) = plate_flags(args, &base)?;
    let dur = duration_flag(args, ctx, f, gam)?;
    let rtol = check(
        "--rtol",
        args.rtol,
        |v| (1e-14..=1e-2).contains(&v),
        "1e-14 <= value <= 1e-2 (1)",
    )?;
    let mut p = StickParams::new(l, m, k, c, mu, th0, base.g_mps2, gam, f);
    p.collision_angle = args.collision_angle;
    let opts = Options {
        method: args.method.method(),
        control: StepControl::tol(rtol, rtol),
        ..Options::default()
    };
    Ok((p, dur, opts))
}

/// The rod's flags: `(L m, m kg, k N m/rad, gamma N m s/rad, mu, theta_0 rad)`.
fn rod_flags(args: &Args, base: &StickParams) -> Result<(f64, f64, f64, f64, f64, f64)> {
    let half_pi = std::f64::consts::FRAC_PI_2;
    let box10 = "within a factor 10 of the authors' stick, the box over which the chapter's checks are run at the corners (tests/cli.rs)";
    let l = range(
        "--length-m",
        args.length_m.unwrap_or(base.length_m),
        0.015,
        1.5,
        "m",
        box10,
    )?;
    let m = range(
        "--mass-kg",
        args.mass_kg.unwrap_or(base.mass_kg),
        0.1,
        10.0,
        "kg",
        box10,
    )?;
    let k = range(
        "--stiffness",
        args.stiffness.unwrap_or(base.stiffness_nm_per_rad),
        0.0,
        100.0,
        "N m/rad",
        "0 (a free hinge) to 10 x the authors' spring; a spring too weak to hold the stick lets it fall, which the run reports",
    )?;
    let c = range(
        "--damping",
        args.damping.unwrap_or(base.damping_nms_per_rad),
        0.0,
        0.1,
        "N m s/rad",
        "0 to 10 x the authors' damper",
    )?;
    if c == 0.0 && k > 0.0 {
        // formula: in flight the massless rod's moment balance is k (theta - theta_0) + gamma theta' = 0 (C.3)
        return Err(WorkbookError::bad_input(
            "--damping",
            c,
            "0 < value <= 0.1 (N m s/rad) when --stiffness is above 0: in flight the massless rod follows θ' = -(k/γ)(θ - θ₀) (C.3), undetermined at γ = 0 (0 is accepted only with --stiffness 0)",
        ));
    }
    let mu = range(
        "--mu",
        args.mu.unwrap_or(base.mu),
        0.0,
        2.0,
        "1",
        "dry friction at the foot",
    )?;
    let th0 = check(
        "--theta0-rad",
        args.theta0_rad.unwrap_or(base.theta0_rad),
        |v| v.abs() < half_pi,
        "-pi/2 < value < pi/2 (rad), i.e. strictly between -90 and 90 degrees",
    )?;
    Ok((l, m, k, c, mu, th0))
}

/// The plate's flags: `(Gamma, f Hz)`.
fn plate_flags(args: &Args, base: &StickParams) -> Result<(f64, f64)> {
    let gam = range(
        "--gamma",
        args.gamma.unwrap_or(base.gamma_accel()),
        0.0,
        50.0,
        "1",
        "a still plate to 5 x the authors' Gamma = 10",
    )?;
    let f = range(
        "--frequency-hz",
        args.frequency_hz.unwrap_or(base.frequency_hz()),
        1.0,
        1000.0,
        "Hz",
        "1 Hz to 1 kHz; the duration is bounded by omega t Gamma, see --duration-s",
    )?;
    Ok((gam, f))
}

/// `--duration-s`, bounded by the rounding of the plate phase at `f` Hz and `gam`.
fn duration_flag(args: &Args, ctx: &Context, f: f64, gam: f64) -> Result<f64> {
    let default_duration = if ctx.quick { 2.0 } else { 10.0 };
    let t_max = max_duration_s(f, gam);
    check(
        "--duration-s",
        args.duration_s.unwrap_or(default_duration),
        |v| v > 0.0 && v <= t_max,
        &format!(
            "0 < value <= {} (s): omega t Gamma <= {} and t <= 1e4 s; the plate phase omega t carries a rounding of eps omega t, a force error of ~3 eps omega t Gamma m g that the cone check's 1e-10 m g must cover",
            floor_digits(t_max, 6),
            crate::error::num(PHASE_ROUNDING_MAX)
        ),
    )
}
