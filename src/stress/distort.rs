//! Randomly distorted meshes: interior nodes moved by a random fraction of their local spacing.
//!
//! ```text
//! h_i   = distance from node i to the nearest other node of the cells containing it
//! x_i  ← x_i + a h_i (r cos θ, r sin θ),   r, θ uniform in [0, 1) and [0, 2π)   (a: amplitude)
//! ```
//!
//! Nodes on a 1D physical group (the boundaries, the contact edges, the symmetry lines) stay
//! where they are, so the boundary conditions and the contact geometry are unchanged. The
//! random numbers come from a fixed-seed SplitMix64 generator: the same seed gives the same
//! mesh. Validity is measured, not assumed: [`jacobian_quality`] returns the smallest ratio
//! min det J / max det J over the cells (sampled at the Gauss points and nodes); a value ≤ 0
//! means an inverted cell.

use contact2d_mesh::Mesh;

/// SplitMix64 (Steele, Lea, Flood 2014): a small, fixed-seed generator of uniform numbers.
#[derive(Debug, Clone)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// A generator with this seed.
    pub fn new(seed: u64) -> SplitMix64 {
        SplitMix64(seed)
    }

    /// The next number, uniform in [0, 1).
    pub fn next_f64(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Moves every node not on a 1D physical group by `amplitude` times its local spacing in a
/// random direction (see the module documentation).
pub fn distort_interior(mesh: &mut Mesh, amplitude: f64, seed: u64) {
    let n = mesh.num_nodes();
    let mut on_curve = vec![false; n];
    let mut spacing = vec![f64::INFINITY; n];
    for block in &mesh.blocks {
        let curve = block.kind.dim() == 1 && !block.physical_tags.is_empty();
        for cell in block.cells() {
            for (k, a) in cell.iter().enumerate() {
                if curve {
                    on_curve[a.0] = true;
                }
                if block.kind.dim() == 2 {
                    for b in &cell[k + 1..] {
                        let (pa, pb) = (mesh.points[a.0], mesh.points[b.0]);
                        let d = (pa[0] - pb[0]).hypot(pa[1] - pb[1]);
                        spacing[a.0] = spacing[a.0].min(d);
                        spacing[b.0] = spacing[b.0].min(d);
                    }
                }
            }
        }
    }
    let mut rng = SplitMix64::new(seed);
    for i in 0..n {
        let (r, theta) = (rng.next_f64(), std::f64::consts::TAU * rng.next_f64());
        if on_curve[i] || !spacing[i].is_finite() {
            continue;
        }
        let d = amplitude * spacing[i] * r;
        mesh.points[i][0] += d * theta.cos();
        mesh.points[i][1] += d * theta.sin();
    }
}

/// The smallest min det J / max det J over the 2D cells (Gauss points of the stiffness rule and
/// the reference nodes); ≤ 0 for an inverted cell, 1 for affine cells. `None` without 2D cells.
pub fn jacobian_quality(mesh: &Mesh) -> Option<f64> {
    let blocks_2d: Vec<_> = mesh.blocks.iter().filter(|b| b.kind.dim() == 2).collect();
    if blocks_2d.is_empty() {
        return None;
    }
    crate::mesh_summary::jacobian_extremes(mesh)
        .map(|[lo, hi]| if hi > 0.0 { lo / hi } else { lo })
        .fold(None, |worst: Option<f64>, q| Some(worst.map_or(q, |w| w.min(q))))
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;
    use contact2d_mesh::read_msh;

    #[test]
    fn uniform_numbers_in_the_unit_interval_with_the_right_mean() {
        let mut g = SplitMix64::new(7);
        let v: Vec<f64> = (0..10_000).map(|_| g.next_f64()).collect();
        assert!(v.iter().all(|x| (0.0..1.0).contains(x)));
        // Mean of 10⁴ uniforms: standard deviation 0.29/100; 0.01 is more than three of them.
        assert!((v.iter().sum::<f64>() / 1e4 - 0.5).abs() < 0.01);
    }

    #[test]
    fn boundary_nodes_stay_and_cells_stay_valid() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/meshes/plate_insert/plate_insert_eps0_N16.msh");
        let original = read_msh(path).unwrap();
        let mut mesh = original.clone();
        distort_interior(&mut mesh, 0.2, 1);
        let hole = original.group_nodes("hole_edge").unwrap();
        assert!(hole.iter().all(|v| mesh.points[v.0] == original.points[v.0]));
        let moved = mesh.points.iter().zip(&original.points).filter(|(a, b)| a != b).count();
        assert!(moved > original.num_nodes() / 2);
        let q0 = jacobian_quality(&original).unwrap();
        let q = jacobian_quality(&mesh).unwrap();
        assert!(q > 0.0 && q < q0, "quality {q} (undistorted {q0})");
    }
}
