//! Tier 3 of the tests (../shared/STYLE.md): verification against published or analytical
//! numbers, one module per case (`verify_<source>_<case>.rs`, each opening with its citation,
//! goal, sketch, parameters and tolerances). One test binary for the tier, as fenris keeps one per
//! tier: the cases run in parallel in one process and link once.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod verify_augmented_lagrangian;
mod verify_axisymmetric_contact;
mod verify_axisymmetric_lame;
mod verify_axisymmetric_shrink_fit;
mod verify_boussinesq_agrees;
mod verify_boussinesq_placed;
mod verify_cattaneo_mindlin;
mod verify_clamped_block;
mod verify_contact_patch;
mod verify_friction_incline;
mod verify_hills_nowell;
mod verify_kirsch_plate_hole;
mod verify_lame_cylinder;
mod verify_lame_incompressible;
mod verify_lame_interference_fit;
mod verify_mindlin_deresiewicz;
mod verify_moving_roller;
mod verify_nafems_hertz;
mod verify_node_placement;
mod verify_patch_test;
mod verify_path_error;
mod verify_pin_lug;
mod verify_placed_zone_ends;
mod verify_press_fit;
mod verify_press_fit_axisymmetric;
mod verify_reaction_balance;
mod verify_rigid_insert;
mod verify_slider_long_steps;
mod verify_sliding_patch;
mod verify_solodovnikov_gap_friction;
mod verify_solodovnikov_gap_frictionless;
mod verify_solodovnikov_history;
mod verify_solodovnikov_nogap_friction;
mod verify_solodovnikov_nogap_frictionless;
mod verify_staged_supports;
