//! Notes on a set-up that solves but is probably not what the user meant (issue 27): bodies that
//! share mesh nodes, and an initial interference deeper than the elements on a contact.
//!
//! ```text
//! shared nodes   bodies a and b (regions of the scene) whose element nodes meet: one
//!                displacement per node, so the bodies are glued there, not in contact
//! interference   per contact, the deepest negative initial gap d = −g of a pair against the
//!                local element size h at its master node (the longest master-curve edge that
//!                ends there, chord length); a note when d > h: the pairing linearises about
//!                the initial geometry (fixed normals, small sliding), which an overlap of
//!                more than an element does not respect
//! ```

use contact2d_contact::{BuiltProblem, nodes_face_each_other};

/// A note on a body of revolution's axis: how many nodes lie on it, held at `u_r = 0`
/// ([`contact2d_fem::Model::fix_axis_nodes`]).
pub fn axis_notes(model: &contact2d_fem::Model) -> Option<String> {
    let count = model.axis_nodes().len();
    (count > 0).then(|| {
        format!(
            "axisymmetric: {count} node{} on the axis r = 0 hold u_r = u1 = 0 (a point of the axis cannot leave it)",
            if count == 1 { "" } else { "s" }
        )
    })
}

/// A note per pair of bodies that share nodes, naming both and the number of nodes.
/// `regions` are the scene's body regions in order; an unknown region is left to the build,
/// which reports it.
pub fn shared_node_notes(mesh: &contact2d_mesh::Mesh, regions: &[String]) -> Vec<String> {
    let nodes: Vec<Vec<usize>> = regions
        .iter()
        .map(|r| mesh.group_nodes(r).map(|n| n.iter().map(|id| id.0).collect()).unwrap_or_default())
        .collect();
    let mut notes = vec![];
    for a in 0..regions.len() {
        for b in a + 1..regions.len() {
            // Both lists are sorted and free of duplicates (Mesh::group_nodes).
            let shared = count_common(&nodes[a], &nodes[b]);
            if shared > 0 {
                notes.push(format!(
                    "bodies \"{}\" and \"{}\" share {shared} mesh node{}: they are glued there (one displacement \
                     per node), not in contact; give each body its own nodes and add a [[contact]] if they should \
                     touch",
                    regions[a],
                    regions[b],
                    if shared == 1 { "" } else { "s" }
                ));
            }
        }
    }
    notes
}

/// A note per contact whose deepest initial interference exceeds the local element size.
pub fn deep_interference_notes(built: &BuiltProblem) -> Vec<String> {
    let problem = &built.problem;
    let points = &problem.model.mesh.points;
    let mut notes = vec![];
    for iface in &built.interfaces {
        let mut worst: Option<(f64, f64, usize)> = None;
        for k in iface.pairs.clone() {
            let (Some(pair), Some(&gap)) = (problem.pairs.get(k), problem.gap.get(k)) else { continue };
            let depth = -gap;
            // The longest master edge ending at the pair's master node.
            let size = iface
                .master_contour
                .edges
                .iter()
                .filter(|e| e.nodes[0] == pair.master || e.nodes[1] == pair.master)
                .filter_map(|e| Some(distance(*points.get(e.nodes[0].0)?, *points.get(e.nodes[1].0)?)))
                .fold(0.0f64, f64::max);
            if size > 0.0 && depth > size && worst.is_none_or(|(d, h, _)| depth / size > d / h) {
                worst = Some((depth, size, pair.master.0));
            }
        }
        if let Some((depth, size, node)) = worst {
            let [x, y] = points.get(node).copied().unwrap_or([f64::NAN; 2]);
            notes.push(format!(
                "contact \"{}\": the initial interference {depth:.4e} at ({x:.4e}, {y:.4e}) is deeper than the \
                 element size {size:.4e} there; the pairing assumes overlaps and slips small against the \
                 elements, so check the geometry or the contact's gap",
                iface.name
            ));
        }
    }
    notes
}

/// A note per contact with master nodes that fixes hold along the contact normal (the pair's
/// normal row has no free DOF, [`contact2d_contact::ContactProblem::normal`]): the fix holds
/// them, their contact force is in the fix's reaction, and their gap at the end (`gap`, per
/// pair) is the prescribed values', reported when they prescribe a penetration.
pub fn held_pair_notes(built: &BuiltProblem, gap: &[f64]) -> Vec<String> {
    let problem = &built.problem;
    let points = &problem.model.mesh.points;
    let mut notes = vec![];
    for iface in &built.interfaces {
        let held: Vec<usize> =
            iface.pairs.clone().filter(|&k| !problem.normal.get(k).copied().unwrap_or(true)).collect();
        let Some(&first) = held.first() else { continue };
        let [x, y] = problem.pairs.get(first).and_then(|p| points.get(p.master.0)).copied().unwrap_or([f64::NAN; 2]);
        let deepest = held.iter().filter_map(|&k| gap.get(k)).fold(0.0f64, |a, g| a.max(-g));
        let penetration = if deepest > 0.0 {
            format!("; the fixes prescribe a penetration of {deepest:.4e} there, which no contact force can change")
        } else {
            String::new()
        };
        notes.push(format!(
            "contact \"{}\": {} master node{} (the first at ({x:.4e}, {y:.4e})) held along the contact normal by a \
             fix: the fix, not the contact, holds {} (no contact force there; the force is in the fix's \
             reaction){penetration}",
            iface.name,
            held.len(),
            if held.len() == 1 { "" } else { "s" },
            if held.len() == 1 { "it" } else { "them" },
        ));
    }
    notes
}

/// A note per contact paired node to segment whose slave curve has quadratic (Line3) edges and
/// whose two curves' nodes do not face each other (non-matching meshes): the master nodes'
/// tributary lengths `∫ N_a ds` of Line3 edges put 1/6 of an edge on a corner node and 2/3 on a
/// mid node, and a corner or mid master node that lands anywhere on a slave edge takes the
/// force its weight says; on non-matching curved interfaces the pressure then alternates
/// between corner and mid nodes, and its peak error grew under refinement (0.2 %, 0.4 %, 2.5 %,
/// 7.5 % over four levels, issue 27 item 7). `node_to_segment` names the contacts whose scene
/// asks for that pairing (in the order of the interfaces).
pub fn quadratic_node_to_segment_notes(built: &BuiltProblem, node_to_segment: &[bool]) -> Vec<String> {
    let points = &built.problem.model.mesh.points;
    let mut notes = vec![];
    for (iface, _) in built.interfaces.iter().zip(node_to_segment).filter(|(_, nts)| **nts) {
        let quadratic = iface.slave_contour.edges.iter().any(|e| e.quadratic);
        if quadratic && !nodes_face_each_other(points, &iface.master_contour, &iface.slave_contour) {
            notes.push(format!(
                "contact \"{}\": node-to-segment pairing on quadratic slave edges of a non-matching mesh: the \
                 pressure alternates between corner and mid-side nodes and its peak does not converge under \
                 refinement; use pairing = \"segment_to_segment\" (or \"automatic\")",
                iface.name
            ));
        }
    }
    notes
}

fn distance(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// The number of values two sorted, duplicate-free lists share.
fn count_common(a: &[usize], b: &[usize]) -> usize {
    let (mut i, mut j, mut n) = (0, 0, 0);
    while i < a.len() && j < b.len() {
        match a[i].cmp(&b[j]) {
            std::cmp::Ordering::Less => i += 1,
            std::cmp::Ordering::Greater => j += 1,
            std::cmp::Ordering::Equal => {
                n += 1;
                i += 1;
                j += 1;
            }
        }
    }
    n
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn common_nodes_of_sorted_lists() {
        assert_eq!(count_common(&[1, 3, 5, 7], &[2, 3, 4, 7, 9]), 2);
        assert_eq!(count_common(&[], &[1]), 0);
    }
}
