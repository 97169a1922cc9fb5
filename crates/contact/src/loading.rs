//! Load schedules: named load patterns and the factor of each pattern at the end of each step.
//!
//! ```text
//! load at step i = Σ_p F[i][p] · pattern_p        (pattern_p: its loads and prescribed values)
//! ```
//!
//! "Press with a force, then slide while holding the force" is two patterns, `press` and
//! `slide`, over steps `[{press: 1}, {press: 1, slide: 0.5}, {press: 1, slide: 1}]`.

use crate::error::ContactError;

/// The largest number of steps a schedule may have: every step keeps a full solution, so the
/// bound keeps memory finite and known before the run.
pub const MAX_SCHEDULE_STEPS: usize = 10_000;

/// The factors of named load patterns at the end of each step.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadSchedule {
    patterns: Vec<String>,
    steps: Vec<Vec<f64>>,
}

impl LoadSchedule {
    /// A schedule over `patterns` with the factors of each step (`steps[i][p]` for
    /// `patterns[p]`).
    ///
    /// # Errors
    /// No step, more than [`MAX_SCHEDULE_STEPS`], a repeated pattern name, a step with the wrong
    /// number of factors, or a non-finite factor.
    pub fn new(patterns: Vec<String>, steps: Vec<Vec<f64>>) -> Result<LoadSchedule, ContactError> {
        let fail = |reason: String| Err(ContactError::InvalidInput(format!("load schedule: {reason}")));
        if steps.is_empty() {
            return fail("no step".into());
        }
        if steps.len() > MAX_SCHEDULE_STEPS {
            return fail(format!("{} steps; at most {MAX_SCHEDULE_STEPS}", steps.len()));
        }
        for (i, p) in patterns.iter().enumerate() {
            if patterns[..i].contains(p) {
                return fail(format!("pattern \"{p}\" named twice"));
            }
        }
        for (i, s) in steps.iter().enumerate() {
            if s.len() != patterns.len() {
                return fail(format!("step {} has {} factors for {} patterns", i + 1, s.len(), patterns.len()));
            }
            if let Some(f) = s.iter().find(|f| !f.is_finite()) {
                return fail(format!("step {}: factor {f} is not finite", i + 1));
            }
        }
        Ok(LoadSchedule { patterns, steps })
    }

    /// Every pattern from 0 to 1 in `steps` equal steps.
    ///
    /// # Errors
    /// As [`LoadSchedule::new`] (e.g. `steps = 0`).
    pub fn ramp(patterns: Vec<String>, steps: usize) -> Result<LoadSchedule, ContactError> {
        let n = patterns.len();
        let factors = (1..=steps).map(|i| vec![i as f64 / steps as f64; n]).collect();
        LoadSchedule::new(patterns, factors)
    }

    /// The pattern names.
    pub fn patterns(&self) -> &[String] {
        &self.patterns
    }

    /// The factors of each step, in the order of [`LoadSchedule::patterns`].
    pub fn steps(&self) -> &[Vec<f64>] {
        &self.steps
    }

    /// The factors of step `i` reordered to `names` (patterns the schedule does not name get 0).
    ///
    /// # Errors
    /// A schedule pattern that is not in `names`.
    pub fn factors_for(&self, i: usize, names: &[&str]) -> Result<Vec<f64>, ContactError> {
        let mut out = vec![0.0; names.len()];
        for (p, f) in self.patterns.iter().zip(&self.steps[i]) {
            let at = names.iter().position(|n| n == p).ok_or_else(|| {
                ContactError::InvalidInput(format!(
                    "load schedule names pattern \"{p}\", which no load or prescribed value belongs to \
                     (patterns: {})",
                    names.join(", ")
                ))
            })?;
            out[at] = *f;
        }
        Ok(out)
    }

    /// If every step is a multiple `t_i d` of one direction `d` with `0 < t_1 < t_2 < ...`
    /// (proportional loading that only grows), the direction (with `t` = 1 at the last step)
    /// and the multipliers.
    pub fn proportional(&self) -> Option<(Vec<f64>, Vec<f64>)> {
        let last = self.steps.last()?;
        let norm = last.iter().fold(0.0f64, |a, f| a.max(f.abs()));
        if norm == 0.0 {
            return None;
        }
        let mut multipliers = Vec::with_capacity(self.steps.len());
        for s in &self.steps {
            // The multiplier from the largest component of the direction, then an exact check.
            let k = (0..last.len()).max_by(|a, b| last[*a].abs().total_cmp(&last[*b].abs()))?;
            let t = s[k] / last[k];
            let tolerance = 1e-12 * norm;
            if s.iter().zip(last).any(|(f, d)| (f - t * d).abs() > tolerance) {
                return None;
            }
            multipliers.push(t);
        }
        let increasing = multipliers.first().is_some_and(|t| *t > 0.0) && multipliers.windows(2).all(|w| w[1] > w[0]);
        increasing.then(|| (last.clone(), multipliers))
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    #[test]
    fn ramp_is_proportional_and_press_slide_is_not() {
        let ramp = LoadSchedule::ramp(vec!["main".into()], 4).unwrap();
        let (d, t) = ramp.proportional().unwrap();
        assert_eq!(d, vec![1.0]);
        assert_eq!(t, vec![0.25, 0.5, 0.75, 1.0]);
        let slide = LoadSchedule::new(
            vec!["press".into(), "slide".into()],
            vec![vec![1.0, 0.0], vec![1.0, 0.5], vec![1.0, 1.0]],
        )
        .unwrap();
        assert!(slide.proportional().is_none());
        assert_eq!(slide.factors_for(1, &["slide", "press", "other"]).unwrap(), vec![0.5, 1.0, 0.0]);
        assert!(slide.factors_for(1, &["press"]).is_err());
    }

    #[test]
    fn bad_schedules_are_errors() {
        assert!(LoadSchedule::new(vec!["a".into()], vec![]).is_err());
        assert!(LoadSchedule::new(vec!["a".into(), "a".into()], vec![vec![1.0, 1.0]]).is_err());
        assert!(LoadSchedule::new(vec!["a".into()], vec![vec![f64::NAN]]).is_err());
        assert!(LoadSchedule::new(vec!["a".into()], vec![vec![1.0, 2.0]]).is_err());
        assert!(LoadSchedule::ramp(vec!["a".into()], 0).is_err());
        // Unloading is not "proportional and growing".
        let down = LoadSchedule::new(vec!["a".into()], vec![vec![1.0], vec![0.5]]).unwrap();
        assert!(down.proportional().is_none());
    }
}
