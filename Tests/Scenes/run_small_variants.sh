#!/bin/sh
# Runs every scene's small variant (the `soak run ...` line of its comment,
# or the scene itself when it has none) to the end, and checks finite stats.
# usage: SOAK=... run_small_variants.sh SOURCE_DIR OUTDIR
set -e
src=$1
out=$2
mkdir -p "$out"
cd "$src"
for f in Scenes/*.xml; do
  name=$(basename "$f" .xml)
  recipe=$(grep -m1 "^ *soak run " "$f" | sed 's/^ *soak run //')
  [ -n "$recipe" ] || recipe="$f"
  start=$(date +%s)
  eval "\"$SOAK\" run $recipe -o \"$out/$name\" --device cpu --quiet"
  if grep -qi "nan\|inf" "$out/$name/stats.csv"; then echo "$name: non-finite value in stats.csv"; exit 1; fi
  echo "$name: $(( $(date +%s) - start )) s, last row: $(tail -1 "$out/$name/stats.csv" | cut -d, -f2,4,5)"
done
