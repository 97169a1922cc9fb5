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

/// A displacement component.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Component {
    /// u1, along x1.
    X,
    /// u2, along x2.
    Y,
}

impl Component {
    /// 0 for X, 1 for Y.
    pub fn index(self) -> usize {
        match self {
            Component::X => 0,
            Component::Y => 1,
        }
    }

    /// The paper's name: "u1" or "u2".
    pub fn name(self) -> &'static str {
        match self {
            Component::X => "u1",
            Component::Y => "u2",
        }
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

/// The map from global DOFs to free and constrained indices.
#[derive(Debug, Clone, PartialEq)]
pub struct DofMap {
    kinds: Vec<DofKind>,
    free: Vec<Dof>,
    constrained: Vec<Dof>,
    prescribed: Vec<f64>,
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
        DofMap { kinds, free, constrained, prescribed: values }
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

    /// A full vector (global order) from free values and constrained values.
    pub fn expand(&self, free_values: &[f64], constrained_values: &[f64]) -> Vec<f64> {
        self.kinds
            .iter()
            .map(|k| match k {
                DofKind::Inactive => 0.0,
                DofKind::Free(i) => free_values[*i],
                DofKind::Constrained(j) => constrained_values[*j],
            })
            .collect()
    }

    /// The free part of a full vector.
    pub fn restrict_free(&self, full: &[f64]) -> Vec<f64> {
        self.free.iter().map(|d| full[d.0]).collect()
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
}
