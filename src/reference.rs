//! Reference values by Richardson extrapolation from the finest mesh levels.
//!
//! ```text
//! f1, f2, f3: a quantity on levels N1 < N2 < N3 with N2/N1 = N3/N2 = r (here r = 2)
//! d1 = f2 − f1,  d2 = f3 − f2
//! monotone (d1 d2 > 0 and |d2| < |d1|):  q = d1/d2,  observed order p = ln q / ln r,
//!                                        f_ref = f3 + d2 / (q − 1)        (= f3 + d2/(r^p − 1))
//! otherwise (oscillating, diverging, fewer than three levels, unequal ratios): f_ref = f3
//! ```
//!
//! The contact ends l and b are read from the pressure and slip between mesh nodes, so they often
//! converge non-monotonically; the reference is then the finest value, and the error at the
//! finest level is zero by construction (that point is left out of log-log figures).

/// A quantity of the benchmark.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Quantity {
    /// Pulling force P.
    Pull,
    /// Strain energy Φ_E = Φ_E1 + Φ_E2.
    Energy,
    /// Contact end l.
    ContactEnd,
    /// Stick end b.
    StickEnd,
    /// Largest hoop stress σ* on the hole edge.
    SigmaStar,
}

impl Quantity {
    /// Every quantity, in table order.
    pub const ALL: [Quantity; 5] =
        [Quantity::Pull, Quantity::Energy, Quantity::ContactEnd, Quantity::StickEnd, Quantity::SigmaStar];

    /// Short name for tables and CSV headers.
    pub fn name(self) -> &'static str {
        match self {
            Quantity::Pull => "P",
            Quantity::Energy => "Phi_E",
            Quantity::ContactEnd => "l",
            Quantity::StickEnd => "b",
            Quantity::SigmaStar => "sigma*",
        }
    }
}

/// How a reference value was obtained.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ReferenceMethod {
    /// Richardson extrapolation with this observed order.
    Richardson {
        /// Observed order p.
        order: f64,
    },
    /// The finest level's value: the three finest levels do not converge monotonically.
    FinestNonMonotone,
    /// The finest level's value: fewer than three levels (or unequal refinement ratios).
    FinestTooFewLevels,
}

impl std::fmt::Display for ReferenceMethod {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ReferenceMethod::Richardson { order } => write!(f, "Richardson, observed order {order:.2}"),
            ReferenceMethod::FinestNonMonotone => write!(f, "finest value (not monotone)"),
            ReferenceMethod::FinestTooFewLevels => write!(f, "finest value (fewer than 3 levels)"),
        }
    }
}

/// A reference value with its method.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reference {
    /// The value.
    pub value: f64,
    /// How it was obtained.
    pub method: ReferenceMethod,
    /// The finest level used.
    pub finest_level: usize,
}

/// The reference from `(level, value)` samples, ascending in level; `None` for no samples.
pub fn richardson(samples: &[(usize, f64)]) -> Option<Reference> {
    let &(finest_level, f3) = samples.last()?;
    let finest = |method| Some(Reference { value: f3, method, finest_level });
    let n = samples.len();
    if n < 3 {
        return finest(ReferenceMethod::FinestTooFewLevels);
    }
    let [(n1, f1), (n2, f2), _] = [samples[n - 3], samples[n - 2], samples[n - 1]];
    if n1 == 0 || n2 == 0 || n2 * n2 != n1 * finest_level {
        return finest(ReferenceMethod::FinestTooFewLevels);
    }
    let ratio = n2 as f64 / n1 as f64;
    let (d1, d2) = (f2 - f1, f3 - f2);
    if !(d1 * d2 > 0.0 && d2.abs() < d1.abs()) {
        return finest(ReferenceMethod::FinestNonMonotone);
    }
    let q = d1 / d2;
    Some(Reference {
        value: f3 + d2 / (q - 1.0),
        method: ReferenceMethod::Richardson { order: q.ln() / ratio.ln() },
        finest_level,
    })
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::panic)]
mod tests {
    use super::*;

    /// f(h) = 2 + 3 h² with h = 1/N: extrapolation recovers 2 and order 2 up to round-off.
    #[test]
    fn recovers_the_limit_and_order_of_a_power_law() {
        let s: Vec<(usize, f64)> = [16, 32, 64].iter().map(|&n| (n, 2.0 + 3.0 / (n * n) as f64)).collect();
        let r = richardson(&s).unwrap();
        assert!((r.value - 2.0).abs() < 1e-13);
        match r.method {
            ReferenceMethod::Richardson { order } => assert!((order - 2.0).abs() < 1e-9),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn falls_back_to_the_finest_value() {
        let r = richardson(&[(16, 1.0), (32, 2.0), (64, 1.5)]).unwrap();
        assert_eq!((r.value, r.method), (1.5, ReferenceMethod::FinestNonMonotone));
        let r = richardson(&[(32, 2.0), (64, 1.5)]).unwrap();
        assert_eq!(r.method, ReferenceMethod::FinestTooFewLevels);
        let r = richardson(&[(16, 1.0), (32, 2.0), (128, 2.5)]).unwrap();
        assert_eq!(r.method, ReferenceMethod::FinestTooFewLevels);
        assert!(richardson(&[]).is_none());
    }
}
