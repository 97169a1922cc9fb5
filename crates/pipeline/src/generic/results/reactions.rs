//! Each step's reactions: in total, per fixed group in the components its own fixes prescribe,
//! and their moments about the run's centre (the formulas in [`super`]'s docs).

use std::sync::Arc;

use contact2d_contact::{BuiltProblem, ContactError, ContactSolution};

use super::super::named_map::NamedMap;
use super::{FixedGroup, Names};

/// The reactions of a step in global DOF order (zero at free DOFs).
pub(super) fn reactions_at_dofs(
    built: &BuiltProblem,
    s: &ContactSolution,
    factors: &[f64],
) -> Result<Vec<f64>, ContactError> {
    let problem = &built.problem;
    let mut at_dof = vec![0.0; problem.system.dofs.num_global()];
    let r = problem.reactions(s, factors)?;
    for (j, d) in problem.system.dofs.constrained_dofs().iter().enumerate() {
        at_dof[d.0] = r[j];
    }
    // `r = T r'` at framed nodes.
    problem.system.dofs.to_global_in_place(&mut at_dof);
    Ok(at_dof)
}

/// `[R1, R2]`: the reactions (global DOF order) of every constrained DOF, each once (both
/// components of a framed node's).
pub(super) fn reactions_total(built: &BuiltProblem, at_dof: &[f64]) -> [f64; 2] {
    built.problem.system.dofs.reaction_dofs().iter().fold([0.0; 2], |mut a, d| {
        a[d.0 % 2] += at_dof[d.0];
        a
    })
}

/// The external nodal forces of a step in global DOF order: the loads of its pattern factors plus
/// the reactions.
pub(super) fn external_force(built: &BuiltProblem, reactions: &[f64], factors: &[f64]) -> Vec<f64> {
    let mut f = reactions.to_vec();
    for (pattern, factor) in built.problem.patterns().iter().zip(factors) {
        f.iter_mut().zip(&pattern.nodal).for_each(|(f, v)| *f += factor * v);
    }
    f
}

/// `[f1, f2]` summed over the reactions (global DOF order) of each group's nodes, in the
/// components the group's own fixes prescribe in step `step` (`None` in the others: a node
/// there may be held by another group, whose reaction that is; and a staged fix that does not
/// hold in the step exerts no force of its own).
pub(super) fn group_reactions(
    built: &BuiltProblem,
    at_dof: &[f64],
    (groups, names): (&[FixedGroup], &[Arc<str>]),
    step: usize,
) -> NamedMap<[Option<f64>; 2]> {
    groups
        .iter()
        .enumerate()
        .filter_map(|(i, g)| {
            let nodes = built.problem.model.mesh.group_nodes(&g.name).ok()?;
            let components = g.components_at(step);
            let sum = |c: usize| components[c].then(|| nodes.iter().map(|n| at_dof[2 * n.0 + c]).sum::<f64>());
            Some((Names::shared(names, i, &g.name), [sum(0), sum(1)]))
        })
        .collect()
}

/// `(x − c) × f` for the force `f` in component `component` (0: x1, 1: x2) at `x`.
fn moment_of(x: [f64; 2], centre: [f64; 2], component: usize, f: f64) -> f64 {
    if component == 0 { -(x[1] - centre[1]) * f } else { (x[0] - centre[0]) * f }
}

/// The moment about `centre` of the reactions (global DOF order) of every constrained DOF.
pub(super) fn reaction_moment_total(built: &BuiltProblem, at_dof: &[f64], centre: [f64; 2]) -> f64 {
    let points = &built.problem.model.mesh.points;
    built
        .problem
        .system
        .dofs
        .reaction_dofs()
        .iter()
        .map(|d| points.get(d.0 / 2).map_or(f64::NAN, |x| moment_of(*x, centre, d.0 % 2, at_dof[d.0])))
        .sum()
}

/// The moment about `centre` of each group's reactions in the components its own fixes
/// prescribe (as [`group_reactions`]).
pub(super) fn group_reaction_moments(
    built: &BuiltProblem,
    at_dof: &[f64],
    (groups, names): (&[FixedGroup], &[Arc<str>]),
    centre: [f64; 2],
    step: usize,
) -> NamedMap<f64> {
    let points = &built.problem.model.mesh.points;
    groups
        .iter()
        .enumerate()
        .filter_map(|(i, g)| {
            let nodes = built.problem.model.mesh.group_nodes(&g.name).ok()?;
            // A staged group that holds nothing in this step has no moment (as its reactions
            // are null).
            let components = g.components_at(step);
            if components == [false; 2] {
                return None;
            }
            let moment = nodes
                .iter()
                .flat_map(|n| (0..2).filter(|c| components[*c]).map(move |c| (n.0, c)))
                .map(|(n, c)| points.get(n).map_or(f64::NAN, |x| moment_of(*x, centre, c, at_dof[2 * n + c])))
                .sum();
            Some((Names::shared(names, i, &g.name), moment))
        })
        .collect()
}
