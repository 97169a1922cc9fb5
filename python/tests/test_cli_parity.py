"""The Python results equal the CLI's: for each scene, `contact2d.solve(...).json` and the dict
parsed from `contact2d run SCENE --json` are equal key for key and number for number (Python
parses both JSON texts to the same doubles, so `==` is bit-for-bit equality). Only `time_s`
(wall-clock times) differs between two runs and is left out."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest
from conftest import ROOT, cli_json, run_cli

import contact2d

if sys.version_info >= (3, 11):
    import tomllib
else:  # Python 3.10
    tomllib = pytest.importorskip("tomli")

# Every generic scene: each solves in at most 2 s with the release build (measured on 2 cores:
# 0.02 .. 2.1 s).
GENERIC = sorted(p.stem for p in (ROOT / "scenes" / "generic").glob("*.toml"))
PAPER = sorted(p.stem for p in (ROOT / "scenes").glob("plate_insert_*.toml"))


def without_times(summary: dict) -> dict:
    return {k: v for k, v in summary.items() if k != "time_s"}


def test_the_six_paper_scenes_are_found() -> None:
    assert len(PAPER) == 6, PAPER


@pytest.mark.parametrize("name", GENERIC)
def test_generic_scene_equals_cli_json(name: str) -> None:
    path = ROOT / "scenes" / "generic" / f"{name}.toml"
    result = contact2d.solve(contact2d.Scene.load(path))
    assert without_times(result.json) == without_times(cli_json(path))


@pytest.mark.parametrize("name", PAPER)
def test_paper_scene_equals_cli_json(name: str) -> None:
    path = ROOT / "scenes" / f"{name}.toml"
    result = contact2d.solve(contact2d.Scene.load(path))
    expected = without_times(cli_json(path))
    assert without_times(result.json) == expected
    assert result.paper == expected["paper"] and result.paper is not None
    assert {"l", "P", "Phi_E1", "sigma_star", "K"} <= set(result.paper)


def test_overrides_are_the_cli_set() -> None:
    path = ROOT / "scenes" / "generic" / "pin_lug.toml"
    scene = contact2d.Scene.load(path).set("contact.bore.friction", 0.1).set("solver.algorithm", "clarabel")
    assert scene.overrides == ["contact.bore.friction=0.1", "solver.algorithm=clarabel"]
    expected = cli_json(path, "contact.bore.friction=0.1", "solver.algorithm=clarabel")
    assert without_times(contact2d.solve(scene).json) == without_times(expected)


def test_unset_is_the_cli_unset() -> None:
    # pin_lug gives loading.steps = 4; without it the default is one step (docs/user-guide.md).
    path = ROOT / "scenes" / "generic" / "pin_lug.toml"
    scene = contact2d.Scene.load(path).unset("loading.steps")
    assert scene.overrides == ["!loading.steps"]
    done = run_cli("run", str(path), "--json", "--quiet", "--unset", "loading.steps")
    assert done.returncode == 0, done.stderr
    result = contact2d.solve(scene).json
    assert without_times(result) == without_times(json.loads(done.stdout))
    assert len(result["steps"]) == 1
    # In order with set: a key removed and then set again.
    assert len(contact2d.solve(scene.set("loading.steps", 2)).json["steps"]) == 2
    with pytest.raises(contact2d.SceneError, match='--unset loading.stepz: the scene gives no key "loading.stepz"'):
        contact2d.Scene.load(path).unset("loading.stepz")


def test_from_dict_and_to_toml_give_the_file_s_results() -> None:
    path = ROOT / "scenes" / "generic" / "pin_lug.toml"
    expected = without_times(cli_json(path, "contact.bore.friction=0.3"))
    with path.open("rb") as f:
        table = tomllib.load(f)
    from_dict = contact2d.Scene.from_dict(table, base_dir=path.parent).set("contact.bore.friction", 0.3)
    assert without_times(contact2d.solve(from_dict).json) == expected
    # to_toml carries the override: the text alone, re-read, gives the same run.
    text = from_dict.to_toml()
    assert tomllib.loads(text)["contact"][0]["friction"] == 0.3
    reread = contact2d.Scene.from_dict(tomllib.loads(text), base_dir=path.parent)
    assert without_times(contact2d.solve(reread).json) == expected


def test_result_views_are_the_summary() -> None:
    path = ROOT / "scenes" / "generic" / "pin_lug.toml"
    result = contact2d.solve(contact2d.Scene.load(path))
    summary = result.json
    assert result.status == summary["status"] == "converged"
    bore = result.contacts["bore"]
    assert bore.normal_force == summary["contacts"]["bore"]["normal_force"]
    profile = bore.profile
    assert list(profile.columns) == ["s", "x", "y", "pressure", "shear", "gap", "slip", "state"]
    assert profile["pressure"].tolist() == summary["contacts"]["bore"]["profile"]["pressure"]
    steps = result.steps
    assert len(steps) == len(summary["steps"]) == 4
    assert steps["contacts.bore.normal_force"].tolist() == [s["contacts"]["bore"]["normal_force"] for s in summary["steps"]]
    assert steps["reactions.lug_fixed.0"].iloc[-1] == summary["steps"][-1]["reactions"]["lug_fixed"][0]
    assert result.reactions == summary["reactions"] and result.energies == summary["energies"]
    assert result.kkt == summary["kkt"] and result.paper is None


def test_displacement_and_mesh_are_numpy() -> None:
    import numpy as np

    path = ROOT / "scenes" / "generic" / "pin_lug.toml"
    result = contact2d.solve(contact2d.Scene.load(path))
    mesh = result.mesh
    n = len(mesh.points)
    assert mesh.points.shape == (n, 2) and n > 0
    assert result.n_steps == 4
    last = result.displacement()
    assert last.shape == (n, 2) and np.array_equal(last, result.displacement(3))
    assert np.isfinite(last).all() and np.abs(last).max() > 0
    # The first step of a proportional load is smaller than the last.
    assert np.abs(result.displacement(0)).max() < np.abs(last).max()
    with pytest.raises(IndexError):
        result.displacement(4)
    kinds = {kind for kind, _, _ in mesh.cells}
    assert "quad9" in kinds
    for _, cells, _ in mesh.cells:
        assert cells.min() >= 0 and cells.max() < n
    assert {"lug", "pin", "hole"} <= set(mesh.groups)


def test_write_gives_the_cli_outputs(tmp_path: Path) -> None:
    path = ROOT / "scenes" / "generic" / "pin_lug.toml"
    written = contact2d.solve(contact2d.Scene.load(path)).write(tmp_path / "out")
    names = {p.name for p in written}
    assert {"summary.json", "steps.csv", "steps.pvd"} <= names, names
    assert all(p.is_file() for p in written)


def test_to_meshio_carries_the_mesh_and_displacement(tmp_path: Path) -> None:
    meshio = pytest.importorskip("meshio")
    import numpy as np

    result = contact2d.solve(contact2d.Scene.load(ROOT / "scenes" / "generic" / "pin_lug.toml"))
    mesh = result.to_meshio(step=0)
    assert np.array_equal(mesh.points, result.mesh.points)
    assert np.array_equal(mesh.point_data["u"], result.displacement(0))
    assert sum(len(block.data) for block in mesh.cells) == sum(len(c) for _, c, _ in result.mesh.cells)
    # meshio can write it (VTU) and read it back.
    mesh.write(tmp_path / "pin_lug.vtu")
    assert np.array_equal(meshio.read(tmp_path / "pin_lug.vtu").point_data["u"], result.displacement(0))
