# phyllo_import - File > Import > Phyllotaxis scene (.cfg) for Blender:
# runs the installed phyllo-export on the scene file and then the script
# it writes, which builds (or rebuilds) the scene's collection from the
# artist's own organ objects.  A bad scene file is reported with
# phyllo-export's own FILE:LINE message and changes nothing.
#
# Blender 3.x reads bl_info below; 4.2 and later read
# blender_manifest.toml beside this file (an extension).
import os
import runpy
import shutil
import subprocess
import tempfile

import bpy
from bpy.props import StringProperty
from bpy_extras.io_utils import ImportHelper

bl_info = {
    "name": "Phyllotaxis scene (phyllo-export)",
    "author": "phyllo-export",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "File > Import > Phyllotaxis scene (.cfg)",
    "description": "Spiral phyllotaxis from a phyllo-export scene file",
    "category": "Import-Export",
}

# The add-on's package name: "phyllo_import" for 3.x, and
# "bl_ext.REPO.phyllo_import" when installed as an extension.
PACKAGE = __package__ or __name__


class PhylloPreferences(bpy.types.AddonPreferences):
    bl_idname = PACKAGE

    program: StringProperty(
        name="phyllo-export",
        description="The phyllo-export program: a path, or a name "
        "looked up on PATH",
        default="phyllo-export",
        subtype="FILE_PATH")

    def draw(self, context):
        self.layout.prop(self, "program")


def program(context):
    """The configured phyllo-export; PHYLLO_EXPORT overrides it."""
    prefs = context.preferences.addons.get(PACKAGE)
    name = os.environ.get("PHYLLO_EXPORT") or (
        prefs.preferences.program if prefs else "phyllo-export")
    return shutil.which(name) or name


class IMPORT_SCENE_OT_phyllotaxis(bpy.types.Operator, ImportHelper):
    """Build the organs of a phyllo-export scene file, instancing the
    .blend's own organ objects"""
    bl_idname = "import_scene.phyllotaxis"
    bl_label = "Import Phyllotaxis Scene"
    bl_options = {"REGISTER", "UNDO"}

    filename_ext = ".cfg"
    filter_glob: StringProperty(default="*.cfg", options={"HIDDEN"})

    def execute(self, context):
        exe = program(context)
        with tempfile.TemporaryDirectory(prefix="phyllo-") as tmp:
            script = os.path.join(tmp, "import.py")
            try:
                run = subprocess.run(
                    [exe, "--blender", "-o", script, self.filepath],
                    stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                    universal_newlines=True, timeout=600)
            except (OSError, subprocess.SubprocessError) as e:
                self.report({"ERROR"}, "phyllo-export: cannot run %s: %s"
                            % (exe, e))
                return {"CANCELLED"}
            if run.returncode != 0:
                # Our message names the file and line; show it as it is.
                lines = run.stderr.strip().splitlines()
                self.report({"ERROR"}, lines[-1] if lines else
                            "phyllo-export failed (exit %d)"
                            % run.returncode)
                return {"CANCELLED"}
            try:
                runpy.run_path(script, run_name="__main__")
            except SystemExit:
                # The script's own refusal of this Blender, printed on
                # the console; it stops before it changes anything.
                self.report({"ERROR"}, "phyllo-export: the script does "
                            "not run in Blender %s (see the console)"
                            % bpy.app.version_string)
                return {"CANCELLED"}
        self.report({"INFO"}, "Imported %s"
                    % os.path.basename(self.filepath))
        return {"FINISHED"}


def menu_import(self, context):
    self.layout.operator(IMPORT_SCENE_OT_phyllotaxis.bl_idname,
                         text="Phyllotaxis scene (.cfg)")


CLASSES = (PhylloPreferences, IMPORT_SCENE_OT_phyllotaxis)


def register():
    for c in CLASSES:
        bpy.utils.register_class(c)
    bpy.types.TOPBAR_MT_file_import.append(menu_import)


def unregister():
    bpy.types.TOPBAR_MT_file_import.remove(menu_import)
    for c in reversed(CLASSES):
        bpy.utils.unregister_class(c)
