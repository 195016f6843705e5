# addon.py - the import add-on as an artist meets it: installed from the
# zip the way this Blender expects (an extension from 4.2 on, a legacy
# add-on before), enabled, in File > Import, run on a scene, run again,
# and run on a bad scene; and a scene whose last frame is bad, imported
# without frames, then with them: the .blend as it was, to the last
# data-block and user, the timeline too.  Usage:
#   blender -b --factory-startup --python addon.py -- ZIP GOOD.cfg COUNT \
#       BAD.cfg WHERE GROW.cfg FRAMES WHERE PROGRAM
# where COUNT is the good scene's organ count and WHERE the FILE:LINE
# the bad scene's error names, GROW.cfg the scene good at frame 1 and
# bad at frame FRAMES, its WHERE its message's, and PROGRAM the
# phyllo-export the add-on must choose: "own" for the one in its zip,
# else a path.  Prints "check: ..." lines like check.py.
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import state  # noqa: E402 (after the path)
from install import install_addon  # noqa: E402
from checks import check, done  # noqa: E402

(zip_path, good, count, bad, where, grow, frames, grow_where,
 expect) = sys.argv[sys.argv.index("--") + 1:][:9]
count = int(count)


install_addon(zip_path)

check(hasattr(bpy.types, "IMPORT_SCENE_OT_phyllotaxis"),
      "the add-on is installed and enabled")
menu = [f.__name__ for f in bpy.types.TOPBAR_MT_file_import._dyn_ui_initialize()]
check("menu_import" in menu, "File > Import lists it")

# The add-on's module: phyllo_import, or bl_ext.REPO.phyllo_import.
addon = [m for n, m in sys.modules.items() if n.split(".")[-1] ==
         "phyllo_import"][0]
chosen = addon.program(bpy.context)
if expect == "own":
    check(chosen is not None and os.path.dirname(os.path.dirname(chosen)) ==
          os.path.dirname(os.path.abspath(addon.__file__)),
          "it runs the program in its own folder (%s)" % chosen)
else:
    check(chosen == expect, "it runs %s (%s)" % (expect, chosen))


def organs():
    """Organs in the built collection: points of its point clouds."""
    tops = [c for c in bpy.context.scene.collection.children
            if c.get("phyllo_export")]
    made = [c for c in bpy.data.collections if c.get("phyllo_export")]
    return len(tops), sum(len(o.data.vertices) for c in made
                          for o in c.objects if o.get("phyllo_export")
                          and o.type == "MESH" and o.modifiers)


bpy.ops.import_scene.phyllotaxis(filepath=good)
check(organs() == (1, count), "the import builds one collection of %d "
      "organs (%r)" % (count, organs()))
bpy.ops.import_scene.phyllotaxis(filepath=good)
check(organs() == (1, count), "a second import replaces the first (%r)"
      % (organs(),))


def failed(path, frames=0):
    """The message of an import that must fail, and what it changed in
    the .blend ("" for nothing)."""
    before = state.snapshot()
    timeline = bpy.context.scene.frame_end
    try:
        bpy.ops.import_scene.phyllotaxis(filepath=path, frames=frames)
        message = ""
    except RuntimeError as e:
        message = str(e)
    return message, state.differences(before, state.snapshot()) + (
        " frame_end %d -> %d" % (timeline, bpy.context.scene.frame_end)
        if bpy.context.scene.frame_end != timeline else "")


message, changes = failed(bad)
check(where in message and "phyllo-export:" in message,
      "a bad scene is reported with our FILE:LINE message (%r)" % message)
check(not changes, "and changes nothing in the .blend (%s)" % changes)
bpy.ops.import_scene.phyllotaxis(filepath=grow)
message, changes = failed(grow, int(frames))
check(grow_where in message and not changes,
      "a scene bad at its last frame, imported again with frames: our "
      "message (%r), and the .blend as it was (%s)" % (message, changes))
done()
