//! The comparison's tables: compare.md (printed), compare.csv, compare_reference.csv and
//! compare.json.
//!
//! ```text
//! compare.md              the references (quantity, kind, value, from, how), then one row per
//!                         combination with its "error q" columns — on one mesh, where the
//!                         reference is another method, "q: difference from X"
//! compare.csv             one row per combination; per quantity its value `q` and
//!                         `error_q` (one mesh: `difference_q`), see deviation_column
//! compare_reference.csv   one row per quantity: quantity, kind, from, value, how, deviation
//! compare.json            {"reference": {q: {quantity, kind, from, value, how, deviation}},
//!                          "rows": [...]}
//! ```

use serde_json::{Value, json};

use super::{CompareRow, Comparison, Deviation, Reference};

/// The column of a quantity's deviation from its reference: `error_<q>`, or `difference_<q>`
/// when the reference is another method on the same (only) mesh (not an error).
pub fn deviation_column(quantity: &str, reference: &Reference) -> String {
    format!("{}_{quantity}", reference.deviation.key())
}

/// The method of a reference taken from the runs (`from` without its meshes).
fn method(reference: &Reference) -> &str {
    reference.from.split(" on ").next().unwrap_or(&reference.from)
}

/// compare.md: the references, then the rows.
pub fn markdown(c: &Comparison) -> String {
    let mut s = String::from("References:\n\n| quantity | kind | reference | from | how |\n|---|---|---|---|---|\n");
    for (q, r) in &c.references {
        s += &format!("| {q} | {} | {:.6e} | {} | {} |\n", r.kind.key(), r.value, r.from, r.how);
    }
    let differences: Vec<String> = c
        .references
        .iter()
        .filter(|(_, r)| r.deviation == Deviation::Difference)
        .map(|(q, r)| format!("{q}: {}", r.from))
        .collect();
    if !differences.is_empty() {
        s += &format!(
            "\nOne mesh: the \"difference from\" columns are relative differences from the most accurate method that ran, not errors ({}).\n",
            differences.join("; ")
        );
    }
    s += "\n| algorithm | pairing | mesh | pairs | status | time s | solve s | iterations | penetration | complementarity |";
    for (q, r) in &c.references {
        s += &match r.deviation {
            Deviation::Error => format!(" error {q} |"),
            Deviation::Difference => format!(" {q}: difference from {} |", method(r)),
        };
    }
    s += "\n|---|---|---|---|---|---|---|---|---|---|";
    s += &"---|".repeat(c.references.len());
    s += "\n";
    for r in &c.rows {
        if r.status == "skipped" || r.status == "timed_out" {
            let reason = r.reason.as_deref().unwrap_or("").replace('|', "/");
            s += &format!("| {} | {} | {} | | {}: {reason} |", r.algorithm, r.pairing, r.mesh, r.status);
            s += &" |".repeat(5 + c.references.len());
            s += "\n";
            continue;
        }
        s += &format!(
            "| {} | {} | {} | {} | {} | {:.3} | {:.3} | {} | {:.1e} | {:.1e} |",
            r.algorithm, r.pairing, r.mesh, r.pairs, r.status, r.time, r.solve_time, r.iterations, r.kkt[0], r.kkt[1]
        );
        for q in c.references.keys() {
            s += &r.errors.get(q).map_or(" — |".into(), |e| format!(" {e:.2e} |"));
        }
        s += "\n";
    }
    s
}

/// compare.csv: one row per combination (module docs).
pub fn csv(c: &Comparison) -> String {
    let mut s = String::from(
        "algorithm,pairing,level,mesh,pairs,status,reason,time_s,solve_time_s,iterations,max_penetration,max_complementarity,max_cone_violation",
    );
    for (q, r) in &c.references {
        s += &format!(",{q},{}", deviation_column(q, r));
    }
    s += "\n";
    let quote = |t: &str| format!("\"{}\"", t.replace('"', "\"\""));
    for r in &c.rows {
        s += &format!(
            "{},{},{},{},{},{},{},{},{},{},{},{},{}",
            r.algorithm,
            r.pairing,
            r.level,
            quote(&r.mesh),
            r.pairs,
            r.status,
            quote(r.reason.as_deref().unwrap_or("")),
            r.time,
            r.solve_time,
            r.iterations,
            r.kkt[0],
            r.kkt[1],
            r.kkt[2]
        );
        for q in c.references.keys() {
            let v = r.values.get(q).map_or(String::new(), |v| v.to_string());
            let e = r.errors.get(q).map_or(String::new(), |v| v.to_string());
            s += &format!(",{v},{e}");
        }
        s += "\n";
    }
    s
}

/// A number for JSON (`null` when not finite).
fn number(v: f64) -> Value {
    if v.is_finite() { json!(v) } else { Value::Null }
}

/// compare_reference.csv: one row per quantity (quantity, kind, from, value, how, deviation).
pub fn reference_csv(c: &Comparison) -> String {
    let quote = |t: &str| format!("\"{}\"", t.replace('"', "\"\""));
    let mut s = String::from("quantity,kind,from,value,how,deviation\n");
    for r in c.references.values() {
        s += &format!(
            "{},{},{},{},{},{}\n",
            quote(&r.quantity),
            r.kind.key(),
            quote(&r.from),
            r.value,
            quote(&r.how),
            r.deviation.key()
        );
    }
    s
}

/// A reference as compare.json's `reference` object.
pub fn reference_json(r: &Reference) -> Value {
    json!({
        "quantity": r.quantity, "kind": r.kind.key(), "from": r.from, "value": number(r.value),
        "how": r.how, "deviation": r.deviation.key(),
    })
}

/// compare.json: `reference` (per quantity: quantity, kind, from, value, how, deviation) and the
/// rows with their values and deviations.
pub fn json(c: &Comparison) -> String {
    let references: serde_json::Map<String, Value> =
        c.references.iter().map(|(q, r)| (q.clone(), reference_json(r))).collect();
    let rows: Vec<Value> = c.rows.iter().map(|r| row_json(c, r)).collect();
    let doc = json!({"reference": references, "rows": rows});
    serde_json::to_string_pretty(&doc).unwrap_or_default() + "\n"
}

fn row_json(c: &Comparison, r: &CompareRow) -> Value {
    let mut row = json!({
        "algorithm": r.algorithm, "pairing": r.pairing, "level": r.level, "mesh": r.mesh,
        "status": r.status, "reason": r.reason, "pairs": r.pairs, "time_s": number(r.time),
        "solve_time_s": number(r.solve_time), "iterations": r.iterations,
        "max_penetration": number(r.kkt[0]), "max_complementarity": number(r.kkt[1]),
        "max_cone_violation": number(r.kkt[2]),
    });
    if let Value::Object(map) = &mut row {
        for (q, reference) in &c.references {
            map.insert(q.clone(), r.values.get(q).map_or(Value::Null, |v| number(*v)));
            map.insert(deviation_column(q, reference), r.errors.get(q).map_or(Value::Null, |v| number(*v)));
        }
    }
    row
}
