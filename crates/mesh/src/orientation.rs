//! Cell orientation: which way a 2D cell's nodes run, and the node permutation that reverses it.
//!
//! A Gmsh surface meshed from a clockwise curve loop gives cells whose nodes run clockwise: the
//! isoparametric map x(ξ, η) then has det J < 0 *everywhere* in every cell. Such a cell is a valid
//! element drawn the other way round; renumbering its nodes makes it counter-clockwise with the
//! same geometry, the same shape-function space and so the same stiffness (up to the order of
//! round-off). A cell whose det J changes sign inside it is *inverted* (tangled) and no
//! renumbering helps; a cell of zero area is degenerate. Both are left alone here and reported
//! by whoever needs det J > 0 (the fem crate's `InvertedElement`).
//!
//! ```text
//! Classification (exact for T3 and Q4, necessary conditions for T6, Q8, Q9):
//!   A   = ∫ det J dξ dη = ½ ∮ (x dy − y dx)          signed area, Green's theorem on the
//!         straight (linear kinds) or parabolic (quadratic kinds) edges: per edge the integrand
//!         x y' − y x' is a cubic in the edge parameter t ∈ [−1, 1], so Simpson's rule
//!         (f(−1) + 4 f(0) + f(1)) / 3 integrates it exactly
//!   c_i = t_out(i) × t_back(i)                         at each corner i: the tangent of the edge
//!         leaving i towards the next corner times the tangent of the edge leaving i towards the
//!         previous corner; det J at the corner is a positive multiple of c_i, because on an edge
//!         the map depends on that edge's nodes only: t = x_j − x_i (linear), (−3 x_i + 4 x_m − x_j)/2
//!         (quadratic, m the mid node)
//!   counter-clockwise:  A > 0 and every c_i > 0
//!   clockwise:          A < 0 and every c_i < 0
//!   tangled:            anything else (det J changes sign, or a zero is met: degenerate)
//! ```
//! For T3 det J is constant and for Q4 it is affine in (ξ, η), so the corners decide its sign
//! everywhere; for the quadratic kinds a sign change strictly inside the cell with the right sign
//! at the corners and in the mean is possible and is left to the fem crate's Gauss-point check.
//!
//! The reversal keeps Gmsh's node-order convention: it swaps the two parameter directions
//! (quadrangles: ξ ↔ η; triangles: the corners 1 ↔ 2), so node 0 stays first, the corners run
//! the other way and every mid node stays on its edge. New node k is old node `perm[k]`:
//! ```text
//!   Q4, Q8, Q9                                   T3, T6
//!   3 ── 6 ── 2        1 ── 5 ── 2               2                 1
//!   │         │        │         │               │ `.              │ `.
//!   7    8    5   ──▶  4    8    6               5   4     ──▶     3   4
//!   │         │        │         │               │     `.          │     `.
//!   0 ── 4 ── 1        0 ── 7 ── 3               0 ── 3 ── 1       0 ── 5 ── 2
//!   counter-clockwise  clockwise (and back)
//!   Q4 perm [0, 3, 2, 1]                         T3 perm [0, 2, 1]
//!   Q8 perm [0, 3, 2, 1, 7, 6, 5, 4]             T6 perm [0, 2, 1, 5, 4, 3]
//!   Q9 perm [0, 3, 2, 1, 7, 6, 5, 4, 8]
//! ```
//! (The drawings label each position by the old node that the new cell puts there.) Each
//! permutation is its own inverse.

use crate::mesh::{CellKind, Mesh};

/// Which way the nodes of a 2D cell run (see the module doc for the exact test).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Orientation {
    /// det J > 0 at every corner and in the mean: the orientation every element kernel expects.
    CounterClockwise,
    /// det J < 0 at every corner and in the mean: a valid cell numbered the other way round.
    Clockwise,
    /// det J changes sign (an inverted cell) or vanishes (a degenerate cell).
    Tangled,
}

/// The node permutation that reverses a 2D cell of `kind` (new node `k` is old node `perm[k]`),
/// `None` for a kind that is not 2D. See the module doc for the drawings.
pub fn reversing_permutation(kind: CellKind) -> Option<&'static [usize]> {
    Some(match kind {
        CellKind::Tri3 => &[0, 2, 1],
        CellKind::Tri6 => &[0, 2, 1, 5, 4, 3],
        CellKind::Quad4 => &[0, 3, 2, 1],
        CellKind::Quad8 => &[0, 3, 2, 1, 7, 6, 5, 4],
        CellKind::Quad9 => &[0, 3, 2, 1, 7, 6, 5, 4, 8],
        _ => return None,
    })
}

/// Corner count and whether each edge has a mid node, for a 2D kind.
fn edges_of(kind: CellKind) -> Option<(usize, bool)> {
    Some(match kind {
        CellKind::Tri3 => (3, false),
        CellKind::Tri6 => (3, true),
        CellKind::Quad4 => (4, false),
        CellKind::Quad8 | CellKind::Quad9 => (4, true),
        _ => return None,
    })
}

fn cross(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

/// Tangent at `a` of the edge from `a` to `b` (mid node `m` for quadratic edges), per unit of
/// the edge parameter t ∈ [−1, 1] up to a positive factor.
fn tangent_at_start(a: [f64; 2], m: Option<[f64; 2]>, b: [f64; 2]) -> [f64; 2] {
    match m {
        None => [b[0] - a[0], b[1] - a[1]],
        Some(m) => [(-3.0 * a[0] + 4.0 * m[0] - b[0]) / 2.0, (-3.0 * a[1] + 4.0 * m[1] - b[1]) / 2.0],
    }
}

/// ∫ (x y' − y x') dt along the edge `a` → `b` (mid node `m` at t = 0 for quadratic edges).
fn edge_green(a: [f64; 2], m: Option<[f64; 2]>, b: [f64; 2]) -> f64 {
    match m {
        None => cross(a, b),
        Some(m) => {
            let d_start = [(-3.0 * a[0] + 4.0 * m[0] - b[0]) / 2.0, (-3.0 * a[1] + 4.0 * m[1] - b[1]) / 2.0];
            let d_mid = [(b[0] - a[0]) / 2.0, (b[1] - a[1]) / 2.0];
            let d_end = [(a[0] - 4.0 * m[0] + 3.0 * b[0]) / 2.0, (a[1] - 4.0 * m[1] + 3.0 * b[1]) / 2.0];
            (cross(a, d_start) + 4.0 * cross(m, d_mid) + cross(b, d_end)) / 3.0
        }
    }
}

/// The signed area A = ∫ det J dξ dη of a 2D cell (Gmsh node order), exact for every kind;
/// `None` for a kind that is not 2D or a wrong number of coordinates.
pub fn signed_area(kind: CellKind, coords: &[[f64; 2]]) -> Option<f64> {
    let (nc, quadratic) = edges_of(kind)?;
    if coords.len() != kind.nodes_per_cell() {
        return None;
    }
    let twice: f64 =
        (0..nc).map(|i| edge_green(coords[i], quadratic.then(|| coords[nc + i]), coords[(i + 1) % nc])).sum();
    Some(0.5 * twice)
}

/// The orientation of a 2D cell from its node coordinates in Gmsh order; `None` for a kind that
/// is not 2D or a wrong number of coordinates.
pub fn cell_orientation(kind: CellKind, coords: &[[f64; 2]]) -> Option<Orientation> {
    let (nc, quadratic) = edges_of(kind)?;
    let area = signed_area(kind, coords)?;
    let mid = |edge: usize| quadratic.then(|| coords[nc + edge]);
    let mut positive = area > 0.0;
    let mut negative = area < 0.0;
    for i in 0..nc {
        let next = (i + 1) % nc;
        let prev = (i + nc - 1) % nc;
        let out = tangent_at_start(coords[i], mid(i), coords[next]);
        let back = tangent_at_start(coords[i], mid(prev), coords[prev]);
        let c = cross(out, back);
        positive &= c > 0.0;
        negative &= c < 0.0;
    }
    Some(if positive {
        Orientation::CounterClockwise
    } else if negative {
        Orientation::Clockwise
    } else {
        Orientation::Tangled
    })
}

impl Mesh {
    /// Renumbers every clockwise 2D cell (see [`cell_orientation`]) with
    /// [`reversing_permutation`] so that its nodes run counter-clockwise; returns how many cells
    /// were flipped. Counter-clockwise and tangled (inverted or degenerate) cells are left as they
    /// are. Idempotent; 1D and 0D cells are never touched.
    pub fn orient_cells_counter_clockwise(&mut self) -> usize {
        let mut flipped = 0;
        let points = &self.points;
        for block in &mut self.blocks {
            let Some(perm) = reversing_permutation(block.kind) else { continue };
            let n = perm.len();
            for cell in block.nodes.chunks_exact_mut(n) {
                let Some(coords) = cell.iter().map(|v| points.get(v.0).copied()).collect::<Option<Vec<_>>>() else {
                    continue;
                };
                if cell_orientation(block.kind, &coords) == Some(Orientation::Clockwise) {
                    let old = cell.to_vec();
                    for (k, &p) in perm.iter().enumerate() {
                        cell[k] = old[p];
                    }
                    flipped += 1;
                }
            }
        }
        flipped
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;
    use crate::generate::rectangle;

    const KINDS: [CellKind; 5] = [CellKind::Tri3, CellKind::Tri6, CellKind::Quad4, CellKind::Quad8, CellKind::Quad9];

    /// Reference cells in Gmsh order: the unit triangle and the square [−1, 1]².
    fn reference(kind: CellKind) -> Vec<[f64; 2]> {
        match kind {
            CellKind::Tri3 | CellKind::Tri6 => {
                vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [0.5, 0.0], [0.5, 0.5], [0.0, 0.5]][..kind.nodes_per_cell()]
                    .to_vec()
            }
            _ => vec![
                [-1.0, -1.0],
                [1.0, -1.0],
                [1.0, 1.0],
                [-1.0, 1.0],
                [0.0, -1.0],
                [1.0, 0.0],
                [0.0, 1.0],
                [-1.0, 0.0],
                [0.0, 0.0],
            ][..kind.nodes_per_cell()]
                .to_vec(),
        }
    }

    #[test]
    fn reversal_swaps_the_parameter_directions_and_is_an_involution() {
        for kind in KINDS {
            let perm = reversing_permutation(kind).unwrap();
            let x = reference(kind);
            for (k, &p) in perm.iter().enumerate() {
                assert_eq!(perm[p], k, "{kind:?}: not an involution");
                // New node k sits where the reference node k sits after swapping the axes.
                assert_eq!(x[p], [x[k][1], x[k][0]], "{kind:?} node {k}");
            }
        }
        assert!(reversing_permutation(CellKind::Line3).is_none());
    }

    #[test]
    fn signed_area_is_exact_and_changes_sign_with_the_reversal() {
        // A parabolic edge: the bottom mid node of [−1, 1]² raised by h bulges the edge inwards;
        // the area lost is the parabolic segment 2/3 · 2 · h (Archimedes).
        let h = 0.3;
        let mut x = reference(CellKind::Quad9);
        x[4][1] += h;
        let area = signed_area(CellKind::Quad9, &x).unwrap();
        assert!((area - (4.0 - 4.0 / 3.0 * h)).abs() < 1e-14, "{area}");
        for kind in KINDS {
            let x = reference(kind);
            let perm = reversing_permutation(kind).unwrap();
            let y: Vec<_> = perm.iter().map(|&p| x[p]).collect();
            let expect = if matches!(kind, CellKind::Tri3 | CellKind::Tri6) { 0.5 } else { 4.0 };
            assert_eq!(signed_area(kind, &x), Some(expect));
            assert_eq!(signed_area(kind, &y), Some(-expect));
            assert_eq!(cell_orientation(kind, &x), Some(Orientation::CounterClockwise));
            assert_eq!(cell_orientation(kind, &y), Some(Orientation::Clockwise));
        }
    }

    #[test]
    fn dragged_and_degenerate_cells_are_tangled() {
        // Corner 2 of the square dragged across the diagonal 1-3: a reflex corner.
        let mut x = reference(CellKind::Quad4);
        x[2] = [-0.5, -0.5];
        assert_eq!(cell_orientation(CellKind::Quad4, &x), Some(Orientation::Tangled));
        // A mid node past the quarter point: det J < 0 at corner 0 though the area is positive.
        let mut x = reference(CellKind::Quad8);
        x[4] = [-0.6, -1.0];
        assert!(signed_area(CellKind::Quad8, &x).unwrap() > 0.0);
        assert_eq!(cell_orientation(CellKind::Quad8, &x), Some(Orientation::Tangled));
        let flat = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]];
        assert_eq!(cell_orientation(CellKind::Tri3, &flat), Some(Orientation::Tangled));
        assert_eq!(cell_orientation(CellKind::Tri3, &flat[..2]), None);
    }

    #[test]
    fn orienting_flips_only_the_clockwise_cells() {
        for kind in KINDS {
            let original = rectangle(kind, [0.0, 2.0], [0.0, 1.0], 3, 2);
            let mut mesh = original.clone();
            let perm = reversing_permutation(kind).unwrap();
            let block = mesh.blocks.iter_mut().find(|b| b.kind == kind).unwrap();
            let cells = block.len();
            // Reverse every other cell.
            for cell in block.nodes.chunks_exact_mut(perm.len()).step_by(2) {
                let old = cell.to_vec();
                for (k, &p) in perm.iter().enumerate() {
                    cell[k] = old[p];
                }
            }
            assert_eq!(mesh.orient_cells_counter_clockwise(), cells.div_ceil(2), "{kind:?}");
            assert_eq!(mesh, original, "{kind:?}");
            assert_eq!(mesh.orient_cells_counter_clockwise(), 0);
        }
    }
}
