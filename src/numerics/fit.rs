//! Least-squares fits shared by the convergence studies.

/// The least-squares slope of the points `(x, y)`:
/// `b = sum (x - mean x)(y - mean y) / sum (x - mean x)^2`.
///
/// Fed `(ln h, ln err)` it is the observed order of a method in `err = C h^p`. NaN for
/// fewer than two points or points that all share one `x`.
pub fn slope(pts: &[(f64, f64)]) -> f64 {
    if pts.len() < 2 {
        return f64::NAN;
    }
    let n = pts.len() as f64;
    let mx = pts.iter().map(|p| p.0).sum::<f64>() / n;
    let my = pts.iter().map(|p| p.1).sum::<f64>() / n;
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
    if sxx == 0.0 {
        return f64::NAN;
    }
    sxy / sxx // formula: slope = cov(x, y) / var(x)
}

#[cfg(test)]
mod tests {
    use super::slope;

    #[test]
    fn slope_of_a_power_law_is_its_exponent() {
        // err = 3 h^4 at h = 1e-1 .. 1e-3: the log-log slope is 4 to rounding
        let pts: Vec<(f64, f64)> = [1e-1, 3e-2, 1e-2, 3e-3, 1e-3]
            .iter()
            .map(|&h: &f64| (h.ln(), (3.0 * h.powi(4)).ln()))
            .collect();
        assert!((slope(&pts) - 4.0).abs() < 1e-12);
    }

    #[test]
    fn degenerate_inputs_give_nan() {
        assert!(slope(&[]).is_nan());
        assert!(slope(&[(1.0, 2.0)]).is_nan());
        assert!(slope(&[(1.0, 2.0), (1.0, 3.0)]).is_nan());
    }
}
