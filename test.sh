#!/usr/bin/env bash
# Every test of contact2d: the Rust workspace, then the Python package against the release CLI.
# Installs what Python needs (maturin, numpy, pandas, pytest, meshio, dask.distributed, nbclient, nbformat,
# ipykernel and matplotlib for the notebook, and the package itself, built from
# ./python with the workspace's target directory so that it reuses the Rust build).
set -euo pipefail
cd "$(dirname "$0")"

step() { echo "== [test.sh: $((SECONDS / 60)) min $((SECONDS % 60)) s] $1"; }
step "cargo test --workspace --release"
cargo test --workspace --release
step "the CLI binary, Python's packages, the wheel"
# The CLI binary the Python tests compare with.
cargo build --release --bin contact2d
python3 -m pip install --quiet --disable-pip-version-check maturin numpy pandas pytest meshio 'dask[distributed]' nbclient nbformat ipykernel matplotlib
# The wheel: `cargo build --locked` (python/pyproject.toml, `locked = true`), into the workspace's
# target directory with the workspace's debug setting, so that the dependencies compiled by the
# tests above are reused (python/Cargo.toml's release profile has no debug info).
CARGO_TARGET_DIR="$PWD/target" CARGO_PROFILE_RELEASE_DEBUG=line-tables-only \
    python3 -m pip install --quiet --disable-pip-version-check ./python
step "pytest"
python3 -m pytest python/tests -q --durations=15
step "done"
