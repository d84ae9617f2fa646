#!/usr/bin/env bash
# First command of the README: install what is missing, build Release, run
# the default scene into a ParaView-ready folder. Idempotent.
set -euo pipefail
cd "$(dirname "$0")/../.."
bash Demos/scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release
bash Demos/scripts/install-python-module.sh build/release
scene=${SOAK_SCENE:-Scenes/fig1_jet.xml}
out=soak-out/default
# --overwrite: a second quickstart replaces the default run it wrote before.
build/release/bin/soak run "$scene" -o "$out" --overwrite "$@"
echo
echo "ParaView-ready output: $(pwd)/$out"
echo "  open it:   paraview $out/water.pvd   (then File > Open $out/cloth_sheet.pvd as well)"
echo "  (in ParaView: Apply, colour the cloth by 'saturation', show water as Point Gaussian; press Play)"
