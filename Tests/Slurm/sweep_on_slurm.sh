#!/bin/bash
# `soak sweep` on a real Slurm (Doc/sweeps.md): a one-node Slurm started on
# this machine (local_slurm.sh) runs a sweep of 9 points of a small scene as
# a job array, 2 tasks at a time. Checks:
#  - every good point is done, and collected (a figure for each);
#  - a task cancelled mid-run (scancel) leaves its point interrupted with a
#    checkpoint; submitted again, only the points not done go, and that one
#    resumes from its checkpoint and writes frames byte-equal to an
#    uninterrupted run of the same point;
#  - the point with a bad value (a nozzle faster than Simulation.maxSpeed)
#    fails alone, with its error in the manifest.
# Where Slurm cannot start, the test fails and says why; it never skips.
#
#   sweep_on_slurm.sh SOAK SOURCE_DIR WORK_DIR
set -u
SOAK=$1
SOURCE=$2
WORK=$3
HERE=$(cd "$(dirname "$0")" && pwd)
. "$HERE/local_slurm.sh"

rm -rf "$WORK"
mkdir -p "$WORK"
SLURM_DIR="$WORK/slurm"
trap slurm_stop EXIT
started=$(date +%s)
slurm_start "$SLURM_DIR" 2

fail() { slurm_fail "$*"; }
# Waits (up to $2 seconds) until squeue lists nothing for job $1.
wait_for_job() {
  for _ in $(seq $(($2 * 2))); do
    [ -z "$(squeue -h -j "$1" -o %i 2>/dev/null)" ] && return 0
    sleep 0.5
  done
  squeue -a >&2
  fail "job $1 still in the queue after $2 s"
}
column_of() { head -n 1 "$1" | tr ',' '\n' | grep -n -x "$2" | cut -d: -f1; }
# The manifest's field $2 of the row of point $1.
field() { awk -F, -v id="$1" -v col="$(column_of "$SWEEP/manifest.csv" "$2")" '$1 == id { print $col }' "$SWEEP/manifest.csv"; }

FRAMES=60
SWEEP="$WORK/sweep"
cat > "$WORK/sweep.txt" <<EOF
# 8 nozzle speeds and one a run refuses (faster than Simulation.maxSpeed = 50 m/s)
scene = $SOURCE/Tests/Sweep/wet_sheet.xml
frames = $FRAMES
checkpoint_every = 2
device = cpu
vary Nozzle.speed = list 1.0 1.25 1.5 1.75 2.0 2.25 2.5 2.75 80
EOF
"$SOAK" sweep plan "$WORK/sweep.txt" -o "$SWEEP" || fail "soak sweep plan failed"
[ "$(tail -n +2 "$SWEEP/manifest.csv" | wc -l)" -eq 9 ] || fail "the plan has not 9 points: $(cat "$SWEEP/manifest.csv")"

out=$("$SOAK" sweep run "$SWEEP" --executor slurm --max-running 2 --cpus-per-task 1 --mem 500M) ||
  fail "soak sweep run --executor slurm failed: $out"
echo "$out"
job=$(echo "$out" | sed -n 's/.* as job \([0-9]*\) .*/\1/p')
[ -n "$job" ] || fail "no job id in: $out"
grep -q -- "--array=0-8%2" <<<"$out" || fail "the array is not 0-8%2: $out"
grep -q "^#SBATCH --requeue" "$SWEEP/slurm/sweep.sbatch" || fail "the script does not ask for --requeue"
grep -q "^#SBATCH --mem=500M" "$SWEEP/slurm/sweep.sbatch" || fail "the script does not carry --mem"

# Cancel the point of 1.5 m/s once it has a checkpoint and a few frames.
victim=$(awk -F, '$3 == "1.5" { print $1 }' "$SWEEP/manifest.csv")
task=$(($(grep -n -x "$victim" "$SWEEP/slurm/batch-000.txt" | cut -d: -f1) - 1))
run="$SWEEP/points/$victim/run"
for _ in $(seq 240); do
  [ -f "$run/checkpoint.soak" ] && [ -f "$run/water/water_000004.vtu" ] && break
  sleep 0.5
done
[ -f "$run/checkpoint.soak" ] || fail "point $victim (task ${job}_$task) never wrote a checkpoint"
[ -f "$run/water/water_0000$FRAMES.vtu" ] && fail "point $victim ended before it could be cancelled"
"$SOAK" sweep status "$SWEEP" | grep -q "^$victim .* running " ||
  fail "the point under way is not running in the status: $("$SOAK" sweep status "$SWEEP")"
scancel "${job}_$task" || fail "scancel ${job}_$task failed"
echo "cancelled task ${job}_$task (point $victim) mid-run"
wait_for_job "$job" 240

"$SOAK" sweep status "$SWEEP" || fail "soak sweep status failed"
[ "$(field "$victim" status)" = interrupted ] || fail "the cancelled point is '$(field "$victim" status)', not interrupted"
[ -f "$run/water/water_0000$FRAMES.vtu" ] && fail "the cancelled point ran to its end"
bad=$(awk -F, '$3 == "80" { print $1 }' "$SWEEP/manifest.csv")
[ "$(field "$bad" status)" = failed ] || fail "the point of 80 m/s is '$(field "$bad" status)', not failed"
[ "$(field "$bad" exit_code)" = 4 ] || fail "the point of 80 m/s exited $(field "$bad" exit_code), not 4 (unstable)"
grep "^$bad," "$SWEEP/manifest.csv" | grep -q "maxSpeed" || fail "the manifest does not give the bad point's error: $(grep "^$bad," "$SWEEP/manifest.csv")"
done_count=$(awk -F, 'NR > 1 && $4 == "done"' "$SWEEP/manifest.csv" | wc -l)
[ "$done_count" -eq 7 ] || fail "$done_count points done after the first submission, not 7: $(cat "$SWEEP/manifest.csv")"

# Submitted again: only the cancelled point and the failed one go.
out=$("$SOAK" sweep run "$SWEEP" --executor slurm --max-running 2 --cpus-per-task 1) || fail "resubmission failed: $out"
echo "$out"
job2=$(echo "$out" | sed -n 's/.* as job \([0-9]*\) .*/\1/p')
grep -q "submitted 2 point(s)" <<<"$out" || fail "the resubmission did not submit exactly the 2 points not done: $out"
sort "$SWEEP/slurm/batch-001.txt" | tr '\n' ' ' | grep -q -x "$(printf '%s\n' "$victim" "$bad" | sort | tr '\n' ' ')" ||
  fail "the resubmission's points are $(cat "$SWEEP/slurm/batch-001.txt"), not $victim and $bad"
wait_for_job "$job2" 240
"$SOAK" sweep status "$SWEEP" >/dev/null
[ "$(field "$victim" status)" = done ] || fail "the cancelled point is '$(field "$victim" status)' after the resubmission"
[ "$(field "$victim" attempts)" = 2 ] || fail "the cancelled point took $(field "$victim" attempts) attempts, not 2"
grep -q -- "run --resume $run" "$SWEEP/points/$victim/log.txt" || fail "the cancelled point did not resume from its checkpoint: $(cat "$SWEEP/points/$victim/log.txt")"
[ "$(field "$bad" status)" = failed ] || fail "the bad point is '$(field "$bad" status)' after the resubmission"
done_count=$(awk -F, 'NR > 1 && $4 == "done"' "$SWEEP/manifest.csv" | wc -l)
[ "$done_count" -eq 8 ] || fail "$done_count points done in the end, not 8"

# The resumed point's frames against an uninterrupted run of the same point.
"$SOAK" run "$SWEEP/points/$victim/scene.xml" -o "$WORK/whole" --frames $FRAMES --device cpu --threads 1 --quiet ||
  fail "the uninterrupted run failed"
compared=0
for f in "$WORK"/whole/water/*.vtu "$WORK"/whole/cloth_sheet/*.vtp; do
  other="$run/${f#"$WORK"/whole/}"
  cmp -s "$f" "$other" || fail "$other differs from the uninterrupted run's $f"
  compared=$((compared + 1))
done
[ "$compared" -eq $((2 * (FRAMES + 1))) ] || fail "compared $compared frame files, not $((2 * (FRAMES + 1)))"
echo "the resumed point's $compared frame files equal the uninterrupted run's byte for byte"

"$SOAK" sweep collect "$SWEEP" --plot held --against Nozzle.speed || fail "soak sweep collect failed"
collected=$(awk -F, -v c="$(column_of "$SWEEP/collect.csv" held)" 'NR > 1 && $c != ""' "$SWEEP/collect.csv" | wc -l)
[ "$collected" -eq 8 ] || fail "$collected points have a collected figure, not 8: $(cat "$SWEEP/collect.csv")"
grep -q "<polyline" "$SWEEP/plot-held.svg" || fail "the plot has no line"
echo "slurm sweep test: passed in $(($(date +%s) - started)) s"
