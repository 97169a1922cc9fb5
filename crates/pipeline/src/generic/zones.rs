//! Where an interface's zones lie along its master curve: the contact and stick zones' lengths
//! and ends, each end between the last pair inside and the next one outside, where the gap (or
//! the slip) opens like the 3/2 power of the distance: `gap^{2/3}` is interpolated linearly over
//! the next two outside pairs; on a circular curve also as angles about its centre.

use contact2d_contact::placement::curve::circle_through as circle_through_three;
use serde::Serialize;

/// The ends of the zones of an interface, two per zone (start, end) in order along the master
/// curve: each end interpolated between the last pair inside and the next one outside as
/// `contact_length` is (see the module docs).
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct ZoneEnds {
    /// Arc length along the master curve.
    pub s: Vec<f64>,
    /// The points `[x, y]` on the master curve (undeformed).
    pub points: Vec<[f64; 2]>,
    /// For a master curve that is a circular arc (every node within 1e-6 of its radius of one
    /// circle): the angles of the ends about its centre, degrees in (−180, 180]; absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub angles_deg: Option<Vec<f64>>,
}

/// The ends of every zone of consecutive pairs where `inside` holds (see [`ZoneEnds`]), each
/// end placed as in [`zone_length`]; `curve` holds the pairs' master nodes in the order of `arc`.
pub(crate) fn zone_ends(
    arc: &[f64],
    curve: &[[f64; 2]],
    inside: &[bool],
    opening: &[f64],
    in_contact: &[bool],
) -> ZoneEnds {
    let mut s = vec![];
    let mut k = 0;
    while k < inside.len() {
        if !inside[k] {
            k += 1;
            continue;
        }
        let first = k;
        while k + 1 < inside.len() && inside[k + 1] {
            k += 1;
        }
        s.extend(zone_between(arc, inside, opening, in_contact, first, k));
        k += 1;
    }
    let points: Vec<[f64; 2]> = s.iter().map(|at| point_at(arc, curve, *at)).collect();
    let angles_deg = circle_through(curve)
        .map(|[cx, cy]| points.iter().map(|p| (p[1] - cy).atan2(p[0] - cx).to_degrees()).collect());
    ZoneEnds { s, points, angles_deg }
}

/// The point at arc length `at`, linear between the two nodes around it.
fn point_at(arc: &[f64], points: &[[f64; 2]], at: f64) -> [f64; 2] {
    let i = arc.partition_point(|s| *s < at).clamp(1, arc.len().max(2) - 1);
    let (Some(a), Some(b)) = (points.get(i - 1), points.get(i)) else {
        return points.first().copied().unwrap_or([f64::NAN; 2]);
    };
    let t = if arc[i] > arc[i - 1] { ((at - arc[i - 1]) / (arc[i] - arc[i - 1])).clamp(0.0, 1.0) } else { 0.0 };
    [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
}

/// The centre of the circle through every point (the circumcircle of the first, middle and
/// last, every point within 1e-6 of its radius), or `None`.
fn circle_through(points: &[[f64; 2]]) -> Option<[f64; 2]> {
    let n = points.len();
    if n < 3 {
        return None;
    }
    let ([cx, cy], r) = circle_through_three(points[0], points[n / 2], points[n - 1])?;
    points.iter().all(|p| ((p[0] - cx).hypot(p[1] - cy) - r).abs() <= 1e-6 * r).then_some([cx, cy])
}

/// The length of the zone of pairs where `inside` holds (first to last such pair along `arc`),
/// each end moved into the neighbouring interval where the quantity `opening` of the next two
/// outside pairs opens like the 3/2 power; an end whose neighbour is outside the contact
/// (`in_contact` false while measuring a stick zone) or missing stays at the last inside pair.
pub fn zone_length(arc: &[f64], inside: &[bool], opening: &[f64], in_contact: &[bool]) -> f64 {
    let (Some(first), Some(last)) = (inside.iter().position(|v| *v), inside.iter().rposition(|v| *v)) else {
        return 0.0;
    };
    let [lo, hi] = zone_between(arc, inside, opening, in_contact, first, last);
    (hi - lo).abs()
}

/// The two ends `[start, end]` (arc length) of the zone from pair `first` to pair `last`, each
/// moved into the neighbouring interval where the `opening` of the next two outside pairs opens
/// like the 3/2 power (see [`zone_length`]).
fn zone_between(
    arc: &[f64],
    inside: &[bool],
    opening: &[f64],
    in_contact: &[bool],
    first: usize,
    last: usize,
) -> [f64; 2] {
    let end = |at: usize, next: Option<usize>, after: Option<usize>| -> f64 {
        let (Some(f), Some(f2)) = (next, after) else { return arc[at] };
        if inside[f] || inside[f2] || (!in_contact[f] && in_contact[at] && opening_is_slip(in_contact, inside)) {
            return arc[at];
        }
        let (d1, d2) = (opening[f].powf(2.0 / 3.0), opening[f2].powf(2.0 / 3.0));
        let e = if d2 > d1 { arc[f] - d1 * (arc[f2] - arc[f]) / (d2 - d1) } else { arc[f] };
        let (lo, hi) = if arc[at] < arc[f] { (arc[at], arc[f]) } else { (arc[f], arc[at]) };
        e.clamp(lo, hi)
    };
    let n = arc.len();
    let hi = end(last, (last + 1 < n).then_some(last + 1), (last + 2 < n).then_some(last + 2));
    let lo = end(first, first.checked_sub(1), first.checked_sub(2));
    [lo, hi]
}

/// Whether `inside` is a strict part of the contact zone (a stick zone), so that a free
/// neighbour ends it at the contact end rather than by interpolating a slip.
fn opening_is_slip(in_contact: &[bool], inside: &[bool]) -> bool {
    inside != in_contact
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    #[test]
    fn a_zone_from_the_start_ends_where_the_gap_opens_like_three_halves() {
        // Gap (s − 0.25)^{3/2} beyond the end 0.25: the interpolation over the next two free
        // pairs recovers the end exactly.
        let arc = [0.0, 0.1, 0.2, 0.3, 0.4];
        let inside = [true, true, true, false, false];
        let opening: Vec<f64> = arc.iter().map(|s: &f64| (s - 0.25f64).max(0.0).powf(1.5)).collect();
        let l = zone_length(&arc, &inside, &opening, &inside);
        assert!((l - 0.25).abs() < 1e-12, "{l}");
        assert_eq!(zone_length(&arc, &[false; 5], &opening, &[false; 5]), 0.0);
        assert_eq!(zone_length(&arc, &[true; 5], &opening, &[true; 5]), 0.4);
    }

    /// Points on a circle give its centre (exact up to round-off: the circumcentre of three of
    /// them); points on a line, or one off the circle by 1e-3 of the radius, give none.
    #[test]
    fn a_circular_curve_is_found_and_a_straight_one_is_not() {
        let on = |a: f64| [2.0 + 3.0 * a.cos(), -1.0 + 3.0 * a.sin()];
        let mut arc: Vec<[f64; 2]> = (0..7).map(|k| on(0.3 * k as f64)).collect();
        let c = circle_through(&arc).unwrap();
        assert!((c[0] - 2.0).abs() < 1e-12 && (c[1] + 1.0).abs() < 1e-12, "{c:?}");
        assert!(circle_through(&[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0], [3.0, 3.0]]).is_none());
        arc[3] = [arc[3][0] * 1.001, arc[3][1]];
        assert!(circle_through(&arc).is_none());
    }
}
