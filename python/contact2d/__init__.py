"""contact2d: 2D finite-element contact mechanics with Coulomb friction, from Python.

The package binds the one pipeline of the ``contact2d`` command line: a :class:`Scene` is the
TOML text of a scene file plus ``--set`` overrides, :func:`solve` runs it exactly as
``contact2d run SCENE --json`` does (the GIL released meanwhile) and returns a :class:`Result`
whose ``json`` is the CLI's summary, number for number.

Quick start::

    import contact2d
    result = contact2d.solve(contact2d.Scene.load("scenes/generic/pin_lug.toml").set("contact.bore.friction", 0.1))
    print(result.status, result.contacts["bore"].normal_force)
"""

from __future__ import annotations

from ._core import (
    Contact2dError,
    ContactError,
    MeshError,
    Scene,
    SceneError,
)
from .result import Contact, Result, solve
from .studies import compare, verify
from .sweep import sweep

__all__ = [
    "Contact",
    "Contact2dError",
    "ContactError",
    "MeshError",
    "Result",
    "Scene",
    "SceneError",
    "compare",
    "solve",
    "sweep",
    "verify",
]
