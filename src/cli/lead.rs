//! The answer a chapter gives, in words and numbers, read from its report: the first
//! lines a student sees after the question (`workbook all`, a chapter run).
//!
//! A rule speaks when the results it reads are present (result names are part of each
//! chapter's JSON contract); nothing here names a chapter. Rules are tried in order and
//! each result feeds one sentence at most, so `mean_velocity_mps` beside
//! `mean_velocity_law_mps` (a block and the document's law) reads differently from
//! `mean_velocity_mps` beside `phase_fractions` (a walking stick).

use crate::report::{fmt_num, ChapterReport};
use serde_json::Value;

/// One sentence of an answer: the results it needs and how it says them.
struct Rule {
    keys: &'static [&'static str],
    say: fn(&ChapterReport) -> Option<String>,
}

/// A number of the results.
fn res(r: &ChapterReport, key: &str) -> Option<f64> {
    r.results.get(key).and_then(Value::as_f64)
}

/// A number of the parameters.
fn par(r: &ChapterReport, key: &str) -> Option<f64> {
    r.params.get(key).and_then(Value::as_f64)
}

/// A text of the results.
fn text<'a>(r: &'a ChapterReport, key: &str) -> Option<&'a str> {
    r.results.get(key).and_then(Value::as_str)
}

/// `100 (a - b)/b` as a percentage with 2 significant digits.
fn pct_apart(a: f64, b: f64) -> String {
    fmt_pct((a - b).abs() / b.abs())
}

/// A fraction as a percentage (`0.2675` as `27 %`, `0.003855` as `0.39 %`).
fn fmt_pct(x: f64) -> String {
    let p = 100.0 * x;
    if p.is_nan() || p <= 0.0 || p >= 10.0 {
        return format!("{p:.0} %");
    }
    let decimals = (1.0 - p.log10().floor()).max(0.0) as usize; // two significant digits
    format!("{p:.decimals$} %")
}

/// The rules, most specific first.
const RULES: &[Rule] = &[
    Rule {
        keys: &["outcome"],
        say: |r| match text(r, "outcome")? {
            "completed" => None,
            other => Some(format!(
                "the run ended early: {other}{}",
                text(r, "outcome_reason")
                    .filter(|w| !w.is_empty())
                    .map(|w| format!(" ({w})"))
                    .unwrap_or_default()
            )),
        },
    },
    Rule {
        keys: &["reason"],
        say: |r| text(r, "reason").map(str::to_string),
    },
    Rule {
        keys: &["ratio_point_mass", "ratio_uniform_rod", "m_perp_over_m"],
        say: |r| {
            Some(format!(
                "a vertical kick on the foot comes with a sideways one: J_ℓ/J_v = {} for a point \
                 mass at the top, {} for a uniform rod (lean {}°); the foot's effective mass is \
                 {} m along the rod and {} m across it",
                fmt_num(res(r, "ratio_point_mass")?),
                fmt_num(res(r, "ratio_uniform_rod")?),
                fmt_num(par(r, "angle_deg")?),
                fmt_num(res(r, "m_parallel_over_m").unwrap_or(1.0)),
                fmt_num(res(r, "m_perp_over_m")?)
            ))
        },
    },
    Rule {
        keys: &["drift_velocity_mps", "drift_velocity_averaged_mps"],
        say: |r| {
            let (d, a) = (
                res(r, "drift_velocity_mps")?,
                res(r, "drift_velocity_averaged_mps")?,
            );
            Some(format!(
                "a bias of {} of the sliding friction drifts the block at {} m/s on the shaken \
                 plate (Γₓ = {}); the averaged arcsine law says {} m/s, {} off",
                fmt_num(par(r, "bias")?),
                fmt_num(d),
                fmt_num(res(r, "gamma_x")?),
                fmt_num(a),
                pct_apart(a, d)
            ))
        },
    },
    Rule {
        keys: &["mean_velocity_mps", "mean_velocity_law_mps"],
        say: |r| {
            let (v, law) = (
                res(r, "mean_velocity_mps")?,
                res(r, "mean_velocity_law_mps")?,
            );
            Some(format!(
                "a bias of {} of the sliding friction moves the block at {} m/s (Γ = {}); the \
                 document's law μ_eff = v_ave/v_z predicts {} m/s, {} off{}",
                fmt_num(par(r, "bias")?),
                fmt_num(v),
                fmt_num(par(r, "gamma")?),
                fmt_num(law),
                pct_apart(law, v),
                text(r, "regime_at_gamma")
                    .map(|g| format!("; the bouncing regime is {g}"))
                    .unwrap_or_default()
            ))
        },
    },
    Rule {
        keys: &["drift_velocity_coulomb_mps", "drift_velocity_linear_mps"],
        say: |r| {
            Some(format!(
                "on the sawtooth plate a block with Coulomb friction drifts at {} m/s{}; with \
                 linear friction at {} m/s: asymmetry moves a block only through a nonlinear law",
                fmt_num(res(r, "drift_velocity_coulomb_mps")?),
                text(r, "regime")
                    .map(|g| format!(" ({g})"))
                    .unwrap_or_default(),
                fmt_num(res(r, "drift_velocity_linear_mps")?)
            ))
        },
    },
    Rule {
        keys: &["mean_velocity_mps", "massless_mean_velocity_mps"],
        say: say_inertia,
    },
    Rule {
        keys: &["mean_velocity_mps", "phase_fractions"],
        say: say_walk,
    },
    Rule {
        keys: &["gait_type", "floquet_multipliers_abs"],
        say: |r| {
            let largest = r.results["floquet_multipliers_abs"]
                .as_array()?
                .iter()
                .filter_map(Value::as_f64)
                .fold(0.0, f64::max);
            let stable = match r.results.get("gait_stable").and_then(Value::as_bool) {
                Some(true) => "stable",
                Some(false) => "unstable",
                None => "of unknown stability",
            };
            Some(format!(
                "its gait is a {} limit cycle, {stable} (largest Floquet multiplier {})",
                text(r, "gait_type")?,
                fmt_num(largest)
            ))
        },
    },
    Rule {
        keys: &["stick_rhs_evals_at_1e-10"],
        say: |r| {
            let e = r.results.get("stick_rhs_evals_at_1e-10")?;
            Some(format!(
                "to reach 1e-10 on the stick DOP853 needs {} right-hand-side evaluations, DP5 {}",
                fmt_num(e.get("dop853")?.as_f64()?),
                fmt_num(e.get("dopri5")?.as_f64()?)
            ))
        },
    },
    Rule {
        keys: &["economy"],
        say: |r| {
            let e = r.results.get("economy")?;
            Some(format!(
                "the block's flight map errs {}, the document's μ_eff law {}, at 1/{} of the cost \
                 of a full simulation",
                fmt_pct(e.get("flight_map_error")?.as_f64()?),
                fmt_pct(e.get("mu_eff_law_error")?.as_f64()?),
                fmt_num(e.get("cost_ratio_exact_over_flight_map")?.as_f64()?.round())
            ))
        },
    },
];

/// The stick with a rod of its own mass against the massless model.
fn say_inertia(r: &ChapterReport) -> Option<String> {
    let (v, m) = (
        res(r, "mean_velocity_mps")?,
        res(r, "massless_mean_velocity_mps")?,
    );
    let rod = par(r, "rod_mass_kg")?;
    let mut s = format!(
        "with a {} kg rod under its {} kg tip the stick walks at {} m/s, the massless model at {} \
         m/s ({} apart",
        fmt_num(rod),
        fmt_num(par(r, "tip_mass_kg")?),
        fmt_num(v),
        fmt_num(m),
        pct_apart(v, m)
    );
    if let Some(x) = res(r, "inertia_ratio") {
        s.push_str(&format!(" at I_P k/γ² = {}", fmt_num(x)));
    }
    s.push(')');
    if let Some(t) = res(r, "toothpick_mean_velocity_mps") {
        s.push_str(&format!(
            "; a uniform stick (a toothpick) walks at {} m/s",
            fmt_num(t)
        ));
    }
    if let Some(n) = res(r, "painleve_event_count") {
        s.push_str(&format!("; Painlevé events: {}", fmt_num(n)));
    }
    Some(s)
}

/// The walking stick: its speed, its step and where its time goes.
fn say_walk(r: &ChapterReport) -> Option<String> {
    let v = res(r, "mean_velocity_mps")?;
    let mut parts: Vec<(f64, String)> = r.results["phase_fractions"]
        .as_object()?
        .iter()
        .filter_map(|(k, x)| Some((x.as_f64()?, k.replace('_', " "))))
        .filter(|(x, _)| *x > 0.0)
        .collect();
    parts.sort_by(|a, b| b.0.total_cmp(&a.0));
    let time: Vec<String> = parts
        .iter()
        .map(|(x, k)| format!("{k} {}", fmt_pct(*x)))
        .collect();
    let step = par(r, "frequency_hz")
        .map(|f| format!(", {} mm per drive cycle", fmt_num(1e3 * v / f)))
        .unwrap_or_default();
    Some(format!(
        "the stick walks at {} m/s{step}; of its time: {}",
        fmt_num(v),
        time.join(", ")
    ))
}

/// The answer of a report: one sentence per rule that speaks, in rule order.
pub fn answer(r: &ChapterReport) -> Vec<String> {
    let mut used: Vec<&str> = Vec::new();
    let mut out = Vec::new();
    for rule in RULES {
        let present = rule.keys.iter().all(|k| r.results.contains_key(*k));
        if !present || rule.keys.iter().any(|k| used.contains(k)) {
            continue;
        }
        if let Some(s) = (rule.say)(r) {
            used.extend(rule.keys.iter().copied());
            out.push(s);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn percentages_keep_two_digits() {
        assert_eq!(fmt_pct(0.2675), "27 %");
        assert_eq!(fmt_pct(0.003855), "0.39 %");
        assert_eq!(fmt_pct(0.04763), "4.8 %");
    }

    #[test]
    fn a_block_and_a_stick_read_their_speeds_differently() {
        let mut block = ChapterReport::new("x", "X", "1");
        block.param("bias", 0.1);
        block.param("gamma", 2.0);
        block.result("mean_velocity_mps", 0.01);
        block.result("mean_velocity_law_mps", 0.012);
        let a = answer(&block);
        assert_eq!(a.len(), 1);
        assert!(a[0].contains("μ_eff") && a[0].contains("20 %"), "{a:?}");
        let mut stick = ChapterReport::new("y", "Y", "4");
        stick.param("frequency_hz", 30.0);
        stick.result("mean_velocity_mps", 0.25);
        stick.result(
            "phase_fractions",
            serde_json::json!({"pivot": 0.25, "slide_right": 0.75}),
        );
        let a = answer(&stick);
        assert!(a[0].contains("8.333 mm per drive cycle"), "{a:?}");
        assert!(a[0].contains("slide right 75 %, pivot 25 %"), "{a:?}");
    }
}
