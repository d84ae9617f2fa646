"""The scene's `<Camera position focus up viewAngle>` as a Blender camera.

`viewAngle` is the vertical field of view (as ParaView's), so the camera's
sensor fit is vertical and the picture's height shows that angle whatever
its width. Without a `<Camera>`, the camera looks at the cloths and the
water of the first frame from the front right, above, as Doc/render.py does.
"""
import math

import bpy
from mathutils import Matrix, Vector

from . import axes
from .run_folder import number, vector

# Direction from the focus to the camera without a <Camera> (Soak axes), as Doc/render.py's.
DEFAULT_DIRECTION = (0.55, 0.45, 0.70)


def look_at(position, focus, up):
    """World matrix of a camera at `position` looking at `focus` with `up` up (Blender axes)."""
    forward = (Vector(focus) - Vector(position)).normalized()
    right = forward.cross(Vector(up))
    if right.length < 1e-9:   # up along the view: any perpendicular will do
        right = forward.orthogonal()
    right.normalize()
    true_up = right.cross(forward)
    rotation = Matrix((right, true_up, -forward)).transposed().to_4x4()
    return Matrix.Translation(Vector(position)) @ rotation


def _framing(objects, depsgraph, view_angle):
    """(position, focus) of a view of the objects' bounding sphere (as evaluated: the water is meshed)."""
    points = [obj.matrix_world @ Vector(c) for obj in objects for c in obj.evaluated_get(depsgraph).bound_box]
    if not points:
        points = [Vector((0.0, 0.0, 0.0))]
    lo = Vector([min(p[i] for p in points) for i in range(3)])
    hi = Vector([max(p[i] for p in points) for i in range(3)])
    focus = (lo + hi) / 2
    radius = max((hi - lo).length / 2, 0.1)
    distance = 1.2 * radius / math.sin(math.radians(view_angle) / 2)
    direction = Vector(axes.point(DEFAULT_DIRECTION)).normalized()
    return focus + distance * direction, focus


def create(run, collection, frame_objects, depsgraph):
    element = run.element("Camera")
    data = bpy.data.cameras.new("soak_camera")
    data.sensor_fit = "VERTICAL"
    data.clip_start = 0.01
    data.clip_end = 1000.0
    if element is not None:
        view_angle = number(element, "viewAngle")
        position = axes.point(vector(element, "position"))
        focus = axes.point(vector(element, "focus"))
        up = axes.point(vector(element, "up"))
    else:
        view_angle = 30.0
        position, focus = _framing(frame_objects, depsgraph, view_angle)
        up = (0.0, 0.0, 1.0)
    data.angle_y = math.radians(view_angle)
    obj = bpy.data.objects.new("soak_camera", data)
    obj.matrix_world = look_at(position, focus, up)
    collection.objects.link(obj)
    return obj
