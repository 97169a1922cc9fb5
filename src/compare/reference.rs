//! The reference each compared quantity is measured against, and why that one.
//!
//! ```text
//! order of preference   closed form (--reference path=value)        kind "closed_form"
//!                       published   (Solodovnikov 1998, the paper's  kind "published"
//!                                   case's `published:` quantities)
//!                       from the runs:
//!   reference level     the most accurate mesh level: the highest element order (quadratic
//!                       before linear), then the most nodes (ties: the later --mesh)
//!   reference method    of the combinations with the quantity on that level, the first by
//!                         status      converged before any other status that gave values
//!                         pairing     segment_to_segment < node_to_segment < node_to_node
//!                                     < automatic (plate_insert.pairs: node_to_segment
//!                                     < node_to_node)
//!                         algorithm   active_set < clarabel < augmented_lagrangian
//!                                     < boussinesq < penalty (exact contact before regularised)
//!                       ties keep the run order
//!   kind "richardson"   the method's three finest levels of the reference order give a clean
//!                       rate: Aitken's Δ², q∞ = q₃ − d₂² / (d₂ − d₁), d₁ = q₂ − q₁, d₂ = q₃ − q₂
//!   kind "finest"       otherwise the method's value on the reference level
//! clean rate            (1) three levels with strictly more nodes each, refined in a constant
//!                           ratio: ρ = √(N₍ₖ₊₁₎/N₍ₖ₎) (h ∝ N^(−1/2) in 2D) of the two steps
//!                           within RATIO_CONSISTENCY of each other (Aitken assumes a
//!                           geometric sequence);
//!                       (2) r = d₂/d₁ in (0, RATE_BAND.1]: one sign (no oscillation) and
//!                           contracting at least as a first-order method on halved meshes
//!                           does (r = 0.5), with room for noise; the observed order is
//!                           p = ln(1/r) / ln ρ;
//!                       (3) with a fourth level also r₀ = d₁/d₀ within a factor RATE_CONSISTENCY
//!                           of r (the rate is settled)
//! deviation             "error" |q − q_ref| / |q_ref|; on one mesh, when the reference is
//!                       another method's value there, "difference" (from that method, not an
//!                       error)
//! ```

use std::collections::BTreeMap;

use super::CompareRow;

/// How a reference was obtained (`kind` in compare.json and the tables).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum ReferenceKind {
    /// A closed form given with `--reference path=value`.
    ClosedForm,
    /// A published value (the paper's case).
    Published,
    /// Aitken's Δ² extrapolation of the reference method over its three finest levels.
    Richardson,
    /// The reference method's value on the reference (finest, highest-order) level.
    Finest,
}

impl ReferenceKind {
    /// The name in compare.json and the tables: `closed_form`, `published`, `richardson`,
    /// `finest`.
    pub fn key(self) -> &'static str {
        match self {
            Self::ClosedForm => "closed_form",
            Self::Published => "published",
            Self::Richardson => "richardson",
            Self::Finest => "finest",
        }
    }
}

/// What the rows' deviations from a reference are.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Deviation {
    /// Errors: the reference is a converged value (closed form, published, extrapolated, or a
    /// finer level than most rows').
    Error,
    /// One mesh and the reference is another method's value on it: differences from that
    /// method, not errors.
    Difference,
}

impl Deviation {
    /// `error` or `difference` (compare.json's `deviation`, the column prefixes).
    pub fn key(self) -> &'static str {
        match self {
            Self::Error => "error",
            Self::Difference => "difference",
        }
    }
}

/// A quantity's reference and how it was obtained.
#[derive(Debug, Clone, PartialEq)]
pub struct Reference {
    /// The quantity (a dotted path into the summary, `energy`, or `published:<q>`).
    pub quantity: String,
    /// How it was obtained.
    pub kind: ReferenceKind,
    /// Where it comes from: `--reference`, the publication, or the method and mesh(es), e.g.
    /// `active_set × segment_to_segment on L3.msh`.
    pub from: String,
    /// The value.
    pub value: f64,
    /// One sentence on the choice (the observed rate, or why there is no extrapolation).
    pub how: String,
    /// Whether the rows' deviations are errors or differences.
    pub deviation: Deviation,
}

/// One mesh level as the reference choice sees it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Level {
    /// The mesh file's name (as in the rows).
    pub mesh: String,
    /// Its nodes.
    pub nodes: usize,
    /// Its element order: 1 linear, 2 quadratic (the lowest of its 2D cells).
    pub order: u8,
}

/// The largest clean ratio of successive differences r = d₂/d₁ (module docs).
pub const RATE_BAND: (f64, f64) = (0.0, 0.6);

/// How far the ratios of successive differences may differ, as a factor, for the rate to count
/// as settled when four or more levels give two ratios.
pub const RATE_CONSISTENCY: f64 = 2.0;

/// How far the refinement ratios ρ of the two steps may differ, relative, for the levels to
/// count as a geometric sequence: 15 % (the bundled families: cylinder_on_block 1.91, 1.94;
/// pin_lug 1.73, 1.78).
pub const RATIO_CONSISTENCY: f64 = 0.15;

/// The rank of a pairing key, lower is more accurate (module docs).
fn pairing_rank(pairing: &str) -> usize {
    ["segment_to_segment", "node_to_segment", "node_to_node", "automatic"]
        .iter()
        .position(|p| *p == pairing)
        .unwrap_or(4)
}

/// The rank of an algorithm key, lower is more accurate (module docs).
fn algorithm_rank(algorithm: &str) -> usize {
    ["active_set", "clarabel", "augmented_lagrangian", "boussinesq", "penalty"]
        .iter()
        .position(|a| *a == algorithm)
        .unwrap_or(5)
}

/// A row that gave values (not skipped, failed or timed out).
fn ran(r: &CompareRow) -> bool {
    r.status != "skipped" && r.status != "timed_out" && !r.values.is_empty()
}

/// The reference level: the highest element order, then the most nodes, ties to the later.
fn reference_level(levels: &[Level]) -> usize {
    (0..levels.len()).max_by_key(|&l| (levels[l].order, levels[l].nodes, l)).unwrap_or(0)
}

/// The rows of each algorithm × pairing, in run order, each indexed by level.
fn combinations(rows: &[CompareRow], levels: usize) -> Vec<Vec<Option<&CompareRow>>> {
    let mut out: Vec<Vec<Option<&CompareRow>>> = vec![];
    for r in rows.iter().filter(|r| r.level < levels) {
        let same = |c: &&mut Vec<Option<&CompareRow>>| {
            c.iter().flatten().next().is_some_and(|f| f.algorithm == r.algorithm && f.pairing == r.pairing)
        };
        match out.iter_mut().find(same) {
            Some(c) => c[r.level] = Some(r),
            None => {
                let mut c = vec![None; levels];
                c[r.level] = Some(r);
                out.push(c);
            }
        }
    }
    out
}

/// The reference of every quantity; `fixed` are (quantity, value, kind, from) given outright
/// (closed forms, published values); `rows` are every combination's rows (their `level` indexes
/// `levels`).
pub fn references(
    quantities: &[String],
    fixed: &[(String, f64, ReferenceKind, String)],
    rows: &[CompareRow],
    levels: &[Level],
) -> BTreeMap<String, Reference> {
    let combos = combinations(rows, levels.len());
    let top = reference_level(levels);
    let mut out = BTreeMap::new();
    for q in quantities {
        if let Some((_, value, kind, from)) = fixed.iter().find(|f| &f.0 == q) {
            let how = format!("given ({from})");
            let reference = Reference {
                quantity: q.clone(),
                kind: *kind,
                from: from.clone(),
                value: *value,
                how,
                deviation: Deviation::Error,
            };
            out.insert(q.clone(), reference);
            continue;
        }
        let value_of =
            |c: &[Option<&CompareRow>], l: usize| c[l].filter(|r| ran(r)).and_then(|r| r.values.get(q)).copied();
        let best = combos.iter().filter(|c| value_of(c, top).is_some()).min_by_key(|c| {
            let r = c[top].unwrap_or_else(|| unreachable!("filtered on a value at the top level"));
            (r.status != "converged", pairing_rank(r.pairing), algorithm_rank(r.algorithm))
        });
        let Some(best) = best else { continue };
        let finest = best[top].unwrap_or_else(|| unreachable!("filtered on a value at the top level"));
        let name = format!("{} × {}", finest.algorithm, finest.pairing);
        // The method's levels of the reference order, coarse to fine by nodes.
        let mut same_order: Vec<usize> = (0..levels.len())
            .filter(|&l| levels[l].order == levels[top].order && value_of(best, l).is_some())
            .collect();
        same_order.sort_by_key(|&l| (levels[l].nodes, l));
        let series: Vec<(usize, f64)> =
            same_order.iter().map(|&l| (levels[l].nodes, value_of(best, l).unwrap_or(f64::NAN))).collect();
        let value_top = finest.values[q];
        let reference = match richardson(&series) {
            Ok(r) => {
                let used: Vec<&str> =
                    same_order[same_order.len() - 3..].iter().map(|&l| levels[l].mesh.as_str()).collect();
                Reference {
                    quantity: q.clone(),
                    kind: ReferenceKind::Richardson,
                    from: format!("{name} on {}", used.join(", ")),
                    value: r.value,
                    how: format!(
                        "Aitken Δ² over the three finest levels: ratio of differences r = {:.3}, refinement ρ = {:.2}, observed order p = {:.2}",
                        r.ratio, r.refinement, r.order
                    ),
                    deviation: Deviation::Error,
                }
            }
            Err(why) => Reference {
                quantity: q.clone(),
                kind: ReferenceKind::Finest,
                from: format!("{name} on {}", finest.mesh),
                value: value_top,
                how: format!("no extrapolation: {why}"),
                deviation: if levels.len() == 1 { Deviation::Difference } else { Deviation::Error },
            },
        };
        out.insert(q.clone(), reference);
    }
    out
}

/// A clean extrapolation (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Extrapolation {
    /// q∞.
    pub value: f64,
    /// r = d₂/d₁.
    pub ratio: f64,
    /// ρ of the last step, √(N₃/N₂).
    pub refinement: f64,
    /// The observed order p = ln(1/r) / ln ρ.
    pub order: f64,
}

/// Aitken's Δ² extrapolation of the last three of `series` — (nodes, value) per level, coarse
/// to fine — when the rate is clean (module docs).
///
/// # Errors
/// Why not, in words: fewer than three levels, levels not refined in a constant ratio, or a
/// rate that is not clean.
pub fn richardson(series: &[(usize, f64)]) -> Result<Extrapolation, String> {
    let n = series.len();
    if n < 3 {
        return Err(format!("{n} level(s) of the reference order, three are needed"));
    }
    let [(n1, q1), (n2, q2), (n3, q3)] = [series[n - 3], series[n - 2], series[n - 1]];
    if !(n1 < n2 && n2 < n3) {
        return Err(format!("the three finest levels have {n1}, {n2}, {n3} nodes: not refined in turn"));
    }
    let (rho1, rho2) = ((n2 as f64 / n1 as f64).sqrt(), (n3 as f64 / n2 as f64).sqrt());
    if ((rho2 - rho1) / rho1).abs() > RATIO_CONSISTENCY {
        return Err(format!(
            "refinement ratios {rho1:.2} then {rho2:.2} differ by more than {:.0} %",
            100.0 * RATIO_CONSISTENCY
        ));
    }
    let (d1, d2) = (q2 - q1, q3 - q2);
    if d2 == 0.0 {
        return Err("the two finest levels agree exactly".into());
    }
    let r = d2 / d1;
    if !(r.is_finite() && r > RATE_BAND.0 && r <= RATE_BAND.1) {
        return Err(format!("ratio of differences {r:.3} outside ({}, {}]", RATE_BAND.0, RATE_BAND.1));
    }
    if n >= 4 {
        let r0 = d1 / (q1 - series[n - 4].1);
        if !(r0 > 0.0 && (r / r0).max(r0 / r) <= RATE_CONSISTENCY) {
            return Err(format!("ratios of differences {r0:.3} then {r:.3}: the rate is not settled"));
        }
    }
    Ok(Extrapolation { value: q3 - d2 * d2 / (d2 - d1), ratio: r, refinement: rho2, order: (1.0 / r).ln() / rho2.ln() })
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;
    use crate::compare::tests::row;

    fn q() -> Vec<String> {
        vec!["q".to_string()]
    }

    /// Levels L0, L1, … of one order, each with 4× the nodes of the last (h halved).
    fn levels(n: usize, order: u8) -> Vec<Level> {
        (0..n).map(|l| Level { mesh: format!("L{l}"), nodes: 100 << (2 * l), order }).collect()
    }

    #[test]
    fn aitken_extrapolation_is_exact_for_geometric_convergence() {
        // q_n = 2 + 3 · 4^(−n) (second order on halved meshes, r = 1/4): Aitken's Δ² recovers
        // the limit 2 exactly, to round-off of the differences (~1e-15).
        let limit = |n: i32| 2.0 + 3.0 * 4f64.powi(-n);
        let mut rows: Vec<CompareRow> = (0..3).map(|l| row("active_set", "node_to_segment", l, Some(5.0))).collect();
        rows.extend((0..3).map(|l| row("penalty", "segment_to_segment", l, Some(limit(l as i32 + 1)))));
        let r = &references(&q(), &[], &rows, &levels(3, 2))["q"];
        assert!((r.value - 2.0).abs() < 1e-13, "{r:?}");
        // Segment to segment outranks node to segment whatever the algorithm and run order.
        assert_eq!(
            (r.kind, r.from.as_str()),
            (ReferenceKind::Richardson, "penalty × segment_to_segment on L0, L1, L2")
        );
        // ρ = 2 (4× the nodes), r = 1/4: observed order 2.
        assert!(r.how.contains("p = 2.00"), "{r:?}");
        assert_eq!(r.deviation, Deviation::Error);
        // A closed form takes precedence.
        let fixed = [("q".to_string(), 2.5, ReferenceKind::ClosedForm, "--reference".to_string())];
        let r = &references(&q(), &fixed, &rows, &levels(3, 2))["q"];
        assert_eq!((r.value, r.kind), (2.5, ReferenceKind::ClosedForm));
    }

    #[test]
    fn an_unclean_rate_is_not_extrapolated() {
        let halved = |values: &[f64]| -> Vec<(usize, f64)> {
            values.iter().enumerate().map(|(l, v)| (100 << (2 * l), *v)).collect()
        };
        // Growing differences (1, 2), an oscillation (+1, −0.5) and a stalled rate are refused;
        // a settled first-order rate (r = 0.5 twice) is extrapolated to its limit 0 exactly.
        for values in [[1.0, 2.0, 4.0], [1.0, 2.0, 1.5], [1.0, 1.0 + 1e-3, 1.0 + 1e-3 + 0.9e-3]] {
            assert!(richardson(&halved(&values)).is_err(), "{values:?}");
        }
        let e = richardson(&halved(&[8.0, 4.0, 2.0, 1.0])).unwrap();
        assert_eq!((e.value, e.ratio, e.order), (0.0, 0.5, 1.0));
        // Ratios 0.1 then 0.5: each in the band, but a factor 5 apart.
        assert!(richardson(&halved(&[0.0, 100.0, 110.0, 115.0])).is_err());
        // Refined 2× then 4× in h: not a geometric sequence, whatever the values.
        assert!(richardson(&[(100, 8.0), (400, 4.0), (6400, 3.0)]).unwrap_err().contains("refinement"));
        // Given out of order: not refined in turn.
        assert!(richardson(&[(400, 8.0), (100, 4.0), (1600, 3.0)]).unwrap_err().contains("not refined"));
        let rows: Vec<CompareRow> = [1.0, 2.0, 1.5]
            .iter()
            .enumerate()
            .map(|(l, v)| row("active_set", "segment_to_segment", l, Some(*v)))
            .collect();
        let r = &references(&q(), &[], &rows, &levels(3, 2))["q"];
        assert_eq!((r.value, r.kind, r.deviation), (1.5, ReferenceKind::Finest, Deviation::Error));
        assert!(r.how.contains("outside"), "{r:?}");
    }

    #[test]
    fn one_mesh_is_a_difference_from_the_most_accurate_method() {
        // The first combination to run (node to node) is not the reference: segment to
        // segment with the exact algorithm is, and penalty's segment to segment is not chosen
        // over it; a skipped combination never is.
        let rows = vec![
            row("active_set", "node_to_node", 0, Some(1.0)),
            row("penalty", "segment_to_segment", 0, Some(2.0)),
            row("active_set", "segment_to_segment", 0, Some(3.0)),
            row("clarabel", "segment_to_segment", 0, None),
        ];
        let r = &references(&q(), &[], &rows, &levels(1, 2))["q"];
        assert_eq!(
            (r.value, r.kind, r.from.as_str(), r.deviation),
            (3.0, ReferenceKind::Finest, "active_set × segment_to_segment on L0", Deviation::Difference)
        );
        // A method that did not converge yields to one that did, whatever its pairing.
        let mut rows = rows;
        rows[2].status = "max_iterations".into();
        let r = &references(&q(), &[], &rows, &levels(1, 2))["q"];
        assert_eq!(r.from, "penalty × segment_to_segment on L0");
    }

    #[test]
    fn the_reference_level_is_quadratic_before_linear_then_finest() {
        // A fine linear level (L1, 10,000 nodes) and a coarser quadratic one (L0, 2,500 nodes):
        // the quadratic is the reference level; with two levels there is no extrapolation.
        let lv = vec![
            Level { mesh: "L0".into(), nodes: 2500, order: 2 },
            Level { mesh: "L1".into(), nodes: 10_000, order: 1 },
        ];
        let rows: Vec<CompareRow> =
            [7.0, 9.0].iter().enumerate().map(|(l, v)| row("active_set", "segment_to_segment", l, Some(*v))).collect();
        let r = &references(&q(), &[], &rows, &lv)["q"];
        assert_eq!(
            (r.value, r.kind, r.from.as_str()),
            (7.0, ReferenceKind::Finest, "active_set × segment_to_segment on L0")
        );
        assert!(r.how.contains("1 level(s)"), "{r:?}");
    }
}
