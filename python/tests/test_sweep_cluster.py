"""`contact2d.sweep` on a Dask cluster started as a user starts one: a scheduler (`dask
scheduler`) and two single-threaded workers (`dask worker`), each a separate process on
127.0.0.1, reached through `Client(address)`.

* The sweep's rows equal `contact2d sweep`'s (the CLI's shortest round-trip decimals parse to the
  same doubles, so `==` is bit-for-bit equality).
* A worker killed (SIGKILL, no nanny to restart it) while it solves a case loses no case: the
  scheduler re-runs that worker's tasks on the other one, and the rows still equal the CLI's.

Each test takes about 10 s on 2 loaded cores (process start-up dominates); every process is
killed in a finally block."""

from __future__ import annotations

import csv
import json
import os
import signal
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from pathlib import Path

import pytest
from conftest import ROOT, run_cli

import contact2d

distributed = pytest.importorskip("dask.distributed")

SCENE = ROOT / "scenes" / "generic" / "pin_lug.toml"
COLUMNS = ["contacts.bore.normal_force", "contacts.bore.contact_length"]


def start(args: list[str], log: Path) -> subprocess.Popen[bytes]:
    """A Dask command as its own process (and process group), output to `log`."""
    with log.open("wb") as out:
        return subprocess.Popen(
            [sys.executable, "-m", *args], stdout=out, stderr=subprocess.STDOUT, cwd=log.parent, start_new_session=True
        )


def stop(process: subprocess.Popen[bytes]) -> None:
    if process.poll() is None:
        os.killpg(process.pid, signal.SIGKILL)
    process.wait(timeout=30)


def wait_for(condition, what: str, timeout: float = 60.0) -> None:  # type: ignore[no-untyped-def]
    deadline = time.monotonic() + timeout
    while not condition():
        if time.monotonic() > deadline:
            raise TimeoutError(what)
        time.sleep(0.05)


@pytest.fixture
def cluster(tmp_path: Path) -> Iterator[tuple[str, list[subprocess.Popen[bytes]]]]:
    """A scheduler on a free port of 127.0.0.1 and two `dask worker --nthreads 1 --no-nanny`
    processes; yields (scheduler address, worker processes)."""
    file = tmp_path / "scheduler.json"
    processes = []
    try:
        processes.append(start(["distributed.cli.dask_scheduler", "--host", "127.0.0.1", "--port", "0",
                                "--no-dashboard", "--scheduler-file", str(file)], tmp_path / "scheduler.log"))  # fmt: skip
        wait_for(lambda: file.is_file() and file.stat().st_size > 0, "the scheduler's file")
        address = json.loads(file.read_text())["address"]
        workers = [
            start(["distributed.cli.dask_worker", address, "--nthreads", "1", "--no-nanny", "--no-dashboard",
                   "--name", f"w{i}", "--host", "127.0.0.1"], tmp_path / f"worker{i}.log")  # fmt: skip
            for i in range(2)
        ]
        processes += workers
        yield address, workers
    finally:
        for p in reversed(processes):
            stop(p)


def cli_rows(tmp_path: Path, frictions: list[str], loads: list[str]) -> list[dict[str, str]]:
    done = run_cli(
        "sweep", str(SCENE), "--vary", f"contact.bore.friction={','.join(frictions)}",
        "--vary", f"load.pin_back.force={','.join(loads)}", "--out", str(tmp_path / "cli"), "--quiet",
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    with (tmp_path / "cli" / "sweep.csv").open() as f:
        return list(csv.DictReader(f))


def assert_equal_rows(frame, rows: list[dict[str, str]]) -> None:  # type: ignore[no-untyped-def]
    assert len(frame) == len(rows)
    for (_, row), expected in zip(frame.iterrows(), rows, strict=True):
        assert row["contact.bore.friction"] == expected["contact.bore.friction"]
        assert row["load.pin_back.force"] == expected["load.pin_back.force"]
        assert row["status"] == expected["status"] == "converged"
        for c in COLUMNS:
            assert row[c] == float(expected[c]), (c, row[c], expected[c])
        assert row["iterations"] == int(expected["iterations"])


def test_scheduler_and_two_worker_processes_equal_the_cli(tmp_path: Path, cluster) -> None:  # type: ignore[no-untyped-def]
    address, _ = cluster
    frictions, loads = ["0", "0.2"], ["[800.0, 0.0]", "[1000.0, 0.0]"]
    with distributed.Client(address, timeout=60) as client:
        client.wait_for_workers(2, timeout=60)
        frame = contact2d.sweep(
            contact2d.Scene.load(SCENE), {"contact.bore.friction": frictions, "load.pin_back.force": loads}, client=client
        )
        # Both worker processes ran cases (each is single-threaded).
        assert len(client.scheduler_info()["workers"]) == 2
    assert_equal_rows(frame, cli_rows(tmp_path, frictions, loads))


def test_a_worker_killed_mid_sweep_loses_no_case(tmp_path: Path, cluster) -> None:  # type: ignore[no-untyped-def]
    address, workers = cluster
    frictions = ["0", "0.1", "0.2", "0.3"]
    loads = ["[600.0, 0.0]", "[800.0, 0.0]", "[1000.0, 0.0]", "[1200.0, 0.0]"]
    with distributed.Client(address, timeout=60) as client:
        client.wait_for_workers(2, timeout=60)
        victim = workers[1]
        victim_address = next(a for a, w in client.scheduler_info()["workers"].items() if w["name"] == "w1")
        outcome: dict[str, object] = {}

        def run() -> None:
            try:
                outcome["frame"] = contact2d.sweep(
                    contact2d.Scene.load(SCENE),
                    {"contact.bore.friction": frictions, "load.pin_back.force": loads},
                    client=client,
                )
            except BaseException as e:  # noqa: BLE001 (reported by the main thread)
                outcome["error"] = e

        thread = threading.Thread(target=run)
        thread.start()
        try:
            # Kill w1 while it holds a case (the sweep's 16 cases take a few seconds).
            wait_for(lambda: len(client.processing().get(victim_address, ())) > 0, "w1 to hold a case")
            held = list(client.processing()[victim_address])
            os.killpg(victim.pid, signal.SIGKILL)
            victim.wait(timeout=30)
        finally:
            thread.join(timeout=120)
        assert not thread.is_alive(), "the sweep did not finish"
        assert "error" not in outcome, outcome.get("error")
        assert held, "w1 held no case when killed"
        assert list(client.scheduler_info()["workers"]) != [] and victim_address not in client.scheduler_info()["workers"]
    frame = outcome["frame"]
    assert_equal_rows(frame, cli_rows(tmp_path, frictions, loads))
