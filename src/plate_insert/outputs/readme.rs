//! The `README.txt` of a plate-insert run's folder: what each file written is.

use std::fmt::Write as _;

use super::csv::{HOLE_EDGE_HEADER, INSERT_EDGE_HEADER, STEPS_HEADER};
use crate::output::readme::method_line;
use crate::run::RunOutcome;
use crate::scene::Scene;

/// What the file `name` holds (one line; the same text for the PNG and SVG of a figure).
pub fn describe(name: &str) -> &'static str {
    let stem = name.rsplit_once('.').map_or(name, |(s, _)| s);
    match (stem, name.rsplit_once('.').map(|(_, e)| e)) {
        ("summary", Some("json")) => {
            "the run's summary (as `contact2d run --json`): status, steps, the interface's resultant, zones and profile, reactions, energies, KKT residuals; l, b, P, Φ, σ*, K under \"paper\""
        }
        (s, Some("csv")) if s.starts_with("contact_") && s.contains("_step_") => {
            "one interface's profile at one step (run --profiles all; columns as contact_<name>.csv of a generic run)"
        }
        ("README", _) => "this file",
        ("mesh", _) => {
            "mesh of plate and insert, undeformed and deformed (X = x + β u, β = 1/max|u_i|), element edges, contact pairs coloured stick / slip / free"
        }
        ("hole_edge", Some("csv")) => "hole-edge profile of the last step, one row per hole-edge node (columns below)",
        ("hole_edge", _) => "s_φφ, p, q along the hole edge vs η = 1 − φ/π (last step)",
        ("insert_edge", Some("csv")) => {
            "insert-edge profile of the last step, one row per insert-edge node (columns below)"
        }
        ("insert_hoop", _) => {
            "the insert's hoop stress s_θθ along its edge vs η = 1 − θ/π (last step; not for a rigid insert)"
        }
        ("history", _) => "contact end l and stick end b against the load w over the steps",
        ("von_mises", _) => "von Mises stress of both bodies (last step, undeformed geometry) with its colour bar",
        ("steps", Some("csv")) => "the step table: load w, zone ends, P, energies, work, status per step",
        ("steps", Some("pvd")) => "ParaView collection of the step files (open this one; time = w)",
        (s, Some("vtu")) if s.starts_with("step_") => "one load step for ParaView (VTK XML unstructured grid)",
        _ => "",
    }
}

/// The README text for the files `written` (names relative to the folder).
pub fn readme_text(scene: &Scene, outcome: &RunOutcome, written: &[String]) -> String {
    let mut t = String::new();
    let _ = writeln!(t, "contact2d outputs of scene \"{}\"", scene.name);
    if !scene.description.is_empty() {
        let _ = writeln!(t, "{}", scene.description);
    }
    let _ = writeln!(
        t,
        "{} load step(s), final w = {}, algorithm {:?}, status {}.\n{}\n",
        outcome.steps.len(),
        outcome.paper.w,
        outcome.report.algorithm,
        outcome.report.status,
        method_line(&outcome.report)
    );
    t.push_str(
        "Units: non-dimensional as in the paper (spec section 7): lengths / R, displacements and the\n\
         clearance c / L0, stresses and tractions / E1 (times R/L0), energies / (E1 L0^2). η = 1 − angle/π\n\
         is 0 where the plate bears on the insert and 1 on the far side.\n\nFiles:\n",
    );
    for name in written {
        let _ = writeln!(t, "  {name:<18} {}", describe(name));
    }
    let _ = write!(
        t,
        "\nCSV columns (empty field = no value):\n  hole_edge.csv   {HOLE_EDGE_HEADER}\n  insert_edge.csv {INSERT_EDGE_HEADER}\n  steps.csv       {STEPS_HEADER}\n\n"
    );
    t.push_str(
        "  node: Gmsh node tag; phi_deg / theta_deg: polar angle about the hole centre (0, 0) / the insert\n\
         centre (−ε, 0); s_phiphi, s_thetatheta: hoop stress (Gauss-point stresses extrapolated to the\n\
         nodes and averaged, the recovery of σ*); traction_x1, traction_x2: traction exerted on this\n\
         body by the other one (force per unit length of this edge); weight: the node's tributary\n\
         length ∫ N ds on this edge (force = traction × weight; summed over the hole edge it balances P\n\
         in x1); n1, n2: the pair normal, pointing from the insert into the plate; p, q: normal and\n\
         tangential traction on (n, l = (−n2, n1)) in the paper's sign: on the hole edge the plate's\n\
         stress vector (p < 0 in compression), on the insert edge the insert's (p = s_ρρ, q = s_ρθ);\n\
         gap, slip: the pair's gap and relative tangential displacement; state: free, stick, slip+, slip-.\n\
         Slave-edge nodes take the forces −N_j f of the pairs reaching them (N_j: shape weights) and the\n\
         frame, gap and state of the pair with the largest weight; empty where no pair reaches.\n\n\
         VTU point data: displacement, stress (3 × 3 tensor, nodal recovered), von_mises, contact_p,\n\
         contact_q, contact_state (0 free, 1 stick, 2 slip+, 3 slip-; -1 and NaN off the contact edges);\n\
         cell data: body (0 plate, 1 insert). Quad9 cells are VTK biquadratic quads (type 28).\n",
    );
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_documented_file_is_described() {
        for name in [
            "summary.json",
            "README.txt",
            "mesh.png",
            "mesh.svg",
            "hole_edge.png",
            "insert_hoop.svg",
            "history.png",
            "von_mises.svg",
            "hole_edge.csv",
            "insert_edge.csv",
            "steps.csv",
            "step_000.vtu",
            "steps.pvd",
        ] {
            assert!(!describe(name).is_empty(), "{name}");
        }
        assert!(describe("other.txt").is_empty());
    }
}
