//! The DOF numbering, written down in one place.
//!
//! ```text
//! global DOF of node n, component c (0 = u1, 1 = u2):   g = 2 n + c
//! each global DOF is Inactive (node in no body), Free(i) or Constrained(j);
//! free DOFs are numbered 0..n_free in increasing g, constrained DOFs 0..n_c likewise.
//! ```
//!
//! The unknown vector of the linear system holds the free DOFs only (Dirichlet conditions are
//! eliminated, with their exact values); full vectors of length `2 × nodes` use the global order.
//!
//! Local directions: a node with a frame `T = [n t]` (2×2 orthogonal, from a `[[fix]]` with
//! `un` / `ut` on a curve) has its two DOFs in that frame, `u' = (un, ut)`:
//!
//! ```text
//! u_a = T_a u'_a,   K' = Tᵀ K T,   f' = Tᵀ f,   B' = B T,   r = T r'     (T = I without a frame)
//! ```
//!
//! The linear system (its blocks, right-hand sides, prescribed values and reactions per
//! constrained index) is in the DOFs `u'`; the full vectors that leave it ([`DofMap::expand`],
//! [`DofMap::reactions_global`]) and that enter it ([`DofMap::restrict_free`],
//! [`DofMap::restrict_constrained`]) are in global components. Without a frame nothing is
//! multiplied: the same bits as without the feature.

/// A displacement component.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Component {
    /// u1, along x1.
    X,
    /// u2, along x2.
    Y,
    /// un, along the node's local normal (a `[[fix]]` on a curve): the DOF slot of u1.
    Normal,
    /// ut, along the node's local tangent: the DOF slot of u2.
    Tangent,
}

impl Component {
    /// 0 for X, 1 for Y.
    pub fn index(self) -> usize {
        match self {
            Component::X | Component::Normal => 0,
            Component::Y | Component::Tangent => 1,
        }
    }

    /// The paper's name: "u1" or "u2".
    pub fn name(self) -> &'static str {
        match self {
            Component::X => "u1",
            Component::Y => "u2",
            Component::Normal => "un",
            Component::Tangent => "ut",
        }
    }

    /// Whether it is a local direction (`un`, `ut`).
    pub fn is_local(self) -> bool {
        matches!(self, Component::Normal | Component::Tangent)
    }
}

/// A global DOF index `2 n + c`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Dof(pub usize);

impl Dof {
    /// The DOF of `node`'s component `c`.
    pub fn of(node: usize, c: Component) -> Dof {
        Dof(2 * node + c.index())
    }

    /// The node this DOF belongs to.
    pub fn node(self) -> usize {
        self.0 / 2
    }
}

/// The role of one global DOF.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DofKind {
    /// The node belongs to no body: no unknown.
    Inactive,
    /// An unknown of the linear system, with its index.
    Free(usize),
    /// A prescribed value, with its index among the constrained DOFs.
    Constrained(usize),
}

/// A node's local frame: unit normal `n` and tangent `t`, the columns of `T = [n t]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    /// Unit normal.
    pub n: [f64; 2],
    /// Unit tangent.
    pub t: [f64; 2],
}

impl Frame {
    /// `Tᵀ v = (n · v, t · v)`: a global vector's local components.
    pub fn to_local(&self, v: [f64; 2]) -> [f64; 2] {
        [self.n[0] * v[0] + self.n[1] * v[1], self.t[0] * v[0] + self.t[1] * v[1]]
    }

    /// `T v' = v'_n n + v'_t t`: a local vector's global components.
    pub fn to_global(&self, v: [f64; 2]) -> [f64; 2] {
        [v[0] * self.n[0] + v[1] * self.t[0], v[0] * self.n[1] + v[1] * self.t[1]]
    }
}

/// The map from global DOFs to free and constrained indices.
#[derive(Debug, Clone, PartialEq)]
pub struct DofMap {
    kinds: Vec<DofKind>,
    free: Vec<Dof>,
    constrained: Vec<Dof>,
    prescribed: Vec<f64>,
    /// The frame of each node (empty when no node has one).
    frames: Vec<Option<Frame>>,
}

impl DofMap {
    /// Numbers the DOFs of `num_nodes` nodes given which nodes are active and the prescribed
    /// `(dof, value)` pairs (already checked for conflicts, sorted by DOF, unique).
    pub(crate) fn new(active: &[bool], prescribed: &[(Dof, f64)]) -> DofMap {
        let mut kinds = vec![DofKind::Inactive; 2 * active.len()];
        let mut p = prescribed.iter().peekable();
        let (mut free, mut constrained, mut values) = (vec![], vec![], vec![]);
        for (g, kind) in kinds.iter_mut().enumerate() {
            let fixed = p.next_if(|(d, _)| d.0 == g);
            if !active[g / 2] {
                continue;
            }
            if let Some((d, v)) = fixed {
                *kind = DofKind::Constrained(constrained.len());
                constrained.push(*d);
                values.push(*v);
            } else {
                *kind = DofKind::Free(free.len());
                free.push(Dof(g));
            }
        }
        DofMap { kinds, free, constrained, prescribed: values, frames: vec![] }
    }

    /// The same numbering with local frames `(node, frame)` (sorted by node, unique).
    pub(crate) fn with_frames(mut self, frames: &[(usize, Frame)]) -> DofMap {
        if !frames.is_empty() {
            self.frames = vec![None; self.kinds.len() / 2];
            for (node, f) in frames {
                self.frames[*node] = Some(*f);
            }
        }
        self
    }

    /// Whether any node has a local frame.
    pub fn has_frames(&self) -> bool {
        !self.frames.is_empty()
    }

    /// The local frame of `node`, if it has one (its DOFs are then `un`, `ut`).
    pub fn frame(&self, node: usize) -> Option<&Frame> {
        self.frames.get(node).and_then(Option::as_ref)
    }

    /// `full` (global components) with every framed node's pair in its local components
    /// `Tᵀ u` (unchanged without frames).
    pub fn to_local<'a>(&self, full: &'a [f64]) -> std::borrow::Cow<'a, [f64]> {
        if !self.has_frames() {
            return std::borrow::Cow::Borrowed(full);
        }
        let mut out = full.to_vec();
        for (node, f) in self.frames.iter().enumerate() {
            if let Some(f) = f {
                let l = f.to_local([full[2 * node], full[2 * node + 1]]);
                out[2 * node..2 * node + 2].copy_from_slice(&l);
            }
        }
        std::borrow::Cow::Owned(out)
    }

    /// Turns a full vector in the DOFs `u'` into global components, `u = T u'`, in place.
    pub fn to_global_in_place(&self, full: &mut [f64]) {
        for (node, f) in self.frames.iter().enumerate() {
            if let Some(f) = f {
                let g = f.to_global([full[2 * node], full[2 * node + 1]]);
                full[2 * node..2 * node + 2].copy_from_slice(&g);
            }
        }
    }

    /// `K_e' = T_eᵀ K_e T_e` for a cell's matrix in element order on `nodes` (only the framed
    /// nodes' row and column pairs change; nothing is multiplied without a frame).
    pub fn rotate_cell_matrix(&self, nodes: impl Iterator<Item = usize>, k: &mut nalgebra::DMatrix<f64>) {
        if !self.has_frames() {
            return;
        }
        for (a, node) in nodes.enumerate() {
            let Some(f) = self.frame(node) else { continue };
            let (p, q) = (2 * a, 2 * a + 1);
            for r in 0..k.nrows() {
                let l = f.to_local([k[(r, p)], k[(r, q)]]);
                k[(r, p)] = l[0];
                k[(r, q)] = l[1];
            }
            for c in 0..k.ncols() {
                let l = f.to_local([k[(p, c)], k[(q, c)]]);
                k[(p, c)] = l[0];
                k[(q, c)] = l[1];
            }
        }
    }

    /// A full vector of reactions (global components) from the reactions `r'` per constrained
    /// index: `r = T r'` (a node held in `un` only has its reaction along `n`).
    pub fn reactions_global(&self, constrained_values: &[f64]) -> Vec<f64> {
        let mut full = vec![0.0; self.num_global()];
        for (d, r) in self.constrained.iter().zip(constrained_values) {
            full[d.0] = *r;
        }
        self.to_global_in_place(&mut full);
        full
    }

    /// The global DOFs a reaction acts on: the constrained DOFs, and both DOFs of a framed
    /// node with a constrained DOF (its reaction `r = T r'` has both global components), in
    /// increasing order.
    pub fn reaction_dofs(&self) -> Vec<Dof> {
        if !self.has_frames() {
            return self.constrained.clone();
        }
        let mut out: Vec<Dof> = self
            .constrained
            .iter()
            .flat_map(|d| {
                let n = d.node();
                if self.frame(n).is_some() { vec![Dof(2 * n), Dof(2 * n + 1)] } else { vec![*d] }
            })
            .collect();
        out.dedup();
        out
    }

    /// The role of global DOF `dof`.
    pub fn kind(&self, dof: Dof) -> DofKind {
        self.kinds.get(dof.0).copied().unwrap_or(DofKind::Inactive)
    }

    /// Number of free DOFs (unknowns).
    pub fn num_free(&self) -> usize {
        self.free.len()
    }

    /// Number of constrained DOFs.
    pub fn num_constrained(&self) -> usize {
        self.constrained.len()
    }

    /// Number of global DOFs (`2 × nodes`).
    pub fn num_global(&self) -> usize {
        self.kinds.len()
    }

    /// Global DOF of each free index.
    pub fn free_dofs(&self) -> &[Dof] {
        &self.free
    }

    /// Global DOF of each constrained index.
    pub fn constrained_dofs(&self) -> &[Dof] {
        &self.constrained
    }

    /// The model's prescribed values, per constrained index.
    pub fn prescribed_values(&self) -> &[f64] {
        &self.prescribed
    }

    /// A full vector (global order, global components: `u = T u'` at framed nodes) from free
    /// values and constrained values.
    pub fn expand(&self, free_values: &[f64], constrained_values: &[f64]) -> Vec<f64> {
        let mut full: Vec<f64> = self
            .kinds
            .iter()
            .map(|k| match k {
                DofKind::Inactive => 0.0,
                DofKind::Free(i) => free_values[*i],
                DofKind::Constrained(j) => constrained_values[*j],
            })
            .collect();
        self.to_global_in_place(&mut full);
        full
    }

    /// The free part of a full vector in global components (`Tᵀ u` at framed nodes).
    pub fn restrict_free(&self, full: &[f64]) -> Vec<f64> {
        let full = self.to_local(full);
        self.free.iter().map(|d| full[d.0]).collect()
    }

    /// The constrained part of a full vector in global components (`Tᵀ u` at framed nodes).
    pub fn restrict_constrained(&self, full: &[f64]) -> Vec<f64> {
        let full = self.to_local(full);
        self.constrained.iter().map(|d| full[d.0]).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbering_follows_the_written_rule() {
        // Three nodes, node 1 inactive, node 2's u2 prescribed.
        let map = DofMap::new(&[true, false, true], &[(Dof(5), 0.5)]);
        assert_eq!(map.kind(Dof(0)), DofKind::Free(0));
        assert_eq!(map.kind(Dof(2)), DofKind::Inactive);
        assert_eq!(map.kind(Dof(4)), DofKind::Free(2));
        assert_eq!(map.kind(Dof(5)), DofKind::Constrained(0));
        assert_eq!(map.expand(&[1.0, 2.0, 3.0], &[0.5]), vec![1.0, 2.0, 0.0, 0.0, 3.0, 0.5]);
        assert_eq!(Dof::of(2, Component::Y), Dof(5));
        assert_eq!(map.restrict_free(&[1.0, 2.0, 0.0, 0.0, 3.0, 0.5]), vec![1.0, 2.0, 3.0]);
    }

    /// `K' = Tᵀ K T` against the product of the full matrices (T block-diagonal, identity at the
    /// unframed node), and `expand` / `restrict_*` as `T u'` / `Tᵀ u`: equal to round-off.
    #[test]
    fn a_frame_rotates_matrices_and_vectors_as_t_transpose_k_t() {
        let a = 0.3f64;
        let frame = Frame { n: [a.cos(), a.sin()], t: [-a.sin(), a.cos()] };
        let map = DofMap::new(&[true, true], &[(Dof(2), 0.25)]).with_frames(&[(1, frame)]);
        let k = nalgebra::DMatrix::from_fn(4, 4, |i, j| 1.0 + (i * 4 + j) as f64 + if i == j { 10.0 } else { 0.0 });
        let k = &k + k.transpose();
        let mut t = nalgebra::DMatrix::<f64>::identity(4, 4);
        t[(2, 2)] = frame.n[0];
        t[(3, 2)] = frame.n[1];
        t[(2, 3)] = frame.t[0];
        t[(3, 3)] = frame.t[1];
        let mut rotated = k.clone();
        map.rotate_cell_matrix([0, 1].into_iter(), &mut rotated);
        assert!((rotated - t.transpose() * &k * &t).amax() < 1e-13 * k.amax());
        // u' = (1, 2 | un = 0.25, ut = 3): u = T u'.
        let u = map.expand(&[1.0, 2.0, 3.0], &[0.25]);
        let expected = &t * nalgebra::DVector::from_vec(vec![1.0, 2.0, 0.25, 3.0]);
        assert!(u.iter().zip(expected.iter()).all(|(a, b)| (a - b).abs() < 1e-15));
        let back = map.restrict_free(&u);
        assert!(back.iter().zip([1.0, 2.0, 3.0]).all(|(a, b)| (a - b).abs() < 1e-15), "{back:?}");
        assert!((map.restrict_constrained(&u)[0] - 0.25).abs() < 1e-15);
        // A reaction r' = 2 along n: r = 2 n, on both global DOFs of the node.
        let r = map.reactions_global(&[2.0]);
        assert!((r[2] - 2.0 * frame.n[0]).abs() < 1e-15 && (r[3] - 2.0 * frame.n[1]).abs() < 1e-15);
        assert_eq!(map.reaction_dofs(), vec![Dof(2), Dof(3)]);
        // Without a frame nothing changes.
        let plain = DofMap::new(&[true, true], &[(Dof(2), 0.25)]);
        let mut same = k.clone();
        plain.rotate_cell_matrix([0, 1].into_iter(), &mut same);
        assert_eq!(same, k);
    }
}
