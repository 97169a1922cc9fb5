//! The outputs of a generic run, from (problem, solution) alone:
//!
//! ```text
//! summary.json                      the --json object
//! mesh.png/.svg                     undeformed and deformed mesh with the pair states (last step)
//! contact_<name>.png/.svg           pressure and shear along the master curve (last step)
//! von_mises.png/.svg                the von Mises field (last step)
//! history.png/.svg                  normal and tangential force of every interface over the steps
//! contact_<name>.csv                the profile of each interface (last step)
//! fretting_<name>.*, hysteresis_<name>.*  with a load cycle: src/generic/fretting_outputs.rs
//! steps.csv                         one row per step: factors, status, resultants per interface
//! step_000.vtu ... steps.pvd        one VTK file per step and their collection (time = step number)
//! ```

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use contact2d_contact::{BuiltProblem, ContactSolution};

use serde::ser::{Serialize, SerializeMap, SerializeSeq, Serializer};

use super::{GenericOutcome, GenericReport, StepTable};
use crate::output::chart::{Axes, Series, line_chart};
use crate::output::step_view::{NodeValues, StepView, state_code};
use crate::output::{
    FIGURE_EXTENSIONS, OutputDir, OutputError, PresetFiles, SUMMARY_FILE, atomic, field_plot, figure, mesh_plot,
    step_file_name, vtu,
};

/// Writes every output of `outcome` into the prepared folder `out` (each file atomically, stale
/// files of an earlier run removed, `summary.json` with the manifest last) and returns the paths
/// written. A figure that cannot be drawn is skipped with a note in the summary. The history
/// must hold every step ([`super::solve_generic`]); a streamed run writes each step's file with
/// [`write_step_vtu`] as it is solved and the rest with [`finish_generic_outputs`].
///
/// # Errors
/// [`OutputError`] naming the first file that could not be written; the folder then holds no
/// summary.
pub fn write_generic_outputs_into(mut out: OutputDir, outcome: &GenericOutcome) -> Result<Vec<PathBuf>, OutputError> {
    if outcome.history.steps.len() != outcome.report.steps.len() {
        let reason = "the history does not hold every step (a streamed run writes them as they are solved)".into();
        return Err(OutputError::MissingData { path: out.path().to_path_buf(), reason });
    }
    for (k, step) in outcome.history.steps.iter().enumerate() {
        write_step_vtu(&mut out, &outcome.built, k, &step.solution)?;
    }
    finish_generic_outputs(out, outcome)
}

/// Writes step `k`'s VTU file (`step_<k>.vtu`) into `out`: called for each step as it is solved,
/// before [`finish_generic_outputs`].
///
/// # Errors
/// [`OutputError`] naming the file.
pub fn write_step_vtu(
    out: &mut OutputDir,
    built: &BuiltProblem,
    k: usize,
    solution: &ContactSolution,
) -> Result<PathBuf, OutputError> {
    out.write_with(&step_file_name(k), |tmp| vtu::write_step_vtu(tmp, &built_step_view(built, solution)))
}

/// A solved run as the one writer sees it: the summary, the problem of the last step and that
/// step's view, and the time of each step in `steps.pvd`.
pub struct RunFolder<'a> {
    /// The scene's description (the README's second line).
    pub description: &'a str,
    /// The problem of the last step (its load patterns and interfaces name the table's columns).
    pub built: &'a BuiltProblem,
    /// The summary, with every step row.
    pub report: &'a GenericReport,
    /// The last step as the figures draw it.
    pub last: StepView<'a>,
    /// The time of each step in `steps.pvd` (the step number; the load w of the paper's case).
    pub step_times: Vec<f64>,
}

impl<'a> RunFolder<'a> {
    /// The folder of a generic run: its last step's view, times = step numbers.
    ///
    /// # Errors
    /// [`OutputError::MissingData`] at `path` without a solved step.
    pub fn of(outcome: &'a GenericOutcome, path: &Path) -> Result<RunFolder<'a>, OutputError> {
        let Some(last) = outcome.history.steps.last() else {
            return Err(OutputError::MissingData { path: path.to_path_buf(), reason: "no solved step".into() });
        };
        Ok(RunFolder {
            description: &outcome.scene.description,
            built: &outcome.built,
            report: &outcome.report,
            last: step_view(outcome, &last.solution),
            step_times: (1..=outcome.report.steps.len()).map(|k| k as f64).collect(),
        })
    }
}

/// Writes the outputs of `outcome` other than the step files, which [`write_step_vtu`] wrote for
/// each of the report's steps (see [`finish_outputs`]).
///
/// # Errors
/// As [`write_generic_outputs_into`].
pub fn finish_generic_outputs(out: OutputDir, outcome: &GenericOutcome) -> Result<Vec<PathBuf>, OutputError> {
    let folder = RunFolder::of(outcome, out.path())?;
    finish_outputs(out, &folder, None)
}

/// Writes every run's files but the step files (written before, one per step, as
/// `step_<k>.vtu`): figures and profiles of the last step, `steps.csv`, `steps.pvd`, the
/// preset's own files, `README.txt` and `summary.json` last. The manifest and the returned paths
/// list the step files before `steps.pvd`, whenever they were written.
///
/// # Errors
/// As [`write_generic_outputs_into`].
pub fn finish_outputs(
    mut out: OutputDir,
    folder: &RunFolder,
    preset: Option<&dyn PresetFiles>,
) -> Result<Vec<PathBuf>, OutputError> {
    let report = folder.report;
    let name = &report.scene;
    let n = report.steps.len();
    // The figures show the last step: one that did not converge says so in their titles.
    let solved = ["converged", "penalised"];
    let shown = match report.steps.last().filter(|s| !solved.contains(&s.status)) {
        Some(last) => format!("{n}/{n}, {}: did not converge", last.status),
        None => format!("{n}/{n}"),
    };
    let view = &folder.last;
    let mut skipped = vec![];
    for ext in FIGURE_EXTENSIONS {
        figure(&mut out, &format!("mesh.{ext}"), &mut skipped, |p| {
            mesh_plot::draw_mesh(p, &format!("{name}: mesh (step {shown})"), view)
        })?;
        for (iface, result) in &report.contacts {
            figure(&mut out, &format!("contact_{}.{ext}", file_safe(iface)), &mut skipped, |p| {
                draw_profile(p, &format!("{name}: contact \"{iface}\" (step {shown})"), result)
            })?;
        }
        figure(&mut out, &format!("von_mises.{ext}"), &mut skipped, |p| {
            field_plot::draw_von_mises(p, &format!("{name}: von Mises stress (step {shown})"), view)
        })?;
        for (iface, result) in &report.contacts {
            let Some(f) = result.fretting.as_deref() else { continue };
            let steps = format!("steps {}–{}", f.steps[0], f.steps[1]);
            figure(&mut out, &format!("fretting_{}.{ext}", file_safe(iface)), &mut skipped, |p| {
                let title = format!("{name}: contact \"{iface}\", fretting over the last cycle ({steps})");
                super::fretting_outputs::draw_fretting(p, &title, f)
            })?;
            let Some(h) = &f.hysteresis else { continue };
            figure(&mut out, &format!("hysteresis_{}.{ext}", file_safe(iface)), &mut skipped, |p| {
                let title = format!("{name}: contact \"{iface}\", hysteresis over the last cycle ({steps})");
                super::fretting_outputs::draw_hysteresis(p, &title, h)
            })?;
        }
        if n > 1 && !preset.is_some_and(|p| p.replaces("history")) {
            figure(&mut out, &format!("history.{ext}"), &mut skipped, |p| {
                draw_history(p, &format!("{name}: contact forces over the steps (resultant on the slave side)"), folder)
            })?;
        }
    }
    for (iface, result) in &report.contacts {
        out.write_bytes(&format!("contact_{}.csv", file_safe(iface)), profile_csv(result).as_bytes())?;
        if let Some(f) = result.fretting.as_deref() {
            let csv = super::fretting_outputs::fretting_csv(f);
            out.write_bytes(&format!("fretting_{}.csv", file_safe(iface)), csv.as_bytes())?;
            if let Some(h) = &f.hysteresis {
                let csv = super::fretting_outputs::hysteresis_csv(f, h);
                out.write_bytes(&format!("hysteresis_{}.csv", file_safe(iface)), csv.as_bytes())?;
            }
        }
    }
    out.write_bytes("steps.csv", steps_csv(folder, preset).as_bytes())?;
    write_step_profiles(&mut out, &report.steps)?;
    if let Some(preset) = preset {
        preset.write(&mut out, &mut skipped)?;
    }
    let step_files: Vec<String> = (0..n).map(step_file_name).collect();
    let collection: Vec<(f64, String)> = folder.step_times.iter().copied().zip(step_files.iter().cloned()).collect();
    out.write_with(PVD_FILE, |p| vtu::write_pvd(p, &collection))?;
    let mut names = steps_before_pvd(out.written().to_vec(), |f| f.as_str(), |f| step_files.iter().any(|s| s == f));
    names.extend(["README.txt".to_string(), SUMMARY_FILE.to_string()]);
    let mut text = super::readme::generic_readme_text(report, folder.description, &names, preset);
    if !skipped.is_empty() {
        text.push_str("\nNot drawn (the data cannot be plotted; the CSV and VTU files hold the values):\n");
        for note in &skipped {
            let _ = writeln!(text, "  {note}");
        }
    }
    out.write_bytes("README.txt", text.as_bytes())?;
    // The summary but its step rows, which are printed from the report (no copy of them).
    let mut head = report.without_steps();
    head.notes.extend(skipped);
    let summary_path = out.path().join(SUMMARY_FILE);
    let is_step = |f: &str| step_files.iter().any(|s| s == f);
    let written = out.finish_with(|files, file| {
        // The summary without its step rows as one JSON value (keys sorted at every level, as
        // a manifest prints them); the rows become values one at a time while printed, straight
        // into the file.
        let serialize =
            |e: serde_json::Error| OutputError::Serialize { path: summary_path.clone(), reason: e.to_string() };
        let value = serde_json::to_value(&head).map_err(serialize)?;
        let files = steps_before_pvd(files.to_vec(), |f| f.as_str(), is_step);
        let head = atomic::manifest_object(value, &files);
        serde_json::to_writer_pretty(&mut *file, &SortedSummary { head: &head, steps: &report.steps })
            .map_err(serialize)?;
        file.write_all(b"\n").map_err(|e| OutputError::io(&summary_path, e))
    })?;
    Ok(steps_before_pvd(written, |p| p.file_name().and_then(|f| f.to_str()).unwrap_or(""), is_step))
}

/// Writes the profile of every interface at every step whose summary row carries it (`run
/// --profiles all`): `contact_<name>_step_<k>.csv`, k from 1, the columns of `contact_<name>.csv`.
///
/// # Errors
/// [`OutputError`] naming the file.
pub fn write_step_profiles(out: &mut OutputDir, steps: &StepTable) -> Result<(), OutputError> {
    for (k, step) in steps.iter().enumerate() {
        for (iface, result) in step.contacts.iter().filter(|(_, r)| r.profile.is_some()) {
            out.write_bytes(
                &format!("contact_{}_step_{:03}.csv", file_safe(iface), k + 1),
                profile_csv(result).as_bytes(),
            )?;
        }
    }
    Ok(())
}

/// A summary printed as its whole JSON value would be (keys sorted at every level), with the
/// step rows, which grow with the number of steps, made JSON values one at a time.
struct SortedSummary<'a> {
    /// The summary as a manifest object, `steps` empty.
    head: &'a serde_json::Map<String, serde_json::Value>,
    /// The step rows.
    steps: &'a StepTable,
}

impl Serialize for SortedSummary<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(self.head.len()))?;
        for (k, v) in self.head {
            if k == "steps" {
                map.serialize_entry(k, &RowValues(self.steps))?;
            } else {
                map.serialize_entry(k, v)?;
            }
        }
        map.end()
    }
}

/// Step rows printed as their JSON values, each made only while it is printed.
struct RowValues<'a>(&'a StepTable);

impl Serialize for RowValues<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut seq = serializer.serialize_seq(Some(self.0.len()))?;
        for row in self.0.iter() {
            seq.serialize_element(&serde_json::to_value(&row).map_err(serde::ser::Error::custom)?)?;
        }
        seq.end()
    }
}

/// The collection of the step files.
const PVD_FILE: &str = "steps.pvd";

/// `files` with the step files (those `is_step` names) moved, in their order, to just before
/// `steps.pvd`: the order of a run that writes them after the figures and tables, whenever they
/// were written.
fn steps_before_pvd<T>(files: Vec<T>, name: impl Fn(&T) -> &str, is_step: impl Fn(&str) -> bool) -> Vec<T> {
    let (steps, others): (Vec<T>, Vec<T>) = files.into_iter().partition(|f| is_step(name(f)));
    let mut steps = Some(steps);
    let mut out = Vec::with_capacity(others.len() + steps.as_ref().map_or(0, Vec::len));
    for f in others {
        if name(&f) == PVD_FILE {
            out.extend(steps.take().unwrap_or_default());
        }
        out.push(f);
    }
    out.extend(steps.take().unwrap_or_default());
    out
}

/// A name usable in a file name: letters, digits, `-` and `_` kept, anything else `_`.
fn file_safe(name: &str) -> String {
    name.chars().map(|c| if c.is_ascii_alphanumeric() || c == '-' || c == '_' { c } else { '_' }).collect()
}

/// The writers' view of one step: master-side pressures on the master nodes.
pub fn step_view<'a>(outcome: &'a GenericOutcome, solution: &'a ContactSolution) -> StepView<'a> {
    built_step_view(&outcome.built, solution)
}

/// [`step_view`] from the built problem alone.
pub fn built_step_view<'a>(built: &'a BuiltProblem, solution: &'a ContactSolution) -> StepView<'a> {
    let problem = &built.problem;
    let mut node_contact = vec![None; problem.model.mesh.num_nodes()];
    for iface in &built.interfaces {
        let factor = problem.model.body(&iface.master_region).map_or(1.0, |(_, b)| b.kinematics.pair_area_factor());
        for k in iface.pairs.clone() {
            let pair = &problem.pairs[k];
            let area = pair.weight * factor;
            node_contact[pair.master.0] = Some(NodeValues {
                pressure: solution.normal_force[k] / area,
                shear: solution.tangential_force[k] / area,
                state: state_code(solution.state[k]),
            });
        }
    }
    StepView {
        problem,
        solution,
        obstacles: built.interfaces.iter().filter(|i| i.rigid_slave).map(|i| &i.slave_contour).collect(),
        node_contact,
        axes: ["x1".into(), "x2".into()],
        stress_label: "σ_vM".into(),
    }
}

fn draw_profile(path: &Path, title: &str, result: &super::ContactResult) -> Result<(), OutputError> {
    let Some(p) = &result.profile else { return Ok(()) };
    let series = [
        Series {
            label: "pressure (≥ 0 in compression)".into(),
            points: p.s.iter().copied().zip(p.pressure.iter().copied()).collect(),
            markers: true,
        },
        Series {
            label: "shear".into(),
            points: p.s.iter().copied().zip(p.shear.iter().copied()).collect(),
            markers: true,
        },
    ];
    let axes = Axes {
        title: title.into(),
        x_label: "s, arc length along the master curve".into(),
        y_label: "contact traction (force / area)".into(),
        ..Axes::default()
    };
    line_chart(path, &axes, &series)
}

fn draw_history(path: &Path, title: &str, folder: &RunFolder) -> Result<(), OutputError> {
    let mut series = vec![];
    for iface in &folder.built.interfaces {
        let at = |f: fn(&super::ContactResult) -> f64| -> Vec<(f64, f64)> {
            folder
                .report
                .steps
                .iter()
                .enumerate()
                .filter_map(|(i, s)| s.contacts.get(&iface.name).map(|c| ((i + 1) as f64, f(c))))
                .collect()
        };
        series.push(Series {
            label: format!("{}: normal force", iface.name),
            points: at(|c| c.normal_force),
            markers: true,
        });
        series.push(Series {
            label: format!("{}: tangential force", iface.name),
            points: at(|c| c.tangential_force),
            markers: true,
        });
        // The transmitted force's components, signed: a reversal of the load shows.
        for (c, component) in [(0, "F1"), (1, "F2")] {
            let points = if c == 0 { at(|r| r.resultant[0]) } else { at(|r| r.resultant[1]) };
            series.push(Series { label: format!("{}: resultant {component}", iface.name), points, markers: true });
        }
    }
    let axes = Axes { title: title.into(), x_label: "load step".into(), y_label: "force".into(), ..Axes::default() };
    line_chart(path, &axes, &series)
}

fn profile_csv(result: &super::ContactResult) -> String {
    let mut out = String::from("s,x,y,pressure,shear,gap,slip,state\n");
    if let Some(p) = &result.profile {
        for i in 0..p.s.len() {
            let _ = writeln!(
                out,
                "{:e},{:e},{:e},{:e},{:e},{:e},{:e},{}",
                p.s[i], p.x[i], p.y[i], p.pressure[i], p.shear[i], p.gap[i], p.slip[i], p.state[i]
            );
        }
    }
    out
}

/// The step table: the generic columns, then the preset's.
fn steps_csv(folder: &RunFolder, preset: Option<&dyn PresetFiles>) -> String {
    let (preset_header, preset_rows) = preset.map(|p| p.step_columns()).unwrap_or_default();
    let patterns: Vec<String> = folder.built.problem.patterns().iter().map(|p| p.name.clone()).collect();
    let mut header = vec!["step".to_string()];
    header.extend(patterns.iter().map(|p| format!("factor_{p}")));
    header.extend(["status".into(), "iterations".into()]);
    for i in &folder.built.interfaces {
        for q in [
            "normal_force",
            "tangential_force",
            "contact_length",
            "stick_length",
            "max_pressure",
            "dissipation",
            "resultant_1",
            "resultant_2",
        ] {
            header.push(format!("{}_{q}", i.name));
        }
    }
    header.extend(preset_header.iter().map(|h| h.to_string()));
    let mut out = header.join(",") + "\n";
    for (k, s) in folder.report.steps.iter().enumerate() {
        let mut row = vec![(k + 1).to_string()];
        row.extend(patterns.iter().map(|p| format!("{:e}", s.factors.get(p).copied().unwrap_or(0.0))));
        row.extend([s.status.to_string(), s.iterations.to_string()]);
        for i in &folder.built.interfaces {
            if let Some(c) = s.contacts.get(&i.name) {
                for v in [
                    c.normal_force,
                    c.tangential_force,
                    c.contact_length,
                    c.stick_length,
                    c.max_pressure,
                    c.dissipation,
                    c.resultant[0],
                    c.resultant[1],
                ] {
                    row.push(format!("{v:e}"));
                }
            }
        }
        row.extend(preset_rows.get(k).into_iter().flatten().cloned());
        out += &(row.join(",") + "\n");
    }
    out
}
