//! The stress grid's outputs: a CSV row per cell and algorithm, markdown overview and cell tables.

use std::fmt::Write as _;

use contact2d_element::PlaneCondition;

use super::cell::{AGREE_ETA, AGREE_RELATIVE, CellResult, KKT_TOLERANCE, StressCell, difference, disagrees};

fn plane(c: &StressCell) -> &'static str {
    if c.plane == PlaneCondition::Strain { "strain" } else { "stress" }
}

fn opt(v: Option<f64>) -> String {
    v.map_or_else(|| "–".into(), |x| format!("{x:.1e}"))
}

/// One CSV row per (cell, algorithm).
pub fn csv(results: &[CellResult]) -> String {
    let mut s = String::from(
        "ratio,mu,eps,nu,plane,distortion,jacobian_quality,cond_cnn,diag_ratio,algorithm,status,iterations,\
         time_s,P,Phi_E,l,b,sigma_star,kkt_rel,disagree_rel,disagree_eta,verdict,error\n",
    );
    for c in results {
        let p = &c.cell;
        for r in &c.results {
            let v = r.values;
            let _ = writeln!(
                s,
                "{:e},{},{:e},{},{},{},{},{},{},{},{},{},{:.3},{:e},{:e},{:e},{:e},{:e},{:e},{:e},{:e},\"{}\",\"{}\"",
                p.ratio,
                p.mu,
                p.eps,
                p.nu,
                plane(p),
                p.distortion,
                c.jacobian_quality.map_or_else(String::new, |q| format!("{q:.3}")),
                c.cond_cnn.map_or_else(String::new, |q| format!("{q:e}")),
                c.diag_ratio.map_or_else(String::new, |q| format!("{q:e}")),
                r.algorithm.key(),
                r.status,
                r.iterations,
                r.time_s,
                v[0],
                v[1],
                v[2],
                v[3],
                v[4],
                r.kkt,
                c.disagreement.0,
                c.disagreement.1,
                c.verdict.replace('"', "'"),
                r.error.clone().unwrap_or_default().replace('"', "'"),
            );
        }
    }
    s
}

fn short(c: &CellResult) -> &'static str {
    if c.failed() {
        "FAIL"
    } else if c.verdict == "ok" {
        "ok"
    } else {
        "nc"
    }
}

/// The markdown: counts, the failures and non-converged cells, an overview per ε of the main grid,
/// and a table of every cell.
pub fn markdown(results: &[CellResult], level: usize) -> String {
    let mut s = String::new();
    let count = |k: &str| results.iter().filter(|c| short(c) == k).count();
    let _ = writeln!(
        s,
        "N = {level}: {} cells, {} ok, {} with a non-converged algorithm (status and reason reported), {} FAIL.\n\
         Thresholds: relative KKT residual ≤ {KKT_TOLERANCE:.0e}; agreement ≤ {AGREE_RELATIVE:.0e} relative on \
         P, Φ_E, σ* and ≤ {AGREE_ETA:.0e} on l, b.\n",
        results.len(),
        count("ok"),
        count("nc"),
        count("FAIL"),
    );
    s.push_str(&per_algorithm(results));
    let listed: Vec<&CellResult> = results.iter().filter(|c| c.verdict != "ok").collect();
    if !listed.is_empty() {
        s.push_str("#### Cells that are not plainly ok\n\n| E2/E1 | μ | ε | ν, plane | distortion | verdict |\n|---|---|---|---|---|---|\n");
        for c in listed {
            let p = &c.cell;
            let _ = writeln!(
                s,
                "| {:.0e} | {} | {:.0e} | {} {} | {} | {} |",
                p.ratio,
                p.mu,
                p.eps,
                p.nu,
                plane(p),
                p.distortion,
                c.verdict
            );
        }
        s.push('\n');
    }
    let main: Vec<&CellResult> =
        results.iter().filter(|c| c.cell.distortion == 0.0 && c.cell.plane == PlaneCondition::Stress).collect();
    let mut eps: Vec<f64> = main.iter().map(|c| c.cell.eps).collect();
    eps.dedup();
    let mut mus: Vec<f64> = main.iter().map(|c| c.cell.mu).collect();
    mus.sort_by(f64::total_cmp);
    mus.dedup();
    for e in eps {
        let _ = write!(s, "#### Main grid, ε = {e:e}: verdict (largest relative KKT residual)\n\n| E2/E1 \\ μ |");
        for mu in &mus {
            let _ = write!(s, " {mu} |");
        }
        s.push_str("\n|---|");
        s.push_str(&"---|".repeat(mus.len()));
        s.push('\n');
        let mut ratios: Vec<f64> = main.iter().filter(|c| c.cell.eps == e).map(|c| c.cell.ratio).collect();
        ratios.sort_by(f64::total_cmp);
        ratios.dedup();
        for r in ratios {
            let _ = write!(s, "| {r:.0e} |");
            for mu in &mus {
                let cell = main.iter().find(|c| c.cell.eps == e && c.cell.ratio == r && c.cell.mu == *mu);
                let text = cell.map_or_else(String::new, |c| {
                    let kkt = c.results.iter().map(|x| x.kkt).filter(|k| k.is_finite()).fold(0.0, f64::max);
                    format!("{} ({kkt:.0e})", short(c))
                });
                let _ = write!(s, " {text} |");
            }
            s.push('\n');
        }
        s.push('\n');
    }
    s.push_str(
        "#### Every cell\n\nPer algorithm: status, iterations (summed over the load steps), largest relative KKT \
         residual. cond(C_NN): 2-norm condition number of the condensed normal compliance; diag K: largest over \
         smallest stiffness diagonal; det J: worst min/max Jacobian ratio of a distorted mesh.\n\n\
         | E2/E1 | μ | ε | ν, plane | dist. (det J) | cond(C_NN) | diag K | algorithms | disagreement (rel; η) | verdict |\n\
         |---|---|---|---|---|---|---|---|---|---|\n",
    );
    for c in results {
        let p = &c.cell;
        let algs: Vec<String> = c
            .results
            .iter()
            .map(|r| format!("{} {} {} ({:.0e})", r.algorithm.key(), r.status, r.iterations, r.kkt))
            .collect();
        let _ = writeln!(
            s,
            "| {:.0e} | {} | {:.0e} | {} {} | {} ({}) | {} | {} | {} | {:.0e}; {:.0e} | {} |",
            p.ratio,
            p.mu,
            p.eps,
            p.nu,
            plane(p),
            p.distortion,
            c.jacobian_quality.map_or_else(|| "–".into(), |q| format!("{q:.2}")),
            opt(c.cond_cnn),
            opt(c.diag_ratio),
            algs.join("<br>"),
            c.disagreement.0,
            c.disagreement.1,
            short(c),
        );
    }
    s
}

/// Per algorithm: how its runs ended, the largest residual of its converged runs, and how often
/// it disagrees with the first algorithm of the cell (the active set by default).
fn per_algorithm(results: &[CellResult]) -> String {
    let mut s = String::from(
        "| algorithm | runs | converged | of which KKT ≤ tol | largest KKT (converged) | other status | error | \
         disagrees with the first algorithm (P/Φ_E/σ*; l/b; l or b undefined) |\n|---|---|---|---|---|---|---|---|\n",
    );
    let Some(first) = results.first() else { return s };
    for (i, r0) in first.results.iter().enumerate() {
        let runs: Vec<_> = results.iter().filter_map(|c| Some((c.results.first()?, c.results.get(i)?))).collect();
        let converged: Vec<_> = runs.iter().filter(|(_, r)| r.status == "converged").collect();
        let small = converged.iter().filter(|(_, r)| r.kkt <= KKT_TOLERANCE).count();
        let largest = converged.iter().map(|(_, r)| r.kkt).fold(0.0, f64::max);
        let other = runs.iter().filter(|(_, r)| r.status != "converged" && r.error.is_none()).count();
        let errors = runs.iter().filter(|(_, r)| r.error.is_some()).count();
        let both: Vec<(f64, f64)> = runs
            .iter()
            .filter(|(a, r)| i > 0 && a.status == "converged" && r.status == "converged")
            .map(|(a, r)| difference(a, r))
            .collect();
        let _ = writeln!(
            s,
            "| {} | {} | {} | {small} | {largest:.1e} | {other} | {errors} | {} ({}; {}; {}) |",
            r0.algorithm.key(),
            runs.len(),
            converged.len(),
            both.iter().filter(|d| disagrees(**d)).count(),
            both.iter().filter(|d| d.0 > AGREE_RELATIVE).count(),
            both.iter().filter(|d| d.1 > AGREE_ETA).count(),
            both.iter().filter(|d| d.1.is_infinite()).count(),
        );
    }
    s.push('\n');
    s
}
