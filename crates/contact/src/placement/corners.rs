//! Which master corners carry the placed zone ends, and how far each may move.
//!
//! ```text
//! a corner may move strictly between its neighbouring corners of the generated mesh, keeping
//! 6 % of the corner spacing from each (placement_limits), and the b node stays that far below
//! the l node (below, above); of the corner pairs that can hold (b, l), the one that keeps the
//! corner l was found on and moves the corners least
//! ```

use super::{PlacedCase, corner_range, node_coordinates};

/// The corners to place at l and b: each within its range and keeping 6 % of the corner
/// spacing from its neighbours (placed or not), the b corner before the l corner along c; of the
/// candidates, the pair that keeps `keep_l` for l if it can and moves the corners least.
pub(super) fn assign_corners<C: PlacedCase>(base: &C, l: f64, b: f64, keep_l: usize) -> Option<(usize, usize)> {
    let eta = node_coordinates(base);
    let corners: Vec<usize> = (1..eta.len().saturating_sub(1) / 2).map(|c| 2 * c).collect();
    let mut best: Option<(f64, usize, usize)> = None;
    for &cl in &corners {
        for &cb in corners.iter().filter(|c| eta[**c] < eta[cl]) {
            let fits = |c: usize, x: f64, limits: fn([f64; 2], f64) -> [f64; 2], other: f64| {
                corner_range(base, c)
                    .map(|r| limits(placement_limits(r), other))
                    .is_some_and(|[lo, hi]| x > lo && x < hi)
            };
            if fits(cl, l, above, b) && fits(cb, b, below, l) {
                // Keeping the corner l was found on avoids a new l search (and a cycle of them).
                let moved = if cl == keep_l { 0.0 } else { 1.0 };
                let cost = moved + (eta[cl] - l).abs() + (eta[cb] - b).abs();
                if best.is_none_or(|(c, _, _)| cost < c) {
                    best = Some((cost, cl, cb));
                }
            }
        }
    }
    best.map(|(_, cl, cb)| (cl, cb))
}

/// Where a corner with neighbour range `[lo, hi]` (two corner spacings) may go: 6 % of the
/// spacing from each neighbour (thinner elements are still valid, the interior being relaxed).
pub(super) fn placement_limits([lo, hi]: [f64; 2]) -> [f64; 2] {
    let d = 0.03 * (hi - lo);
    [lo + d, hi - d]
}

/// Limits of the l node above a b node at `b` (about 6 % of the corner spacing clear).
pub(super) fn above([lo, hi]: [f64; 2], b: f64) -> [f64; 2] {
    [lo.max(b + 0.03 * (hi - lo)), hi]
}

/// Limits of the b node below an l node at `l`.
pub(super) fn below([lo, hi]: [f64; 2], l: f64) -> [f64; 2] {
    [lo, hi.min(l - 0.03 * (hi - lo))]
}
