# panel.py - the Phyllotaxis panel as an artist uses it, headless: the
# add-on installed from its zip, a scene imported, count and a model
# setting changed through the panel's properties (each change rebuilds
# the structure), the instances held against --csv with the same --set,
# undo and redo, a bad value (the structure and .blend unchanged, the
# message in the panel and in the Update operator's report), "Save to
# scene file" and the re-import of what it wrote, and an import with
# frames setting the timeline.  Usage:
#   blender -b --factory-startup --python panel.py -- ZIP SCENE DIR
# where SCENE is a copy (Save writes into it) of a planar scene whose
# --csv is DIR/base.csv, with --set count=300 DIR/count.csv, and with
# --set count=300 --set planar.scale=0.05 DIR/scale.csv; and DIR/coll.cfg
# a collision scene on a hemisphere (DIR/coll.csv), DIR/cone.csv with
# --set collision.receptacle.shape="cone"; DIR/inh.cfg an inhibition
# scene with the Gaussian kernel (DIR/inh.csv), DIR/inh-power.csv with
# the power law's, DIR/inh-exp2.csv with its exponent 2 too;
# DIR/inh-file-exp.cfg the power law's with its exponent in the file.
# Prints "check: ..." lines like check.py.
import csv
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from install import install_addon  # noqa: E402 (after the path)

zip_path, scene, folder = sys.argv[sys.argv.index("--") + 1:][:3]
failures = []


def check(ok, what):
    print("check: %s %s" % ("ok" if ok else "FAILED", what))
    if not ok:
        failures.append(what)


install_addon(zip_path)


def positions():
    """Every instance of the structure: its organ and place, rounded."""
    top = bpy.context.scene.phyllo_structure
    ours = {o.name for c in [top] + list(top.children_recursive)
            for o in c.objects}
    dg = bpy.context.evaluated_depsgraph_get()
    return sorted((i.instance_object.name,) + tuple(
        round(x, 5) for x in i.matrix_world.translation)
        for i in dg.object_instances
        if i.is_instance and i.parent.name in ours)


def from_csv(name):
    return sorted((r["object"],) + tuple(
        round(float(r[k]), 5) for k in "xyz")
        for r in csv.DictReader(open(os.path.join(folder, name))))


def same(got, want):
    """Equal up to the rounding of the last digit."""
    return len(got) == len(want) and all(
        a[0] == b[0] and max(abs(x - y) for x, y in zip(a[1:], b[1:]))
        < 2e-5 for a, b in zip(got, want))


def setting(path):
    st = bpy.context.scene.phyllo_structure.phyllo
    return next(s for s in st.settings if s.path == path)


def contents():
    return sorted((kind, d.name) for kind in ("objects", "collections",
                  "meshes", "node_groups")
                  for d in getattr(bpy.data, kind))


# The panel's operators act on a structure: greyed out until one is.
ops = (bpy.ops.phyllo.update, bpy.ops.phyllo.revert, bpy.ops.phyllo.save)
check(not any(op.poll() for op in ops),
      "Update, Revert and Save are greyed out without a structure")
bpy.ops.import_scene.phyllotaxis(filepath=scene)
check(all(op.poll() for op in ops),
      "Update, Revert and Save are live once a structure is imported")
top = bpy.context.scene.phyllo_structure
check(top is not None and top.phyllo.scene == scene,
      "the import remembers its scene file on the collection")
check(hasattr(bpy.types, "VIEW3D_PT_phyllotaxis") and
      bpy.types.VIEW3D_PT_phyllotaxis.bl_category == "Phyllotaxis",
      "a Phyllotaxis panel in the 3D viewport's sidebar")
paths = [s.path for s in top.phyllo.settings]
check("count" in paths and "planar.scale" in paths and
      "organs.0.tilt" in paths,
      "the panel lists the scene's settings (%d)" % len(paths))
check(setting("count").kind == "INTEGER" and
      setting("planar.scale").kind == "NUMBER" and
      setting("organs.0.tilt").kind == "STRING",
      "numbers as number fields, expressions as text")
check(same(positions(), from_csv("base.csv")),
      "imported: the instances where --csv puts them")
bpy.ops.ed.undo_push(message="imported")

setting("count").integer = 300
check(same(positions(), from_csv("count.csv")),
      "count changed in the panel: rebuilt as --csv --set count=300 says")
setting("planar.scale").number = 0.05
check(same(positions(), from_csv("scale.csv")),
      "a model setting changed too: as --csv with both --set")
check(sorted(top.phyllo.overrides()) == ["count=300", "planar.scale=0.05"],
      "the collection remembers the changes (%s)" % top.phyllo.overrides())
bpy.ops.ed.undo_push(message="changed")

bpy.ops.ed.undo()
check(same(positions(), from_csv("base.csv")) and
      setting("count").integer == int(setting("count").written),
      "undo: the structure and the panel as imported")
bpy.ops.ed.redo()
check(same(positions(), from_csv("scale.csv")) and
      setting("count").integer == 300,
      "redo: the changed structure again")

before = contents()
built = positions()
setting("count").integer = 0
st = bpy.context.scene.phyllo_structure.phyllo
check("--set count=0: count 0 is out of range" in st.error,
      "a bad value: our message in the panel (%r)" % st.error)
check(positions() == built and contents() == before,
      "and the structure and .blend as they were")
try:
    bpy.ops.phyllo.update()
    report = ""
except RuntimeError as e:
    report = str(e)
check("--set count=0: count 0 is out of range" in report,
      "Update reports it too (%r)" % report)
setting("count").integer = 300
check(not st.error and same(positions(), from_csv("scale.csv")),
      "a good value again clears the message and rebuilds")

text_before = open(scene).read()
bpy.ops.phyllo.save()
text = open(scene).read()
check("count = 300;" in text and "scale = 0.05" in text,
      "Save to scene file writes the changes into the .cfg")
check([l for l in text.splitlines() if l.lstrip().startswith("#")] ==
      [l for l in text_before.splitlines() if l.lstrip().startswith("#")],
      "and keeps its comments")
# (Undo reloaded the data: references from before it are gone.)
top = bpy.context.scene.phyllo_structure
check(top.phyllo.overrides() == [],
      "after saving, the panel shows the file's own values")
saved = positions()
# A fresh start (the add-on stays): everything of the structure gone.
for kind in ("objects", "collections", "meshes", "node_groups"):
    for d in list(getattr(bpy.data, kind)):
        getattr(bpy.data, kind).remove(d)
bpy.ops.import_scene.phyllotaxis(filepath=scene)
check(same(positions(), saved) and same(saved, from_csv("scale.csv")),
      "re-importing the saved file builds the same structure")

# A word of a list, from its menu: the receptacle's shape.
bpy.ops.import_scene.phyllotaxis(filepath=os.path.join(folder, "coll.cfg"))
shape = setting("collision.receptacle.shape")
check(shape.kind == "CHOICE" and shape.choice == "hemisphere" and
      bpy.context.scene.phyllo_structure.phyllo.overrides() == [],
      "a choice as a menu, as the file has it, and nothing changed")
check(same(positions(), from_csv("coll.csv")),
      "the collision scene where --csv puts it")
shape.choice = "cone"
check(same(positions(), from_csv("cone.csv")),
      "shape chosen from the menu: rebuilt as --set shape=\"cone\" says")
# A receptacle by profile has no shape: the menu says so, and offers it.
bpy.ops.import_scene.phyllotaxis(filepath=os.path.join(
    os.path.dirname(os.path.dirname(folder)), "..", "scenes",
    "coneflower.cfg"))
check(setting("collision.receptacle.shape").choice == "(none)" and
      bpy.context.scene.phyllo_structure.phyllo.overrides() == [],
      "a shape not given reads (none), and is no change")

# A setting the others leave unused: greyed out, and out of --set.
bpy.ops.import_scene.phyllotaxis(filepath=os.path.join(folder, "inh.cfg"))
st = bpy.context.scene.phyllo_structure.phyllo
exponent, kernel = setting("inhibition.exponent"), setting("inhibition.kernel")
check(not exponent.applies and "gaussian" in exponent.why and
      kernel.applies and same(positions(), from_csv("inh.csv")),
      "the Gaussian kernel's scene: the exponent listed, not applying "
      "(%r)" % exponent.why)
kernel.choice = "power"
check(exponent.applies and not st.error and
      same(positions(), from_csv("inh-power.csv")),
      "the kernel chosen from the menu: the exponent applies again, and "
      "the structure is the power law's (%r)" % st.error)
exponent.number = 2
check(same(positions(), from_csv("inh-exp2.csv")) and
      sorted(st.overrides()) == ['inhibition.exponent=2',
                                 'inhibition.kernel="power"'],
      "the exponent changed: as --csv with both --set (%s)"
      % st.overrides())
kernel.choice = "gaussian"
check(not st.error and not exponent.applies and
      same(positions(), from_csv("inh.csv")) and st.overrides() == [] and
      st.overrides(every=True) == ["inhibition.exponent=2"],
      "back to the Gaussian: the changed exponent kept but not sent, "
      "no error (%r), the file's structure again" % st.error)
bpy.ops.phyllo.save()
st = bpy.context.scene.phyllo_structure.phyllo
check(not setting("inhibition.exponent").applies and
      setting("inhibition.exponent").number == 2 and
      st.overrides(every=True) == ["inhibition.exponent=2"],
      "Save keeps the change of a setting that does not apply (%s)"
      % st.overrides(every=True))
# The exponent in the file itself: the kernel's menu must still work.
bpy.ops.import_scene.phyllotaxis(
    filepath=os.path.join(folder, "inh-file-exp.cfg"))
st = bpy.context.scene.phyllo_structure.phyllo
setting("inhibition.kernel").choice = "gaussian"
check(not st.error and not setting("inhibition.exponent").applies and
      same(positions(), from_csv("inh.csv")),
      "a scene whose file gives the exponent, switched to the Gaussian: "
      "built, the file's exponent ignored (%r)" % st.error)

bpy.ops.import_scene.phyllotaxis(filepath=scene, frames=5)
sc = bpy.context.scene
check(sc.frame_end - sc.frame_start == 4 and
      bpy.context.scene.phyllo_structure.phyllo.frames == 5,
      "an import with 5 frames sets the timeline to them")
if failures:
    raise SystemExit("check: %d failed" % len(failures))
