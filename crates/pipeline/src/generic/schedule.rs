//! The load schedule of a generic scene: the preload (`[loading] steps` or `schedule`), then
//! the load cycle (`cycle`) repeated `cycles` times.
//!
//! ```text
//! steps = preload ++ cycle ++ cycle ++ … (cycles times),   at most MAX_SCHEDULE_STEPS in all
//! ```

use contact2d_contact::LoadSchedule;
use contact2d_contact::loading::MAX_SCHEDULE_STEPS;

use super::scene::GenericScene;
use super::schedule_rows::ScheduleRows;
use crate::schema::SceneError;

impl GenericScene {
    /// The load schedule: the preload (`steps = N` ramps every pattern; a `schedule` lists each
    /// step's factors; neither: one step with every pattern at 1, or none before a `cycle`),
    /// then `cycle` repeated `cycles` times.
    ///
    /// ```text
    /// steps = preload ++ cycle ++ cycle ++ … (cycles times)
    /// ```
    ///
    /// # Errors
    /// Both `steps` and `schedule`; a step naming an unknown pattern; `cycles` without a
    /// `cycle`, `cycles = 0`, an empty `cycle`, more than 10 000 steps in all; a schedule the
    /// library refuses.
    pub fn schedule(&self) -> Result<LoadSchedule, SceneError> {
        let names = self.pattern_names();
        let loading = &self.loading;
        let preload: Vec<Vec<f64>> = match (&loading.steps, &loading.schedule, &loading.cycle) {
            (Some(_), Some(_), _) => return Err(self.fail("loading", "give steps or schedule, not both".into())),
            (Some(n), None, _) => LoadSchedule::ramp(names.clone(), *n)
                .map_err(|e| self.fail("loading.steps", e.to_string()))?
                .steps()
                .to_vec(),
            (None, Some(schedule), _) => self.factor_rows("loading.schedule", schedule, &names)?,
            (None, None, None) => {
                return LoadSchedule::ramp(names, 1).map_err(|e| self.fail("loading", e.to_string()));
            }
            (None, None, Some(_)) => vec![],
        };
        let mut steps = preload;
        match (&loading.cycle, loading.cycles) {
            (None, Some(_)) => {
                return Err(self.fail("loading.cycles", "no loading.cycle to repeat: give the cycle's factors".into()));
            }
            (None, None) => {}
            (Some(cycle), cycles) => {
                let cycles = cycles.unwrap_or(1);
                if cycles == 0 {
                    return Err(self.fail("loading.cycles", "0 cycles: give at least 1".into()));
                }
                if cycle.is_empty() {
                    return Err(self.fail("loading.cycle", "an empty cycle: give the factors of its steps".into()));
                }
                let total = cycle.len().checked_mul(cycles).and_then(|n| n.checked_add(steps.len()));
                if total.is_none_or(|n| n > MAX_SCHEDULE_STEPS) {
                    return Err(self.fail(
                        "loading.cycles",
                        format!(
                            "{cycles} cycles of {} steps after {} steps exceed {MAX_SCHEDULE_STEPS} steps",
                            cycle.len(),
                            steps.len()
                        ),
                    ));
                }
                let rows = self.factor_rows("loading.cycle", cycle, &names)?;
                for _ in 0..cycles {
                    steps.extend(rows.iter().cloned());
                }
            }
        }
        let key = if loading.cycle.is_some() { "loading.cycle" } else { "loading.schedule" };
        LoadSchedule::new(names, steps).map_err(|e| self.fail(key, e.to_string()))
    }

    /// The steps of the last load cycle (indices from 0 into the schedule's steps) and the
    /// number of steps per cycle; `None` without a `cycle`.
    pub fn last_cycle(&self) -> Option<std::ops::Range<usize>> {
        let cycle = self.loading.cycle.as_ref()?;
        let total = self.schedule().ok()?.steps().len();
        Some(total.saturating_sub(cycle.len())..total)
    }

    /// Each step's factors in the order of `names`, after checking that every step names
    /// patterns of the scene (`key`: where the steps are, for the error).
    fn factor_rows(&self, key: &str, rows: &ScheduleRows, names: &[String]) -> Result<Vec<Vec<f64>>, SceneError> {
        // A pattern only zero-valued fixes name scales nothing: a step may name it.
        let inert = self.inert_patterns();
        for i in 0..rows.len() {
            if let Some(unknown) =
                rows.names_of(i).find(|k| !names.iter().any(|n| n == k) && !inert.iter().any(|n| n == k))
            {
                return Err(self.fail(
                    &format!("{key}[{i}]"),
                    format!("\"{unknown}\" is no load pattern of this scene (patterns: {})", names.join(", ")),
                ));
            }
        }
        Ok((0..rows.len()).map(|i| names.iter().map(|n| rows.get(i, n).unwrap_or(0.0)).collect()).collect())
    }
}
