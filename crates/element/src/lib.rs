//! Isoparametric plane-elasticity elements: local mathematics only.
//!
//! Shape functions (T3, T6, Q4, Q8, Q9 and 2-/3-node edges, in Gmsh's node order), Gauss rules,
//! the isoparametric map, the body's [`Kinematics`] (plane stress / plane strain with its thickness, or a body of
//! revolution),
//! isotropic elasticity, element stiffness,
//! consistent loads, and strains and stresses at any reference point, in the standard or the
//! locking-free B-bar [`Formulation`]. This crate knows nothing of
//! meshes: it works on one element's nodal coordinates.
//!
//! # Examples
//! ```
//! use contact2d_element::{element_stiffness, ElementType, GaussRule, Kinematics, Material, PlaneCondition};
//! let steel = Material::new(210e9, 0.3)?;
//! let plate = Kinematics::plane(PlaneCondition::Stress, 1.0)?;
//! let quad9 = ElementType::Quad9;
//! let coords: Vec<[f64; 2]> = quad9.reference_nodes().to_vec();
//! let k = element_stiffness(quad9, &coords, &steel, &plate, &GaussRule::stiffness_rule(quad9))?;
//! assert_eq!(k.nrows(), 18);
//! # Ok::<(), contact2d_element::ElementError>(())
//! ```

pub mod error;
pub mod formulation;
pub mod isoparametric;
pub mod kinematics;
pub mod loads;
pub mod material;
pub mod quadrature;
pub mod shape;
pub mod stiffness;
pub mod stress;

pub use error::ElementError;
pub use formulation::{
    DilatationProjection, Formulation, LOCKING_POISSON_THRESHOLD, VolumetricSplit, deviatoric_split, lame_parameters,
    locking_warning, locking_warning_in, pressure_space_dim, volumetric_split,
};
pub use isoparametric::{EdgePoint, MappedPoint, jacobian_determinant, map_edge_point, map_point};
pub use kinematics::Kinematics;
pub use loads::{body_force_load, edge_traction_load};
pub use material::{Material, PlaneCondition};
pub use quadrature::{GaussRule, gauss_legendre};
pub use shape::{EdgeType, ElementType, MAX_NODES, ShapeEval};
pub use stiffness::{element_area, element_stiffness, element_stiffness_with};
pub use stress::{
    gauss_to_node_extrapolation, hoop_strain_at, strain_at, strain_at_with, stress_at, stress_at_with, stress_state_at,
    von_mises,
};
