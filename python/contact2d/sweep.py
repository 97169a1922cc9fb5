"""Parameter sweeps on Dask: one task per case, each shipping the scene's TOML text and its mesh's
bytes (no path that exists on one machine only) and returning a small record."""

from __future__ import annotations

import csv
import itertools
import sys
import tempfile
from collections.abc import Mapping, Sequence
from os import PathLike
from pathlib import Path
from typing import Any

import pandas as pd

from . import _core
from .result import solve

if sys.version_info >= (3, 11):
    import tomllib
else:  # Python 3.10
    import tomli as tomllib

#: The paper's quantities a sweep of a preset scene tabulates (as `contact2d sweep` does).
PAPER_COLUMNS = ("l", "b", "P", "Phi_E1", "Phi_E2", "Phi_f", "W", "sigma_star", "K", "insert_hoop_max")


def default_columns(scene: _core.Scene) -> list[str]:
    """The columns `contact2d sweep` tabulates for `scene`: each interface's normal force and
    contact length, or the paper's quantities for a preset scene."""
    if scene.is_preset:
        return list(PAPER_COLUMNS)
    contacts = tomllib.loads(scene.to_toml()).get("contact", [])
    return [f"contacts.{c['name']}.{q}" for c in contacts for q in ("normal_force", "contact_length")]


def quantity(summary: dict[str, Any], path: str) -> float | None:
    """The number at a dotted path of a summary (`contacts.bore.normal_force`,
    `reactions.lug_fixed.1`), looked up in the `paper` block when the top level has none (`P` is
    `paper.P`), or `energy` (the bodies' strain energies summed); `None` if there is none."""
    if path == "energy":
        return float(sum(summary.get("energies", {}).values()))

    def at(value: Any) -> float | None:
        for part in path.split("."):
            if isinstance(value, list) and part.isdigit() and int(part) < len(value):
                value = value[int(part)]
            elif isinstance(value, dict) and part in value:
                value = value[part]
            else:
                return None
        return value if isinstance(value, (int, float)) and not isinstance(value, bool) else None

    found = at(summary)
    return found if found is not None or "paper" not in summary else at(summary["paper"])


def last_held_factor(summary: dict[str, Any]) -> float | None:
    """The load factor a run last held (the column `last_held_factor`, as `contact2d sweep`'s,
    src/sweep/capacity.rs): the factor of the pattern whose factor changes most in the last step
    row (ties: the first name) — its final factor for `converged` (1.0 without pattern factors),
    `not_held.last_held_factors` for `not_held`, the last converged step's for another status
    (0 when the first step failed); `None` for a case that failed to start."""
    steps = summary.get("steps") or []
    last = steps[-1].get("factors") if steps else None
    status = summary.get("status")
    if not last:
        return 1.0 if status == "converged" else None
    before = (steps[-2].get("factors") or {}) if len(steps) > 1 else {}
    pattern, change = None, -1.0
    for name in sorted(last):
        d = abs(float(last[name]) - float(before.get(name, 0.0)))
        if d > change:
            pattern, change = name, d
    if status == "converged" or steps[-1].get("status") == "converged":
        return float(last[pattern])
    if status == "not_held":
        held = (summary.get("not_held") or {}).get("last_held_factors", {}).get(pattern)
        return None if held is None else float(held)
    if len(steps) == 1:
        return 0.0
    previous = steps[-2]
    return float(previous["factors"][pattern]) if previous.get("status") == "converged" else None


def run_case(
    payload: tuple[str, str, bytes, str],
    keys: Sequence[str],
    values: Sequence[Any],
    columns: Sequence[str],
    threads: int | None = None,
) -> dict[str, Any]:
    """One case on a worker: the scene text and mesh bytes written to a temporary folder, the
    varied keys set, solved on `threads` threads (`solve`'s argument); the record holds the varied values, status,
    last_held_factor, columns, iterations and
    error (a failed case is a record with status `error`)."""
    text, mesh_name, mesh_bytes, mesh_key = payload
    record: dict[str, Any] = dict(zip(keys, values, strict=True))
    with tempfile.TemporaryDirectory(prefix="contact2d-case-") as tmp:
        (Path(tmp) / mesh_name).write_bytes(mesh_bytes)
        (Path(tmp) / "scene.toml").write_text(text)
        try:
            scene = _core.Scene.load(Path(tmp) / "scene.toml").set(mesh_key, mesh_name)
            for key, value in zip(keys, values, strict=True):
                scene = scene.set(key, value)
            summary = solve(scene, threads=threads).json
        except _core.Contact2dError as e:
            record.update(
                {"status": "error", "last_held_factor": None, **{c: None for c in columns}, "iterations": None, "error": str(e)}
            )
            return record
    record.update({"status": summary["status"], "last_held_factor": last_held_factor(summary)})
    record.update({c: quantity(summary, c) for c in columns})
    record.update({"iterations": summary["iterations"], "error": ""})
    return record


class RowFile:
    """A CSV file of sweep rows written as they arrive: a header (`case`, then the sweep's
    columns), then one line per finished case, flushed at once, so that an interrupted sweep
    keeps every finished row. `case` is the row's place in the case list (from 0); the lines are
    in the order the cases finished. Numbers are Python's shortest round-trip texts, a missing
    value is empty."""

    def __init__(self, path: str | PathLike[str], columns: Sequence[str]) -> None:
        path = Path(path)
        if path.suffix.lower() != ".csv":
            raise ValueError(f"out: {str(path)!r}: rows are written as CSV; give a path ending in .csv")
        self.columns = list(columns)
        self.file = path.open("w", newline="")
        self.writer = csv.writer(self.file)
        self.writer.writerow(["case", *self.columns])
        self.file.flush()

    def write(self, case: int, record: Mapping[str, Any]) -> None:
        """Appends one finished case and flushes it to the file."""
        self.writer.writerow([case, *("" if record.get(c) is None else record[c] for c in self.columns)])
        self.file.flush()

    def close(self) -> None:
        self.file.close()


def sweep(
    scene: _core.Scene,
    vary: Mapping[str, Sequence[Any]],
    *,
    client: Any = None,
    columns: Sequence[str] | None = None,
    out: str | PathLike[str] | None = None,
    threads_per_case: int | None = 1,
) -> pd.DataFrame:
    """Solve `scene` over the Cartesian product of `vary`'s values ({`--set` path: values}; the
    last key varies fastest, as in `contact2d sweep`) on Dask and return one row per case:
    the varied values, `status`, `last_held_factor`, the columns (default: those of `contact2d sweep`; any dotted
    path of the summary), `iterations`, `error` (a failed case is a row with status `error`).

    `client=None` starts a `dask.distributed.LocalCluster` on this machine's cores for the call;
    any `dask.distributed.Client` (a scheduler with workers on other machines, a
    `dask_jobqueue.SLURMCluster`) runs the same call there: each task receives the scene's TOML
    text and mesh bytes, not paths. Dask re-runs the tasks of a worker that dies.

    `out` (a path ending in `.csv`) receives each row as soon as its case finishes (in the order
    they finish, with a leading `case` column giving the row's place in the case list), flushed
    line by line, so an interrupted sweep keeps its finished rows; the returned DataFrame is the
    same as without `out` (in case order).

    `threads_per_case` is each solve's thread pool (`solve(threads=...)`): 1 by default, as each
    worker thread runs one case (the LocalCluster has one single-threaded worker per core);
    `None` lets each solve use every core of its machine. The results do not depend on it.
    """
    from dask.distributed import Client, LocalCluster  # noqa: PLC0415 (optional dependency)

    keys = list(vary)
    cases = list(itertools.product(*(list(vary[k]) for k in keys)))
    mesh = Path(scene.mesh_path)
    payload = (scene.to_toml(), mesh.name, mesh.read_bytes(), "plate_insert.mesh" if scene.is_preset else "mesh")
    cols = list(columns) if columns is not None else default_columns(scene)
    frame_columns = [*keys, "status", "last_held_factor", *cols, "iterations", "error"]
    if out is not None and Path(out).suffix.lower() != ".csv":
        raise ValueError(f"out: {str(out)!r}: rows are written as CSV; give a path ending in .csv")
    cluster = None
    if client is None:
        cluster = LocalCluster(processes=True, threads_per_worker=1, dashboard_address=None)
        client = Client(cluster)
    rows = None
    try:
        rows = RowFile(out, frame_columns) if out is not None else None
        # hash=False: a key of its own per call. A content-hashed key would be shared with an
        # earlier sweep of the same scene on the same client, whose release then cancels this one's
        # tasks ("lost dependencies").
        shipped = client.scatter(payload, broadcast=True, hash=False)
        futures = [client.submit(run_case, shipped, keys, case, cols, threads_per_case, pure=False) for case in cases]
        if rows is None:
            records = client.gather(futures)
        else:
            from dask.distributed import as_completed  # noqa: PLC0415 (optional dependency)

            place = {future.key: i for i, future in enumerate(futures)}
            records = [None] * len(futures)
            for future, record in as_completed(futures, with_results=True):
                records[place[future.key]] = record
                rows.write(place[future.key], record)
    finally:
        if rows is not None:
            rows.close()
        if cluster is not None:
            client.close()
            cluster.close()
    return pd.DataFrame(records, columns=frame_columns)
