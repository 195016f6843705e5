# timeit.py - seconds a script takes inside Blender, start-up excluded:
# the script run, then the dependency graph evaluated, so that the
# instances are really made.  Usage:
#   blender -b --factory-startup --python timeit.py -- SCRIPT
# Prints "timeit: SECONDS".
import runpy
import sys
import time

import bpy

script = sys.argv[sys.argv.index("--") + 1]
t0 = time.perf_counter()
runpy.run_path(script, run_name="__main__")
bpy.context.evaluated_depsgraph_get()
print("timeit: %.4f" % (time.perf_counter() - t0))
