"""The CLI's studies as DataFrames: ``compare`` (every algorithm × pairing × mesh level on one
scene, ``contact2d compare``) and ``verify`` (the verification gallery, ``contact2d verify``).
Both call the library functions the CLI calls; neither writes files."""

from __future__ import annotations

import contextlib
import tempfile
from collections.abc import Iterator, Mapping, Sequence
from os import PathLike
from pathlib import Path

import pandas as pd

from . import _core

#: The first columns of ``compare``'s table, as in ``compare.csv``.
COMPARE_COLUMNS = (
    "algorithm",
    "pairing",
    "level",
    "mesh",
    "pairs",
    "status",
    "reason",
    "time_s",
    "solve_time_s",
    "iterations",
    "max_penetration",
    "max_complementarity",
    "max_cone_violation",
)

#: The columns of ``verify``'s table.
VERIFY_COLUMNS = (
    "case",
    "quantity",
    "mesh",
    "measured",
    "reference",
    "error",
    "tolerance",
    "tolerance_kind",
    "passed",
    "source",
)


@contextlib.contextmanager
def scene_file(scene: _core.Scene) -> Iterator[tuple[Path, list[str]]]:
    """A file the CLI's studies can read the scene from, and the overrides to apply: the scene's
    own file and overrides, or (a scene made by ``from_dict``) its TOML text in a temporary
    folder with the mesh path made absolute."""
    if Path(scene.path).is_file():
        yield Path(scene.path), list(scene.overrides)
        return
    key = "plate_insert.mesh" if scene.is_preset else "mesh"
    mesh = Path(scene.mesh_path).resolve()
    text = scene.set(key, f'"{mesh.as_posix()}"').to_toml()
    with tempfile.TemporaryDirectory(prefix="contact2d-scene-") as tmp:
        path = Path(tmp) / "scene.toml"
        path.write_text(text)
        yield path, []


def compare(
    scene: _core.Scene,
    *,
    meshes: Sequence[str | PathLike[str]] = (),
    repeat: int = 3,
    references: Mapping[str, float] | None = None,
    time_limit: float = 120.0,
) -> pd.DataFrame:
    """Run every contact algorithm × pairing × mesh level on ``scene``, as
    ``contact2d compare SCENE`` does, and return its table: one row per combination with the
    columns of ``compare.csv`` (algorithm, pairing, level, mesh, pairs, status, reason, time_s,
    solve_time_s, iterations, max_penetration, max_complementarity, max_cone_violation, then for
    each quantity ``q`` its value ``q`` and relative error ``error_q`` — on one mesh, where the
    reference is the most accurate method's value there, ``difference_q``).

    ``meshes`` are the mesh levels, coarse to fine (default: the scene's own; for the paper's
    case its N = 16, 32, 64 meshes); ``repeat`` runs per combination (the median time is
    reported); ``references`` closed-form values ``{dotted.path: value}`` (``--reference``);
    ``time_limit`` seconds per combination (a slower one is ``timed_out``). A combination the
    library refuses is a row with status ``skipped`` and its reason.

    The reference of each quantity is in ``frame.attrs["reference"]``, as compare.json's
    ``reference``: ``{quantity: {"quantity", "kind", "from", "value", "how", "deviation"}}`` with
    ``kind`` one of ``closed_form``, ``published``, ``richardson`` (the most accurate method's
    three finest levels extrapolated), ``finest`` (its value on the finest level), ``from`` the
    source or method and meshes, and ``deviation`` ``error`` or ``difference``.

    Raises SceneError / MeshError with the CLI's message for a bad scene or mesh, ValueError for
    a malformed reference or time limit.
    """
    refs = [f"{path}={value!r}" for path, value in (references or {}).items()]
    with scene_file(scene) as (path, sets):
        rows, refs_out = _core.compare(
            path, sets, [Path(m) for m in meshes], int(repeat), refs, float(time_limit)
        )
    columns = list(COMPARE_COLUMNS)
    for q, ref in refs_out.items():
        columns += [q, f"{ref['deviation']}_{q}"]
    frame = pd.DataFrame(rows, columns=columns)
    frame.attrs["reference"] = {q: dict(ref) for q, ref in refs_out.items()}
    return frame


def verify(
    cases: Sequence[str] | None = None,
    *,
    level: str = "fast",
    root: str | PathLike[str] = ".",
) -> pd.DataFrame:
    """Run the verification gallery as ``contact2d verify`` does and return one row per check:
    case, quantity, mesh, measured, reference, error (relative or absolute, as the tolerance),
    tolerance, tolerance_kind (``relative``/``absolute``), passed, source (the closed form or
    publication). Measurements without a reference (rates, step studies) follow as rows whose
    reference, error, tolerance and passed are empty.

    ``cases`` is a subset of contact_patch, hertz, cattaneo_mindlin, interference_fit, incline,
    pin_lug, flagship (default: all, which takes minutes); ``level`` is ``fast`` (coarse and
    middle meshes) or ``full`` (every bundled level); ``root`` is the repository root (where
    ``scenes/`` and ``meshes/`` are). The cases' notes are in ``frame.attrs["notes"]`` as
    ``[(case, note), ...]``. A failed check is a row with ``passed == False``, not an exception.
    """
    rows, notes = _core.verify(list(cases or []), level, Path(root))
    frame = pd.DataFrame(rows, columns=list(VERIFY_COLUMNS))
    frame.attrs["notes"] = notes
    return frame
