"""The water of a run: its OpenVDB sequence as a volume, meshed for rendering.

`water_vdb/water_NNNNNN.vdb` (written with `Output.vdb`) holds a level set
`surface` (negative inside) and a points grid `particles`. The importer
makes:
- `water_volume`, a Volume object reading the files as a sequence in place
  (nothing copied into the .blend), Blender frame k = file k, the last file
  held past the end. It is drawn as its bounds and not rendered: Blender
  would render a level set as a density, and it does not render points grids.
- `water_surface`, a mesh object whose Volume to Mesh modifier meshes the
  `surface` grid at 0 (the water's surface) every frame, smooth shaded.

The volume object is rotated from Soak's y-up axes to Blender's z-up, and
moved by half a voxel down each of Blender's axes: Blender's Volume to
Mesh adds half a voxel along each axis of the mesh object (it takes a
voxel's value to sit at the voxel's corner, where OpenVDB puts it at the
centre), and the shift puts the mesh where Soak's level set has its zero,
so long as `water_surface` is neither rotated nor scaled.
"""
import os

import bpy
from mathutils import Matrix, Vector

from . import axes
from .run_folder import number

SURFACE_GRID = "surface"


def _voxel_axes(volume, run):
    """The `surface` grid's index-to-object matrix (3 x 3), from the file, else from scene.xml."""
    try:
        if volume.grids.load() and SURFACE_GRID in volume.grids:
            m = volume.grids[SURFACE_GRID].matrix_object
            return Matrix([[m[i][j] for j in range(3)] for i in range(3)])
    except (AttributeError, RuntimeError):
        pass
    surface = run.element("WaterSurface")
    if surface is not None and surface.get("cellSize"):
        h = float(surface.get("cellSize"))
    elif surface is not None:
        h = 0.014
    else:
        water = run.element("Water")
        h = 0.7 * (number(water, "spacing") if water is not None else 0.02)
    return Matrix.Diagonal((h, h, h))


def create_volume(run, collection):
    frames = sorted(run.water_vdb)
    first, last = frames[0], frames[-1]
    volume = bpy.data.volumes.new("water")
    volume.filepath = run.water_vdb[first]
    volume.is_sequence = True
    volume.frame_start = first
    volume.frame_duration = last - first + 1
    # Blender reads file (frame - frame_start + 1 + frame_offset): file = frame.
    volume.frame_offset = first - 1
    volume.sequence_mode = "EXTEND"
    obj = bpy.data.objects.new("water_volume", volume)
    rotation = Matrix.Rotation(axes.SOAK_TO_BLENDER_EULER[0], 4, "X")
    voxel = _voxel_axes(volume, run)
    # The modifier adds half the voxel's extent along each axis of the mesh object's space.
    extent = [(rotation.to_3x3() @ voxel.col[i]) for i in range(3)]
    half = Vector([0.5 * sum(abs(e[axis]) for e in extent) for axis in range(3)])
    obj.matrix_world = Matrix.Translation(-half) @ rotation
    obj.display_type = "BOUNDS"
    obj.hide_render = True
    collection.objects.link(obj)
    return obj


def create_surface(volume_obj, collection):
    mesh = bpy.data.meshes.new("water_surface")
    obj = bpy.data.objects.new("water_surface", mesh)
    modifier = obj.modifiers.new("Soak water surface", "VOLUME_TO_MESH")
    modifier.object = volume_obj
    modifier.grid_name = SURFACE_GRID
    modifier.resolution_mode = "GRID"
    modifier.threshold = 0.0
    modifier.adaptivity = 0.0
    modifier.use_smooth_shade = True
    collection.objects.link(obj)
    return obj


def has_water(run):
    return bool(run.water_vdb)


def missing_water_message(run):
    return (f"{os.path.join(run.folder, 'water_vdb')} has no .vdb files: the water is left out "
            "(run soak with --set Output.vdb=true)")

