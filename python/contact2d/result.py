"""The result of a solve: the CLI's JSON summary as a dict, its tables as pandas DataFrames, the
mesh and displacements as numpy arrays."""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from . import _core

#: The columns of a contact profile, in the summary's order.
PROFILE_COLUMNS = ("s", "x", "y", "pressure", "shear", "gap", "slip", "state")


def solve(
    scene: _core.Scene,
    *,
    profiles: str = "last",
    threads: int | None = None,
    about: tuple[float, float] | None = None,
) -> Result:
    """Solve ``scene`` as ``contact2d run SCENE --json`` does and return its :class:`Result`.

    The GIL is released while solving, so several threads solve concurrently. ``profiles`` is
    ``"last"`` (default) or ``"all"``: which steps carry the interfaces' profiles in the summary
    (the CLI's ``--profiles``). ``threads`` (an int >= 1) runs the solve on a thread pool of
    that size (the library's parallel parts: assembly, ordering, stress recovery); ``None`` uses
    one thread per core. The results do not depend on it. ``about`` = ``(x, y)`` is the centre
    the moments (``reaction_moments``, ``reaction_moment_total``, each contact's ``moment``) are
    taken about (the CLI's ``--about x,y``; ``None``: the origin, ``json["moment_centre"]``).

    A solve that does not converge is a status (``result.status``), not an exception. Raises
    :class:`SceneError`, :class:`MeshError` or :class:`ContactError` with the CLI's message when
    the scene, its mesh or the problem's set-up is at fault.
    """
    return Result(_core.solve(scene, profiles, threads, about))


def flatten(value: Any, prefix: str = "") -> dict[str, Any]:
    """The scalars of a JSON value as ``{dotted path: value}`` (the paths ``sweep --plot``
    takes: ``contacts.bore.normal_force``, ``reactions.lug_fixed.1``). Lists of up to three
    numbers (vectors) are split by index; longer lists (profiles, zones) are left out."""
    out: dict[str, Any] = {}
    if isinstance(value, dict):
        for key, item in value.items():
            out.update(flatten(item, f"{prefix}.{key}" if prefix else str(key)))
    elif isinstance(value, list):
        if len(value) <= 3 and all(v is None or isinstance(v, (int, float)) for v in value):
            for i, item in enumerate(value):
                out[f"{prefix}.{i}"] = item
    else:
        out[prefix] = value
    return out


@dataclass(frozen=True)
class Contact:
    """One interface of the last step: its summary entry (``json["contacts"][name]``)."""

    name: str
    json: dict[str, Any]

    @property
    def normal_force(self) -> float:
        """The transmitted normal force (per unit thickness times thickness)."""
        return self.json["normal_force"]

    @property
    def tangential_force(self) -> float:
        """The transmitted tangential force (signed)."""
        return self.json["tangential_force"]

    @property
    def contact_length(self) -> float:
        """The length of the contact zone along the master curve."""
        return self.json["contact_length"]

    @property
    def stick_length(self) -> float:
        """The length of the stick zone."""
        return self.json["stick_length"]

    @property
    def max_pressure(self) -> float:
        """The largest contact pressure."""
        return self.json["max_pressure"]

    @property
    def resultant(self) -> list[float]:
        """The force vector transmitted to the slave side."""
        return self.json["resultant"]

    @property
    def profile(self) -> pd.DataFrame:
        """The profile along the master curve: one row per point, columns s, x, y, pressure,
        shear, gap, slip, state."""
        profile = self.json.get("profile") or {}
        return pd.DataFrame({c: profile.get(c, []) for c in PROFILE_COLUMNS})


class Result:
    """A solved scene. ``json`` is the summary ``contact2d run --json`` prints (the same numbers);
    the other attributes are views of it or of the solved fields."""

    def __init__(self, outcome: _core.Outcome) -> None:
        self._outcome = outcome
        #: The JSON summary as a dict, parsed from the exact text the CLI prints.
        self.json: dict[str, Any] = json.loads(outcome.json_text)

    def __repr__(self) -> str:
        return f"<contact2d.Result {self.json.get('scene')!r}: {self.status}, {len(self.json.get('steps', []))} steps>"

    @property
    def json_text(self) -> str:
        """The summary's JSON text, as ``contact2d run --json`` prints it."""
        return self._outcome.json_text

    @property
    def status(self) -> str:
        """The run's status: ``converged`` or why not (``max_iterations``, ...)."""
        return self.json["status"]

    @property
    def steps(self) -> pd.DataFrame:
        """The step table: one row per load step, columns the step's scalars by dotted path
        (status, iterations, work, dissipated, factors.<pattern>, contacts.<c>.normal_force,
        reactions.<group>.0, energies.<body>, kkt.<residual>, ...)."""
        rows = [flatten(step) for step in self.json.get("steps", [])]
        frame = pd.DataFrame(rows)
        frame.index = pd.RangeIndex(1, len(rows) + 1, name="step")
        return frame

    @property
    def contacts(self) -> dict[str, Contact]:
        """The interfaces by name, at the last step."""
        return {name: Contact(name, entry) for name, entry in self.json.get("contacts", {}).items()}

    @property
    def reactions(self) -> dict[str, list[float | None]]:
        """The reaction force of each fixed group, ``None`` for a free component."""
        return self.json["reactions"]

    @property
    def energies(self) -> dict[str, float]:
        """The strain energy of each body."""
        return self.json["energies"]

    @property
    def kkt(self) -> dict[str, float]:
        """The KKT residuals of the last step (penetration, complementarity, cone, ...)."""
        return self.json["kkt"]

    @property
    def path_error(self) -> float | None:
        """The error the step size causes, relative (``json["path_error"]``; docs/theory.md
        section 13): the run solved again with every step halved, the largest change of the
        contact forces (against the largest force of each interface) and of the dissipation
        (against the largest work), doubled. 0 for a run that cannot depend on the path (no
        friction, or solved once and scaled); ``None`` where it was not estimated. Per step:
        ``steps["path_error"]``."""
        return self.json.get("path_error")

    @property
    def paper(self) -> dict[str, Any] | None:
        """The paper's quantities (l, b, P, Phi_E1, ..., sigma_star, K) for the preset scenes of
        the plate with an insert; ``None`` for a generic scene."""
        return self.json.get("paper")

    @property
    def n_steps(self) -> int:
        """The number of solved steps whose displacement is kept."""
        return self._outcome.n_steps

    def displacement(self, step: int = -1) -> np.ndarray:
        """The displacement (u1, u2) of every mesh node at solved step ``step`` (from 0; negative
        counts from the end), an (n_nodes, 2) array."""
        return self._outcome.displacement(step)

    def stress(self, step: int = -1) -> np.ndarray:
        """The recovered nodal stresses at solved step ``step``, an (n_nodes, 4) array of
        (σ11, σ22, σ12, σ33) per node (MPa for the bundled scenes): the Gauss-point stresses
        extrapolated to the nodes and averaged over each body's cells, the ``stress`` of the VTU
        files. σ33 is the out-of-plane stress (0 in plane stress, ν(σ11 + σ22) in plane
        strain, the hoop stress σθθ for a body of revolution).
        A node of no body is NaN; a node shared by two bodies holds the later body's value."""
        return self._outcome.stress(step)

    @property
    def mesh(self) -> Mesh:
        """The mesh: points, cells by kind and physical groups as numpy arrays."""
        return Mesh(self._outcome)

    def to_meshio(self, step: int = -1) -> Any:
        """A ``meshio.Mesh`` with the displacement of ``step`` as point data ``u`` (needs the
        optional dependency meshio)."""
        import meshio  # noqa: PLC0415 (optional dependency)

        mesh = self.mesh
        return meshio.Mesh(
            mesh.points,
            [(kind, cells) for kind, cells, _ in mesh.cells],
            point_data={"u": self.displacement(step)},
        )

    def write(self, out_dir: str | Path) -> list[Path]:
        """Write the CLI's outputs (``contact2d run --out DIR``: summary.json, figures, CSV, VTU)
        into ``out_dir``; returns the paths written."""
        return [Path(p) for p in self._outcome.write(Path(out_dir))]


class Mesh:
    """The solved mesh (the scene's Gmsh mesh as the pipeline read it)."""

    def __init__(self, outcome: _core.Outcome) -> None:
        #: Node coordinates, (n_nodes, 2).
        self.points: np.ndarray = outcome.points()
        #: Cell blocks in file order: (meshio cell type, (n_cells, k) node indices, physical tags).
        self.cells: list[tuple[str, np.ndarray, list[int]]] = outcome.cells()
        #: Physical groups: name -> (dimension, tag).
        self.groups: dict[str, tuple[int, int]] = {name: (dim, tag) for name, dim, tag in outcome.groups()}

    def __repr__(self) -> str:
        kinds = ", ".join(f"{len(c)} {k}" for k, c, _ in self.cells)
        return f"<contact2d.Mesh {len(self.points)} points; {kinds}>"
