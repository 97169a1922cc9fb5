//! A small map from names to values, ordered by name, for what every step's summary row keeps
//! per interface, load pattern, group and body (issue 44 item 7: a long history's memory).
//!
//! A `BTreeMap<String, V>` allocates a node of 11 slots however few its entries (a row's maps
//! hold one to a few), and each key its own `String`: kept for thousands of steps, that was most
//! of a run's memory. [`NamedMap`] holds its entries in one slice of exactly their number, sorted
//! by name as a `BTreeMap<String, _>` is (byte order), and its keys are [`Arc<str>`] shared with
//! the names of the run ([`super::results::StepResults`] makes each name once), so a step's key
//! costs no allocation. It serialises as the `BTreeMap` did: a JSON object, keys in that order.

use std::collections::BTreeMap;
use std::sync::Arc;

use serde::{Serialize, Serializer, ser::SerializeMap};

/// Values by name, in the names' byte order (as a `BTreeMap<String, V>`); a name appears once.
#[derive(Debug, Clone, PartialEq)]
pub struct NamedMap<V> {
    entries: Box<[(Arc<str>, V)]>,
}

impl<V> Default for NamedMap<V> {
    fn default() -> Self {
        NamedMap { entries: Box::new([]) }
    }
}

impl<V> NamedMap<V> {
    /// The value named `name`.
    pub fn get(&self, name: &str) -> Option<&V> {
        self.position(name).map(|i| &self.entries[i].1)
    }

    /// The value named `name`, to change it.
    pub fn get_mut(&mut self, name: &str) -> Option<&mut V> {
        self.position(name).map(|i| &mut self.entries[i].1)
    }

    /// Whether a value is named `name`.
    pub fn contains_key(&self, name: &str) -> bool {
        self.position(name).is_some()
    }

    /// The number of entries.
    pub fn len(&self) -> usize {
        self.entries.len()
    }

    /// Whether there is no entry.
    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    /// `(name, value)` in the names' order.
    pub fn iter(&self) -> impl ExactSizeIterator<Item = (&str, &V)> + DoubleEndedIterator {
        self.entries.iter().map(|(k, v)| (&**k, v))
    }

    /// The names in order.
    pub fn keys(&self) -> impl ExactSizeIterator<Item = &str> + DoubleEndedIterator {
        self.entries.iter().map(|(k, _)| &**k)
    }

    /// The values in the names' order.
    pub fn values(&self) -> impl ExactSizeIterator<Item = &V> + DoubleEndedIterator {
        self.entries.iter().map(|(_, v)| v)
    }

    /// The values in the names' order, to change them.
    pub fn values_mut(&mut self) -> impl ExactSizeIterator<Item = &mut V> + DoubleEndedIterator {
        self.entries.iter_mut().map(|(_, v)| v)
    }

    /// The same names (shared, not copied) with `f` of each value.
    pub fn map_values<W>(&self, f: impl Fn(&V) -> W) -> NamedMap<W> {
        NamedMap { entries: self.entries.iter().map(|(k, v)| (k.clone(), f(v))).collect() }
    }

    /// The same entries in a `BTreeMap` (the reports' top-level maps).
    pub fn to_btree(&self) -> BTreeMap<String, V>
    where
        V: Clone,
    {
        self.iter().map(|(k, v)| (k.to_string(), v.clone())).collect()
    }

    /// The shared names in order (the step table stores them once).
    pub(crate) fn shared_names(&self) -> impl ExactSizeIterator<Item = &Arc<str>> {
        self.entries.iter().map(|(k, _)| k)
    }

    /// Entries already sorted by name, each name once (as [`NamedMap::shared_names`] gave them).
    pub(crate) fn from_sorted(entries: Vec<(Arc<str>, V)>) -> Self {
        NamedMap { entries: entries.into_boxed_slice() }
    }

    fn position(&self, name: &str) -> Option<usize> {
        self.entries.binary_search_by(|(k, _)| (**k).cmp(name)).ok()
    }
}

/// The entries sorted by name; of entries with the same name the last one stays (as
/// `BTreeMap::from_iter`).
impl<K: Into<Arc<str>>, V> FromIterator<(K, V)> for NamedMap<V> {
    fn from_iter<I: IntoIterator<Item = (K, V)>>(iter: I) -> Self {
        // Sorted by name, and of equal names the later first, so that keeping the first of each
        // run of equal names keeps the last one given.
        let mut indexed: Vec<(usize, Arc<str>, V)> =
            iter.into_iter().enumerate().map(|(i, (k, v))| (i, k.into(), v)).collect();
        indexed.sort_by(|a, b| a.1.cmp(&b.1).then(b.0.cmp(&a.0)));
        let mut entries: Vec<(Arc<str>, V)> = Vec::with_capacity(indexed.len());
        for (_, k, v) in indexed {
            if entries.last().is_none_or(|(last, _)| *last != k) {
                entries.push((k, v));
            }
        }
        NamedMap { entries: entries.into_boxed_slice() }
    }
}

impl<V> std::ops::Index<&str> for NamedMap<V> {
    type Output = V;

    /// # Panics
    /// When no value is named `name` (as `BTreeMap`'s index).
    #[allow(clippy::panic)]
    fn index(&self, name: &str) -> &V {
        self.get(name).unwrap_or_else(|| panic!("no entry named {name}"))
    }
}

impl<'a, V> IntoIterator for &'a NamedMap<V> {
    type Item = (&'a str, &'a V);
    type IntoIter = std::iter::Map<std::slice::Iter<'a, (Arc<str>, V)>, fn(&'a (Arc<str>, V)) -> (&'a str, &'a V)>;

    fn into_iter(self) -> Self::IntoIter {
        self.entries.iter().map(|(k, v)| (&**k, v))
    }
}

impl<V: Serialize> Serialize for NamedMap<V> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(self.entries.len()))?;
        for (k, v) in self.entries.iter() {
            map.serialize_entry(&**k, v)?;
        }
        map.end()
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    /// The truth is `BTreeMap<String, _>`, which the rows held before: the same entries from the
    /// same input (names out of order, one repeated), the same JSON text, the same lookups.
    #[test]
    fn it_orders_looks_up_and_serialises_as_a_btreemap() {
        let input = [("upper", 1.0), ("Lower", 2.0), ("lower", 3.0), ("upper", 4.0), ("a_b", 5.0), ("ä", 6.0)];
        let map: NamedMap<f64> = input.iter().map(|(k, v)| (*k, *v)).collect();
        let truth: BTreeMap<String, f64> = input.iter().map(|(k, v)| (k.to_string(), *v)).collect();
        assert_eq!(serde_json::to_string_pretty(&map).unwrap(), serde_json::to_string_pretty(&truth).unwrap());
        assert_eq!(map.len(), truth.len());
        assert!(map.keys().eq(truth.keys().map(String::as_str)));
        assert!(map.values().eq(truth.values()));
        for (k, v) in &truth {
            assert_eq!(map.get(k), Some(v));
            assert_eq!(map[k.as_str()], *v);
        }
        assert_eq!(map.get("absent"), None);
        assert!(!map.contains_key("absent"));
        assert_eq!(map.to_btree(), truth);
        let empty: NamedMap<f64> = std::iter::empty::<(&str, f64)>().collect();
        assert!(empty.is_empty());
        assert_eq!(serde_json::to_string(&empty).unwrap(), "{}");
    }
}
