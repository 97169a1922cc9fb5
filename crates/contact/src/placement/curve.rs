//! Master curves whose nodes can be placed: a straight segment or a circular arc, detected from
//! the master contour's nodes, with the coordinate c the zone-end search works on.
//!
//! ```text
//! line   x(c) = x₀ + c L t             (t the unit chord from the first node to the last, L its length)
//! arc    x(c) = x_c + r (cos θ, sin θ),  θ = θ₀ + σ c Θ   (Θ the arc's angle, σ = ±1 its turn)
//! c      = s / L ∈ [0, 1]: arc length from the start over the curve's length (dimensionless,
//!          as the paper's η = 1 − φ/π is on its half circle: the search's tolerances are in c)
//! detect every node within TOLERANCE × L of the line through the ends (line), else within
//!        TOLERANCE × r of the circle through the first, middle and last node (arc), the
//!        nodes' c strictly increasing along the contour in both cases
//! ```

use std::f64::consts::PI;

/// Relative distance of a node from the detected line (× the chord) or circle (× the radius)
/// still taken as on it: 1e-6, as the generic zone ends take a curve as circular
/// (`crates/pipeline/src/generic/zones.rs`). Gmsh writes coordinates to 16 digits and places curve nodes on the
/// exact geometry, so a meshed line or circle is within ~1e-15 of it; a polygon with a kink or a
/// circle of another radius is off by far more than 1e-6 of its size.
pub const TOLERANCE: f64 = 1e-6;

/// A straight or circular master curve, oriented from the end where the contact zone starts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MasterCurve {
    /// A straight segment.
    Line {
        /// The start point (c = 0).
        start: [f64; 2],
        /// The unit tangent from the start to the end.
        tangent: [f64; 2],
        /// The length L.
        length: f64,
    },
    /// A circular arc.
    Arc {
        /// The centre.
        centre: [f64; 2],
        /// The radius r.
        radius: f64,
        /// The polar angle θ₀ of the start about the centre, radians.
        start_angle: f64,
        /// The arc's angle Θ > 0, radians.
        span: f64,
        /// +1 counter-clockwise from the start, −1 clockwise.
        turn: f64,
    },
}

impl MasterCurve {
    /// The line or circle through `points` (a contour's nodes in order), oriented from the first
    /// point to the last; `Err` says why the points are neither (see the module docs).
    ///
    /// # Errors
    /// A reason in words: too few points, coinciding ends, or a node off both the line and the
    /// circle by more than [`TOLERANCE`].
    pub fn detect(points: &[[f64; 2]]) -> Result<MasterCurve, String> {
        let n = points.len();
        if n < 3 {
            return Err(format!("the master curve has {n} nodes; at least 3 are needed"));
        }
        let (first, last) = (points[0], points[n - 1]);
        let chord = [last[0] - first[0], last[1] - first[1]];
        let length = chord[0].hypot(chord[1]);
        if length.is_nan() || length == 0.0 {
            return Err("the master curve is closed (its ends coincide)".into());
        }
        let tangent = [chord[0] / length, chord[1] / length];
        let off_line = points
            .iter()
            .map(|p| ((p[0] - first[0]) * tangent[1] - (p[1] - first[1]) * tangent[0]).abs())
            .fold(0.0, f64::max);
        if off_line <= TOLERANCE * length {
            return MasterCurve::Line { start: first, tangent, length }.monotone(points);
        }
        let Some((centre, radius)) = circle_through(first, points[n / 2], last) else {
            return Err(format!("a node lies {:.3e} of the chord off the line through the ends", off_line / length));
        };
        let off_circle =
            points.iter().map(|p| ((p[0] - centre[0]).hypot(p[1] - centre[1]) - radius).abs()).fold(0.0, f64::max);
        if off_circle > TOLERANCE * radius {
            return Err(format!(
                "the master curve is neither straight nor circular: a node lies {:.3e} of the chord off the line \
                 through its ends and {:.3e} of the radius off the circle through its ends and middle node \
                 (tolerance {TOLERANCE:.0e})",
                off_line / length,
                off_circle / radius
            ));
        }
        // The angle swept from the first node, unwrapped node by node.
        let angle = |p: [f64; 2]| (p[1] - centre[1]).atan2(p[0] - centre[0]);
        let start_angle = angle(first);
        let mut swept = 0.0;
        for w in points.windows(2) {
            swept += wrap(angle(w[1]) - angle(w[0]));
        }
        let arc = MasterCurve::Arc { centre, radius, start_angle, span: swept.abs(), turn: swept.signum() };
        arc.monotone(points)
    }

    /// `self` if the points' coordinates increase strictly along the contour.
    fn monotone(self, points: &[[f64; 2]]) -> Result<MasterCurve, String> {
        let c: Vec<f64> = points.iter().map(|p| self.coordinate(*p)).collect();
        match c.windows(2).position(|w| w[1] <= w[0]) {
            Some(i) => Err(format!("the master contour turns back along its curve at node {}", i + 1)),
            None => Ok(self),
        }
    }

    /// The same curve traversed from its other end.
    pub fn reversed(self) -> MasterCurve {
        match self {
            MasterCurve::Line { start, tangent, length } => MasterCurve::Line {
                start: [start[0] + length * tangent[0], start[1] + length * tangent[1]],
                tangent: [-tangent[0], -tangent[1]],
                length,
            },
            MasterCurve::Arc { centre, radius, start_angle, span, turn } => {
                MasterCurve::Arc { centre, radius, start_angle: start_angle + turn * span, span, turn: -turn }
            }
        }
    }

    /// The curve's length L.
    pub fn length(&self) -> f64 {
        match *self {
            MasterCurve::Line { length, .. } => length,
            MasterCurve::Arc { radius, span, .. } => radius * span,
        }
    }

    /// c of a point on (or near) the curve: its projection's arc length from the start over L.
    pub fn coordinate(&self, x: [f64; 2]) -> f64 {
        match *self {
            MasterCurve::Line { start, tangent, length } => {
                ((x[0] - start[0]) * tangent[0] + (x[1] - start[1]) * tangent[1]) / length
            }
            MasterCurve::Arc { centre, start_angle, span, turn, .. } => {
                let d = turn * ((x[1] - centre[1]).atan2(x[0] - centre[0]) - start_angle);
                // The turn of d (mod 2π) nearest to the arc's middle: arcs up to a full circle.
                let d = d - 2.0 * PI * ((d - 0.5 * span) / (2.0 * PI)).round();
                d / span
            }
        }
    }

    /// The point at coordinate `c`.
    pub fn point(&self, c: f64) -> [f64; 2] {
        match *self {
            MasterCurve::Line { start, tangent, length } => {
                [start[0] + c * length * tangent[0], start[1] + c * length * tangent[1]]
            }
            MasterCurve::Arc { centre, radius, start_angle, span, turn } => {
                let theta = start_angle + turn * c * span;
                [centre[0] + radius * theta.cos(), centre[1] + radius * theta.sin()]
            }
        }
    }

    /// The centre of an arc (none for a line).
    pub fn centre(&self) -> Option<[f64; 2]> {
        match *self {
            MasterCurve::Line { .. } => None,
            MasterCurve::Arc { centre, .. } => Some(centre),
        }
    }
}

/// An angle reduced to (−π, π].
fn wrap(a: f64) -> f64 {
    let r = a - 2.0 * PI * (a / (2.0 * PI)).round();
    if r <= -PI { r + 2.0 * PI } else { r }
}

/// The circumcircle of three points (centre, radius); `None` when they are collinear:
/// `c = (|a|²(b − c)^⊥ + |b|²(c − a)^⊥ + |c|²(a − b)^⊥) / (2 a × (b − c) + …)`, the point
/// equidistant from all three.
pub fn circle_through(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Option<([f64; 2], f64)> {
    let d = 2.0 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]));
    if d.abs() < f64::EPSILON {
        return None;
    }
    let sq = |p: [f64; 2]| p[0] * p[0] + p[1] * p[1];
    let cx = (sq(a) * (b[1] - c[1]) + sq(b) * (c[1] - a[1]) + sq(c) * (a[1] - b[1])) / d;
    let cy = (sq(a) * (c[0] - b[0]) + sq(b) * (a[0] - c[0]) + sq(c) * (b[0] - a[0])) / d;
    Some(([cx, cy], (a[0] - cx).hypot(a[1] - cy)))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn half_circle(n: usize) -> Vec<[f64; 2]> {
        (0..n).map(|i| PI * i as f64 / (n - 1) as f64).map(|t| [2.0 + 3.0 * t.cos(), 3.0 * t.sin()]).collect()
    }

    #[test]
    fn a_half_circle_is_an_arc_whose_coordinate_is_the_angle_over_pi() {
        let points = half_circle(9);
        let curve = MasterCurve::detect(&points);
        assert!(curve.is_ok(), "{curve:?}");
        let Ok(curve) = curve else { return };
        assert!((curve.length() - 3.0 * PI).abs() < 1e-12, "length {}", curve.length());
        for (i, p) in points.iter().enumerate() {
            let want = i as f64 / 8.0;
            assert!((curve.coordinate(*p) - want).abs() < 1e-12);
            let q = curve.point(want);
            assert!((q[0] - p[0]).hypot(q[1] - p[1]) < 1e-12);
        }
        let back = curve.reversed();
        assert!((back.coordinate(points[2]) - 0.75).abs() < 1e-12, "reversed: c = 1 − c");
    }

    #[test]
    fn a_segment_is_a_line_and_a_kinked_polyline_is_refused() {
        let line: Vec<[f64; 2]> = (0..5).map(|i| [1.0 + 0.5 * i as f64, 2.0 - 0.25 * i as f64]).collect();
        let curve = MasterCurve::detect(&line);
        assert!(curve.is_ok(), "{curve:?}");
        let Ok(curve) = curve else { return };
        assert!(matches!(curve, MasterCurve::Line { .. }));
        assert!((curve.coordinate(line[3]) - 0.75).abs() < 1e-12);
        let kinked = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [2.0, 2.0]];
        let why = MasterCurve::detect(&kinked).err().unwrap_or_default();
        assert!(why.contains("neither straight nor circular"), "{why}");
    }
}
