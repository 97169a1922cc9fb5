//! Tests of the generic scene schema (`scene.rs`): parsing, overrides, schedules and the
//! errors that name their key.
#![allow(clippy::unwrap_used)]

use super::*;

const SCENE: &str = r#"
name = "t"
mesh = "m.msh"
[[body]]
region = "a"
youngs_modulus = 1.0
poissons_ratio = 0.3
[[body]]
region = "b"
youngs_modulus = 2.0
poissons_ratio = 0.3
[[fix]]
group = "bottom"
u1 = 0.0
u2 = 0.0
[[fix]]
group = "top"
u1 = 0.1
pattern = "slide"
[[load]]
group = "top"
pressure = 1.0
pattern = "press"
[[contact]]
name = "joint"
master = "b_bottom"
slave = "a_top"
[loading]
schedule = [{ press = 1.0 }, { press = 1.0, slide = 1.0 }]
"#;

#[test]
fn parses_patterns_schedule_and_overrides_by_index_and_name() {
    let path = Path::new("scenes/t.toml");
    let s = GenericScene::from_toml_str(SCENE, path, &["contact.joint.friction=0.3".into()]).unwrap();
    assert_eq!(s.contact[0].friction, 0.3);
    let s = GenericScene::from_toml_str(SCENE, path, &["contact.0.friction=0.2".into(), "body.b.thickness=2".into()])
        .unwrap();
    assert_eq!(s.contact[0].friction, 0.2);
    assert_eq!(s.body[1].thickness, Some(2.0));
    assert_eq!(s.pattern_names(), ["slide", "press"]);
    let schedule = s.schedule().unwrap();
    assert_eq!(schedule.steps(), &[vec![0.0, 1.0], vec![1.0, 1.0]]);
}

#[test]
fn bad_values_name_their_key() {
    let path = Path::new("scenes/t.toml");
    let err = |o: &str| GenericScene::from_toml_str(SCENE, path, &[o.into()]).unwrap_err().to_string();
    assert!(err("contact.0.friction=-1").contains("contact.0.friction"));
    assert!(err("body.a.poissons_ratio=0.5").contains("body.0.poissons_ratio"));
    assert!(err("contact.7.friction=0").contains("past its end"));
    assert!(err("contact.nope.friction=0").contains("nope"));
    // A file giving both is an error; a `--set` of one replaces the other (the user guide).
    let both = SCENE.replace("[loading]", "[loading]\nsteps = 3");
    assert!(GenericScene::from_toml_str(&both, path, &[]).unwrap_err().to_string().contains("not both"));
    let stepped = GenericScene::from_toml_str(SCENE, path, &["loading.steps=3".into()]).unwrap();
    assert_eq!(stepped.schedule().unwrap().steps().len(), 3);
    let text = SCENE.replace("pressure = 1.0", "pressure = 1.0\nforce = [1.0, 0.0]");
    assert!(GenericScene::from_toml_str(&text, path, &[]).unwrap_err().to_string().contains("exactly one"));
    let text = SCENE.replace("group = \"top\"\npressure = 1.0", "group = \"top\"\nbody_force = [0.0, -1.0]");
    assert!(GenericScene::from_toml_str(&text, path, &[]).unwrap_err().to_string().contains("no [[body]] region"));
    let text = SCENE.replace("group = \"top\"\npressure = 1.0", "group = \"b\"\nbody_force = [0.0, -1.0]");
    assert!(GenericScene::from_toml_str(&text, path, &[]).is_ok());
    let text = SCENE.replace("{ press = 1.0 }, ", "{ pres = 1.0 }, ");
    assert!(GenericScene::from_toml_str(&text, path, &[]).unwrap_err().to_string().contains("pres"));
    let text = format!("{SCENE}\nbogus = 1\n");
    assert!(GenericScene::from_toml_str(&text, path, &[]).unwrap_err().to_string().contains("bogus"));
}

/// The scene with `overrides`, or the error's text.
fn with(overrides: &[&str]) -> Result<GenericScene, String> {
    let overrides: Vec<String> = overrides.iter().map(ToString::to_string).collect();
    GenericScene::from_toml_str(SCENE, Path::new("scenes/t.toml"), &overrides).map_err(|e| e.to_string())
}

#[test]
fn a_cycle_runs_after_the_preload_as_many_times_as_cycles_says() {
    let scene = with(&["loading.cycle=[{press=1.0,slide=1.0},{press=1.0,slide=-1.0}]", "loading.cycles=3"]).unwrap();
    let schedule = scene.schedule().unwrap();
    // 2 preload steps, then 3 × 2 cycle steps.
    assert_eq!(schedule.steps().len(), 2 + 6);
    let at = schedule.patterns().iter().position(|p| p == "slide").unwrap();
    let slide: Vec<f64> = schedule.steps().iter().map(|s| s[at]).collect();
    assert_eq!(slide, [0.0, 1.0, 1.0, -1.0, 1.0, -1.0, 1.0, -1.0]);
    assert_eq!(scene.last_cycle(), Some(6..8));
    // Without `cycles`: one cycle.
    let once = with(&["loading.cycle=[{press=1.0,slide=1.0}]"]).unwrap();
    assert_eq!(once.schedule().unwrap().steps().len(), 3);
    assert_eq!(with(&[]).unwrap().last_cycle(), None);
}

#[test]
fn bad_cycles_are_errors_naming_the_key() {
    let cases: [(&[&str], &str); 5] = [
        (&["loading.cycles=2"], "loading.cycles: no loading.cycle"),
        (&["loading.cycle=[{slide=1.0}]", "loading.cycles=0"], "loading.cycles: 0 cycles"),
        (&["loading.cycle=[]", "loading.cycles=2"], "loading.cycle: an empty cycle"),
        (&["loading.cycle=[{slide=1.0},{slide=-1.0}]", "loading.cycles=5000"], "exceed 10000 steps"),
        (&["loading.cycle=[{slide=1.0},{twist=1.0}]"], "loading.cycle[1]: \"twist\" is no load pattern"),
    ];
    for (overrides, expected) in cases {
        let err = with(overrides).unwrap_err();
        assert!(err.contains(expected), "{overrides:?}: {err}");
    }
    // A count that overflows the step count is the same error, not a panic.
    let err = with(&["loading.cycle=[{slide=1.0},{slide=-1.0}]", "loading.cycles=9223372036854775807"]).unwrap_err();
    assert!(err.contains("loading.cycles"), "{err}");
}

#[test]
fn staged_supports_out_of_the_schedule_name_their_key() {
    let path = Path::new("scenes/t.toml");
    let err = |o: &[&str]| {
        let o: Vec<String> = o.iter().map(|s| s.to_string()).collect();
        GenericScene::from_toml_str(SCENE, path, &o).unwrap_err().to_string()
    };
    let past = err(&["fix.1.from_step=3"]);
    assert!(past.contains("fix.1.from_step") && past.contains("past the last step"), "{past}");
    let past = err(&["fix.0.until_step=3"]);
    assert!(past.contains("fix.0.until_step") && past.contains("past the last step"), "{past}");
    let after = err(&["fix.1.from_step=2", "fix.1.until_step=1"]);
    assert!(after.contains("fix.1.from_step") && after.contains("after until_step"), "{after}");
    assert!(err(&["fix.0.from_step=0"]).contains("fix.0.from_step"));
    let finite = err(&["fix.1.from_step=2", "contact.0.sliding=finite"]);
    assert!(finite.contains("fix.1.from_step") && finite.contains("finite"), "{finite}");
    let boussinesq = err(&["fix.0.until_step=1", "solver.algorithm=boussinesq"]);
    assert!(boussinesq.contains("fix.0.until_step") && boussinesq.contains("boussinesq"), "{boussinesq}");
    // A rotation's values are node values that hold in every step: staging one is refused.
    let turned = err(&["fix.1.rotation=0.001", "fix.1.about=[0.0, 0.0]", "fix.1.from_step=2"]);
    assert!(turned.contains("fix.1.from_step") && turned.contains("every step"), "{turned}");
}

#[test]
fn stages_are_the_runs_of_steps_with_the_same_fixes() {
    let path = Path::new("scenes/t.toml");
    let s = GenericScene::from_toml_str(SCENE, path, &[]).unwrap();
    // No staged fix: one stage, every fix (three components) active.
    assert_eq!(s.fix_stages().unwrap(), vec![(0..2, vec![true, true, true])]);
    let s = GenericScene::from_toml_str(SCENE, path, &["fix.1.from_step=2".into()]).unwrap();
    assert_eq!(s.fix_stages().unwrap(), vec![(0..1, vec![true, true, false]), (1..2, vec![true, true, true])]);
}

#[test]
fn the_kinematics_key_and_what_it_refuses() {
    let path = Path::new("scenes/t.toml");
    let parse = |sets: &[&str]| {
        let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
        GenericScene::from_toml_str(SCENE, path, &sets)
    };
    let key_of = |sets: &[&str]| match parse(sets) {
        Err(SceneError::Value { key, .. }) => key,
        other => format!("not a value error: {other:?}"),
    };
    let s = parse(&["kinematics=axisymmetric"]).unwrap();
    assert!(s.is_axisymmetric());
    assert_eq!(s.body_kinematics(&s.body[0]), contact2d_element::Kinematics::Axisymmetric);
    let strain = parse(&["kinematics=plane_strain", "body.b.thickness=2"]).unwrap();
    assert_eq!(strain.body_kinematics(&strain.body[1]), contact2d_element::Kinematics::PlaneStrain { thickness: 2.0 });
    assert_eq!(key_of(&["kinematics=axisymmetric", "body.a.thickness=2"]), "body.0.thickness");
    assert_eq!(key_of(&["kinematics=axisymmetric", "plane=strain"]), "plane");
    assert_eq!(key_of(&["kinematics=axisymmetric", "body.b.plane=stress"]), "body.1.plane");
    assert_eq!(key_of(&["kinematics=plane_strain", "plane=stress"]), "plane");
    assert_eq!(key_of(&["body.a.thickness=-1"]), "body.0.thickness");
    assert!(parse(&["kinematics=spherical"]).is_err(), "an unknown kinematics is refused");
}
