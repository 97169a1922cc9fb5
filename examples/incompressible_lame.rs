//! Volumetric locking on the Lamé cylinder in plane strain: standard elements against B-bar as
//! ν → ½ (the table of `docs/verification.md`, "Nearly incompressible materials").
//!
//! ```text
//! cargo run --release --example incompressible_lame [ν ...]     (default ν = 0.3 0.49 0.499 0.4999)
//! ```
//!
//! Prints, per element kind, formulation and ν, the relative L2 displacement error, the relative
//! L2 stress error and the inner-wall σ_rr and σ_θθ errors on the meshes of
//! `verify::lame::standard_levels`, with the observed rates of the finest pair.

use contact2d::element::{Formulation, PlaneCondition};
use contact2d::mesh::CellKind;
use contact2d::verify::lame::{LameSetup, lame_study, standard_levels};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<f64> = std::env::args().skip(1).map(|a| a.parse()).collect::<Result<_, _>>()?;
    let nus = if args.is_empty() { vec![0.3, 0.49, 0.499, 0.4999] } else { args };
    println!("| kind | formulation | ν | nr | L2(u) | L2(σ) | σ_rr(a) | σ_θθ(a) |");
    println!("|---|---|---|---|---|---|---|---|");
    for kind in [CellKind::Quad4, CellKind::Quad8, CellKind::Quad9, CellKind::Tri6] {
        for formulation in [Formulation::Standard, Formulation::BBar] {
            for &nu in &nus {
                let setup = LameSetup { poissons_ratio: nu, formulation, ..LameSetup::default() };
                let study = lame_study(kind, PlaneCondition::Strain, &standard_levels(kind), &setup)?;
                for l in &study.levels {
                    println!(
                        "| {kind:?} | {formulation:?} | {nu} | {} | {:.2e} | {:.2e} | {:.2e} | {:.2e} |",
                        l.n_radial,
                        l.norms.relative_l2(),
                        l.relative_stress_l2,
                        l.inner_radial_stress_error,
                        l.inner_hoop_stress_error
                    );
                }
                let last = |r: Vec<f64>| r.last().copied().unwrap_or(f64::NAN);
                println!(
                    "| {kind:?} | {formulation:?} | {nu} | rate | {:.2} | {:.2} | {:.2} | {:.2} |",
                    last(study.l2_rates()),
                    last(study.stress_l2_rates()),
                    last(study.wall_stress_rates()),
                    last(study.rates_of(|l| l.inner_hoop_stress_error))
                );
            }
        }
    }
    Ok(())
}
