//! CSV tables: the contour profiles of a step and the paper's columns of the run's step table.
//!
//! Plain comma-separated text with one header line; numbers in Rust's shortest round-trip form
//! (reading them back gives the same `f64`); an empty field where a value does not exist (a node
//! without a pair, the hoop stress of a rigid insert, a zone end that was not found).

use std::fmt::Write as _;
use std::path::Path;

use super::profiles::{ProfileRow, state_name};
use crate::output::OutputError;
use crate::run::RunOutcome;

/// Header of `hole_edge.csv`.
pub const HOLE_EDGE_HEADER: &str =
    "node,eta,phi_deg,x1,x2,s_phiphi,p,q,traction_x1,traction_x2,weight,n1,n2,gap,slip,state";
/// Header of `insert_edge.csv`.
pub const INSERT_EDGE_HEADER: &str =
    "node,eta,theta_deg,x1,x2,s_thetatheta,p,q,traction_x1,traction_x2,weight,n1,n2,gap,slip,state";
/// The paper's columns of `steps.csv` (after every scene's columns).
pub const STEP_COLUMNS: [&str; 8] = ["w", "l", "b", "P", "Phi_E1", "Phi_E2", "Phi_f", "W"];

/// Writes one contour profile (`header` is [`HOLE_EDGE_HEADER`] or [`INSERT_EDGE_HEADER`]);
/// `node_tags` maps node indices to the mesh's node tags.
///
/// # Errors
/// [`OutputError::Io`] if the file cannot be written.
pub fn write_profile_csv(path: &Path, header: &str, rows: &[ProfileRow], node_tags: &[u64]) -> Result<(), OutputError> {
    let mut text = format!("{header}\n");
    for r in rows {
        let c = r.contact;
        let tag = node_tags.get(r.node.0).copied().unwrap_or(r.node.0 as u64);
        let fields = [
            tag.to_string(),
            num(r.eta),
            num(r.angle.to_degrees()),
            num(r.x[0]),
            num(r.x[1]),
            opt(r.hoop_stress),
            opt(c.map(|c| c.pressure)),
            opt(c.map(|c| c.shear)),
            opt(c.map(|c| c.traction[0])),
            opt(c.map(|c| c.traction[1])),
            opt(c.map(|c| c.weight)),
            opt(c.map(|c| c.normal[0])),
            opt(c.map(|c| c.normal[1])),
            opt(c.map(|c| c.gap)),
            opt(c.map(|c| c.slip)),
            c.map_or(String::new(), |c| state_name(c.state).to_string()),
        ];
        let _ = writeln!(text, "{}", fields.join(","));
    }
    std::fs::write(path, text).map_err(|e| OutputError::io(path, e))
}

/// The paper's values of [`STEP_COLUMNS`] per step: load, zone ends, force, energies, work.
pub fn step_rows(outcome: &RunOutcome) -> Vec<Vec<String>> {
    outcome
        .paper
        .steps
        .iter()
        .map(|row| {
            vec![
                num(row.w),
                opt(row.l),
                opt(row.b),
                num(row.P),
                num(row.Phi_E1),
                num(row.Phi_E2),
                num(row.Phi_f),
                num(row.W),
            ]
        })
        .collect()
}

/// A number in shortest round-trip form; non-finite values as an empty field.
fn num(v: f64) -> String {
    if v.is_finite() { format!("{v:?}") } else { String::new() }
}

/// An optional number; `None` as an empty field.
fn opt(v: Option<f64>) -> String {
    v.map_or(String::new(), num)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_round_trip_and_missing_values_are_empty() {
        for v in [0.1, -1.234_567_890_123_456_7e-300, 1e300, 0.0] {
            assert_eq!(num(v).parse::<f64>().ok(), Some(v));
        }
        assert_eq!(num(f64::NAN), "");
        assert_eq!(opt(None), "");
    }

    #[test]
    fn headers_have_the_documented_columns() {
        for h in [HOLE_EDGE_HEADER, INSERT_EDGE_HEADER] {
            assert_eq!(h.split(',').count(), 16);
        }
        assert!(HOLE_EDGE_HEADER.contains("s_phiphi") && INSERT_EDGE_HEADER.contains("s_thetatheta"));
    }
}
