//! The von Mises field of both bodies on the undeformed geometry, with a colour bar.
//!
//! ```text
//! σ_vM = √(½[(σ11 − σ22)² + (σ22 − σ33)² + (σ33 − σ11)²] + 3 σ12²)   (σ33 from the plane condition)
//! ```
//! Each cell is cut into [`SUBDIVISION`]² sub-cells in reference coordinates (sub-triangles for
//! triangles); a sub-cell is the polygon of its mapped corners, filled with the viridis colour of
//! σ_vM evaluated from the element's own displacement field at its reference centre (no
//! smoothing across cells). The colour bar spans the smallest to the largest sub-cell value.

use std::path::Path;

use contact2d_element::{ElementType, map_point, stress_state_at, von_mises};
use plotters::coord::Shift;
use plotters::prelude::*;

use super::OutputError;
use super::chart::{FIGURE_SIZE, ImageFormat, drawable_range, register_bundled_font};
use super::mesh_plot::{bounding_box, draw_plane_axes, equal_aspect_ranges};
use super::step_view::StepView;

/// Sub-cells per cell edge.
pub const SUBDIVISION: usize = 3;

/// One filled sub-cell: its corners and its value.
#[derive(Debug, Clone, PartialEq)]
pub struct SubCell {
    /// Corners (undeformed positions).
    pub corners: Vec<(f64, f64)>,
    /// σ_vM at the sub-cell's reference centre.
    pub value: f64,
}

/// The sub-cells of every cell of every body with their von Mises stress.
///
/// # Errors
/// [`OutputError::Element`] where an element map or stress cannot be evaluated.
pub fn von_mises_cells(step: &StepView) -> Result<Vec<SubCell>, OutputError> {
    let model = &step.problem.model;
    let u = &step.solution.displacement;
    let mut cells = vec![];
    for body in &model.bodies {
        for c in 0..body.num_cells() {
            let element = body.elements[c];
            let coords = body.cell_coords(&model.mesh, c);
            let ue: Vec<f64> = body.cell_dofs(c).map(|d| u[d.0]).collect();
            for corners in reference_subcells(element) {
                let n = corners.len() as f64;
                let centre = corners.iter().fold([0.0, 0.0], |a, p| [a[0] + p[0] / n, a[1] + p[1] / n]);
                let state =
                    stress_state_at(element, &coords, &body.material, &body.kinematics, &ue, centre, body.formulation)?;
                let mapped = corners
                    .iter()
                    .map(|xi| map_point(element, &coords, *xi).map(|m| (m.x[0], m.x[1])))
                    .collect::<Result<Vec<_>, _>>()?;
                cells.push(SubCell { corners: mapped, value: von_mises(&state) });
            }
        }
    }
    Ok(cells)
}

/// The sub-cells of the reference element as corner lists in reference coordinates.
fn reference_subcells(element: ElementType) -> Vec<Vec<[f64; 2]>> {
    let n = SUBDIVISION;
    let h = 1.0 / n as f64;
    let mut out = vec![];
    if element.is_triangle() {
        let p = |i: usize, j: usize| [i as f64 * h, j as f64 * h];
        for i in 0..n {
            for j in 0..n - i {
                out.push(vec![p(i, j), p(i + 1, j), p(i, j + 1)]);
                if i + j + 1 < n {
                    out.push(vec![p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)]);
                }
            }
        }
    } else {
        let p = |i: usize, j: usize| [-1.0 + 2.0 * i as f64 * h, -1.0 + 2.0 * j as f64 * h];
        for i in 0..n {
            for j in 0..n {
                out.push(vec![p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)]);
            }
        }
    }
    out
}

/// Draws the von Mises field of `step` to `path` (PNG or SVG by extension).
///
/// # Errors
/// As [`von_mises_cells`], plus [`OutputError::UnsupportedFormat`], [`OutputError::Font`],
/// [`OutputError::Draw`].
pub fn draw_von_mises(path: &Path, title: &str, step: &StepView) -> Result<(), OutputError> {
    let format = ImageFormat::from_path(path)?;
    register_bundled_font()?;
    let cells = von_mises_cells(step)?;
    let undrawable = |reason: String| OutputError::Undrawable { path: path.to_path_buf(), reason };
    if cells.iter().any(|c| !c.value.is_finite() || c.corners.iter().any(|p| !(p.0.is_finite() && p.1.is_finite()))) {
        return Err(undrawable("non-finite von Mises stress or geometry".into()));
    }
    let (lo, hi) = colour_range(&cells);
    drawable_range(lo, hi).map_err(|r| undrawable(format!("colour bar: {r}")))?;
    let bounds = bounding_box(step.problem.model.mesh.points.iter());
    for (axis, k) in [("x1", 0), ("x2", 1)] {
        drawable_range(bounds[0][k], bounds[1][k]).map_err(|r| undrawable(format!("mesh extent in {axis}: {r}")))?;
    }
    let size = figure_size(bounding_box(step.problem.model.mesh.points.iter()));
    let title = &super::chart::drawable_text(title);
    let result = match format {
        ImageFormat::Png => draw_on(&BitMapBackend::new(path, size).into_drawing_area(), title, step, &cells, true),
        ImageFormat::Svg => draw_on(&SVGBackend::new(path, size).into_drawing_area(), title, step, &cells, false),
    };
    result.map_err(|reason| OutputError::draw(path, reason))
}

/// The colour bar's range: the smallest to the largest finite sub-cell value (a constant field
/// v gets [v, v + 1], no value [0, 1]).
fn colour_range(cells: &[SubCell]) -> (f64, f64) {
    let (lo, hi) = cells.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), c| {
        if c.value.is_finite() { (lo.min(c.value), hi.max(c.value)) } else { (lo, hi) }
    });
    if lo < hi {
        (lo, hi)
    } else if lo.is_finite() {
        (lo, lo + 1.0)
    } else {
        (0.0, 1.0)
    }
}

/// A figure as wide as [`FIGURE_SIZE`] and as high as the geometry needs at equal scales (the
/// colour bar, labels and title take 300 × 110 pixels), between 400 and 1000 pixels.
fn figure_size(bounds: [[f64; 2]; 2]) -> (u32, u32) {
    let (w, h) = (bounds[1][0] - bounds[0][0], bounds[1][1] - bounds[0][1]);
    let plot_width = f64::from(FIGURE_SIZE.0 - 300);
    let height = if w > 0.0 && h.is_finite() { 1.08 * plot_width * h / w + 110.0 } else { f64::from(FIGURE_SIZE.1) };
    (FIGURE_SIZE.0, height.clamp(400.0, 1000.0) as u32)
}

fn draw_on<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    title: &str,
    step: &StepView,
    cells: &[SubCell],
    outlines: bool,
) -> Result<(), String> {
    let err = |e: &dyn std::fmt::Display| e.to_string();
    let (lo, hi) = colour_range(cells);
    // The colour map indexes its table by the normalised value: keep it in [lo, hi] (a NaN
    // is excluded by draw_von_mises; clamping guards the table anyway).
    let colour = |v: f64| ViridisRGB::get_color_normalized(if v.is_nan() { lo } else { v.clamp(lo, hi) }, lo, hi);

    root.fill(&WHITE).map_err(|e| err(&e))?;
    let title = format!("{title}, {} in [{lo:.4}, {hi:.4}]", step.stress_label);
    let root = root.titled(&title, ("sans-serif", 22)).map_err(|e| err(&e))?;
    let (field, bar) = root.split_horizontally(root.dim_in_pixel().0 - 150);

    let mesh = &step.problem.model.mesh;
    let bounds = bounding_box(mesh.points.iter());
    let (fw, fh) = field.dim_in_pixel();
    let (xr, yr) = equal_aspect_ranges(bounds, (fw as f64 - 60.0 - 20.0, fh as f64 - 40.0 - 20.0));
    let mut chart = ChartBuilder::on(&field)
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(xr.0..xr.1, yr.0..yr.1)
        .map_err(|e| err(&e))?;
    draw_plane_axes(&mut chart, &step.axes)?;
    chart
        .draw_series(cells.iter().map(|c| Polygon::new(c.corners.clone(), colour(c.value).filled())))
        .map_err(|e| err(&e))?;
    // Outlines in the fill colour close the hairline gaps the bitmap rasteriser leaves between
    // polygons (SVG viewers anti-alias instead; outlines there would double the file).
    let outlined = if outlines { cells } else { &[] };
    chart
        .draw_series(outlined.iter().map(|c| {
            let mut ring = c.corners.clone();
            ring.extend(c.corners.first().copied());
            PathElement::new(ring, colour(c.value).stroke_width(1))
        }))
        .map_err(|e| err(&e))?;

    // The colour bar: 100 bands over [lo, hi] with a value axis.
    let mut bar_chart = ChartBuilder::on(&bar)
        .margin_top(40)
        .margin_bottom(50)
        .margin_right(10)
        .y_label_area_size(80)
        .caption(step.stress_label.as_str(), ("sans-serif", 16))
        .build_cartesian_2d(0.0..1.0, lo..hi)
        .map_err(|e| err(&e))?;
    bar_chart
        .configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .y_labels(8)
        .label_style(("sans-serif", 13))
        .draw()
        .map_err(|e| err(&e))?;
    let bands = 100;
    bar_chart
        .draw_series((0..bands).map(|k| {
            let v0 = lo + (hi - lo) * k as f64 / bands as f64;
            let v1 = lo + (hi - lo) * (k + 1) as f64 / bands as f64;
            Rectangle::new([(0.0, v0), (1.0, v1)], colour(0.5 * (v0 + v1)).filled())
        }))
        .map_err(|e| err(&e))?;
    root.present().map_err(|e| err(&e))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The sub-cells tile the reference element: their areas sum to its area (4 or 1/2).
    #[test]
    fn subcells_tile_the_reference_element() {
        let area = |c: &Vec<[f64; 2]>| {
            let n = c.len();
            0.5 * (0..n).map(|i| c[i][0] * c[(i + 1) % n][1] - c[(i + 1) % n][0] * c[i][1]).sum::<f64>()
        };
        let quad: f64 = reference_subcells(ElementType::Quad9).iter().map(area).sum();
        let tri: f64 = reference_subcells(ElementType::Tri6).iter().map(area).sum();
        assert!((quad - 4.0).abs() < 1e-12 && (tri - 0.5).abs() < 1e-12);
        assert_eq!(reference_subcells(ElementType::Tri3).len(), SUBDIVISION * SUBDIVISION);
    }
}
