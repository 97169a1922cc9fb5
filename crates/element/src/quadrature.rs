//! Gauss quadrature rules: line, tensor-product quadrilateral, and symmetric triangle rules.
//!
//! ```text
//! ∫_{-1}^{1} f(ξ) dξ ≈ Σ_g w_g f(ξ_g)              (n points: exact to degree 2n - 1)
//! ∫_{[-1,1]²} f dξ dη ≈ Σ_i Σ_j w_i w_j f(ξ_i, η_j)   (tensor product)
//! ∫_{triangle} f dr ds ≈ Σ_g w_g f(r_g, s_g)        (weights sum to the area 1/2)
//! ```
//!
//! # References
//! Strang & Fix (1973) and Dunavant (1985) for the triangle rules of degree 2, 4, 5.

use crate::error::ElementError;
use crate::shape::ElementType;

/// A quadrature rule on a 2D reference cell.
#[derive(Debug, Clone, PartialEq)]
pub struct GaussRule {
    /// Reference coordinates of the points.
    pub points: Vec<[f64; 2]>,
    /// Weights (sum 4 on the square, 1/2 on the triangle).
    pub weights: Vec<f64>,
}

/// Gauss-Legendre points and weights on `[-1, 1]` with `n` points, `n` in `1..=5`.
///
/// # Errors
/// [`ElementError::UnsupportedRule`] for any other `n`.
pub fn gauss_legendre(n: usize) -> Result<(Vec<f64>, Vec<f64>), ElementError> {
    let (x, w): (&[f64], &[f64]) = match n {
        1 => (&[0.0], &[2.0]),
        2 => {
            let a = 1.0 / 3f64.sqrt();
            return Ok((vec![-a, a], vec![1.0, 1.0]));
        }
        3 => {
            let a = (0.6f64).sqrt();
            return Ok((vec![-a, 0.0, a], vec![5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0]));
        }
        4 => {
            let s = (6.0f64 / 5.0).sqrt();
            let (a, b) = (((3.0 - 2.0 * s) / 7.0).sqrt(), ((3.0 + 2.0 * s) / 7.0).sqrt());
            let (wa, wb) = ((18.0 + 30f64.sqrt()) / 36.0, (18.0 - 30f64.sqrt()) / 36.0);
            return Ok((vec![-b, -a, a, b], vec![wb, wa, wa, wb]));
        }
        5 => {
            let s = 2.0 * (10.0f64 / 7.0).sqrt();
            let (a, b) = ((5.0 - s).sqrt() / 3.0, (5.0 + s).sqrt() / 3.0);
            let r = 70f64.sqrt();
            let (wa, wb) = ((322.0 + 13.0 * r) / 900.0, (322.0 - 13.0 * r) / 900.0);
            return Ok((vec![-b, -a, 0.0, a, b], vec![wb, wa, 128.0 / 225.0, wa, wb]));
        }
        _ => return Err(ElementError::UnsupportedRule { what: format!("{n}-point Gauss-Legendre line rule") }),
    };
    Ok((x.to_vec(), w.to_vec()))
}

impl GaussRule {
    /// The `n × n` tensor-product Gauss rule on the square (exact to degree `2n - 1` per direction).
    ///
    /// # Errors
    /// [`ElementError::UnsupportedRule`] unless `n` is in `1..=5`.
    pub fn quad(n: usize) -> Result<GaussRule, ElementError> {
        let (x, w) = gauss_legendre(n)?;
        let mut rule = GaussRule { points: Vec::with_capacity(n * n), weights: Vec::with_capacity(n * n) };
        for j in 0..n {
            for i in 0..n {
                rule.points.push([x[i], x[j]]);
                rule.weights.push(w[i] * w[j]);
            }
        }
        Ok(rule)
    }

    /// A symmetric triangle rule exact to polynomial degree `degree` (1, 2, 4 or 5; 3 uses 4).
    ///
    /// # Errors
    /// [`ElementError::UnsupportedRule`] for degree 0 or above 5.
    pub fn triangle(degree: usize) -> Result<GaussRule, ElementError> {
        let orbit3 = |a: f64, w: f64, rule: &mut GaussRule| {
            let b = 1.0 - 2.0 * a;
            for p in [[a, a], [b, a], [a, b]] {
                rule.points.push(p);
                rule.weights.push(w);
            }
        };
        let mut rule = GaussRule { points: vec![], weights: vec![] };
        match degree {
            1 => {
                rule.points.push([1.0 / 3.0, 1.0 / 3.0]);
                rule.weights.push(0.5);
            }
            2 => orbit3(1.0 / 6.0, 1.0 / 6.0, &mut rule),
            3 | 4 => {
                orbit3(0.445_948_490_915_965, 0.5 * 0.223_381_589_678_011, &mut rule);
                orbit3(0.091_576_213_509_771, 0.5 * 0.109_951_743_655_322, &mut rule);
            }
            5 => {
                rule.points.push([1.0 / 3.0, 1.0 / 3.0]);
                rule.weights.push(0.5 * 0.225);
                let s = 15f64.sqrt();
                orbit3((6.0 - s) / 21.0, 0.5 * (155.0 - s) / 1200.0, &mut rule);
                orbit3((6.0 + s) / 21.0, 0.5 * (155.0 + s) / 1200.0, &mut rule);
            }
            _ => {
                return Err(ElementError::UnsupportedRule { what: format!("triangle rule of degree {degree}") });
            }
        }
        Ok(rule)
    }

    /// The rule that integrates the stiffness of an undistorted element exactly:
    /// 1 point (Tri3), degree 2 (Tri6), 2×2 (Quad4), 3×3 (Quad8, Quad9).
    pub fn stiffness_rule(element: ElementType) -> GaussRule {
        // These sizes are all supported, so the fallbacks below are unreachable.
        let rule = match element {
            ElementType::Tri3 => GaussRule::triangle(1),
            ElementType::Tri6 => GaussRule::triangle(2),
            ElementType::Quad4 => GaussRule::quad(2),
            ElementType::Quad8 | ElementType::Quad9 => GaussRule::quad(3),
        };
        rule.unwrap_or_else(|_| GaussRule { points: vec![], weights: vec![] })
    }

    /// Number of points.
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// Whether the rule has no points.
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    /// ∫_{-1}^{1} x^k dx.
    fn line_moment(k: i32) -> f64 {
        if k % 2 == 1 { 0.0 } else { 2.0 / (k as f64 + 1.0) }
    }

    /// ∫_T r^i s^j = i! j! / (i + j + 2)!.
    fn triangle_moment(i: u32, j: u32) -> f64 {
        let f = |n: u32| (1..=n).map(f64::from).product::<f64>();
        f(i) * f(j) / f(i + j + 2)
    }

    #[test]
    fn line_rules_are_exact_to_degree_2n_minus_1() {
        for n in 1..=5 {
            let (x, w) = gauss_legendre(n).unwrap();
            for k in 0..(2 * n as i32) {
                let q: f64 = x.iter().zip(&w).map(|(x, w)| w * x.powi(k)).sum();
                assert!((q - line_moment(k)).abs() < 1e-14, "n={n} k={k}");
            }
        }
        assert!(gauss_legendre(6).is_err());
    }

    #[test]
    fn quad_rules_are_exact_per_direction() {
        for n in 1..=5 {
            let rule = GaussRule::quad(n).unwrap();
            for i in 0..(2 * n as i32) {
                for j in 0..(2 * n as i32) {
                    let q: f64 =
                        rule.points.iter().zip(&rule.weights).map(|(p, w)| w * p[0].powi(i) * p[1].powi(j)).sum();
                    assert!((q - line_moment(i) * line_moment(j)).abs() < 1e-13);
                }
            }
        }
    }

    #[test]
    fn triangle_rules_are_exact_to_their_degree() {
        for degree in [1usize, 2, 4, 5] {
            let rule = GaussRule::triangle(degree).unwrap();
            for i in 0..=degree as u32 {
                for j in 0..=(degree as u32 - i) {
                    let q: f64 = rule
                        .points
                        .iter()
                        .zip(&rule.weights)
                        .map(|(p, w)| w * p[0].powi(i as i32) * p[1].powi(j as i32))
                        .sum();
                    assert!((q - triangle_moment(i, j)).abs() < 1e-13, "degree {degree}: r^{i} s^{j}");
                }
            }
        }
        assert!(GaussRule::triangle(0).is_err());
        assert!(GaussRule::triangle(6).is_err());
    }
}
