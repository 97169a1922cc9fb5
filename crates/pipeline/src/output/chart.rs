//! Line charts (PNG or SVG, headless) with the bundled font: the one drawing API of the project.
//!
//! ```text
//! line_chart(path, axes, series)   path ".png" → bitmap (1024 × 768), ".svg" → vector
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

use super::OutputError;

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
            draw_with_scales(&root, axes, series, x_range, y_range)
        }
        ImageFormat::Svg => {
            let root = SVGBackend::new(path, FIGURE_SIZE).into_drawing_area();
            draw_with_scales(&root, axes, series, x_range, y_range)
        }
    };
    result.map_err(|reason| OutputError::draw(path, reason))
}

/// `text` with every control character (C0, DEL, C1; tab and line breaks included, which a
/// one-line label cannot show) and the non-characters U+FFFE, U+FFFF replaced by U+FFFD, so that
/// it can go into any figure: XML 1.0, and so SVG, allows no C0 control but tab and line breaks.
pub fn drawable_text(text: &str) -> String {
    text.chars().map(|c| if c.is_control() || c == '\u{FFFE}' || c == '\u{FFFF}' { '\u{FFFD}' } else { c }).collect()
}

/// The largest magnitude an axis may reach and the smallest range it may span: the plotting
/// backend computes tick positions by repeated steps of 10^⌊log10(range)⌋, which overflow,
/// underflow to subnormals or never end outside these bounds.
pub const DRAWABLE_MAGNITUDE: (f64, f64) = (1e-150, 1e150);

/// Checks that an axis range `lo..hi` can be drawn: finite, `hi > lo`, within
/// [`DRAWABLE_MAGNITUDE`] (|lo|, |hi| ≤ 1e150 and hi − lo ≥ 1e-150).
///
/// # Errors
/// Why the range cannot be drawn, for a note in place of the figure.
pub fn drawable_range(lo: f64, hi: f64) -> Result<(), String> {
    let (small, large) = DRAWABLE_MAGNITUDE;
    if !(lo.is_finite() && hi.is_finite()) {
        return Err(format!("non-finite range [{lo}, {hi}]"));
    }
    if hi <= lo {
        return Err(format!("zero range at {lo}"));
    }
    if lo.abs().max(hi.abs()) > large {
        return Err(format!("values up to {:.3e} exceed ±{large:e}", lo.abs().max(hi.abs())));
    }
    if hi - lo < small {
        return Err(format!("range {:.3e} is below {small:e}", hi - lo));
    }
    Ok(())
}

/// The range of an axis over the finite values (positive ones on a log axis), with a margin.
pub(crate) fn axis_range(values: impl Iterator<Item = f64>, log: bool) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite() && (!log || *v > 0.0))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)));
    if !lo.is_finite() {
        return if log { (0.1, 10.0) } else { (0.0, 1.0) };
    }
    if log {
        // A 5 % margin in log space.
        let pad = if hi / lo < 1.0 + 1e-9 { 2.0 } else { (hi / lo).powf(0.05) };
        (lo / pad, hi * pad)
    } else {
        let span = hi - lo;
        if span <= 1e-12 * hi.abs().max(lo.abs()).max(1e-300) {
            let pad = if lo == 0.0 { 1.0 } else { 0.1 * lo.abs() };
            (lo - pad, hi + pad)
        } else {
            (lo - 0.05 * span, hi + 0.05 * span)
        }
    }
}

/// Dispatches on the four linear/log combinations (each is a different coordinate type).
fn draw_with_scales<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    axes: &Axes,
    series: &[Series],
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
) -> Result<(), String> {
    let corner = legend_corner(series, [(x0, x1, axes.log_x), (y0, y1, axes.log_y)]);
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
    let mut chart = ChartBuilder::on(root)
        .caption(&axes.title, ("sans-serif", 26))
        .margin(18)
        .x_label_area_size(56)
        .y_label_area_size(84)
        .build_cartesian_2d(x_spec, y_spec)
        .map_err(|e| err(&e))?;
    chart
        .configure_mesh()
        .x_desc(axes.x_label.as_str())
        .y_desc(axes.y_label.as_str())
        .label_style(("sans-serif", 16))
        .axis_desc_style(("sans-serif", 18))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()
        .map_err(|e| err(&e))?;
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
    if any_label {
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

    #[test]
    fn axis_range_covers_the_data() {
        assert_eq!(axis_range([0.0, 10.0].into_iter(), false), (-0.5, 10.5));
        let (lo, hi) = axis_range([1e-2, 1e2, -3.0].into_iter(), true);
        assert!((lo * 10f64.powf(0.2) - 1e-2).abs() < 1e-12 && (hi / 10f64.powf(0.2) - 1e2).abs() < 1e-9);
        assert_eq!(axis_range(std::iter::empty(), false), (0.0, 1.0));
        let (lo, hi) = axis_range([2.0, 2.0].into_iter(), false);
        assert!(lo < 2.0 && hi > 2.0);
    }
}
