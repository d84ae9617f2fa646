#!/bin/sh
# Catalyst Live: Tests/Catalyst/live_client.py, a pvpython Live client,
# listens, lets `soak run --live` connect, extracts the cloth twice, pauses
# and continues the run. Without pvpython or the adaptor it fails.
# usage: SOAK=... PVPYTHON=... live_and_check.sh SOURCE_DIR OUTDIR
set -e
src=$1
out=$2
if [ -z "$PVPYTHON" ] || ! command -v "$PVPYTHON" >/dev/null 2>&1; then
  echo "catalyst live test: no pvpython at '$PVPYTHON' (Debian: python3-paraview)" >&2
  exit 1
fi
rm -rf "$out"
mkdir -p "$out"
exec "$PVPYTHON" "$(dirname "$0")/live_client.py" "$SOAK" "$src/Scenes/fig7_small.xml" "$out"
