//! The step table of a run: every step's summary row ([`StepResult`]) stored in one byte
//! buffer, the names of its maps (load patterns, interfaces, groups, bodies, points) stored once
//! (issue 44 item 7: a long history's memory flat in the number of steps).
//!
//! A [`StepResult`] in a `Vec` costs ≈ 1 kB a step in structs, maps and small vectors (the row,
//! each interface's result, the zone ends' vectors), while its numbers are ≈ 45 `f64`. Here a
//! row is its numbers one after the other (each `f64`'s 8 bytes, unchanged, so a row read back
//! is bit for bit the row stored and serialises to the same text), the counts and flags in
//! single bytes, and a 4-byte offset per row (the rows in chunks of 64 kB); what varies
//! between rows in shape (the zones' number, the options present) is written in the row, what
//! is the same (the names) in a shape shared by the rows. The rare parts (a failed check's words, a load not held, an
//! interface's profile or fretting numbers) are kept aside, boxed, for the rows that have them.
//!
//! [`StepTable::get`] rebuilds an owned row; the table serialises as the JSON array of its rows.

use std::sync::Arc;

use serde::{Serialize, Serializer, ser::SerializeSeq};

use contact2d_contact::EnergyAllowance;

use super::fretting::Fretting;
use super::named_map::NamedMap;
use super::points::PointResult;
use super::results::{ContactResult, Kkt, NotHeldResult, Profile, StepResult};
use super::zones::ZoneEnds;

/// The names of a row's maps, shared by every row of that shape.
#[derive(Debug, Clone, PartialEq, Default)]
struct Shape {
    factors: Vec<Arc<str>>,
    contacts: Vec<Arc<str>>,
    reactions: Vec<Arc<str>>,
    reaction_moments: Vec<Arc<str>>,
    energies: Vec<Arc<str>>,
    points: Vec<Arc<str>>,
}

impl Shape {
    fn of(row: &StepResult) -> Shape {
        Shape {
            factors: row.factors.shared_names().cloned().collect(),
            contacts: row.contacts.shared_names().cloned().collect(),
            reactions: row.reactions.shared_names().cloned().collect(),
            reaction_moments: row.reaction_moments.shared_names().cloned().collect(),
            energies: row.energies.shared_names().cloned().collect(),
            points: row.points.shared_names().cloned().collect(),
        }
    }
}

/// The parts of a row that are rarely present, kept aside.
#[derive(Debug, Clone, PartialEq, Default)]
struct Rare {
    failed_check: Option<String>,
    not_held: Option<Box<NotHeldResult>>,
    /// Per interface (in the row's order): its profile and fretting numbers.
    boxes: Vec<InterfaceBoxes>,
}

/// An interface's profile and fretting numbers in a row.
type InterfaceBoxes = (Option<Box<Profile>>, Option<Box<Fretting>>);

/// Every step's summary row, compactly; see the module docs.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct StepTable {
    /// The rows' bytes, in chunks of [`CHUNK`] bytes (or one row's, if longer) that are filled
    /// and never grown: no reallocation leaves a copy of the table behind in the allocator's
    /// free memory as a doubling `Vec` would.
    chunks: Vec<Vec<u8>>,
    /// The first row of each chunk.
    chunk_rows: Vec<u32>,
    /// Where each row starts in its chunk.
    starts: Vec<u32>,
    shapes: Vec<Shape>,
    statuses: Vec<&'static str>,
    /// Each row's `path_error` (set after the run, in place: [`StepTable::set_path_error`]).
    path_errors: Vec<Option<f64>>,
    /// The rows with rare parts, by row index (ascending).
    rare: Vec<(u32, Box<Rare>)>,
}

// Row flags (one byte).
const HAS_RARE: u8 = 1;
const HAS_REPAIRINGS: u8 = 2;
const HAS_SUBSTEPS: u8 = 4;

/// The bytes of a chunk of rows: below the allocator's threshold for a mapping of its own, and
/// what the table may hold unused.
const CHUNK: usize = 64 * 1024;

impl StepTable {
    /// An empty table.
    pub fn new() -> Self {
        StepTable::default()
    }

    /// The number of rows.
    pub fn len(&self) -> usize {
        self.starts.len()
    }

    /// Whether there is no row.
    pub fn is_empty(&self) -> bool {
        self.starts.is_empty()
    }

    /// Row `i` (from 0), rebuilt; `None` past the last.
    pub fn get(&self, i: usize) -> Option<StepResult> {
        (i < self.len()).then(|| self.row_at(i))
    }

    /// Row `i`, which is below [`StepTable::len`].
    fn row_at(&self, i: usize) -> StepResult {
        let c = self.chunk_rows.partition_point(|r| *r as usize <= i) - 1;
        let chunk = &self.chunks[c];
        let start = self.starts[i] as usize;
        let next_here = i + 1 < self.len() && self.chunk_rows.get(c + 1).is_none_or(|r| *r as usize > i + 1);
        let end = if next_here { self.starts[i + 1] as usize } else { chunk.len() };
        let rare = self.rare.binary_search_by_key(&(i as u32), |(k, _)| *k).ok().map(|k| &*self.rare[k].1);
        self.decode(&chunk[start..end], rare, self.path_errors[i])
    }

    /// The first row.
    pub fn first(&self) -> Option<StepResult> {
        self.get(0)
    }

    /// The last row.
    pub fn last(&self) -> Option<StepResult> {
        self.len().checked_sub(1).and_then(|i| self.get(i))
    }

    /// Every row in order, each rebuilt as it is reached.
    pub fn iter(&self) -> impl ExactSizeIterator<Item = StepResult> + DoubleEndedIterator + '_ {
        (0..self.len()).map(|i| self.row_at(i))
    }

    /// Every row, rebuilt, in a `Vec` (for the few readers that index rows many times).
    pub fn to_vec(&self) -> Vec<StepResult> {
        self.iter().collect()
    }

    /// The first row's load not held (status `not_held`), if any row has one.
    pub fn first_not_held(&self) -> Option<NotHeldResult> {
        self.rare.iter().find_map(|(_, r)| r.not_held.as_deref().cloned())
    }

    /// Appends `row`.
    ///
    /// # Panics
    /// Never in practice: more than 4 × 10⁹ rows, or a row of more than 4 GB, would overflow the
    /// row indices and offsets.
    #[allow(clippy::expect_used)]
    pub fn push(&mut self, row: StepResult) {
        let index = u32::try_from(self.len()).expect("fewer than 4e9 rows");
        let mut bytes = Vec::with_capacity(512);
        let rare = self.encode(&row, &mut bytes);
        if self.chunks.last().is_none_or(|c| c.capacity() - c.len() < bytes.len()) {
            self.chunks.push(Vec::with_capacity(CHUNK.max(bytes.len())));
            self.chunk_rows.push(index);
        }
        if let Some(chunk) = self.chunks.last_mut() {
            self.starts.push(u32::try_from(chunk.len()).expect("a row under 4 GB"));
            chunk.extend_from_slice(&bytes);
        }
        self.path_errors.push(row.path_error);
        if let Some(rare) = rare {
            self.rare.push((index, Box::new(rare)));
        }
    }

    /// Every row changed by `f(i, row)` (rows rebuilt, changed and stored again).
    pub fn update(&mut self, mut f: impl FnMut(usize, &mut StepResult)) {
        let mut table = StepTable::new();
        for (i, mut row) in self.iter().enumerate() {
            f(i, &mut row);
            table.push(row);
        }
        *self = table;
    }

    /// Sets row `i`'s `path_error` (nothing past the last row), in place.
    pub fn set_path_error(&mut self, i: usize, error: Option<f64>) {
        if let Some(slot) = self.path_errors.get_mut(i) {
            *slot = error;
        }
    }

    /// Row `i` changed by `f` (nothing past the last row): the last row is stored again in its
    /// place, another one by storing every row again.
    pub fn modify(&mut self, i: usize, f: impl FnOnce(&mut StepResult)) {
        let Some(mut row) = self.get(i) else { return };
        if i + 1 == self.len() {
            f(&mut row);
            if let Some(chunk) = self.chunks.last_mut() {
                chunk.truncate(self.starts[i] as usize);
            }
            if self.chunk_rows.last().is_some_and(|r| *r as usize == i) {
                self.chunks.pop();
                self.chunk_rows.pop();
            }
            self.starts.truncate(i);
            self.path_errors.truncate(i);
            self.rare.retain(|(k, _)| *k as usize != i);
            self.push(row);
        } else {
            let mut f = Some(f);
            self.update(|k, row| {
                if k == i
                    && let Some(f) = f.take()
                {
                    f(row);
                }
            });
        }
    }

    fn shape_index(&mut self, row: &StepResult) -> usize {
        let shape = Shape::of(row);
        if let Some(i) = self.shapes.iter().rposition(|s| *s == shape) {
            return i;
        }
        self.shapes.push(shape);
        self.shapes.len() - 1
    }

    fn status_index(&mut self, status: &'static str) -> usize {
        if let Some(i) = self.statuses.iter().position(|s| *s == status) {
            return i;
        }
        self.statuses.push(status);
        self.statuses.len() - 1
    }

    /// Writes `row` at the end of `bytes`; its rare parts if it has any.
    fn encode(&mut self, row: &StepResult, bytes: &mut Vec<u8>) -> Option<Rare> {
        let shape = self.shape_index(row);
        let status = self.status_index(row.status);
        let rare = Rare {
            failed_check: row.failed_check.clone(),
            not_held: row.not_held.clone(),
            boxes: row.contacts.values().map(|c| (c.profile.clone(), c.fretting.clone())).collect(),
        };
        let has_rare = rare.failed_check.is_some()
            || rare.not_held.is_some()
            || rare.boxes.iter().any(|(p, f)| p.is_some() || f.is_some());
        let w = &mut Writer(bytes);
        w.count(shape);
        w.count(status);
        let flags = flag(has_rare, HAS_RARE)
            | flag(row.repairings.is_some(), HAS_REPAIRINGS)
            | flag(row.substeps.is_some(), HAS_SUBSTEPS);
        w.0.push(flags);
        w.count(row.iterations);
        row.repairings.into_iter().chain(row.substeps).for_each(|n| w.count(n));
        row.factors.values().for_each(|v| w.f64(*v));
        for c in row.contacts.values() {
            let (a, b) = (c.zones.angles_deg.is_some(), c.stick_zones.angles_deg.is_some());
            w.0.push(
                flag(c.mean_pressure.is_some(), 1)
                    | flag(c.rigid_resultant.is_some(), 2)
                    | flag(c.rigid_moment.is_some(), 4)
                    | flag(c.couple.is_some(), 8)
                    | flag(c.closed, 16)
                    | flag(c.zones.all_round, 32)
                    | flag(c.stick_zones.all_round, 64),
            );
            w.0.push(flag(a, 1) | flag(b, 2));
            for v in [c.normal_force, c.tangential_force, c.contact_length, c.stick_length] {
                w.f64(v);
            }
            c.mean_pressure.into_iter().for_each(|v| w.f64(v));
            for v in [c.max_pressure, c.dissipation, c.resultant[0], c.resultant[1]] {
                w.f64(v);
            }
            c.rigid_resultant.into_iter().flatten().for_each(|v| w.f64(v));
            w.f64(c.moment);
            c.rigid_moment.into_iter().chain(c.couple).for_each(|v| w.f64(v));
            for zones in [&c.zones, &c.stick_zones] {
                w.floats(&zones.s);
                w.floats(zones.points.as_flattened());
                if let Some(angles) = &zones.angles_deg {
                    w.floats(angles);
                }
            }
        }
        for r in row.reactions.values() {
            w.0.push(flag(r[0].is_some(), 1) | flag(r[1].is_some(), 2));
            r.iter().flatten().for_each(|v| w.f64(*v));
        }
        row.reactions_total.iter().for_each(|v| w.f64(*v));
        row.reaction_moments.values().for_each(|v| w.f64(*v));
        w.f64(row.reaction_moment_total);
        row.energies.values().for_each(|v| w.f64(*v));
        for p in row.points.values() {
            w.0.push(flag(p.rotation.is_some(), 1) | flag(p.reaction_moment.is_some(), 2));
            p.displacement
                .iter()
                .chain(&p.rotation)
                .chain(&p.reaction)
                .chain(&p.reaction_moment)
                .for_each(|v| w.f64(*v));
        }
        let k = &row.kkt;
        for v in [
            row.work,
            row.dissipated,
            k.max_penetration,
            k.max_complementarity,
            k.max_cone_violation,
            k.min_dissipation,
            k.max_slip_inside_cone,
            k.floating_residual,
            row.energy_allowance.trapezoid,
            row.energy_allowance.round_off,
        ] {
            w.f64(v);
        }
        w.count(k.floating_iterations);
        has_rare.then_some(rare)
    }

    /// The row written in `bytes` by [`StepTable::encode`], with its rare parts.
    fn decode(&self, bytes: &[u8], rare: Option<&Rare>, path_error: Option<f64>) -> StepResult {
        let r = &mut Reader { bytes, at: 0 };
        let shape = &self.shapes[r.count()];
        let status = self.statuses[r.count()];
        let flags = r.byte();
        let iterations = r.count();
        let repairings = (flags & HAS_REPAIRINGS != 0).then(|| r.count());
        let substeps = (flags & HAS_SUBSTEPS != 0).then(|| r.count());
        let factors = named(&shape.factors, |_| r.f64());
        let contacts = named(&shape.contacts, |k| {
            let (flags, angles) = (r.byte(), r.byte());
            let [normal_force, tangential_force, contact_length, stick_length] = r.array();
            let mean_pressure = (flags & 1 != 0).then(|| r.f64());
            let [max_pressure, dissipation, r0, r1] = r.array();
            let rigid_resultant = (flags & 2 != 0).then(|| r.array());
            let moment = r.f64();
            let rigid_moment = (flags & 4 != 0).then(|| r.f64());
            let couple = (flags & 8 != 0).then(|| r.f64());
            let mut zones = |all_round: bool, has_angles: bool| ZoneEnds {
                s: r.floats(),
                points: r.floats().chunks_exact(2).map(|p| [p[0], p[1]]).collect(),
                angles_deg: has_angles.then(|| r.floats()),
                all_round,
            };
            let zones_of = zones(flags & 32 != 0, angles & 1 != 0);
            let stick_zones = zones(flags & 64 != 0, angles & 2 != 0);
            let (profile, fretting) = rare.and_then(|x| x.boxes.get(k).cloned()).unwrap_or_default();
            ContactResult {
                normal_force,
                tangential_force,
                contact_length,
                stick_length,
                mean_pressure,
                max_pressure,
                dissipation,
                resultant: [r0, r1],
                rigid_resultant,
                moment,
                rigid_moment,
                couple,
                closed: flags & 16 != 0,
                zones: zones_of,
                stick_zones,
                profile,
                fretting,
            }
        });
        let reactions = named(&shape.reactions, |_| {
            let present = r.byte();
            [(present & 1 != 0).then(|| r.f64()), (present & 2 != 0).then(|| r.f64())]
        });
        let reactions_total = r.array();
        let reaction_moments = named(&shape.reaction_moments, |_| r.f64());
        let reaction_moment_total = r.f64();
        let energies = named(&shape.energies, |_| r.f64());
        let points = named(&shape.points, |_| {
            let present = r.byte();
            PointResult {
                displacement: r.array(),
                rotation: (present & 1 != 0).then(|| r.f64()),
                reaction: r.array(),
                reaction_moment: (present & 2 != 0).then(|| r.f64()),
            }
        });
        let [work, dissipated, max_penetration, max_complementarity, max_cone_violation, min_dissipation] = r.array();
        let [max_slip_inside_cone, floating_residual, trapezoid, round_off] = r.array();
        let floating_iterations = r.count();
        StepResult {
            factors,
            status,
            failed_check: rare.and_then(|x| x.failed_check.clone()),
            iterations,
            repairings,
            substeps,
            contacts,
            reactions,
            reactions_total,
            reaction_moments,
            reaction_moment_total,
            energies,
            points,
            work,
            dissipated,
            kkt: Kkt {
                max_penetration,
                max_complementarity,
                max_cone_violation,
                min_dissipation,
                max_slip_inside_cone,
                floating_residual,
                floating_iterations,
            },
            energy_allowance: EnergyAllowance { trapezoid, round_off },
            not_held: rare.and_then(|x| x.not_held.clone()),
            path_error,
        }
    }
}

fn flag(on: bool, bit: u8) -> u8 {
    if on { bit } else { 0 }
}

/// A map of the shape's `names`, the value of the `k`-th name `value(k)` (read in order).
fn named<V>(names: &[Arc<str>], mut value: impl FnMut(usize) -> V) -> NamedMap<V> {
    NamedMap::from_sorted(names.iter().enumerate().map(|(k, n)| (n.clone(), value(k))).collect())
}

/// Appends numbers to a row's bytes.
struct Writer<'a>(&'a mut Vec<u8>);

impl Writer<'_> {
    fn f64(&mut self, v: f64) {
        self.0.extend_from_slice(&v.to_bits().to_le_bytes());
    }

    /// A count, 7 bits a byte (LEB128): one byte below 128.
    fn count(&mut self, mut n: usize) {
        while n >= 0x80 {
            self.0.push((n & 0x7f) as u8 | 0x80);
            n >>= 7;
        }
        self.0.push(n as u8);
    }

    fn floats(&mut self, values: &[f64]) {
        self.count(values.len());
        values.iter().for_each(|v| self.f64(*v));
    }
}

/// Reads a row's bytes back in the order [`Writer`] wrote them. The bytes are the table's own,
/// written by [`StepTable::encode`]: a read past their end is a bug of this module.
struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl Reader<'_> {
    fn byte(&mut self) -> u8 {
        let b = self.bytes[self.at];
        self.at += 1;
        b
    }

    #[allow(clippy::expect_used)]
    fn f64(&mut self) -> f64 {
        let word: [u8; 8] = self.bytes[self.at..self.at + 8].try_into().expect("8 bytes");
        self.at += 8;
        f64::from_bits(u64::from_le_bytes(word))
    }

    fn array<const N: usize>(&mut self) -> [f64; N] {
        std::array::from_fn(|_| self.f64())
    }

    fn count(&mut self) -> usize {
        let (mut n, mut shift) = (0usize, 0);
        loop {
            let b = self.byte();
            n |= usize::from(b & 0x7f) << shift;
            if b & 0x80 == 0 {
                return n;
            }
            shift += 7;
        }
    }

    fn floats(&mut self) -> Vec<f64> {
        let n = self.count();
        (0..n).map(|_| self.f64()).collect()
    }
}

impl FromIterator<StepResult> for StepTable {
    fn from_iter<I: IntoIterator<Item = StepResult>>(iter: I) -> Self {
        let mut table = StepTable::new();
        iter.into_iter().for_each(|row| table.push(row));
        table
    }
}

impl From<Vec<StepResult>> for StepTable {
    fn from(rows: Vec<StepResult>) -> Self {
        rows.into_iter().collect()
    }
}

impl Extend<StepResult> for StepTable {
    fn extend<I: IntoIterator<Item = StepResult>>(&mut self, iter: I) {
        iter.into_iter().for_each(|row| self.push(row));
    }
}

/// The JSON array of the rows, each rebuilt as it is written (no copy of the whole table).
impl Serialize for StepTable {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut seq = serializer.serialize_seq(Some(self.len()))?;
        for row in self.iter() {
            seq.serialize_element(&row)?;
        }
        seq.end()
    }
}

#[cfg(test)]
#[path = "step_table_tests.rs"]
pub(super) mod tests;
