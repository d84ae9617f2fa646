"""Soak run importer for Blender (File > Import > Soak run (folder)).

Doc/output.md, "Blender", says what it makes and how to change the look.
Headless, installed:
    blender -b --python-expr "import bpy; bpy.ops.preferences.addon_enable(module='soak_blender'); \
        bpy.ops.import_scene.soak_run(directory='RUN')"
or from a script, with Demos/blender on sys.path:
    import soak_blender; soak_blender.register(); soak_blender.import_run(bpy.context, 'RUN')
The modules ply and run_folder need no Blender (numpy only).
"""
bl_info = {
    "name": "Soak run",
    "author": "Soak",
    "version": (1, 0, 0),
    "blender": (3, 4, 0),
    "location": "File > Import > Soak run (folder)",
    "description": "Imports a Soak run: animated cloth with saturation attributes, the water's VDB "
                   "sequence meshed, colliders, camera and frame range",
    "category": "Import-Export",
}

from .ply import PlyError
from .run_folder import RunError

try:
    import bpy
except ImportError:   # outside Blender: ply and run_folder only
    bpy = None

if bpy is not None:
    from .importer import Options, import_run
    from .operator import register, unregister
