"""Poses a clamped joint from Python on the mesh of ``clamped_block_mesh.py`` (the tutorial
``docs/tutorials/clamped_block.md``): a block clamped onto a base through a reference point with
a force P and a moment M, its side support released after the clamp, then pulled through the same
point until friction lets go.

Run from anywhere (needs the ``contact2d`` package: ``pip install ./python``)::

    python3 python/examples/clamped_block_joint.py

The scene is a plain dict with the schema of the TOML scene files (``docs/user-guide.md``); the
committed mesh ``meshes/generic/clamped_block.msh`` is read, so gmsh is not needed here.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import contact2d

ROOT = Path(__file__).resolve().parents[2]
MESH = ROOT / "meshes" / "generic" / "clamped_block.msh"
#: The reference point: the middle of the block's top.
CLAMP_AT = (2.0, 2.0)


def joint(clamp: float = 1000.0, moment: float = 100.0, pull: float = 1000.0, mu: float = 0.35,
          pull_factors: tuple[float, ...] = (0.1, 0.2, 0.3, 0.4, 0.5)) -> dict[str, Any]:
    """The joint as a scene dict: the clamp force ``clamp`` (N/mm, downwards) and ``moment``
    (N·mm/mm, counter-clockwise) on the point in step 1 with the block's left side held in u1,
    then that support released and the point pulled by ``pull`` × each of ``pull_factors``."""
    steel = {"youngs_modulus": 2.0e5, "poissons_ratio": 0.3}
    return {
        "name": "clamped_joint",
        "mesh": str(MESH),
        "plane": "strain",
        "body": [{"region": "base", **steel}, {"region": "block", **steel}],
        "fix": [
            {"group": "base_bottom", "u1": 0.0, "u2": 0.0},
            # the side support: it holds the block while it is clamped, released after step 1
            {"group": "block_left", "u1": 0.0, "until_step": 1},
        ],
        "point": [{"name": "clamp", "at": list(CLAMP_AT), "group": "block_top", "coupling": "distributing"}],
        "load": [
            {"point": "clamp", "force": [0.0, -clamp], "moment": moment, "pattern": "clamp"},
            {"point": "clamp", "force": [pull, 0.0], "pattern": "pull"},
        ],
        "contact": [{"name": "joint", "master": "block_bottom", "slave": "base_top", "friction": mu}],
        "loading": {
            "schedule": [{"clamp": 1.0}] + [{"clamp": 1.0, "pull": f} for f in pull_factors],
            "path_error": False,
        },
        "solver": {"algorithm": "active_set"},
    }


def solve(**kwargs: Any) -> contact2d.Result:
    """Solves :func:`joint` with the moments taken about the reference point."""
    return contact2d.solve(contact2d.Scene.from_dict(joint(**kwargs)), about=CLAMP_AT)


def main(clamp: float = 1000.0, pull: float = 1000.0, mu: float = 0.35) -> None:
    result = solve(clamp=clamp, pull=pull, mu=mu)
    print(f"status: {result.status}")
    for row in result.json["steps"]:
        c = row["contacts"]["joint"]
        side = row["reaction_moments"].get("block_left", 0.0)
        print(f"pull {row['factors'].get('pull', 0.0):.1f}: {row['status']:>10}  N = {c['normal_force']:8.2f}"
              f"  T = {c['resultant'][0]:7.2f}  moment about the point = {c['moment']:8.3f}"
              f"  (side support's {side:8.3f})")
    held = result.json.get("not_held")
    if held:
        print(f"not held at step {held['step']}: last held pull factor {held['last_held_factors']['pull']}"
              f" (mu P / F = {mu * clamp / pull:.2f}), demanded/available = {held['ratio']:.3f}")


if __name__ == "__main__":
    main()
