#!/bin/sh
# Runs a scene for its first output frame (a few steps) and checks that it
# wrote finite stats. usage: SOAK=... run_scene.sh SCENE OUTDIR
set -e

# Cloth edge strain stays below 100 % (a wall or a bad pin tears a sheet).
strain_ok() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "max_stretch") c = i; next }
           c && $c + 0 > 1.0 { print "max_stretch " $c " at t = " $2; bad = 1 } END { exit bad }' "$1"
}
scene=$1
out=$2
rm -rf "$out"
"$SOAK" run "$scene" -o "$out" --frames 1 --device cpu --quiet
rows=$(wc -l < "$out/stats.csv")
[ "$rows" -eq 3 ] || { echo "run_scene: expected 2 frames in $out/stats.csv, found $((rows - 1))"; exit 1; }
if grep -qi "nan\|inf" "$out/stats.csv"; then echo "run_scene: non-finite value in $out/stats.csv"; exit 1; fi
strain_ok "$out/stats.csv" || { echo "run_scene: cloth torn in $scene"; exit 1; }
echo "run_scene: $scene ok ($(tail -1 "$out/stats.csv" | cut -d, -f4,5 | tr , ' ') water, cloth particles)"
