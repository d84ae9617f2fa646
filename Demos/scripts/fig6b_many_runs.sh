#!/usr/bin/env bash
# Many whole runs of fig6b_emission on a lent GPU machine, from a bundle
# (../shared/tools/device-bundle BUNDLE build/release/bin/soak -- Scenes),
# to see how often the sheet tangles or flails (Doc/performance.md,
# "fig6b's tangles and the end velocity's limit (H100)"):
#
#   T=4 J=16 Demos/scripts/fig6b_many_runs.sh BUNDLE 'name|options' ...
#
# Each argument is one run: its name and its soak options, where $DEF
# stands for the default counts (the scene's counts given back to the
# solver). T: simulated seconds (8); J: runs at once (16). Results in $OUT
# (default /tmp/soak-fig6b-runs): log.txt (exit codes, then
# tangle_summary.py's line per run) and csv.tgz (every run's stats.csv).
set -u
bundle=$(cd "${1:?usage: $0 BUNDLE 'name|options' ...}" && pwd)
shift
repo=$(cd "$(dirname "$0")/../.." && pwd)
out=${OUT:-/tmp/soak-fig6b-runs}
mkdir -p "$out"
work=$(mktemp -d)
DEF="--set Simulation.clothSubsteps=0 --set Simulation.clothIterations=0 --set Simulation.clothSubstepTravel=-1 --set Simulation.clothStrainTarget=-1"
cd "$("$bundle/run" --data)"  # the bundle's Scenes/
i=0
for spec in "$@"; do
  IFS='|' read -r name opts <<< "$spec"
  opts=${opts//\$DEF/$DEF}
  ( "$bundle/run" soak run Scenes/fig6b_emission.xml --device cuda -o "$work/$name" --overwrite --quiet \
      --time "${T:-8}" $opts > "$work/$name.log" 2>&1
    echo "$name rc=$? $(tail -c 300 "$work/$name.log" | tr '\n' ' ')" >> "$out/log.txt"
    cp "$work/$name/stats.csv" "$work/$name.csv" ) &
  i=$((i + 1)); [ $((i % ${J:-16})) -eq 0 ] && wait
done
wait
python3 "$repo/Demos/scripts/tangle_summary.py" "$work"/*.csv >> "$out/log.txt" 2>&1
(cd "$work" && tar czf "$out/csv.tgz" ./*.csv)
rm -rf "$work"
