#!/usr/bin/env bash
# Every test of contact2d: the Rust workspace, then the Python package against the release CLI.
# Installs what Python needs (maturin, numpy, pandas, pytest, meshio, dask.distributed, nbclient, nbformat,
# ipykernel and matplotlib for the notebook, and the package itself, built from
# ./python, a member of the workspace, so that it reuses the Rust build).
set -euo pipefail
cd "$(dirname "$0")"

step() { echo "== [test.sh: $((SECONDS / 60)) min $((SECONDS % 60)) s] $1"; }
step "cargo test --workspace --release"
cargo test --workspace --release
step "Python's packages, the wheel"
# The CLI binary the Python tests compare with is target/release/contact2d, built by `cargo test`
# for the integration tests (CARGO_BIN_EXE_contact2d).
python3 -m pip install --quiet --disable-pip-version-check maturin numpy pandas pytest meshio 'dask[distributed]' nbclient nbformat ipykernel matplotlib
# The wheel: maturin's `cargo build --locked -p contact2d-python` in this workspace (python/ is a
# member), so that it reuses what `cargo test` compiled above: the same features
# (.ci/feature-sets), the same profile, the same target directory. Only the binding, pyo3 and the
# root crate without its command line are compiled.
python3 -m pip install --quiet --disable-pip-version-check ./python
step "pytest"
python3 -m pytest python/tests -q --durations=15
step "done"
