//! Claims on Algorithms 3 and 4 (SLIDE RIGHT, SLIDE LEFT), one per reading: the rules
//! run at every instant (`-continuous`), or when an inequality of the slide is violated
//! (Table 1's caption: the slip stops or the normal force reaches zero).

use super::claims::{rule, Ctx};
use super::doc::Doc;
use super::evidence::state_at;
use crate::physics::stick::{Mode, State, StickModel, StickParams, VXC};
use crate::report::{Check, Claim};
use serde_json::json;

fn frac(a: usize, b: usize) -> f64 {
    if b == 0 {
        0.0
    } else {
        a as f64 / b as f64
    }
}

/// Events of `mode` in the evidence that leave it, with the state before.
fn exits(c: &Ctx, mode: Mode) -> Vec<(StickModel, f64, State, Mode)> {
    let mut v = Vec::new();
    for (run, q) in c.runs() {
        let m = StickModel::new(*q);
        for &(t, from, to) in &run.events {
            if let (true, Some(to)) = (from == mode, to) {
                if let Some(y) = state_at(run, t, mode) {
                    v.push((m, t, y, to));
                }
            }
        }
    }
    v
}

/// The claims of the algorithm of slide `mode`.
pub fn alg34(d: &Doc, c: &Ctx, mode: Mode) -> Vec<Claim> {
    let (key, alg, name, other) = if mode == Mode::SlideRight {
        ("a3", "Alg. 3", "SLIDE RIGHT", Mode::SlideLeft)
    } else {
        ("a4", "Alg. 4", "SLIDE LEFT", Mode::SlideRight)
    };
    let other_name = if other == Mode::SlideLeft {
        "SLIDE LEFT"
    } else {
        "SLIDE RIGHT"
    };
    let sigma = mode.sigma();
    let mut v = Vec::new();
    let hinge_ok = |m: &StickModel, t: f64, y: &State| {
        let f = m.pivot_eval(t, y);
        m.p.mu * f.fz >= f.fx.abs()
    };
    // continuous reading: every slipping sample
    let (mut slipping, mut hinge_slip, mut against) = (0usize, 0usize, 0usize);
    for (run, q) in c.runs() {
        let m = StickModel::new(*q);
        for x in run
            .trace
            .iter()
            .filter(|x| x.mode == mode && x.y[VXC].abs() > 1e-9)
        {
            slipping += 1;
            let fires = hinge_ok(&m, x.t_s, &x.y);
            hinge_slip += usize::from(fires && d.slide_hinge_while_slipping);
            let target = if d.slide_to_other {
                other.sigma()
            } else {
                sigma
            };
            let o = m.slide_eval(target, x.t_s, &x.y);
            // friction power -F_x v_x < 0: the chosen slide's friction pushes along the slip
            against += usize::from(!fires && o.fz > 0.0 && -o.fx * x.y[VXC] < 0.0);
        }
    }
    v.push(rule(&format!("{key}-hinge-continuous"), alg, &format!("Reading: the rules run at every instant of {name}. As printed: if the hinge forces satisfy μ F_z >= |F_x| go to HINGE with x_c' <- 0, while C still slips. Correct: a slide ends when the slip stops (Table 1's v_x guard). Fraction of slipping {name} samples at which the stated test stops C without an impulse."), json!(0.0), json!(frac(hinge_slip, slipping)), "0", slipping > 0 && hinge_slip == 0, slipping > 0, Check::Simulation));
    v.push(rule(&format!("{key}-other-slide-continuous"), alg, &format!("Reading: the rules run at every instant of {name}. As printed: when the hinge test fails go to {other_name} if its F_z > 0. Slipping {name} samples at which the stated rule switches to a slide whose friction would push along the slip (power -F_x v_x < 0)."), json!(0), json!(against), "0", slipping > 0 && against == 0, slipping > 0, Check::Simulation));
    // Table 1's reading: the algorithm runs at the slide's violations (slip stop, F_z = 0)
    // lift-offs of either slide: the two algorithms print the same lines mirrored
    let ex: Vec<_> = exits(c, mode)
        .into_iter()
        .filter(|e| e.3 != Mode::Flight)
        .chain(
            [Mode::SlideLeft, Mode::SlideRight]
                .into_iter()
                .flat_map(|s| exits(c, s))
                .filter(|e| e.3 == Mode::Flight),
        )
        .collect();
    let (mut lift_hinge, mut stops, mut stop_agree, mut lifts, mut lift_abort) =
        (0usize, 0usize, 0usize, 0usize, 0usize);
    for (m, t, y, to) in &ex {
        let slipping = y[VXC].abs() > 1e-9;
        if to == &Mode::Flight {
            lifts += 1;
            lift_hinge +=
                usize::from(slipping && hinge_ok(m, *t, y) && d.slide_hinge_while_slipping);
            let target = if d.slide_to_other { other } else { mode };
            lift_abort += usize::from(
                m.slide_eval(target.sigma(), *t, y).fz <= 1e-9 * m.p.mass_kg * m.p.g_mps2
                    && d.slide_abort,
            );
        } else if !slipping {
            stops += 1;
            let printed = if hinge_ok(m, *t, y) {
                Mode::Pivot
            } else if d.slide_to_other {
                other
            } else {
                mode
            };
            stop_agree += usize::from(printed == *to);
        }
    }
    v.push(rule(&format!("{key}-hinge-while-slipping"), alg, &format!("Reading: Table 1's caption ({name} runs Alg. when an inequality is violated: the slip stops or F_z reaches 0). As printed the hinge test also runs at a lift-off (F_z = 0) while C still slips, and then stops C without an impulse. Lift-offs from either slide (Alg. 3 and 4 print the same lines, mirrored) in both scenes at which the stated test fires while C slips."), json!(0), json!(lift_hinge), "0", lift_hinge == 0, true, Check::Simulation));
    v.push(rule(&format!("{key}-other-slide"), alg, &format!("Reading: Table 1's caption. At a slip stop of {name}: HINGE if the hinge forces are inside the cone, else {other_name} (its F_z > 0). Slip stops of both scenes at which the stated rule picks the mode the contact conditions took."), json!(stops), json!(stop_agree), "exact", stops > 0 && stop_agree == stops, false, Check::Simulation));
    v.push(rule(&format!("{key}-abort"), alg, &format!("As printed ({name}): if the new slide's F_z <= 0, ABORT. Correct: a vanishing normal force is a lift-off (FLIGHT; read as assignments, the later 'F_z = 0 -> FLIGHT' line overrides the ABORT when F_z is exactly 0). Lift-offs from either slide (the same line, mirrored; the simulation continued in flight) at which the stated line aborts."), json!(0), json!(lift_abort), "0", lifts > 0 && lift_abort == 0, lifts > 0, Check::Simulation));
    v.push(flight_fx_claim(d, c, key, alg, name));
    v
}

fn flight_fx_claim(d: &Doc, c: &Ctx, key: &str, alg: &str, name: &str) -> Claim {
    let smp = c
        .runs()
        .into_iter()
        .flat_map(|(s, _)| s.trace.iter())
        .find(|x| matches!(x.mode, Mode::SlideLeft | Mode::SlideRight));
    let (fx0, fz0) = match smp {
        Some(x) => {
            let mut q: StickParams = c.ev.params[0];
            q.mu = 0.0;
            let f = StickModel::new(q).slide_eval(x.mode.sigma(), x.t_s, &x.y);
            (f.fx, f.fz)
        }
        None => (f64::NAN, f64::NAN),
    };
    // F_x = sigma mu F_z is exactly 0 at mu = 0 while F_z > 0: a slide, not a lift-off
    let counter = fx0 == 0.0 && fz0 > 0.0;
    rule(&format!("{key}-flight-test"), alg, &format!("As printed ({name}): if F_z = 0 or F_x = 0 go to FLIGHT. Correct: F_z reaching 0 is a lift-off; F_x = 0 is not: with μ = 0 a slide has F_x = 0 and F_z > 0 throughout. Normal force (N) of a sampled slide state evaluated with μ = 0, where F_x = 0."), json!("F_z > 0"), json!(fz0), "sign", !(d.slide_flight_on_fx && counter), counter, Check::ClosedForm)
}
