//! Impacts at C with friction and restitution, by integration in the normal impulse
//! (Darboux-Keller), exact for the planar rod.
//!
//! An impulse `P = (P_t, P_n)` at C changes C's velocity by `W P`, with the mobility
//! (Delassus matrix) `W = (Id + alpha e_theta e_theta^T)/M` (see [`super::contact`]).
//! During the impact the normal impulse `p` grows and the relative velocity of C,
//! `u = (u_t, u_n)` (in the plate's frame), follows `du/dp = W (dP_t/dp, 1)` with
//! `dP_t/dp = -sign(u_t) mu` while C slips, and the `r = -W_tn/W_tt` that keeps
//! `u_t = 0` while it sticks (if `|r| <= mu`; otherwise the slip restarts in the
//! direction of `sign(W_tn)`). Each regime has a constant slope, so `u(p)` is piecewise
//! linear and every switch (slip stops, compression ends) is found exactly.
//! Compression ends when `u_n` returns to 0; restitution (Stronge's energetic
//! coefficient `e`) continues until the normal impulse has given back `e^2` of the work
//! it absorbed in compression. With `e <= 1` the loss `-int u . dP` is never negative.

/// The result of one impact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpulseResult {
    /// Tangential impulse (N s).
    pub p_t: f64,
    /// Normal impulse (N s).
    pub p_n: f64,
    /// Relative velocity of C after `(u_t, u_n)` (m/s).
    pub u_after: [f64; 2],
    /// Energy lost, `-int u . dP` (J).
    pub loss_j: f64,
}

/// Why an impact has no finite solution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unbounded;

/// The impact of a contact with mobility `w = [[W_tt, W_tn], [W_tn, W_nn]]` (1/kg),
/// friction `mu`, restitution `e` (0 to 1), from the relative velocity `u0` (m/s).
/// `u0[1] < 0` (approach) for a collision; `u0[1] = 0` with a normal slope that drives C
/// into the plate for an impact without collision.
///
/// `iwc`: an impact without collision, started on the Painleve boundary or beyond it:
/// its first, slipping, piece runs until the slip stops even when its normal slope is
/// zero to rounding (the limit from the inconsistent side, where the slope is negative).
pub fn darboux_keller(
    w: [[f64; 2]; 2],
    mu: f64,
    e: f64,
    u0: [f64; 2],
    iwc: bool,
) -> Result<ImpulseResult, Unbounded> {
    let (wtt, wtn, wnn) = (w[0][0], w[0][1], w[1][1]);
    let [mut ut, mut un] = u0;
    let (mut pt, mut pn, mut loss) = (0.0, 0.0, 0.0);
    // work absorbed in compression, to give back in restitution, given back (J)
    let (mut work_c, mut target, mut given, mut restituting) = (0.0, 0.0, 0.0, false);
    let vscale = u0[0].abs().max(u0[1].abs()).max(1e-300);
    for _ in 0..16 {
        // The regime's slope: tangential impulse rate r = dP_t/dp and du/dp.
        let slipping = ut.abs() > 1e-14 * vscale;
        let (r, sticks) = tangential_rate(slipping, ut, wtt, wtn, mu);
        ut = if sticks { 0.0 } else { ut };
        let kt = wtt * r + wtn; // formula: du_t/dp = W_tt r + W_tn
        let kn = wtn * r + wnn; // formula: du_n/dp = W_nt r + W_nn
                                // Compression is over once C no longer approaches and the regime would not drive
                                // it into the plate (at the start of an impact without collision the normal
                                // velocity is zero and the slope negative: compression lies ahead).
        let first_iwc_slip = iwc && slipping && pn == 0.0;
        if !restituting && un >= 0.0 && kn >= 0.0 && !first_iwc_slip {
            restituting = true;
            target = e * e * work_c;
        }
        let mut dp = f64::INFINITY;
        if slipping && kt * ut < 0.0 {
            dp = dp.min(-ut / kt); // slip stops
        }
        if !restituting {
            if kn > 0.0 && un < 0.0 && !first_iwc_slip {
                dp = dp.min(-un / kn); // compression ends
            }
        } else {
            let rem = target - given;
            if rem <= 0.0 {
                break;
            }
            let d = restitution_step(un, kn, rem);
            if d > 0.0 {
                dp = dp.min(d);
            }
        }
        if !dp.is_finite() {
            return Err(Unbounded);
        }
        // Advance: exact on the linear piece.
        let wn = un * dp + 0.5 * kn * dp * dp; // formula: int u_n dp
        let wt = ut * r * dp + 0.5 * kt * r * dp * dp; // formula: int u_t dP_t
        loss -= wn + wt;
        if restituting {
            given += wn;
        } else {
            work_c -= wn;
        }
        pt += r * dp;
        pn += dp;
        ut += kt * dp;
        un += kn * dp;
        if slipping && (ut * (ut - kt * dp) <= 0.0) {
            ut = 0.0; // the slip stopped exactly here
        }
        if !restituting && un >= -1e-15 * vscale && kn > 0.0 {
            un = 0.0;
        }
        if restituting && given >= target * (1.0 - 1e-14) {
            break;
        }
    }
    Ok(ImpulseResult {
        p_t: pt,
        p_n: pn,
        u_after: [ut, un],
        loss_j: loss,
    })
}

/// The regime's tangential impulse rate `r = dP_t/dp`, and whether C sticks: slipping,
/// `-sign(u_t) mu`; at rest, the `r = -W_tn/W_tt` that keeps `u_t = 0` if inside the cone,
/// otherwise the cone's edge along which the slip restarts.
fn tangential_rate(slipping: bool, ut: f64, wtt: f64, wtn: f64, mu: f64) -> (f64, bool) {
    if slipping {
        return (-ut.signum() * mu, false);
    }
    let r_stick = -wtn / wtt; // formula: du_t/dp = W_tt r + W_tn = 0
    if r_stick.abs() <= mu {
        (r_stick, true)
    } else {
        (-wtn.signum() * mu, false) // formula: the slip restarts along sign(W_tn)
    }
}

/// The normal impulse `dp` over which restitution gives back the work `rem` (J) on a
/// linear piece `u_n(p) = un + kn p` (infinite if it never does).
fn restitution_step(un: f64, kn: f64, rem: f64) -> f64 {
    // formula: int u_n dp over the step = un dp + kn dp^2/2 = rem
    if kn.abs() < 1e-300 {
        rem / un.max(1e-300)
    } else {
        let disc = un * un + 2.0 * kn * rem;
        if disc < 0.0 {
            f64::INFINITY
        } else {
            (-un + disc.sqrt()) / kn
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Mobility of a rod of mass 1 with `alpha` at angle `theta`.
    fn w(alpha: f64, theta: f64) -> [[f64; 2]; 2] {
        let (s, c) = theta.sin_cos();
        [
            [1.0 + alpha * c * c, -alpha * s * c],
            [-alpha * s * c, 1.0 + alpha * s * s],
        ]
    }

    #[test]
    fn frictionless_plastic_impact_stops_normal_velocity_only() {
        let r = darboux_keller(w(3.0, 0.4), 0.0, 0.0, [0.3, -1.0], false).unwrap();
        assert!(r.p_t == 0.0 && r.u_after[1].abs() < 1e-14, "{r:?}");
        assert!(r.loss_j > 0.0);
    }

    #[test]
    fn elastic_frictionless_impact_reverses_normal_velocity_and_keeps_energy() {
        let r = darboux_keller(w(3.0, 0.4), 0.0, 1.0, [0.3, -1.0], false).unwrap();
        assert!((r.u_after[1] - 1.0).abs() < 1e-12, "{r:?}");
        assert!(r.loss_j.abs() < 1e-12);
    }

    #[test]
    fn sticking_impact_matches_the_linear_solve() {
        let m = w(3.0, 0.6);
        let r = darboux_keller(m, 5.0, 0.0, [0.0, -1.0], false).unwrap();
        // W P = -u0: P = W^{-1} (0, 1)
        let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
        let (pt, pn) = (-m[0][1] / det, m[0][0] / det);
        assert!(
            (r.p_t - pt).abs() < 1e-12 && (r.p_n - pn).abs() < 1e-12,
            "{r:?} {pt} {pn}"
        );
        assert!(r.u_after[0] == 0.0 && r.u_after[1].abs() < 1e-14);
    }

    #[test]
    fn impacts_never_create_energy_over_a_grid() {
        for alpha in [0.5, 3.0, 30.0, 1e4] {
            for th in [-1.2, -0.3, 0.2, 0.7, 1.3] {
                for mu in [0.0, 0.3, 1.0, 3.0] {
                    for e in [0.0, 0.5, 1.0] {
                        for ut in [-2.0, -0.1, 0.0, 0.5, 3.0] {
                            if let Ok(r) = darboux_keller(w(alpha, th), mu, e, [ut, -1.0], false) {
                                let scale = 1.0 + alpha;
                                assert!(
                                    r.loss_j >= -1e-12 * scale,
                                    "{alpha} {th} {mu} {e} {ut} {r:?}"
                                );
                                assert!(r.u_after[1] >= -1e-12, "{r:?}");
                            }
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn impact_without_collision_on_the_boundary_stops_the_slip() {
        // uniform rod at -45 deg, mu = 5/3: exactly on the Painleve boundary for a foot
        // slipping right, the normal slope of the slip is zero
        let m = w(3.0, -std::f64::consts::FRAC_PI_4);
        let r = darboux_keller(m, 5.0 / 3.0, 0.0, [1.0, 0.0], true).unwrap();
        assert!(
            r.u_after[0] == 0.0 && r.p_n > 0.0 && r.loss_j > 0.0,
            "{r:?}"
        );
        assert!(r.u_after[1].abs() < 1e-12, "{r:?}");
    }
}
