"""`contact2d.sweep` on a Dask LocalCluster gives the rows of `contact2d sweep`: same cases in the
same order, same status, and the same numbers bit for bit (the CLI writes each float's shortest
round-trip text, which Python parses back to the same double). A failed case (friction -1) is a
row in both; only its message differs in the scene path it names (the task's temporary copy)."""

from __future__ import annotations

import csv
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
    assert list(frame.columns) == ["contact.bore.friction", "load.pin_back.force", "status", *columns, "iterations", "error"]
    for (_, row), expected in zip(frame.iterrows(), cli_rows, strict=True):
        assert row["contact.bore.friction"] == expected["contact.bore.friction"]
        assert row["load.pin_back.force"] == expected["load.pin_back.force"]
        assert row["status"] == expected["status"]
        if expected["status"] == "error":
            assert row["error"] and expected["error"]
            continue
        for c in columns:
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
