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
step "Python's packages, the wheel"
# The CLI binary the Python tests compare with is target/release/contact2d, built by `cargo test`
# for the integration tests (CARGO_BIN_EXE_contact2d). A separate `cargo build --bin` would
# resolve the features without the dev-dependencies and compile the libraries again (2 min 56 s
# in the 2026-11-29 clean-clone CI).
python3 -m pip install --quiet --disable-pip-version-check maturin numpy pandas pytest meshio 'dask[distributed]' nbclient nbformat ipykernel matplotlib
# The wheel: `cargo build --locked` (python/pyproject.toml, `locked = true`), into the workspace's
# target directory with the workspace's debug setting (python/Cargo.toml's release profile has no
# debug info), so that what the tests above compiled with the same features is reused; today some
# dependencies' features differ and faer, nalgebra and clarabel compile again (docs/benchmarks.md,
# "Installing the Python package").
CARGO_TARGET_DIR="$PWD/target" CARGO_PROFILE_RELEASE_DEBUG=line-tables-only \
    python3 -m pip install --quiet --disable-pip-version-check ./python
step "pytest"
python3 -m pytest python/tests -q --durations=15
step "done"
