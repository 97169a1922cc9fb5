//! A `[loading]` `schedule` or `cycle` as given: each step's factors by load pattern name,
//! stored as the pattern names once and every step's factors in one vector (issue 44 item 7:
//! a `Vec<BTreeMap<String, f64>>` allocated a map node and a `String` per step and name,
//! ≈ 370 bytes a step of a two-pattern schedule, for as long as the scene lives).
//!
//! ```toml
//! schedule = [{press = 0.5}, {press = 1.0, slide = 0.25}]   # names: press, slide
//! ```
//! is held as names `[press, slide]`, factors `[0.5, _, 1.0, 0.25]` and which are given
//! (`slide` is not in the first step): [`ScheduleRows::row`] gives back each step's map.

use std::collections::BTreeMap;

use serde::de::{Deserialize, Deserializer, SeqAccess, Visitor};

/// Each step's factors by pattern name; see the module docs.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ScheduleRows {
    /// Every name any step gives, sorted (as a `BTreeMap`'s keys).
    names: Vec<String>,
    /// Step by step, a factor per name (0 where the step does not give it).
    factors: Vec<f64>,
    /// Whether the step gives the name (row-major as `factors`).
    given: Vec<bool>,
    steps: usize,
}

impl ScheduleRows {
    /// The number of steps.
    pub fn len(&self) -> usize {
        self.steps
    }

    /// Whether there is no step.
    pub fn is_empty(&self) -> bool {
        self.steps == 0
    }

    /// Step `i`'s factors by name (`None` past the last step).
    pub fn row(&self, i: usize) -> Option<BTreeMap<String, f64>> {
        (i < self.steps).then(|| {
            let n = self.names.len();
            (0..n).filter(|k| self.given[i * n + k]).map(|k| (self.names[k].clone(), self.factors[i * n + k])).collect()
        })
    }

    /// Step `i`'s factor of pattern `name`, if the step gives it.
    pub fn get(&self, i: usize, name: &str) -> Option<f64> {
        let n = self.names.len();
        let k = self.names.binary_search_by(|m| m.as_str().cmp(name)).ok()?;
        (i < self.steps && self.given[i * n + k]).then(|| self.factors[i * n + k])
    }

    /// The names step `i` gives, in order.
    pub fn names_of(&self, i: usize) -> impl Iterator<Item = &str> {
        let n = self.names.len();
        self.names
            .iter()
            .enumerate()
            .filter(move |(k, _)| i < self.steps && self.given[i * n + k])
            .map(|(_, m)| m.as_str())
    }

    /// Appends a step.
    pub fn push(&mut self, step: &BTreeMap<String, f64>) {
        for name in step.keys() {
            if let Err(at) = self.names.binary_search(name) {
                self.insert_name(at, name);
            }
        }
        let n = self.names.len();
        self.factors.extend(self.names.iter().map(|m| step.get(m).copied().unwrap_or(0.0)));
        self.given.extend(self.names.iter().map(|m| step.contains_key(m)));
        debug_assert_eq!(self.factors.len(), (self.steps + 1) * n);
        self.steps += 1;
    }

    /// A name no step before gave, at position `at` of the names: a column of zeros, not given.
    fn insert_name(&mut self, at: usize, name: &str) {
        let n = self.names.len();
        let (mut factors, mut given) =
            (Vec::with_capacity(self.steps * (n + 1)), Vec::with_capacity(self.steps * (n + 1)));
        for i in 0..self.steps {
            let row = i * n..(i + 1) * n;
            factors.extend_from_slice(&self.factors[row.start..row.start + at]);
            factors.push(0.0);
            factors.extend_from_slice(&self.factors[row.start + at..row.end]);
            given.extend_from_slice(&self.given[row.start..row.start + at]);
            given.push(false);
            given.extend_from_slice(&self.given[row.start + at..row.end]);
        }
        self.names.insert(at, name.to_string());
        (self.factors, self.given) = (factors, given);
    }
}

impl FromIterator<BTreeMap<String, f64>> for ScheduleRows {
    fn from_iter<I: IntoIterator<Item = BTreeMap<String, f64>>>(iter: I) -> Self {
        let mut rows = ScheduleRows::default();
        iter.into_iter().for_each(|step| rows.push(&step));
        rows
    }
}

/// From the TOML array of tables, one step's map at a time.
impl<'de> Deserialize<'de> for ScheduleRows {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Steps;
        impl<'de> Visitor<'de> for Steps {
            type Value = ScheduleRows;

            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("an array of tables of factors by load pattern name")
            }

            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<ScheduleRows, A::Error> {
                let mut rows = ScheduleRows::default();
                while let Some(step) = seq.next_element::<BTreeMap<String, f64>>()? {
                    rows.push(&step);
                }
                Ok(rows)
            }
        }
        deserializer.deserialize_seq(Steps)
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    /// The truth is the `Vec<BTreeMap<String, f64>>` the scene held before: the same maps back,
    /// step by step, names appearing late included, and the same when read from TOML.
    #[test]
    fn each_step_reads_back_as_the_map_given() {
        let text = "s = [{press = 0.5}, {press = 1.0, slide = -0.0}, {a = 2.0}, {}, {slide = 1e-300, press = 3.0}]";
        #[derive(serde::Deserialize)]
        struct Page {
            s: Vec<BTreeMap<String, f64>>,
        }
        #[derive(serde::Deserialize)]
        struct Compact {
            s: ScheduleRows,
        }
        let truth = toml::from_str::<Page>(text).unwrap().s;
        let rows = toml::from_str::<Compact>(text).unwrap().s;
        assert_eq!(rows, truth.iter().cloned().collect::<ScheduleRows>());
        assert_eq!(rows.len(), truth.len());
        for (i, step) in truth.iter().enumerate() {
            let back = rows.row(i).unwrap();
            assert_eq!(format!("{back:?}"), format!("{step:?}"), "step {i}, bit for bit");
            assert!(rows.names_of(i).eq(step.keys().map(String::as_str)));
            for name in ["a", "press", "slide", "z"] {
                assert_eq!(rows.get(i, name), step.get(name).copied());
            }
        }
        assert_eq!(rows.row(truth.len()), None);
        assert!(toml::from_str::<Compact>("s = [{press = true}]").is_err());
    }
}
