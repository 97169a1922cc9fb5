#!/usr/bin/env bash
# Builds the teaching page's WebAssembly module into web/pkg (git-ignored); then serve web/ with
# any static server, e.g. `python3 -m http.server -d web 8000`, and open http://localhost:8000.
#
# On a fresh machine with Rust: adds the wasm32 target, installs wasm-bindgen-cli at the exact
# version of the wasm-bindgen crate in Cargo.lock (skipped when already installed), builds the
# crate contact2d-web for wasm32-unknown-unknown and generates the JavaScript bindings.
# JOBS=1 web/build.sh limits cargo to one job (a busy machine).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
target_dir=${CARGO_TARGET_DIR:-$root/target}

rustup target add wasm32-unknown-unknown >/dev/null

version=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/[^0-9.]/, ""); print; exit }' Cargo.lock)
if [ -z "$version" ]; then
    echo "build.sh: no wasm-bindgen in Cargo.lock" >&2
    exit 1
fi
if ! command -v wasm-bindgen >/dev/null || [ "$(wasm-bindgen --version | awk '{print $2}')" != "$version" ]; then
    echo "== cargo install wasm-bindgen-cli $version"
    cargo install wasm-bindgen-cli --version "$version" ${JOBS:+-j "$JOBS"}
fi

echo "== cargo build -p contact2d-web --target wasm32-unknown-unknown"
# No debug info: wasm-bindgen drops it anyway, and leaving it out shortens the build.
CARGO_PROFILE_RELEASE_DEBUG=false \
    cargo build --release --lib -p contact2d-web --target wasm32-unknown-unknown ${JOBS:+-j "$JOBS"}

echo "== wasm-bindgen --target web -> web/pkg"
wasm-bindgen --target web --no-typescript --out-dir web/pkg \
    "$target_dir/wasm32-unknown-unknown/release/contact2d_web.wasm"
# The bundled generic scenes' files (those compiled into the module), offered on the "Your
# scene" tab as example .toml + .msh pairs to download.
mkdir -p web/pkg/examples
grep -o 'include_[a-z]*!("../../../\(scenes\|meshes\)/generic/[^"]*")' crates/web/src/generic_scene.rs |
    sed 's|.*"\.\./\.\./\.\./\(.*\)")|\1|' | while read -r f; do cp "$f" web/pkg/examples/; done
ls -l web/pkg/contact2d_web_bg.wasm | awk '{printf "web/pkg/contact2d_web_bg.wasm: %.2f MB\n", $5 / 1e6}'
