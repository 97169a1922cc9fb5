//! Line charts (PNG or SVG, headless) with the bundled font: the one drawing API of the project.
//!
//! ```text
//! line_chart(path, axes, series)   path ".png" → bitmap (1024 × 768), ".svg" → vector; the
//!                                  legend inside the plot, in the corner that hides least
//! line_chart_legend_beside(…)      the same with the legend in a column right of the plot, so
//!                                  that it covers no point (legend_beside_box)
//! log axes                         ticks labelled by log_tick_label: 1e-5, 0.001, 2e-4, 100
//! ```
//! Axis ranges cover every finite point of every series (positive ones only on a log axis), with a
//! 5 % margin on linear axes. Non-finite points are skipped, so a series may carry gaps as NaN.
//! Data that cannot be drawn (no finite point, a range beyond [`DRAWABLE_MAGNITUDE`]) is refused
//! with [`OutputError::Undrawable`], which writers turn into a note in place of the figure.

use std::path::Path;
use std::sync::OnceLock;

use plotters::coord::Shift;
use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::OutputError;
pub(crate) use super::drawable::axis_range;
pub use super::drawable::{DRAWABLE_MAGNITUDE, drawable_range, drawable_text, log_tick_label};

/// DejaVu Sans, embedded so that figures render the same on every machine (no system fonts).
const FONT_BYTES: &[u8] = include_bytes!("../../../../assets/fonts/DejaVuSans.ttf");

/// The size of every figure, in pixels (the SVG's user units).
pub const FIGURE_SIZE: (u32, u32) = (1024, 768);

/// Colours of successive series (the "tab10" palette, distinguishable in print and by most readers
/// with colour-vision deficiency).
pub const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

/// One line of a chart.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// The legend entry.
    pub label: String,
    /// The points (x, y), drawn in this order; non-finite points are skipped.
    pub points: Vec<(f64, f64)>,
    /// Whether each point also gets a marker (a filled circle).
    pub markers: bool,
}

/// Title and axes of a chart (labels carry quantity and unit, e.g. "w (non-dimensional)").
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Axes {
    /// The chart's title (drawn above the plot).
    pub title: String,
    /// The horizontal axis' label.
    pub x_label: String,
    /// The vertical axis' label.
    pub y_label: String,
    /// A logarithmic horizontal axis.
    pub log_x: bool,
    /// A logarithmic vertical axis.
    pub log_y: bool,
}

/// The image format of a figure file, chosen by its extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ImageFormat {
    /// A PNG bitmap.
    Png,
    /// An SVG vector drawing.
    Svg,
}

impl ImageFormat {
    /// The format named by `path`'s extension (".png" or ".svg", any case).
    ///
    /// # Errors
    /// [`OutputError::UnsupportedFormat`] for any other extension.
    pub fn from_path(path: &Path) -> Result<Self, OutputError> {
        let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
        match ext.as_deref() {
            Some("png") => Ok(Self::Png),
            Some("svg") => Ok(Self::Svg),
            _ => Err(OutputError::UnsupportedFormat { path: path.to_path_buf(), expected: "\".png\" or \".svg\"" }),
        }
    }
}

/// Registers the bundled font as plotters' "sans-serif" family, once per process.
///
/// Every drawing function of this module calls it; figure code outside this module that draws with
/// plotters directly calls it first too.
///
/// # Errors
/// [`OutputError::Font`] when the embedded font cannot be parsed (then on every call).
pub fn register_bundled_font() -> Result<(), OutputError> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok =
        *REGISTERED.get_or_init(|| plotters::style::register_font("sans-serif", FontStyle::Normal, FONT_BYTES).is_ok());
    if ok { Ok(()) } else { Err(OutputError::Font) }
}

/// Draws the series as lines (with point markers where asked) with a legend; PNG or SVG chosen by
/// the path's extension (".png" / ".svg"); the bundled font is registered on first use.
///
/// # Errors
/// [`OutputError::UnsupportedFormat`] for another extension, [`OutputError::Font`] if the font
/// cannot be registered, [`OutputError::Draw`] if the backend fails (e.g. the directory is missing).
///
/// # Examples
/// ```
/// use contact2d_pipeline::output::chart::{line_chart, Axes, Series};
/// let dir = std::env::temp_dir().join("contact2d_chart_doctest");
/// std::fs::create_dir_all(&dir).unwrap();
/// let axes = Axes { title: "y = x²".into(), x_label: "x (-)".into(), y_label: "y (-)".into(),
///                   ..Axes::default() };
/// let s = Series { label: "x²".into(), points: (0..10).map(|i| (i as f64, (i * i) as f64)).collect(),
///                  markers: true };
/// line_chart(&dir.join("square.svg"), &axes, &[s]).unwrap();
/// ```
pub fn line_chart(path: &Path, axes: &Axes, series: &[Series]) -> Result<(), OutputError> {
    chart_with_legend(path, axes, series, false)
}

/// [`line_chart`] with the legend in a column right of the plot area ([`legend_beside_box`]),
/// where it covers no point: for charts whose points fill every corner (work-precision plots).
///
/// # Errors
/// As [`line_chart`].
pub fn line_chart_legend_beside(path: &Path, axes: &Axes, series: &[Series]) -> Result<(), OutputError> {
    chart_with_legend(path, axes, series, true)
}

/// The legend's font size, pixels, and the height of one entry.
const LEGEND_FONT: u32 = 16;
const LEGEND_ROW: i32 = 22;

/// The box (x0, y0, x1, y1) of the legend drawn beside the plot for `labels` (their widths in
/// pixels), in figure pixels: a column at the right edge as wide as the widest label plus the
/// 40-pixel sample line, at most 40 % of the figure (longer labels are cut with "…"); the plot
/// takes the rest of the width.
pub fn legend_beside_box(label_widths: &[u32]) -> (i32, i32, i32, i32) {
    let (w, h) = (FIGURE_SIZE.0 as i32, FIGURE_SIZE.1 as i32);
    let widest = label_widths.iter().copied().max().unwrap_or(0) as i32;
    let width = (widest + 56).min(w * 2 / 5);
    let height = (LEGEND_ROW * label_widths.len() as i32 + 12).min(h - 80);
    (w - width - 10, 60, w - 10, 60 + height)
}

fn chart_with_legend(path: &Path, axes: &Axes, series: &[Series], beside: bool) -> Result<(), OutputError> {
    let format = ImageFormat::from_path(path)?;
    // Names from the scene (titles, legends) may hold control characters, which XML forbids.
    let axes = &Axes {
        title: drawable_text(&axes.title),
        x_label: drawable_text(&axes.x_label),
        y_label: drawable_text(&axes.y_label),
        ..axes.clone()
    };
    let series: &[Series] =
        &series.iter().map(|s| Series { label: drawable_text(&s.label), ..s.clone() }).collect::<Vec<_>>();
    register_bundled_font()?;
    let points = || series.iter().flat_map(|s| s.points.iter());
    if points().next().is_some() && !points().any(|p| p.0.is_finite() && p.1.is_finite()) {
        return Err(OutputError::Undrawable { path: path.to_path_buf(), reason: "no finite value to draw".into() });
    }
    // A point is drawn only when both coordinates are finite: only those set the ranges.
    let drawn = || points().filter(|p| p.0.is_finite() && p.1.is_finite());
    let x_range = axis_range(drawn().map(|p| p.0), axes.log_x);
    let y_range = axis_range(drawn().map(|p| p.1), axes.log_y);
    for (axis, (lo, hi)) in [("x", x_range), ("y", y_range)] {
        drawable_range(lo, hi).map_err(|reason| OutputError::Undrawable {
            path: path.to_path_buf(),
            reason: format!("{axis} axis: {reason}"),
        })?;
    }
    let result = match format {
        ImageFormat::Png => {
            let root = BitMapBackend::new(path, FIGURE_SIZE).into_drawing_area();
            draw_with_scales(&root, axes, series, beside, x_range, y_range)
        }
        ImageFormat::Svg => {
            let root = SVGBackend::new(path, FIGURE_SIZE).into_drawing_area();
            draw_with_scales(&root, axes, series, beside, x_range, y_range)
        }
    };
    result.map_err(|reason| OutputError::draw(path, reason))
}

/// Dispatches on the four linear/log combinations (each is a different coordinate type).
fn draw_with_scales<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    axes: &Axes,
    series: &[Series],
    beside: bool,
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
) -> Result<(), String> {
    // Corner 4: the legend beside the plot.
    let corner = if beside { 4 } else { legend_corner(series, [(x0, x1, axes.log_x), (y0, y1, axes.log_y)]) };
    match (axes.log_x, axes.log_y) {
        (false, false) => draw_chart(root, axes, series, corner, x0..x1, y0..y1),
        (true, false) => draw_chart(root, axes, series, corner, (x0..x1).log_scale(), y0..y1),
        (false, true) => draw_chart(root, axes, series, corner, x0..x1, (y0..y1).log_scale()),
        (true, true) => draw_chart(root, axes, series, corner, (x0..x1).log_scale(), (y0..y1).log_scale()),
    }
}

/// The corner (0 upper right, 1 upper left, 2 lower right, 3 lower left) whose legend-sized box
/// (38 % of the width, 28 % of the height) covers the fewest samples of the drawn lines, so that
/// the legend hides as little data as possible; ties go to the upper right.
fn legend_corner(series: &[Series], axes: [(f64, f64, bool); 2]) -> usize {
    let unit = |v: f64, (lo, hi, log): (f64, f64, bool)| {
        if log { (v.ln() - lo.ln()) / (hi.ln() - lo.ln()) } else { (v - lo) / (hi - lo) }
    };
    let mut counts = [0usize; 4];
    for s in series {
        for w in s.points.windows(2) {
            for k in 0..=8 {
                let t = k as f64 / 8.0;
                let (x, y) = (w[0].0 + t * (w[1].0 - w[0].0), w[0].1 + t * (w[1].1 - w[0].1));
                let (u, v) = (unit(x, axes[0]), unit(y, axes[1]));
                if !(u.is_finite() && v.is_finite()) {
                    continue;
                }
                let (right, left, top, bottom) = (u > 0.62, u < 0.38, v > 0.72, v < 0.28);
                for (c, inside) in [right && top, left && top, right && bottom, left && bottom].into_iter().enumerate()
                {
                    counts[c] += usize::from(inside);
                }
            }
        }
    }
    (0..4).min_by_key(|c| counts[*c]).unwrap_or(0)
}

/// Draws the chart on `root` with the given coordinate specs and presents it (writes the file).
fn draw_chart<DB, X, Y>(
    root: &DrawingArea<DB, Shift>,
    axes: &Axes,
    series: &[Series],
    corner: usize,
    x_spec: X,
    y_spec: Y,
) -> Result<(), String>
where
    DB: DrawingBackend,
    X: AsRangedCoord<Value = f64>,
    Y: AsRangedCoord<Value = f64>,
    X::CoordDescType: ValueFormatter<f64>,
    Y::CoordDescType: ValueFormatter<f64>,
{
    let err = |e: &dyn std::fmt::Display| e.to_string();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let labels: Vec<String> = series.iter().filter(|s| !s.label.is_empty()).map(|s| s.label.clone()).collect();
    let font: TextStyle = ("sans-serif", LEGEND_FONT).into();
    let width_of = |t: &str| root.estimate_text_size(t, &font).map_or(0, |(w, _)| w);
    let legend_box = legend_beside_box(&labels.iter().map(|l| width_of(l)).collect::<Vec<_>>());
    let plot_area =
        if corner == 4 && !labels.is_empty() { root.split_horizontally(legend_box.0 - 10).0 } else { root.clone() };
    // Log axes get round tick labels (the backend's own print 9999999998e-5 for 1e-5).
    let (x_log, y_log) = (axes.log_x, axes.log_y);
    let log_format = |v: &f64| log_tick_label(*v);
    let mut chart = ChartBuilder::on(&plot_area)
        .caption(&axes.title, ("sans-serif", 26))
        .margin(18)
        .margin_right(28)
        .x_label_area_size(56)
        .y_label_area_size(96)
        .build_cartesian_2d(x_spec, y_spec)
        .map_err(|e| err(&e))?;
    let mut mesh = chart.configure_mesh();
    mesh.x_desc(axes.x_label.as_str())
        .y_desc(axes.y_label.as_str())
        .label_style(("sans-serif", 16))
        .axis_desc_style(("sans-serif", 18))
        .light_line_style(RGBColor(235, 235, 235));
    if x_log {
        mesh.x_label_formatter(&log_format);
    }
    if y_log {
        mesh.y_label_formatter(&log_format);
    }
    mesh.draw().map_err(|e| err(&e))?;
    let mut any_label = false;
    for (k, s) in series.iter().enumerate() {
        let colour = PALETTE[k % PALETTE.len()];
        let style = colour.stroke_width(2);
        for (r, run) in finite_runs(&s.points).into_iter().enumerate() {
            let drawn = chart.draw_series(LineSeries::new(run.iter().copied(), style)).map_err(|e| err(&e))?;
            // One legend entry per series, attached to its first drawn run.
            if r == 0 && !s.label.is_empty() {
                drawn
                    .label(s.label.as_str())
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], colour.stroke_width(2)));
                any_label = true;
            }
        }
        if s.markers {
            chart
                .draw_series(
                    s.points
                        .iter()
                        .filter(|p| p.0.is_finite() && p.1.is_finite())
                        .map(|&p| Circle::new(p, 3, colour.filled())),
                )
                .map_err(|e| err(&e))?;
        }
    }
    if any_label && corner == 4 {
        draw_legend_beside(root, series, legend_box, &width_of).map_err(|e| err(&e))?;
    } else if any_label {
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font(("sans-serif", 16))
            .position(match corner {
                1 => SeriesLabelPosition::UpperLeft,
                2 => SeriesLabelPosition::LowerRight,
                3 => SeriesLabelPosition::LowerLeft,
                _ => SeriesLabelPosition::UpperRight,
            })
            .draw()
            .map_err(|e| err(&e))?;
    }
    root.present().map_err(|e| err(&e))
}

/// Draws the legend in `bounds` (from [`legend_beside_box`]): a framed column, per labelled
/// series a sample line (with a marker where the series has them) and its label, cut with "…"
/// to the box.
fn draw_legend_beside<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    series: &[Series],
    (x0, y0, x1, y1): (i32, i32, i32, i32),
    width_of: &dyn Fn(&str) -> u32,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    root.draw(&Rectangle::new([(x0, y0), (x1, y1)], WHITE.filled()))?;
    root.draw(&Rectangle::new([(x0, y0), (x1, y1)], BLACK.stroke_width(1)))?;
    let room = (x1 - x0 - 52).max(0) as u32;
    let mut y = y0 + 6 + LEGEND_ROW / 2;
    for (k, s) in series.iter().enumerate() {
        if s.label.is_empty() || y > y1 - LEGEND_ROW / 2 {
            continue;
        }
        let colour = PALETTE[k % PALETTE.len()];
        root.draw(&PathElement::new(vec![(x0 + 8, y), (x0 + 40, y)], colour.stroke_width(2)))?;
        if s.markers {
            root.draw(&Circle::new((x0 + 24, y), 3, colour.filled()))?;
        }
        let (mut label, mut chars) = (s.label.clone(), s.label.chars().collect::<Vec<_>>());
        while width_of(&label) > room && !chars.is_empty() {
            chars.pop();
            label = chars.iter().collect::<String>() + "…";
        }
        let style = ("sans-serif", LEGEND_FONT).into_font().color(&BLACK).pos(Pos::new(HPos::Left, VPos::Center));
        root.draw(&Text::new(label, (x0 + 48, y), style))?;
        y += LEGEND_ROW;
    }
    Ok(())
}

/// The maximal runs of consecutive finite points (a NaN breaks the line).
fn finite_runs(points: &[(f64, f64)]) -> Vec<&[(f64, f64)]> {
    points.split(|p| !(p.0.is_finite() && p.1.is_finite())).filter(|run| !run.is_empty()).collect()
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    fn sample() -> (Axes, Vec<Series>) {
        let axes = Axes {
            title: "Chart test title".into(),
            x_label: "x (non-dimensional)".into(),
            y_label: "y (non-dimensional)".into(),
            log_x: false,
            log_y: false,
        };
        let series = vec![
            Series {
                label: "sin".into(),
                points: (0..50).map(|i| (i as f64 * 0.1, (i as f64 * 0.1).sin())).collect(),
                markers: false,
            },
            Series {
                label: "with a gap".into(),
                points: vec![(0.0, 0.5), (1.0, f64::NAN), (2.0, -0.5), (3.0, 0.0)],
                markers: true,
            },
        ];
        (axes, series)
    }

    fn temp_dir(name: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("contact2d_chart_{name}_{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn writes_png_and_svg() {
        let dir = temp_dir("both");
        let (axes, series) = sample();
        let png = dir.join("c.png");
        let svg = dir.join("c.svg");
        line_chart(&png, &axes, &series).unwrap();
        line_chart(&svg, &axes, &series).unwrap();
        let bytes = std::fs::read(&png).unwrap();
        // The eight-byte PNG signature (PNG specification, section 5.2).
        assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
        let text = std::fs::read_to_string(&svg).unwrap();
        assert!(text.starts_with("<svg"), "{}", &text[..40.min(text.len())]);
        assert!(text.contains("Chart test title"));
        assert!(text.contains("with a gap"));
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn log_axes_and_empty_series_draw() {
        let dir = temp_dir("log");
        let (mut axes, _) = sample();
        axes.log_x = true;
        axes.log_y = true;
        let s = Series {
            label: "power".into(),
            points: vec![(1e-3, 1.0), (1.0, 10.0), (1e3, 100.0), (-1.0, 5.0)],
            markers: true,
        };
        line_chart(&dir.join("log.svg"), &axes, &[s]).unwrap();
        line_chart(&dir.join("empty.png"), &axes, &[]).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn errors_are_typed() {
        let (axes, series) = sample();
        let bad_ext = Path::new("figure.jpg");
        assert!(matches!(line_chart(bad_ext, &axes, &series), Err(OutputError::UnsupportedFormat { .. })));
        let missing_dir = std::env::temp_dir().join("contact2d_no_such_dir_xyz/deeper/c.png");
        assert!(matches!(line_chart(&missing_dir, &axes, &series), Err(OutputError::Draw { .. })));
    }

    #[test]
    fn the_legend_avoids_the_data() {
        let rising = Series { label: "y = x".into(), points: vec![(0.0, 0.0), (1.0, 1.0)], markers: false };
        // A rising diagonal crosses the upper-right and lower-left corners: the legend goes upper left.
        assert_eq!(legend_corner(&[rising], [(0.0, 1.0, false), (0.0, 1.0, false)]), 1);
        assert_eq!(legend_corner(&[], [(0.0, 1.0, false), (0.0, 1.0, false)]), 0);
    }

    #[test]
    fn undrawable_data_is_refused_not_looped_on() {
        let dir = temp_dir("undrawable");
        let (axes, _) = sample();
        for points in [
            vec![(0.0, 1e-310), (1.0, 2e-310)],
            vec![(0.0, 1e300), (1.0, 1e308)],
            vec![(0.0, f64::NAN), (1.0, f64::INFINITY)],
            vec![(1e-320, 0.0), (2e-320, 1.0)],
        ] {
            let s = Series { label: "s".into(), points: points.clone(), markers: true };
            let r = line_chart(&dir.join("u.svg"), &axes, &[s]);
            assert!(matches!(r, Err(OutputError::Undrawable { .. })), "{points:?}: {r:?}");
        }
        // Just inside the bounds both ends draw (the backend's tick loop terminates).
        for points in [vec![(0.0, 1e-149), (1.0, 3e-149)], vec![(0.0, -1e140), (1.0, 1e140)]] {
            let s = Series { label: "s".into(), points, markers: true };
            line_chart(&dir.join("ok.svg"), &axes, &[s]).unwrap();
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }

    /// A `<text>` element of an SVG: x, y, text, anchor, font size.
    type SvgText = (f64, f64, String, String, f64);

    /// The [`SvgText`] of every `<text>` element and the (cx, cy, r) of every `<circle>` of an SVG
    /// written by this module (attributes in double quotes, as plotters writes them).
    fn svg_items(svg: &str) -> (Vec<SvgText>, Vec<(f64, f64, f64)>) {
        let attr = |tag: &str, name: &str| -> Option<f64> {
            let start = tag.find(&format!(" {name}=\""))? + name.len() + 3;
            tag[start..].split('"').next()?.parse().ok()
        };
        let (mut texts, mut circles) = (vec![], vec![]);
        for piece in svg.split('<').skip(1) {
            let (tag, rest) = piece.split_once('>').unwrap_or((piece, ""));
            if tag.starts_with("text ") {
                let anchor = if tag.contains("text-anchor=\"end\"") {
                    "end"
                } else if tag.contains("text-anchor=\"middle\"") {
                    "middle"
                } else {
                    "start"
                };
                let rotated = tag.contains("rotate(");
                let kind = if rotated { format!("{anchor} rotated") } else { anchor.to_string() };
                let size = attr(tag, "font-size").unwrap_or(26.0);
                texts.push((attr(tag, "x").unwrap(), attr(tag, "y").unwrap(), rest.trim().to_string(), kind, size));
            } else if tag.starts_with("circle ") {
                circles.push((attr(tag, "cx").unwrap(), attr(tag, "cy").unwrap(), attr(tag, "r").unwrap()));
            }
        }
        (texts, circles)
    }

    #[test]
    fn a_legend_beside_covers_no_point_and_every_text_is_on_the_canvas() {
        // Twelve series filling the plot's corners on log axes (a work-precision figure: error
        // from 9.99e-6 to 1.2e-3 against time), with long labels.
        let dir = temp_dir("beside");
        let axes = Axes {
            title: "work-precision: contacts.bore.max_pressure".into(),
            x_label: "whole-run wall time (s, median)".into(),
            y_label: "relative error of contacts.bore.max_pressure".into(),
            log_x: true,
            log_y: true,
        };
        let series: Vec<Series> = (0..12)
            .map(|k| Series {
                label: format!("augmented_lagrangian × segment_to_segment {k}"),
                points: (0..3)
                    .map(|l| {
                        (0.05 * 3f64.powi(l) * (1.0 + k as f64), 1.2e-3 * 0.11f64.powi(l) / (1.0 + 0.02 * k as f64))
                    })
                    .chain([(9.99e-6 / 1.0001, 9.99e-6)])
                    .collect(),
                markers: true,
            })
            .collect();
        let path = dir.join("wp.svg");
        line_chart_legend_beside(&path, &axes, &series).unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        let (texts, circles) = svg_items(&svg);
        let (w, h) = (FIGURE_SIZE.0 as f64, FIGURE_SIZE.1 as f64);
        // Text extents: DejaVu Sans averages under 0.62 em per character; the largest font
        // drawn is 26 px (the title), so a label of n characters spans at most 0.62 · size · n.
        for (x, y, text, kind, size) in &texts {
            let width = 0.62 * size * text.chars().count() as f64;
            let (x0, x1) = match kind.split(' ').next().unwrap() {
                "end" => (x - width, *x),
                "middle" => (x - width / 2.0, x + width / 2.0),
                _ => (*x, x + width),
            };
            assert!((0.0..=w).contains(x) && (0.0..=h).contains(y), "{text:?} at ({x}, {y})");
            if !kind.contains("rotated") && !text.contains("augmented") && !text.contains("work-precision") {
                // Tick labels and axis names, whose width this bound does not overestimate
                // into a false alarm: wholly on the canvas.
                assert!(x0 >= 0.0 && x1 <= w, "{text:?} spans [{x0}, {x1}]");
            }
        }
        // No tick label shows the backend's round-off.
        assert!(texts.iter().all(|t| !t.2.contains("9999")), "{texts:?}");
        // The legend box as drawn (legend_beside_box of the labels' widths): its sample
        // markers sit at x0 + 24; every other marker is a data point and lies outside the box.
        let probe = dir.join("probe.svg");
        let (bx0, by0, bx1, by1) = {
            let font: TextStyle = ("sans-serif", LEGEND_FONT).into();
            let root = SVGBackend::new(&probe, FIGURE_SIZE).into_drawing_area();
            let widths: Vec<u32> = series.iter().map(|s| root.estimate_text_size(&s.label, &font).unwrap().0).collect();
            legend_beside_box(&widths)
        };
        let (legend, data): (Vec<_>, Vec<_>) = circles.iter().partition(|c| c.0 == f64::from(bx0 + 24));
        // 12 series × 4 points, and one sample marker per legend entry.
        assert_eq!((data.len(), legend.len()), (48, 12), "{circles:?}");
        assert!(texts.iter().filter(|t| t.2.starts_with("augmented")).all(|t| t.0 > f64::from(bx0)));
        for (cx, cy, r) in data {
            let outside = cx + r < bx0 as f64 || cx - r > bx1 as f64 || cy + r < by0 as f64 || cy - r > by1 as f64;
            assert!(outside, "marker ({cx}, {cy}) under the legend box ({bx0}, {by0})–({bx1}, {by1})");
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
