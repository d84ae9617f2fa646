#!/bin/sh
# Runs a scene with soak, then opens the output with ParaView's own reader.
# usage: SOAK=... PVPYTHON=... run_and_check.sh SCENE OUTDIR
set -e
scene=$1
out=$2
rm -rf "$out"
"$SOAK" run "$scene" -o "$out" --frames 6 --device cpu --quiet --set Simulation.frameRate=20
exec "$PVPYTHON" --force-offscreen-rendering "$(dirname "$0")/check_output.py" "$out" 6 20
