#!/usr/bin/env bash
# The teaching page's tests (after web/build.sh): the native reference numbers, the node test
# (the WebAssembly module returns them to 1e-12) and the headless-browser tests (Chromium +
# puppeteer-core; screenshots in web/out/): the physics on the page (browser.mjs) and the
# page's defects of issue 24 (browser_page.mjs), issue 42's (browser_teaching.mjs, browser_present.mjs) and
# the ball on a plate of issue 43 (browser_ball.mjs). Installs Debian's chromium (as root) and the npm
# package when missing. Every step is wrapped in `timeout`.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p web/out
if [ ! -f web/pkg/contact2d_web_bg.wasm ]; then
    echo "test.sh: web/pkg is missing: run web/build.sh first" >&2
    exit 1
fi

echo "== native reference numbers -> web/out/reference.json"
# Built with the whole workspace's package selection, whose features are those `cargo test
# --workspace --release` (../test.sh) compiled (.ci/feature-sets), so nothing but this binary is
# compiled again (`cargo run -p contact2d-web` would resolve the features of this crate alone and
# compile the pipeline and faer once more).
timeout 1200 cargo build --quiet --release --workspace --bins
timeout 1200 "${CARGO_TARGET_DIR:-target}/release/web_reference" > web/out/reference.json

echo "== node: the WebAssembly module returns the native numbers"
timeout 600 node web/tests/wasm_matches_native.mjs web/out/reference.json

if ! command -v chromium >/dev/null; then
    echo "== apt-get install chromium"
    timeout 600 apt-get update -qq
    DEBIAN_FRONTEND=noninteractive timeout 600 apt-get install -y -qq --no-install-recommends chromium >/dev/null
fi
if [ ! -d web/node_modules/puppeteer-core ]; then
    echo "== npm install (puppeteer-core, no browser download)"
    (cd web && timeout 300 npm install --no-audit --no-fund --loglevel=error)
fi

echo "== headless Chromium: the page"
timeout 600 node web/tests/browser.mjs web/out/reference.json

echo "== headless Chromium: issue 24's defects (state, readability, URL, export, a user's scene)"
timeout 900 node web/tests/browser_page.mjs web/out/reference.json

echo "== headless Chromium: issue 42 (the smaller items, each scene's limits)"
timeout 600 node web/tests/browser_teaching.mjs

echo "== headless Chromium: issue 42 (the player of histories and cycles)"
timeout 600 node web/tests/browser_present.mjs

echo "== headless Chromium: issue 43 (the ball on a plate: Hertz's sphere, page = native CLI)"
timeout 600 node web/tests/browser_ball.mjs
