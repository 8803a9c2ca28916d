//! One-dimensional searches on a bracket: golden-section search for the extremum of a
//! unimodal function (shared by chapter 2's best angle and chapter 8's least Painleve
//! boundary).

/// Golden-section search for the minimum of a unimodal `f` on `[a, b]`, stopped when the
/// bracket is below `tol`. Returns the abscissa (the bracket's midpoint).
pub(crate) fn golden_min(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64, tol: f64) -> f64 {
    let g = (5f64.sqrt() - 1.0) / 2.0; // formula: 1/phi
    let (mut c, mut d) = (b - g * (b - a), a + g * (b - a));
    let (mut fc, mut fd) = (f(c), f(d));
    while b - a > tol {
        if fc < fd {
            b = d;
            (d, fd) = (c, fc);
            c = b - g * (b - a);
            fc = f(c);
        } else {
            a = c;
            (c, fc) = (d, fd);
            d = a + g * (b - a);
            fd = f(d);
        }
    }
    0.5 * (a + b)
}

/// Golden-section search for the maximum of a unimodal `f` on `[a, b]`: the minimum of
/// `-f` (the same comparisons, so the same points are evaluated).
pub fn golden_max(f: impl Fn(f64) -> f64, a: f64, b: f64, tol: f64) -> f64 {
    golden_min(|x| -f(x), a, b, tol)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn golden_finds_the_extremum_of_a_parabola() {
        let x = golden_min(|x| (x - 0.3) * (x - 0.3), 0.0, 1.0, 1e-10);
        assert!((x - 0.3).abs() < 1e-9, "{x}");
        let y = golden_max(|x| -(x - 0.7) * (x - 0.7), 0.0, 1.0, 1e-10);
        assert!((y - 0.7).abs() < 1e-9, "{y}");
    }
}
