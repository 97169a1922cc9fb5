"""The per-case overhead of `contact2d.sweep` against the solve time, on a Dask LocalCluster and
on a scheduler + workers started as separate processes (as a user starts them).

    python3 python/benchmarks/sweep_overhead.py [N] [--setup local|processes|both]

N cases of `scenes/generic/pin_lug.toml` (frictions 0 … 0.4; default 200), after a warm-up sweep
of one case per worker. Prints the mean in-process solve time of one case (`contact2d.solve`,
serial, 20 cases, measured before and after the sweeps: the machine's load drifts), the sweep's
wall time, and the overhead per case: wall × workers / N − solve time (what each case costs a
worker beyond its solve: scheduling, shipping the record, the temporary scene folder, re-reading
the mesh and scene). Also prints the load average. A benchmark, not a test: the numbers depend on
the machine and its load.

`processes`: `python -m distributed.cli.dask_scheduler --host 127.0.0.1 --port 0` and one
`dask worker --nthreads 1 --no-nanny` process per core, killed at the end.
"""

from __future__ import annotations

import argparse
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from dask.distributed import Client, LocalCluster

import contact2d

ROOT = Path(__file__).resolve().parents[2]
SCENE = ROOT / "scenes" / "generic" / "pin_lug.toml"


def solve_time(scene: contact2d.Scene, frictions: list[float]) -> float:
    t0 = time.perf_counter()
    for mu in frictions[:20]:
        contact2d.solve(scene.set("contact.bore.friction", mu))
    return (time.perf_counter() - t0) / len(frictions[:20])


def timed_sweep(client: Client, scene: contact2d.Scene, frictions: list[float]) -> tuple[float, int]:
    workers = len(client.scheduler_info()["workers"])
    contact2d.sweep(scene, {"contact.bore.friction": frictions[:workers]}, client=client)  # warm-up
    t0 = time.perf_counter()
    frame = contact2d.sweep(scene, {"contact.bore.friction": frictions}, client=client)
    wall = time.perf_counter() - t0
    assert (frame["status"] == "converged").all(), frame["status"].value_counts()
    return wall, workers


def on_processes(scene: contact2d.Scene, frictions: list[float]) -> tuple[float, int]:
    workers = os.cpu_count() or 1
    with tempfile.TemporaryDirectory() as tmp:
        file = Path(tmp) / "scheduler.json"
        run = lambda *a: subprocess.Popen([sys.executable, "-m", *a], cwd=tmp, start_new_session=True,  # noqa: E731
                                          stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)  # fmt: skip
        processes = [run("distributed.cli.dask_scheduler", "--host", "127.0.0.1", "--port", "0", "--no-dashboard",
                         "--scheduler-file", str(file))]  # fmt: skip
        try:
            while not (file.is_file() and file.stat().st_size > 0):
                time.sleep(0.1)
            address = json.loads(file.read_text())["address"]
            processes += [run("distributed.cli.dask_worker", address, "--nthreads", "1", "--no-nanny", "--no-dashboard",
                              "--host", "127.0.0.1") for _ in range(workers)]  # fmt: skip
            with Client(address) as client:
                client.wait_for_workers(workers, timeout=120)
                return timed_sweep(client, scene, frictions)
        finally:
            for p in processes:
                if p.poll() is None:
                    os.killpg(p.pid, signal.SIGKILL)
                p.wait()


def on_local_cluster(scene: contact2d.Scene, frictions: list[float]) -> tuple[float, int]:
    with LocalCluster(processes=True, threads_per_worker=1, dashboard_address=None) as cluster, Client(cluster) as client:
        return timed_sweep(client, scene, frictions)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("n", nargs="?", type=int, default=200)
    parser.add_argument("--setup", choices=["local", "processes", "both"], default="local")
    args = parser.parse_args()
    n = args.n
    scene = contact2d.Scene.load(SCENE)
    frictions = [round(0.4 * i / (n - 1), 6) for i in range(n)]
    print(f"load average at start: {os.getloadavg()}; {os.cpu_count()} cores")
    before = solve_time(scene, frictions)
    setups = ["local", "processes"] if args.setup == "both" else [args.setup]
    results = {}
    for setup in setups:
        results[setup] = (on_local_cluster if setup == "local" else on_processes)(scene, frictions)
        print(f"load average after {setup}: {os.getloadavg()}")
    after = solve_time(scene, frictions)
    solve = (before + after) / 2
    print(f"solve in-process: {before * 1e3:.1f} ms/case before, {after * 1e3:.1f} ms/case after the sweeps")
    for setup, (wall, workers) in results.items():
        per_case = wall * workers / n
        overhead = per_case - solve
        print(f"{setup}: {n} cases on {workers} workers, wall {wall:.2f} s ({n / wall:.1f} cases/s); per case "
              f"{per_case * 1e3:.1f} ms of worker time, overhead {overhead * 1e3:.1f} ms ({overhead / solve:.0%} of the solve)")  # fmt: skip


if __name__ == "__main__":
    main()
