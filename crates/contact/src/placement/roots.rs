//! Scalar root finding for the zone-end search: secant steps until bracketed, then the
//! Illinois variant of regula falsi (superlinear, never leaves a bracket).
//!
//! ```text
//! secant:    x₂ = x₁ − f₁ (x₁ − x₀)/(f₁ − f₀)       (until f changes sign; limited to the range)
//! Illinois:  the same step inside the bracket; the end kept twice has its f halved
//! ```

use crate::{ContactError, PairState};

/// Why one pass of the zone-end search stopped.
pub(super) enum Miss {
    /// A failure to report.
    Contact(ContactError),
    /// l* lies beyond its corner's range, about at this η.
    ContactEnd(f64),
    /// b* lies beyond its corner's range, about at `towards`, with l at `contact_end`.
    StickEnd { towards: f64, slip: PairState, contact_end: f64 },
}

impl From<ContactError> for Miss {
    fn from(e: ContactError) -> Self {
        Miss::Contact(e)
    }
}

/// Why a root was not found.
pub(super) enum RootMiss {
    /// The root lies beyond the range, about at this point (the secant's extrapolation).
    Outside(f64),
    /// An evaluation failed.
    Failed(ContactError),
}

impl RootMiss {
    pub(super) fn into_miss(self, outside: impl FnOnce(f64) -> Miss) -> Miss {
        match self {
            RootMiss::Outside(x) => outside(x),
            RootMiss::Failed(e) => Miss::Contact(e),
        }
    }
}

/// A root of `f` in `range` from `x0`: secant steps until the root is bracketed, then the
/// Illinois variant of regula falsi; converged when the bracket or the step is below `tol`.
/// A secant step that leaves the range at a side where `f` keeps its sign ends the search with
/// [`RootMiss::Outside`] and the extrapolated root (limited to half the range beyond it).
pub(super) fn find_root(
    mut f: impl FnMut(f64) -> Result<f64, ContactError>,
    x0: f64,
    [lo, hi]: [f64; 2],
    tol: f64,
) -> Result<f64, RootMiss> {
    let mut f = |x: f64| f(x).map_err(RootMiss::Failed);
    let reach = 0.5 * (hi - lo).max(0.0);
    let outside = |raw: f64| {
        let towards = if raw.is_nan() { 0.5 * (lo + hi) } else { raw.clamp(lo - reach, hi + reach) };
        RootMiss::Outside(towards)
    };
    if lo >= hi || lo.is_nan() || hi.is_nan() {
        return Err(outside(x0));
    }
    let x0 = x0.clamp(lo, hi);
    let h = (1e-3 * (hi - lo)).max(tol);
    let mut a = (x0, f(x0)?);
    if a.1 == 0.0 {
        return Ok(a.0);
    }
    let x1 = if x0 + h <= hi { x0 + h } else { x0 - h };
    let mut b = (x1, f(x1)?);
    // Secant until bracketed.
    while a.1.signum() == b.1.signum() {
        let raw = b.0 - b.1 * (b.0 - a.0) / (b.1 - a.1);
        if !raw.is_finite() {
            return Err(outside(f64::NAN));
        }
        let x = raw.clamp(lo, hi);
        if (x - b.0).abs() <= tol {
            // Converged by secant steps, unless the step was cut at the range's end.
            return if (raw - b.0).abs() <= tol { Ok(b.0) } else { Err(outside(raw)) };
        }
        a = b;
        b = (x, f(x)?);
        if b.1 == 0.0 {
            return Ok(b.0);
        }
    }
    // Illinois: (a, b) bracket the root, b the newest.
    loop {
        let x = b.0 - b.1 * (b.0 - a.0) / (b.1 - a.1);
        let fx = f(x)?;
        if fx == 0.0 || (x - b.0).abs() <= 0.25 * tol {
            return Ok(x);
        }
        if fx.signum() != b.1.signum() {
            a = b;
        } else {
            a.1 *= 0.5;
        }
        b = (x, fx);
        if (b.0 - a.0).abs() <= tol {
            return Ok(b.0);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn illinois_finds_a_cubic_root_to_tolerance() {
        let root = find_root(|x| Ok(x * x * x - 0.2), 0.3, [0.0, 1.0], 1e-10).unwrap_or(f64::NAN);
        assert!((root - 0.2f64.cbrt()).abs() < 1e-9);
    }

    #[test]
    fn a_root_outside_the_range_points_beyond_it() {
        let miss = find_root(|x| Ok(x - 2.0), 0.5, [0.0, 1.0], 1e-8);
        assert!(matches!(miss, Err(RootMiss::Outside(x)) if (x - 1.5).abs() < 1e-12), "points beyond the range");
    }
}
