//! Interference fit (Lamé): a solid disk of radius a = 500 mm shrunk into a ring of outer radius
//! b = 1000 mm of the same material, E = 2e5 MPa, ν = 0.3, plane stress, radial interference
//! δ = 0.6667 mm given as a negative gap (`scenes/generic/interference_fit.toml`, quarter model).
//!
//! ```text
//!   y │‾‾‾‾╲ ring (a ≤ r ≤ b)        closed form (thick-walled cylinders, e.g. Timoshenko &
//!     │disk ╲  ╲                      Goodier §30):  p = E δ (b² − a²) / (2 a b²) = 100 MPa
//!     │______|__|__ x                 ring bore hoop stress  σθθ = p (b² + a²)/(b² − a²)
//!   u1 = 0 on x = 0, u2 = 0 on y = 0   disk: σ11 = σ22 = −p everywhere
//! ```
//!
//! Tolerance 0.5 % (the issue's target). The disk's uniform stress is reproduced by any mesh;
//! the ring's field varies as 1/r², which Quad9 on 12 radial cells resolves to about 1e-4 at
//! the bore, and the pairs are node-to-node (coincident arcs), so the pressure is uniform to the
//! arcs' parabolic approximation (~1e-4).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::fem::{StressRecovery, nodal_stresses};
use contact2d::generic::{load_scene, solve_generic};

#[test]
fn shrink_fit_pressure_and_stresses_match_lame() {
    let (a, b, e, delta) = (500.0f64, 1000.0f64, 2e5f64, 0.6667f64);
    let p = e * delta * (b * b - a * a) / (2.0 * a * b * b);
    let hoop = p * (b * b + a * a) / (b * b - a * a);
    let scene = load_scene(Path::new("scenes/generic/interference_fit.toml"), &[]).unwrap();
    let out = solve_generic(&scene, &mut |_, _| {}).unwrap();
    assert_eq!(out.report.status, "converged");
    let fit = &out.report.contacts["fit"];
    let profile = fit.profile.as_ref().unwrap();
    assert!(profile.state.iter().all(|s| *s == "contact"), "every pair in contact");
    for (s, pressure) in profile.s.iter().zip(&profile.pressure) {
        assert!((pressure / p - 1.0).abs() < 0.005, "pressure {pressure} at s = {s} against {p}");
    }
    let model = &out.built.problem.model;
    let u = &out.history.steps.last().unwrap().solution.displacement;
    let (ring, _) = model.body("ring").unwrap();
    let (disk, _) = model.body("disk").unwrap();
    let ring_stress = nodal_stresses(model, ring, u, StressRecovery::Extrapolated).unwrap();
    for node in model.mesh.group_nodes("ring_bore").unwrap() {
        let [x, y] = model.mesh.points[node.0];
        let (sin, cos) = (y.atan2(x).sin(), y.atan2(x).cos());
        let s = ring_stress[node.0].unwrap();
        let hoop_h = s[0] * sin * sin + s[1] * cos * cos - 2.0 * s[2] * sin * cos;
        assert!((hoop_h / hoop - 1.0).abs() < 0.005, "ring hoop {hoop_h} at ({x}, {y}) against {hoop}");
    }
    let disk_stress = nodal_stresses(model, disk, u, StressRecovery::Extrapolated).unwrap();
    for s in disk_stress.iter().flatten() {
        assert!((s[0] / -p - 1.0).abs() < 0.005 && (s[1] / -p - 1.0).abs() < 0.005, "disk stress {s:?} against −{p}");
        assert!(s[2].abs() < 0.005 * p);
    }
}
