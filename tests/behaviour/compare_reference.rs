//! `contact2d compare`'s references (issue 44 item 9) against independent truths: the reference
//! is named, comes from the most accurate method that ran (not the first), and lands on the
//! closed form where one exists.

use contact2d::compare::{CompareArgs, Deviation, ReferenceKind, compare};

/// The interference fit (`scenes/generic/interference_fit.toml`): a disk a = 500 mm pressed
/// into a ring b = 1000 mm, E = 2e5 MPa, radial interference δ = 0.6667 mm. Lamé (Timoshenko &
/// Goodier §30): p = E δ (b² − a²) / (2 a b²).
const FIT: &str = "scenes/generic/interference_fit.toml";
const P_LAME: f64 = 2e5 * 0.6667 * (1000.0 * 1000.0 - 500.0 * 500.0) / (2.0 * 500.0 * 1000.0 * 1000.0);

#[test]
fn one_mesh_is_a_difference_from_the_most_accurate_method_which_lands_on_lame() {
    // 5 algorithms × 3 pairings on the scene's one mesh, 0.03 s each.
    let args = CompareArgs {
        scene: FIT.into(),
        meshes: vec![],
        repeat: 1,
        references: vec![],
        sets: vec![],
        out: std::env::temp_dir().join("contact2d-compare-reference-unused"),
        time_limit: 60.0,
    };
    let comparison = compare(&args, &mut |_, _, _| {}).unwrap();
    let r = &comparison.references["contacts.fit.max_pressure"];
    // The first combination to run is active_set × node_to_segment; the reference is the
    // segment-to-segment one (reference.rs's order), named, and a difference, not an error.
    assert_eq!(comparison.rows[0].pairing, "node_to_segment");
    assert_eq!(
        (r.kind, r.deviation, r.from.as_str()),
        (ReferenceKind::Finest, Deviation::Difference, "active_set × segment_to_segment on (scene)")
    );
    // verify's tolerance for this case (0.5 %, tests/verification: the Lamé pressure on this
    // mesh) bounds the reference's distance from the closed form.
    assert!((r.value - P_LAME).abs() / P_LAME < 5e-3, "reference {} against Lamé {P_LAME}", r.value);
    // The tables say so: the column is a difference from the method, not an error.
    let md = contact2d::compare::markdown(&comparison);
    assert!(md.contains("contacts.fit.max_pressure: difference from active_set × segment_to_segment"), "{md}");
    assert!(!md.contains("error contacts.fit.max_pressure"), "{md}");
    let json: serde_json::Value = serde_json::from_str(&contact2d::compare::json(&comparison)).unwrap();
    let j = &json["reference"]["contacts.fit.max_pressure"];
    assert_eq!((j["kind"].as_str(), j["deviation"].as_str()), (Some("finest"), Some("difference")));
    assert_eq!(j["value"].as_f64(), Some(r.value));
    assert!(
        contact2d::compare::csv(&comparison).lines().next().unwrap().contains(",difference_contacts.fit.max_pressure")
    );
    // With the closed form given, the same rows are errors against it.
    let args = CompareArgs { references: vec![format!("contacts.fit.max_pressure={P_LAME}")], ..args };
    let comparison = compare(&args, &mut |_, _, _| {}).unwrap();
    let r = &comparison.references["contacts.fit.max_pressure"];
    assert_eq!((r.kind, r.deviation, r.value), (ReferenceKind::ClosedForm, Deviation::Error, P_LAME));
}
