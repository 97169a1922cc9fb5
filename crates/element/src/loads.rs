//! Consistent load vectors: tractions on edges and body forces in cells.
//!
//! ```text
//! f_a = ∫_Γe N_a t(x) t_h ds  = Σ_g N_a(ξ_g) t(x(ξ_g), n(ξ_g)) t_h (ds/dξ)(ξ_g) w_g     (edge traction)
//! f_a = ∫_Ωe N_a b t_h dΩ     = Σ_g N_a(ξ_g) b t_h det J(ξ_g) w_g                     (body force)
//! ```
//!
//! `t_h` is the boundary or volume weight of the body's [`Kinematics`] (the thickness in the plane). Load vectors are interleaved like the stiffness: `[f_0x, f_0y, f_1x, ...]`.

use crate::error::ElementError;
use crate::isoparametric::{map_edge_point, map_point};
use crate::kinematics::Kinematics;
use crate::quadrature::{GaussRule, gauss_legendre};
use crate::shape::{EdgeType, ElementType};

/// The consistent nodal forces of a traction on one edge, integrated with an `n_gauss`-point rule.
///
/// `traction(x, normal)` gives the traction vector at a point of the edge; `normal` is the edge
/// normal `[t_y, -t_x]` (outward when the edge runs counter-clockwise around the body), so a
/// pressure `p` is `|_, n| [-p n[0], -p n[1]]`.
///
/// # Errors
/// [`ElementError::WrongNodeCount`], [`ElementError::DegenerateEdge`], or an unsupported rule size.
pub fn edge_traction_load(
    edge: EdgeType,
    coords: &[[f64; 2]],
    kinematics: &Kinematics,
    n_gauss: usize,
    traction: impl Fn([f64; 2], [f64; 2]) -> [f64; 2],
) -> Result<Vec<f64>, ElementError> {
    let (xs, ws) = gauss_legendre(n_gauss)?;
    let mut f = vec![0.0; 2 * edge.num_nodes()];
    for (xi, w) in xs.iter().zip(&ws) {
        let p = map_edge_point(edge, coords, *xi)?;
        let t = traction(p.x, p.normal);
        let scale = w * p.ds_dxi * kinematics.boundary_weight(p.x);
        for a in 0..edge.num_nodes() {
            f[2 * a] += p.n[a] * t[0] * scale;
            f[2 * a + 1] += p.n[a] * t[1] * scale;
        }
    }
    Ok(f)
}

/// The consistent nodal forces of a constant body force `b` (force per volume) in one cell.
///
/// # Errors
/// As [`crate::isoparametric::map_point`].
pub fn body_force_load(
    element: ElementType,
    coords: &[[f64; 2]],
    kinematics: &Kinematics,
    body_force: [f64; 2],
    rule: &GaussRule,
) -> Result<Vec<f64>, ElementError> {
    let mut f = vec![0.0; 2 * element.num_nodes()];
    for (xi, w) in rule.points.iter().zip(&rule.weights) {
        let p = map_point(element, coords, *xi)?;
        let weight = kinematics.volume_weight(p.x);
        for a in 0..element.num_nodes() {
            f[2 * a] += p.n[a] * body_force[0] * p.det_j * w * weight;
            f[2 * a + 1] += p.n[a] * body_force[1] * p.det_j * w * weight;
        }
    }
    Ok(f)
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    #[test]
    fn uniform_traction_on_quadratic_edge_gives_simpson_weights() {
        // A straight Line3 of length 2 with unit traction: nodal forces 1/3, 1/3, 4/3.
        let c = [[0.0, 0.0], [2.0, 0.0], [1.0, 0.0]];
        let f =
            edge_traction_load(EdgeType::Line3, &c, &Kinematics::PlaneStress { thickness: 1.0 }, 3, |_, _| [1.0, 0.0])
                .unwrap();
        for (a, expected) in [1.0 / 3.0, 1.0 / 3.0, 4.0 / 3.0].iter().enumerate() {
            assert!((f[2 * a] - expected).abs() < 1e-14 && f[2 * a + 1].abs() < 1e-15);
        }
    }

    #[test]
    fn total_body_force_is_force_times_area() {
        let c = [
            [0.0, 0.0],
            [2.0, 0.0],
            [2.0, 1.0],
            [0.0, 1.0],
            [1.0, 0.0],
            [2.0, 0.5],
            [1.0, 1.0],
            [0.0, 0.5],
            [1.0, 0.5],
        ];
        let f = body_force_load(
            ElementType::Quad9,
            &c,
            &Kinematics::PlaneStress { thickness: 0.5 },
            [3.0, -1.0],
            &GaussRule::quad(3).unwrap(),
        )
        .unwrap();
        let (fx, fy): (f64, f64) = (f.iter().step_by(2).sum(), f.iter().skip(1).step_by(2).sum());
        assert!((fx - 3.0).abs() < 1e-13 && (fy + 1.0).abs() < 1e-13);
    }

    #[test]
    fn outward_normal_for_counter_clockwise_edge() {
        // The bottom edge of a counter-clockwise square runs +x: outward normal is -y.
        let c = [[0.0, 0.0], [1.0, 0.0]];
        let f = edge_traction_load(EdgeType::Line2, &c, &Kinematics::PlaneStress { thickness: 1.0 }, 2, |_, n| {
            [-n[0], -n[1]]
        })
        .unwrap();
        assert!((f[1] - 0.5).abs() < 1e-15 && (f[3] - 0.5).abs() < 1e-15);
    }
}
