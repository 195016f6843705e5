# roundtrip.py - the panel's round trip, timed: a setting changed
# through the Phyllotaxis panel's property until the structure is built
# again (phyllo-export run with --set, its script run) and evaluated
# (the instances made), best of three.
# Usage: blender -b --factory-startup --python roundtrip.py -- ZIP SCENE
# Prints "roundtrip: SECONDS ORGANS".
import os
import sys
import time

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from install import install_addon  # noqa: E402 (after the path)

zip_path, scene = sys.argv[sys.argv.index("--") + 1:][:2]
install_addon(zip_path)
bpy.ops.import_scene.phyllotaxis(filepath=scene)
st = bpy.context.scene.phyllo_structure.phyllo
scale = next(s for s in st.settings if s.path == "planar.scale")
count = next(s for s in st.settings if s.path == "count").integer
st.live = False     # each change rebuilt by Update, whatever its time
best = None
for i in range(3):
    start = time.perf_counter()
    scale.text = "%g" % (0.01 + 0.001 * (i + 1))
    bpy.ops.phyllo.update()
    # Evaluated: the geometry nodes have made the new instances.
    bpy.context.evaluated_depsgraph_get()
    t = time.perf_counter() - start
    best = t if best is None else min(best, t)
print("roundtrip: %.3f %d" % (best, count))
