//! Shards: a sweep's case list cut into N disjoint, contiguous slices in the deterministic
//! combination order, so that N jobs (a Slurm job array, one shard per array task) each run one
//! slice and their `sweep.csv` rows, concatenated in shard order, are exactly the unsharded rows.
//!
//! ```text
//! n cases, N shards:  shard i (0-based) runs cases ⌊i·n/N⌋ .. ⌊(i+1)·n/N⌋ − 1
//! 5 cases, 3 shards:  [0]  [1 2]  [3 4]        (sizes differ by at most one; a shard may be empty)
//! ```

use std::ops::Range;

use super::SweepError;

/// One of N disjoint slices of a sweep's cases (the whole sweep is shard 0 of 1).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    index: usize,
    count: usize,
}

impl Shard {
    /// The whole sweep: shard 0 of 1.
    pub const WHOLE: Shard = Shard { index: 0, count: 1 };

    /// Shard `index` (from 0) of `count`.
    ///
    /// # Errors
    /// [`SweepError::Shard`] if `count` is 0 or `index` is not below it.
    pub fn new(index: usize, count: usize) -> Result<Shard, SweepError> {
        let err = |reason: &str| SweepError::Shard { index, count, reason: reason.into() };
        if count == 0 {
            return Err(err("--shards must be at least 1"));
        }
        if index >= count {
            return Err(err("--shard counts from 0 and must be below --shards"));
        }
        Ok(Shard { index, count })
    }

    /// The shard's index (from 0).
    pub fn index(&self) -> usize {
        self.index
    }

    /// The number of shards.
    pub fn count(&self) -> usize {
        self.count
    }

    /// The indices of this shard's cases among `n` cases in combination order.
    pub fn range(&self, n: usize) -> Range<usize> {
        // u128: i·n cannot overflow for any usize n and count.
        let at = |i: usize| ((i as u128 * n as u128) / self.count as u128) as usize;
        at(self.index)..at(self.index + 1)
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::super::{Variation, csv_header, csv_row, run_sweep, run_sweep_shard};
    use super::*;
    use std::path::Path;

    #[test]
    fn shards_partition_the_cases_in_order() {
        for n in [0, 1, 5, 7, 100] {
            for count in 1..=9 {
                let covered: Vec<usize> = (0..count).flat_map(|i| Shard::new(i, count).unwrap().range(n)).collect();
                assert_eq!(covered, (0..n).collect::<Vec<_>>(), "n = {n}, count = {count}");
                let sizes: Vec<usize> = (0..count).map(|i| Shard::new(i, count).unwrap().range(n).len()).collect();
                assert!(sizes.iter().max().unwrap() - sizes.iter().min().unwrap() <= 1, "{sizes:?}");
            }
        }
        assert_eq!(Shard::WHOLE.range(4), 0..4);
        assert!(matches!(Shard::new(3, 3), Err(SweepError::Shard { index: 3, count: 3, .. })));
        let e = Shard::new(0, 0).unwrap_err().to_string();
        assert!(e.contains("--shards must be at least 1"), "{e}");
    }

    /// The claim of the Slurm recipe (docs/python.md): the shards' sweep.csv rows, concatenated
    /// in shard order under one header, are the unsharded sweep's rows, text for text; a failing
    /// case (friction −1) is a row in both.
    #[test]
    fn merged_shards_give_exactly_the_unsharded_rows() {
        let scene = Path::new("scenes/plate_insert_nogap_mu0.toml");
        let variations = [
            Variation::parse("plate_insert.friction=0,0.2,-1").unwrap(),
            Variation::parse("plate_insert.load=0.5,1").unwrap(),
        ];
        let columns: Vec<String> = ["P", "l", "b"].map(String::from).to_vec();
        let csv = |rows: &[super::super::SweepRow]| rows.iter().map(|r| csv_row(r, &columns)).collect::<String>();
        let whole =
            format!("{}{}", csv_header(&variations, &columns), csv(&run_sweep(scene, &variations, &[], |_| {})));
        assert_eq!(whole.lines().count(), 7);
        assert_eq!(whole.lines().skip(1).filter(|l| l.contains(",error,")).count(), 2, "{whole}");
        for count in [2, 4, 6] {
            let mut merged = csv_header(&variations, &columns);
            for i in 0..count {
                let shard = Shard::new(i, count).unwrap();
                merged.push_str(&csv(&run_sweep_shard(scene, &variations, &[], shard, |_| {})));
            }
            assert_eq!(merged, whole, "{count} shards");
        }
    }
}
