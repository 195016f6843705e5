# roundtrip.py - the panel's round trip, timed: a setting changed
# through the Phyllotaxis panel's property until the structure is built
# again (phyllo-export run with --set, its script run) and evaluated
# (the instances made), best of three.
# Usage: blender -b --factory-startup --python roundtrip.py -- ZIP SCENE
# Prints "roundtrip: SECONDS ORGANS".
import sys
import time

import bpy

zip_path, scene = sys.argv[sys.argv.index("--") + 1:][:2]
if bpy.app.version >= (4, 2, 0):
    bpy.ops.extensions.package_install_files(
        filepath=zip_path, repo="user_default", enable_on_install=True)
else:
    bpy.ops.preferences.addon_install(filepath=zip_path)
    bpy.ops.preferences.addon_enable(module="phyllo_import")
bpy.ops.import_scene.phyllotaxis(filepath=scene)
st = bpy.context.scene.phyllo_structure.phyllo
scale = next(s for s in st.settings if s.path == "planar.scale")
count = next(s for s in st.settings if s.path == "count").integer
st.live = False     # each change rebuilt by Update, whatever its time
best = None
for i in range(3):
    start = time.perf_counter()
    scale.number = 0.01 + 0.001 * (i + 1)
    bpy.ops.phyllo.update()
    # Evaluated: the geometry nodes have made the new instances.
    bpy.context.evaluated_depsgraph_get()
    t = time.perf_counter() - start
    best = t if best is None else min(best, t)
print("roundtrip: %.3f %d" % (best, count))
