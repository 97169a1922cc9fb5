//! A summary of a mesh for people: counts, physical groups, bounding box, element quality.
//!
//! Quality of a 2D cell is `min det J / max det J` over its nodes and stiffness Gauss points
//! (1 for an affine cell, ≤ 0 for an inverted one); `min_det_j` is the smallest determinant of
//! the whole mesh, which is negative if any cell is inverted. Both are measured as a model sees
//! the cells: clockwise cells (a Gmsh surface from a clockwise curve loop) are counted in
//! `clockwise_cells` and measured renumbered counter-clockwise, as `Model::add_body` renumbers them.
//!
//! det J is constant in a straight-sided triangle, so that ratio is 1 for any triangle however
//! flat. The shape of a cell is therefore measured as well, by its scaled Jacobian at the corners
//! (Knupp 2000), from the corner nodes (the straight-sided cell):
//!
//! ```text
//!   at corner i, with edges e1 = x(i+1) − x(i) and e2 = x(i−1) − x(i) (corners counter-clockwise):
//!     s_i   = (e1 × e2) / (|e1| |e2|) = sin θ_i            θ_i the corner's angle
//!   shape   = min_i s_i / sin θ*                           θ* = 60° (triangle), 90° (quadrangle)
//! ```
//!
//! 1 for an equilateral triangle or a square (0.816 for a right isosceles triangle), → 0 for a
//! corner closing to 0° or opening to 180° (a sliver, a needle), ≤ 0 for an inverted or
//! non-convex corner.

use std::collections::BTreeMap;

use contact2d_element::{GaussRule, jacobian_determinant};
use contact2d_fem::element_type;
use contact2d_mesh::{CellBlock, CellKind, Mesh, NodeId};
use serde::Serialize;

/// One physical group in the summary.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GroupSummary {
    /// Name.
    pub name: String,
    /// Dimension.
    pub dim: usize,
    /// Number of cells.
    pub elements: usize,
}

/// The summary printed by `contact2d mesh`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MeshSummary {
    /// Number of nodes.
    pub nodes: usize,
    /// Cell counts by kind name (`quad9`, `line3`, ...).
    pub elements: BTreeMap<String, usize>,
    /// Physical groups.
    pub physical_groups: Vec<GroupSummary>,
    /// `[[xmin, ymin], [xmax, ymax]]`.
    pub bbox: [[f64; 2]; 2],
    /// Smallest Jacobian determinant over all 2D cells (`None` without 2D cells).
    pub min_det_j: Option<f64>,
    /// Worst cell quality `min det J / max det J` (`None` without 2D cells).
    pub worst_quality: Option<f64>,
    /// Worst cell shape, the scaled Jacobian at the corners (see the module doc; `None` without
    /// 2D cells).
    pub worst_shape: Option<f64>,
    /// Cells whose nodes run clockwise (renumbered when a model is built; not an error).
    pub clockwise_cells: usize,
    /// Cells of quality below [`MIN_QUALITY`] or shape below [`MIN_SHAPE`], worst first (at
    /// most [`MAX_LISTED`]).
    pub poor_cells: Vec<PoorCell>,
    /// How many cells are below [`MIN_QUALITY`] or [`MIN_SHAPE`] (all of them, listed or not).
    pub poor_cell_count: usize,
}

/// The quality below which a cell is warned about: its det J varies more than 20-fold inside
/// (a sliver or a badly bent edge), where the stiffness is poorly integrated and the stresses
/// near it are not to be trusted. The cells of every bundled mesh stay above 0.17 (Gmsh's
/// curved quadratic meshes; measured 2026-11-25).
pub const MIN_QUALITY: f64 = 0.05;

/// The shape (scaled Jacobian at the corners, see the module doc) below which a cell is warned
/// about: a corner angle under about 10° or over 170° in a triangle (sin θ < 0.2 · sin 60°),
/// under 11.5° or over 168.5° in a quadrangle. Such a cell makes the stiffness ill-conditioned
/// and its stresses inaccurate (the error bounds of triangles grow as 1/sin θ_max, Babuška &
/// Aziz 1976). The cells of every bundled mesh stay above 0.24 (moving_roller_L1; measured
/// 2026-11-28).
pub const MIN_SHAPE: f64 = 0.2;

/// The most poor cells a summary lists.
pub const MAX_LISTED: usize = 10;

/// A cell of poor quality.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PoorCell {
    /// The file's element tag.
    pub element: u64,
    /// The 2D physical group (body region) it belongs to (empty if none).
    pub region: String,
    /// The mean of its nodes.
    pub centroid: [f64; 2],
    /// Its quality `min det J / max det J`.
    pub quality: f64,
    /// Its shape, the scaled Jacobian at the corners (see the module doc).
    pub shape: f64,
}

impl PoorCell {
    /// How far below its thresholds the cell is: the smaller of quality / [`MIN_QUALITY`] and
    /// shape / [`MIN_SHAPE`] (below 1 for every poor cell; the worst cell first when sorted).
    fn severity(&self) -> f64 {
        (self.quality / MIN_QUALITY).min(self.shape / MIN_SHAPE)
    }
}

impl std::fmt::Display for PoorCell {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let [x, y] = self.centroid;
        write!(f, "element {} of \"{}\" at ({x:.4e}, {y:.4e}): ", self.element, self.region)?;
        let mut below = vec![];
        if self.quality < MIN_QUALITY {
            below.push(format!("quality {:.2e} (below {MIN_QUALITY})", self.quality));
        }
        if self.shape < MIN_SHAPE {
            below.push(format!("shape {:.2e} (below {MIN_SHAPE})", self.shape));
        }
        write!(f, "{}", below.join(", "))
    }
}

/// The cells of `mesh` below [`MIN_QUALITY`] or [`MIN_SHAPE`], worst first, and how many there
/// are (the list capped at [`MAX_LISTED`]); measured counter-clockwise as a model sees them.
pub fn poor_cells(mesh: &Mesh) -> (Vec<PoorCell>, usize) {
    let mut poor = vec![];
    for b in mesh.blocks.iter().filter(|b| element_type(b.kind).is_some()) {
        let region = mesh
            .groups
            .iter()
            .find(|g| g.dim == 2 && b.physical_tags.contains(&g.tag))
            .map_or(String::new(), |g| g.name.clone());
        for ((cell, tag), [lo, hi]) in b.cells().zip(&b.element_tags).zip(block_jacobian_extremes(mesh, b)) {
            let quality = if hi > 0.0 { lo / hi } else { lo.min(0.0) };
            let shape = cell_shape(mesh, b.kind, cell);
            if quality < MIN_QUALITY || shape < MIN_SHAPE {
                let n = cell.len() as f64;
                let centroid = cell.iter().fold([0.0; 2], |a, p| {
                    let x = mesh.points[p.0];
                    [a[0] + x[0] / n, a[1] + x[1] / n]
                });
                poor.push(PoorCell { element: *tag, region: region.clone(), centroid, quality, shape });
            }
        }
    }
    poor.sort_by(|a, b| a.severity().total_cmp(&b.severity()));
    let count = poor.len();
    poor.truncate(MAX_LISTED);
    (poor, count)
}

/// Summarises `mesh`.
pub fn summarize_mesh(mesh: &Mesh) -> MeshSummary {
    let mut elements = BTreeMap::new();
    for b in &mesh.blocks {
        *elements.entry(b.kind.name().to_string()).or_insert(0) += b.len();
    }
    let physical_groups = mesh
        .groups
        .iter()
        .map(|g| GroupSummary {
            name: g.name.clone(),
            dim: g.dim,
            elements: mesh.group_cell_count(&g.name).unwrap_or(0),
        })
        .collect();
    let mut oriented = mesh.clone();
    let clockwise_cells = oriented.orient_cells_counter_clockwise();
    let (mut min_det_j, mut worst_quality) = (None::<f64>, None::<f64>);
    for [lo, hi] in jacobian_extremes(&oriented) {
        min_det_j = Some(min_det_j.map_or(lo, |m| m.min(lo)));
        let q = if hi > 0.0 { lo / hi } else { lo.min(0.0) };
        worst_quality = Some(worst_quality.map_or(q, |w| w.min(q)));
    }
    let worst_shape = oriented
        .blocks
        .iter()
        .filter(|b| element_type(b.kind).is_some())
        .flat_map(|b| b.cells().map(|cell| cell_shape(&oriented, b.kind, cell)))
        .reduce(f64::min);
    let (poor_cells, poor_cell_count) = poor_cells(&oriented);
    MeshSummary {
        poor_cells,
        poor_cell_count,
        nodes: mesh.num_nodes(),
        elements,
        physical_groups,
        bbox: mesh.bounding_box().unwrap_or([[0.0; 2]; 2]),
        min_det_j,
        worst_quality,
        worst_shape,
        clockwise_cells,
    }
}

/// The shape of one cell of kind `kind`: its scaled Jacobian at the corners, `min_i sin θ_i /
/// sin θ*` (see the module doc), from its corner nodes (the first three of a triangle, four of
/// a quadrangle, in Gmsh's order); 1 for a kind without corners (points, lines). A corner with a zero-length
/// edge counts as 0.
pub fn cell_shape(mesh: &Mesh, kind: CellKind, cell: &[NodeId]) -> f64 {
    let (corners, ideal) = match kind {
        CellKind::Tri3 | CellKind::Tri6 => (3, 3f64.sqrt() / 2.0),
        CellKind::Quad4 | CellKind::Quad8 | CellKind::Quad9 => (4, 1.0),
        _ => return 1.0,
    };
    let point = |i: usize| cell.get(i % corners).and_then(|n| mesh.points.get(n.0)).copied().unwrap_or([0.0; 2]);
    (0..corners)
        .map(|i| {
            let (x, next, prev) = (point(i), point(i + 1), point(i + corners - 1));
            let e1 = [next[0] - x[0], next[1] - x[1]];
            let e2 = [prev[0] - x[0], prev[1] - x[1]];
            let lengths = e1[0].hypot(e1[1]) * e2[0].hypot(e2[1]);
            if lengths > 0.0 { (e1[0] * e2[1] - e1[1] * e2[0]) / lengths / ideal } else { 0.0 }
        })
        .fold(f64::INFINITY, f64::min)
}

/// `[min, max]` of det J over each cell with an element type (at the Gauss points of its
/// stiffness rule and its reference nodes): min ≤ 0 for an inverted cell, min = max for an
/// affine one.
pub fn jacobian_extremes(mesh: &Mesh) -> impl Iterator<Item = [f64; 2]> + '_ {
    mesh.blocks.iter().flat_map(move |b| block_jacobian_extremes(mesh, b))
}

/// [`jacobian_extremes`] of the cells of one block of `mesh` (none for a block of no element
/// type).
fn block_jacobian_extremes<'a>(mesh: &'a Mesh, b: &'a CellBlock) -> impl Iterator<Item = [f64; 2]> + 'a {
    element_type(b.kind).into_iter().flat_map(move |element| {
        let rule = GaussRule::stiffness_rule(element);
        b.cells().map(move |cell| {
            let coords: Vec<[f64; 2]> = cell.iter().map(|n| mesh.points[n.0]).collect();
            rule.points
                .iter()
                .chain(element.reference_nodes())
                .filter_map(|xi| jacobian_determinant(element, &coords, *xi).ok())
                .fold([f64::INFINITY, f64::NEG_INFINITY], |[lo, hi], d| [lo.min(d), hi.max(d)])
        })
    })
}

impl std::fmt::Display for MeshSummary {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        writeln!(f, "nodes: {}", self.nodes)?;
        writeln!(f, "elements:")?;
        for (kind, count) in &self.elements {
            writeln!(f, "  {kind:<10} {count}")?;
        }
        writeln!(f, "physical groups:")?;
        for g in &self.physical_groups {
            writeln!(f, "  {:<20} dim {}  {} elements", g.name, g.dim, g.elements)?;
        }
        let [[x0, y0], [x1, y1]] = self.bbox;
        writeln!(f, "bounding box: [{x0}, {x1}] x [{y0}, {y1}]")?;
        if self.clockwise_cells > 0 {
            writeln!(
                f,
                "clockwise cells: {} (renumbered counter-clockwise when a model is built)",
                self.clockwise_cells
            )?;
        }
        match (self.min_det_j, self.worst_quality) {
            (Some(d), Some(q)) => write!(f, "min det J: {d:.6e}\nworst quality (min/max det J): {q:.4}")?,
            _ => write!(f, "no 2D cells")?,
        }
        if let Some(s) = self.worst_shape {
            write!(
                f,
                "\nworst shape (scaled Jacobian at the corners, 1 for a square or equilateral triangle): {s:.4}"
            )?;
        }
        if self.poor_cell_count > 0 {
            write!(
                f,
                "\nwarning: {} cells below quality {MIN_QUALITY} or shape {MIN_SHAPE}, the worst:",
                self.poor_cell_count
            )?;
            for cell in &self.poor_cells {
                write!(f, "\n  {cell}")?;
            }
        }
        Ok(())
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;
    use contact2d_mesh::{CellKind, generate::rectangle};

    /// A sliver: the free corner (2, 1) of the second unit Q4 of a 2 × 1 strip moved onto
    /// (1.501, 0.501), 1e-3 beside its cell's diagonal from (2, 0) to (1, 1). det J of the
    /// bilinear map is linear along each reference axis, so its extremes sit at the corners: the
    /// moved corner's is ∓2e-3 (twice the distance times the edges), the opposite corner's about
    /// 1, so the quality is about ±2e-3, far below 0.05; the first cell stays a unit square.
    #[test]
    fn a_sliver_is_listed_with_its_place() {
        let mut mesh = rectangle(CellKind::Quad4, [0.0, 2.0], [0.0, 1.0], 2, 1);
        let corner = mesh.points.iter().position(|p| *p == [2.0, 1.0]).unwrap();
        mesh.points[corner] = [1.501, 0.501];
        let s = summarize_mesh(&mesh);
        assert_eq!(s.poor_cell_count, 1, "{s}");
        let sliver = &s.poor_cells[0];
        assert!(sliver.quality.abs() < 0.01 && sliver.region == "domain", "{sliver}");
        let [x, y] = sliver.centroid;
        assert!((x - (1.0 + 2.0 + 1.501 + 1.0) / 4.0).abs() < 1e-12 && (y - (0.501 + 1.0) / 4.0).abs() < 1e-12);
        assert!(format!("{s}").contains("warning: 1 cells below quality 0.05 or shape 0.2"), "{s}");
    }

    /// The textbook bad element det J cannot see: a triangle (0, 0), (1, 0), (0.5, h) with
    /// h = 1e-3 (aspect 1/h = 1,000). Its det J is constant (quality exactly 1), but its apex
    /// angle is 180° − 2·atan(2h) and its base angles atan(2h), whose sine 2h/√(1 + 4h²) is the
    /// smallest (the apex's is twice it): the shape is 2h/√(1 + 4h²) / (√3/2), about 2.3e-3, far
    /// below 0.2.
    #[test]
    fn a_flat_triangle_is_a_sliver_whatever_its_det_j() {
        let h = 1e-3;
        let mut mesh = rectangle(CellKind::Tri3, [0.0, 1.0], [0.0, 1.0], 1, 1);
        mesh.points = vec![[0.0, 0.0], [1.0, 0.0], [0.5, h], [2.0, 2.0]];
        mesh.blocks[0].nodes = vec![NodeId(0), NodeId(1), NodeId(2), NodeId(1), NodeId(3), NodeId(2)];
        let s = summarize_mesh(&mesh);
        let base = 2.0 * h / (1.0 + 4.0 * h * h).sqrt() / (3f64.sqrt() / 2.0);
        let sliver = &s.poor_cells[0];
        assert_eq!(s.poor_cell_count, 1, "{s}");
        // Both sines are computed from rounded coordinates of size 1: a relative 1e-12 bounds it.
        assert!((sliver.shape - base).abs() < 1e-12 * base, "{} against {base}", sliver.shape);
        assert!((sliver.quality - 1.0).abs() < 1e-12);
        assert_eq!(sliver.element, mesh.blocks[0].element_tags[0]);
        assert!(s.to_string().contains("shape 2.31e-3 (below 0.2)"), "{s}");
        assert!(!s.to_string().contains("quality 1"), "{s}");
    }

    /// Closed forms of the shape: a square 1, any rectangle 1 (right angles), a right isosceles
    /// triangle sin 45° / sin 60° = √(2/3), an equilateral triangle 1, a rhombus of 30° sin 30° = 0.5.
    #[test]
    fn shape_of_known_cells() {
        let shape = |kind: CellKind, points: Vec<[f64; 2]>| {
            let n = points.len();
            let mesh = Mesh { points, ..Mesh::default() };
            let cell: Vec<NodeId> = (0..n).map(NodeId).collect();
            cell_shape(&mesh, kind, &cell)
        };
        let close = |a: f64, b: f64| (a - b).abs() < 1e-14;
        assert!(close(shape(CellKind::Quad4, vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]), 1.0));
        assert!(close(shape(CellKind::Quad4, vec![[0.0, 0.0], [1e3, 0.0], [1e3, 1.0], [0.0, 1.0]]), 1.0));
        assert!(close(shape(CellKind::Tri3, vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]), (2.0f64 / 3.0).sqrt()));
        assert!(close(shape(CellKind::Tri3, vec![[0.0, 0.0], [1.0, 0.0], [0.5, 3f64.sqrt() / 2.0]]), 1.0));
        let (c, s) = (30f64.to_radians().cos(), 30f64.to_radians().sin());
        assert!(close(shape(CellKind::Quad4, vec![[0.0, 0.0], [1.0, 0.0], [1.0 + c, s], [c, s]]), 0.5));
        // Clockwise: every corner negative, the right angle most: −1 / sin 60°.
        assert!(close(shape(CellKind::Tri3, vec![[0.0, 0.0], [0.0, 1.0], [1.0, 0.0]]), -2.0 / 3f64.sqrt()));
        assert_eq!(shape(CellKind::Line3, vec![[0.0, 0.0], [1.0, 0.0], [0.5, 0.0]]), 1.0);
    }

    #[test]
    fn affine_mesh_has_quality_one_and_exact_det_j() {
        // A 2 × 1 rectangle in 4 × 2 Quad4 cells of 0.5 × 0.5: det J = area / 4 = 1/16.
        let s = summarize_mesh(&rectangle(CellKind::Quad4, [0.0, 2.0], [0.0, 1.0], 4, 2));
        assert_eq!(s.nodes, 15);
        assert_eq!(s.elements["quad"], 8);
        assert!((s.min_det_j.unwrap() - 1.0 / 16.0).abs() < 1e-15);
        assert!((s.worst_quality.unwrap() - 1.0).abs() < 1e-12);
        assert_eq!(s.bbox, [[0.0, 0.0], [2.0, 1.0]]);
        assert!(s.physical_groups.iter().any(|g| g.name == "left" && g.dim == 1 && g.elements == 2));
    }

    #[test]
    fn inverted_cell_shows_a_negative_det_j() {
        let mut mesh = rectangle(CellKind::Quad4, [0.0, 1.0], [0.0, 1.0], 1, 1);
        // Corner (1, 1) dragged across the diagonal: a reflex corner, det J changes sign.
        let corner = mesh.points.iter().position(|p| *p == [1.0, 1.0]).unwrap();
        mesh.points[corner] = [0.2, 0.2];
        let s = summarize_mesh(&mesh);
        assert!(s.min_det_j.unwrap() < 0.0 && s.worst_quality.unwrap() < 0.0);
        assert_eq!(s.clockwise_cells, 0);
    }

    #[test]
    fn clockwise_cells_are_counted_and_measured_as_the_model_sees_them() {
        let mesh = rectangle(CellKind::Quad4, [0.0, 2.0], [0.0, 1.0], 4, 2);
        let mut twin = mesh.clone();
        twin.blocks[0].nodes.reverse(); // every cell reversed (and the cell order too)
        let (s, t) = (summarize_mesh(&mesh), summarize_mesh(&twin));
        assert_eq!((s.clockwise_cells, t.clockwise_cells), (0, 8));
        assert_eq!(t.min_det_j, s.min_det_j);
        assert!(t.to_string().contains("clockwise cells: 8"));
    }
}
