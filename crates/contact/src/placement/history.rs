//! The slip history of a loading on the master contour, carried between meshes whose nodes
//! were moved (the zone ends are placed anew every step).

use crate::{ContactSolution, StepStart};

use super::{PlacedCase, pair_coordinates};

/// The slip history on the master contour: slips and tangential tractions as functions of the
/// master curve's coordinate c, carried from one step's mesh to the next.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ContourHistory {
    eta: Vec<f64>,
    slip: Vec<f64>,
    traction: Vec<f64>,
}

impl ContourHistory {
    /// The virgin state: no slip, no traction.
    pub fn virgin() -> ContourHistory {
        ContourHistory::default()
    }

    /// The state at the end of a solved step on `case`.
    pub fn after<C: PlacedCase>(case: &C, solution: &ContactSolution) -> ContourHistory {
        let eta = pair_coordinates(case);
        let mut order: Vec<usize> = (0..eta.len()).collect();
        order.sort_by(|a, b| eta[*a].total_cmp(&eta[*b]));
        let pairs = &case.problem().pairs;
        ContourHistory {
            eta: order.iter().map(|&k| eta[k]).collect(),
            slip: order.iter().map(|&k| solution.slip[k]).collect(),
            traction: order.iter().map(|&k| solution.tangential_force[k] / pairs[k].weight).collect(),
        }
    }

    /// The step start on `case`'s pairs: slips and tractions interpolated linearly in c, the
    /// tangential forces from the tractions times the new tributary lengths.
    pub fn start_for<C: PlacedCase>(&self, case: &C) -> StepStart {
        let m = case.problem().num_pairs();
        if self.eta.is_empty() {
            return StepStart::initial(m);
        }
        let eta = pair_coordinates(case);
        let pairs = &case.problem().pairs;
        StepStart {
            slip: eta.iter().map(|e| interpolate(&self.eta, &self.slip, *e)).collect(),
            tangential_force: (0..m)
                .map(|k| interpolate(&self.eta, &self.traction, eta[k]) * pairs[k].weight)
                .collect(),
        }
    }
}

/// Piecewise-linear interpolation of `y(x)` (x ascending), constant beyond the ends.
fn interpolate(x: &[f64], y: &[f64], at: f64) -> f64 {
    let i = x.partition_point(|v| *v < at);
    match i {
        0 => y[0],
        i if i >= x.len() => y[x.len() - 1],
        i => {
            let t = (at - x[i - 1]) / (x[i] - x[i - 1]);
            if t.is_finite() { y[i - 1] + t * (y[i] - y[i - 1]) } else { y[i] }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolation_is_linear_inside_and_constant_outside() {
        let (x, y) = ([0.0, 1.0, 2.0], [0.0, 2.0, 3.0]);
        assert_eq!(interpolate(&x, &y, 0.5), 1.0);
        assert_eq!(interpolate(&x, &y, 1.5), 2.5);
        assert_eq!(interpolate(&x, &y, -1.0), 0.0);
        assert_eq!(interpolate(&x, &y, 5.0), 3.0);
    }
}
