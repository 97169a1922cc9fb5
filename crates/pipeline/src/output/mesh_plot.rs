//! The mesh figure: plate and insert undeformed (top) and deformed (bottom), element edges drawn as
//! their curves, contact pairs coloured by state.
//!
//! ```text
//! X = x + β u,   β = 1 / max_i |u_i|   (the largest displacement component maps to 1; spec §7)
//! ```
//! Quadratic element edges are drawn as their 3-node curves x(ξ) = Σ N_a(ξ) x_a, sampled at
//! [`EDGE_SAMPLES`] points; both panels have equal x1 and x2 scales.

use std::collections::HashSet;
use std::path::Path;

use contact2d_contact::PairState;
use contact2d_element::EdgeType;
use plotters::coord::Shift;
use plotters::prelude::*;

use super::OutputError;
use super::chart::{FIGURE_SIZE, ImageFormat, drawable_range, register_bundled_font};
use super::step_view::StepView;

/// Points per drawn element edge.
pub const EDGE_SAMPLES: usize = 7;

/// Colours of the pair states: stick, slip, free.
const STICK: RGBColor = RGBColor(31, 119, 180);
const SLIP: RGBColor = RGBColor(214, 39, 40);
const FREE: RGBColor = RGBColor(150, 150, 150);
/// Colour of frictionless pairs in contact.
const CONTACT: RGBColor = RGBColor(44, 160, 44);

/// The polylines of every element edge of every body (each shared edge once) and, for a rigid
/// insert (no body), of the insert contour, at positions `x` (one per mesh node).
pub(crate) fn edge_polylines(step: &StepView, x: &[[f64; 2]]) -> Vec<Vec<(f64, f64)>> {
    let model = &step.problem.model;
    let mut seen = HashSet::new();
    let mut lines = vec![];
    for body in &model.bodies {
        for c in 0..body.num_cells() {
            let element = body.elements[c];
            let nodes = body.cell_nodes(c);
            for edge in element.edges() {
                let (a, b) = (nodes[edge[0]].0, nodes[edge[1]].0);
                if !seen.insert((a.min(b), a.max(b))) {
                    continue;
                }
                let mid = (element.degree() > 1).then(|| nodes[edge[2]].0);
                lines.push(curve(x, a, b, mid));
            }
        }
    }
    for obstacle in &step.obstacles {
        for e in &obstacle.edges {
            lines.push(curve(x, e.nodes[0].0, e.nodes[1].0, e.quadratic.then_some(e.nodes[2].0)));
        }
    }
    lines
}

/// An edge from node `a` to node `b` (through `mid` when quadratic), sampled along ξ ∈ [−1, 1].
fn curve(x: &[[f64; 2]], a: usize, b: usize, mid: Option<usize>) -> Vec<(f64, f64)> {
    let Some(m) = mid else {
        return vec![(x[a][0], x[a][1]), (x[b][0], x[b][1])];
    };
    (0..EDGE_SAMPLES)
        .map(|k| {
            let xi = -1.0 + 2.0 * k as f64 / (EDGE_SAMPLES - 1) as f64;
            let (n, _) = EdgeType::Line3.eval(xi);
            let p = |i: usize| n[0] * x[a][i] + n[1] * x[b][i] + n[2] * x[m][i];
            (p(0), p(1))
        })
        .collect()
}

/// Axis ranges containing `bounds` ([[x_min, y_min], [x_max, y_max]]) with a 4 % margin, widened so
/// that one unit has the same length on both axes in a plot area of `pixels` (width, height).
pub(crate) fn equal_aspect_ranges(bounds: [[f64; 2]; 2], pixels: (f64, f64)) -> ((f64, f64), (f64, f64)) {
    let [[x0, y0], [x1, y1]] = bounds;
    let (mut w, mut h) = ((x1 - x0).max(1e-12) * 1.08, (y1 - y0).max(1e-12) * 1.08);
    let (cx, cy) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
    // Units per pixel must agree: w / px = h / py.
    if w / pixels.0 > h / pixels.1 {
        h = w * pixels.1 / pixels.0;
    } else {
        w = h * pixels.0 / pixels.1;
    }
    ((cx - 0.5 * w, cx + 0.5 * w), (cy - 0.5 * h, cy + 0.5 * h))
}

pub(crate) use super::step_view::bounding_box;

/// The exaggeration β of spec §7: the largest displacement component maps to 1 (0 if nothing
/// moves, or if the displacements are too small for 1 / max to be finite, or not finite).
pub fn exaggeration(u: &[f64]) -> f64 {
    let max = u.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let beta = 1.0 / max;
    if max > 0.0 && beta.is_finite() { beta } else { 0.0 }
}

/// Draws the axes of a chart of the bodies in the plane (x1, x2 labelled, no grid).
pub(crate) fn draw_plane_axes<DB: DrawingBackend>(
    chart: &mut ChartContext<
        '_,
        DB,
        Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
    >,
    axes: &[String; 2],
) -> Result<(), String> {
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc(axes[0].as_str())
        .y_desc(axes[1].as_str())
        .label_style(("sans-serif", 14))
        .axis_desc_style(("sans-serif", 15))
        .draw()
        .map_err(|e| e.to_string())
}

/// Draws the mesh figure of `step` to `path` (PNG or SVG by extension).
///
/// # Errors
/// [`OutputError::UnsupportedFormat`], [`OutputError::Font`] or [`OutputError::Draw`].
pub fn draw_mesh(path: &Path, title: &str, step: &StepView) -> Result<(), OutputError> {
    let format = ImageFormat::from_path(path)?;
    register_bundled_font()?;
    let undrawable = |reason: String| OutputError::Undrawable { path: path.to_path_buf(), reason };
    if step.solution.displacement.iter().any(|v| !v.is_finite()) {
        return Err(undrawable("non-finite displacements".into()));
    }
    let bounds = bounding_box(step.problem.model.mesh.points.iter());
    for (axis, k) in [("x1", 0), ("x2", 1)] {
        drawable_range(bounds[0][k], bounds[1][k]).map_err(|r| undrawable(format!("mesh extent in {axis}: {r}")))?;
    }
    let title = &super::chart::drawable_text(title);
    let result = match format {
        ImageFormat::Png => draw_on(&BitMapBackend::new(path, FIGURE_SIZE).into_drawing_area(), title, step),
        ImageFormat::Svg => draw_on(&SVGBackend::new(path, FIGURE_SIZE).into_drawing_area(), title, step),
    };
    result.map_err(|reason| OutputError::draw(path, reason))
}

fn draw_on<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>, title: &str, step: &StepView) -> Result<(), String> {
    let err = |e: &dyn std::fmt::Display| e.to_string();
    let mesh = &step.problem.model.mesh;
    let u = &step.solution.displacement;
    let beta = exaggeration(u);
    let undeformed = mesh.points.clone();
    let at = |k: usize| u.get(k).copied().unwrap_or(0.0);
    let deformed: Vec<[f64; 2]> =
        mesh.points.iter().enumerate().map(|(i, p)| [p[0] + beta * at(2 * i), p[1] + beta * at(2 * i + 1)]).collect();
    let bounds = bounding_box(undeformed.iter().chain(&deformed));

    root.fill(&WHITE).map_err(|e| err(&e))?;
    let root = root.titled(title, ("sans-serif", 24)).map_err(|e| err(&e))?;
    let panels = root.split_evenly((2, 1));
    let captions = ["undeformed x".to_string(), format!("deformed X = x + β u, β = {beta:.4}")];
    for ((panel, x), caption) in panels.iter().zip([&undeformed, &deformed]).zip(captions) {
        let (pw, ph) = panel.dim_in_pixel();
        // The plot area: the panel less the label areas, margins and caption drawn below.
        let pixels = ((pw as f64 - 60.0 - 2.0 * 8.0).max(10.0), (ph as f64 - 40.0 - 2.0 * 8.0 - 26.0).max(10.0));
        let (xr, yr) = equal_aspect_ranges(bounds, pixels);
        let mut chart = ChartBuilder::on(panel)
            .caption(caption, ("sans-serif", 18))
            .margin(8)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(xr.0..xr.1, yr.0..yr.1)
            .map_err(|e| err(&e))?;
        draw_plane_axes(&mut chart, &step.axes)?;
        let edge_style = RGBColor(90, 90, 90).stroke_width(1);
        chart
            .draw_series(edge_polylines(step, x).into_iter().map(|line| PathElement::new(line, edge_style)))
            .map_err(|e| err(&e))?;
        draw_pairs(&mut chart, step, x).map_err(|e| err(&e))?;
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK)
            .label_font(("sans-serif", 14))
            .position(SeriesLabelPosition::UpperRight)
            .draw()
            .map_err(|e| err(&e))?;
    }
    root.present().map_err(|e| err(&e))
}

/// The master node of every pair, a filled circle in the colour of its state, one legend entry per
/// state present.
fn draw_pairs<DB: DrawingBackend>(
    chart: &mut ChartContext<
        DB,
        Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
    >,
    step: &StepView,
    x: &[[f64; 2]],
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let pairs = &step.problem.pairs;
    let states = &step.solution.state;
    let friction = &step.problem.friction;
    // A frictionless pair in contact is "contact", not "stick".
    let group = |s: &PairState, mu: f64| match s {
        PairState::Stick if mu == 0.0 => 3,
        PairState::Stick => 0,
        PairState::SlipPositive | PairState::SlipNegative => 1,
        PairState::Free => 2,
    };
    let legend = [("stick", STICK), ("slip", SLIP), ("free", FREE), ("contact", CONTACT)];
    for (g, (name, colour)) in legend.into_iter().enumerate() {
        let points: Vec<(f64, f64)> = pairs
            .iter()
            .zip(states)
            .zip(friction)
            .filter(|((_, s), mu)| group(s, **mu) == g)
            .map(|((p, s), _)| (p, s))
            .map(|(p, _)| (x[p.master.0][0], x[p.master.0][1]))
            .collect();
        if points.is_empty() {
            continue;
        }
        chart
            .draw_series(points.into_iter().map(|p| Circle::new(p, 3, colour.filled())))?
            .label(format!("{name} pairs"))
            .legend(move |(px, py)| Circle::new((px + 10, py), 4, colour.filled()));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exaggeration_maps_the_largest_component_to_one() {
        assert_eq!(exaggeration(&[0.0, -0.5, 0.25]), 2.0);
        assert_eq!(exaggeration(&[0.0, 0.0]), 0.0);
        assert_eq!(exaggeration(&[1e-310]), 0.0, "1/1e-310 overflows");
        assert_eq!(exaggeration(&[f64::INFINITY]), 0.0);
    }

    #[test]
    fn equal_aspect_ranges_have_equal_units_per_pixel() {
        let ((x0, x1), (y0, y1)) = equal_aspect_ranges([[-2.5, 0.0], [5.0, 2.5]], (900.0, 300.0));
        assert!(((x1 - x0) / 900.0 - (y1 - y0) / 300.0).abs() < 1e-12);
        assert!(x0 <= -2.5 && x1 >= 5.0 && y0 <= 0.0 && y1 >= 2.5);
    }

    #[test]
    fn a_quadratic_edge_passes_through_its_three_nodes() {
        let x = [[0.0, 0.0], [2.0, 0.0], [1.0, 1.0]];
        let c = curve(&x, 0, 1, Some(2));
        assert_eq!(c.len(), EDGE_SAMPLES);
        assert_eq!(c[0], (0.0, 0.0));
        assert_eq!(c[EDGE_SAMPLES - 1], (2.0, 0.0));
        let mid = c[EDGE_SAMPLES / 2];
        assert!((mid.0 - 1.0).abs() < 1e-12 && (mid.1 - 1.0).abs() < 1e-12);
    }
}
