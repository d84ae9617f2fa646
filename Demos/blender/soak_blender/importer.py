"""Imports a Soak run folder into the current Blender scene.

Everything goes into a new collection "Soak <folder name>": one mesh per
cloth (cloth.py), the water (water.py), the colliders (colliders.py), the
camera (camera.py) and a sun. The scene's frame rate is the run's
`Simulation.frameRate` and its frame range the run's frames, frame k being
Soak frame k (frame 0 is the initial state).
"""
import math
import os

import bpy
from mathutils import Euler

from . import camera, cloth, colliders, materials, water
from .run_folder import Run, RunError


class Options:
    """What import_run makes; each can be turned off."""

    def __init__(self, water_surface=True, colliders=True, camera=True, sun=True, materials=True,
                 frame_range=True):
        self.water_surface = water_surface
        self.colliders = colliders
        self.camera = camera
        self.sun = sun
        self.materials = materials
        self.frame_range = frame_range


def _set_frame_rate(scene, rate):
    """fps / fps_base = rate: an integer rate as is, any other to the nearest integer fps."""
    fps = max(1, round(rate))
    scene.render.fps = fps
    scene.render.fps_base = fps / rate


def _sun(collection, camera_obj):
    data = bpy.data.lights.new("soak_sun", "SUN")
    data.energy = 2.0
    data.angle = math.radians(3.0)
    obj = bpy.data.objects.new("soak_sun", data)
    # 50 degrees high, from 80 degrees to the camera's side: light that models folds and wrinkles.
    heading = camera_obj.matrix_world.to_euler().z if camera_obj else 0.0
    obj.rotation_euler = Euler((math.radians(40.0), 0.0, heading + math.radians(80.0)))
    collection.objects.link(obj)
    return obj


def import_run(context, folder, options=None):
    """Imports the run; returns (collection, warnings). Raises RunError where nothing can be imported."""
    options = options or Options()
    run = Run(folder)
    if not run.cloths and not run.water_vdb:
        raise RunError(f"{run.folder} has neither cloth PLY frames nor water VDB frames: run soak with "
                       "--set Output.ply=true --set Output.vdb=true")
    warnings = []
    if not run.cloths:
        warnings.append(f"{run.folder} has no cloth_*_ply folders: the cloth is left out "
                        "(run soak with --set Output.ply=true)")
    scene = context.scene
    collection = bpy.data.collections.new(f"Soak {os.path.basename(run.folder)}")
    collection["soak_run"] = run.folder
    scene.collection.children.link(collection)

    cloth_material = materials.wet_cloth(run.saturation_max) if options.materials else None
    cloth_objects = []
    for name in run.cloths:
        obj = cloth.create(run, name, collection)
        if cloth_material:
            obj.data.materials.append(cloth_material)
        cloth_objects.append(obj)

    framed = list(cloth_objects)
    if options.water_surface and water.has_water(run):
        volume_obj = water.create_volume(run, collection)
        surface_obj = water.create_surface(volume_obj, collection)
        framed.append(surface_obj)
        if options.materials:
            surface_obj.data.materials.append(materials.water())
    elif options.water_surface:
        warnings.append(water.missing_water_message(run))

    if options.colliders:
        colliders.create(run, collection, materials.collider() if options.materials else None,
                         materials.container() if options.materials else None)

    if options.frame_range:
        _set_frame_rate(scene, run.frame_rate)
        frames = run.frames()
        scene.frame_start = frames[0] if frames else 0
        scene.frame_end = frames[-1] if frames else 0
    # The cloth changes in a frame handler: rendering an animation from the interface must not
    # draw the viewport meanwhile.
    scene.render.use_lock_interface = True
    scene.frame_set(scene.frame_start if options.frame_range else scene.frame_current)

    camera_obj = None
    if options.camera:
        camera_obj = camera.create(run, collection, framed, context.evaluated_depsgraph_get())
        scene.camera = camera_obj
    if options.sun:
        _sun(collection, camera_obj)
    return collection, warnings

