"""Renders one frame of a Soak run with Cycles.

    blender -b -P Demos/blender/render_soak.py -- RUN --frame N -o shot.png \
        [--samples 64] [--resolution 1280x720] [--threads T] [--device auto|cpu|gpu] [--blend shot.blend]

RUN is a folder written by `soak run ... --set Output.ply=true --set Output.vdb=true`.
The scene is imported by the soak_blender add-on (installed, or from the
folder beside this script) into an empty file; frame N is Soak's frame N.
Cycles renders on the GPU where Blender finds one (OptiX, CUDA or HIP) and
--device is not cpu, else on the CPU; the denoiser runs where Blender has
one (Debian's build has none, so few samples leave grain). --blend also
saves the set-up scene, to open in Blender and change.
"""
import argparse
import os
import sys
import time

import bpy

BACKGROUND = (0.78, 0.82, 0.88, 1.0)   # a pale sky
BACKGROUND_STRENGTH = 0.45


def parse(argv):
    args = argv[argv.index("--") + 1:] if "--" in argv else []
    p = argparse.ArgumentParser(prog="render_soak.py", description="Render a frame of a Soak run with Cycles.")
    p.add_argument("run", help="run folder written by soak run")
    p.add_argument("--frame", type=int, default=0, help="Soak frame to render (default 0)")
    p.add_argument("-o", "--output", required=True, help="PNG to write")
    p.add_argument("--samples", type=int, default=64, help="Cycles samples per pixel (default 64)")
    p.add_argument("--resolution", default="1280x720", help="WIDTHxHEIGHT in pixels (default 1280x720)")
    p.add_argument("--threads", type=int, default=0, help="CPU threads (default 0: all)")
    p.add_argument("--device", choices=("auto", "cpu", "gpu"), default="auto",
                   help="auto: a GPU where Blender finds one, else the CPU")
    p.add_argument("--blend", help="also save the scene as this .blend")
    a = p.parse_args(args)
    try:
        a.width, a.height = (int(x) for x in a.resolution.lower().split("x"))
    except ValueError:
        p.error(f"--resolution {a.resolution}: expected WIDTHxHEIGHT, e.g. 1280x720")
    return a


def load_addon():
    """The installed add-on, else the package beside this script."""
    try:
        import soak_blender
    except ImportError:
        sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
        import soak_blender
    if not hasattr(bpy.types, "IMPORT_SCENE_OT_soak_run"):
        soak_blender.register()
    return soak_blender


def gpu_device(kind):
    """Sets Cycles' compute device; returns a description of the device used."""
    if kind == "cpu":
        return "CPU"
    prefs = bpy.context.preferences.addons["cycles"].preferences
    for backend in ("OPTIX", "CUDA", "HIP", "ONEAPI", "METAL"):
        try:
            prefs.compute_device_type = backend
        except TypeError:   # not built into this Blender
            continue
        prefs.get_devices()
        gpus = [d for d in prefs.devices if d.type == backend]
        if gpus:
            for d in prefs.devices:
                d.use = d.type == backend
            return f"GPU ({backend}: {', '.join(d.name for d in gpus)})"
    if kind == "gpu":
        sys.exit("render_soak: --device gpu, but this Blender finds no GPU it can render on")
    return "CPU"


def configure(scene, samples, width, height, threads=0, device="auto"):
    """Cycles, samples, size, world and colour management of a shot; returns the device used."""
    scene.render.engine = "CYCLES"
    used = gpu_device(device)
    scene.cycles.device = "GPU" if used.startswith("GPU") else "CPU"
    scene.cycles.samples = samples
    scene.cycles.use_adaptive_sampling = True
    scene.cycles.max_bounces = 12
    scene.cycles.transmission_bounces = 12
    scene.cycles.transparent_max_bounces = 16
    scene.cycles.caustics_reflective = False
    scene.cycles.caustics_refractive = False
    import _cycles
    scene.cycles.use_denoising = bool(getattr(_cycles, "with_openimagedenoise", False))
    scene.render.resolution_x = width
    scene.render.resolution_y = height
    scene.render.resolution_percentage = 100
    scene.render.threads_mode = "FIXED" if threads > 0 else "AUTO"
    if threads > 0:
        scene.render.threads = threads
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGB"
    scene.view_settings.view_transform = "Filmic"
    for look in ("Medium High Contrast", "Filmic - Medium High Contrast"):   # Blender 3, Blender 4
        try:
            scene.view_settings.look = look
            break
        except TypeError:
            pass
    world = scene.world or bpy.data.worlds.new("soak_world")
    scene.world = world
    world.use_nodes = True
    background = world.node_tree.nodes.get("Background")
    background.inputs["Color"].default_value = BACKGROUND
    background.inputs["Strength"].default_value = BACKGROUND_STRENGTH
    return used


def main():
    a = parse(sys.argv)
    if not os.path.isdir(a.run):
        sys.exit(f"render_soak: {a.run} is not a folder")
    bpy.ops.wm.read_homefile(use_empty=True)
    addon = load_addon()
    t0 = time.perf_counter()
    try:
        addon.import_run(bpy.context, a.run)
    except (addon.RunError, OSError, ValueError) as e:
        sys.exit(f"render_soak: {e}")
    scene = bpy.context.scene
    if a.frame < scene.frame_start or a.frame > scene.frame_end:
        sys.exit(f"render_soak: --frame {a.frame}: the run has frames {scene.frame_start} to {scene.frame_end}")
    scene.frame_set(a.frame)
    t1 = time.perf_counter()
    used = configure(scene, a.samples, a.width, a.height, a.threads, a.device)
    if a.blend:
        bpy.ops.wm.save_as_mainfile(filepath=os.path.abspath(a.blend))
    scene.render.filepath = os.path.abspath(a.output)
    bpy.ops.render.render(write_still=True)
    t2 = time.perf_counter()
    print(f"render_soak: {a.run} frame {a.frame} -> {a.output} ({a.width}x{a.height}, {a.samples} samples, "
          f"{used}): import {t1 - t0:.2f} s, render {t2 - t1:.1f} s")


if __name__ == "__main__":
    main()
