"""Checks a still that render_soak.py rendered of a run's frame N:
- it is the size asked for and shows the cloth: where the cloth is (its
  alpha in a render of the cloth alone), the still differs from a render of
  the same shot without the cloth;
- the wet cloth material darkens with saturation: the cloth rendered with
  every vertex at saturation sMax is darker than with every vertex dry.
Renders are Cycles on the CPU at the still's size and samples, set up by
render_soak.py's own functions.
usage: blender -b --factory-startup --python-exit-code 1 -P check_render.py -- ADDON_DIR RUN N STILL.png SAMPLES
"""
import os
import sys

import bpy
import numpy as np

addon_dir, run, frame, still, samples = sys.argv[sys.argv.index("--") + 1:][:5]
frame, samples = int(frame), int(samples)
sys.path.insert(0, addon_dir)
import render_soak  # noqa: E402
import soak_blender  # noqa: E402

failures = []
work = os.path.dirname(os.path.abspath(still))


def check(ok, message):
    if not ok:
        failures.append(message)
        print("FAIL:", message)


def load_rgba(path):
    image = bpy.data.images.load(path)
    w, h = image.size
    pixels = np.zeros(w * h * 4, np.float32)
    image.pixels.foreach_get(pixels)
    bpy.data.images.remove(image)
    return pixels.reshape(h, w, 4)


def render(name, transparent=False):
    scene = bpy.context.scene
    scene.render.film_transparent = transparent
    scene.render.image_settings.color_mode = "RGBA" if transparent else "RGB"
    scene.render.filepath = os.path.join(work, name)
    bpy.ops.render.render(write_still=True)
    return load_rgba(scene.render.filepath)


shot = load_rgba(still)
height, width = shot.shape[:2]
check((width, height) == (160, 90), f"{still} is {width}x{height}, not 160x90")

bpy.ops.wm.read_homefile(use_empty=True)
soak_blender.register()
soak_blender.import_run(bpy.context, run)
scene = bpy.context.scene
scene.frame_set(frame)
render_soak.configure(scene, samples, width, height, device="cpu")
sheet = bpy.data.objects["cloth_sheet"]
others = [o for o in scene.objects if o is not sheet and not o.hide_render]

for o in others:
    o.hide_render = True
mask = render("cloth_alone.png", transparent=True)[:, :, 3] > 0.5
for o in others:
    o.hide_render = False
covered = mask.mean()
check(covered > 0.03, f"the cloth covers {covered:.1%} of the picture")

sheet.hide_render = True
without = render("without_cloth.png")[:, :, :3]
sheet.hide_render = False
changed = np.abs(shot[:, :, :3] - without).max(axis=2) > 0.05
shown = changed[mask].mean() if mask.any() else 0.0
print(f"check_render: cloth on {covered:.1%} of the picture; {shown:.1%} of those pixels differ without it")
check(shown > 0.8, f"only {shown:.1%} of the cloth's pixels differ from the shot without the cloth")

# The material: a still copy of the frame's cloth (the frame handler, which a render runs, passes over
# it: it has no soak_cloth property) with every vertex dry, then soaked.
still_cloth = sheet.copy()
still_cloth.data = sheet.data.copy()
del still_cloth[soak_blender.cloth.CLOTH_PROPERTY]
sheet.users_collection[0].objects.link(still_cloth)
sheet.hide_render = True
saturation = still_cloth.data.attributes["saturation"]
s_max = soak_blender.run_folder.Run(run).saturation_max
brightness = {}
for label, value in (("dry", 0.0), ("soaked", s_max)):
    saturation.data.foreach_set("value", np.full(len(saturation.data), value, np.float32))
    still_cloth.data.update()
    rgb = render(f"cloth_{label}.png")[:, :, :3]
    brightness[label] = float(rgb[mask].mean()) if mask.any() else 0.0
print(f"check_render: mean brightness of the cloth, dry {brightness['dry']:.3f}, soaked {brightness['soaked']:.3f}")
check(brightness["soaked"] < 0.85 * brightness["dry"],
      f"soaked cloth ({brightness['soaked']:.3f}) is not clearly darker than dry cloth ({brightness['dry']:.3f})")

if failures:
    sys.exit(f"check_render: {len(failures)} failures:\n  " + "\n  ".join(failures))
print("check_render: ok")
