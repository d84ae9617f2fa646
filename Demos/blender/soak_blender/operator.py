"""File > Import > Soak run (folder): the operator and its menu entry."""
import os

import bpy
from bpy.props import BoolProperty, StringProperty

from . import cloth
from .importer import Options, import_run
from .ply import PlyError
from .run_folder import RunError


class IMPORT_SCENE_OT_soak_run(bpy.types.Operator):
    """Import a Soak run folder (written by soak run with Output.ply and Output.vdb)"""
    bl_idname = "import_scene.soak_run"
    bl_label = "Import Soak run"
    bl_options = {"REGISTER", "UNDO"}

    directory: StringProperty(name="Run folder", subtype="DIR_PATH",
                              description="Folder written by soak run (holds scene.xml)")
    filter_folder: BoolProperty(default=True, options={"HIDDEN"})
    water_surface: BoolProperty(name="Water", default=True,
                                description="The water_vdb sequence as a volume and its meshed surface")
    colliders: BoolProperty(name="Colliders", default=True, description="The scene's planes, boxes and spheres")
    camera: BoolProperty(name="Camera", default=True, description="The scene's <Camera>, made the scene camera")
    sun: BoolProperty(name="Sun", default=True, description="A sun light from the side of the camera")
    materials: BoolProperty(name="Materials", default=True,
                            description="Wet cloth (darker and glossier with saturation), water, colliders")
    frame_range: BoolProperty(name="Frame rate and range", default=True,
                              description="Set the scene's fps and frame range from the run")

    def invoke(self, context, event):
        context.window_manager.fileselect_add(self)
        return {"RUNNING_MODAL"}

    def execute(self, context):
        folder = bpy.path.abspath(self.directory)
        if os.path.isfile(folder):   # a file of the run chosen: its folder
            folder = os.path.dirname(folder)
        options = Options(water_surface=self.water_surface, colliders=self.colliders, camera=self.camera,
                          sun=self.sun, materials=self.materials, frame_range=self.frame_range)
        try:
            collection, warnings = import_run(context, folder, options)
        except (RunError, PlyError, OSError) as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        for warning in warnings:
            self.report({"WARNING"}, warning)
        self.report({"INFO"}, f"Imported {folder} into collection '{collection.name}'")
        return {"FINISHED"}


def menu_import(self, context):
    self.layout.operator(IMPORT_SCENE_OT_soak_run.bl_idname, text="Soak run (folder)")


def register():
    bpy.utils.register_class(IMPORT_SCENE_OT_soak_run)
    bpy.types.TOPBAR_MT_file_import.append(menu_import)
    cloth.register()


def unregister():
    cloth.unregister()
    bpy.types.TOPBAR_MT_file_import.remove(menu_import)
    bpy.utils.unregister_class(IMPORT_SCENE_OT_soak_run)
