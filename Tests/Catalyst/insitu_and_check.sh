#!/bin/sh
# Catalyst in situ: a short Scenes/fig7_small.xml run with
# Tests/Catalyst/picture_and_csv.py, a picture and two CSV extracts every
# frame, checked against the run's files by check_insitu.py. Without
# pvpython, Xvfb or the Catalyst adaptor it fails.
# usage: SOAK=... PVPYTHON=... XVFB=... insitu_and_check.sh SOURCE_DIR OUTDIR
set -e
src=$1
out=$2
here=$(cd "$(dirname "$0")" && pwd)
frames=14   # 0.47 s: the block lands on the sheet and wets it
if [ -z "$PVPYTHON" ] || ! command -v "$PVPYTHON" >/dev/null 2>&1; then
  echo "catalyst test: no pvpython at '$PVPYTHON' (Debian: python3-paraview)" >&2
  exit 1
fi
rm -rf "$out"
sh "$here/with_display.sh" "$SOAK" run "$src/Scenes/fig7_small.xml" -o "$out/run" --frames $frames --device cpu \
  --quiet --catalyst "$here/picture_and_csv.py"
exec "$PVPYTHON" "$here/check_insitu.py" "$out/run" $frames
