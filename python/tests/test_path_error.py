"""The step size's error of a frictional run (`path_error`) and adaptive stepping from Python:
the same numbers as the CLI (one code path), and the adaptive answer of the pin in the lug from
one user step within its tolerance's promise of the converged path (400 equal steps): the
resultant within 1e-3 of the largest contact force plus the 400 steps' own error (0.1 N), as
tests/verification/verify_path_error.rs states."""

from __future__ import annotations

from conftest import ROOT, cli_json

import contact2d

PIN_LUG = ROOT / "scenes" / "generic" / "pin_lug.toml"


def test_path_error_is_the_clis_and_adaptive_stepping_keeps_the_users_steps() -> None:
    scene = contact2d.Scene.load(PIN_LUG)
    bundled = contact2d.solve(scene)
    assert bundled.path_error == cli_json(PIN_LUG)["path_error"]
    assert list(bundled.steps["path_error"]) == [s["path_error"] for s in bundled.json["steps"]]

    truth = cli_json(PIN_LUG, "loading.steps=400", "loading.path_error=false")["contacts"]["bore"]["resultant"]
    adaptive = contact2d.solve(scene.set("loading.steps", 1).set("loading.adaptive.tolerance", 1e-3))
    assert adaptive.status == "converged"
    assert len(adaptive.json["steps"]) == 1
    assert adaptive.json["steps_taken"] == adaptive.json["steps"][0]["substeps"] > 1
    assert adaptive.path_error <= 1e-3
    largest = (truth[0] ** 2 + truth[1] ** 2) ** 0.5
    assert abs(adaptive.contacts["bore"].resultant[1] - truth[1]) <= 1e-3 * largest + 0.1
