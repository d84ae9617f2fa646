#!/bin/sh
# Runs a scene for its first output frame (a few steps) and checks that it
# wrote finite stats. usage: SOAK=... run_scene.sh SCENE OUTDIR
set -e

. "$(dirname "$0")/check_stats.sh"
scene=$1
out=$2
rm -rf "$out"
"$SOAK" run "$scene" -o "$out" --frames 1 --device cpu --quiet
rows=$(wc -l < "$out/stats.csv")
[ "$rows" -eq 3 ] || { echo "run_scene: expected 2 frames in $out/stats.csv, found $((rows - 1))"; exit 1; }
stats_ok "$out/stats.csv" || { echo "run_scene: bad stats for $scene"; exit 1; }
echo "run_scene: $scene ok ($(tail -1 "$out/stats.csv" | cut -d, -f4,5 | tr , ' ') water, cloth particles)"
