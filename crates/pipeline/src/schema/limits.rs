//! The limits of scene values every scene shares, the generic ones and the plate-insert preset
//! alike: every loop and allocation a scene asks for is bounded, and magnitudes that f64
//! arithmetic cannot carry through the solve are refused up front, naming the key (issue 15).
//!
//! ```text
//! steps, len(l_steps)   ≤ MAX_STEPS = 1000 (the preset; a generic schedule: the contact crate's
//!                         MAX_SCHEDULE_STEPS, its rows streamed)
//! max_iterations        ≤ MAX_ITERATIONS = 10 000
//! w, c                  0 or 1e-100 ..= 1e100     (energies ∝ w², c² stay normal f64 numbers)
//! E2/E1, E_max/E_min    1e-8 ..= 1e8              (condition number ∝ the ratio)
//! μ                     ≤ 1000
//! name                  no control characters     (they corrupt SVG and CSV)
//! ```

/// The largest number of load steps a scene may ask for (`steps` or the length of `l_steps`).
///
/// Every step keeps its solution in memory and writes one VTU file: with the active set about
/// 20 bytes per mesh node and step (1 GB for 1000 steps of the N = 128 mesh); the Boussinesq
/// algorithm with placed zone ends keeps a whole problem per step (about 2 kB per node and step),
/// which [`crate::run`] bounds further by [`crate::run::MAX_HISTORY_BYTES`].
pub const MAX_STEPS: usize = 1000;

/// The largest iteration limit a scene may set: each iteration of the active set solves the
/// condensed interface system once (milliseconds on the bundled meshes), so the limit bounds a
/// step that cycles to minutes, not days.
pub const MAX_ITERATIONS: usize = 10_000;

/// The magnitudes of the load w and the clearance c that are accepted besides 0: quantities
/// scale with their square (energies ∝ w², c²), which stays within f64's normal range
/// (2.2e-308 ..= 1.8e308) only for magnitudes within 1e-100 ..= 1e100.
pub const MAGNITUDE_RANGE: (f64, f64) = (1e-100, 1e100);

/// The accepted stiffness ratios E2/E1: the assembled stiffness's condition number grows in
/// proportion to max(E2/E1, E1/E2); beyond 1e8 it passes 1e8 × the mesh's own, and the
/// softer body's stiffness drowns in the round-off (1e-16 relative) of the stiffer one.
pub const STIFFNESS_RATIO_RANGE: (f64, f64) = (1e-8, 1e8);

/// The largest friction coefficient accepted.
pub const MAX_FRICTION: f64 = 1000.0;
