//! The scene parser never panics: arbitrary text, mutations of the bundled scenes (lines deleted,
//! duplicated, swapped, values replaced by absurd ones, truncation) and random `--set` overrides
//! all give a scene that passes its own checks or a typed [`SceneError`] that names the file (or
//! the override) on one line.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;
use std::sync::OnceLock;

use contact2d::plate_insert::PlateInsertScene;
use contact2d::scene::SceneError;
use proptest::prelude::*;

const PATH: &str = "scenes/mutated.toml";

fn scenes() -> &'static [String] {
    static SCENES: OnceLock<Vec<String>> = OnceLock::new();
    SCENES.get_or_init(|| {
        // The flagship's scenes (scenes/generic/ holds the generic ones: tests/behaviour/generic_scenes.rs).
        let mut paths: Vec<_> =
            std::fs::read_dir("scenes").unwrap().map(|e| e.unwrap().path()).filter(|p| p.is_file()).collect();
        paths.sort();
        paths.iter().map(|p| std::fs::read_to_string(p).unwrap()).collect()
    })
}

/// Parses and checks the outcome: a valid scene or a one-line typed error naming its source.
fn parse_checked(text: &str, overrides: &[String]) {
    match PlateInsertScene::from_toml_str(text, Path::new(PATH), overrides) {
        Ok(scene) => {
            scene.validate().unwrap();
            let p = &scene.plate_insert;
            assert!(p.load.is_finite() && p.friction.is_finite() && p.poissons_ratio < 0.5 && p.steps >= 1);
        }
        Err(e) => {
            let shown = e.to_string();
            assert!(!shown.contains('\n'), "more than one line: {shown}");
            match &e {
                SceneError::Override { assignment, .. } => assert!(shown.contains(assignment.as_str())),
                SceneError::Invalid { .. } | SceneError::Value { .. } => assert!(shown.contains(PATH), "{shown}"),
                other => panic!("unexpected error kind: {other:?}"),
            }
        }
    }
}

/// One edit of a scene file.
#[derive(Debug, Clone)]
enum Mutation {
    DeleteLine(prop::sample::Index),
    DuplicateLine(prop::sample::Index),
    SwapLines(prop::sample::Index, prop::sample::Index),
    ReplaceValue(prop::sample::Index, &'static str),
    Truncate(prop::sample::Index),
    InsertLine(prop::sample::Index, &'static str),
}

const VALUES: &[&str] = &[
    "0",
    "-1",
    "1e400",
    "nan",
    "-inf",
    "0.5",
    "1.0",
    "99999999999999999999",
    "\"\"",
    "\"x\"",
    "true",
    "[]",
    "[0.3, 0.1]",
    "[nan]",
    "{}",
    "{ a = 1 }",
    "\"../../etc\"",
    "\"insert_master\"",
    "\"boussinesq\"",
    "2024-01-01",
];

fn mutation() -> impl Strategy<Value = Mutation> {
    let line = prop::sample::select(vec![
        "[plate_insert]",
        "[solver]",
        "[[plate_insert]]",
        "rigid_insert = true",
        "stiffness_ratio = 3.0",
        "l_steps = [0.1, 0.2]",
        "steps = 0",
        "clearance = 1.0",
        "eps = 0.0",
        "algorithm = \"boussinesq\"",
        "bogus = 1",
        "= 1",
        "\"",
    ]);
    prop_oneof![
        any::<prop::sample::Index>().prop_map(Mutation::DeleteLine),
        any::<prop::sample::Index>().prop_map(Mutation::DuplicateLine),
        (any::<prop::sample::Index>(), any::<prop::sample::Index>()).prop_map(|(a, b)| Mutation::SwapLines(a, b)),
        (any::<prop::sample::Index>(), prop::sample::select(VALUES)).prop_map(|(i, v)| Mutation::ReplaceValue(i, v)),
        any::<prop::sample::Index>().prop_map(Mutation::Truncate),
        (any::<prop::sample::Index>(), line).prop_map(|(i, l)| Mutation::InsertLine(i, l)),
    ]
}

fn apply(text: &str, m: &Mutation) -> String {
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    if lines.is_empty() {
        return String::new();
    }
    match m {
        Mutation::DeleteLine(i) => {
            lines.remove(i.index(lines.len()));
        }
        Mutation::DuplicateLine(i) => {
            let k = i.index(lines.len());
            lines.insert(k, lines[k].clone());
        }
        Mutation::SwapLines(a, b) => {
            let (a, b) = (a.index(lines.len()), b.index(lines.len()));
            lines.swap(a, b);
        }
        Mutation::ReplaceValue(i, v) => {
            let k = i.index(lines.len());
            if let Some((key, _)) = lines[k].split_once('=') {
                lines[k] = format!("{key}= {v}");
            }
        }
        Mutation::Truncate(i) => {
            let cut = i.index(text.len());
            let cut = (0..=cut).rev().find(|c| text.is_char_boundary(*c)).unwrap_or(0);
            return text[..cut].to_string();
        }
        Mutation::InsertLine(i, l) => lines.insert(i.index(lines.len() + 1), (*l).to_string()),
    }
    lines.join("\n")
}

fn assignment() -> impl Strategy<Value = String> {
    let key = prop::sample::select(vec![
        "plate_insert.load",
        "plate_insert.friction",
        "plate_insert.steps",
        "plate_insert.l_steps",
        "plate_insert.rigid_insert",
        "plate_insert.stiffness_ratio",
        "plate_insert.poissons_ratio",
        "plate_insert.eps",
        "plate_insert.clearance",
        "plate_insert.gap",
        "plate_insert.pairs",
        "plate_insert.variant",
        "plate_insert",
        "solver.algorithm",
        "solver.max_iterations",
        "solver.algorithm.x",
        "nosuch.key",
        "",
        "name",
    ]);
    (key, prop::sample::select(VALUES), any::<bool>())
        .prop_map(|(k, v, eq)| if eq { format!("{k}={v}") } else { format!("{k}{v}") })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    #[test]
    fn arbitrary_text_never_panics(text in ".{0,400}") {
        parse_checked(&text, &[]);
    }

    #[test]
    fn arbitrary_toml_like_text_never_panics(text in "([a-z_\\.\\[\\]]{1,12} ?= ?[-0-9a-z\\.\"\\[\\], ]{0,12}\n){0,12}") {
        parse_checked(&text, &[]);
    }

    #[test]
    fn mutated_scenes_never_panic(
        which in any::<prop::sample::Index>(),
        edits in prop::collection::vec(mutation(), 1..6),
        overrides in prop::collection::vec(assignment(), 0..3),
    ) {
        let all = scenes();
        let mut text = all[which.index(all.len())].clone();
        for m in &edits {
            text = apply(&text, m);
        }
        parse_checked(&text, &overrides);
    }
}

#[test]
fn the_bundled_scenes_are_valid() {
    for text in scenes() {
        parse_checked(text, &[]);
        assert!(PlateInsertScene::from_toml_str(text, Path::new(PATH), &[]).is_ok());
    }
}
