#!/bin/sh
# Runs every scene's small variant (the `soak run ...` line of its comment,
# or the scene itself when it has none) to the end, and checks finite stats.
# usage: SOAK=... run_small_variants.sh SOURCE_DIR OUTDIR
set -e

# Cloth edge strain stays below 100 % (a wall or a bad pin tears a sheet).
strain_ok() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "max_stretch") c = i; next }
           c && $c + 0 > 1.0 { print "max_stretch " $c " at t = " $2; bad = 1 } END { exit bad }' "$1"
}
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
  strain_ok "$out/$name/stats.csv" || { echo "$name: cloth torn"; exit 1; }
  echo "$name: $(( $(date +%s) - start )) s, last row: $(tail -1 "$out/$name/stats.csv" | cut -d, -f2,4,5)"
done
