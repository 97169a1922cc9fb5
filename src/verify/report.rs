//! The gallery's tables (terminal text and markdown) and its figures.
//!
//! ```text
//! case | quantity | mesh | measured | reference | error | tolerance | PASS/FAIL
//! ```
//! The error is relative (%) or absolute as the tolerance is; measurements without a reference
//! follow each case's checks.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use super::{CaseReport, Check, Tolerance};
use crate::output::OutputError;
use crate::output::atomic::OutputDir;
use crate::output::chart::line_chart;

fn error_text(c: &Check) -> (String, String) {
    match c.tolerance {
        Tolerance::Relative(t) if t < 1e-4 => (format!("{:.1e}", c.error()), format!("{t:.0e} rel")),
        Tolerance::Relative(t) => (format!("{:.3} %", 100.0 * c.error()), format!("{:.3} %", 100.0 * t)),
        Tolerance::Absolute(t) => (format!("{:.3e}", c.error()), format!("{t:.1e}")),
    }
}

fn verdict(c: &Check) -> &'static str {
    if c.passed() { "PASS" } else { "FAIL" }
}

/// The plain-text table of `reports`: one line per check, then the measurements.
pub fn text_table(reports: &[CaseReport]) -> String {
    let mut s = String::new();
    for r in reports {
        let _ = writeln!(s, "== {} ({})", r.name, r.source);
        for c in &r.checks {
            let (e, t) = error_text(c);
            let _ = writeln!(
                s,
                "  {:<48} {:<28} measured {:>12.6} reference {:>12.6} error {:>11} tol {:>9}  {}",
                c.quantity,
                c.mesh,
                c.measured,
                c.reference,
                e,
                t,
                verdict(c)
            );
        }
        for m in &r.measurements {
            let _ = writeln!(s, "  {:<48} {:<28} measured {:>12.6}", m.quantity, m.mesh, m.value);
        }
        for n in &r.notes {
            let _ = writeln!(s, "  note: {n}");
        }
    }
    let (passed, total) = counts(reports);
    let _ = writeln!(s, "{passed} of {total} checks passed");
    s
}

/// The markdown tables of `reports` (one per case), for `docs/verification.md`.
pub fn markdown(reports: &[CaseReport]) -> String {
    let mut s = String::new();
    for r in reports {
        let _ = writeln!(s, "#### {}\n\nSource: {}.\n", r.name, r.source);
        let _ = writeln!(
            s,
            "| quantity | mesh | measured | reference | error | tolerance | |\n|---|---|---|---|---|---|---|"
        );
        for c in &r.checks {
            let (e, t) = error_text(c);
            let _ = writeln!(
                s,
                "| {} | {} | {:.6} | {:.6} | {e} | {t} | {} |",
                c.quantity,
                c.mesh,
                c.measured,
                c.reference,
                verdict(c)
            );
        }
        if !r.measurements.is_empty() {
            let _ = writeln!(s, "\n| measured without a reference | mesh | value |\n|---|---|---|");
            for m in &r.measurements {
                let _ = writeln!(s, "| {} | {} | {:.6} |", m.quantity, m.mesh, m.value);
            }
        }
        for n in &r.notes {
            let _ = writeln!(s, "\nNote: {n}");
        }
        let _ = writeln!(s);
    }
    s
}

/// (passed, total) checks.
pub fn counts(reports: &[CaseReport]) -> (usize, usize) {
    let checks = reports.iter().flat_map(|r| &r.checks);
    (checks.clone().filter(|c| c.passed()).count(), checks.count())
}

/// Writes the figures (SVG and PNG) and `verification.md` (the markdown tables) into `dir`, each file whole.
///
/// # Errors
/// [`OutputError`] when the folder or a file cannot be written.
pub fn write(dir: &Path, reports: &[CaseReport]) -> Result<Vec<PathBuf>, OutputError> {
    let mut out = OutputDir::prepare(dir, None)?;
    for figure in reports.iter().flat_map(|r| &r.figures) {
        // The SVG for documents, a PNG beside it for a quick look.
        let png = Path::new(&figure.file).with_extension("png").to_string_lossy().into_owned();
        for name in [figure.file.as_str(), png.as_str()] {
            out.write_with(name, |tmp| line_chart(tmp, &figure.axes, &figure.series))?;
        }
    }
    out.write_bytes("verification.md", markdown(reports).as_bytes())?;
    out.close()
}
