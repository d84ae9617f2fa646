#!/bin/sh
# Runs a small wet scene, renders its last frame with Doc/render.py under
# Xvfb, and checks the picture (Tests/ParaView/check_render.py).
# usage: SOAK=... PVPYTHON=... XVFB_RUN=... render_and_check.sh SOURCE_DIR OUTDIR
set -e
src=$1
out=$2
rm -rf "$out"
"$SOAK" run "$src/Scenes/fig1_jet.xml" -o "$out" --device cpu --quiet --time 0.4 \
  --set Cloth.cellsU=29 --set Cloth.cellsV=29 --set Simulation.frameRate=10
# A display number of our own: xvfb-run -a can race with a server that is
# still shutting down ("bad X server connection"); try three.
ok=0
for attempt in 1 2 3; do
  if "$XVFB_RUN" -n $(( 100 + ($$ + attempt * 97) % 800 )) -s "-screen 0 1280x1024x24" \
       "$PVPYTHON" "$src/Doc/render.py" "$out" --frame -1 --size 640x400 --no-animation; then
    ok=1
    break
  fi
done
[ "$ok" -eq 1 ] || { echo "render_and_check: Doc/render.py failed three times"; exit 1; }
exec "$PVPYTHON" "$(dirname "$0")/check_render.py" "$out/render/frame_000004.png" "$out/render/water_budget.png"
