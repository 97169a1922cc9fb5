//! Where an interface's zones lie along its master curve: the contact and stick zones' lengths
//! and ends, each end between the last pair inside and the next one outside, where the gap (or
//! the slip) opens like the 3/2 power of the distance: `gap^{2/3}` is interpolated linearly over
//! the next two outside pairs; on a circular curve also as angles about its centre.
//!
//! ```text
//! stick length = Σ_zones (end − start)                 (the zones' lengths, summed)
//! contact length = the span from the first zone's start to the last one's end (gaps included;
//!     on a closed curve the shortest arc holding every zone)
//! closed curve of length L (a full circle): the pair after the last is the first, at s + L;
//!     a zone that crosses the curve's start is one zone, its start s in [0, L) and its end
//!     beyond L; inside everywhere: one zone [s_0, s_0 + L], `all_round`, length L
//! angles: the first end's atan2 in (−180°, 180°], each next one unwrapped to follow the
//!     curve (within 180° of the previous end turned by ±Δs/R), so they are monotonic
//! ```

use contact2d_contact::placement::curve::circle_through as circle_through_three;
use serde::Serialize;

/// The ends of the zones of an interface, two per zone (start, end) in order along the master
/// curve: each end interpolated between the last pair inside and the next one outside as
/// `contact_length` is (see the module docs).
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct ZoneEnds {
    /// Arc length along the master curve (on a closed curve, a zone that crosses the curve's
    /// start ends beyond its length).
    pub s: Vec<f64>,
    /// The points `[x, y]` on the master curve (undeformed).
    pub points: Vec<[f64; 2]>,
    /// For a master curve that is a circular arc (every node within 1e-6 of its radius of one
    /// circle): the angles of the ends about its centre, degrees, the first in (−180, 180], the
    /// next ones unwrapped along the curve (monotonic); absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub angles_deg: Option<Vec<f64>>,
    /// On a closed curve, inside at every pair: one zone all round (the whole perimeter).
    #[serde(skip_serializing_if = "is_false")]
    pub all_round: bool,
}

fn is_false(b: &bool) -> bool {
    !*b
}

/// An interface's master curve as its zones are measured on: the pairs' arc lengths (sorted)
/// and master points in that order, and the curve's length if it closes on itself.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PairCurve<'a> {
    /// Arc length of each pair's master node, ascending.
    pub arc: &'a [f64],
    /// Each pair's master node (undeformed), in the order of `arc`.
    pub points: &'a [[f64; 2]],
    /// The curve's length L where it closes on itself (the pair after the last is the first).
    pub period: Option<f64>,
}

/// Which pairs a zone holds and how its ends are placed: `inside` marks the pairs in the zone,
/// `opening` the quantity (gap, slip) that opens like the 3/2 power beyond an end, `in_contact`
/// the pairs in contact (a stick zone ends at a free neighbour without interpolating).
#[derive(Debug, Clone, Copy)]
pub(crate) struct ZoneMarks<'a> {
    /// The pairs in the zone.
    pub inside: &'a [bool],
    /// The gap or slip beyond the ends.
    pub opening: &'a [f64],
    /// The pairs in contact.
    pub in_contact: &'a [bool],
}

/// Each zone's `[start, end]` (arc length) in order along the curve, and whether the one zone
/// goes all round a closed curve.
fn zone_spans(curve: &PairCurve<'_>, marks: &ZoneMarks<'_>) -> (Vec<[f64; 2]>, bool) {
    let (arc, inside) = (curve.arc, marks.inside);
    let n = inside.len().min(arc.len()).min(marks.opening.len()).min(marks.in_contact.len());
    let Some(period) = curve.period.filter(|_| n > 0) else {
        return (open_spans(arc, marks, 0..n), false);
    };
    let Some(j0) = inside[..n].iter().position(|v| !*v) else {
        return (vec![[arc[0], arc[0] + period]], true);
    };
    // The closed curve unrolled from two pairs before the first outside one, j0, to two after
    // it once round: every zone lies between the positions of j0 (2 and n + 2), each end with
    // the two neighbours its placement reads.
    let at = |p: usize| {
        let q = (j0 + p) as isize - 2;
        (q.rem_euclid(n as isize) as usize, q.div_euclid(n as isize) as f64 * period)
    };
    let positions: Vec<(usize, f64)> = (0..n + 4).map(at).collect();
    let ext_arc: Vec<f64> = positions.iter().map(|(k, shift)| arc[*k] + shift).collect();
    let pick = |v: &[bool]| positions.iter().map(|(k, _)| v[*k]).collect::<Vec<bool>>();
    let (ext_inside, ext_contact) = (pick(inside), pick(marks.in_contact));
    let ext_opening: Vec<f64> = positions.iter().map(|(k, _)| marks.opening[*k]).collect();
    let ext = ZoneMarks { inside: &ext_inside, opening: &ext_opening, in_contact: &ext_contact };
    let mut spans: Vec<[f64; 2]> = open_spans(&ext_arc, &ext, 2..n + 2)
        .into_iter()
        .map(|[a, b]| if a >= period { [a - period, b - period] } else { [a, b] })
        .collect();
    spans.sort_by(|a, b| a[0].total_cmp(&b[0]));
    (spans, false)
}

/// The zones of consecutive pairs where `inside` holds that start in `range` (open curve: the
/// whole curve; each end placed as in [`zone_between`]).
fn open_spans(arc: &[f64], marks: &ZoneMarks<'_>, range: std::ops::Range<usize>) -> Vec<[f64; 2]> {
    let inside = marks.inside;
    let mut spans = vec![];
    let mut k = range.start;
    while k < range.end {
        if !inside[k] {
            k += 1;
            continue;
        }
        let first = k;
        while k + 1 < inside.len() && inside[k + 1] {
            k += 1;
        }
        spans.push(zone_between(arc, inside, marks.opening, marks.in_contact, first, k));
        k += 1;
    }
    spans
}

/// The length from where the zones start to where they end, the gaps between them included: on
/// an open curve from the first zone's start to the last one's end; on a closed curve the
/// shortest arc that holds every zone (the perimeter less the widest gap between two zones),
/// the whole perimeter for a zone all round.
pub(crate) fn zones_span(curve: &PairCurve<'_>, marks: &ZoneMarks<'_>) -> f64 {
    let (spans, all_round) = zone_spans(curve, marks);
    let (Some(first), Some(last)) = (spans.first(), spans.last()) else { return 0.0 };
    let period = match curve.period {
        Some(period) if !all_round => period,
        _ => return (last[1] - first[0]).abs(),
    };
    // The widest gap, from the end of zone g to the start of the next (round the curve's start
    // after the last zone); the span runs from that next zone's start round to zone g's end.
    let n = spans.len();
    let gap = |i: usize| spans[(i + 1) % n][0] - spans[i][1] + if i + 1 == n { period } else { 0.0 };
    let g = (0..n).max_by(|a, b| gap(*a).total_cmp(&gap(*b))).unwrap_or(n - 1);
    spans[g][1] - spans[(g + 1) % n][0] + if g + 1 == n { 0.0 } else { period }
}

/// The summed length of the zones (see [`ZoneEnds`]): the whole perimeter for a zone all round
/// a closed curve.
pub(crate) fn zones_length(curve: &PairCurve<'_>, marks: &ZoneMarks<'_>) -> f64 {
    zone_spans(curve, marks).0.iter().map(|[a, b]| (b - a).abs()).sum()
}

/// The ends of every zone of consecutive pairs where `inside` holds (see [`ZoneEnds`]), each
/// end placed as in [`zone_between`].
pub(crate) fn zone_ends(curve: &PairCurve<'_>, marks: &ZoneMarks<'_>) -> ZoneEnds {
    let (spans, all_round) = zone_spans(curve, marks);
    let s: Vec<f64> = spans.iter().flatten().copied().collect();
    let points: Vec<[f64; 2]> = s.iter().map(|at| point_at(curve, *at)).collect();
    let angles_deg = circle_through(curve.points).map(|c| unwrapped_angles(curve.points, c, &s, &points));
    ZoneEnds { s, points, angles_deg, all_round }
}

/// The angles (degrees) of `points`, the zone ends at arc lengths `s` in order, about the
/// centre `c` of the circle through `curve`: the first by atan2 in (−180, 180], each next
/// turned by 360° to lie within 180° of the previous one advanced by Δs / R in the curve's
/// sense of rotation.
fn unwrapped_angles(curve: &[[f64; 2]], c: [f64; 2], s: &[f64], points: &[[f64; 2]]) -> Vec<f64> {
    let angle = |p: &[f64; 2]| (p[1] - c[1]).atan2(p[0] - c[0]).to_degrees();
    let wrap = |d: f64| d - 360.0 * (d / 360.0).round();
    // The curve's sense: +1 counter-clockwise about c, −1 clockwise.
    let turn: f64 = curve.windows(2).map(|w| wrap(angle(&w[1]) - angle(&w[0]))).sum();
    let sense = if turn < 0.0 { -1.0 } else { 1.0 };
    let radius = curve.first().map_or(1.0, |p| (p[0] - c[0]).hypot(p[1] - c[1]));
    let mut out: Vec<f64> = Vec::with_capacity(points.len());
    for (i, p) in points.iter().enumerate() {
        let a = angle(p);
        let unwrapped = match (i.checked_sub(1).and_then(|j| out.get(j)), i.checked_sub(1).and_then(|j| s.get(j))) {
            (Some(prev), Some(s_prev)) => {
                let expected = prev + sense * ((s[i] - s_prev) / radius).to_degrees();
                let turns = ((expected - a) / 360.0).round();
                if turns == 0.0 { a } else { a + 360.0 * turns }
            }
            _ => a,
        };
        out.push(unwrapped);
    }
    out
}

/// The point at arc length `at`, linear between the two nodes around it (on a closed curve
/// `at` is taken modulo its length, and the last node is followed by the first).
fn point_at(curve: &PairCurve<'_>, at: f64) -> [f64; 2] {
    let (arc, points) = (curve.arc, curve.points);
    match (curve.period, arc.first(), points.first()) {
        (Some(period), Some(a0), Some(p0)) if period > 0.0 => {
            let arc: Vec<f64> = arc.iter().copied().chain([a0 + period]).collect();
            let points: Vec<[f64; 2]> = points.iter().copied().chain([*p0]).collect();
            point_between(&arc, &points, a0 + (at - a0).rem_euclid(period))
        }
        _ => point_between(arc, points, at),
    }
}

/// The point at arc length `at` of an open chain, linear between the two nodes around it.
fn point_between(arc: &[f64], points: &[[f64; 2]], at: f64) -> [f64; 2] {
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

/// The span of an open curve's pairs where `inside` holds, from the first such pair to the last
/// (one zone: several zones' span includes the gaps between them, which [`ZoneEnds`] and the
/// results' summed lengths do not), each end moved into the neighbouring interval where the
/// quantity `opening` of the next two outside pairs opens like the 3/2 power; an end whose
/// neighbour is outside the contact (`in_contact` false while measuring a stick zone) or
/// missing stays at the last inside pair.
pub fn zone_length(arc: &[f64], inside: &[bool], opening: &[f64], in_contact: &[bool]) -> f64 {
    let (Some(first), Some(last)) = (inside.iter().position(|v| *v), inside.iter().rposition(|v| *v)) else {
        return 0.0;
    };
    let [lo, hi] = zone_between(arc, inside, opening, in_contact, first, last);
    (hi - lo).abs()
}

/// The two ends `[start, end]` (arc length) of the zone from pair `first` to pair `last`, each
/// moved into the neighbouring interval where the `opening` of the next two outside pairs opens
/// like the 3/2 power; an end whose neighbour is outside the contact (`in_contact` false while
/// measuring a stick zone) or missing stays at the last inside pair.
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

    /// A closed curve of 96 pairs on a circle of radius 20 (counter-clockwise from angle 0,
    /// arc length R θ): the pair after the last is the first.
    fn circle() -> (Vec<f64>, Vec<[f64; 2]>, f64) {
        let (n, r) = (96, 20.0);
        let step = std::f64::consts::TAU / n as f64;
        let arc: Vec<f64> = (0..n).map(|k| r * step * k as f64).collect();
        let points: Vec<[f64; 2]> =
            (0..n).map(|k| [r * (step * k as f64).cos(), r * (step * k as f64).sin()]).collect();
        (arc, points, r * std::f64::consts::TAU)
    }

    /// In contact at every pair of a closed curve: one zone all round, the whole perimeter
    /// (an open chain of the same pairs measured 124.35 of 125.66: the closing interval lost).
    #[test]
    fn a_closed_curve_in_contact_everywhere_is_in_contact_all_round() {
        let (arc, points, perimeter) = circle();
        let all = vec![true; arc.len()];
        let zero = vec![0.0; arc.len()];
        let curve = PairCurve { arc: &arc, points: &points, period: Some(perimeter) };
        let marks = ZoneMarks { inside: &all, opening: &zero, in_contact: &all };
        assert_eq!(zones_length(&curve, &marks), perimeter);
        assert_eq!(zones_span(&curve, &marks), perimeter);
        let ends = zone_ends(&curve, &marks);
        assert!(ends.all_round);
        assert_eq!(ends.s, vec![0.0, perimeter]);
        // The angles go once round, counter-clockwise: 0° to 360° (to round-off of atan2).
        let a = ends.angles_deg.unwrap();
        assert!(a[0].abs() < 1e-12 && (a[1] - 360.0).abs() < 1e-9, "{a:?}");
        let open = PairCurve { period: None, ..curve };
        assert!((zones_span(&open, &marks) - (perimeter - perimeter / 96.0)).abs() < 1e-9);
    }

    /// A zone across the curve's start (angles 141° round to 208°, i.e. −152°) is one zone:
    /// its ends are where the gap, (distance beyond the end)^{3/2}, opens (exact, as in the
    /// open case), its angles unwrapped, its start in [0, L) and its end beyond L; a second
    /// zone elsewhere adds its own length to the sum, and the span holds both.
    #[test]
    fn a_zone_across_the_start_of_a_closed_curve_is_one_zone() {
        let (arc, points, perimeter) = circle();
        let r = 20.0;
        let (start, end) = (141f64.to_radians() * r, 208f64.to_radians() * r);
        // Two zones: [141°, 208°] and [20°, 30°] (in contact where the distance to the zone is
        // 0; the gap opens like its 3/2 power beyond each end, measured round the circle).
        let zones = [(start, end), (20f64.to_radians() * r, 30f64.to_radians() * r)];
        let distance = |s: f64| {
            zones
                .iter()
                .map(|&(a, b)| {
                    let inside = |t: f64| t >= a && t <= b;
                    if inside(s) || inside(s + perimeter) {
                        0.0
                    } else {
                        [a - s, a - s - perimeter, s - b, s + perimeter - b, s - perimeter - b]
                            .into_iter()
                            .filter(|d| *d >= 0.0)
                            .fold(f64::INFINITY, f64::min)
                    }
                })
                .fold(f64::INFINITY, f64::min)
        };
        let gap: Vec<f64> = arc.iter().map(|s| distance(*s).powf(1.5)).collect();
        let inside: Vec<bool> = gap.iter().map(|g| *g == 0.0).collect();
        let curve = PairCurve { arc: &arc, points: &points, period: Some(perimeter) };
        let marks = ZoneMarks { inside: &inside, opening: &gap, in_contact: &inside };
        let ends = zone_ends(&curve, &marks);
        assert!(!ends.all_round);
        assert_eq!(ends.s.len(), 4, "{:?}", ends.s);
        // In order along the curve: [20°, 30°], then [141°, 208°] (its end beyond L).
        let expected = [zones[1].0, zones[1].1, start, end];
        for (got, want) in ends.s.iter().zip(expected) {
            assert!((got - want).abs() < 1e-9, "{:?} against {expected:?}", ends.s);
        }
        let a = ends.angles_deg.unwrap();
        // The ends lie on chords, not on the circle: their angles match to the chord's
        // deviation (h² / 8R of the 1.3 step over R = 20, well below 0.1°).
        for (got, want) in a.iter().zip([20.0, 30.0, 141.0, 208.0]) {
            assert!((got - want).abs() < 0.1, "{a:?}");
        }
        assert!(a.windows(2).all(|w| w[1] > w[0]), "{a:?}");
        let length = (zones[1].1 - zones[1].0) + (end - start);
        assert!((zones_length(&curve, &marks) - length).abs() < 1e-9);
        // The span that holds both zones: from 20° to 208°, the widest gap (208° round to 20°,
        // 172°) left out.
        let span = end - zones[1].0;
        assert!((zones_span(&curve, &marks) - span).abs() < 1e-9);
    }

    /// Stick zones: their lengths summed (4 pairs stick at two places of a 96-pair contact:
    /// the span from the first to the last, which counted the slip between them, was the
    /// defect).
    #[test]
    fn the_stick_length_is_the_sum_of_the_stick_zones() {
        let arc: Vec<f64> = (0..96).map(|k| k as f64).collect();
        let in_contact = vec![true; 96];
        let mut sticks = vec![false; 96];
        for k in [10, 11, 80, 81] {
            sticks[k] = true;
        }
        // Slip opening like (distance to the nearer stick zone)^{3/2}, the zones 9.5 .. 11.5 and
        // 79.5 .. 81.5: the interpolation of slip^{2/3} recovers each end exactly.
        let distance = |s: f64| {
            [(9.5, 11.5), (79.5, 81.5)].iter().map(|&(a, b)| (a - s).max(s - b).max(0.0)).fold(f64::INFINITY, f64::min)
        };
        let slip: Vec<f64> = arc.iter().map(|s| distance(*s).powf(1.5)).collect();
        let points: Vec<[f64; 2]> = arc.iter().map(|s| [*s, 0.0]).collect();
        let curve = PairCurve { arc: &arc, points: &points, period: None };
        let marks = ZoneMarks { inside: &sticks, opening: &slip, in_contact: &in_contact };
        let ends = zone_ends(&curve, &marks);
        assert_eq!(ends.s.len(), 4, "{:?}", ends.s);
        for (got, want) in ends.s.iter().zip([9.5, 11.5, 79.5, 81.5]) {
            assert!((got - want).abs() < 1e-12, "{:?}", ends.s);
        }
        assert!((zones_length(&curve, &marks) - 4.0).abs() < 1e-12, "{}", zones_length(&curve, &marks));
        // The span from the first to the last end (72) is the old, wrong stick length.
        assert!((zones_span(&curve, &marks) - 72.0).abs() < 1e-12);
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
