//! Every solution of the one-contact frictional problem, not only the first.
//!
//! [`super::solve_contact`] returns the first case that holds in the order open, stick,
//! slide towards +t, slide towards -t. When `W` couples the normal and tangential
//! directions strongly (`mu |W_nt| > W_nn` for one slip direction: the slide's normal
//! "effective mass" `W_nn - sigma mu W_nt` is negative) a positive normal impulse can
//! *pull* the contact together, so a separating free velocity admits a sliding solution
//! beside the open one: the discrete form of Painleve's non-uniqueness. This module
//! lists all cases that hold, so a model can say where that happens.

use super::{ContactStatus, Impulse};

/// The cases of the problem `u = u_free + W P`, `0 <= u_n + s0 _|_ P_n >= 0`, Coulomb on
/// `(u_t, P_t)`, that hold, in the order open, stick, slide +t, slide -t (`None`: the
/// case does not hold). Unlike [`super::solve_contact`] a slide with a negative
/// effective normal mass `W_nn - sigma mu W_nt` is admitted (its impulse is then
/// positive only for a separating free velocity).
pub fn contact_solutions(
    w: [[f64; 2]; 2],
    u_free: [f64; 2],
    s0: f64,
    mu: f64,
) -> [Option<Impulse>; 4] {
    let s = u_free[0] + s0;
    let ut = u_free[1];
    let (wnn, wnt, wtt) = (w[0][0], w[0][1], w[1][1]);
    let mut out = [None; 4];
    if s >= 0.0 {
        out[0] = Some(Impulse {
            status: ContactStatus::Open,
            p_n: 0.0,
            p_t: 0.0,
        });
    }
    // Slack of the inequalities: round-off of the 2 x 2 solves relative to the terms.
    let eps = 1e-12;
    let det = wnn * wtt - wnt * wnt; // formula: det W
    if det > eps * (wnn * wtt).abs() {
        let p_n = (-s * wtt + ut * wnt) / det; // formula: Cramer's rule on W P = -(s, u_t)
        let p_t = (-ut * wnn + s * wnt) / det;
        if p_n > 0.0 && p_t.abs() <= mu * p_n * (1.0 + eps) {
            out[1] = Some(Impulse {
                status: ContactStatus::Stick,
                p_n,
                p_t,
            });
        }
    }
    for (k, sigma, status) in [
        (2, 1.0, ContactStatus::SlidePositive),
        (3, -1.0, ContactStatus::SlideNegative),
    ] {
        let denom = wnn - sigma * mu * wnt; // formula: effective normal mass W_nn - sigma mu W_nt
        if denom == 0.0 {
            continue;
        }
        let p_n = -s / denom; // formula: u_n = s + (W_nn - sigma mu W_nt) P_n = 0
        let p_t = -sigma * mu * p_n;
        let ut1 = ut + wnt * p_n + wtt * p_t; // formula: u_t,{k+1} = u_t,free + W_tn P_n + W_tt P_t
        if p_n > 0.0 && sigma * ut1 >= -eps * (ut.abs() + (wtt * p_t).abs()) {
            out[k] = Some(Impulse { status, p_n, p_t });
        }
    }
    out
}

/// How many distinct solutions [`contact_solutions`] found (impulses further apart than
/// `1e-9` relative count as distinct: a slide on the edge of the cone with zero final
/// slip is the stick solution, not a second one).
pub fn distinct_solutions(sols: &[Option<Impulse>; 4]) -> usize {
    let found: Vec<&Impulse> = sols.iter().flatten().collect();
    let mut n = 0;
    for (i, a) in found.iter().enumerate() {
        let same = found[..i].iter().any(|b| {
            let scale = a.p_n.abs().max(b.p_n.abs()).max(1e-300);
            (a.p_n - b.p_n).abs() <= 1e-9 * scale && (a.p_t - b.p_t).abs() <= 1e-9 * scale
        });
        if !same {
            n += 1;
        }
    }
    n
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::timestepping::solve_contact;

    #[test]
    fn an_uncoupled_problem_has_exactly_one_solution() {
        // W = identity (a point mass): no coupling, so the cases are exclusive.
        let w = [[1.0, 0.0], [0.0, 1.0]];
        for u in [[0.5, 3.0], [-1.0, 0.2], [-1.0, 2.0], [-1.0, -2.0]] {
            let sols = contact_solutions(w, u, 0.0, 0.3);
            assert_eq!(distinct_solutions(&sols), 1, "{u:?}: {sols:?}");
            let first = sols.iter().flatten().next().unwrap();
            assert_eq!(Some(*first), solve_contact(w, u, 0.0, 0.3));
        }
    }

    #[test]
    fn a_negative_effective_normal_mass_gives_more_solutions() {
        // W_nn = 1, W_nt = 2, W_tt = 5 (positive definite, det 1): with mu = 1 the slide
        // towards +t has effective normal mass 1 - 2 = -1 < 0. A separating free velocity
        // u = (0.5, 1): open holds; the slide needs P_n = 0.5, P_t = -0.5, and leaves
        // u_t = 1 + 2 (0.5) + 5 (-0.5) = -0.5 < 0: not a slide towards +t. With u_t = 3:
        // u_t,1 = 3 + 1 - 2.5 = 1.5 >= 0, so both open and the slide hold; and so does
        // the stick, W P = -(0.5, 3): P = (3.5, -2) by Cramer's rule, |P_t| <= mu P_n.
        let w = [[1.0, 2.0], [2.0, 5.0]];
        let sols = contact_solutions(w, [0.5, 3.0], 0.0, 1.0);
        assert_eq!(distinct_solutions(&sols), 3, "{sols:?}");
        let stick = sols[1].unwrap();
        assert!((stick.p_n - 3.5).abs() < 1e-14 && (stick.p_t + 2.0).abs() < 1e-14);
        let slide = sols[2].unwrap();
        assert!((slide.p_n - 0.5).abs() < 1e-15 && (slide.p_t + 0.5).abs() < 1e-15);
        assert_eq!(
            solve_contact(w, [0.5, 3.0], 0.0, 1.0).unwrap().status,
            ContactStatus::Open,
            "the scheme picks the open case"
        );
        // The same with a weak coupling (mu W_nt < W_nn): one solution only.
        let sols = contact_solutions(w, [0.5, 3.0], 0.0, 0.4);
        assert_eq!(distinct_solutions(&sols), 1, "{sols:?}");
    }
}
