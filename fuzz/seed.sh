#!/bin/sh
# Seeds the fuzz corpora from the committed meshes and scenes (run from fuzz/).
set -eu
mkdir -p corpus/msh corpus/scene
cp ../meshes/fixtures/*.msh corpus/msh/
cp ../meshes/plate_insert/plate_insert_eps0_N16.msh corpus/msh/
cp ../tests/bad_inputs/*.msh corpus/msh/ 2>/dev/null || true
cp ../scenes/*.toml corpus/scene/
cp ../tests/bad_inputs/*.toml corpus/scene/ 2>/dev/null || true
