//! Scene values out of range and contradictory combinations are errors naming the scene file and
//! the key; a scene file's own syntax and type errors name the line.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::plate_insert::PlateInsertScene;
use contact2d::scene::SceneError;

const SCENE: &str = r#"
name = "t"
[plate_insert]
mesh = "m.msh"
variant = "hole_master"
load = 1.0
[solver]
algorithm = "active_set"
"#;

fn check(overrides: &[&str]) -> Result<PlateInsertScene, SceneError> {
    let overrides: Vec<String> = overrides.iter().map(|s| (*s).to_string()).collect();
    PlateInsertScene::from_toml_str(SCENE, Path::new("dir/s.toml"), &overrides)
}

fn key_of(r: Result<PlateInsertScene, SceneError>) -> String {
    match r {
        Err(SceneError::Value { key, path, .. }) => {
            assert_eq!(path, "dir/s.toml");
            key
        }
        other => panic!("expected a value error, got {other:?}"),
    }
}

#[test]
fn ranges_are_checked_with_the_key_named() {
    assert_eq!(check(&[]).unwrap().base_dir, Path::new("dir"));
    for (set, key) in [
        ("plate_insert.load=-1", "plate_insert.load"),
        ("plate_insert.load=nan", "plate_insert.load"),
        ("plate_insert.friction=inf", "plate_insert.friction"),
        ("plate_insert.eps=1.0", "plate_insert.eps"),
        ("plate_insert.clearance=-0.1", "plate_insert.clearance"),
        ("plate_insert.stiffness_ratio=0", "plate_insert.stiffness_ratio"),
        ("plate_insert.poissons_ratio=0.5", "plate_insert.poissons_ratio"),
        ("plate_insert.poissons_ratio=-1", "plate_insert.poissons_ratio"),
        ("plate_insert.steps=0", "plate_insert.steps"),
        ("plate_insert.steps=1001", "plate_insert.steps"),
        ("solver.max_iterations=0", "solver.max_iterations"),
    ] {
        assert_eq!(key_of(check(&[set])), key, "{set}");
    }
    // The limits themselves are admissible.
    check(&["plate_insert.steps=1000", "plate_insert.poissons_ratio=0.499", "plate_insert.load=0"]).unwrap();
}

#[test]
fn contradictions_are_errors_and_compatible_combinations_are_not() {
    assert_eq!(key_of(check(&["plate_insert.clearance=1"])), "plate_insert.clearance");
    check(&["plate_insert.eps=0.05", "plate_insert.clearance=1"]).unwrap();
    // c = 0 on a mesh with eps > 0 is a neat fit solved on that mesh: allowed.
    check(&["plate_insert.eps=0.05"]).unwrap();
    assert_eq!(key_of(check(&["plate_insert.l_steps=[0.1]"])), "plate_insert.l_steps");
    let bous = "solver.algorithm=boussinesq";
    check(&[bous, "plate_insert.l_steps=[0.1, 0.2]", "plate_insert.load=0"]).unwrap();
    assert_eq!(key_of(check(&[bous, "plate_insert.l_steps=[0.1]"])), "plate_insert.load");
    assert_eq!(
        key_of(check(&[bous, "plate_insert.l_steps=[0.1]", "plate_insert.load=0", "plate_insert.steps=2"])),
        "plate_insert.steps"
    );
    assert_eq!(
        key_of(check(&[bous, "plate_insert.l_steps=[0.2, 0.2]", "plate_insert.load=0"])),
        "plate_insert.l_steps[1]"
    );
    assert_eq!(key_of(check(&[bous, "plate_insert.l_steps=[1.0]", "plate_insert.load=0"])), "plate_insert.l_steps[0]");
    check(&["plate_insert.rigid_insert=true"]).unwrap();
    check(&["plate_insert.rigid_insert=true", "plate_insert.stiffness_ratio=1.0"]).unwrap();
    assert_eq!(
        key_of(check(&["plate_insert.rigid_insert=true", "plate_insert.stiffness_ratio=2"])),
        "plate_insert.stiffness_ratio"
    );
    assert_eq!(
        key_of(check(&["plate_insert.rigid_insert=true", "plate_insert.variant=insert_master"])),
        "plate_insert.variant"
    );
}

#[test]
fn file_errors_give_the_line_and_the_key() {
    let text = SCENE.replace("load = 1.0", "load = \"x\"");
    let e = PlateInsertScene::from_toml_str(&text, Path::new("s.toml"), &[]).unwrap_err().to_string();
    assert!(e.contains("line 6") && e.contains("plate_insert.load") && !e.contains('\n'), "{e}");
    let e = PlateInsertScene::from_toml_str("a = [", Path::new("s.toml"), &[]).unwrap_err().to_string();
    assert!(e.contains("line 1") && e.contains("s.toml"), "{e}");
    let dir = std::env::temp_dir().join(format!("contact2d-scene-utf8-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("bad.toml"), b"name = \"\xff\"").unwrap();
    let e = PlateInsertScene::load(&dir.join("bad.toml"), &[]).unwrap_err().to_string();
    assert!(e.contains("UTF-8") && e.contains("bad.toml"), "{e}");
}

#[test]
fn the_mesh_must_have_the_scenes_eps() {
    // The bundled meshes are made for eps = 0 and 0.05 (meshes/README.md): their insert edges
    // are circles of radius 1 − eps about (−eps, 0) to 2e-16.
    let neat = contact2d::mesh::read_msh("meshes/plate_insert/plate_insert_eps0_N16.msh").unwrap();
    let gap = contact2d::mesh::read_msh("meshes/plate_insert/plate_insert_eps0.05_N16.msh").unwrap();
    let with_eps = |eps: &str| check(&[&format!("plate_insert.eps={eps}")]).unwrap();
    with_eps("0").check_mesh_geometry(&neat).unwrap();
    with_eps("0.05").check_mesh_geometry(&gap).unwrap();
    for (scene, mesh) in [(with_eps("0.05"), &neat), (with_eps("0"), &gap), (with_eps("0.04"), &gap)] {
        match scene.check_mesh_geometry(mesh) {
            Err(SceneError::Value { key, .. }) => assert_eq!(key, "plate_insert.eps"),
            other => panic!("expected a value error, got {other:?}"),
        }
    }
}
