//! The scene parser on arbitrary text: the part before the first NUL byte is the scene file, each
//! line after it one `--set` override. Any input gives a valid scene or a typed error, never a
//! panic; a scene that loads passes its own checks again.
#![no_main]

use contact2d::scene::Scene;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| {
    let Ok(text) = std::str::from_utf8(bytes) else { return };
    let (scene, sets) = text.split_once('\0').unwrap_or((text, ""));
    let overrides: Vec<String> = sets.lines().map(str::to_string).collect();
    if let Ok(s) = Scene::from_toml_str(scene, std::path::Path::new("scenes/fuzz.toml"), &overrides) {
        assert!(s.validate().is_ok());
        let _ = s.plate_insert();
    }
});
