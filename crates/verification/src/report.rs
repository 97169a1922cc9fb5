//! Markdown tables of the verification studies (strings only; the caller decides where they go).

use std::fmt::Write;

use contact2d_element::PlaneCondition;
use contact2d_mesh::CellKind;

use crate::analytic::KirschPlate;
use crate::kirsch::ScfStudy;
use crate::lame::{LameStudy, theoretical_rates};
use crate::patch::{PatchResult, PatchVariant};

/// Short element name: `T3`, `T6`, `Q4`, `Q8`, `Q9`.
pub fn kind_name(kind: CellKind) -> &'static str {
    match kind {
        CellKind::Tri3 => "T3",
        CellKind::Tri6 => "T6",
        CellKind::Quad4 => "Q4",
        CellKind::Quad8 => "Q8",
        CellKind::Quad9 => "Q9",
        _ => "?",
    }
}

/// `stress` or `strain`.
pub fn plane_name(plane: PlaneCondition) -> &'static str {
    match plane {
        PlaneCondition::Stress => "stress",
        PlaneCondition::Strain => "strain",
    }
}

fn join(values: &[f64], digits: usize) -> String {
    values.iter().map(|v| format!("{v:.digits$}")).collect::<Vec<_>>().join(", ")
}

/// The Lamé convergence table: errors on the finest mesh and the rates between successive meshes.
pub fn lame_table(studies: &[LameStudy]) -> String {
    let mut s = String::from(
        "| element | plane | nr (finest) | DOFs | L2 error | L2 rates | theory | energy error | energy rates | theory | σ_rr(a) error | σ_rr(a) rates |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for study in studies {
        let Some(f) = study.finest() else { continue };
        let (l2, en) = theoretical_rates(study.kind);
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {:.2e} | {} | {} | {:.2e} | {} | {} | {:.2e} | {} |",
            kind_name(study.kind),
            plane_name(study.plane),
            f.n_radial,
            f.dofs,
            f.norms.relative_l2(),
            join(&study.l2_rates(), 2),
            l2,
            f.norms.relative_energy(),
            join(&study.energy_rates(), 2),
            en,
            f.inner_radial_stress_error,
            join(&study.wall_stress_rates(), 2),
        );
    }
    s
}

/// The Howland comparison: SCF per mesh, the mesh change, and the references.
pub fn howland_table(studies: &[ScfStudy]) -> String {
    let mut s = String::new();
    let ns: Vec<usize> = studies.first().map(|st| st.levels.iter().map(|l| l.n).collect()).unwrap_or_default();
    s.push_str("| λ = d/D |");
    for n in &ns {
        let _ = write!(s, " SCF (n = {n}) |");
    }
    s.push_str(" mesh change | Howland (1930) | FE − Howland | Heywood (1952) |\n|---|");
    s.push_str(&"---|".repeat(ns.len() + 4));
    s.push('\n');
    for st in studies {
        let _ = write!(s, "| {:.2} |", st.plate.diameter_ratio());
        for l in &st.levels {
            let _ = write!(s, " {:.4} |", l.scf);
        }
        let (howland, diff) = match st.howland {
            Some(h) => (format!("{h:.2}"), format!("{:+.2}%", 100.0 * (st.scf() - h) / h)),
            None => ("—".into(), "—".into()),
        };
        let _ = writeln!(s, " {:.3}% | {howland} | {diff} | {:.3} |", 100.0 * st.mesh_change(), st.heywood);
    }
    s
}

/// The Kirsch limit: SCF of the square plate against 3 as the hole shrinks.
pub fn kirsch_table(studies: &[ScfStudy]) -> String {
    let mut s = String::from(
        "| a/W | DOFs (finest) | SCF | mesh change | SCF − 3 | σ_θθ(a, 0°)/σ (Kirsch: −1) | Heywood strip, λ = a/W |\n\
         |---|---|---|---|---|---|---|\n",
    );
    for st in studies {
        let Some(f) = st.levels.last() else { continue };
        let _ = writeln!(
            s,
            "| {:.2} | {} | {:.4} | {:.3}% | {:+.4} | {:.4} | {:.4} |",
            st.plate.radius / st.plate.half_width,
            f.dofs,
            f.scf,
            100.0 * st.mesh_change(),
            f.scf - KirschPlate::SCF,
            f.hoop_at_zero,
            st.heywood,
        );
    }
    s
}

/// The patch tests: largest relative displacement and stress errors.
pub fn patch_table(results: &[PatchResult]) -> String {
    let mut s = String::from(
        "| element | plane | boundary conditions | cells | interior nodes | max vertex move / h | displacement error | stress error |\n\
         |---|---|---|---|---|---|---|---|\n",
    );
    for r in results {
        let variant = match r.variant {
            PatchVariant::Dirichlet => "u prescribed on ∂Ω",
            PatchVariant::Traction => "rollers + traction",
        };
        let _ = writeln!(
            s,
            "| {} | {} | {variant} | {} | {} | {:.2} | {:.1e} | {:.1e} |",
            kind_name(r.kind),
            plane_name(r.plane),
            r.cells,
            r.interior_nodes,
            r.max_vertex_move,
            r.displacement_error,
            r.stress_error,
        );
    }
    s
}

/// The balance checks: residuals of forces and moment, and the load against its closed form.
pub fn balance_table(cases: &[crate::balance::BalanceCase]) -> String {
    let mut s = String::from(
        "| model | element | plane | (F + R)₁ / ‖F‖ | (F + R)₂ / ‖F‖ | (M_F + M_R) / (‖F‖ L) | ‖F − F_exact‖ / ‖F_exact‖ |\n\
         |---|---|---|---|---|---|---|\n",
    );
    for c in cases {
        let [r1, r2] = c.balance.relative_force_residual();
        let f = c.balance.load;
        let scale = c.expected_load[0].hypot(c.expected_load[1]);
        let load_error = (f[0] - c.expected_load[0]).hypot(f[1] - c.expected_load[1]) / scale;
        let _ = writeln!(
            s,
            "| {} | {} | {} | {:.1e} | {:.1e} | {:.1e} | {:.1e} |",
            c.model,
            kind_name(c.kind),
            plane_name(c.plane),
            r1,
            r2,
            c.balance.relative_moment_residual(c.length),
            load_error,
        );
    }
    s
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;
    use crate::patch::{PatchSetup, run_patch_test};

    #[test]
    fn tables_have_a_header_a_rule_and_one_row_per_result() {
        let r = run_patch_test(CellKind::Quad4, PlaneCondition::Stress, PatchVariant::Traction, &PatchSetup::default())
            .unwrap();
        let table = patch_table(&[r, r]);
        let lines: Vec<&str> = table.lines().collect();
        assert_eq!(lines.len(), 4);
        assert!(lines.iter().all(|l| l.starts_with('|') && l.ends_with('|')));
        let columns = |l: &str| l.matches('|').count();
        assert!(lines.iter().all(|l| columns(l) == columns(lines[0])));
        assert_eq!(join(&[1.0, 2.5], 1), "1.0, 2.5");
    }
}
