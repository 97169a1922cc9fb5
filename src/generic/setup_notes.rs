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

use contact2d_contact::BuiltProblem;

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
