"""Shared fixtures: the repository root, the release CLI binary (the truth the bindings are held
to) and a helper that runs it."""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parents[2]


def cli_binary() -> Path:
    """The CLI the bindings are compared with: $CONTACT2D_CLI, else target/release/contact2d."""
    path = Path(os.environ.get("CONTACT2D_CLI", ROOT / "target" / "release" / "contact2d"))
    if not path.is_file():
        pytest.fail(f"no CLI binary at {path}: run `cargo build --release` first (or set CONTACT2D_CLI)")
    return path


def run_cli(*args: str) -> subprocess.CompletedProcess[str]:
    """Runs the CLI from the repository root."""
    return subprocess.run([str(cli_binary()), *args], cwd=ROOT, capture_output=True, text=True, timeout=600)


def cli_json(scene: Path, *sets: str) -> dict[str, Any]:
    """`contact2d run SCENE --json [--set ...]` as a dict."""
    args = ["run", str(scene), "--json", "--quiet"]
    for s in sets:
        args += ["--set", s]
    done = run_cli(*args)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def cli_error(*args: str) -> str:
    """The CLI's one-line error message (stderr without the `error: ` prefix) of a failing run."""
    done = run_cli(*args)
    assert done.returncode == 1, (done.returncode, done.stdout, done.stderr)
    line = done.stderr.strip().splitlines()[-1]
    assert line.startswith("error: "), line
    return line.removeprefix("error: ")
