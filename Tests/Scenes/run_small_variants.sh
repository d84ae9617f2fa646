#!/bin/sh
# Runs every scene's small variant (the `soak run ...` line of its comment,
# or the scene itself when it has none) to the end, and checks finite stats.
# usage: SOAK=... run_small_variants.sh SOURCE_DIR OUTDIR
set -e

. "$(cd "$(dirname "$0")" && pwd)/check_stats.sh"
src=$1
out=$2
mkdir -p "$out"
cd "$src"
for f in Scenes/*.xml; do
  name=$(basename "$f" .xml)
  recipe=$(grep -m1 "^ *soak run " "$f" | sed 's/^ *soak run //')
  [ -n "$recipe" ] || recipe="$f"
  start=$(date +%s)
  eval "\"$SOAK\" run $recipe -o \"$out/$name\" --overwrite --device cpu --quiet"
  stats_ok "$out/$name/stats.csv" || { echo "$name: bad stats"; exit 1; }
  echo "$name: $(( $(date +%s) - start )) s, last row: $(tail -1 "$out/$name/stats.csv" | cut -d, -f2,4,5)"
done
