"""Every exception type, raised with the CLI's message: the text after `error: ` on the CLI's
stderr for the same scene, mesh or override."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from conftest import ROOT, cli_error

import contact2d

PIN_LUG = ROOT / "scenes" / "generic" / "pin_lug.toml"


def test_exceptions_share_a_base() -> None:
    for e in (contact2d.SceneError, contact2d.MeshError, contact2d.ContactError):
        assert issubclass(e, contact2d.Contact2dError) and issubclass(e, Exception)


def test_bad_scene_file_is_a_scene_error(tmp_path: Path) -> None:
    bad = tmp_path / "bad.toml"
    bad.write_text('name = "x"\nmesh = [\n')
    with pytest.raises(contact2d.SceneError) as caught:
        contact2d.Scene.load(bad)
    assert str(caught.value) == cli_error("run", str(bad), "--json")
    assert str(bad) in str(caught.value)


def test_missing_scene_file_is_a_scene_error(tmp_path: Path) -> None:
    missing = tmp_path / "missing.toml"
    with pytest.raises(contact2d.SceneError) as caught:
        contact2d.Scene.load(missing)
    assert str(caught.value) == cli_error("run", str(missing))


def test_bad_value_in_a_dict_is_a_scene_error() -> None:
    with pytest.raises(contact2d.SceneError, match="body"):
        contact2d.Scene.from_dict({"name": "x", "mesh": "m.msh", "body": []})
    with pytest.raises(TypeError, match="name"):
        contact2d.Scene.from_dict({"name": object()})


@pytest.mark.parametrize(
    "key,value,cli",
    [
        ("contact.bore.nope", 1, "contact.bore.nope=1"),
        ("contact.bore.friction", -1.0, "contact.bore.friction=-1.0"),
        ("contact.7.friction", 0.1, "contact.7.friction=0.1"),
    ],
)
def test_bad_override_is_a_scene_error(key: str, value: object, cli: str) -> None:
    scene = contact2d.Scene.load(PIN_LUG)
    with pytest.raises(contact2d.SceneError) as caught:
        scene.set(key, value)
    assert str(caught.value) == cli_error("run", str(PIN_LUG), "--set", cli)
    # The scene is unchanged: set returns a new scene or raises.
    assert scene.overrides == []


def test_bad_mesh_is_a_mesh_error(tmp_path: Path) -> None:
    (tmp_path / "garbage.msh").write_text("$MeshFormat\n9.9 0 8\n$EndMeshFormat\n")
    scene_file = tmp_path / "scene.toml"
    text = PIN_LUG.read_text().replace('"../../meshes/generic/pin_lug.msh"', '"garbage.msh"')
    assert "garbage.msh" in text
    scene_file.write_text(text)
    scene = contact2d.Scene.load(scene_file)
    with pytest.raises(contact2d.MeshError) as caught:
        contact2d.solve(scene)
    assert str(caught.value) == cli_error("run", str(scene_file), "--json")
    assert "garbage.msh" in str(caught.value)


def test_bad_mesh_of_a_paper_scene_is_a_mesh_error(tmp_path: Path) -> None:
    (tmp_path / "garbage.msh").write_text("not a mesh\n")
    source = ROOT / "scenes" / "plate_insert_nogap_mu0.toml"
    scene = contact2d.Scene.load(source).set("plate_insert.mesh", str(tmp_path / "garbage.msh"))
    with pytest.raises(contact2d.MeshError) as caught:
        contact2d.solve(scene)
    assert "garbage.msh" in str(caught.value)


def test_contact_set_up_failure_is_a_contact_error(tmp_path: Path) -> None:
    # A contact whose master curve is a group of the mesh that is not a curve of a body's
    # boundary: the scene parses, the problem cannot be built.
    shutil.copy(ROOT / "meshes" / "generic" / "pin_lug.msh", tmp_path / "pin_lug.msh")
    scene_file = tmp_path / "scene.toml"
    text = PIN_LUG.read_text().replace('"../../meshes/generic/pin_lug.msh"', '"pin_lug.msh"')
    scene_file.write_text(text.replace('master = "pin_contact"', 'master = "lug"'))
    scene = contact2d.Scene.load(scene_file)
    with pytest.raises(contact2d.ContactError) as caught:
        contact2d.solve(scene)
    assert str(caught.value) == cli_error("run", str(scene_file), "--json")


def test_non_converged_solve_is_a_status() -> None:
    scene = contact2d.Scene.load(PIN_LUG).set("solver.max_iterations", 1)
    result = contact2d.solve(scene)
    assert result.status != "converged"
