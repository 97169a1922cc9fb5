//! Adaptive load stepping (`[loading] adaptive = { tolerance = … }`): the user's steps split
//! where the path error ([`super::path_error`]) exceeds the tolerance, the user's steps kept as
//! the output points.
//!
//! ```text
//! P_0 = the user's steps
//! round r: solve P_r and its halved path; e_j = path error of step j of P_r,
//!          c_j = what step j adds to it (the change of the two paths' difference over the step)
//! stop when max_j e_j ≤ tol (or at MAX_ROUNDS rounds / MAX_STEPS steps: a note says so);
//! else every step with e_j > tol or c_j > tol / n (n steps in P_r) is split at the middle of
//!          its straight path → P_{r+1}
//! answer: P_r with every step halved (the finer of the two paths compared)
//! ```
//! A step is never merged across a user's step (those are the output points). Where the estimate
//! is zero nothing is split: a frictionless run is path-independent and solved at the user's steps
//! only, and proportional loads without a gap stay one solve scaled to every step.

use contact2d_contact::{ContactError, LoadSchedule, Stage};
use serde::Deserialize;

/// The `adaptive` table of `[loading]`.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AdaptiveKey {
    /// The largest path error a step may keep (relative, as `path_error`; > 0).
    pub tolerance: f64,
}

/// Rounds of splitting at most.
pub const MAX_ROUNDS: usize = 12;
/// Steps of the refined path at most.
pub const MAX_STEPS: usize = 1_024;

/// A refined path: its schedule and, per user step, the index of its last step in it.
#[derive(Debug, Clone, PartialEq)]
pub struct Refined {
    /// The steps taken.
    pub schedule: LoadSchedule,
    /// `ends[i]`: the step of `schedule` at which user step `i` ends.
    pub ends: Vec<usize>,
}

impl Refined {
    /// The user's own steps.
    pub fn of(schedule: &LoadSchedule) -> Refined {
        Refined { schedule: schedule.clone(), ends: (0..schedule.steps().len()).collect() }
    }

    /// How many steps of the path each user step takes.
    pub fn substeps(&self) -> Vec<usize> {
        self.ends.iter().enumerate().map(|(i, &e)| if i == 0 { e + 1 } else { e - self.ends[i - 1] }).collect()
    }

    /// The path with each step `j` for which `split[j]` cut in two at the middle of its straight
    /// path (the first step from zero factors).
    ///
    /// # Errors
    /// A path of more than [`contact2d_contact::loading::MAX_SCHEDULE_STEPS`] steps.
    pub fn split(&self, split: &[bool]) -> Result<Refined, ContactError> {
        let patterns = self.schedule.patterns().to_vec();
        let mut before = vec![0.0; patterns.len()];
        let (mut steps, mut index) = (vec![], vec![]);
        for (j, step) in self.schedule.steps().iter().enumerate() {
            if split.get(j).copied().unwrap_or(false) {
                steps.push(before.iter().zip(step).map(|(a, b)| 0.5 * (a + b)).collect());
            }
            steps.push(step.clone());
            index.push(steps.len() - 1);
            before.clone_from(step);
        }
        let ends = self.ends.iter().map(|&e| index[e]).collect();
        Ok(Refined { schedule: LoadSchedule::new(patterns, steps)?, ends })
    }

    /// A user step's index range `a..b` as the path's steps.
    pub fn steps_of(&self, users: &std::ops::Range<usize>) -> std::ops::Range<usize> {
        let start = if users.start == 0 { 0 } else { self.ends[users.start - 1] + 1 };
        let end = if users.end == 0 { 0 } else { self.ends[users.end - 1] + 1 };
        start..end
    }

    /// The stages of the user's steps on this path.
    pub fn stages(&self, stages: &[Stage]) -> Vec<Stage> {
        stages
            .iter()
            .map(|s| Stage { steps: self.steps_of(&s.steps), built: s.built.clone(), held: s.held.clone() })
            .collect()
    }
}

/// The user step each step of the path belongs to, and whether it ends it.
pub fn user_step_of(ends: &[usize], j: usize) -> (usize, bool) {
    let i = ends.partition_point(|&e| e < j);
    (i, ends.get(i) == Some(&j))
}

/// The next path: `None` when no step's path error exceeds `tolerance`; else split every step
/// whose error exceeds it and every step that adds more than `tolerance / n` to the error
/// (`contributions`, [`super::path_error::step_contributions`]; `n` steps). A step's error is at
/// most the sum of the contributions up to it: the second rule splits the steps where the error
/// arises, the first those where it shows (the stick/slip state of a step's end).
///
/// # Errors
/// As [`Refined::split`].
pub fn next(
    path: &Refined,
    errors: &[f64],
    contributions: &[f64],
    tolerance: f64,
) -> Result<Option<Refined>, ContactError> {
    if errors.iter().all(|e| *e <= tolerance) {
        return Ok(None);
    }
    let share = tolerance / contributions.len().max(1) as f64;
    let split: Vec<bool> = errors.iter().zip(contributions).map(|(e, c)| *e > tolerance || *c > share).collect();
    path.split(&split).map(Some)
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    fn path() -> Refined {
        Refined::of(&LoadSchedule::new(vec!["a".into()], vec![vec![1.0], vec![2.0], vec![4.0]]).unwrap())
    }

    #[test]
    fn splitting_keeps_the_user_steps_as_output_points() {
        let p = path().split(&[true, false, true]).unwrap();
        assert_eq!(p.schedule.steps(), &[vec![0.5], vec![1.0], vec![2.0], vec![3.0], vec![4.0]]);
        assert_eq!(p.ends, vec![1, 2, 4]);
        assert_eq!(p.substeps(), vec![2, 1, 2]);
        assert_eq!(p.steps_of(&(1..3)), 2..5);
        assert_eq!(user_step_of(&p.ends, 0), (0, false));
        assert_eq!(user_step_of(&p.ends, 1), (0, true));
        assert_eq!(user_step_of(&p.ends, 3), (2, false));
        assert_eq!(user_step_of(&p.ends, 4), (2, true));
    }

    #[test]
    fn nothing_is_split_below_the_tolerance() {
        assert_eq!(next(&path(), &[1e-4, 0.0, 5e-4], &[1e-4, 1e-4, 5e-4], 1e-3).unwrap(), None);
        // The error shows at the last step (split) but arises in the first (split too).
        let p = next(&path(), &[5e-4, 5e-4, 2e-3], &[1.5e-3, 0.0, 5e-4], 1e-3).unwrap().unwrap();
        assert_eq!(p.schedule.steps(), &[vec![0.5], vec![1.0], vec![2.0], vec![3.0], vec![4.0]]);
    }
}
