# rerun.py - running the script again keeps the artist's work: the
# structure's collection itself (with what the artist put on it), a
# placeholder whose mesh they edited, and one they renamed, each kept
# as their organ and instanced, with a line saying so; placeholders
# left as they were are made again, once.  Usage:
#   blender -b --factory-startup --python rerun.py -- SCRIPT NAME
# for a SCRIPT of scene NAME whose organs Seed, Leaf and Petal are all
# placeholders.  Prints "check: ..." lines like check.py.
import contextlib
import io
import os
import runpy
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, done  # noqa: E402

script, name = sys.argv[sys.argv.index("--") + 1:][:2]


def run():
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        runpy.run_path(script, run_name="__main__")
    print(out.getvalue(), end="")
    return out.getvalue()


def organ_of(points_name):
    """The object the point cloud's modifier instances, read by the
    identifier of its group's "Organ" input, as the script sets it."""
    mod = bpy.data.objects[points_name].modifiers[0]
    group = mod.node_group
    if hasattr(group, "interface"):
        ident = next(i.identifier for i in group.interface.items_tree
                     if i.name == "Organ")
    else:
        ident = group.inputs["Organ"].identifier
    inputs = getattr(getattr(mod, "properties", None), "inputs", None)
    if inputs is not None:      # Blender 5.2's RNA inputs
        return getattr(inputs, ident).value
    return mod[ident]


run()
top = bpy.data.collections[name]
pointer = top.as_pointer()
top["artist_note"] = "mine"
seed = bpy.data.objects["Seed"]
for v in seed.data.vertices:        # the artist models the seed
    v.co.x *= 2.0
leaf = bpy.data.objects["Leaf"]
leaf.name = "MyLeaf"                # and renames the leaf

said = run()
top = bpy.data.collections.get(name)
check(top is not None and top.as_pointer() == pointer,
      "the collection is the same one, not made again")
check(top is not None and top.get("artist_note") == "mine",
      "what the artist put on the collection stays")
seed = bpy.data.objects.get("Seed")
check(seed is not None and max(v.co.x for v in seed.data.vertices) > 1.9,
      "the edited Seed placeholder is kept, mesh and all")
check("kept 'Seed', a placeholder you edited" in said and
      "kept 'MyLeaf', a placeholder you edited" in said,
      "the script says which it kept")
check(organ_of(name + ".Seed") == seed,
      "the seeds instance the artist's edited Seed")
check(organ_of(name + ".Leaf") == bpy.data.objects.get("MyLeaf"),
      "the leaves instance the renamed MyLeaf")
check(bpy.data.objects.get("Leaf") is None,
      "no new Leaf placeholder beside the renamed one")
petal = bpy.data.objects.get("Petal")
check(petal is not None and petal.get("phyllo_organ") == "Petal",
      "the Petal placeholder, left as it was, is made again")

said = run()
check("kept" not in said, "a third run keeps nothing more")
names = sorted(o.name for o in bpy.data.objects)
check(not any(n.split(".")[-1].isdigit() for n in names),
      "no duplicates (.001) of anything: %s" % names)
check(sum(1 for c in bpy.data.collections if c.get("phyllo_structure")) == 1,
      "one structure collection")
names = sorted(c.name for c in bpy.data.collections)
check(not any(n.split(".")[-1].isdigit() for n in names),
      "no duplicate collections (.001): %s" % names)
check(organ_of(name + ".Seed") == bpy.data.objects.get("Seed") and
      organ_of(name + ".Leaf") == bpy.data.objects.get("MyLeaf"),
      "still the artist's organs")
done()
