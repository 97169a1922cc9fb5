//! The benchmark's outputs: references, errors, CSV, a markdown table and the error-time data of
//! the figures.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use contact2d_contact::ContactAlgorithm;

use super::{BenchCase, Measurement, Quantity, Reference, median, richardson};

/// The references of one case: the algorithm whose values gave them, and the reference per
/// quantity (`None`: not defined, e.g. no contact end).
pub type CaseReferences = (ContactAlgorithm, Vec<(Quantity, Option<Reference>)>);

/// The reference of every (case, quantity) and the algorithm whose values gave it.
#[derive(Debug, Clone, PartialEq)]
pub struct References {
    /// Per case (b only with friction: without it b = l).
    pub by_case: BTreeMap<BenchCase, CaseReferences>,
}

/// The quantities reported for a case (b only with friction; without it b = l).
pub fn quantities(case: BenchCase) -> Vec<Quantity> {
    Quantity::ALL.into_iter().filter(|q| *q != Quantity::StickEnd || case.frictional()).collect()
}

/// References from the converged runs: per case the algorithm with converged values on the most
/// levels (ties: active set, then Boussinesq, then Clarabel, the order of their cost), then
/// [`richardson`] on its three finest levels.
pub fn references(measurements: &[Measurement]) -> References {
    let mut by_case = BTreeMap::new();
    let preference = [ContactAlgorithm::ActiveSet, ContactAlgorithm::Boussinesq, ContactAlgorithm::Clarabel];
    let converged = |case, algorithm| -> Vec<&Measurement> {
        let mut v: Vec<&Measurement> = measurements
            .iter()
            .filter(|m| m.case == case && m.algorithm == algorithm && m.status == "converged" && m.values.is_some())
            .collect();
        v.sort_by_key(|m| m.level);
        v
    };
    let mut cases: Vec<BenchCase> = measurements.iter().map(|m| m.case).collect();
    cases.sort();
    cases.dedup();
    for case in cases {
        let Some(algorithm) = preference.iter().copied().rev().max_by_key(|a| converged(case, *a).len()) else {
            continue;
        };
        let runs = converged(case, algorithm);
        let refs = quantities(case)
            .into_iter()
            .map(|q| {
                let samples: Vec<(usize, f64)> =
                    runs.iter().filter_map(|m| m.values.and_then(|v| v.get(q)).map(|x| (m.level, x))).collect();
                (q, richardson(&samples))
            })
            .collect();
        by_case.insert(case, (algorithm, refs));
    }
    References { by_case }
}

impl References {
    /// The reference of one quantity of a case.
    pub fn get(&self, case: BenchCase, q: Quantity) -> Option<Reference> {
        self.by_case.get(&case)?.1.iter().find(|(x, _)| *x == q).and_then(|(_, r)| *r)
    }

    /// Relative error |x − ref| / |ref| of a measurement's quantity; `None` where undefined,
    /// including the finest level when the reference is that level's value (no error to
    /// measure there).
    pub fn error(&self, m: &Measurement, q: Quantity) -> Option<f64> {
        let r = self.get(m.case, q)?;
        if m.level >= r.finest_level && !matches!(r.method, super::ReferenceMethod::Richardson { .. }) {
            return None;
        }
        let x = m.values?.get(q)?;
        (r.value != 0.0).then(|| (x - r.value).abs() / r.value.abs())
    }
}

fn fmt_opt(v: Option<f64>, digits: usize) -> String {
    v.map_or_else(String::new, |x| format!("{x:.digits$e}"))
}

/// One CSV row per measurement.
pub fn csv(measurements: &[Measurement], refs: &References) -> String {
    let mut s = String::from(
        "case,level,algorithm,dofs,pairs,status,iterations,repeats,time_median_s,time_min_s,time_max_s,\
         solve_median_s,P,Phi_E,l,b,sigma_star,err_P,err_Phi_E,err_l,err_b,err_sigma_star,note\n",
    );
    for m in measurements {
        let t = |f: fn(&[f64]) -> Option<f64>| f(&m.times).map_or_else(String::new, |x| format!("{x:.4}"));
        let v = |q| m.values.and_then(|v| v.get(q)).map_or_else(String::new, |x| format!("{x:.10e}"));
        let e = |q| fmt_opt(refs.error(m, q), 3);
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},\"{}\"",
            m.case.name(),
            m.level,
            m.algorithm.key(),
            m.dofs,
            m.pairs,
            m.status,
            m.iterations,
            m.times.len(),
            t(median),
            t(min),
            t(max),
            median(&m.solve_times).map_or_else(String::new, |x| format!("{x:.4}")),
            v(Quantity::Pull),
            v(Quantity::Energy),
            v(Quantity::ContactEnd),
            v(Quantity::StickEnd),
            v(Quantity::SigmaStar),
            e(Quantity::Pull),
            e(Quantity::Energy),
            e(Quantity::ContactEnd),
            e(Quantity::StickEnd),
            e(Quantity::SigmaStar),
            m.note.replace('"', "'"),
        );
    }
    s
}

fn min(v: &[f64]) -> Option<f64> {
    v.iter().copied().reduce(f64::min)
}
fn max(v: &[f64]) -> Option<f64> {
    v.iter().copied().reduce(f64::max)
}

/// The markdown tables: references per case, then per case one row per (level, algorithm).
pub fn markdown(measurements: &[Measurement], refs: &References) -> String {
    let mut s = String::new();
    s.push_str("#### Reference values\n\n| case | quantity | reference | method | from |\n|---|---|---|---|---|\n");
    for (case, (algorithm, list)) in &refs.by_case {
        for (q, r) in list {
            let (value, method, from) = match r {
                Some(r) => (
                    format!("{:.6}", r.value),
                    r.method.to_string(),
                    format!("{}, N ≤ {}", algorithm.key(), r.finest_level),
                ),
                None => ("–".into(), "not defined".into(), String::new()),
            };
            let _ = writeln!(s, "| {} | {} | {value} | {method} | {from} |", case.name(), q.name());
        }
    }
    let mut cases: Vec<BenchCase> = measurements.iter().map(|m| m.case).collect();
    cases.dedup();
    for case in cases {
        let qs = quantities(case);
        let _ = write!(
            s,
            "\n#### {}\n\n| N | DOFs | algorithm | status | iterations | wall time median [min–max] (s) | algorithm alone (s) |",
            case.name()
        );
        for q in &qs {
            let _ = write!(s, " err {} |", q.name());
        }
        s.push_str(" note |\n|---|---|---|---|---|---|---|");
        s.push_str(&"---|".repeat(qs.len() + 1));
        s.push('\n');
        let mut rows: Vec<&Measurement> = measurements.iter().filter(|m| m.case == case).collect();
        rows.sort_by_key(|m| m.level);
        for m in rows {
            let time = match (median(&m.times), min(&m.times), max(&m.times)) {
                (Some(a), Some(b), Some(c)) => format!("{a:.3} [{b:.3}–{c:.3}]"),
                _ => "–".into(),
            };
            let solve = median(&m.solve_times).map_or_else(|| "–".into(), |x| format!("{x:.4}"));
            let _ = write!(
                s,
                "| {} | {} | {} | {} | {} | {time} | {solve} |",
                m.level,
                m.dofs,
                m.algorithm.key(),
                m.status,
                m.iterations
            );
            for q in &qs {
                let finest_reference = refs.get(m.case, *q).is_some_and(|r| {
                    m.level >= r.finest_level && !matches!(r.method, super::ReferenceMethod::Richardson { .. })
                });
                let text = match refs.error(m, *q) {
                    Some(e) => format!("{e:.1e}"),
                    None if finest_reference && m.values.is_some() => "ref".into(),
                    None => "–".into(),
                };
                let _ = write!(s, " {text} |");
            }
            let _ = writeln!(s, " {} |", m.note);
        }
    }
    s
}

/// Error against median wall time, one series per algorithm, for one case and quantity: points
/// (time, error) in level order; undefined and zero errors (the finest level when it is its own
/// reference) are left out, they cannot be drawn on a log scale.
pub fn error_time_series(
    measurements: &[Measurement],
    refs: &References,
    case: BenchCase,
    q: Quantity,
) -> Vec<(ContactAlgorithm, Vec<(f64, f64)>)> {
    let mut algorithms: Vec<ContactAlgorithm> = Vec::new();
    for m in measurements.iter().filter(|m| m.case == case) {
        if !algorithms.contains(&m.algorithm) {
            algorithms.push(m.algorithm);
        }
    }
    algorithms
        .into_iter()
        .map(|a| {
            let mut runs: Vec<&Measurement> =
                measurements.iter().filter(|m| m.case == case && m.algorithm == a && m.status == "converged").collect();
            runs.sort_by_key(|m| m.level);
            let points = runs
                .iter()
                .filter_map(|m| Some((m.median_time()?, refs.error(m, q)?)))
                .filter(|(t, e)| *t > 0.0 && *e > 0.0)
                .collect();
            (a, points)
        })
        .collect()
}

/// The log-log figures of error against median wall time, one per case (`bench_<case>.svg` and
/// `.png`): one line per algorithm and quantity (P and Φ_E, the two that converge smoothly; l, b
/// and σ* are in the tables). Both axes carry log₁₀ of the value on a linear scale, which keeps
/// the tick labels exact decades.
///
/// # Errors
/// The path and cause of a figure that cannot be drawn.
pub fn figures(
    dir: &std::path::Path,
    measurements: &[Measurement],
    refs: &References,
) -> Result<(), (std::path::PathBuf, String)> {
    for (name, axes, series) in figure_specs(measurements, refs) {
        let path = dir.join(name);
        crate::output::chart::line_chart(&path, &axes, &series).map_err(|e| (path.clone(), e.to_string()))?;
    }
    Ok(())
}

/// The figures of [`figures`] as (file name, axes, series), for writers that place the files
/// themselves.
pub fn figure_specs(
    measurements: &[Measurement],
    refs: &References,
) -> Vec<(String, crate::output::chart::Axes, Vec<crate::output::chart::Series>)> {
    use crate::output::chart::{Axes, Series};
    let mut specs = vec![];
    for case in refs.by_case.keys() {
        let mut series = Vec::new();
        for q in [Quantity::Pull, Quantity::Energy] {
            for (algorithm, points) in error_time_series(measurements, refs, *case, q) {
                if !points.is_empty() {
                    series.push(Series {
                        label: format!("{} {}", algorithm.key(), q.name()),
                        points: points.iter().map(|(t, e)| (t.log10(), e.log10())).collect(),
                        markers: true,
                    });
                }
            }
        }
        let mut levels: Vec<String> = Vec::new();
        for m in measurements.iter().filter(|m| m.case == *case && m.values.is_some()) {
            let n = m.level.to_string();
            if !levels.contains(&n) {
                levels.push(n);
            }
        }
        let axes = Axes {
            title: format!("{}: error against wall time (N = {})", case.name(), levels.join(", ")),
            x_label: "log10 of the median wall time of the run (s)".into(),
            y_label: "log10 of the relative error".into(),
            log_x: false,
            log_y: false,
        };
        for ext in ["svg", "png"] {
            specs.push((format!("bench_{}.{ext}", case.name()), axes.clone(), series.clone()));
        }
    }
    specs
}
