//! The sparse matrix type every stage of the fem crate shares (assembly, ordering, pattern).

use faer::sparse::SparseColMat;

/// Compressed sparse column matrix of f64 with usize indices.
pub type Csc = SparseColMat<usize, f64>;
