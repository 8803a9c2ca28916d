//! The lab's request: a JSON object of parameters, turned into the flags of
//! `workbook stick-state-machine` (the registered chapter whose flag table is the main
//! run's, [`crate::flags::main_run`]) and validated by the CLI's own clap definitions
//! and range checks ([`RunFlags::setup`]), so that a value the
//! CLI refuses is refused here with the CLI's own one-line reason. Anything else wrong
//! with a request (malformed JSON, a missing or unknown field, a value of the wrong
//! type, a body too large) is an [`ApiError`] with HTTP status 400 or 413 and one line
//! saying why; nothing here panics on any input.

use super::http::clip;
use crate::chapters::{ChapterInfo, CHAPTERS};
use crate::flags::main_run::{RunFlags, FLAGS};
use crate::flags::stick::ROD_MASS_KG;
use crate::flags::Flag;
use crate::grammar::{Cli, Command};
use crate::numerics::hybrid::Options;
use crate::physics::stick::StickParams;
use crate::scenes::stick::main_run::{self, Settings};
use clap::FromArgMatches;
use serde_json::Value;

/// Largest request body accepted (bytes): a full parameter set is about 300 bytes.
pub const MAX_BODY_BYTES: usize = 16 * 1024;

/// Longest text accepted for one field (characters): enough for any number or name.
const MAX_FIELD_CHARS: usize = 64;

/// Most drive cycles `f t` one lab run may simulate: the lab animates every run, and
/// keeps its trajectory in memory (one sample per integration step, about 16 a cycle at
/// the default rtol and some 350 with DOPRI5 at 1e-14, 112 bytes each) while it thins it
/// to frames: at most about 40 MB a run. 1000 cycles are 33 s at 30 Hz, a fraction of a
/// second of work at the default rtol. Longer runs: the CLI.
pub const MAX_CYCLES: f64 = 1000.0;

/// The chapter the lab is a browser for: the registered chapter whose flag table is the
/// stick's main run's ([`FLAGS`]), found in the registry (the lab names no chapter).
pub fn chapter() -> Result<&'static ChapterInfo, ApiError> {
    CHAPTERS
        .iter()
        .find(|c| c.flags == FLAGS)
        .ok_or_else(|| internal("no registered chapter runs the stick's main run"))
}

/// One field of a request: its JSON key, the CLI flag it becomes, and whether it is
/// required.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Field {
    /// The JSON key: the flag's name without `--`, `_` for `-` (`theta0_rad`).
    pub key: String,
    /// The flag as typed (`--theta0-rad`).
    pub flag: String,
}

/// The request's fields, from the chapter's own flags (its subcommand, clap's view of
/// [`RunFlags`]): every flag that takes a value except files, and `--g-mps2`.
/// [`required`] says which a request must carry.
pub fn fields() -> Vec<Field> {
    let Ok(c) = chapter() else {
        return Vec::new();
    };
    let cmd = c.subcommand();
    let mut out: Vec<Field> = cmd
        .get_arguments()
        .filter(|a| a.get_action().takes_values())
        .filter(|a| a.get_value_hint() != clap::ValueHint::FilePath)
        .filter_map(|a| a.get_long())
        .map(|l| Field {
            key: l.replace('-', "_"),
            flag: format!("--{l}"),
        })
        .collect();
    out.push(Field {
        key: "g_mps2".into(),
        flag: "--g-mps2".into(),
    });
    out
}

/// Whether a request must carry `field`: the scene and every physical flag the page shows
/// as a control (the table's entries with a lab control), so that a page never runs on
/// a value it did not show; the run's options may be left to the CLI's defaults.
pub fn required(field: &Field) -> bool {
    field.flag == "--scene"
        || crate::flags::find(FLAGS, &field.flag)
            .is_some_and(|f| f.control.is_some_and(|c| c.required))
}

/// The lab's own field: a sequence number chosen by the page, echoed in the answer so
/// that the page can drop the answer to a request it has since superseded.
pub const SEQ_FIELD: &str = "seq";

/// The lab's field for chapter 8's rod: its mass (kg), optional (absent or 0: chapter
/// 6's massless rod). Not a flag of `workbook stick-state-machine`: the lab checks it
/// against chapter 8's entry [`ROD_MASS_KG`] (shared in the flag table) and runs the
/// rod with the physics layer ([`crate::physics::stick_inertia`]).
pub const ROD_MASS_FIELD: &str = "rod_mass_kg";

/// Why the lab runs no rod lighter than [`ROD_MASS_MIN_KG`] but 0 (see there).
const WHY_ROD_MIN: &str = "0, or 1e-4 to 10 (kg) in the lab: lighter rods lose digits in their impacts and chapter 8's CLI (workbook stick-with-inertia) runs them as a composite, with no trajectory to animate";

pub use crate::flags::stick::ROD_MASS_MIN_KG;

/// A refused request: the HTTP status and one line saying why.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ApiError {
    /// HTTP status (400 bad request, 413 too large, 503 busy or too slow, 500 a defect).
    pub status: u16,
    /// One line: the CLI's own reason where the CLI would refuse the same value.
    pub reason: String,
}

impl ApiError {
    /// A 400 with `reason`, which starts `error: ` as the CLI's lines do.
    pub fn bad(reason: impl Into<String>) -> Self {
        let reason: String = reason.into();
        ApiError {
            status: 400,
            reason: if reason.starts_with("error: ") {
                reason
            } else {
                format!("error: {reason}")
            },
        }
    }
}

/// A validated run request.
#[derive(Debug, Clone)]
pub struct RunRequest {
    /// The chapter whose flags the request became.
    pub chapter: &'static ChapterInfo,
    /// The main run's settings as the CLI parsed them.
    pub settings: Settings,
    /// The validated parameters.
    pub params: StickParams,
    /// The validated simulated time (s).
    pub duration_s: f64,
    /// The integrator's options.
    pub opts: Options,
    /// The page's sequence number, if any.
    pub seq: Option<u64>,
    /// Mass of chapter 8's rod (kg): 0 for chapter 6's massless rod ([`ROD_MASS_FIELD`]).
    pub rod_mass_kg: f64,
    /// The argument vector the request became (for messages and tests).
    pub argv: Vec<String>,
}

/// The flags of a request body: `["workbook", "stick-state-machine", "--mu=0.4", ...]`,
/// and the sequence number. Each value goes in as `--flag=value`, so that no value can be
/// read as another flag.
pub fn to_argv(body: &[u8]) -> Result<(Vec<String>, Option<u64>), ApiError> {
    let v: Value =
        serde_json::from_slice(body).map_err(|e| ApiError::bad(format!("malformed JSON: {e}")))?;
    let Value::Object(obj) = v else {
        return Err(ApiError::bad(
            "the body must be a JSON object of parameters, as {\"mu\": 0.4, ...}",
        ));
    };
    let mut seq = None;
    let mut argv = vec!["workbook".to_string(), chapter()?.id.to_string()];
    let fields = fields();
    for (key, value) in &obj {
        if key == ROD_MASS_FIELD {
            continue; // the lab's own field, read by `rod_mass`
        }
        if key == SEQ_FIELD {
            seq = Some(value.as_u64().ok_or_else(|| {
                ApiError::bad(format!("field `seq`: {value} is not a whole number >= 0"))
            })?);
            continue;
        }
        let Some(Field { flag, .. }) = fields.iter().find(|f| f.key == *key) else {
            let known: Vec<&str> = fields.iter().map(|f| f.key.as_str()).collect();
            return Err(ApiError::bad(format!(
                "unknown field `{}`: the fields are {}, seq, rod_mass_kg",
                clip(key),
                known.join(", ")
            )));
        };
        argv.push(format!("{flag}={}", field_text(key, value)?));
    }
    if let Some(Field { key, flag }) = fields
        .iter()
        .find(|f| required(f) && !obj.contains_key(&f.key))
    {
        return Err(ApiError::bad(format!(
            "missing field `{key}` (the flag {flag} of workbook {})",
            chapter()?.id
        )));
    }
    Ok((argv, seq))
}

/// A field's value as the text of its flag: a JSON number as written, or a string (a
/// scene's or method's name, or a number typed into a field, which the CLI then parses).
fn field_text(key: &str, value: &Value) -> Result<String, ApiError> {
    let text = match value {
        Value::Number(n) => n.to_string(),
        Value::String(s) => s.trim().to_string(),
        other => {
            return Err(ApiError::bad(format!(
                "field `{key}`: {} is not a number or a name",
                clip(&other.to_string())
            )))
        }
    };
    if text.chars().count() > MAX_FIELD_CHARS || text.chars().any(char::is_control) {
        return Err(ApiError::bad(format!(
            "field `{key}`: \"{}\" is not a number or a name (at most {MAX_FIELD_CHARS} printable characters)",
            clip(&text)
        )));
    }
    Ok(text)
}

/// The one line the CLI prints for a clap error: the same text as `workbook` on stderr.
pub fn clap_line(e: &clap::Error) -> String {
    crate::grammar::clap_error_line(e)
}

/// Parses and validates a request body: the CLI's parser, the chapter's `setup` (its
/// ranges), the CLI's work budget, and the lab's own bound on drive cycles.
pub fn parse_run(body: &[u8]) -> Result<RunRequest, ApiError> {
    if body.len() > MAX_BODY_BYTES {
        return Err(too_large(body.len()));
    }
    let (argv, seq) = to_argv(body)?;
    let matches = crate::grammar::command()
        .try_get_matches_from(&argv)
        .map_err(|e| ApiError::bad(clap_line(&e)))?;
    let cli = Cli::from_arg_matches(&matches).map_err(|e| ApiError::bad(clap_line(&e)))?;
    let chapter = chapter()?;
    let flags = match &cli.command {
        Command::Chapter(c) if c.chapter == chapter => {
            RunFlags::from_arg_matches(&c.matches).map_err(|e| ApiError::bad(clap_line(&e)))?
        }
        _ => return Err(internal("the request did not parse as the stick's chapter")),
    };
    let ctx = cli.context().map_err(|e| ApiError::bad(e.to_string()))?;
    let (params, duration_s, opts) = flags
        .setup(ctx.g_mps2, ctx.quick)
        .map_err(|e| ApiError::bad(e.to_string()))?;
    main_run::check_work(&params, duration_s, false).map_err(|e| ApiError::bad(e.to_string()))?;
    let cycles = duration_s * params.frequency_hz(); // formula: drive cycles f t
    if cycles > MAX_CYCLES {
        return Err(ApiError::bad(format!(
            "error: invalid value {} for --duration-s: the lab runs at most {MAX_CYCLES} drive cycles f t (here {} Hz x {} s = {} cycles); longer runs: workbook {}",
            crate::error::num(duration_s),
            crate::error::num(params.frequency_hz()),
            crate::error::num(duration_s),
            crate::error::num(cycles.round()),
            chapter.id
        )));
    }
    let rod_mass_kg = rod_mass(body, &params)?;
    Ok(RunRequest {
        chapter,
        settings: flags.settings(),
        params,
        duration_s,
        opts,
        seq,
        argv,
        rod_mass_kg,
    })
}

/// The rod's mass of a request body (kg; 0 when absent), checked against
/// [`ROD_MASS_KG`] with the CLI's form of line, and the lab's lower end above 0.
pub fn rod_mass(body: &[u8], p: &StickParams) -> Result<f64, ApiError> {
    let v: Value =
        serde_json::from_slice(body).map_err(|e| ApiError::bad(format!("malformed JSON: {e}")))?;
    let Some(value) = v.get(ROD_MASS_FIELD) else {
        return Ok(0.0);
    };
    let text = field_text(ROD_MASS_FIELD, value)?;
    let m_r: f64 = text.parse().map_err(|_| {
        ApiError::bad(format!(
            "error: invalid value '{}' for '{} <ROD_MASS_KG>': invalid float literal",
            clip(&text),
            ROD_MASS_KG.name
        ))
    })?;
    let m_r = ROD_MASS_KG
        .check(m_r)
        .map_err(|e| ApiError::bad(e.to_string()))?;
    if m_r > 0.0 && m_r < ROD_MASS_MIN_KG {
        return Err(ApiError::bad(
            crate::error::WorkbookError::bad_input(
                ROD_MASS_KG.name,
                crate::error::num(m_r),
                WHY_ROD_MIN,
            )
            .to_string(),
        ));
    }
    let _ = p; // the tip mass is at least 0.1 kg (chapter 6's range): m + m_r > 0 holds
    Ok(m_r)
}

/// The 413 answer to a body of `n` bytes.
pub fn too_large(n: usize) -> ApiError {
    ApiError {
        status: 413,
        reason: format!(
            "error: the request body has {n} bytes, more than the lab's limit of {MAX_BODY_BYTES}"
        ),
    }
}

/// A 500: a defect of the lab (never a user's input).
pub fn internal(why: &str) -> ApiError {
    ApiError {
        status: 500,
        reason: format!("error: internal error of the lab: {why}"),
    }
}

/// The scenes' values as request fields (`{"jamming": {...}, "authors": {...}}`): the
/// page's presets, taken from the scenes themselves ([`crate::scenes::stick::Scene`]);
/// with the page's controls ([`controls`]), the choices of its menus and the modes'
/// colours.
pub fn scenes() -> Value {
    use crate::scenes::stick::Scene;
    use crate::scenes::{round, Choice};
    let one = |scene: Scene| {
        let p = scene.params(None);
        serde_json::json!({
            "scene": scene.name(),
            "theta0_rad": round(p.theta0_rad, 10),
            "mu": p.mu,
            "gamma": round(p.gamma_accel(), 12),
            "frequency_hz": round(p.frequency_hz(), 12),
            "stiffness": p.stiffness_nm_per_rad,
            "damping": p.damping_nms_per_rad,
            "length_m": p.length_m,
            "mass_kg": p.mass_kg,
            "g_mps2": p.g_mps2,
        })
    };
    let mut o = serde_json::Map::new();
    for &s in Scene::ALL {
        o.insert(s.name().to_string(), one(s));
    }
    o.insert("controls".into(), controls());
    o.insert("choices".into(), choices());
    o.insert("mode_colours".into(), mode_colours());
    Value::Object(o)
}

/// The choices of the page's menus, by field: each value's name and description.
pub fn choices() -> Value {
    use crate::scenes::stick::{ContactMethod, Scene};
    use crate::scenes::Choice;
    fn list<T: Choice>() -> Value {
        T::ALL
            .iter()
            .map(|c| serde_json::json!({"name": c.name(), "about": c.about()}))
            .collect()
    }
    serde_json::json!({ "scene": list::<Scene>(), "method": list::<ContactMethod>() })
}

/// The modes' colours of the book's figures and GIFs (the scenes' `MODE_COLOUR`, the
/// Okabe-Ito palette of [`crate::plot::PALETTE`]), by mode letter and name: the one
/// palette of the book and the lab.
pub fn mode_colours() -> Value {
    use crate::physics::stick::Mode;
    let mut o = serde_json::Map::new();
    for m in Mode::ALL {
        let c = crate::plot::color(crate::scenes::stick::MODE_COLOUR[m.index()]);
        o.insert(
            m.letter().to_string(),
            serde_json::json!({
                "name": m.name(),
                "hex": format!("#{:02x}{:02x}{:02x}", c.0, c.1, c.2),
            }),
        );
    }
    Value::Object(o)
}

/// One control as the page reads it: its field, flag, symbol, unit, label, scale and
/// ends (the flag's range, or the lab's own), the range as text with its reason, and
/// its default where the table holds one.
fn control_json(f: &Flag, c: &crate::flags::Control) -> Value {
    use crate::flags::{DefaultValue, Scale};
    let r = f.range;
    let (min, max, own) = match c.ends {
        Some((lo, hi)) => (lo, hi, true),
        None => (r.lo, r.hi, false),
    };
    let (kind, step, lo, values): (&str, Option<f64>, Option<f64>, &[f64]) = match c.scale {
        Scale::Linear(step) => ("linear", Some(step), None, &[]),
        Scale::Log(lo) => ("log", None, lo, &[]),
        Scale::Menu(v) => ("menu", None, None, v),
    };
    let key = f.name.trim_start_matches("--").replace('-', "_");
    serde_json::json!({
        "key": key, "flag": f.name, "name": c.symbol, "help": c.label,
        "unit": if f.unit == "1" { "" } else { f.unit },
        "scale": kind, "step": step, "lo": lo, "zero": lo.is_some(), "values": values,
        "min": min, "max": max, "min_open": r.lo_open && !own, "max_open": r.hi_open && !own,
        "own": own, "required": c.required, "rod": key == ROD_MASS_FIELD,
        "range": f.range_text(), "reason": f.reason,
        "default": match f.default { DefaultValue::Value(v) => Some(v), _ => None },
    })
}

/// The page's controls, in its order: the flag table's lab entries
/// ([`crate::flags::main_run::LAB`]), each with its control ([`crate::flags::Control`]).
pub fn controls() -> Value {
    crate::flags::main_run::LAB
        .iter()
        .filter_map(|f| f.control.map(|c| control_json(f, &c)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn body(rod: &str) -> Vec<u8> {
        format!(
            r#"{{"scene": "jamming", "theta0_rad": 0.3, "mu": 0.4, "gamma": 3, "frequency_hz": 30,
            "stiffness": 10, "damping": 0.01, "length_m": 0.15, "mass_kg": 1, "duration_s": 2{rod}}}"#
        )
        .into_bytes()
    }

    /// Chapter 8's CLI line for `--rod-mass-kg value` (in-process).
    fn chapter8_line(value: &str) -> String {
        let argv: Vec<String> = ["workbook", "stick-with-inertia", "--rod-mass-kg", value]
            .map(String::from)
            .to_vec();
        let (mut out, mut err) = (Vec::new(), Vec::new());
        let code = crate::cli::run_cli(&argv, &mut out, &mut err);
        assert_eq!(code, 2, "{value}");
        String::from_utf8(err)
            .expect("utf-8")
            .trim_end()
            .to_string()
    }

    #[test]
    fn the_rods_mass_is_checked_as_chapter_8_checks_it() {
        assert_eq!(parse_run(&body("")).expect("no rod").rod_mass_kg, 0.0);
        let r = parse_run(&body(r#", "rod_mass_kg": 0.5"#)).expect("a rod");
        assert_eq!(r.rod_mass_kg, 0.5);
        for v in ["11", "-1"] {
            let e = parse_run(&body(&format!(r#", "rod_mass_kg": {v}"#))).expect_err(v);
            assert_eq!(e.status, 400);
            assert_eq!(e.reason, chapter8_line(v), "the lab's line is chapter 8's");
        }
        // the lab's own end: no composite to animate below 1e-4 kg
        let e = parse_run(&body(r#", "rod_mass_kg": 1e-5"#)).expect_err("too light");
        assert!(
            e.reason
                .starts_with("error: invalid value 1e-5 for --rod-mass-kg"),
            "{}",
            e.reason
        );
        assert!(e.reason.contains("composite"), "{}", e.reason);
        let e = parse_run(&body(r#", "rod_mass_kg": "abc""#)).expect_err("not a number");
        assert!(
            e.reason.contains("--rod-mass-kg") && !e.reason.contains('\n'),
            "{}",
            e.reason
        );
        let rod = controls()
            .as_array()
            .expect("controls")
            .iter()
            .find(|c| c["key"] == "rod_mass_kg")
            .cloned()
            .expect("the rod's control");
        assert_eq!(
            (rod["max"].as_f64(), rod["lo"].as_f64()),
            (Some(10.0), Some(ROD_MASS_MIN_KG))
        );
    }
}
