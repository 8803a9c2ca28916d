//! Reference solutions of the build exercises (exercise N.5 of each chapter). They run in
//! every `cargo test` through the same checks as the student's code (`build.rs`), so they
//! stay correct as the workbook changes. Read them after trying.

use super::build::{Exercises, PivotInputs};

/// The reference answers.
pub struct Reference;

/// `(b - a) x (c - a)`: positive when a, b, c turn counter-clockwise.
fn orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// `v` on the segment from `a` to `b` (inclusive), assuming the three are collinear.
fn between(a: [f64; 2], b: [f64; 2], v: [f64; 2]) -> bool {
    (0..2).all(|k| a[k].min(b[k]) <= v[k] && v[k] <= a[k].max(b[k]))
}

impl Exercises for Reference {
    fn is_outside_hull(v: [f64; 2], media: &[[f64; 2]]) -> bool {
        // Exact here: the checks use halves and small integers, so every product is exact.
        match *media {
            [a] => v != a,
            [a, b] => !(orient(a, b, v) == 0.0 && between(a, b, v)),
            [a, b, c] if orient(a, b, c) == 0.0 => {
                // A degenerate triangle: the segment between the two farthest points.
                let (p, q) = [(a, b), (b, c), (a, c)]
                    .into_iter()
                    .max_by(|x, y| {
                        let d = |(p, q): ([f64; 2], [f64; 2])| (p[0] - q[0]).hypot(p[1] - q[1]);
                        d(*x).total_cmp(&d(*y))
                    })
                    .unwrap();
                !(orient(p, q, v) == 0.0 && between(p, q, v))
            }
            [a, b, c] => {
                // Inside or on the triangle: v is on the same side of all three edges (or on one).
                let s = [orient(a, b, v), orient(b, c, v), orient(c, a, v)];
                let inside = s.iter().all(|&x| x >= 0.0) || s.iter().all(|&x| x <= 0.0);
                !inside
            }
            _ => unimplemented!("1 to 3 media"),
        }
    }

    fn rod_impulse_ratio(theta_rad: f64) -> f64 {
        // A uniform rod, m = L = 1: I_G = 1/12, C at r = -(L/2) e_r from G.
        let (m, i_g) = (1.0, 1.0 / 12.0);
        let r = [-0.5 * theta_rad.sin(), -0.5 * theta_rad.cos()];
        let p = [-r[1], r[0]]; // r turned by 90 degrees in the x-z plane
                               // formula: W = Id/m + p p^T / I_G
        let w = [
            [1.0 / m + p[0] * p[0] / i_g, p[0] * p[1] / i_g],
            [p[1] * p[0] / i_g, 1.0 / m + p[1] * p[1] / i_g],
        ];
        let det = w[0][0] * w[1][1] - w[0][1] * w[1][0];
        // formula: M = W^-1; J = M (0, dv): J_l/J_v = M_xz/M_zz
        let (m_xz, m_zz) = (-w[0][1] / det, w[0][0] / det);
        m_xz / m_zz
    }

    fn mean_friction(u: f64) -> f64 {
        // The relative velocity u - cos(phi) is negative (friction +1) while cos(phi) > u,
        // i.e. for |phi| < acos(u): a fraction acos(u)/pi of the period; -1 the rest.
        let a = u.clamp(-1.0, 1.0).acos() / std::f64::consts::PI;
        a - (1.0 - a)
    }

    fn dither_drift(b: f64) -> f64 {
        // The mean friction falls from 0 (u = 0) to -1 (u = 1): bisect friction + b = 0.
        let (mut lo, mut hi) = (0.0, 1.0);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if Self::mean_friction(mid) + b > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    fn landing_phase(gamma: f64, takeoff_phase: f64) -> f64 {
        // Units delta = omega = 1: g = 1/Gamma. The gap block - plate is zero at take-off
        // and positive just after; step until it changes sign, then bisect (event location).
        let p0 = takeoff_phase;
        let gap = |p: f64| {
            let s = p - p0;
            p0.sin() + p0.cos() * s - s * s / (2.0 * gamma) - p.sin()
        };
        let h = 1e-3;
        let mut a = p0 + h;
        while gap(a + h) > 0.0 {
            a += h;
        }
        let mut b = a + h;
        for _ in 0..100 {
            let mid = 0.5 * (a + b);
            if gap(mid) > 0.0 {
                a = mid;
            } else {
                b = mid;
            }
        }
        b
    }

    fn sawtooth_drift(v_slow: f64, v_fast: f64, t_slow: f64, mu_g: f64) -> f64 {
        // Each stroke: the plate moves at a constant u; the block slips towards u at
        // +-mu g until it reaches u, then rides with it (no force needed).
        let t_fast = v_slow * t_slow / v_fast;
        let strokes = [(v_slow, t_slow), (-v_fast, t_fast)];
        let (mut v, mut x) = (0.0f64, 0.0f64);
        let period = |v: &mut f64, x: &mut f64| {
            for (u, dur) in strokes {
                let a = mu_g * (u - *v).signum();
                let t_reach = if *v == u { 0.0 } else { (u - *v).abs() / mu_g };
                let slip = t_reach.min(dur);
                *x += *v * slip + 0.5 * a * slip * slip;
                *v += a * slip;
                if t_reach <= dur {
                    *v = u; // stuck: rides with the plate for the rest of the stroke
                    *x += u * (dur - slip);
                }
            }
        };
        for _ in 0..5000 {
            period(&mut v, &mut x);
        }
        let x0 = x;
        for _ in 0..10 {
            period(&mut v, &mut x);
        }
        (x - x0) / (10.0 * (t_slow + t_fast))
    }

    fn pivot_reaction(p: &PivotInputs, theta: f64, theta_dot: f64, a_s: f64) -> [f64; 2] {
        let (m, l, g) = (p.mass_kg, p.length_m, p.g_mps2);
        let (s, c) = theta.sin_cos();
        let q = p.stiffness_nm_per_rad * (theta - p.theta0_rad) + p.damping_nms_per_rad * theta_dot;
        let theta_dd = ((g + a_s) * m * l * s - q) / (m * l * l); // formula: C.6
        let ax = l * (theta_dd * c - theta_dot * theta_dot * s); // formula: C.7, x of P
        let az = a_s - l * (theta_dd * s + theta_dot * theta_dot * c); // formula: C.7, z of P
        [m * ax, m * (az + g)] // formula: F = m (a_P + g e_z)
    }

    fn rk4_step(f: &dyn Fn(f64, f64) -> f64, t: f64, y: f64, h: f64) -> f64 {
        let k1 = f(t, y);
        let k2 = f(t + 0.5 * h, y + 0.5 * h * k1);
        let k3 = f(t + 0.5 * h, y + 0.5 * h * k2);
        let k4 = f(t + h, y + h * k3);
        y + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)
    }

    fn rod_mobility(length_m: f64, rod_kg: f64, tip_kg: f64, theta_rad: f64) -> [[f64; 2]; 2] {
        let (l, m_r, m) = (length_m, rod_kg, tip_kg);
        let total = m + m_r; // formula: M = m + m_r
        let l_g = (m * l + 0.5 * m_r * l) / total; // formula: l_G = (m L + m_r L/2)/M
        let i_g = m_r * l * l / 12.0 + m_r * (0.5 * l - l_g).powi(2) + m * (l - l_g).powi(2); // formula: I_G by parallel axes
        let alpha = total * l_g * l_g / i_g; // formula: alpha = M l_G^2 / I_G
        let (s, c) = theta_rad.sin_cos(); // e_theta = (cos, -sin)
        [
            [(1.0 + alpha * c * c) / total, -alpha * s * c / total],
            [-alpha * s * c / total, (1.0 + alpha * s * s) / total],
        ] // formula: W = (Id + alpha e_theta e_theta^T)/M
    }
}
