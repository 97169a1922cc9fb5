//! What the figures and VTU files of one solved step need, for any problem: the problem, the
//! solution, and a few labels. Writers take a [`StepView`], never a preset's types.

use contact2d_contact::{ContactProblem, ContactSolution, PairState};
use contact2d_mesh::Contour;

/// Contact values at one mesh node, for the VTU point data.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NodeValues {
    /// Pressure (the writer's sign convention).
    pub pressure: f64,
    /// Shear traction.
    pub shear: f64,
    /// State code: 0 free, 1 stick (or frictionless contact), 2 slip+, 3 slip−.
    pub state: i32,
}

/// One solved step as the writers see it.
#[derive(Debug, Clone)]
pub struct StepView<'a> {
    /// The discrete problem.
    pub problem: &'a ContactProblem,
    /// The step's solution (displacements in the problem's global DOF order).
    pub solution: &'a ContactSolution,
    /// Curves of rigid obstacles (regions that are no body), drawn as outlines.
    pub obstacles: Vec<&'a Contour>,
    /// Contact values per mesh node (`None` away from the interfaces).
    pub node_contact: Vec<Option<NodeValues>>,
    /// Axis labels of plane figures.
    pub axes: [String; 2],
    /// The stress quantity's label in figure titles (e.g. "σ_vM / E1", "σ_vM in MPa").
    pub stress_label: String,
}

/// The state code of a pair state (VTU and CSV): 0 free, 1 stick, 2 slip+, 3 slip−.
pub fn state_code(state: PairState) -> i32 {
    match state {
        PairState::Free => 0,
        PairState::Stick => 1,
        PairState::SlipPositive => 2,
        PairState::SlipNegative => 3,
    }
}

/// The state of a pair for people: a frictionless pair in contact is `contact`, not `stick`.
pub fn state_label(state: PairState, friction: f64) -> &'static str {
    match state {
        PairState::Free => "free",
        PairState::Stick if friction == 0.0 => "contact",
        PairState::Stick => "stick",
        PairState::SlipPositive => "slip+",
        PairState::SlipNegative => "slip-",
    }
}

/// The bounding box of points.
pub(crate) fn bounding_box<'a>(points: impl Iterator<Item = &'a [f64; 2]>) -> [[f64; 2]; 2] {
    points.fold([[f64::INFINITY; 2], [f64::NEG_INFINITY; 2]], |[lo, hi], p| {
        [[lo[0].min(p[0]), lo[1].min(p[1])], [hi[0].max(p[0]), hi[1].max(p[1])]]
    })
}
