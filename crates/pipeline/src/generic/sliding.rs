//! The small-sliding check: every contact is paired once, in the undeformed configuration
//! (`sliding = "small"`), so a pair whose node has moved far along the segment it was paired
//! with no longer describes the bodies' contact. After each step the relative tangential
//! displacement of every pair in contact is compared with the length of its segment:
//!
//! ```text
//! ratio_k = |s_k| / h_k          s_k = (B_T u)_k: relative tangential displacement of pair k
//!                                h_k: length of the segment (edge of the pair's segment curve)
//!                                     the pair's node was projected on; at a node between two
//!                                     edges, the shorter
//! a note when max_k ratio_k > SMALL_SLIDING_FRACTION = 0.5 (pairs in contact only)
//! ```
//!
//! Why 0.5: the pairing freezes the projection's shape-function weights. A node paired at the
//! middle of its segment leaves that segment after half a segment of travel, and every node has
//! then moved further than the distance over which the mesh resolves the other side's
//! displacement and geometry; the error of the frozen pairing is then no longer one of the mesh's
//! own size. Below the fraction, on flat or gently curved interfaces, the frozen pairing differs
//! from a re-paired one by less than the discretisation error. An open pair carries no force and
//! is left out (a pair that slid and closes again is counted at the step it is in contact).

use contact2d_contact::{BuiltProblem, ContactSolution, PairState};

/// The largest relative tangential displacement of a pair in contact, as a fraction of its
/// segment's length, that small sliding accepts without a note.
pub const SMALL_SLIDING_FRACTION: f64 = 0.5;

/// The largest sliding ratio an interface reached, and where.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Worst {
    /// The step (from 1).
    step: usize,
    /// `|s_k| / h_k`.
    ratio: f64,
    /// The pair's node's arc length along the paired curve.
    s: f64,
}

/// One interface's watch.
#[derive(Debug, Clone, PartialEq)]
struct Watched {
    name: String,
    first: usize,
    /// `h_k` per pair of the interface.
    segment: Vec<f64>,
    master_s: Vec<f64>,
    /// The first step (from 1) past the fraction.
    first_past: Option<usize>,
    worst: Option<Worst>,
}

/// The sliding ratios of every interface, followed step by step.
#[derive(Debug, Clone, PartialEq)]
pub struct SlidingWatch {
    interfaces: Vec<Watched>,
    steps: usize,
}

impl SlidingWatch {
    /// A watch of no interface: no note, ever.
    pub fn none() -> SlidingWatch {
        SlidingWatch { interfaces: vec![], steps: 0 }
    }

    /// Before the first step of a history of `built`: each pair's segment length `h_k`.
    pub fn new(built: &BuiltProblem) -> SlidingWatch {
        let pairs = &built.problem.pairs;
        let interfaces = built
            .interfaces
            .iter()
            .map(|info| {
                let contour = &info.slave_contour;
                let spans: Vec<(f64, f64)> =
                    contour.edges.iter().map(|e| (contour.arc_length[e.first], contour.edge_length(e, 1.0))).collect();
                let range = info.pairs.clone();
                let segment = pairs[range.clone()].iter().map(|p| segment_length(&spans, p.slave_arc_length)).collect();
                let master_s = pairs[range.clone()].iter().map(|p| p.master_arc_length).collect();
                Watched {
                    name: info.name.clone(),
                    first: range.start,
                    segment,
                    master_s,
                    first_past: None,
                    worst: None,
                }
            })
            .collect();
        SlidingWatch { interfaces, steps: 0 }
    }

    /// Takes the next step's solution.
    pub fn observe(&mut self, solution: &ContactSolution) {
        self.steps += 1;
        for w in &mut self.interfaces {
            let mut step_worst: Option<Worst> = None;
            for (j, (&h, &s)) in w.segment.iter().zip(&w.master_s).enumerate() {
                let k = w.first + j;
                let (Some(state), Some(slip)) = (solution.state.get(k), solution.slip.get(k)) else { continue };
                if *state == PairState::Free || h <= 0.0 || !slip.is_finite() {
                    continue;
                }
                let ratio = slip.abs() / h;
                if step_worst.is_none_or(|b| ratio > b.ratio) {
                    step_worst = Some(Worst { step: self.steps, ratio, s });
                }
            }
            let Some(now) = step_worst else { continue };
            if now.ratio > SMALL_SLIDING_FRACTION && w.first_past.is_none() {
                w.first_past = Some(self.steps);
            }
            if w.worst.is_none_or(|b| now.ratio > b.ratio) {
                w.worst = Some(now);
            }
        }
    }

    /// The largest ratio of each interface over the steps seen (`None`: no pair was in contact).
    pub fn max_ratios(&self) -> Vec<(String, Option<f64>)> {
        self.interfaces.iter().map(|w| (w.name.clone(), w.worst.map(|b| b.ratio))).collect()
    }

    /// A note per interface whose ratio passed [`SMALL_SLIDING_FRACTION`]: the contact, the
    /// first step past it, and the largest ratio with its step and place.
    pub fn notes(&self) -> Vec<String> {
        self.interfaces
            .iter()
            .filter_map(|w| {
                let (first, worst) = (w.first_past?, w.worst?);
                Some(format!(
                    "contact \"{}\": sliding beyond small sliding from step {first} on: a pair in contact moved \
                     {:.3} times the length of the segment it was paired with (largest at step {}, s = {:.4}; \
                     the limit is {SMALL_SLIDING_FRACTION}); the pairs were formed once in the undeformed \
                     configuration (sliding = \"small\"), so past that step the gap, the contact zone and the \
                     pressure do not follow the motion",
                    w.name, worst.ratio, worst.step, worst.s
                ))
            })
            .collect()
    }
}

/// The length of the edge at arc length `s` (the shorter of two at a shared node); `spans` are
/// the edges' `(start, length)` in order along the curve.
fn segment_length(spans: &[(f64, f64)], s: f64) -> f64 {
    let total = spans.last().map_or(0.0, |(a, h)| a + h);
    let tol = 1e-9 * total.max(f64::MIN_POSITIVE);
    let after = spans.partition_point(|(start, _)| *start <= s + tol);
    spans[after.saturating_sub(2)..after]
        .iter()
        .filter(|(start, h)| *start - tol <= s && s <= start + h + tol)
        .map(|(_, h)| *h)
        .fold(f64::INFINITY, f64::min)
        .min(total.max(0.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_segment_at_a_shared_node_is_the_shorter() {
        let spans = [(0.0, 1.0), (1.0, 0.5), (1.5, 2.0)];
        assert_eq!(segment_length(&spans, 0.3), 1.0);
        assert_eq!(segment_length(&spans, 1.0), 0.5);
        assert_eq!(segment_length(&spans, 1.5), 0.5);
        assert_eq!(segment_length(&spans, 3.0), 2.0);
        assert_eq!(segment_length(&spans, 0.0), 1.0);
    }
}
