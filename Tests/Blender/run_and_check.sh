#!/bin/sh
# Runs a short Scenes/fig7_small.xml with PLY and VDB output, then checks it in
# Blender: `import` installs the add-on from its zip and checks what it imports
# (check_import.py); `render` renders the last frame with render_soak.py and
# checks the picture (check_render.py). Without a working Blender it fails.
# usage: SOAK=... BLENDER=... run_and_check.sh import|render SOURCE_DIR OUTDIR
set -e
what=$1
src=$2
out=$3
here=$(cd "$(dirname "$0")" && pwd)
frames=14   # 0.48 s: the block has fallen onto the sheet, wetted it and started to drip through

if [ -z "$BLENDER" ] || ! command -v "$BLENDER" >/dev/null 2>&1; then
  echo "blender test: no Blender at '${BLENDER}': install Debian's blender (bash Demos/scripts/install-deps.sh)" >&2
  exit 1
fi
rm -rf "$out"
mkdir -p "$out/user/config" "$out/user/scripts"
# Blender's own settings and add-ons stay in the test's folder.
export BLENDER_USER_CONFIG="$out/user/config" BLENDER_USER_SCRIPTS="$out/user/scripts"
if ! "$BLENDER" -b --factory-startup --python-exit-code 1 --python-expr "import bpy, numpy" >"$out/blender_start.log" 2>&1; then
  cat "$out/blender_start.log" >&2
  echo "blender test: $BLENDER does not start headless with numpy (log above)" >&2
  exit 1
fi
"$SOAK" run "$src/Scenes/fig7_small.xml" -o "$out/run" --frames $frames --device cpu --quiet \
  --set Output.ply=true --set Output.vdb=true
run_blender() { "$BLENDER" -b --factory-startup --python-exit-code 1 "$@"; }
case $what in
  import)
    python3 "$src/Demos/blender/make_addon_zip.py" "$out/soak_blender.zip"
    run_blender -P "$here/check_import.py" -- "$out/soak_blender.zip" "$out/run" $frames
    ;;
  render)
    run_blender -P "$src/Demos/blender/render_soak.py" -- "$out/run" --frame $frames -o "$out/shot.png" \
      --samples 4 --resolution 160x90 --device cpu
    run_blender -P "$here/check_render.py" -- "$src/Demos/blender" "$out/run" $frames "$out/shot.png" 4
    ;;
  *)
    echo "usage: run_and_check.sh import|render SOURCE_DIR OUTDIR" >&2
    exit 2
    ;;
esac
