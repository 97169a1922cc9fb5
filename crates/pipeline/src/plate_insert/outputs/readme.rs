//! The plate-insert preset's lines of a run's `README.txt`: its own files, and its units and
//! tables' columns.

use super::csv::{HOLE_EDGE_HEADER, INSERT_EDGE_HEADER, STEP_COLUMNS};

/// What the file `name` holds when the preset has its own words for it (the same text for the
/// PNG and SVG of a figure); `None` for every scene's files.
pub fn describe(name: &str) -> Option<&'static str> {
    let stem = name.rsplit_once('.').map_or(name, |(s, _)| s);
    let text = match (stem, name.rsplit_once('.').map(|(_, e)| e)) {
        ("summary", Some("json")) => {
            "the run's summary (as `contact2d run --json`): status, steps, the interface's resultant, zones and profile, reactions, energies, KKT residuals; l, b, P, Φ, σ*, K under \"paper\""
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
        ("steps", Some("csv")) => {
            "one row per step: pattern factor, status, iterations, the interface's forces and zone lengths, then the paper's w, l, b, P, energies, work"
        }
        ("steps", Some("pvd")) => "ParaView collection of the step files (open this one; time = w)",
        _ => return None,
    };
    Some(text)
}

/// The preset's README text after the list of files: units and the columns of its tables.
pub fn notes() -> String {
    let mut t = String::from(
        "Units: non-dimensional as in the paper (spec section 7): lengths / R, displacements and the\n\
         clearance c / L0, stresses and tractions / E1 (times R/L0), energies / (E1 L0^2). η = 1 − angle/π\n\
         is 0 where the plate bears on the insert and 1 on the far side.\n\n",
    );
    t.push_str(&format!(
        "CSV columns (empty field = no value):\n  hole_edge.csv   {HOLE_EDGE_HEADER}\n  insert_edge.csv {INSERT_EDGE_HEADER}\n  steps.csv       (every scene's columns),{}\n\n",
        STEP_COLUMNS.join(",")
    ));
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
         VTU point data (the flagship's view, both edges in the paper's signs): displacement, stress\n\
         (3 × 3 tensor, nodal recovered), von_mises, contact_p, contact_q, contact_state (0 free,\n\
         1 stick, 2 slip+, 3 slip-; -1 and NaN off the contact edges); cell data: body (0 plate,\n\
         1 insert). Quad9 cells are VTK biquadratic quads (type 28).\n",
    );
    t
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::generic::readme::describe_generic;

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
            "contact_hole.csv",
            "von_mises.svg",
            "hole_edge.csv",
            "insert_edge.csv",
            "steps.csv",
            "step_000.vtu",
            "steps.pvd",
        ] {
            let what = describe(name).unwrap_or_else(|| describe_generic(name));
            assert!(!what.is_empty(), "{name}");
        }
        assert!(describe("other.txt").is_none() && describe_generic("other.txt").is_empty());
    }
}
