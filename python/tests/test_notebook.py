"""The tutorial docs/notebooks/pin_in_lug.ipynb executes from start to end (nbclient, a fresh
Python kernel, from the notebook's own folder as Jupyter runs it). Its own cells assert what it
shows: equilibrium of the pin (contact resultant and lug reaction = the push within 1e-6) and a
sweep whose six cases converge."""

from __future__ import annotations

import pytest
from conftest import ROOT

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")
pytest.importorskip("matplotlib")
pytest.importorskip("distributed")

NOTEBOOK = ROOT / "docs" / "notebooks" / "pin_in_lug.ipynb"


def test_the_tutorial_notebook_executes() -> None:
    # The kernel draws with matplotlib's inline backend (no display needed).
    notebook = nbformat.read(NOTEBOOK, as_version=4)
    client = nbclient.NotebookClient(
        notebook,
        timeout=300,  # per cell; the sweep's cell takes about 10 s on 2 loaded cores
        kernel_name="python3",
        resources={"metadata": {"path": str(NOTEBOOK.parent)}},
    )
    client.execute()  # raises CellExecutionError with the failing cell's traceback
    errors = [o for c in notebook.cells if c.cell_type == "code" for o in c.get("outputs", []) if o.output_type == "error"]
    assert errors == []
    # The two figures were drawn.
    images = [o for c in notebook.cells for o in c.get("outputs", []) if "image/png" in o.get("data", {})]
    assert len(images) == 2
