"""Builds ``meshes/generic/clamped_block.msh`` with the gmsh Python API (``pip install gmsh``).

A block [1, 3] × [1, 2] (mm) resting on a base [0, 4] × [0, 1], two bodies that touch along
y = 1 but share no node (a ``[[contact]]`` joins them). Structured quadrilaterals (Quad4), 8
cells along the block and 16 along the base, so the nodes of the two sides of the interface
face each other one to one (spacing 0.25 mm)::

              block_left  ┌────── block_top ──────┐  y = 2
                          │         block         │
                          └───── block_bottom ────┘  y = 1
        ┌────────────────────── base_top ───────────────────────┐  y = 1
        │                          base                         │
        └───────────────────── base_bottom ─────────────────────┘  y = 0
       x = 0              x = 1                   x = 3        x = 4

Run from the repository root: ``python3 python/examples/clamped_block_mesh.py`` (writes the
mesh; ``--show`` opens the gmsh window). The tutorial is ``docs/tutorials/clamped_block.md``;
the committed mesh is what the tests read, so they need no gmsh.
"""

from __future__ import annotations

import sys
from pathlib import Path

import gmsh

OUT = Path(__file__).resolve().parents[2] / "meshes" / "generic" / "clamped_block.msh"


def rectangle(x0: float, y0: float, x1: float, y1: float, nx: int, ny: int) -> tuple[int, list[int]]:
    """A structured rectangle: its surface tag and its edges (bottom, right, top, left), each
    drawn so that the surface's loop runs counter-clockwise (every cell does too)."""
    geo = gmsh.model.geo
    p = [geo.addPoint(x, y, 0.0) for x, y in ((x0, y0), (x1, y0), (x1, y1), (x0, y1))]
    edges = [geo.addLine(p[i], p[(i + 1) % 4]) for i in range(4)]
    surface = geo.addPlaneSurface([geo.addCurveLoop(edges)])
    geo.synchronize()
    for edge, n in zip(edges, (nx, ny, nx, ny), strict=True):
        gmsh.model.mesh.setTransfiniteCurve(edge, n + 1)
    gmsh.model.mesh.setTransfiniteSurface(surface)
    gmsh.model.mesh.setRecombine(2, surface)
    return surface, edges


def build(out: Path = OUT, show: bool = False) -> Path:
    """Meshes the two bodies and writes ``out`` (MSH 4.1)."""
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
        gmsh.model.add("clamped_block")
        base, (base_bottom, _, base_top, _) = rectangle(0.0, 0.0, 4.0, 1.0, 16, 4)
        block, (block_bottom, _, block_top, block_left) = rectangle(1.0, 1.0, 3.0, 2.0, 8, 4)
        groups = {
            (2, "base"): [base],
            (2, "block"): [block],
            (1, "base_bottom"): [base_bottom],
            (1, "base_top"): [base_top],
            (1, "block_bottom"): [block_bottom],
            (1, "block_top"): [block_top],
            (1, "block_left"): [block_left],
        }
        for (dim, name), tags in groups.items():
            gmsh.model.addPhysicalGroup(dim, tags, name=name)
        gmsh.model.mesh.generate(2)
        out.parent.mkdir(parents=True, exist_ok=True)
        gmsh.write(str(out))
        if show:
            gmsh.fltk.run()
    finally:
        gmsh.finalize()
    return out


if __name__ == "__main__":
    print(build(show="--show" in sys.argv))
