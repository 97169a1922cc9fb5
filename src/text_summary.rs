//! The text summary `run` prints: every scene's, with a preset's lines (the paper's quantities
//! for a plate-insert scene) after the method line.

use std::io::Write;

/// The first line of a run's text report.
fn heading(
    out: &mut impl Write,
    scene: &str,
    (dofs, pairs): (usize, usize),
    algorithm: &str,
    status: &str,
    (iterations, steps): (usize, usize),
) -> std::io::Result<()> {
    writeln!(
        out,
        "scene {scene}  ({dofs} DOFs, {pairs} pairs, {algorithm}, {status} after {iterations} iterations in {steps} step(s))"
    )
}

/// A run's text report (`preset_lines`: a preset's quantities, e.g. the paper's).
pub(crate) fn print_summary(
    out: &mut impl Write,
    r: &contact2d::generic::GenericReport,
    preset_lines: &[String],
) -> std::io::Result<()> {
    heading(out, &r.scene, (r.dofs, r.pairs), &format!("{:?}", r.algorithm), r.status, (r.iterations, r.steps.len()))?;
    // Every choice the run made on its own: a refinement study must not mix them unknowingly.
    writeln!(out, "  {}", contact2d::generic::readme::method_line(r))?;
    if let Some(e) = r.path_error {
        let steps = r.steps_taken.map_or_else(String::new, |n| format!(", adaptive stepping: {n} steps"));
        writeln!(out, "  path error (the step size's, from halving every step): {:.3} %{steps}", 100.0 * e)?;
    }
    for line in preset_lines {
        writeln!(out, "{line}")?;
    }
    for (name, c) in &r.contacts {
        writeln!(
            out,
            "  contact {name}: normal force {:.6e}, tangential force {:.6e}, contact length {:.6e}, stick length {:.6e}, \
             max pressure {:.6e}, dissipation {:.3e}",
            c.normal_force, c.tangential_force, c.contact_length, c.stick_length, c.max_pressure, c.dissipation
        )?;
        let [f1, f2] = c.resultant;
        writeln!(out, "  contact {name}: resultant on the slave side [{f1:.6e}, {f2:.6e}], moment {:.6e}", c.moment)?;
        if let Some(p) = c.mean_pressure {
            writeln!(out, "  contact {name}: mean pressure (normal force / contact length) {p:.6e}")?;
        }
        let where_ = |z: &contact2d::generic::zones::ZoneEnds| match &z.angles_deg {
            // + 0.0: an angle of −1e-15° prints as 0.0°, not −0.0°.
            Some(a) => a
                .chunks(2)
                .map(|e| format!("{:.1}° to {:.1}°", (e[0] * 10.0).round() / 10.0 + 0.0, e.get(1).unwrap_or(&e[0])))
                .collect::<Vec<_>>(),
            None => z.points.chunks(2).map(|e| format!("{:?} to {:?}", e[0], e.get(1).unwrap_or(&e[0]))).collect(),
        };
        if c.zones.all_round {
            writeln!(out, "  contact {name}: in contact all round")?;
        } else {
            writeln!(out, "  contact {name}: in contact {}", where_(&c.zones).join(", "))?;
        }
        if c.stick_zones.all_round {
            writeln!(out, "  contact {name}: sticking all round")?;
        } else if !c.stick_zones.s.is_empty() {
            writeln!(out, "  contact {name}: sticking {}", where_(&c.stick_zones).join(", "))?;
        }
        if let (Some([f1, f2]), Some(m)) = (c.rigid_resultant, c.rigid_moment) {
            writeln!(out, "  contact {name}: rigid obstacle's resultant [{f1:.6e}, {f2:.6e}], moment {m:.6e}")?;
        }
        if let Some(f) = c.fretting.as_deref() {
            print_fretting(out, name, f)?;
        }
    }
    // A component the group's own fixes do not prescribe is "none" (JSON null).
    let component = |f: Option<f64>| f.map_or_else(|| "none".to_string(), |v| format!("{v:.6e}"));
    for (group, f) in &r.reactions {
        let moment = r.reaction_moments.get(group).map_or_else(String::new, |m| format!(", moment {m:.6e}"));
        writeln!(out, "  reaction {group}: [{}, {}]{moment}", component(f[0]), component(f[1]))?;
    }
    let [t1, t2] = r.reactions_total;
    writeln!(
        out,
        "  reactions total (every constrained DOF once): [{t1:.6e}, {t2:.6e}], moment {:.6e}",
        r.reaction_moment_total
    )?;
    let [cx, cy] = r.moment_centre;
    writeln!(out, "  moments about ({cx}, {cy}), counter-clockwise positive")?;
    for (name, p) in &r.points {
        let [u1, u2] = p.displacement;
        let [f1, f2] = p.reaction;
        let turned = p.rotation.map_or_else(String::new, |t| format!(", rotation {t:.6e}"));
        let moment = p.reaction_moment.map_or_else(String::new, |m| format!(", reaction moment {m:.6e}"));
        writeln!(
            out,
            "  point {name}: displacement [{u1:.6e}, {u2:.6e}]{turned}, reaction [{f1:.6e}, {f2:.6e}]{moment}"
        )?;
    }
    for (body, e) in &r.energies {
        writeln!(out, "  energy {body}: {e:.6e}")?;
    }
    for f in &r.floating_bodies {
        writeln!(out, "  body {} held by contact only (free: {})", f.body, f.free_modes.join(", "))?;
    }
    let k = &r.kkt;
    writeln!(
        out,
        "  KKT: penetration {:.1e}, complementarity {:.1e}, cone {:.1e}, floating residual {:.1e}",
        k.max_penetration, k.max_complementarity, k.max_cone_violation, k.floating_residual
    )?;
    let t = &r.time_s;
    writeln!(
        out,
        "  time {:.3} s (read {:.3}, assemble {:.3}, factor {:.3}, condense {:.3}, solve {:.3}, post {:.3})",
        t.total, t.read, t.assemble, t.factor, t.condense, t.solve, t.post
    )?;
    for note in &r.notes {
        writeln!(out, "  note: {note}")?;
    }
    Ok(())
}

/// A contact's fretting numbers over the last load cycle, in one line: the energy dissipated,
/// the largest slip amplitude and the Ruiz parameter's maximum, each with where it lies.
fn print_fretting(
    out: &mut dyn std::io::Write,
    name: &str,
    f: &contact2d::generic::fretting::Fretting,
) -> std::io::Result<()> {
    let [first, last] = f.steps;
    let amplitude =
        f.slip_amplitude.iter().zip(&f.s).fold((0.0f64, f64::NAN), |m, (a, s)| if *a > m.0 { (*a, *s) } else { m });
    let [ruiz, at, ..] = f.ruiz_max;
    writeln!(
        out,
        "  contact {name}: last cycle (steps {first}–{last}): dissipated {:.6e}, slip amplitude up to {:.6e} at s = {:.4e}, Ruiz parameter up to {ruiz:.6e} at s = {at:.4e}",
        f.dissipated, amplitude.0, amplitude.1
    )
}
