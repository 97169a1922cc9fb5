//! The `README.txt` of a generic run's folder: what each file written is, and the method line
//! every run's summary and README carry.

use std::fmt::Write as _;

use contact2d_contact::ContactAlgorithm;

use crate::generic::GenericReport;
use crate::output::PresetFiles;

/// What the file `name` of a generic run's folder holds (one line).
pub fn describe_generic(name: &str) -> &'static str {
    let stem = name.rsplit_once('.').map_or(name, |(s, _)| s);
    match (stem, name.rsplit_once('.').map(|(_, e)| e)) {
        ("summary", Some("json")) => "the run's summary (as `contact2d run --json`; docs/user-guide.md lists its keys)",
        ("README", _) => "this file",
        ("mesh", _) => "the mesh undeformed and deformed, contact pairs coloured by state (last step)",
        ("von_mises", _) => "von Mises stress of every body (last step) with its colour bar",
        ("history", _) => {
            "each interface's normal and tangential force and its resultant F1, F2 (signed) over the steps"
        }
        ("steps", Some("csv")) => {
            "one row per step: pattern factors, status, iterations, each interface's forces and zone lengths"
        }
        ("steps", Some("pvd")) => "ParaView collection of the step files (open this one; time = step number)",
        (s, Some("vtu")) if s.starts_with("step_") => "one load step for ParaView (VTK XML unstructured grid)",
        (s, Some("csv")) if s.starts_with("contact_") && s.contains("_step_") => {
            "one interface's profile at one step (run --profiles all): s, x, y, pressure, shear, gap, slip, state"
        }
        (s, Some("csv")) if s.starts_with("contact_") => {
            "one interface's profile at the last step: s, x, y, pressure, shear, gap, slip, state"
        }
        (s, _) if s.starts_with("contact_") => "pressure and shear along one interface's master curve (last step)",
        (s, Some("csv")) if s.starts_with("fretting_") => {
            "one interface's fretting numbers over the last load cycle, per pair: s, slip_amplitude, dissipation, \
             shear_max, sigma_tt, ruiz"
        }
        (s, _) if s.starts_with("fretting_") => {
            "slip amplitude, dissipation per length and the Ruiz parameter along one interface (last cycle), \
             each over its largest value"
        }
        (s, Some("csv")) if s.starts_with("hysteresis_") => {
            "one interface's hysteresis loop over the last load cycle: step, displacement, tangential_force"
        }
        (s, _) if s.starts_with("hysteresis_") => {
            "one interface's tangential force against the reference groups' relative displacement (last cycle)"
        }
        _ => "",
    }
}

/// The README text of a run's folder with the files `written`, described by the preset where it
/// has its own words for them.
pub fn generic_readme_text(
    report: &GenericReport,
    description: &str,
    written: &[String],
    preset: Option<&dyn PresetFiles>,
) -> String {
    let mut t = format!("contact2d outputs of scene \"{}\"\n", report.scene);
    if !description.is_empty() {
        let _ = writeln!(t, "{description}");
    }
    let _ = writeln!(t, "{}", method_line(report));
    if preset.is_none() {
        t.push_str("Units: those of the scene (forces per unit thickness where the thickness is 1).\n");
    }
    t.push_str("\nFiles:\n");
    for file in written {
        let what = preset.and_then(|p| p.describe(file)).unwrap_or_else(|| describe_generic(file));
        let _ = writeln!(t, "  {file:<24} {what}");
    }
    if let Some(p) = preset {
        t.push('\n');
        t.push_str(&p.readme_notes());
    }
    t
}

/// The choices a run made on its own: the algorithm, whether the history was solved once and
/// scaled, and the pairing of each interface (what `automatic` chose).
pub fn method_line(report: &GenericReport) -> String {
    let pairings: Vec<String> = report.pairing_used.iter().map(|(name, p)| format!("{name}: {p}")).collect();
    let history =
        if report.scaled { "solved once and scaled (no gap, proportional loads)" } else { "solved step by step" };
    format!(
        "Method: {}, {}, {history}; pairing {}; {}.",
        report.algorithm.key(),
        report.kinematics.replace('_', " "),
        pairings.join(", "),
        linear_phrase(report.algorithm, report.linear_used)
    )
}

/// What the contact states' linear algebra was, in words (`linear_used` of the summary).
fn linear_phrase(algorithm: ContactAlgorithm, linear_used: &str) -> &'static str {
    match (algorithm, linear_used) {
        (ContactAlgorithm::Penalty | ContactAlgorithm::AugmentedLagrangian, "sparse") => {
            "Newton on the full system (a sparse LU per iteration)"
        }
        (ContactAlgorithm::Penalty | ContactAlgorithm::AugmentedLagrangian, _) => {
            "Newton condensed onto the pairs (the interface's dense compliances, a dense LU per iteration)"
        }
        (_, "sparse") => "linear path sparse (each state on the full system, no dense block)",
        _ => "linear path condensed (the interface's dense compliances)",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_generic_file_is_described() {
        for name in [
            "summary.json",
            "README.txt",
            "mesh.png",
            "contact_bore.svg",
            "contact_bore.csv",
            "contact_bore_step_003.csv",
            "history.png",
            "von_mises.svg",
            "steps.csv",
            "step_000.vtu",
            "steps.pvd",
        ] {
            assert!(!describe_generic(name).is_empty(), "{name}");
        }
        assert!(describe_generic("other.txt").is_empty());
    }

    #[test]
    fn the_linear_phrase_names_the_path_each_algorithm_took() {
        for algorithm in [ContactAlgorithm::Penalty, ContactAlgorithm::AugmentedLagrangian] {
            assert!(linear_phrase(algorithm, "sparse").contains("full system"));
            assert!(linear_phrase(algorithm, "condensed").contains("condensed"));
        }
        assert!(linear_phrase(ContactAlgorithm::ActiveSet, "sparse").contains("sparse"));
        assert!(linear_phrase(ContactAlgorithm::ActiveSet, "condensed").contains("condensed"));
    }
}
