//! Errors of a computed traction profile against a closed form.
//!
//! ```text
//! e_L2 = [ (1/|I|) ∫_I (f_h(x) − f(x))² dx ]^½      (trapezoid rule on the profile's nodes in I)
//! ```
//!
//! The nodal values are the pairs' tractions (force over tributary length), sampled where the
//! closed form is evaluated, so the error measures the pairing's tractions themselves, with no
//! smoothing.

/// The root-mean-square deviation of `(x, f_h)` samples from `exact` over those with `x` in
/// `[lo, hi]` (sorted by `x` first); `None` with fewer than two samples there.
pub fn l2_error(samples: &[(f64, f64)], lo: f64, hi: f64, exact: impl Fn(f64) -> f64) -> Option<f64> {
    let mut inside: Vec<(f64, f64)> = samples.iter().copied().filter(|(x, _)| *x >= lo && *x <= hi).collect();
    inside.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (mut sum, mut length) = (0.0, 0.0);
    for w in inside.windows(2) {
        let dx = w[1].0 - w[0].0;
        sum += 0.5 * dx * ((w[0].1 - exact(w[0].0)).powi(2) + (w[1].1 - exact(w[1].0)).powi(2));
        length += dx;
    }
    (length > 0.0).then(|| (sum / length).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_constant_offset_is_its_own_error() {
        let samples: Vec<(f64, f64)> = (0..11).map(|i| (f64::from(i) / 10.0, 1.5)).collect();
        let e = l2_error(&samples, 0.0, 1.0, |_| 1.0).unwrap_or(f64::NAN);
        assert!((e - 0.5).abs() < 1e-14);
        assert!(l2_error(&samples, 2.0, 3.0, |_| 1.0).is_none());
    }
}
