#!/bin/sh
# Runs the four libFuzzer targets for SECONDS each: the scene loader, the
# OBJ loader, the checkpoint reader and `soak run`'s command line, from seed
# corpora taken from the scenes, the bad-input corpus, Tests/Fuzz/seeds and
# Tests/Fuzz/cli_seeds. Exit status non-zero if any found a crash, a leak,
# undefined behaviour or a memory bomb (the input is kept in OUT).
#   run_fuzzers.sh BIN_DIR SOURCE_DIR OUT SECONDS
set -eu
bin=$(cd "$1" && pwd) src=$(cd "$2" && pwd) out=$3 seconds=$4
rm -rf "$out"
for target in scene obj checkpoint cli; do mkdir -p "$out/$target" "$out/${target}_seeds"; done
out=$(cd "$out" && pwd)
# Regular files only: the corpus also holds a link to /dev/zero and a folder.
find "$src/Scenes" "$src/Tests/BadInput" -maxdepth 1 -type f -name '*.xml' -exec cp {} "$out/scene_seeds/" \;
for f in "$src"/Scenes/small/*.xml; do cp "$f" "$out/scene_seeds/small_$(basename "$f")"; done
find "$src/Tests/BadInput" "$src/Tests/Fuzz/seeds" -maxdepth 1 -type f -name '*.obj' -exec cp {} "$out/obj_seeds/" \;
(cd "$out" && SOAK_FUZZ_SEED="$out/checkpoint_seeds/sample.soak" "$bin/soak_fuzz_checkpoint" > "$out/checkpoint_seed.log" 2>&1) ||
  { echo "could not write the checkpoint seed"; cat "$out/checkpoint_seed.log"; exit 1; }
mkdir -p "$out/cli_files"
find "$src/Tests/BadInput" -maxdepth 1 -type f -exec cp {} "$out/cli_files/" \;
cp "$src"/Tests/Fuzz/cli_seeds/* "$out/cli_seeds/"
status=0
for target in scene obj checkpoint cli; do
  echo "fuzzing the $target reader for $seconds s"
  (cd "$out" && "$bin/soak_fuzz_$target" -max_total_time="$seconds" -rss_limit_mb=2048 -max_len=65536 \
     -print_final_stats=1 -artifact_prefix="$out/$target-" "$out/$target" "$out/${target}_seeds" 2>&1 | tail -25) || status=1
  ls "$out/$target-"* 2>/dev/null && status=1
done
exit $status
