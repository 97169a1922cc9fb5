"""`contact2d.sweep` on a Dask LocalCluster gives the rows of `contact2d sweep`: same cases in the
same order, same status, and the same numbers bit for bit (the CLI writes each float's shortest
round-trip text, which Python parses back to the same double). A failed case (friction -1) is a
row in both; only its message differs in the scene path it names (the task's temporary copy)."""

from __future__ import annotations

import csv
import re
from pathlib import Path

import pytest
from conftest import ROOT, run_cli

import contact2d

pytest.importorskip("dask.distributed")


def test_local_cluster_sweep_equals_cli_sweep(tmp_path: Path) -> None:
    path = ROOT / "scenes" / "generic" / "pin_lug.toml"
    frictions, loads = ["0", "0.2", "-1"], ["[800.0, 0.0]", "[1000.0, 0.0]"]
    done = run_cli(
        "sweep", str(path), "--vary", f"contact.bore.friction={','.join(frictions)}",
        "--vary", f"load.pin_back.force={','.join(loads)}", "--out", str(tmp_path / "cli"), "--quiet",
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    with (tmp_path / "cli" / "sweep.csv").open() as f:
        cli_rows = list(csv.DictReader(f))
    frame = contact2d.sweep(
        contact2d.Scene.load(path), vary={"contact.bore.friction": frictions, "load.pin_back.force": loads}
    )
    assert len(frame) == len(cli_rows) == 6
    columns = ["contacts.bore.normal_force", "contacts.bore.contact_length"]
    assert list(frame.columns) == [
        "contact.bore.friction", "load.pin_back.force", "status", "last_held_factor", *columns, "iterations", "error",
    ]  # fmt: skip
    for (_, row), expected in zip(frame.iterrows(), cli_rows, strict=True):
        assert row["contact.bore.friction"] == expected["contact.bore.friction"]
        assert row["load.pin_back.force"] == expected["load.pin_back.force"]
        assert row["status"] == expected["status"]
        if expected["status"] == "error":
            assert row["error"] and expected["error"]
            continue
        for c in [*columns, "last_held_factor"]:
            assert row[c] == float(expected[c]), (c, row[c], expected[c])
        assert row["iterations"] == int(expected["iterations"])
    assert (frame["status"] == "error").sum() == 2


def test_sweeps_of_one_scene_on_one_client_follow_each_other() -> None:
    from dask.distributed import Client, LocalCluster

    scene = contact2d.Scene.load(ROOT / "scenes" / "generic" / "pin_lug.toml")
    with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None) as cluster, Client(cluster) as client:
        first = contact2d.sweep(scene, {"contact.bore.friction": [0.0, 0.1]}, client=client)
        second = contact2d.sweep(scene, {"contact.bore.friction": [0.0, 0.1, 0.2]}, client=client)
    assert (first["status"] == "converged").all() and (second["status"] == "converged").all()
    assert first["contacts.bore.normal_force"].tolist() == second["contacts.bore.normal_force"].tolist()[:2]


def test_rows_are_written_as_they_arrive(tmp_path: Path) -> None:
    """`out=rows.csv`: the file holds finished rows while the sweep still runs, all rows at the
    end (each number the frame's, to the bit: Python writes shortest round-trip texts), and the
    returned frame equals a sweep without `out`."""
    import threading
    import time

    from dask.distributed import Client, LocalCluster

    scene = contact2d.Scene.load(ROOT / "scenes" / "generic" / "pin_lug.toml")
    vary = {"contact.bore.friction": [0.0, 0.1, 0.2, -1.0], "load.pin_back.force": ["[600.0, 0.0]", "[800.0, 0.0]", "[1000.0, 0.0]"]}
    rows = tmp_path / "rows.csv"
    seen_while_running: list[int] = []
    with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None) as cluster, Client(cluster) as client:
        result: dict[str, object] = {}
        thread = threading.Thread(target=lambda: result.update(frame=contact2d.sweep(scene, vary, client=client, out=rows)))
        thread.start()
        while thread.is_alive():
            if rows.is_file():
                lines = rows.read_text().splitlines()
                if len(lines) > 1:
                    seen_while_running.append(len(lines) - 1)
            time.sleep(0.01)
        thread.join()
        plain = contact2d.sweep(scene, vary, client=client)
    frame = result["frame"]
    assert seen_while_running and min(seen_while_running) < len(frame), seen_while_running
    # The same frame; an error's message names the task's temporary folder, which differs.
    assert frame.drop(columns="error").equals(plain.drop(columns="error"))
    anonymous = lambda t: re.sub(r"contact2d-case-[^/]+", "contact2d-case-*", t)  # noqa: E731
    assert frame["error"].map(anonymous).tolist() == plain["error"].map(anonymous).tolist()
    with rows.open() as f:
        written = sorted(csv.DictReader(f), key=lambda r: int(r["case"]))
    assert [int(r["case"]) for r in written] == list(range(len(frame)))
    for (_, row), line in zip(frame.iterrows(), written, strict=True):
        for column in frame.columns:
            value = row[column]
            if value is None or (isinstance(value, float) and value != value):
                assert line[column] == ""
            elif isinstance(value, str):
                assert line[column] == value
            else:
                assert float(line[column]) == value, (column, line[column], value)
    assert (frame["status"] == "error").sum() == 3


def test_rows_file_must_be_csv(tmp_path: Path) -> None:
    scene = contact2d.Scene.load(ROOT / "scenes" / "generic" / "pin_lug.toml")
    with pytest.raises(ValueError, match=r"\.csv"):
        contact2d.sweep(scene, {"contact.bore.friction": [0.0]}, out=tmp_path / "rows.parquet")


def test_last_held_factor_matches_the_cli_on_a_capacity_sweep(tmp_path: Path) -> None:
    """The block on the incline pushed past Coulomb's threshold λ* = (tan α + μ)/(1 − μ tan α)
    in steps of 0.1: the Python column equals the CLI's, and brackets λ* (λ* − 0.1 < factor ≤ λ*)."""
    path = ROOT / "scenes" / "generic" / "incline_push.toml"
    pushes = ",".join(f"{{weight=1.0,push={i / 10:.1f}}}" for i in range(1, 9))
    schedule = f"[{{weight=1.0}},{pushes}]"
    done = run_cli(
        "sweep", str(path), "--vary", "contact.incline.friction=0.25,0.45", "--set", f"loading.schedule={schedule}",
        "--set", "loading.path_error=false", "--out", str(tmp_path / "cli"), "--quiet",
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    with (tmp_path / "cli" / "sweep.csv").open() as f:
        cli_rows = list(csv.DictReader(f))
    steps = [{"weight": 1.0}, *({"weight": 1.0, "push": i / 10} for i in range(1, 9))]
    scene = contact2d.Scene.load(path).set("loading.schedule", steps).set("loading.path_error", False)
    frame = contact2d.sweep(scene, vary={"contact.incline.friction": ["0.25", "0.45"]})
    for (_, row), expected in zip(frame.iterrows(), cli_rows, strict=True):
        mu = float(expected["contact.incline.friction"])
        threshold = (0.1 + mu) / (1 - 0.1 * mu)
        assert row["last_held_factor"] == float(expected["last_held_factor"])
        # The steps are exact decimals of the input; λ* (0.359, 0.576) is not on a step.
        assert threshold - 0.1 < row["last_held_factor"] <= threshold, (mu, row["last_held_factor"])
