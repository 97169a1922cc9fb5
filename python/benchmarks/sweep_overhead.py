"""The per-case overhead of `contact2d.sweep` on a Dask LocalCluster against the solve time.

    python3 python/benchmarks/sweep_overhead.py [N]     # N cases of pin_lug (default 200)

Prints the mean in-process solve time of one case (`contact2d.solve`, serial), the sweep's wall
time, and the overhead per case: wall × workers / N − solve time (what each case costs a worker
beyond its solve: shipping, the temporary scene folder, re-reading the mesh, scheduling). A
benchmark, not a test: the numbers depend on the machine and its load.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

from dask.distributed import Client, LocalCluster

import contact2d

ROOT = Path(__file__).resolve().parents[2]


def main() -> None:
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 200
    scene = contact2d.Scene.load(ROOT / "scenes" / "generic" / "pin_lug.toml")
    frictions = [round(0.4 * i / (n - 1), 6) for i in range(n)]
    t0 = time.perf_counter()
    for mu in frictions[:20]:
        contact2d.solve(scene.set("contact.bore.friction", mu))
    solve = (time.perf_counter() - t0) / 20
    with LocalCluster(processes=True, threads_per_worker=1, dashboard_address=None) as cluster, Client(cluster) as client:
        workers = len(client.scheduler_info()["workers"])
        contact2d.sweep(scene, {"contact.bore.friction": frictions[:workers]}, client=client)  # warm-up
        t0 = time.perf_counter()
        frame = contact2d.sweep(scene, {"contact.bore.friction": frictions}, client=client)
        wall = time.perf_counter() - t0
    assert (frame["status"] == "converged").all(), frame["status"].value_counts()
    overhead = wall * workers / n - solve
    print(f"{n} cases on {workers} workers: solve {solve * 1e3:.1f} ms/case in-process, sweep wall {wall:.2f} s")
    print(f"per case: {wall * workers / n * 1e3:.1f} ms of worker time, overhead {overhead * 1e3:.1f} ms ({overhead / solve:.0%} of the solve)")


if __name__ == "__main__":
    main()
