//! The displacements `x = K⁻¹ Bᵀ f` of contact forces `f` that lie in the span of the last two
//! solved, by linearity instead of a solve with `K`.
//!
//! ```text
//! q₁ = f₁ / ‖f₁‖,  q₂ = d / ‖d‖ with d = f₂ − (q₁·f₂) q₁   (Gram–Schmidt, done twice; y₁, y₂
//!                      their images)
//! f ≈ a q₁ + b q₂      a = q₁·f, b = q₂·f; accepted if ‖f − a q₁ − b q₂‖∞ ≤ 2e-12 ‖f‖∞
//!                      and |b| ‖f₂‖ / ‖d‖ ≤ 10 ‖f‖ (q₂ carries f₂'s round-off magnified by
//!                      ‖f₂‖ / ‖d‖: its coefficient must be of the size of the difference itself)
//! x = a y₁ + b y₂      (x linear in f)
//! ```
//!
//! Why: along a load history the steps that keep one contact state have forces affine in the
//! load (the state's solution is `w x₁ + x₂`, and the history terms of its stick rows do not
//! change while they stick), so from the third such step on the forces lie in the span of the
//! two before. Each step's final displacement otherwise costs a pair of triangular solves with
//! `K`'s factor (23 ms at 145k DOFs, 48 ms at 290k: most of a long history's recovery). The
//! result is the solve's for forces within 2e-12 of the given ones (the forces' own round-off is
//! about 1e-13), so it is used from [`SPAN_FROM_DOFS`] only: smaller problems stay bit for bit.

use std::sync::{Mutex, PoisonError};

/// The smallest problem (free DOFs) whose displacements are taken from the span.
pub(crate) const SPAN_FROM_DOFS: usize = 50_000;
/// The residual of `f` in the span, relative to `‖f‖∞`, below which the span is used. The
/// forces of a state's solve carry its LU's round-off, about cond · ε ≈ 1e-13 of their size on a
/// long interface (measured: 2e-13 to 9e-13 between the steps of `long_interface.toml` that keep
/// their state), so a tighter test would refuse every step; at 2e-12 the displacements are
/// those of forces within 2e-12 of the given ones.
const SPAN_RESIDUAL: f64 = 2e-12;
/// The largest `|b| ‖f₂‖ / (‖d‖ ‖f‖)` accepted (round-off magnified in q₂).
const MAX_CANCELLATION: f64 = 10.0;

/// The last two `(f, K⁻¹ Bᵀ f)` solved on an interface.
#[derive(Debug, Default)]
pub(crate) struct ForceSpan(Mutex<Vec<(Vec<f64>, Vec<f64>)>>);

impl Clone for ForceSpan {
    /// A clone starts empty (a cache, not part of the value).
    fn clone(&self) -> ForceSpan {
        ForceSpan::default()
    }
}

fn inf_norm(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |a, x| a.max(x.abs()))
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

impl ForceSpan {
    /// `K⁻¹ Bᵀ f` from the last two solved forces, or `None` if `f` is not in their span (see
    /// the module docs).
    pub(crate) fn solution(&self, f: &[f64]) -> Option<Vec<f64>> {
        let kept = self.0.lock().unwrap_or_else(PoisonError::into_inner);
        let [(f1, x1), (f2, x2)] = kept.as_slice() else { return None };
        if f1.len() != f.len() || f2.len() != f.len() {
            return None;
        }
        // An orthonormal basis q₁, q₂ of the span and its images y₁, y₂ (Gram–Schmidt).
        let n1 = dot(f1, f1).sqrt();
        if n1.is_nan() || n1 <= 0.0 {
            return None;
        }
        let q1: Vec<f64> = f1.iter().map(|v| v / n1).collect();
        let y1: Vec<f64> = x1.iter().map(|v| v / n1).collect();
        // Twice ("twice is enough"): when f₂ is close to f₁ the first pass leaves d with a
        // component along q₁ of the size of f₁'s round-off, large against d itself.
        let (mut d, mut e) = (f2.clone(), x2.clone());
        for _ in 0..2 {
            let c = dot(&q1, &d);
            d.iter_mut().zip(&q1).for_each(|(v, q)| *v -= c * q);
            e.iter_mut().zip(&y1).for_each(|(v, y)| *v -= c * y);
        }
        let nd = dot(&d, &d).sqrt();
        let a = dot(&q1, f);
        let (b, q2, y2) = if nd > 0.0 {
            let q2: Vec<f64> = d.iter().map(|v| v / nd).collect();
            (dot(&q2, f), q2, e.iter().map(|v| v / nd).collect())
        } else {
            (0.0, vec![0.0; f.len()], vec![0.0; x2.len()])
        };
        let norm = inf_norm(f);
        let residual = f.iter().zip(q1.iter().zip(&q2)).fold(0.0f64, |m, (v, (p, q))| m.max((v - a * p - b * q).abs()));
        // q₂ comes from f₂ − c f₁, with the round-off of f₁ and f₂ magnified by ‖f₂‖ / ‖d‖: its
        // coefficient must stay of the size of the difference the steps actually make.
        let spread = b.abs() * dot(f2, f2).sqrt() / nd.max(f64::MIN_POSITIVE);
        let in_span = residual <= SPAN_RESIDUAL * norm;
        let well_conditioned = spread <= MAX_CANCELLATION * dot(f, f).sqrt().max(f64::MIN_POSITIVE);
        if !(in_span && well_conditioned) {
            return None; // (also when a norm is NaN)
        }
        Some(y1.iter().zip(&y2).map(|(p, q)| a * p + b * q).collect())
    }

    /// Keeps `(f, x)` as the latest solved pair (the older of the two kept is dropped).
    pub(crate) fn remember(&self, f: Vec<f64>, x: Vec<f64>) {
        let mut kept = self.0.lock().unwrap_or_else(PoisonError::into_inner);
        if kept.len() == 2 {
            kept.remove(0);
        }
        kept.push((f, x));
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
    use super::*;

    /// `x = M f` for a fixed matrix stands for `K⁻¹ Bᵀ f`: a combination of the kept forces is
    /// answered exactly (to round-off), anything else is not answered.
    #[test]
    fn answers_only_forces_in_the_span() {
        let m = |f: &[f64]| vec![2.0 * f[0] + f[1], f[1] - f[2], 3.0 * f[2] + f[0]];
        let span = ForceSpan::default();
        let (f1, f2) = (vec![1.0, 2.0, 0.5], vec![-1.0, 0.25, 4.0]);
        assert!(span.solution(&f1).is_none(), "nothing kept yet");
        span.remember(f1.clone(), m(&f1));
        span.remember(f2.clone(), m(&f2));
        let f: Vec<f64> = f1.iter().zip(&f2).map(|(p, q)| 0.3 * p + 1.7 * q).collect();
        let x = span.solution(&f).expect("in the span");
        let exact = m(&f);
        // a, b from a 2 × 2 solve of O(1) entries: round-off, 1e-14 of the O(1) answer.
        assert!(x.iter().zip(&exact).all(|(a, b)| (a - b).abs() <= 1e-14 * 10.0));
        assert!(span.solution(&[0.0, 0.0, 1.0]).is_none(), "out of the span");
        // Nearly equal kept forces (the steps of a history that change the forces little): a
        // force along their tiny difference is answered, one far off it is refused.
        let near = ForceSpan::default();
        let g: Vec<f64> = f1.iter().zip(&f2).map(|(p, q)| p + 1e-9 * q).collect();
        near.remember(f1.clone(), m(&f1));
        near.remember(g.clone(), m(&g));
        let h: Vec<f64> = f1.iter().zip(&f2).map(|(p, q)| p + 2e-9 * q).collect();
        let x = near.solution(&h).expect("on the line through f1 and g");
        assert!(x.iter().zip(&m(&h)).all(|(a, b)| (a - b).abs() <= 1e-14 * 10.0));
        let off: Vec<f64> = f1.iter().zip(&f2).map(|(p, q)| p + 0.5 * q).collect();
        assert!(near.solution(&off).is_none(), "the span is known to 1e-9 only in that direction");
    }
}
