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
         step {step}: free {}; fix these motions (a [[fix]] on a group of the body) or make sure a contact closes",
        modes.join(", ")
    )]
    BodyNotHeld {
        /// The body.
        body: String,
        /// The free rigid motions the contact does not take up.
        modes: Vec<String>,
        /// The load step (from 1).
        step: usize,
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
