# lookup.py - where the add-on carries no program and none is on PATH,
# an import says so, and runs none from the current folder (PATH's "."
# and empty entries) or the scene's, where a decoy waits.  Usage:
#   blender -b --factory-startup --python lookup.py -- ZIP SCENE MARKER
# where SCENE's folder holds a phyllo-export that would make MARKER.
# Prints "check: ..." lines like check.py.
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from install import install_addon  # noqa: E402 (after the path)
from checks import check, done  # noqa: E402

zip_path, scene, marker = sys.argv[sys.argv.index("--") + 1:][:3]


install_addon(zip_path)
try:
    bpy.ops.import_scene.phyllotaxis(filepath=scene)
    message = ""
except RuntimeError as e:
    message = str(e)
check("program not found" in message,
      "with none on PATH the import says the program is not found (%r)"
      % message)
check(not os.path.exists(marker), "and ran nothing from the scene's "
      "folder")
check(not [c for c in bpy.data.collections if c.get("phyllo_export")],
      "nor from the current folder: nothing was built")
done()
