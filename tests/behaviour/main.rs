//! The tests of what the CLI, the scenes and the outputs do (errors, statuses, files, balance
//! laws, agreement between algorithms), one module per subject. One test binary, as fenris keeps
//! one per tier: the modules run in parallel in one process and link once.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

#[path = "../common/mod.rs"]
mod common;

mod against_getfem;
mod bad_inputs;
mod clarabel_agrees;
mod clarabel_warm_start;
mod cli;
mod closed_interfaces;
mod compare_reference;
mod contact_sides;
mod corner_contacts;
mod corners_and_quadratic_edges;
mod determinism;
mod engineer_outputs;
mod floating_landing;
mod fretting_outputs;
mod generic_outputs;
mod generic_scenes;
mod honest_status;
mod local_directions;
mod locking_warning;
mod memory_flat;
mod moment_balance_scenes;
mod not_held;
mod output_folders;
mod outputs;
mod pairing_closed_forms;
mod paper_case_every_algorithm;
mod points_and_couplings;
mod reaction_balance_scenes;
mod revolution_studies;
mod robustness;
mod scene_errors;
mod scene_robustness;
mod sliding_patch;
mod small_errors;
mod small_sliding;
mod status_at_rest;
mod stick_continuation;
mod stress_subset;
mod sweep;
mod sweep_capacity;
