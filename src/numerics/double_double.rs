//! Double-double arithmetic (about 32 significant digits) for the tests that check a
//! rounding bound against a value far more accurate than the double it bounds.
//!
//! A value is the unevaluated sum `hi + lo` with `|lo| <= ulp(hi)/2`. Sums use
//! Knuth's TwoSum and products Dekker's TwoProduct (through `mul_add`), so each
//! operation's relative error is about `u^2` (`u = 2^-53`); the Taylor series below are
//! summed to far below that.

/// A double-double number `hi + lo`.
#[derive(Debug, Clone, Copy)]
pub struct Dd(pub f64, pub f64);

impl Dd {
    /// The double `x`, exactly.
    pub fn new(x: f64) -> Dd {
        Dd(x, 0.0)
    }
    /// `self + y`.
    pub fn add(self, y: Dd) -> Dd {
        let s = self.0 + y.0;
        let bb = s - self.0;
        let e = (self.0 - (s - bb)) + (y.0 - bb) + self.1 + y.1; // formula: TwoSum
        let t = s + e;
        Dd(t, e - (t - s))
    }
    /// `-self`.
    pub fn neg(self) -> Dd {
        Dd(-self.0, -self.1)
    }
    /// `self - y`.
    pub fn sub(self, y: Dd) -> Dd {
        self.add(y.neg())
    }
    /// `self * y`.
    pub fn mul(self, y: Dd) -> Dd {
        let p = self.0 * y.0;
        let e = self.0.mul_add(y.0, -p) + (self.0 * y.1 + self.1 * y.0); // formula: TwoProduct
        let t = p + e;
        Dd(t, e - (t - p))
    }
    /// `self / y` by three quotient digits.
    pub fn div(self, y: Dd) -> Dd {
        let q1 = self.0 / y.0;
        let r = self.sub(y.mul(Dd::new(q1)));
        let q2 = r.0 / y.0;
        let r = r.sub(y.mul(Dd::new(q2)));
        Dd::new(q1).add(Dd::new(q2)).add(Dd::new(r.0 / y.0))
    }
    /// The nearest double (to within one rounding).
    pub fn f(self) -> f64 {
        self.0 + self.1
    }
    /// `|self - x|` as a double.
    pub fn dist(self, x: f64) -> f64 {
        (self.0 - x + self.1).abs()
    }
    /// sin and cos of a double `|x| <= π/2` by their Taylor series (40 terms: the
    /// remainder is below `(π/2)^40/40!`, about 1e-40).
    pub fn sin_cos(x: f64) -> (Dd, Dd) {
        let (mut s, mut c, mut term) = (Dd::new(0.0), Dd::new(0.0), Dd::new(1.0));
        for n in 0..40 {
            match n % 4 {
                0 => c = c.add(term),
                1 => s = s.add(term),
                2 => c = c.sub(term),
                _ => s = s.sub(term),
            }
            term = term.mul(Dd::new(x)).div(Dd::new((n + 1) as f64));
        }
        (s, c)
    }
}

#[cfg(test)]
mod tests {
    use super::Dd;

    #[test]
    fn sin_cos_agree_with_libm_and_square_to_one_far_below_a_double_rounding() {
        for x in [
            1e-3,
            0.3,
            0.4636476090008061,
            1.0,
            std::f64::consts::FRAC_PI_2,
        ] {
            let (s, c) = Dd::sin_cos(x);
            assert!(s.dist(x.sin()) <= 2.3e-16 * x.sin(), "{x}");
            assert!(c.dist(x.cos()) <= 2.3e-16 * x.cos().max(1e-16), "{x}");
            let one = s.mul(s).add(c.mul(c));
            assert!(one.dist(1.0) < 1e-30, "{x}: {:e}", one.dist(1.0));
        }
        let third = Dd::new(1.0).div(Dd::new(3.0));
        assert!(third.mul(Dd::new(3.0)).dist(1.0) < 1e-31);
    }
}
