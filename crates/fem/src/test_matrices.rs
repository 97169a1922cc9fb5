//! Matrices the unit tests of the sparse solvers share (`constrained.rs`, `saddle.rs`).

use faer::sparse::{SparseColMat, Triplet};

use crate::sparse::Csc;

/// The lower triangle of the 5-point Laplacian on an `m × m` grid plus `shift` on the diagonal
/// (SPD for `shift > −8 sin²(π/(2(m+1)))`, so for every `shift ≥ 0`).
#[allow(clippy::expect_used)]
pub(crate) fn grid_laplacian(m: usize, shift: f64) -> Csc {
    let id = |i: usize, j: usize| i * m + j;
    let mut t = vec![];
    for i in 0..m {
        for j in 0..m {
            t.push(Triplet::new(id(i, j), id(i, j), 4.0 + shift));
            if i + 1 < m {
                t.push(Triplet::new(id(i + 1, j), id(i, j), -1.0));
            }
            if j + 1 < m {
                t.push(Triplet::new(id(i, j + 1), id(i, j), -1.0));
            }
        }
    }
    SparseColMat::try_new_from_triplets(m * m, m * m, &t).expect("valid triplets")
}
