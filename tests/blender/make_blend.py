# make_blend.py - a .blend as an artist would have it: their own "Seed"
# object (modelled at its origin, placed elsewhere in the scene) and a
# collection "Bract" of two objects.  Usage: blender -b --factory-startup
# --python make_blend.py -- OUT.blend
import os
import sys

import bmesh
import bpy

out = sys.argv[sys.argv.index("--") + 1]
bpy.ops.wm.read_factory_settings(use_empty=True)


def cube(name, size):
    bm = bmesh.new()
    bmesh.ops.create_cube(bm, size=size)
    mesh = bpy.data.meshes.new(name)
    bm.to_mesh(mesh)
    bm.free()
    return bpy.data.objects.new(name, mesh)


seed = cube("Seed", 1.0)
seed.location = (5, 5, 5)           # out of the way; the organ ignores it
bpy.context.scene.collection.objects.link(seed)
bract = bpy.data.collections.new("Bract")
bpy.context.scene.collection.children.link(bract)
for name in ("BractA", "BractB"):
    bract.objects.link(cube(name, 0.5))
bpy.ops.wm.save_as_mainfile(filepath=os.path.abspath(out))
