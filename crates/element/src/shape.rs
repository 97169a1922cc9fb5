//! Shape functions of the isoparametric elements, in Gmsh's node order.
//!
//! Quadrilaterals live on the reference square `(ξ, η) ∈ [-1, 1]²`, triangles on the reference
//! triangle `r, s ≥ 0, r + s ≤ 1`, edges on `ξ ∈ [-1, 1]`.
//!
//! ```text
//!  Quad4 / Quad8 / Quad9              Tri3 / Tri6          Line2 / Line3
//!
//!  η                                  s
//!  3-----6-----2                      2                    0-----2-----1   → ξ
//!  |           |                      |\                  -1     0     1
//!  7     8     5   → ξ                5  4
//!  |           |                      |    \
//!  0-----4-----1                      0--3--1   → r
//! ```
//!
//! Quad4 uses nodes 0-3, Quad8 adds the mid-side nodes 4-7 (serendipity), Quad9 adds the
//! centre node 8 (Lagrange, `N = ℓ_a(ξ) ℓ_b(η)`). Tri6 mid-side nodes: 3 on 0-1, 4 on 1-2, 5 on
//! 2-0. Line3 lists the two end nodes first and the mid node last, as Gmsh does.

/// Largest number of nodes of any element (Quad9).
pub const MAX_NODES: usize = 9;

/// The 2D isoparametric element types.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ElementType {
    /// 3-node linear triangle.
    Tri3,
    /// 6-node quadratic triangle.
    Tri6,
    /// 4-node bilinear quadrilateral.
    Quad4,
    /// 8-node serendipity quadrilateral.
    Quad8,
    /// 9-node Lagrange quadrilateral (Bathe's 9-node element).
    Quad9,
}

/// The 1D edge (boundary) element types.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum EdgeType {
    /// 2-node linear edge.
    Line2,
    /// 3-node quadratic edge (ends first, mid node last).
    Line3,
}

/// Values and reference-coordinate gradients of the shape functions at one point.
///
/// Only the first `len` entries are meaningful; the arrays have room for the largest element
/// so that evaluating shape functions never allocates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShapeEval {
    /// Number of nodes.
    pub len: usize,
    /// `N_a(ξ)`.
    pub n: [f64; MAX_NODES],
    /// `[∂N_a/∂ξ, ∂N_a/∂η]` (for triangles `[∂N_a/∂r, ∂N_a/∂s]`).
    pub dn: [[f64; 2]; MAX_NODES],
}

impl ShapeEval {
    fn new(len: usize) -> Self {
        ShapeEval { len, n: [0.0; MAX_NODES], dn: [[0.0; 2]; MAX_NODES] }
    }

    /// The values `N_a` as a slice.
    pub fn values(&self) -> &[f64] {
        &self.n[..self.len]
    }

    /// The gradients `∂N_a/∂ξ` as a slice.
    pub fn gradients(&self) -> &[[f64; 2]] {
        &self.dn[..self.len]
    }
}

/// The 1D quadratic Lagrange polynomials at nodes -1, 1, 0 (Gmsh order) and their derivatives.
fn lagrange3(x: f64) -> ([f64; 3], [f64; 3]) {
    ([0.5 * x * (x - 1.0), 0.5 * x * (x + 1.0), 1.0 - x * x], [x - 0.5, x + 0.5, -2.0 * x])
}

/// Reference coordinates of the quadrilateral nodes 0..9 in Gmsh order.
const QUAD_NODES: [[f64; 2]; 9] =
    [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0], [0.0, -1.0], [1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, 0.0]];

/// Reference coordinates of the triangle nodes 0..6 in Gmsh order.
const TRI_NODES: [[f64; 2]; 6] = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [0.5, 0.0], [0.5, 0.5], [0.0, 0.5]];

/// For each Quad9 node, the index (into `lagrange3`'s order -1, 1, 0) of its ξ and η factors.
const QUAD9_FACTORS: [[usize; 2]; 9] = [[0, 0], [1, 0], [1, 1], [0, 1], [2, 0], [1, 2], [2, 1], [0, 2], [2, 2]];

impl ElementType {
    /// All 2D element types.
    pub const ALL: [ElementType; 5] =
        [ElementType::Tri3, ElementType::Tri6, ElementType::Quad4, ElementType::Quad8, ElementType::Quad9];

    /// Number of nodes.
    pub fn num_nodes(self) -> usize {
        match self {
            ElementType::Tri3 => 3,
            ElementType::Tri6 => 6,
            ElementType::Quad4 => 4,
            ElementType::Quad8 => 8,
            ElementType::Quad9 => 9,
        }
    }

    /// Whether the reference cell is the triangle (else the square).
    pub fn is_triangle(self) -> bool {
        matches!(self, ElementType::Tri3 | ElementType::Tri6)
    }

    /// Polynomial degree of the complete polynomial space the element reproduces.
    pub fn degree(self) -> usize {
        match self {
            ElementType::Tri3 | ElementType::Quad4 => 1,
            _ => 2,
        }
    }

    /// Reference coordinates of the nodes, in Gmsh order.
    pub fn reference_nodes(self) -> &'static [[f64; 2]] {
        if self.is_triangle() { &TRI_NODES[..self.num_nodes()] } else { &QUAD_NODES[..self.num_nodes()] }
    }

    /// The boundary edges as local node lists `[start, end, mid]` (mid only for quadratic elements),
    /// counter-clockwise, in Gmsh's edge order.
    pub fn edges(self) -> &'static [[usize; 3]] {
        match self {
            ElementType::Tri3 | ElementType::Tri6 => &[[0, 1, 3], [1, 2, 4], [2, 0, 5]],
            _ => &[[0, 1, 4], [1, 2, 5], [2, 3, 6], [3, 0, 7]],
        }
    }

    /// The edge type of this element's sides.
    pub fn edge_type(self) -> EdgeType {
        if self.degree() == 1 { EdgeType::Line2 } else { EdgeType::Line3 }
    }

    /// Shape functions and their reference gradients at `xi`.
    pub fn eval(self, xi: [f64; 2]) -> ShapeEval {
        match self {
            ElementType::Tri3 => tri3(xi),
            ElementType::Tri6 => tri6(xi),
            ElementType::Quad4 => quad4(xi),
            ElementType::Quad8 => quad8(xi),
            ElementType::Quad9 => quad9(xi),
        }
    }
}

fn tri3([r, s]: [f64; 2]) -> ShapeEval {
    let mut e = ShapeEval::new(3);
    e.n[..3].copy_from_slice(&[1.0 - r - s, r, s]);
    e.dn[..3].copy_from_slice(&[[-1.0, -1.0], [1.0, 0.0], [0.0, 1.0]]);
    e
}

fn tri6([r, s]: [f64; 2]) -> ShapeEval {
    let mut e = ShapeEval::new(6);
    let l = [1.0 - r - s, r, s];
    // ∂L/∂r and ∂L/∂s of the three area coordinates.
    let dl = [[-1.0, -1.0], [1.0, 0.0], [0.0, 1.0]];
    for a in 0..3 {
        e.n[a] = l[a] * (2.0 * l[a] - 1.0);
        e.dn[a] = dl[a].map(|d| (4.0 * l[a] - 1.0) * d);
    }
    for (m, (a, b)) in [(0, 1), (1, 2), (2, 0)].into_iter().enumerate() {
        e.n[3 + m] = 4.0 * l[a] * l[b];
        e.dn[3 + m] = [4.0 * (dl[a][0] * l[b] + l[a] * dl[b][0]), 4.0 * (dl[a][1] * l[b] + l[a] * dl[b][1])];
    }
    e
}

fn quad4([x, y]: [f64; 2]) -> ShapeEval {
    let mut e = ShapeEval::new(4);
    for (a, [xa, ya]) in QUAD_NODES[..4].iter().copied().enumerate() {
        e.n[a] = 0.25 * (1.0 + xa * x) * (1.0 + ya * y);
        e.dn[a] = [0.25 * xa * (1.0 + ya * y), 0.25 * ya * (1.0 + xa * x)];
    }
    e
}

fn quad8([x, y]: [f64; 2]) -> ShapeEval {
    let mut e = ShapeEval::new(8);
    for (a, [xa, ya]) in QUAD_NODES[..8].iter().copied().enumerate() {
        if a < 4 {
            let (fx, fy, g) = (1.0 + xa * x, 1.0 + ya * y, xa * x + ya * y - 1.0);
            e.n[a] = 0.25 * fx * fy * g;
            e.dn[a] = [0.25 * xa * fy * (g + fx), 0.25 * ya * fx * (g + fy)];
        } else if xa == 0.0 {
            e.n[a] = 0.5 * (1.0 - x * x) * (1.0 + ya * y);
            e.dn[a] = [-x * (1.0 + ya * y), 0.5 * ya * (1.0 - x * x)];
        } else {
            e.n[a] = 0.5 * (1.0 + xa * x) * (1.0 - y * y);
            e.dn[a] = [0.5 * xa * (1.0 - y * y), -y * (1.0 + xa * x)];
        }
    }
    e
}

fn quad9([x, y]: [f64; 2]) -> ShapeEval {
    let mut e = ShapeEval::new(9);
    let (lx, dlx) = lagrange3(x);
    let (ly, dly) = lagrange3(y);
    for (a, [i, j]) in QUAD9_FACTORS.iter().copied().enumerate() {
        e.n[a] = lx[i] * ly[j];
        e.dn[a] = [dlx[i] * ly[j], lx[i] * dly[j]];
    }
    e
}

impl EdgeType {
    /// Number of nodes.
    pub fn num_nodes(self) -> usize {
        match self {
            EdgeType::Line2 => 2,
            EdgeType::Line3 => 3,
        }
    }

    /// Reference coordinates of the nodes in Gmsh order (`-1, 1` then `0` for Line3).
    pub fn reference_nodes(self) -> &'static [f64] {
        match self {
            EdgeType::Line2 => &[-1.0, 1.0],
            EdgeType::Line3 => &[-1.0, 1.0, 0.0],
        }
    }

    /// Shape functions `N_a(ξ)` and derivatives `dN_a/dξ` (only the first `num_nodes` entries).
    pub fn eval(self, xi: f64) -> ([f64; 3], [f64; 3]) {
        match self {
            EdgeType::Line2 => ([0.5 * (1.0 - xi), 0.5 * (1.0 + xi), 0.0], [-0.5, 0.5, 0.0]),
            EdgeType::Line3 => lagrange3(xi),
        }
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn kronecker(t: ElementType) {
        for (j, xj) in t.reference_nodes().iter().enumerate() {
            let e = t.eval(*xj);
            for i in 0..t.num_nodes() {
                let expected = if i == j { 1.0 } else { 0.0 };
                assert!((e.n[i] - expected).abs() < 1e-14, "{t:?} N_{i}(x_{j}) = {}", e.n[i]);
            }
        }
    }

    #[test]
    fn shape_functions_are_kronecker_at_nodes() {
        ElementType::ALL.into_iter().for_each(kronecker);
        for t in [EdgeType::Line2, EdgeType::Line3] {
            for (j, &xj) in t.reference_nodes().iter().enumerate() {
                let (n, _) = t.eval(xj);
                for (i, ni) in n.iter().take(t.num_nodes()).enumerate() {
                    assert!((ni - if i == j { 1.0 } else { 0.0 }).abs() < 1e-14);
                }
            }
        }
    }

    fn reference_point(t: ElementType) -> impl Strategy<Value = [f64; 2]> {
        (0.0..1.0f64, 0.0..1.0f64)
            .prop_map(move |(a, b)| if t.is_triangle() { [a * (1.0 - b), b] } else { [2.0 * a - 1.0, 2.0 * b - 1.0] })
    }

    proptest! {
        /// Partition of unity, zero-sum gradients and reproduction of x and y at random points.
        #[test]
        fn partition_of_unity_and_linear_completeness(ti in 0usize..5, u in 0.0..1.0f64, v in 0.0..1.0f64) {
            let t = ElementType::ALL[ti];
            let xi = if t.is_triangle() { [u * (1.0 - v), v] } else { [2.0 * u - 1.0, 2.0 * v - 1.0] };
            let e = t.eval(xi);
            let nodes = t.reference_nodes();
            let sum: f64 = e.values().iter().sum();
            prop_assert!((sum - 1.0).abs() < 1e-13);
            for k in 0..2 {
                let dsum: f64 = e.gradients().iter().map(|g| g[k]).sum();
                prop_assert!(dsum.abs() < 1e-13);
                let xk: f64 = e.values().iter().zip(nodes).map(|(n, x)| n * x[k]).sum();
                prop_assert!((xk - xi[k]).abs() < 1e-13);
            }
        }

        /// Gradients agree with central finite differences.
        #[test]
        fn gradients_match_finite_differences(ti in 0usize..5, xi in reference_point(ElementType::Quad9)) {
            let t = ElementType::ALL[ti];
            let xi = if t.is_triangle() { [0.5 * (xi[0] + 1.0) * 0.5, 0.5 * (xi[1] + 1.0) * 0.5] } else { xi };
            let h = 1e-6;
            let e = t.eval(xi);
            for k in 0..2 {
                let mut p = xi;
                let mut m = xi;
                p[k] += h;
                m[k] -= h;
                let (ep, em) = (t.eval(p), t.eval(m));
                for a in 0..t.num_nodes() {
                    let fd = (ep.n[a] - em.n[a]) / (2.0 * h);
                    prop_assert!((fd - e.dn[a][k]).abs() < 1e-8, "{:?} node {} dir {}", t, a, k);
                }
            }
        }

        /// Quadratic elements reproduce every complete quadratic (x², xy, y²).
        #[test]
        fn quadratic_completeness(ti in 0usize..5, u in 0.0..1.0f64, v in 0.0..1.0f64) {
            let t = ElementType::ALL[ti];
            prop_assume!(t.degree() == 2);
            let xi = if t.is_triangle() { [u * (1.0 - v), v] } else { [2.0 * u - 1.0, 2.0 * v - 1.0] };
            let e = t.eval(xi);
            let nodes = t.reference_nodes();
            for f in [|p: [f64; 2]| p[0] * p[0], |p: [f64; 2]| p[0] * p[1], |p: [f64; 2]| p[1] * p[1]] {
                let interp: f64 = e.values().iter().zip(nodes).map(|(n, x)| n * f(*x)).sum();
                prop_assert!((interp - f(xi)).abs() < 1e-13);
            }
        }
    }

    #[test]
    fn edge_derivatives_match_finite_differences() {
        for t in [EdgeType::Line2, EdgeType::Line3] {
            for &x in &[-0.7, 0.1, 0.9] {
                let (_, d) = t.eval(x);
                let (p, m) = (t.eval(x + 1e-6).0, t.eval(x - 1e-6).0);
                for a in 0..t.num_nodes() {
                    assert!(((p[a] - m[a]) / 2e-6 - d[a]).abs() < 1e-8);
                }
            }
        }
    }
}
