//! The paper's case as a preset of the generic problem description: the `[plate_insert]` keys
//! expand into bodies, fixes, the pulled edge's load pattern and one contact interface, built by
//! the library's one builder ([`ProblemDescription::build`]) like any scene; only the paper's gap
//! model is applied afterwards, pair by pair, since no scene key describes it.
//!
//! ```text
//! bodies    plate (E1 = 1), insert (E2 = stiffness_ratio; none when rigid), ν, plane, formulation
//! fixes     top, bottom_plate: u2 = 0;  right: u1 = 1 (pattern main, scaled by w), u2 = 0
//!           insert_inner: u1 = u2 = 0;  insert_symmetry: u2 = 0   (elastic insert)
//! contact   "hole": master hole_edge / slave insert_edge (variant 1) or the reverse (variant 2);
//!           node-to-node (slave nodes slid onto the paired points) or node-to-segment; the
//!           insert edge a rigid obstacle for a rigid insert; friction μ
//! gaps      geometric × c/ε, or the paper's u_ρc / u_rc ([`GapModel`])
//! ```

use std::collections::BTreeMap;
use std::path::PathBuf;

use contact2d_contact::{BuiltProblem, ContactError, InterfaceInfo, ProblemDescription, builder::DEFAULT_PATTERN};
use contact2d_element::{Formulation, PlaneCondition};
use contact2d_mesh::{Contour, Mesh};

use super::{PairDiscretisation, PairingVariant, PlateInsert, PlateInsertProblem};
use crate::generic::kinematics_key::PlaneKey;
use crate::generic::scene::{
    BodyEntry, ContactEntry, FixEntry, FormulationKey, GapKey, GenericScene, LoadingSection, PairingKey, SlidingKey,
};
use crate::schema::SolverEntry;

/// The name of the preset's one contact interface.
pub const INTERFACE: &str = "hole";

impl PlateInsert {
    /// The case as a generic scene named `name` (see the module docs): the load w of each step
    /// in `loads` is the factor of the pattern `main`, whose one value is u1 = 1 on `right`.
    pub fn generic_scene(&self, name: &str, loads: &[f64], solver: &SolverEntry) -> GenericScene {
        let body = |region: &str, youngs_modulus: f64| BodyEntry {
            region: region.into(),
            youngs_modulus,
            poissons_ratio: self.poissons_ratio,
            plane: None,
            thickness: Some(1.0),
            formulation: match self.formulation {
                Formulation::BBar => FormulationKey::Bbar,
                _ => FormulationKey::Standard,
            },
        };
        let fix = |group: &str, u1: Option<f64>, u2: Option<f64>| FixEntry {
            group: Some(group.into()),
            point: None,
            u1,
            u2,
            un: None,
            ut: None,
            rotation: None,
            about: None,
            pattern: DEFAULT_PATTERN.into(),
            from_step: None,
            until_step: None,
        };
        let mut bodies = vec![body("plate", 1.0)];
        let mut fixes =
            vec![fix("top", None, Some(0.0)), fix("bottom_plate", None, Some(0.0)), fix("right", Some(1.0), Some(0.0))];
        if !self.rigid_insert {
            bodies.push(body("insert", self.stiffness_ratio));
            fixes.extend([fix("insert_inner", Some(0.0), Some(0.0)), fix("insert_symmetry", None, Some(0.0))]);
        }
        let (master, slave) = self.curves();
        let contact = ContactEntry {
            name: INTERFACE.into(),
            master: master.into(),
            slave: slave.into(),
            rigid: self.rigid_insert,
            pairing: match self.pairs {
                PairDiscretisation::NodeToNode => PairingKey::NodeToNode,
                PairDiscretisation::NodeToSegment => PairingKey::NodeToSegment,
            },
            gap: GapKey::Named("geometric".into()),
            friction: self.friction,
            self_contact: false,
            sliding: SlidingKey::Small,
            reference_groups: None,
        };
        let schedule: crate::generic::schedule_rows::ScheduleRows =
            loads.iter().map(|w| BTreeMap::from([(DEFAULT_PATTERN.to_string(), *w)])).collect();
        GenericScene {
            name: name.into(),
            description: String::new(),
            mesh: PathBuf::from(&self.mesh),
            kinematics: None,
            plane: Some(match self.plane {
                PlaneCondition::Strain => PlaneKey::Strain,
                _ => PlaneKey::Stress,
            }),
            body: bodies,
            fix: fixes,
            load: vec![],
            point: vec![],
            contact: vec![contact],
            loading: LoadingSection {
                steps: None,
                schedule: Some(schedule),
                cycle: None,
                cycles: None,
                path_error: true,
                adaptive: None,
            },
            solver: SolverEntry { place_zone_ends: None, ..solver.clone() },
            base_dir: PathBuf::new(),
            file: PathBuf::from(&self.mesh),
            every_profile: false,
            moment_centre: [0.0; 2],
            // u / L0 against x / R (spec §7): the paper's theory is linearised, L0 ≪ R.
            linearised_displacements: true,
        }
    }

    /// The generic description of the case on `mesh`: that of [`PlateInsert::generic_scene`].
    ///
    /// # Errors
    /// None in practice (the case has no `[[point]]`); a point's error as
    /// [`ContactError::InvalidInput`].
    pub fn description(&self, mesh: Mesh) -> Result<ProblemDescription, ContactError> {
        self.generic_scene("plate_insert", &[1.0], &SolverEntry::default())
            .description(mesh)
            .map_err(|e| ContactError::InvalidInput(e.to_string()))
    }

    /// The master and slave curves (groups) of the pairing variant.
    fn curves(&self) -> (&'static str, &'static str) {
        match self.variant {
            PairingVariant::HoleMaster => ("hole_edge", "insert_edge"),
            PairingVariant::InsertMaster => ("insert_edge", "hole_edge"),
        }
    }

    /// The interface of a problem built by the paper's own code (placed nodes), as the library's
    /// builder describes it: every pair, in order along the master curve.
    pub(super) fn interface_info(
        &self,
        problem: &contact2d_contact::ContactProblem,
        hole: &Contour,
        insert: &Contour,
    ) -> InterfaceInfo {
        let (master, slave) = self.curves();
        let (master_contour, slave_contour) = match self.variant {
            PairingVariant::HoleMaster => (hole.clone(), insert.clone()),
            PairingVariant::InsertMaster => (insert.clone(), hole.clone()),
        };
        let region = |curve: &str| if curve == "hole_edge" { "plate" } else { "insert" };
        InterfaceInfo {
            name: INTERFACE.into(),
            pairs: 0..problem.num_pairs(),
            master: master.into(),
            slave: slave.into(),
            master_region: region(master).into(),
            slave_region: region(slave).into(),
            rigid_slave: self.rigid_insert,
            master_contour,
            slave_contour,
            friction: self.friction,
            pairing: match self.pairs {
                PairDiscretisation::NodeToNode => contact2d_contact::Pairing::NodeToNode,
                PairDiscretisation::NodeToSegment => contact2d_contact::Pairing::NodeToSegment,
            },
        }
    }

    /// The case built through the generic description ([`PlateInsert::description`]), the
    /// paper's gaps set on its pairs.
    ///
    /// # Errors
    /// Those of [`ProblemDescription::build`], and a clearance the mesh has no room for.
    pub fn build_preset(&self, mesh: Mesh) -> Result<PlateInsertProblem, ContactError> {
        let mut built: BuiltProblem = self.description(mesh)?.build()?;
        self.set_gaps(&mut built)?;
        self.case_of(built)
    }

    /// Sets the paper's gaps ([`GapModel`](super::GapModel), scaled by c/ε) on the pairs of the
    /// built description: what no generic scene key describes.
    ///
    /// # Errors
    /// A clearance the mesh has no room for.
    pub fn set_gaps(&self, built: &mut BuiltProblem) -> Result<(), ContactError> {
        built.problem.set_gaps(self.gaps(&built.problem)?)
    }

    /// The case of a problem built from its description: the problem and the paper's contours.
    ///
    /// # Errors
    /// A mesh without the hole or insert edge.
    pub fn case_of(&self, built: BuiltProblem) -> Result<PlateInsertProblem, ContactError> {
        let hole = Contour::from_group(&built.problem.model.mesh, "hole_edge")?;
        let insert = Contour::from_group(&built.problem.model.mesh, "insert_edge")?;
        Ok(PlateInsertProblem { built, hole, insert, variant: self.variant, eps: self.eps })
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;
    use contact2d_contact::{ContactAlgorithm, SolverSettings};

    use crate::plate_insert::GapModel;

    /// The preset built by the library's builder against the paper's own model and pairing code
    /// (`build_reusing`, which the placed zone ends still use) on variants of the case: the same
    /// pairs, gaps and friction, and the same answer. 1e-10 relative: the two paths assemble the
    /// same matrices in the same order; only round-off of sums may differ.
    #[test]
    fn the_preset_builds_the_papers_own_problem() {
        let mesh = |eps: &str| format!("{}/meshes/plate_insert/plate_insert_eps{eps}_N16.msh", crate::REPOSITORY_ROOT);
        let gap = |variant, gap_model| PlateInsert {
            eps: 0.05,
            clearance: 1.0,
            friction: 0.3,
            variant,
            gap_model,
            ..PlateInsert::paper(mesh("0.05"))
        };
        let cases = [
            PlateInsert { friction: 0.3, ..PlateInsert::paper(mesh("0")) },
            PlateInsert { rigid_insert: true, ..PlateInsert::paper(mesh("0")) },
            PlateInsert { pairs: PairDiscretisation::NodeToSegment, ..PlateInsert::paper(mesh("0")) },
            gap(PairingVariant::HoleMaster, GapModel::Paper),
            gap(PairingVariant::InsertMaster, GapModel::Paper),
            gap(PairingVariant::HoleMaster, GapModel::Geometric),
        ];
        let settings = SolverSettings::new(ContactAlgorithm::ActiveSet);
        for case in cases {
            let read = || contact2d_mesh::read_msh(&case.mesh).unwrap();
            let (preset, own) = (case.build_preset(read()).unwrap(), case.build_reusing(read(), None).unwrap());
            let (p, o) = (&preset.problem, &own.problem);
            assert_eq!(preset.interfaces[0].pairs, own.interfaces[0].pairs, "{case:?}");
            assert_eq!(p.num_pairs(), o.num_pairs(), "{case:?}");
            assert_eq!((&p.gap, &p.friction), (&o.gap, &o.friction), "{case:?}");
            let load = [0.3];
            let a = preset.solve_loads(&settings, &load, &mut |_| {}).unwrap();
            let b = own.solve_loads(&settings, &load, &mut |_| {}).unwrap();
            let (u, v) = (&a[0].solution.displacement, &b[0].solution.displacement);
            let scale = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            let diff = u.iter().zip(v).fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
            assert!(diff <= 1e-10 * scale, "{case:?}: displacements differ by {diff:e} of {scale:e}");
        }
    }
}
