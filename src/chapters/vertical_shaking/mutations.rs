//! Falsification: edits of the document's statements, each judged by the same claim
//! functions ([`super::claims`]) on the evidence of the default scene in quick mode,
//! computed once.

use super::claims;
use super::evidence::{gather, Evidence};
use super::scene::Scene;
use super::statements::{Statements, PRINTED};
use crate::report::{Claim, DocEdit, Falsifiable};

/// The chapter's default scene (its flags' defaults, g = 9.81 m/s^2).
fn scene() -> Scene {
    Scene {
        gamma: 2.0,
        frequency_hz: 30.0,
        mu: 0.4,
        bias: 0.1,
        g_mps2: crate::chapters::Context::G_DEFAULT_MPS2,
    }
}

/// The chapter's document for the generic judge (`crate::report::falsify`): the
/// default scene's evidence in quick mode.
pub struct Document;

impl Falsifiable for Document {
    type Statements = Statements;
    type Evidence = Evidence;
    fn printed() -> Statements {
        PRINTED
    }
    fn quick_evidence() -> Evidence {
        gather(&scene(), true)
    }
    fn claims(st: &Statements, ev: &Evidence) -> Vec<Claim> {
        claims::all(st, ev)
    }
    const EDITS: &'static [DocEdit<Statements>] = EDITS;
    const WITHOUT_TEN_PERCENT: &'static [(&'static str, &'static str)] = PRINTS_NO_NUMBER;
}

/// The claims of the chapter that print no number a 10 % change could move, with the
/// reason; their mutations flip the sign, inequality or statement instead.
pub const PRINTS_NO_NUMBER: &[(&str, &str)] = &[
    (
        "contact-fraction-to-zero",
        "a limit (the contact fraction goes to 0), and 0 has no 10 % neighbour: the mutation moves the limit to 0.05",
    ),
    (
        "landing-extinguishes-flight-motion",
        "the printed bound (F < mu m g) is far above b*(Gamma) (below 0.6 over 1 < Gamma < 3.3), so no 10 % change of it moves the verdict; the mutations move the workbook's derived b*",
    ),
    (
        "period-doubling-multiplier",
        "the period doublings are the workbook's derivation: the document prints none (the mutations move the derived values)",
    ),
    (
        "flight-period-boundaries",
        "Gamma_n = sqrt(1 + (n pi)^2) is the workbook's derivation: the document prints no boundary (the mutations move the derived factor)",
    ),
];

/// The falsification mutations (a data table): every document claim gets a 10 %
/// change of a number its statement prints ("x -> 1.1 x"; thresholds both ways), and
/// a sign or an inequality reversed where it states one. The claims that print no
/// number are listed in [`PRINTS_NO_NUMBER`].
const EDITS: &[DocEdit<Statements>] = &[
    (
        "landing-extinguishes-flight-motion",
        "derived b* -> 1.1 b*",
        |d| d.landing_closed_form_factor = 1.1,
    ),
    (
        "landing-extinguishes-flight-motion",
        "derived b* -> 0.9 b*",
        |d| d.landing_closed_form_factor = 0.9,
    ),
    (
        "contact-fraction-to-zero",
        "fraction -> 0 replaced by -> 0.05",
        |d| d.contact_limit = 0.05,
    ),
    (
        "viscous-constant-to-zero",
        "c -> 0 replaced by c independent of omega",
        |d| d.c_exponent = 0.0,
    ),
    (
        "viscous-constant-to-zero",
        "c ~ 1/omega -> 1/omega^2",
        |d| d.c_exponent = 2.0,
    ),
    (
        "viscous-constant-to-zero",
        "c ~ 1/omega -> 1/omega^1.1 (10 % on the exponent)",
        |d| d.c_exponent = 1.1,
    ),
    (
        "viscous-constant-to-zero",
        "c ~ 1/omega -> 1/omega^0.9 (10 % on the exponent)",
        |d| d.c_exponent = 0.9,
    ),
    (
        "small-force-moves-block",
        "moves once delta omega^2 > g -> > 0.9 g (10 %)",
        |d| d.flight_gamma_small_force = 0.9,
    ),
    (
        "small-force-moves-block",
        "moves once delta omega^2 > g -> > 1.1 g (10 %)",
        |d| d.flight_gamma_small_force = 1.1,
    ),
    (
        "flight-time-2vz-over-g",
        "t_f = 2 v_z/g -> 2.2 v_z/g (10 %)",
        |d| d.flight_coeff = 2.2,
    ),
    (
        "flight-time-2vz-over-g",
        "t_f = 2 v_z/g -> 1.8 v_z/g (10 %)",
        |d| d.flight_coeff = 1.8,
    ),
    (
        "bias-law-mu-eff",
        "mu_eff = v_ave/v_z -> 1.1 v_ave/v_z (10 %)",
        |d| d.law_coeff = 1.1,
    ),
    (
        "bias-law-mu-eff",
        "mu_eff = v_ave/v_z -> 0.9 v_ave/v_z (10 %)",
        |d| d.law_coeff = 0.9,
    ),
    (
        "period-doubling-multiplier",
        "derived period doublings at 1.1 x the located Gamma",
        |d| d.pd_scale = 1.1,
    ),
    (
        "period-doubling-multiplier",
        "derived period doublings at 0.9 x the located Gamma",
        |d| d.pd_scale = 0.9,
    ),
    (
        "flight-period-boundaries",
        "derived Gamma_n = sqrt(1 + (n pi)^2) -> sqrt(1 + (1.1 n pi)^2)",
        |d| d.gamma_n_factor = 1.1,
    ),
    (
        "flight-period-boundaries",
        "derived Gamma_n = sqrt(1 + (n pi)^2) -> sqrt(1 + (0.9 n pi)^2)",
        |d| d.gamma_n_factor = 0.9,
    ),
];
