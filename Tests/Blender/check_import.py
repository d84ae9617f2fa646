"""Installs the soak_blender add-on from its zip, imports a run of
Scenes/fig7_small.xml and checks what Blender then holds against the run's
own files:
- the cloth's vertices at frames 0, N/2 and N are the PLY frames' (Soak's
  (x, y, z) as Blender's (x, -z, y)) within 1e-6 m, and half-way between
  two frames at a sub-frame; `saturation`, `held_water` and `velocity` are
  the frame's; the largest saturation is stats.csv's;
- the water mesh is there at every frame, read from that frame's .vdb; while
  the block falls free (frames 0-3) its volume is the water's mass / rho0
  and its centre falls as the integrator's gravity says (which a frame
  off by one, or the level set half a voxel off, would fail);
- the plane, the camera, the frame rate and range are the scene's;
- saved and opened again, the .blend follows the run's files (the frame
  handler survives the load; nothing of the run is packed into it).
usage: blender -b --factory-startup --python-exit-code 1 -P check_import.py -- ADDON.zip RUN N
"""
import csv
import math
import os
import sys
import time

import bpy
import numpy as np
from mathutils import Vector

zip_path, run, last = sys.argv[sys.argv.index("--") + 1:][:3]
last = int(last)
failures = []


def check(ok, message):
    if not ok:
        failures.append(message)
        print("FAIL:", message)


def read_ply_vertices(path):
    """The test's own reader: header lines, then the vertex records (binary little endian)."""
    codes = {"float": "<f4", "uchar": "u1", "int": "<i4", "double": "<f8"}
    fields, count = [], None
    with open(path, "rb") as f:
        assert f.readline().strip() == b"ply"
        while True:
            words = f.readline().decode().split()
            if words[:2] == ["format", "binary_little_endian"] or not words or words[0] == "comment":
                continue
            if words[0] == "element" and words[1] == "vertex":
                count = int(words[2])
                element = "vertex"
            elif words[0] == "element":
                element = words[1]
            elif words[0] == "property" and element == "vertex":
                fields.append((words[2], codes[words[1]]))
            elif words[0] == "end_header":
                break
        return np.fromfile(f, dtype=np.dtype(fields), count=count)


def ply_path(frame):
    return os.path.join(run, "cloth_sheet_ply", f"cloth_sheet_{frame:06d}.ply")


def soak_to_blender(a, b, c):
    return np.stack([a, -c, b], axis=1).astype(np.float64)


stats = {int(r["frame"]): r for r in csv.DictReader(open(os.path.join(run, "stats.csv")))}
check(sorted(stats) == list(range(last + 1)), f"stats.csv has frames {sorted(stats)}, not 0..{last}")

# --- install from the zip, as Preferences > Add-ons > Install does ---------------------------------
bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
bpy.ops.preferences.addon_enable(module="soak_blender")
import soak_blender  # noqa: E402  (installed just above)

user_scripts = os.environ.get("BLENDER_USER_SCRIPTS", "")
check(user_scripts and os.path.realpath(soak_blender.__file__).startswith(os.path.realpath(user_scripts)),
      f"soak_blender was loaded from {soak_blender.__file__}, not from the zip's install in {user_scripts}")
check(hasattr(bpy.types, "IMPORT_SCENE_OT_soak_run"), "the import operator is not registered")
menu = [f for f in bpy.types.TOPBAR_MT_file_import._dyn_ui_initialize() if f.__module__.startswith("soak_blender")]
check(len(menu) == 1, "File > Import has no Soak run entry")

for obj in list(bpy.data.objects):   # the factory scene's cube, light and camera
    bpy.data.objects.remove(obj)
t0 = time.perf_counter()
result = bpy.ops.import_scene.soak_run(directory=run)
import_seconds = time.perf_counter() - t0
check(result == {"FINISHED"}, f"import returned {result}")
print(f"check_import: import took {import_seconds:.2f} s")
scene = bpy.context.scene

# --- frame rate and range ----------------------------------------------------------------------
check(scene.render.fps == 30 and abs(scene.render.fps_base - 1.0) < 1e-9,
      f"fps {scene.render.fps}/{scene.render.fps_base}, the run's frameRate is 30")
check((scene.frame_start, scene.frame_end) == (0, last),
      f"frame range {scene.frame_start}..{scene.frame_end}, the run has 0..{last}")

# --- the cloth -----------------------------------------------------------------------------------
sheet = bpy.data.objects.get("cloth_sheet")
check(sheet is not None and sheet.type == "MESH", "no mesh object cloth_sheet")
mesh = sheet.data
n = len(mesh.vertices)
check(n == 2500 and len(mesh.polygons) == 2 * 49 * 49,
      f"cloth has {n} vertices and {len(mesh.polygons)} faces, the sheet 2500 and {2 * 49 * 49}")
for name in ("saturation", "held_water", "velocity"):
    check(name in mesh.attributes and mesh.attributes[name].domain == "POINT",
          f"cloth has no point attribute '{name}'")


def cloth_state():
    co = np.zeros(3 * n, np.float32)
    mesh.vertices.foreach_get("co", co)
    s = np.zeros(n, np.float32)
    mesh.attributes["saturation"].data.foreach_get("value", s)
    w = np.zeros(n, np.float32)
    mesh.attributes["held_water"].data.foreach_get("value", w)
    v = np.zeros(3 * n, np.float32)
    mesh.attributes["velocity"].data.foreach_get("vector", v)
    return co.reshape(-1, 3).astype(np.float64), s, w, v.reshape(-1, 3).astype(np.float64)


frames_checked = {}
for frame in (0, last // 2, last):
    scene.frame_set(frame)
    co, s, w, v = cloth_state()
    ply = read_ply_vertices(ply_path(frame))
    expected = soak_to_blender(ply["x"], ply["y"], ply["z"])
    err = np.abs(co - expected).max()
    check(err <= 1e-6, f"frame {frame}: cloth vertices differ from the PLY's by {err:.3g} m")
    check(np.array_equal(s, ply["saturation"]), f"frame {frame}: saturation differs from the PLY's")
    check(np.array_equal(w, ply["held_water"]), f"frame {frame}: held_water differs from the PLY's")
    verr = np.abs(v - soak_to_blender(ply["vx"], ply["vy"], ply["vz"])).max()
    check(verr <= 1e-6, f"frame {frame}: velocity differs from the PLY's by {verr:.3g} m/s")
    s_max = float(stats[frame]["max_saturation"])
    check(abs(float(s.max()) - s_max) <= 1e-6 * max(1.0, s_max),
          f"frame {frame}: largest saturation {s.max()}, stats.csv says {s_max}")
    frames_checked[frame] = (co, s)
    print(f"check_import: frame {frame}: vertices within {err:.2g} m, max saturation {s.max():.4f}")

check(np.all(frames_checked[0][1] == 0), "the sheet is wet at frame 0")
check(frames_checked[last][1].max() > 0.1, f"the sheet is still dry at frame {last}: the run checks nothing")
sag = frames_checked[0][0][:, 2].min() - frames_checked[last][0][:, 2].min()
check(sag > 0.02, f"the sheet moved {sag:.3f} m down between frames 0 and {last}: the frames check nothing")

half = last // 2
scene.frame_set(half, subframe=0.5)
co_mid, s_mid, _, _ = cloth_state()
a, b = read_ply_vertices(ply_path(half)), read_ply_vertices(ply_path(half + 1))
expected_mid = 0.5 * (soak_to_blender(a["x"], a["y"], a["z"]) + soak_to_blender(b["x"], b["y"], b["z"]))
check(np.abs(co_mid - expected_mid).max() <= 1e-6, f"frame {half}.5 is not half-way between {half} and {half + 1}")

# --- the water -----------------------------------------------------------------------------------
surface = bpy.data.objects.get("water_surface")
volume_obj = bpy.data.objects.get("water_volume")
check(surface is not None and volume_obj is not None, "no water_surface or water_volume object")
dt, g = 0.015, 9.81   # fig7_small's timeStep and gravity
rho0 = 1000.0
centre = {}
for frame in range(last + 1):
    scene.frame_set(frame)
    depsgraph = bpy.context.evaluated_depsgraph_get()
    grids = volume_obj.evaluated_get(depsgraph).data.grids
    want = os.path.join(run, "water_vdb", f"water_{frame:06d}.vdb")
    check(grids.frame == frame and os.path.samefile(grids.frame_filepath, want),
          f"frame {frame}: the volume reads {grids.frame_filepath} (file {grids.frame}), not {want}")
    check("surface" in grids, f"frame {frame}: the volume has no 'surface' grid")
    evaluated = surface.evaluated_get(depsgraph)
    m = evaluated.to_mesh()
    m.calc_loop_triangles()
    co = np.zeros(3 * len(m.vertices))
    m.vertices.foreach_get("co", co)
    tri = np.zeros(3 * len(m.loop_triangles), np.int64)
    m.loop_triangles.foreach_get("vertices", tri)
    co, tri = co.reshape(-1, 3), tri.reshape(-1, 3)
    evaluated.to_mesh_clear()
    check(len(tri) > 100, f"frame {frame}: the water mesh has {len(tri)} triangles")
    if len(tri) == 0:
        continue
    p, q, r = co[tri[:, 0]], co[tri[:, 1]], co[tri[:, 2]]
    six_v = np.einsum("ij,ij->i", p, np.cross(q, r))
    volume = six_v.sum() / 6
    centre[frame] = (p + q + r).T @ six_v / (24 * volume)
    mass = float(stats[frame]["free_water_mass"])
    print(f"check_import: frame {frame}: water mesh {len(tri)} triangles, {volume * 1e3:.2f} L "
          f"(free water {mass:.2f} kg), centre {np.round(centre[frame], 4)}")
    if frame <= 4:   # the block falls as one body until it meets the sheet
        check(abs(volume * rho0 / mass - 1) < 0.2,
              f"frame {frame}: the water mesh holds {volume * 1e3:.2f} L, the water is {mass / rho0 * 1e3:.2f} L")

# The block (12 x 12 particles around x = z = 0, 13 layers from y = 0.61 to 0.85) is centred at Blender (0, 0, 0.73).
err0 = np.abs(centre[0] - np.array([0.0, 0.0, 0.73])).max()
check(err0 < 0.002, f"frame 0: the water's centre is {np.round(centre[0], 4)}, the block's (0, 0, 0.73)")
for frame in (1, 2, 3):   # before it reaches the sheet: n steps of symplectic Euler fall g dt^2 n (n + 1) / 2
    steps = int(stats[frame]["step"])
    fall = g * dt * dt * steps * (steps + 1) / 2
    got = centre[0][2] - centre[frame][2]
    check(abs(got - fall) < 0.002, f"frame {frame}: the water fell {got:.4f} m, gravity says {fall:.4f} m")

# --- colliders and camera ---------------------------------------------------------------------------
planes = [o for o in bpy.data.objects if o.get("soak_collider") == "Plane"]
check(len(planes) == 1, f"{len(planes)} planes, the scene has 1")
if planes:
    normal = planes[0].matrix_world.to_3x3() @ Vector((0, 0, 1))
    check(abs(planes[0].matrix_world.translation.z) < 1e-9 and (normal - Vector((0, 0, 1))).length < 1e-6,
          "the floor is not the plane z = 0 facing up")
cam = scene.camera
check(cam is not None and cam.type == "CAMERA", "the scene has no camera")
if cam is not None:
    position = cam.matrix_world.translation
    look = cam.matrix_world.to_3x3() @ Vector((0, 0, -1))
    to_focus = Vector((0, 0, 0.35)) - position   # <Camera position="1.2 1.2 1.7" focus="0 0.35 0">
    check((position - Vector((1.2, -1.7, 1.2))).length < 1e-6, f"camera at {position}, not (1.2, -1.7, 1.2)")
    check(look.angle(to_focus) < 1e-5, "the camera does not look at the focus (0, 0, 0.35)")
    check((cam.matrix_world.to_3x3() @ Vector((0, 1, 0))).z > 0.5, "the camera's up is not up")
    check(cam.data.sensor_fit == "VERTICAL" and abs(cam.data.angle_y - math.radians(30)) < 1e-6,
          f"the camera's vertical view angle is {math.degrees(cam.data.angle_y)} degrees, not 30")

# --- save, open again: the cloth follows the run's files -------------------------------------------------
blend = os.path.join(os.path.dirname(zip_path), "imported.blend")
bpy.ops.wm.save_as_mainfile(filepath=blend)
bpy.ops.wm.open_mainfile(filepath=blend)
scene = bpy.context.scene
scene.frame_set(last)
sheet = bpy.data.objects["cloth_sheet"]
co = np.zeros(3 * len(sheet.data.vertices), np.float32)
sheet.data.vertices.foreach_get("co", co)
ply = read_ply_vertices(ply_path(last))
err = np.abs(co.reshape(-1, 3) - soak_to_blender(ply["x"], ply["y"], ply["z"])).max()
check(err <= 1e-6, f"after opening the .blend, frame {last}'s vertices differ from the PLY's by {err:.3g} m")
volume = bpy.data.objects["water_volume"].data
check(volume.packed_file is None and not any(i.packed_file for i in bpy.data.images),
      "the .blend has the run's files packed into it")

if failures:
    sys.exit(f"check_import: {len(failures)} failures:\n  " + "\n  ".join(failures))
print("check_import: ok")
