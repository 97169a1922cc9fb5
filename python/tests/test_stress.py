"""`Result.stress` and `solve(threads=)`.

stress: equals the `stress` tensor of the CLI's VTU files (`contact2d run --out`, read with
meshio) bit for bit (the VTU stores the doubles in binary), on a generic scene and a paper scene;
and on the interference fit, the disk's stress is −p everywhere (Lamé) within 0.5 % (the
verification gallery's tolerance for this mesh).

threads: a solve on a pool of 1 or 2 threads gives the CLI's summary."""

from __future__ import annotations

import tempfile
from pathlib import Path

import numpy as np
import pytest
from conftest import ROOT, cli_json, run_cli

import contact2d

meshio = pytest.importorskip("meshio")


def cli_vtu_stress(scene: Path) -> np.ndarray:
    """The last step's VTU `stress` (n_nodes × 9, row-major 3 × 3) of `contact2d run --out`."""
    with tempfile.TemporaryDirectory() as tmp:
        done = run_cli("run", str(scene), "--out", tmp, "--quiet")
        assert done.returncode == 0, done.stderr
        last = sorted(Path(tmp).glob("step_*.vtu"))[-1]
        return meshio.read(last).point_data["stress"]


@pytest.mark.parametrize(
    "scene",
    [
        "scenes/generic/pin_lug.toml",
        "scenes/plate_insert_nogap_mu03.toml",
        "scenes/generic/shrink_fit_axisymmetric.toml",
    ],
)
def test_stress_equals_the_cli_vtu(scene: str) -> None:
    path = ROOT / scene
    result = contact2d.solve(contact2d.Scene.load(path))
    stress = result.stress()
    vtu = cli_vtu_stress(path)
    assert stress.shape == (len(result.mesh.points), 4)
    in_body = ~np.isnan(stress[:, 0])
    assert in_body.any()
    # (σ11, σ22, σ12, σ33) are the tensor's (0,0), (1,1), (0,1) and (2,2) entries.
    expected = vtu[:, [0, 4, 1, 8]]
    assert np.array_equal(stress[in_body], expected[in_body])
    assert (vtu[~in_body] == 0.0).all()  # the VTU writes 0 at a node of no body
    assert np.array_equal(result.stress(0), result.stress(-result.n_steps))
    with pytest.raises(IndexError):
        result.stress(result.n_steps)


def test_interference_fit_disk_stress_is_minus_p() -> None:
    # Lamé: p = E δ (b² − a²) / (2 a b²), the disk's σ11 = σ22 = −p (the scene's comments).
    a, b, e, delta = 500.0, 1000.0, 2e5, 0.6667
    p = e * delta * (b * b - a * a) / (2 * a * b * b)
    result = contact2d.solve(contact2d.Scene.load(ROOT / "scenes" / "generic" / "interference_fit.toml"))
    stress = result.stress()
    points = result.mesh.points
    disk = np.hypot(points[:, 0], points[:, 1]) < a - 1e-6  # strictly inside the disk
    assert disk.sum() > 10
    assert np.allclose(stress[disk, :2], -p, rtol=5e-3, atol=0)
    assert (stress[:, 3][~np.isnan(stress[:, 3])] == 0.0).all()  # plane stress: σ33 = 0


def test_a_body_of_revolution_from_a_dict_gives_lames_shrink_fit() -> None:
    # The axisymmetric shrink fit posed from a dict with the scene file's keys (kinematics =
    # "axisymmetric"): the CLI's summary, and Lamé's closed forms (plane strain along the axis,
    # the ends held): p = E δ / (b (1 + ν) [((1 − 2ν) b² + c²)/(c² − b²) + (1 − 2ν)]), the hub's
    # bore σθθ = p (c² + b²)/(c² − b²), the shaft's σ_rr = σθθ = −p, within 0.5 % (the
    # verification gallery's tolerance for this mesh; docs/verification.md).
    import tomllib

    path = ROOT / "scenes" / "generic" / "shrink_fit_axisymmetric.toml"
    scene = contact2d.Scene.from_dict(tomllib.loads(path.read_text()), base_dir=path.parent)
    result = contact2d.solve(scene)
    drop = lambda s: {k: v for k, v in s.items() if k != "time_s"}  # noqa: E731
    assert drop(result.json) == drop(cli_json(path))
    assert result.json["kinematics"] == "axisymmetric"
    e, nu, delta, b, c = 2e5, 0.3, 0.01, 10.0, 20.0
    p = e * delta / (b * (1 + nu) * (((1 - 2 * nu) * b * b + c * c) / (c * c - b * b) + (1 - 2 * nu)))
    stress = result.stress()
    points = result.mesh.points
    shaft = points[:, 0] < b - 1e-9
    assert np.allclose(stress[shaft][:, [0, 3]], -p, rtol=5e-3, atol=0)
    bore = np.isclose(points[:, 0], b) & ~np.isnan(stress[:, 3]) & (stress[:, 3] > 0)
    assert bore.sum() > 5
    assert np.allclose(stress[bore, 3], p * (c * c + b * b) / (c * c - b * b), rtol=5e-3, atol=0)


@pytest.mark.parametrize("threads", [1, 2])
def test_threads_give_the_cli_summary(threads: int) -> None:
    path = ROOT / "scenes" / "generic" / "pin_lug.toml"
    result = contact2d.solve(contact2d.Scene.load(path), threads=threads)
    drop = lambda s: {k: v for k, v in s.items() if k != "time_s"}  # noqa: E731
    assert drop(result.json) == drop(cli_json(path))


def test_threads_must_be_positive() -> None:
    with pytest.raises(ValueError, match="threads"):
        contact2d.solve(contact2d.Scene.load(ROOT / "scenes" / "generic" / "pin_lug.toml"), threads=0)
