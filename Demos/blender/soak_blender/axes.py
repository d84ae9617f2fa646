"""Soak's axes to Blender's.

Soak is y-up (gravity 0 -9.81 0 by default), Blender z-up, both right-handed
and in metres. A Soak point (x, y, z) is the Blender point (x, -z, y): a
rotation of +90 degrees about x, so nothing is mirrored. Only the sign of one
coordinate changes, so a float32 position converts exactly.
"""
import math

import numpy as np

# The rotation as Euler angles (XYZ) for an object whose data stays in Soak's axes.
SOAK_TO_BLENDER_EULER = (math.pi / 2, 0.0, 0.0)


def point(v):
    """One Soak vector (3 numbers) -> Blender (x, -z, y)."""
    return (float(v[0]), -float(v[2]), float(v[1]))


def columns(x, y, z):
    """Soak x, y, z columns (numpy arrays) -> an (n, 3) array in Blender's axes, same dtype."""
    out = np.empty((len(x), 3), dtype=np.result_type(x, y, z))
    out[:, 0] = x
    out[:, 1] = -z
    out[:, 2] = y
    return out
