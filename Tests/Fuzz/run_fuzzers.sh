#!/bin/sh
# Runs the two libFuzzer targets for SECONDS each, from seed corpora taken
# from the scenes and the bad-input corpus. Exit status non-zero if either
# found a crash, a leak or undefined behaviour (the input is kept in OUT).
#   run_fuzzers.sh BIN_DIR SOURCE_DIR OUT SECONDS
set -eu
bin=$(cd "$1" && pwd) src=$(cd "$2" && pwd) out=$3 seconds=$4
rm -rf "$out" && mkdir -p "$out/scene" "$out/obj" "$out/scene_seeds" "$out/obj_seeds"
cp "$src"/Scenes/*.xml "$src"/Tests/BadInput/*.xml "$out/scene_seeds/"
for f in "$src"/Scenes/small/*.xml; do cp "$f" "$out/scene_seeds/small_$(basename "$f")"; done
out=$(cd "$out" && pwd)
cp "$src"/Tests/BadInput/*.obj "$src"/Tests/Fuzz/seeds/*.obj "$out/obj_seeds/"
status=0
for target in scene obj; do
  echo "fuzzing the $target loader for $seconds s"
  (cd "$out" && "$bin/soak_fuzz_$target" -max_total_time="$seconds" -rss_limit_mb=2048 -max_len=65536 \
     -print_final_stats=1 -artifact_prefix="$out/$target-" "$out/$target" "$out/${target}_seeds" 2>&1 | tail -25) || status=1
  ls "$out/$target-"* 2>/dev/null && status=1
done
exit $status
