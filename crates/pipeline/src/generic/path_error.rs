//! The error that the load steps cause in a frictional run, estimated against the same run on a
//! path of half the step (`path_error` in the JSON, per step and per run).
//!
//! Coulomb friction is path-dependent: each step solves the increment from its start state to
//! its end load in one go, so the answer depends on the step size, to first order (the slip
//! direction and the stick/slip states are taken at the step's end for the whole step). The
//! estimate solves the whole run again with every step split in two (each pattern's factor
//! halfway along the step's straight path, [`super::adaptive::Refined::split`]; staged supports
//! and cycles follow, a stage of steps `a..b` becoming `2a..2b`) and compares the two at the user's steps. For a first-order path
//! the error of the user's steps is twice their difference from the halved path (Richardson):
//!
//! ```text
//! e_F(i) = 2 max_c ‖f_c,i − f'_c,i‖_∞ / S_c,     f = (N, T, F1, F2)
//!          S_c = max_j max(|(N', T')_c,j|, |(F1', F2')_c,j|)   (the largest force of the interface in the run)
//! e_D(i) = 2 |D_i − D'_i| / max_j |W'_j|       (the largest work of the loads in the run)
//! path_error_i = max(e_F(i), e_D(i)),   path_error = max_i path_error_i
//! ```
//! with `N`, `T` each interface's normal and tangential sums, `(F1, F2)` its resultant, `D` the dissipation and `W`
//! the work up to the step, primed on the halved path. Both are measured against the largest
//! value of their kind in the run, as an engineer reads a history: the first steps of a press
//! fit carry a hundredth of the final force, and their relative errors would flag a run whose
//! every result is right. The dissipation is measured against the energy the history carries
//! (W = U + D ≥ D), not against itself: a dissipation that tends to zero as the steps shrink (a
//! slip that is an artefact of the step) would otherwise never settle.
//!
//! A frictionless run is path-independent (elastic contact without friction is a convex
//! minimisation of the energy at each load): its estimate is 0 without a second solve, as is a
//! run solved once and scaled (proportional loads without a gap: the frictional answer is
//! self-similar).

use std::collections::BTreeMap;
use std::sync::Arc;

use super::named_map::NamedMap;
use super::results::StepResult;

/// A run's [`PathPoint`]s gathered step by step in one flat vector and made points at the end:
/// a small block kept per step among each step's freed temporaries fragments the heap (issue 44
/// item 7: ≈ 2 kB of resident memory a step on the halved path of a 2,000-step run), one
/// growing vector does not.
///
/// ```text
/// numbers = [ (Σλ, Στ, F1, F2) per interface of the first point, D, W ]  per point
/// ```
#[derive(Debug, Default)]
pub struct PathPoints {
    /// The interfaces, as the first point names them.
    names: Vec<String>,
    /// The numbers of every point, as above (NaN for an interface a row does not have).
    numbers: Vec<f64>,
}

impl PathPoints {
    /// Adds the point of a step's summary row ([`PathPoint::of`]).
    pub fn push(&mut self, row: &StepResult) {
        if self.numbers.is_empty() {
            self.names = row.contacts.keys().map(str::to_string).collect();
        }
        for name in &self.names {
            self.numbers.extend(
                row.contacts
                    .get(name)
                    .map_or([f64::NAN; 4], |c| [c.normal_force, c.tangential_force, c.resultant[0], c.resultant[1]]),
            );
        }
        self.numbers.extend([row.dissipated, row.work]);
    }

    /// The points, in the order pushed.
    pub fn into_points(self) -> Vec<PathPoint> {
        let per = 4 * self.names.len() + 2;
        let names: Vec<Arc<str>> = self.names.iter().map(|n| Arc::from(n.as_str())).collect();
        self.numbers
            .chunks_exact(per)
            .map(|p| PathPoint {
                forces: names
                    .iter()
                    .zip(p.chunks_exact(4))
                    .filter(|(_, f)| !f[0].is_nan())
                    .map(|(name, f)| (name.clone(), [f[0], f[1], f[2], f[3]]))
                    .collect(),
                dissipated: p[per - 2],
                work: p[per - 1],
            })
            .collect()
    }
}

/// The relative path error above which a run's notes advise more steps.
pub const NOTE_ABOVE: f64 = 0.01;

/// What the runs compared need of a step: per interface (normal, tangential) resultants, the
/// dissipation and the work up to the step.
#[derive(Debug, Clone, PartialEq)]
pub struct PathPoint {
    /// Per interface: `[Σ λ, Σ τ, F1, F2]`, the normal and tangential sums and the resultant.
    pub forces: NamedMap<[f64; 4]>,
    /// Dissipation up to the step.
    pub dissipated: f64,
    /// Work of the loads up to the step.
    pub work: f64,
}

impl PathPoint {
    /// The point of a step's summary row.
    pub fn of(row: &StepResult) -> PathPoint {
        PathPoint {
            forces: row.contacts.map_values(|c| [c.normal_force, c.tangential_force, c.resultant[0], c.resultant[1]]),
            dissipated: row.dissipated,
            work: row.work,
        }
    }
}

/// Each user step's path error (module docs) from the user's points and the halved path's points
/// at the same loads (`fine[i]` at the end of user step `i`); steps beyond the shorter of the two
/// (a run that stopped) get none.
pub fn step_errors(coarse: &[PathPoint], fine: &[PathPoint]) -> Vec<f64> {
    measured(coarse, fine, false)
}

/// What each step adds to the path error: the same measure (module docs) of the change of the
/// difference `d_i = f_i − f'_i` over the step, `2 ‖d_i − d_(i−1)‖ / S` (`d_(−1) = 0`). The path
/// error of a step is at most the sum of these up to it, so the steps that add the most are the
/// ones to refine (adaptive stepping), wherever their error shows.
pub fn step_contributions(coarse: &[PathPoint], fine: &[PathPoint]) -> Vec<f64> {
    measured(coarse, fine, true)
}

/// [`step_errors`] (`over_step` false) or [`step_contributions`] (true).
fn measured(coarse: &[PathPoint], fine: &[PathPoint], over_step: bool) -> Vec<f64> {
    let n = coarse.len().min(fine.len());
    let (coarse, fine) = (&coarse[..n], &fine[..n]);
    let mut largest: BTreeMap<&str, f64> = BTreeMap::new();
    for (name, [normal, tangential, f1, f2]) in fine.iter().flat_map(|f| &f.forces) {
        let scale = largest.entry(name).or_insert(0.0);
        *scale = scale.max(normal.hypot(*tangential)).max(f1.hypot(*f2));
    }
    let work = fine.iter().map(|f| f.work.abs()).fold(0.0, f64::max);
    let difference = |i: usize, name: &str| -> Option<[f64; 4]> {
        let (c, f) = (coarse[i].forces.get(name)?, fine[i].forces.get(name)?);
        Some([c[0] - f[0], c[1] - f[1], c[2] - f[2], c[3] - f[3]])
    };
    let dissipation = |i: usize| coarse[i].dissipated - fine[i].dissipated;
    (0..n)
        .map(|i| {
            let mut e: f64 = 0.0;
            for name in fine[i].forces.keys() {
                let (Some(d), Some(&scale)) = (difference(i, name), largest.get(name)) else {
                    continue;
                };
                let d0 = match over_step && i > 0 {
                    true => difference(i - 1, name).unwrap_or([0.0; 4]),
                    false => [0.0; 4],
                };
                if scale > 0.0 {
                    let change = d.iter().zip(d0).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
                    e = e.max(2.0 * change / scale);
                }
            }
            if work > 0.0 {
                let d0 = if over_step && i > 0 { dissipation(i - 1) } else { 0.0 };
                e = e.max(2.0 * (dissipation(i) - d0).abs() / work);
            }
            e
        })
        .collect()
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    fn point(n: f64, t: f64, d: f64, w: f64) -> PathPoint {
        PathPoint { forces: [("c", [n, t, 0.0, 0.0])].into_iter().collect(), dissipated: d, work: w }
    }

    /// The flat gathering gives each row's own point, bit for bit (`{:?}` tells −0.0 from 0.0),
    /// rows with and without interfaces among them.
    #[test]
    fn points_gathered_flat_are_each_rows_point() {
        let rows: Vec<StepResult> = (0..40).map(crate::generic::step_table::tests::row).collect();
        let mut flat = PathPoints::default();
        rows.iter().for_each(|r| flat.push(r));
        let points = flat.into_points();
        assert_eq!(points.len(), rows.len());
        for (row, point) in rows.iter().zip(&points) {
            assert_eq!(format!("{:?}", PathPoint::of(row)), format!("{point:?}"));
        }
    }

    #[test]
    fn identical_paths_have_no_error_and_a_difference_counts_twice() {
        let a = vec![point(10.0, 3.0, 0.1, 5.0), point(20.0, 6.0, 0.2, 10.0)];
        assert_eq!(step_errors(&a, &a), vec![0.0, 0.0]);
        // Tangential 6.2 against 6.0 on a force of |(20, 6)|: 2 · 0.2 / 20.88.
        let b = vec![point(10.0, 3.0, 0.1, 5.0), point(20.0, 6.2, 0.2, 10.0)];
        let e = step_errors(&b, &a);
        assert!((e[1] - 0.4 / 20.0f64.hypot(6.0)).abs() < 1e-15);
        // Dissipation 0.3 against 0.2 with a work of 10: 2 · 0.1 / 10.
        let c = vec![point(10.0, 3.0, 0.1, 5.0), point(20.0, 6.0, 0.3, 10.0)];
        assert!((step_errors(&c, &a)[1] - 0.02).abs() < 1e-15);
    }

    #[test]
    fn an_unloaded_interface_is_measured_against_the_largest_force_it_carried() {
        let fine = vec![point(10.0, 0.0, 0.0, 1.0), point(0.0, 0.0, 0.0, 1.0)];
        let coarse = vec![point(10.0, 0.0, 0.0, 1.0), point(0.1, 0.0, 0.0, 1.0)];
        assert!((step_errors(&coarse, &fine)[1] - 0.02).abs() < 1e-15);
    }

    #[test]
    fn a_step_contributes_the_change_of_the_difference_over_it() {
        // Differences 0.1 then 0.1 again in the normal force: the first step adds 2 · 0.1 / 20,
        // the second nothing, while both steps' path errors are 2 · 0.1 / 20.
        let fine = vec![point(10.0, 0.0, 0.0, 1.0), point(20.0, 0.0, 0.0, 1.0)];
        let coarse = vec![point(10.1, 0.0, 0.0, 1.0), point(20.1, 0.0, 0.0, 1.0)];
        let added = step_contributions(&coarse, &fine);
        assert!((added[0] - 0.01).abs() < 1e-15 && added[1].abs() < 1e-15);
        assert!(step_errors(&coarse, &fine).iter().all(|e| (e - 0.01).abs() < 1e-15));
    }
}
