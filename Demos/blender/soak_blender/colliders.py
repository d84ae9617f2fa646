"""The scene's colliders (`<Plane>`, `<Box>`, `<Sphere>`) as simple objects.

A plane is a square (Soak's is infinite) of `plane_half_size` metres each
side of its point, or less where the scene's domain is smaller. A solid box
or sphere is a closed mesh. A container (`inside="true"`) has its normals
inward and the cut-away material (materials.py), so the walls between the
camera and the inside are not drawn. A collider with a `path` is keyframed
at every frame of the run, at the frame's simulated time (stats.csv), so it
is where the simulation had it.
"""
import bmesh
import bpy
from mathutils import Vector

from . import axes
from .run_folder import boolean, number, offset_at, path_keys, vector

PLANE_HALF_SIZE = 5.0


def _mesh_object(name, bm, collection):
    mesh = bpy.data.meshes.new(name)
    bm.to_mesh(mesh)
    bm.free()
    obj = bpy.data.objects.new(name, mesh)
    collection.objects.link(obj)
    return obj


def _plane(element, run, collection, index):
    lo = vector(run.element("Simulation"), "domainMin") if run.element("Simulation") is not None else None
    hi = vector(run.element("Simulation"), "domainMax") if run.element("Simulation") is not None else None
    half = PLANE_HALF_SIZE
    if lo and hi:
        half = min(half, 0.5 * max(hi[0] - lo[0], hi[2] - lo[2]))
    bm = bmesh.new()
    bmesh.ops.create_grid(bm, x_segments=1, y_segments=1, size=half)
    obj = _mesh_object(f"plane_{index}", bm, collection)
    normal = Vector(axes.point(vector(element, "normal"))).normalized()
    obj.rotation_mode = "QUATERNION"
    obj.rotation_quaternion = Vector((0.0, 0.0, 1.0)).rotation_difference(normal)
    return obj, vector(element, "point")


def _box(element, collection, index):
    lo, hi = vector(element, "min"), vector(element, "max")
    centre = [(a + b) / 2 for a, b in zip(lo, hi)]
    size = axes.point([b - a for a, b in zip(lo, hi)])
    bm = bmesh.new()
    bmesh.ops.create_cube(bm, size=1.0)
    for v in bm.verts:
        v.co = Vector((v.co.x * abs(size[0]), v.co.y * abs(size[1]), v.co.z * abs(size[2])))
    return _mesh_object(f"box_{index}", bm, collection), centre


def _sphere(element, collection, index):
    bm = bmesh.new()
    bmesh.ops.create_uvsphere(bm, u_segments=64, v_segments=32, radius=number(element, "radius"))
    for face in bm.faces:
        face.smooth = True
    return _mesh_object(f"sphere_{index}", bm, collection), vector(element, "center")


def _flip_inward(obj):
    bm = bmesh.new()
    bm.from_mesh(obj.data)
    bmesh.ops.reverse_faces(bm, faces=bm.faces[:])
    bm.to_mesh(obj.data)
    bm.free()


def _animate(obj, rest, keys, run):
    """Keyframes the object's location at every frame of the run from the path's offsets."""
    for frame in run.frames():
        off = offset_at(keys, run.time_of(frame))
        obj.location = axes.point([rest[k] + off[k] for k in range(3)])
        obj.keyframe_insert("location", frame=frame)
    if obj.animation_data and obj.animation_data.action:
        for curve in obj.animation_data.action.fcurves:
            for point in curve.keyframe_points:
                point.interpolation = "LINEAR"


def create(run, collection, solid_material=None, container_material=None):
    """Makes every collider of the run's scene; returns the objects."""
    made = []
    for index, element in enumerate(run.elements("Plane", "Box", "Sphere")):
        if element.tag == "Plane":
            obj, rest = _plane(element, run, collection, index)
            inside = False
        elif element.tag == "Box":
            obj, rest = _box(element, collection, index)
            inside = boolean(element, "inside")
        else:
            obj, rest = _sphere(element, collection, index)
            inside = boolean(element, "inside")
        if element.get("name"):
            obj.name = element.get("name")
        if inside:
            _flip_inward(obj)
        material = container_material if inside else solid_material
        if material is not None:
            obj.data.materials.append(material)
        obj["soak_collider"] = element.tag
        keys = path_keys(element)
        obj.location = axes.point(rest)
        if keys:
            _animate(obj, rest, keys, run)
        made.append(obj)
    return made
