//! Errors of the contact crate.

use contact2d_fem::FemError;
use contact2d_mesh::MeshError;
use thiserror::Error;

/// Everything that can go wrong setting up a contact problem. Non-convergence of an
/// algorithm is not an error: it is a [`crate::ContactStatus`].
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum ContactError {
    /// From the finite-element layer.
    #[error(transparent)]
    Fem(#[from] FemError),
    /// From the mesh layer (unknown group, bad contour).
    #[error(transparent)]
    Mesh(#[from] MeshError),
    /// Pairing could not be built.
    #[error("pairing \"{master}\" with \"{slave}\": {reason}")]
    Pairing {
        /// Master contour.
        master: String,
        /// Slave contour.
        slave: String,
        /// What went wrong.
        reason: String,
    },
    /// The two curves of an interface bound one body, and the interface does not declare
    /// self-contact.
    #[error(
        "contact \"{contact}\": master \"{master}\" and slave \"{slave}\" both bound the body \"{body}\"; \
         a contact joins two bodies (pick a curve of the other body, or set self_contact = true for a body \
         that touches itself)"
    )]
    SameBody {
        /// The interface.
        contact: String,
        /// The body both curves bound.
        body: String,
        /// The master curve.
        master: String,
        /// The slave curve.
        slave: String,
    },
    /// A body held only by contact that the contact does not hold under the load: no pair
    /// closes against some of its rigid motions (it would fly away or spin).
    #[error(
        "body \"{body}\" is held by no Dirichlet condition and its contact does not hold it under the load at \
         step {step}: free {}; {}",
        modes.join(", "),
        not_held_advice(*largest_gap, *model_size)
    )]
    BodyNotHeld {
        /// The body.
        body: String,
        /// The free rigid motions the contact does not take up.
        modes: Vec<String>,
        /// The load step (from 1).
        step: usize,
        /// The initial gap of largest magnitude of the problem's pairs (negative: an interference).
        largest_gap: f64,
        /// The model's size (its largest coordinate extent).
        model_size: f64,
    },
    /// A solution with a non-finite number (overflow): reported as an error, never as a
    /// result whose NaN would be written as JSON `null`.
    #[error("the solution is not finite ({0}); status numerical")]
    NotFinite(String),
    /// The deadline of [`crate::SolverSettings::with_deadline`] passed before load step `step`
    /// (from 1) of `steps` could start.
    #[error("the time limit passed before load step {step} of {steps}")]
    DeadlineExceeded {
        /// The step that was not started (from 1).
        step: usize,
        /// The steps of the schedule.
        steps: usize,
    },
    /// An algorithm asked for a problem outside its assumptions, refused before solving (e.g.
    /// the Boussinesq algorithm, which grows one zone from an end of the master curve under
    /// growing proportional loads, on a body that crosses a clearance as a rigid body first).
    #[error("{algorithm} does not apply here: {reason}")]
    NotApplicable {
        /// The algorithm's scene key.
        algorithm: &'static str,
        /// Which of its assumptions the problem breaks, and what to use instead.
        reason: String,
    },
    /// Finite sliding asked for an interface it does not handle (segment-to-segment or
    /// node-to-node pairing, a given gap), refused before solving.
    #[error("finite sliding of contact \"{contact}\": {reason}")]
    FiniteSliding {
        /// The interface's name.
        contact: String,
        /// What finite sliding does not handle there, and what to use instead.
        reason: String,
    },
    /// A parameter outside its admissible range.
    #[error("invalid contact input: {0}")]
    InvalidInput(String),
}

/// What to do about a body the contact does not hold: when the initial gaps exceed the model's
/// size (a gap of ±1e6 on a block of size 4), the rigid travel across them is beyond what the
/// landing resolves — the pairs' positions after a travel `t` are rounded to about `ε t`, and
/// the landing's safety margin is relative to `t` — so the gap, not a missing fix, is at fault.
fn not_held_advice(largest_gap: f64, model_size: f64) -> String {
    if largest_gap.abs() > model_size {
        let what = if largest_gap > 0.0 { "gap" } else { "interference" };
        format!(
            "its contact's initial {what} reaches {largest_gap:.3e}, {:.1e} times the model's size {model_size:.3e}: a \
             gap or travel that large is beyond what the landing onto the contact can cross; give a gap within \
             the model's size, or fix these motions (a [[fix]] on a group of the body)",
            largest_gap.abs() / model_size
        )
    } else {
        "fix these motions (a [[fix]] on a group of the body) or make sure a contact closes".into()
    }
}
