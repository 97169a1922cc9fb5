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
    assert_eq!(s.body[1].thickness, 2.0);
    assert_eq!(s.pattern_names(), ["slide", "press"]);
    let schedule = s.schedule().unwrap();
    assert_eq!(schedule.steps(), &[vec![0.0, 1.0], vec![1.0, 1.0]]);
    assert!(is_generic(SCENE));
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
