//! Lookup of the file's node and element tags.
//!
//! ```text
//!   file tags   7   3   1000000   8         (any u64, need not be contiguous)
//!   NodeId      0   1   2         3         (dense, in order of appearance)
//! ```
//!
//! Gmsh numbers nodes and elements almost contiguously, so tags below a limit proportional to
//! the number of entries are kept in a dense table (one slot per tag); larger tags go to a hash
//! map. Memory stays bounded by the entry count whatever tags a (corrupt) file holds.

use std::collections::{HashMap, HashSet};

/// Tags below `DENSE_FLOOR` always use the dense table.
const DENSE_FLOOR: u64 = 1 << 16;

/// The dense table may be this many times longer than the number of expected entries.
const DENSE_FACTOR: u64 = 4;

/// Marks an empty slot of the dense table.
const EMPTY: usize = usize::MAX;

/// The tag limit of the dense table for `expected` entries.
fn dense_limit(expected: usize) -> u64 {
    DENSE_FLOOR.max(DENSE_FACTOR.saturating_mul(expected as u64))
}

/// Map from a file tag to a dense 0-based index.
#[derive(Debug, Default)]
pub(crate) struct TagMap {
    dense: Vec<usize>,
    sparse: HashMap<u64, usize>,
    limit: u64,
}

impl TagMap {
    /// An empty map sized for about `expected` tags.
    pub(crate) fn with_expected(expected: usize) -> Self {
        TagMap { dense: Vec::new(), sparse: HashMap::new(), limit: dense_limit(expected) }
    }

    /// Raises the expected size (the dense table may then hold larger tags). Has no effect once
    /// a tag went to the hash map, so that every tag stays where it was put.
    pub(crate) fn expect(&mut self, expected: usize) {
        if self.sparse.is_empty() {
            self.limit = self.limit.max(dense_limit(expected));
        }
    }

    /// Maps `tag` to `index`; on a duplicate returns the index it already has.
    pub(crate) fn insert(&mut self, tag: u64, index: usize) -> Result<(), usize> {
        if tag < self.limit {
            let slot = usize::try_from(tag).unwrap_or(usize::MAX);
            if slot >= self.dense.len() {
                self.dense.resize(slot.saturating_add(1), EMPTY);
            }
            match self.dense.get_mut(slot) {
                Some(s) if *s == EMPTY => {
                    *s = index;
                    Ok(())
                }
                Some(s) => Err(*s),
                None => Err(EMPTY),
            }
        } else {
            match self.sparse.insert(tag, index) {
                None => Ok(()),
                Some(previous) => {
                    self.sparse.insert(tag, previous);
                    Err(previous)
                }
            }
        }
    }

    /// The index of `tag`, if mapped.
    #[inline]
    pub(crate) fn get(&self, tag: u64) -> Option<usize> {
        if tag < self.limit {
            let slot = usize::try_from(tag).ok()?;
            self.dense.get(slot).copied().filter(|&i| i != EMPTY)
        } else {
            self.sparse.get(&tag).copied()
        }
    }
}

/// A set of file tags, for finding duplicates.
#[derive(Debug, Default)]
pub(crate) struct TagSet {
    bits: Vec<u64>,
    sparse: HashSet<u64>,
    limit: u64,
}

impl TagSet {
    /// An empty set sized for about `expected` tags.
    pub(crate) fn with_expected(expected: usize) -> Self {
        TagSet { bits: Vec::new(), sparse: HashSet::new(), limit: dense_limit(expected) }
    }

    /// Adds `tag`; `false` if it was already there.
    pub(crate) fn insert(&mut self, tag: u64) -> bool {
        if tag < self.limit {
            let word = usize::try_from(tag / 64).unwrap_or(usize::MAX);
            if word >= self.bits.len() {
                self.bits.resize(word.saturating_add(1), 0);
            }
            let bit = 1u64 << (tag % 64);
            match self.bits.get_mut(word) {
                Some(w) if *w & bit == 0 => {
                    *w |= bit;
                    true
                }
                _ => false,
            }
        } else {
            self.sparse.insert(tag)
        }
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
mod tests {
    use super::*;

    #[test]
    fn map_dense_and_sparse() {
        let mut m = TagMap::with_expected(2);
        m.insert(7, 0).unwrap();
        m.insert(u64::MAX, 1).unwrap();
        m.insert(0, 2).unwrap();
        assert_eq!(m.get(7), Some(0));
        assert_eq!(m.get(u64::MAX), Some(1));
        assert_eq!(m.get(0), Some(2));
        assert_eq!(m.get(8), None);
        assert_eq!(m.get(1 << 40), None);
        assert_eq!(m.insert(7, 5), Err(0));
        assert_eq!(m.insert(u64::MAX, 5), Err(1));
        assert_eq!(m.get(u64::MAX), Some(1));
    }

    #[test]
    fn map_limit_grows_with_expectation() {
        let mut m = TagMap::with_expected(0);
        m.expect(1 << 20);
        m.insert(3 << 20, 0).unwrap();
        assert_eq!(m.get(3 << 20), Some(0));
        assert!(m.sparse.is_empty());
        m.insert(u64::MAX, 1).unwrap();
        m.expect(usize::MAX);
        assert_eq!(m.get(u64::MAX), Some(1));
    }

    #[test]
    fn set_finds_duplicates() {
        let mut s = TagSet::with_expected(1);
        assert!(s.insert(1));
        assert!(s.insert(64));
        assert!(s.insert(u64::MAX));
        assert!(!s.insert(1));
        assert!(!s.insert(64));
        assert!(s.insert(2));
    }
}
