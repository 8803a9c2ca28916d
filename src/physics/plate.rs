//! Prescribed plate motions: position, velocity and acceleration of a rigid plate,
//! horizontal (x) and vertical (z), in SI units.
//!
//! - [`Harmonic`]: `u = A sin(omega t + phi)` along one axis (the document's
//!   `u_x = delta_x sin(omega t)`, `u_z = delta_z sin(omega t)`, and the stick's
//!   platform `z_s = delta cos(omega t)` with `phi = pi/2`).
//! - [`Sawtooth`]: the two-velocity sawtooth of section 3.2.2: a slow stroke towards
//!   +x at `v_slow` for `t_slow`, then a fast stroke back at `-v_fast` for
//!   `t_fast = v_slow t_slow / v_fast`: zero net displacement per period.
//! - [`Biharmonic`]: a smooth asymmetric drive `v_p = V (sin(omega t) + eps cos(2 omega t))`.

use std::f64::consts::TAU;

/// The axis a one-dimensional plate motion acts along.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Axis {
    /// Horizontal.
    X,
    /// Vertical.
    Z,
}

/// A rigid plate's prescribed motion. Components not overridden are zero.
pub trait PlateMotion: Send + Sync {
    /// Horizontal position (m).
    fn x_m(&self, _t: f64) -> f64 {
        0.0
    }
    /// Horizontal velocity (m/s).
    fn vx_mps(&self, _t: f64) -> f64 {
        0.0
    }
    /// Horizontal acceleration (m/s^2); zero between the jumps of a piecewise-linear motion.
    fn ax_mps2(&self, _t: f64) -> f64 {
        0.0
    }
    /// Vertical position (m).
    fn z_m(&self, _t: f64) -> f64 {
        0.0
    }
    /// Vertical velocity (m/s).
    fn vz_mps(&self, _t: f64) -> f64 {
        0.0
    }
    /// Vertical acceleration (m/s^2).
    fn az_mps2(&self, _t: f64) -> f64 {
        0.0
    }
    /// Drive period (s).
    fn period_s(&self) -> f64;
    /// First time strictly after `t` at which the velocity or acceleration jumps.
    fn breakpoint_after(&self, _t: f64) -> Option<f64> {
        None
    }
    /// Bounds over all t of `[|v_xp|, |a_xp|, |v_zp|, |a_zp|]` (m/s, m/s^2), where the
    /// motion knows them (`None`: unknown; the block then reads the values at t).
    fn peak_rates(&self) -> Option<[f64; 4]> {
        None
    }
}

/// `u = amplitude_m sin(omega t + phase_rad)` along `axis`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Harmonic {
    /// Axis of motion.
    pub axis: Axis,
    /// Amplitude delta (m).
    pub amplitude_m: f64,
    /// Angular frequency omega (rad/s).
    pub omega_rad_s: f64,
    /// Phase phi (rad): 0 for the sine of section 3.1, pi/2 for the stick's cosine.
    pub phase_rad: f64,
}

impl Harmonic {
    /// `u = delta sin(2 pi f t)` along `axis`.
    pub fn sine(axis: Axis, amplitude_m: f64, frequency_hz: f64) -> Self {
        Harmonic {
            axis,
            amplitude_m,
            omega_rad_s: TAU * frequency_hz,
            phase_rad: 0.0,
        }
    }

    /// `u = delta cos(2 pi f t)` along `axis` (the stick's platform, section 4).
    pub fn cosine(axis: Axis, amplitude_m: f64, frequency_hz: f64) -> Self {
        Harmonic {
            axis,
            amplitude_m,
            omega_rad_s: TAU * frequency_hz,
            phase_rad: std::f64::consts::FRAC_PI_2,
        }
    }

    /// Peak velocity delta omega (m/s).
    pub(crate) fn peak_velocity_mps(&self) -> f64 {
        self.amplitude_m * self.omega_rad_s
    }

    /// Peak acceleration delta omega^2 (m/s^2).
    pub(crate) fn peak_acceleration_mps2(&self) -> f64 {
        self.amplitude_m * self.omega_rad_s * self.omega_rad_s
    }

    fn u(&self, t: f64) -> f64 {
        self.amplitude_m * (self.omega_rad_s * t + self.phase_rad).sin() // formula: u = delta sin(wt + phi)
    }
    fn v(&self, t: f64) -> f64 {
        self.amplitude_m * self.omega_rad_s * (self.omega_rad_s * t + self.phase_rad).cos()
        // formula: u' = delta w cos(wt + phi)
    }
    fn a(&self, t: f64) -> f64 {
        -self.amplitude_m
            * self.omega_rad_s
            * self.omega_rad_s
            * (self.omega_rad_s * t + self.phase_rad).sin() // formula: u'' = -delta w^2 sin(wt + phi)
    }
}

impl PlateMotion for Harmonic {
    fn x_m(&self, t: f64) -> f64 {
        if self.axis == Axis::X {
            self.u(t)
        } else {
            0.0
        }
    }
    fn vx_mps(&self, t: f64) -> f64 {
        if self.axis == Axis::X {
            self.v(t)
        } else {
            0.0
        }
    }
    fn ax_mps2(&self, t: f64) -> f64 {
        if self.axis == Axis::X {
            self.a(t)
        } else {
            0.0
        }
    }
    fn z_m(&self, t: f64) -> f64 {
        if self.axis == Axis::Z {
            self.u(t)
        } else {
            0.0
        }
    }
    fn vz_mps(&self, t: f64) -> f64 {
        if self.axis == Axis::Z {
            self.v(t)
        } else {
            0.0
        }
    }
    fn az_mps2(&self, t: f64) -> f64 {
        if self.axis == Axis::Z {
            self.a(t)
        } else {
            0.0
        }
    }
    fn period_s(&self) -> f64 {
        TAU / self.omega_rad_s
    }
    fn peak_rates(&self) -> Option<[f64; 4]> {
        let (v, a) = (
            self.peak_velocity_mps().abs(),
            self.peak_acceleration_mps2().abs(),
        ); // formula: |v| <= delta w, |a| <= delta w^2
        Some(match self.axis {
            Axis::X => [v, a, 0.0, 0.0],
            Axis::Z => [0.0, 0.0, v, a],
        })
    }
}

/// Two-velocity horizontal sawtooth: `+slow_velocity_mps` for `slow_duration_s`, then
/// `-fast_velocity_mps` for `fast_duration_s = slow_velocity_mps slow_duration_s /
/// fast_velocity_mps`; `x(0) = 0` and zero net displacement per period.
///
/// Breakpoints are **canonical floats**: the `i`-th is always computed by the same
/// expression, `B(2k) = k T` (a slow stroke starts) and `B(2k+1) = k T + t_slow` (a fast
/// stroke starts), and every query compares `t` with these floats, never with a
/// rounded phase. Hence `breakpoint_after(t)` is strictly greater than `t`, stepping
/// to it and asking again yields the next one, and velocity is exactly
/// right-continuous: at `t = B(i)` it is the velocity of the stroke that begins there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sawtooth {
    /// Speed of the slow stroke towards +x (m/s).
    pub slow_velocity_mps: f64,
    /// Speed of the fast stroke towards -x (m/s), larger than the slow speed.
    pub fast_velocity_mps: f64,
    /// Duration of the slow stroke (s).
    pub slow_duration_s: f64,
}

/// Which stroke of a [`Sawtooth`] is under way.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stroke {
    /// Slow stroke towards +x.
    Slow,
    /// Fast stroke towards -x.
    Fast,
}

impl Sawtooth {
    /// Duration of the fast stroke (s): `v_slow t_slow / v_fast`.
    pub(crate) fn fast_duration_s(&self) -> f64 {
        self.slow_velocity_mps * self.slow_duration_s / self.fast_velocity_mps // formula: v_s t_s = v_f t_f
    }

    /// The canonical float of breakpoint `i` (s).
    pub(crate) fn breakpoint(&self, i: i64) -> f64 {
        let k = i.div_euclid(2) as f64;
        let base = k * self.period_s(); // formula: B(2k) = k T
        if i.rem_euclid(2) == 0 {
            base
        } else {
            base + self.slow_duration_s // formula: B(2k+1) = k T + t_slow
        }
    }

    /// Index of the piece containing `t`: the largest `i` with `B(i) <= t`.
    pub(crate) fn piece_index(&self, t: f64) -> i64 {
        let mut i = 2 * (t / self.period_s()).floor() as i64;
        while self.breakpoint(i) > t {
            i -= 1;
        }
        while self.breakpoint(i + 1) <= t {
            i += 1;
        }
        i
    }

    /// The stroke under way at `t` (right-continuous at the breakpoints).
    pub(crate) fn stroke_at(&self, t: f64) -> Stroke {
        if self.piece_index(t).rem_euclid(2) == 0 {
            Stroke::Slow
        } else {
            Stroke::Fast
        }
    }
}

impl PlateMotion for Sawtooth {
    fn x_m(&self, t: f64) -> f64 {
        let i = self.piece_index(t);
        let since = t - self.breakpoint(i);
        if i.rem_euclid(2) == 0 {
            self.slow_velocity_mps * since // formula: x = v_s (t - kT)
        } else {
            self.slow_velocity_mps * self.slow_duration_s - self.fast_velocity_mps * since
            // formula: x = v_s t_s - v_f (t - kT - t_s)
        }
    }
    fn vx_mps(&self, t: f64) -> f64 {
        match self.stroke_at(t) {
            Stroke::Slow => self.slow_velocity_mps,
            Stroke::Fast => -self.fast_velocity_mps,
        }
    }
    fn period_s(&self) -> f64 {
        self.slow_duration_s + self.fast_duration_s()
    }
    fn breakpoint_after(&self, t: f64) -> Option<f64> {
        Some(self.breakpoint(self.piece_index(t) + 1))
    }
    fn peak_rates(&self) -> Option<[f64; 4]> {
        let v = self
            .slow_velocity_mps
            .abs()
            .max(self.fast_velocity_mps.abs()); // formula: |v| <= max(v_s, v_f), a = 0 between jumps
        Some([v, 0.0, 0.0, 0.0])
    }
}

/// Smooth asymmetric horizontal drive `v_p = V (sin(omega t) + eps cos(2 omega t))`,
/// `x(0) = 0`, zero mean velocity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Biharmonic {
    /// Velocity amplitude V (m/s).
    pub velocity_amplitude_mps: f64,
    /// Angular frequency omega (rad/s).
    pub omega_rad_s: f64,
    /// Asymmetry eps of the second harmonic (dimensionless).
    pub asymmetry: f64,
}

impl PlateMotion for Biharmonic {
    fn x_m(&self, t: f64) -> f64 {
        let (v, w, e) = (
            self.velocity_amplitude_mps,
            self.omega_rad_s,
            self.asymmetry,
        );
        v * ((1.0 - (w * t).cos()) / w + e * (2.0 * w * t).sin() / (2.0 * w)) // formula: x = V((1 - cos wt)/w + eps sin 2wt/(2w))
    }
    fn vx_mps(&self, t: f64) -> f64 {
        let (v, w, e) = (
            self.velocity_amplitude_mps,
            self.omega_rad_s,
            self.asymmetry,
        );
        v * ((w * t).sin() + e * (2.0 * w * t).cos()) // formula: v_p = V (sin wt + eps cos 2wt)
    }
    fn ax_mps2(&self, t: f64) -> f64 {
        let (v, w, e) = (
            self.velocity_amplitude_mps,
            self.omega_rad_s,
            self.asymmetry,
        );
        v * w * ((w * t).cos() - 2.0 * e * (2.0 * w * t).sin()) // formula: a_p = V w (cos wt - 2 eps sin 2wt)
    }
    fn period_s(&self) -> f64 {
        TAU / self.omega_rad_s
    }
    fn peak_rates(&self) -> Option<[f64; 4]> {
        let (v, w, e) = (
            self.velocity_amplitude_mps.abs(),
            self.omega_rad_s.abs(),
            self.asymmetry.abs(),
        );
        Some([v * (1.0 + e), v * w * (1.0 + 2.0 * e), 0.0, 0.0]) // formula: |v_p| <= V (1 + eps), |a_p| <= V w (1 + 2 eps)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Central difference of f at t (step h).
    fn diff(f: impl Fn(f64) -> f64, t: f64, h: f64) -> f64 {
        (f(t + h) - f(t - h)) / (2.0 * h)
    }

    #[test]
    fn derivatives_match_finite_differences() {
        // Central differences have error ~ h^2 f'''/6: 1e-6 relative is ample at h = 1e-5 T.
        let plates: Vec<Box<dyn PlateMotion>> = vec![
            Box::new(Harmonic::sine(Axis::X, 0.002, 7.0)),
            Box::new(Harmonic::cosine(Axis::Z, 0.003, 30.0)),
            Box::new(Biharmonic {
                velocity_amplitude_mps: 0.2,
                omega_rad_s: 40.0,
                asymmetry: 0.3,
            }),
        ];
        for p in &plates {
            let h = 1e-5 * p.period_s();
            for k in 0..20 {
                let t = 0.013 + 0.037 * k as f64 * p.period_s();
                let scale_v = 1.0 + p.vx_mps(t).abs() + p.vz_mps(t).abs();
                assert!((diff(|s| p.x_m(s), t, h) - p.vx_mps(t)).abs() < 1e-6 * scale_v * 10.0);
                assert!((diff(|s| p.z_m(s), t, h) - p.vz_mps(t)).abs() < 1e-6 * scale_v * 10.0);
                let scale_a = 1.0 + p.ax_mps2(t).abs() + p.az_mps2(t).abs();
                assert!((diff(|s| p.vx_mps(s), t, h) - p.ax_mps2(t)).abs() < 1e-5 * scale_a * 10.0);
                assert!((diff(|s| p.vz_mps(s), t, h) - p.az_mps2(t)).abs() < 1e-5 * scale_a * 10.0);
            }
        }
    }

    #[test]
    fn sawtooth_has_zero_net_displacement_and_exact_breakpoints() {
        let s = Sawtooth {
            slow_velocity_mps: 0.1,
            fast_velocity_mps: 0.3,
            slow_duration_s: 0.03,
        };
        assert!((s.fast_duration_s() - 0.01).abs() < 1e-15);
        assert!((s.period_s() - 0.04).abs() < 1e-15);
        assert!(s.x_m(0.04 * 7.0 + 1e-12).abs() < 1e-12);
        assert!((s.x_m(0.03) - 0.003).abs() < 1e-12 || (s.x_m(0.03 - 1e-12) - 0.003).abs() < 1e-12);
        assert_eq!(s.vx_mps(0.01), 0.1);
        assert_eq!(s.vx_mps(0.035), -0.3);
        let b1 = s.breakpoint_after(0.0).unwrap();
        assert!((b1 - 0.03).abs() < 1e-15);
        let b2 = s.breakpoint_after(b1).unwrap();
        assert!((b2 - 0.04).abs() < 1e-15, "{b2}");
        let b3 = s.breakpoint_after(b2).unwrap();
        assert!((b3 - 0.07).abs() < 1e-14, "{b3}");
        // Walking the breakpoints from any of them, or from an ulp before or after,
        // never skips or repeats one, and the velocity switches exactly at each.
        let mut b = 0.0;
        for i in 1..2000 {
            let next = s.breakpoint_after(b).unwrap();
            assert_eq!(next, s.breakpoint(i), "breakpoint {i}");
            let before = f64::from_bits(next.to_bits() - 1);
            assert_eq!(s.breakpoint_after(before), Some(next), "an ulp before {i}");
            let after = f64::from_bits(next.to_bits() + 1);
            assert_eq!(
                s.breakpoint_after(after),
                Some(s.breakpoint(i + 1)),
                "an ulp after {i}"
            );
            // even breakpoints start a slow stroke (+0.1), odd ones a fast one (-0.3)
            let (left, right) = if i % 2 == 0 { (-0.3, 0.1) } else { (0.1, -0.3) };
            assert_eq!(s.vx_mps(next), right, "right-continuous at {i}");
            assert_eq!(s.vx_mps(before), left, "left of {i}");
            b = next;
        }
        // mean velocity over a period is zero
        let n = 4000;
        let mean: f64 = (0..n)
            .map(|i| s.vx_mps((i as f64 + 0.5) * s.period_s() / n as f64))
            .sum::<f64>()
            / n as f64;
        assert!(mean.abs() < 1e-12, "{mean}");
    }

    #[test]
    fn stick_platform_is_a_cosine() {
        let p = Harmonic::cosine(Axis::Z, 0.01, 30.0);
        assert!((p.z_m(0.0) - 0.01).abs() < 1e-15);
        assert!(p.vz_mps(0.0).abs() < 1e-15);
        assert!((p.peak_acceleration_mps2() - 0.01 * (TAU * 30.0).powi(2)).abs() < 1e-9);
    }
}
