//! The load factor a run last held (the sweep column `last_held_factor`), so that a capacity
//! study — how far a load goes before friction lets go — is one sweep.
//!
//! ```text
//! driving pattern p* = the pattern whose factor changes most in the run's last step row
//!                      (from the row before it, or from 0 for the first; ties: the first name)
//! converged:   last_held_factor = steps[last].factors[p*]      (the final factor; 1.0 for a run
//!                                                               without step factors)
//! not_held:    last_held_factor = not_held.last_held_factors[p*] (the previous converged step's)
//! any other status of a run that stopped at a step (max_iterations, numerical, …; a run whose
//! last row converged, e.g. one failing a history check, reports that row's factor):
//!              last_held_factor = steps[last − 1].factors[p*]  (the last converged step's; 0
//!                                                               when the first step failed)
//! a run that failed to start (error): none (empty cell)
//! ```
//! `not_held` certifies that friction let go in the next step; another status only says that
//! the next step was not solved, so its factor is a lower bound on the capacity. For a block
//! pressed by N and pulled by F·λ in steps of Δλ, a run that stops at friction's limit gives
//! `μN/F − Δλ < last_held_factor ≤ μN/F`.

use serde_json::Value;

/// The name of the sweep column.
pub const COLUMN: &str = "last_held_factor";

/// The pattern whose factor changes most in the last step row of the summary `run` (ties: the
/// first in name order), or `None` without step rows with factors.
fn driving_pattern(run: &Value) -> Option<String> {
    let steps = run["steps"].as_array()?;
    let last = steps.last()?["factors"].as_object()?;
    let before = steps.len().checked_sub(2).and_then(|i| steps[i]["factors"].as_object());
    let change = |name: &str, value: &Value| {
        let previous = before.and_then(|b| b.get(name)).and_then(Value::as_f64).unwrap_or(0.0);
        (value.as_f64().unwrap_or(0.0) - previous).abs()
    };
    let mut best: Option<(&String, f64)> = None;
    for (name, value) in last {
        let d = change(name, value);
        if best.is_none_or(|(_, b)| d > b) {
            best = Some((name, d));
        }
    }
    best.map(|(name, _)| name.clone())
}

/// The load factor the run (its JSON summary) last held; see the module documentation.
pub fn last_held_factor(run: &Value) -> Option<f64> {
    let steps = run["steps"].as_array().map_or(&[][..], Vec::as_slice);
    let Some(p) = driving_pattern(run) else {
        return (run["status"].as_str()? == "converged").then_some(1.0);
    };
    match run["status"].as_str()? {
        "converged" => steps.last()?["factors"][&p].as_f64(),
        "not_held" => run["not_held"]["last_held_factors"][&p].as_f64(),
        _ if steps.last()?["status"] == "converged" => steps.last()?["factors"][&p].as_f64(),
        _ => match steps.len().checked_sub(2) {
            Some(i) if steps[i]["status"] == "converged" => steps[i]["factors"][&p].as_f64(),
            Some(_) => None,
            None => Some(0.0),
        },
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;
    use serde_json::json;

    /// The pushed pattern drives the run, not the weight held constant; a not-held run reports
    /// the previous step's factor, a converged one its final factor.
    #[test]
    fn the_driving_pattern_s_factor_is_reported_per_status() {
        let steps = json!([
            {"factors": {"push": 0.0, "weight": 1.0}},
            {"factors": {"push": 0.3, "weight": 1.0}},
            {"factors": {"push": 0.5, "weight": 1.0}},
        ]);
        let not_held = json!({"status": "not_held", "steps": steps,
            "not_held": {"last_held_factors": {"push": 0.3, "weight": 1.0}}});
        assert_eq!(last_held_factor(&not_held), Some(0.3));
        let converged = json!({"status": "converged", "steps": steps});
        assert_eq!(last_held_factor(&converged), Some(0.5));
        let one_step = json!({"status": "converged", "steps": [{"factors": {"a": 0.25, "b": 1.0}}]});
        assert_eq!(last_held_factor(&one_step), Some(1.0));
        assert_eq!(last_held_factor(&json!({"status": "converged"})), Some(1.0));
        // A run stopped by another failure reports its last converged step (a lower bound).
        let stopped = json!({"status": "max_iterations", "steps": [
            {"factors": {"push": 0.2}, "status": "converged"},
            {"factors": {"push": 0.3}, "status": "max_iterations"},
        ]});
        assert_eq!(last_held_factor(&stopped), Some(0.2));
        let first = json!({"status": "numerical", "steps": [{"factors": {"push": 0.3}, "status": "numerical"}]});
        assert_eq!(last_held_factor(&first), Some(0.0));
        assert_eq!(last_held_factor(&json!({"status": "max_iterations"})), None);
    }
}
