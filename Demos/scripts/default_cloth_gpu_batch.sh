#!/usr/bin/env bash
# The default cloth solver's GPU measurements (Doc/performance.md, "The
# default cloth, whole runs and Table 2's cost (H100)"), as one batch for a
# lent GPU machine that has none of our Debian libraries: the programs come
# from a bundle (../shared/tools/device-bundle BUNDLE build/release/bin/soak
# build/release/bin/soak-bench build/release/bin/soak_gpu_tests -- Scenes),
# this script and worst_strain.py from the repository's copy there.
#
#   Demos/scripts/default_cloth_gpu_batch.sh BUNDLE [tests|bench|runs|scale|fig6b|all]
#
# Results go to $OUT (default /tmp/soak-gpu-batch), at most eight files:
#   gpu.txt        the GPU, each part's start, the tests' summary, run exit codes
#   tests.txt      soak_gpu_tests
#   bench_*.txt    soak-bench, the scene files' counts (named) and the default counts, alternated
#   runs.txt       worst_strain.py over whole runs, as the scenes are (r_) and with the default counts (d_)
#   fig6b_*.csv    fig6b_emission with the default counts: stats.csv of each variant (part fig6b)
# `all` runs tests, bench, runs and scale in that order; fig6b runs only when named.
# EXTRA (environment): options added to every run and bench, e.g.
# EXTRA="--set Simulation.clothSpectralRadius=0.9".
set -u
bundle=$(cd "${1:?usage: $0 BUNDLE [part]}" && pwd)
part=${2:-all}
repo=$(cd "$(dirname "$0")/../.." && pwd)
out=${OUT:-/tmp/soak-gpu-batch}
mkdir -p "$out"
work=$(mktemp -d)
run() { "$bundle/run" "$@"; }
worst() { python3 "$repo/Demos/scripts/worst_strain.py" "$@"; }
DEF="--set Simulation.clothSubsteps=0 --set Simulation.clothIterations=0 --set Simulation.clothSubstepTravel=-1 --set Simulation.clothStrainTarget=-1"
X=${EXTRA:-}
want() { [ "$part" = all ] || [ "$part" = "$1" ]; }
log() { echo "== $* $(date +%T)" >> "$out/gpu.txt"; }
cd "$(run --data)"  # the bundle's Scenes/
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader >> "$out/gpu.txt" 2>&1

if want tests; then
  log tests
  timeout 300 "$bundle/run" soak_gpu_tests > "$out/tests.txt" 2>&1
  echo "soak_gpu_tests rc=$?" >> "$out/gpu.txt"
  grep -E "^\[  (PASSED|FAILED) " "$out/tests.txt" >> "$out/gpu.txt"
fi

if want bench; then
  for round in 1 2; do
    log "bench round $round"
    run soak-bench --device cuda --scenes Scenes $X > "$out/bench_named_$round.txt" 2>&1
    run soak-bench --device cuda --scenes Scenes $DEF $X > "$out/bench_def_$round.txt" 2>&1
  done
fi

# soak run SCENE, four at a time: "scene|folder|options".
run_all() {
  local i=0 s o a
  for j in "$@"; do
    IFS='|' read -r s o a <<< "$j"
    ( run soak run "$s" --device cuda -o "$work/$o" --overwrite --quiet $a $X > "$work/$o.log" 2>&1
      echo "$o rc=$?" >> "$out/gpu.txt" ) &
    i=$((i + 1)); [ $((i % 4)) -eq 0 ] && wait
  done
  wait
}

if want runs; then
  log runs
  # The README's "Wetting a scene" example and the sheet hung by a diagonal (Doc/performance.md, "Default cloth solver").
  cat > "$work/readme.xml" <<'EOF'
<Scene>
  <Cloth name="sheet" origin="-0.6 1.5 0" axisU="1 0 0" axisV="0 -1 0" width="1.2" height="1.2" pinCorners="u0v0 u1v0"/>
  <Nozzle position="0 1.0 0.8" direction="0 0.1 -1" radius="0.05" speed="4.0" stop="6"/>
  <Plane/>
  <WetCloth/>
</Scene>
EOF
  cat > "$work/diag.xml" <<'EOF'
<Scene>
  <Simulation duration="5"/>
  <Cloth name="sheet" origin="-0.6 1.9 0" axisU="1 0 0" axisV="0 -1 0" width="1.2" height="1.2" cellsU="39" cellsV="39" pinCorners="u0v0 u1v1"/>
</Scene>
EOF
  jobs=()
  for s in Scenes/*.xml; do jobs+=("$s|r_$(basename "$s" .xml)|"); done
  for n in fig1_jet fig3a_dry_drop fig3b_wet_drop fig6b_emission fig7_small fig9a_ball fig9b_ball_sticky sheet_drape_ball; do
    jobs+=("Scenes/$n.xml|d_$n|$DEF")
  done
  jobs+=("$work/readme.xml|r_readme|--time 4" "$work/diag.xml|r_diag|")
  run_all "${jobs[@]}"
  worst "$work"/r_*/ "$work"/d_*/ >> "$out/runs.txt" 2>&1
fi

if want scale; then
  log scale
  mkdir -p "$work/sc"
  run soak-bench --scale 100k,1M --write-scale-scenes "$work/sc" > /dev/null 2>&1
  run_all "$work/sc/scale_100k.xml|r_scale100k|--time 2" "$work/sc/scale_1M.xml|r_scale1M|--time 1.5"
  worst "$work/r_scale100k/" "$work/r_scale1M/" >> "$out/runs.txt" 2>&1
  run soak-bench --device cuda --no-table2 --scale 100k,1M $X > "$out/bench_scale.txt" 2>&1
fi

if [ "$part" = fig6b ]; then
  # fig6b with the default counts, frame by frame (sub-steps, strain, step_ms): two runs as it is, one without
  # the strain redo, one without wet sticking, and one with the scene's own counts (Doc/performance.md, "The
  # default cloth, whole runs and Table 2's cost (H100)").
  log fig6b
  run_all "Scenes/fig6b_emission.xml|fig6b_def|$DEF" "Scenes/fig6b_emission.xml|fig6b_def2|$DEF" \
          "Scenes/fig6b_emission.xml|fig6b_noredo|$DEF --set Simulation.clothStrainRedo=0" \
          "Scenes/fig6b_emission.xml|fig6b_nostick|$DEF --set WetCloth.sticking=false" \
          "Scenes/fig6b_emission.xml|fig6b_named|"
  for v in def def2 noredo nostick named; do cp "$work/fig6b_$v/stats.csv" "$out/fig6b_$v.csv" 2>/dev/null; done
  worst "$work"/fig6b_*/ >> "$out/gpu.txt" 2>&1
  # Its cost over 500 steps rather than the bench's 50, three rounds alternated (the scene's counts, then the default's).
  log "fig6b bench"
  for round in 1 2 3; do
    run soak-bench --device cuda --scenes Scenes --only fig6b_emission --steps 500 $X 2>&1 | grep "^| fig6b" >> "$out/gpu.txt"
    run soak-bench --device cuda --scenes Scenes --only fig6b_emission --steps 500 $DEF $X 2>&1 | grep "^| fig6b" >> "$out/gpu.txt"
  done
fi
log done
rm -rf "$work"
