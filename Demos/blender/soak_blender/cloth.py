"""Cloth meshes that follow a run's PLY frames.

Each cloth is one mesh object built from its first PLY frame (vertices and
triangles). A frame-change handler (`on_frame_change`, registered by the
add-on, persistent across file loads) reads the PLY of the scene's frame and
writes the positions and the per-vertex attributes into the mesh, so the
.blend holds one frame of the cloth and reads the others from the run
folder. Blender frame k shows Soak frame k; between two frames (motion blur
sub-frames) positions and attributes are linear between them. Frames past
the last on disk hold the last.

Attributes (point domain, readable by a shader's Attribute node):
`saturation`, `held_water`, `buffer`, `volume`, ... (one float per Soak
channel, under the channel's name) and `velocity` (m/s, a vector in
Blender's axes).

The object keeps where its frames are as custom properties: `soak_run`
(the run folder) and `soak_cloth` (the cloth's name).
"""
import os
from collections import OrderedDict

import bpy
import numpy as np

from . import axes, ply
from .run_folder import numbered_files

RUN_PROPERTY = "soak_run"
CLOTH_PROPERTY = "soak_cloth"
VELOCITY = "velocity"

_cache = OrderedDict()   # (path, mtime) -> vertex record array
_CACHE_SIZE = 8


def ply_folder(run_folder, name):
    return os.path.join(run_folder, f"cloth_{name}_ply")


def _read_vertices(path):
    key = (path, os.path.getmtime(path))
    if key in _cache:
        _cache.move_to_end(key)
        return _cache[key]
    vertices, _ = ply.read(path, faces=False)
    _cache[key] = vertices
    while len(_cache) > _CACHE_SIZE:
        _cache.popitem(last=False)
    return vertices


def _frame_arrays(vertices):
    """Positions (n, 3), velocity (n, 3) in Blender's axes, and {channel: values}, all float32."""
    co = axes.columns(vertices["x"], vertices["y"], vertices["z"]).astype(np.float32, copy=False)
    names = vertices.dtype.names
    if all(v in names for v in ("vx", "vy", "vz")):
        vel = axes.columns(vertices["vx"], vertices["vy"], vertices["vz"]).astype(np.float32, copy=False)
    else:
        vel = np.zeros_like(co)
    channels = {c: np.ascontiguousarray(vertices[c], dtype=np.float32) for c in ply.channel_names(vertices)}
    return co, vel, channels


def _write(mesh, co, vel, channels):
    mesh.vertices.foreach_set("co", co.ravel())
    if VELOCITY in mesh.attributes:
        mesh.attributes[VELOCITY].data.foreach_set("vector", vel.ravel())
    for name, values in channels.items():
        if name in mesh.attributes:
            mesh.attributes[name].data.foreach_set("value", values)
    mesh.update()


def create(run, name, collection):
    """Makes the mesh object of cloth `name` of a run_folder.Run, at its first frame."""
    frames = run.cloths[name]
    first = frames[min(frames)]
    vertices, triangles = ply.read(first)
    if triangles is None:
        raise ply.PlyError(f"{first}: no face element")
    co, vel, channels = _frame_arrays(vertices)
    mesh = bpy.data.meshes.new(f"cloth_{name}")
    mesh.vertices.add(len(co))
    mesh.loops.add(3 * len(triangles))
    mesh.polygons.add(len(triangles))
    mesh.loops.foreach_set("vertex_index", triangles.ravel())
    mesh.polygons.foreach_set("loop_start", np.arange(0, 3 * len(triangles), 3, dtype=np.int32))
    mesh.polygons.foreach_set("loop_total", np.full(len(triangles), 3, dtype=np.int32))
    mesh.polygons.foreach_set("use_smooth", np.ones(len(triangles), dtype=bool))
    mesh.attributes.new(VELOCITY, "FLOAT_VECTOR", "POINT")
    for channel in channels:
        if channel in mesh.attributes:
            raise ply.PlyError(f"{first}: channel '{channel}' has the name of a Blender attribute")
        mesh.attributes.new(channel, "FLOAT", "POINT")
    _write(mesh, co, vel, channels)
    mesh.validate()
    obj = bpy.data.objects.new(f"cloth_{name}", mesh)
    obj[RUN_PROPERTY] = run.folder
    obj[CLOTH_PROPERTY] = name
    collection.objects.link(obj)
    return obj


def update(obj, frame):
    """Moves a cloth object to a (possibly fractional) Blender frame = Soak frame."""
    folder = ply_folder(bpy.path.abspath(obj[RUN_PROPERTY]), obj[CLOTH_PROPERTY])
    frames = numbered_files(folder)
    if not frames:
        return False
    numbers = sorted(frames)
    f0 = int(np.floor(frame))
    t = frame - f0
    f0 = min(max(f0, numbers[0]), numbers[-1])
    mesh = obj.data
    co, vel, channels = _frame_arrays(_read_vertices(frames[f0]))
    if len(co) != len(mesh.vertices):
        print(f"soak_blender: {frames[f0]} has {len(co)} vertices, the mesh {len(mesh.vertices)}; not updated")
        return False
    if t > 0 and f0 + 1 in frames and f0 < numbers[-1]:
        co1, vel1, channels1 = _frame_arrays(_read_vertices(frames[f0 + 1]))
        co = (1 - t) * co + t * co1
        vel = (1 - t) * vel + t * vel1
        channels = {k: (1 - t) * v + t * channels1[k] for k, v in channels.items() if k in channels1}
    _write(mesh, co.astype(np.float32), vel.astype(np.float32), channels)
    return True


def update_scene(scene):
    frame = scene.frame_current + scene.frame_subframe
    for obj in scene.objects:
        if obj.type == "MESH" and CLOTH_PROPERTY in obj and RUN_PROPERTY in obj:
            try:
                update(obj, frame)
            except (OSError, ply.PlyError) as e:
                print(f"soak_blender: {obj.name}: {e}")


@bpy.app.handlers.persistent
def on_frame_change(scene, *_):
    update_scene(scene)


@bpy.app.handlers.persistent
def on_load(*_):
    scene = bpy.context.scene
    if scene is not None:
        update_scene(scene)


def register():
    if on_frame_change not in bpy.app.handlers.frame_change_pre:
        bpy.app.handlers.frame_change_pre.append(on_frame_change)
    if on_load not in bpy.app.handlers.load_post:
        bpy.app.handlers.load_post.append(on_load)


def unregister():
    if on_frame_change in bpy.app.handlers.frame_change_pre:
        bpy.app.handlers.frame_change_pre.remove(on_frame_change)
    if on_load in bpy.app.handlers.load_post:
        bpy.app.handlers.load_post.remove(on_load)
