# run_all.py - run several generated scripts in one Blender process, each
# into a fresh empty file, and say of each whether it built: one start-up
# per Blender instead of one per scene.  Usage:
#   blender -b --factory-startup --python run_all.py -- SCRIPT...
# Prints "run_all: ok SCRIPT" or "run_all: FAILED SCRIPT: why".
import runpy
import sys
import traceback

import bpy

for path in sys.argv[sys.argv.index("--") + 1:]:
    bpy.ops.wm.read_factory_settings(use_empty=True)
    try:
        runpy.run_path(path, run_name="__main__")
        made = [c for c in bpy.data.collections if c.get("phyllo_export")]
        if not made:
            raise RuntimeError("no collection built")
        print("run_all: ok %s" % path)
    except BaseException as e:
        why = traceback.format_exception_only(type(e), e)[-1].strip()
        print("run_all: FAILED %s: %s" % (path, why))
