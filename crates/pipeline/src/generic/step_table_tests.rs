//! Tests of the step table (`step_table.rs`): rows in and out against a `Vec<StepResult>`.
#![allow(clippy::unwrap_used)]

use super::*;

fn names(list: &[&str]) -> Vec<Arc<str>> {
    list.iter().map(|n| Arc::from(*n)).collect()
}

fn contact(k: f64, rich: bool) -> ContactResult {
    let zones = |n: usize| ZoneEnds {
        s: (0..n).map(|i| k + i as f64 / 3.0).collect(),
        points: (0..n).map(|i| [k * 0.1 + i as f64, -k]).collect(),
        angles_deg: rich.then(|| (0..n).map(|i| -179.5 + i as f64).collect()),
        all_round: rich && n == 0,
    };
    ContactResult {
        normal_force: k * 1.1,
        tangential_force: -0.0,
        contact_length: 1.0 / 3.0,
        stick_length: f64::MIN_POSITIVE,
        mean_pressure: rich.then_some(k / 7.0),
        max_pressure: 1e300,
        dissipation: k * 1e-17,
        resultant: [k, -k],
        rigid_resultant: rich.then_some([2.0, 3.0]),
        moment: -k / 9.0,
        rigid_moment: rich.then_some(0.25),
        couple: (!rich).then_some(1e-12),
        closed: rich,
        zones: zones(if rich { 4 } else { 2 }),
        stick_zones: zones(if rich { 0 } else { 2 }),
        profile: rich.then(|| {
            Box::new(Profile {
                s: vec![0.0, 1.0],
                x: vec![1.0, 2.0],
                y: vec![0.5, 0.5],
                pressure: vec![3.0, 0.0],
                shear: vec![0.1, 0.0],
                gap: vec![0.0, 1e-3],
                slip: vec![0.0, 0.0],
                state: vec!["stick", "free"],
            })
        }),
        fretting: None,
    }
}

/// A row of every kind of content: options present and absent, zones of 0, 2 and 4 ends,
/// counts above 127 (two bytes), `-0.0`, subnormal and extreme numbers, rare parts.
pub(in crate::generic) fn row(i: usize) -> StepResult {
    let x = i as f64 + 0.1;
    let rich = i % 3 == 1;
    let shared = |list: &[&str], f: &dyn Fn(usize) -> f64| {
        NamedMap::from_sorted(names(list).into_iter().enumerate().map(|(k, n)| (n, f(k))).collect())
    };
    StepResult {
        factors: shared(&["press", "slide"], &|k| x * k as f64),
        status: if rich { "not_held" } else { "converged" },
        failed_check: rich.then(|| format!("step {i}: a check")),
        iterations: 100 * i,
        repairings: rich.then_some(i),
        substeps: (i % 2 == 0).then_some(3),
        contacts: [("a", contact(x, rich)), ("b", contact(-x, false))].into_iter().collect(),
        reactions: [("base", [Some(x), None]), ("top", [None, Some(-x)])].into_iter().collect(),
        reactions_total: [x, 5e-324],
        reaction_moments: shared(&["base", "top"], &|k| -x * k as f64),
        reaction_moment_total: -x,
        energies: shared(&["lower", "upper"], &|k| x + k as f64),
        points: if rich {
            [(
                "p",
                PointResult {
                    displacement: [x, 0.0],
                    rotation: Some(0.5),
                    reaction: [1.0, 2.0],
                    reaction_moment: None,
                },
            )]
            .into_iter()
            .collect()
        } else {
            NamedMap::default()
        },
        work: x * x,
        dissipated: f64::MAX,
        kkt: Kkt {
            max_penetration: 1e-9,
            max_complementarity: 0.0,
            max_cone_violation: -0.0,
            min_dissipation: -x,
            max_slip_inside_cone: 0.5,
            floating_residual: 1e-20,
            floating_iterations: 200 + i,
        },
        energy_allowance: EnergyAllowance { trapezoid: x, round_off: x * f64::EPSILON },
        not_held: rich.then(|| {
            Box::new(NotHeldResult {
                contact: "a".into(),
                body: "upper".into(),
                step: i + 1,
                last_held_factors: [("press".to_string(), 1.0)].into_iter().collect(),
                ratio: 1.5,
                demanded: 3.0,
                available: 2.0,
            })
        }),
        path_error: (i % 4 != 0).then_some(x / 1e3),
    }
}

/// The truth is the rows themselves (a `Vec<StepResult>`, what the report held before): each
/// row read back equal field by field, every `f64` bit for bit (`{:?}` tells `-0.0` from
/// `0.0`), and the table's JSON text the `Vec`'s.
#[test]
fn a_row_in_is_the_same_row_out_and_serialises_as_a_vec() {
    let rows: Vec<StepResult> = (0..300).map(row).collect();
    let table: StepTable = rows.iter().cloned().collect();
    assert_eq!(table.len(), rows.len());
    for (i, truth) in rows.iter().enumerate() {
        let got = table.get(i).unwrap();
        assert_eq!(got, *truth, "row {i}");
        assert_eq!(format!("{got:?}"), format!("{truth:?}"), "row {i}, bit for bit");
    }
    assert_eq!(table.get(rows.len()), None);
    assert_eq!(table.last().as_ref(), rows.last());
    assert_eq!(serde_json::to_string_pretty(&table).unwrap(), serde_json::to_string_pretty(&rows).unwrap());
    assert_eq!(table.to_vec(), rows);
    assert_eq!(table.first_not_held().as_ref(), rows.iter().find_map(|r| r.not_held.as_deref()));
    let empty = StepTable::new();
    assert!(empty.is_empty() && empty.last().is_none());
    assert_eq!(serde_json::to_string(&empty).unwrap(), "[]");
}

/// Changing a row in the table is changing it in the `Vec`: the last row in place, another
/// one, and every row's `path_error`.
#[test]
fn rows_change_as_in_a_vec() {
    let mut rows: Vec<StepResult> = (0..20).map(row).collect();
    let mut table = StepTable::from(rows.clone());
    let change = |r: &mut StepResult| {
        r.contacts.values_mut().for_each(|c| c.zones = ZoneEnds::default());
        r.substeps = Some(7);
    };
    for i in [19, 4] {
        change(&mut rows[i]);
        table.modify(i, change);
    }
    for (i, r) in rows.iter_mut().enumerate() {
        r.path_error = Some(i as f64);
        table.set_path_error(i, Some(i as f64));
    }
    table.update(|i, r| r.iterations = i);
    rows.iter_mut().enumerate().for_each(|(i, r)| r.iterations = i);
    assert_eq!(table.to_vec(), rows);
}
