# panel.py - the Phyllotaxis panel as an artist uses it, headless: the
# add-on installed from its zip, a scene imported, count and a model
# setting changed through the panel's properties (each change rebuilds
# the structure), the instances held against --csv with the same --set,
# undo and redo, a bad value (the structure and .blend unchanged, the
# message in the panel, wrapped to the sidebar's width, and in the
# Update operator's report), "Save to scene file" and the re-import of
# what it wrote, numbers reaching the structure exactly as typed, Save
# taking out a setting a change leaves unused, a part's settings
# changed and saved into the part's own file, and imports with frames:
# the timeline set, a change and its undoing leaving nothing orphaned.
# Usage:
#   blender -b --factory-startup --python panel.py -- ZIP SCENE DIR
# where SCENE is a copy (Save writes into it) of a planar scene whose
# --csv is DIR/base.csv, with --set count=300 DIR/count.csv, and with
# --set count=300 --set planar.scale=0.05 DIR/scale.csv; DIR/panel.cfg
# the scene as it was, DIR/exact.csv its --csv with --set
# planar.scale=0.0437 --set divergence=137.36; and DIR/coll.cfg
# a collision scene on a hemisphere (DIR/coll.csv), DIR/cone.csv with
# --set collision.receptacle.shape="cone"; DIR/inh.cfg an inhibition
# scene with the Gaussian kernel (DIR/inh.csv), DIR/inh-power.csv with
# the power law's, DIR/inh-exp2.csv with its exponent 2 too.  Beside
# SCENE, copies Save writes into: inh-file-exp.cfg, the power law's with
# its exponent in the file (and comments), and gb/goatsbeard.cfg with
# its part gb/parts/goatsbeard-pappus.cfg, whose leaves with --set
# Achene:count=15 are DIR/gb15.csv (--csv --flatten).  DIR/stages.cfg:
# the README's growth.  Prints "check: ..." lines like check.py.
import csv
import os
import shutil
import sys
import types

import blf
import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import state  # noqa: E402 (after the path)
from install import install_addon  # noqa: E402
from checks import check, done  # noqa: E402

zip_path, scene, folder = sys.argv[sys.argv.index("--") + 1:][:3]
here = os.path.dirname(scene)


install_addon(zip_path)
start = state.snapshot()


def positions(leaves=False):
    """Every instance of the structure: its organ and place, rounded;
    leaves: a compound's leaves, not its parts."""
    top = bpy.context.scene.phyllo_structure
    ours = {o.name for c in [top] + list(top.children_recursive)
            for o in c.objects}
    dg = bpy.context.evaluated_depsgraph_get()
    return sorted((i.instance_object.name,) + tuple(
        round(x, 5) for x in i.matrix_world.translation)
        for i in dg.object_instances
        if i.is_instance and i.parent.name in ours and not (
            leaves and i.instance_object.name in ours and
            i.instance_object.modifiers))


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


class Layout:
    """What the panel's draw() is given as its layout, keeping the
    labels it draws: (text, icon, whether in a setting's row, whose name
    is cut short by design)."""

    def __init__(self, labels, in_row=False):
        self.labels, self.in_row = labels, in_row

    def label(self, text="", icon="NONE"):
        self.labels.append((text, icon, self.in_row))

    def prop(self, *args, **kwargs):
        pass

    operator = prop

    def box(self, **kwargs):
        return Layout(self.labels, self.in_row)

    row = column = box

    def split(self, **kwargs):
        return Layout(self.labels, True)


def drawn(width):
    """The labels the panel draws in a sidebar width pixels wide."""
    labels = []
    context = types.SimpleNamespace(
        scene=bpy.context.scene, preferences=bpy.context.preferences,
        region=types.SimpleNamespace(width=width))
    bpy.types.VIEW3D_PT_phyllotaxis.draw(
        types.SimpleNamespace(layout=Layout(labels)), context)
    return labels


def at_width(width, scale):
    """The labels the panel draws in a sidebar width pixels wide at UI
    scale, and those of them, out of its settings' rows, that do not fit:
    what Blender would cut short.  A label has the width less the tabs',
    the panel's, the box's and its own margins, 64 pixels at scale 1,
    and beside an icon 25 more (a screenshot of Blender 3.4: a sidebar
    229 pixels wide at scale 1.04 shows 162 pixels of text, 136 beside
    an icon)."""
    view = bpy.context.preferences.view
    old, view.ui_scale = view.ui_scale, scale
    try:
        labels = drawn(width * scale)
        blf.size(0, bpy.context.preferences.ui_styles[0].widget.points *
                 scale)
        return labels, [
            text for text, icon, in_row in labels
            if not in_row and blf.dimensions(0, text)[0] >
            (width - 64 - 25 * (icon != "NONE")) * scale]
    finally:
        view.ui_scale = old


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
      setting("planar.scale").text == "0.1" and
      setting("organs.0.tilt").kind == "NUMBER" and
      setting("organs.1.tilt").text == "20 * rand(1)",
      "integers as integer fields, numbers and expressions as their text")
check(same(positions(), from_csv("base.csv")),
      "imported: the instances where --csv puts them")
bpy.ops.ed.undo_push(message="imported")

setting("count").integer = 300
check(same(positions(), from_csv("count.csv")),
      "count changed in the panel: rebuilt as --csv --set count=300 says")
setting("planar.scale").text = "0.05"
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

before = state.snapshot()
built = positions()
setting("count").integer = 0
st = bpy.context.scene.phyllo_structure.phyllo
check("--set count=0: count 0 is out of range" in st.error,
      "a bad value: our message in the panel (%r)" % st.error)
changes = state.differences(before, state.snapshot())
check(positions() == built and not changes,
      "and the structure and .blend as they were (%s)" % changes)


def wrapped_whole(what):
    """The message whole, on lines that fit the sidebar (Blender cuts a
    label too wide for it in the middle), at its narrowest and at double
    scale."""
    error = bpy.context.scene.phyllo_structure.phyllo.error
    for width, scale in ((220, 1.0), (300, 1.0), (220, 2.0)):
        labels, wide = at_width(width, scale)
        # The message's: the ERROR label and the BLANK1 ones after it.
        icons = [icon for text, icon, in_row in labels]
        first = icons.index("ERROR") if "ERROR" in icons else len(icons)
        last = first + 1
        while last < len(icons) and icons[last] == "BLANK1":
            last += 1
        lines = [text for text, icon, in_row in labels[first:last]]
        check(error and not wide and "".join(lines).replace(" ", "") ==
              error.replace(" ", ""),
              "%s, in a sidebar %d pixels wide at scale %g: the message "
              "whole, in %d lines that fit (too wide: %s)"
              % (what, width, scale, len(lines), wide))


wrapped_whole("count 0")
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
# An expression written without spaces, wider than a line by itself.
setting("organs.1.tilt").text = "20*rand(1)*smoothstep(0,0.6,t)*unknown"
wrapped_whole("an unknown variable in a long expression")
setting("organs.1.tilt").text = "20 * rand(1)"
check(not st.error and same(positions(), from_csv("scale.csv")),
      "the expression as it was: no message, the structure as before")

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
# A fresh start (the add-on stays): everything made since it was
# installed gone.
had = {(k, name) for k, blocks in start.items() for name, _ in blocks}
bpy.data.batch_remove([d for k in state.kinds() for d in getattr(bpy.data, k)
                       if (k, d.name) not in had])
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
exponent.text = "2"
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
      setting("inhibition.exponent").text == "2" and
      st.overrides(every=True) == ["inhibition.exponent=2"],
      "Save keeps the change of a setting that does not apply (%s)"
      % st.overrides(every=True))
# The exponent in the file itself: the kernel's menu must still work,
# and Save takes the exponent out of the file, the comments kept.
saving = os.path.join(here, "inh-file-exp.cfg")
bpy.ops.import_scene.phyllotaxis(filepath=saving)
st = bpy.context.scene.phyllo_structure.phyllo
setting("inhibition.kernel").choice = "gaussian"
check(not st.error and not setting("inhibition.exponent").applies and
      same(positions(), from_csv("inh.csv")),
      "a scene whose file gives the exponent, switched to the Gaussian: "
      "built, the file's exponent ignored (%r)" % st.error)
text_before = open(saving).read()
try:
    bpy.ops.phyllo.save()
    report = ""
except RuntimeError as e:
    report = str(e)
text = open(saving).read()
check(not report and 'kernel = "gaussian"' in text and
      not any(l.split("#")[0].strip().startswith("exponent")
              for l in text.splitlines()),
      "Save writes the kernel and takes the exponent out of the file "
      "(%r)" % report)
check([l for l in text.splitlines() if "#" in l] ==
      [l for l in text_before.splitlines() if "#" in l],
      "and keeps its comments")
bpy.ops.import_scene.phyllotaxis(filepath=saving)
check(same(positions(), from_csv("inh.csv")) and
      bpy.context.scene.phyllo_structure.phyllo.overrides() == [],
      "the file saved builds the Gaussian's structure")

# Numbers reach the structure exactly as typed, not rounded to what a
# float field holds (seven digits) or to fewer.
bpy.ops.import_scene.phyllotaxis(filepath=os.path.join(folder,
                                                        "panel.cfg"))
st = bpy.context.scene.phyllo_structure.phyllo
setting("planar.scale").text = "0.0437"
setting("divergence").text = "137.36"
check(sorted(st.overrides()) == ["divergence=137.36",
                                 "planar.scale=0.0437"] and
      same(positions(), from_csv("exact.csv")),
      "0.0437 and 137.36 typed: sent so, the structure as --csv --set "
      "planar.scale=0.0437 --set divergence=137.36 (%s)" % st.overrides())
setting("divergence").text = "137.50776405003785"
check(st.overrides() == ["planar.scale=0.0437"] and not st.error,
      "the divergence typed back to the default's 17 digits: no change "
      "(%s)" % st.overrides())
setting("divergence").text = "137.507764050"
check("divergence=137.507764050" in st.overrides(),
      "12 digits sent as typed (%s)" % st.overrides())

# A part's settings, listed by part: a change rebuilds the part as
# --set PART:path does, and Save writes it into the part's own file.
gb = os.path.join(here, "gb", "goatsbeard.cfg")
part = os.path.join(here, "gb", "parts", "goatsbeard-pappus.cfg")
bpy.ops.import_scene.phyllotaxis(filepath=gb)
st = bpy.context.scene.phyllo_structure.phyllo
count = setting("Achene:count")
check(count.kind == "INTEGER" and count.file == part and
      setting("count").file == gb,
      "the part's count listed, from the part's file (%s)" % count.file)
count.integer = 15
check(not st.error and st.overrides() == ["Achene:count=15"] and
      same(positions(True), from_csv("gb15.csv")),
      "the part's count changed: the leaves where --csv --flatten --set "
      "Achene:count=15 puts them (%r)" % st.error)
main_before, part_before = open(gb).read(), open(part).read()
bpy.ops.phyllo.save()
main_after, part_after = open(gb).read(), open(part).read()
check(main_after == main_before and "count = 15;" in part_after and
      [l for l in part_after.splitlines() if "#" in l] ==
      [l for l in part_before.splitlines() if "#" in l],
      "Save writes it into the part's own file, its comments kept, and "
      "leaves the scene's")
bpy.ops.import_scene.phyllotaxis(filepath=gb)
check(bpy.context.scene.phyllo_structure.phyllo.overrides() == [] and
      same(positions(True), from_csv("gb15.csv")),
      "imported again: the part as saved, nothing changed")

bpy.ops.import_scene.phyllotaxis(filepath=scene, frames=5)
sc = bpy.context.scene
check(sc.frame_end - sc.frame_start == 4 and
      bpy.context.scene.phyllo_structure.phyllo.frames == 5,
      "an import with 5 frames sets the timeline to them")

# The README's growth, its numbers expressions of f: imported with 4
# frames, a change and its undoing by the panel leave the .blend as the
# import did, nothing orphaned.
stages = os.path.join(folder, "stages.cfg")
bpy.ops.import_scene.phyllotaxis(filepath=stages, frames=4)
st = bpy.context.scene.phyllo_structure.phyllo
scale = setting("planar.scale")
check(scale.kind == "NUMBER" and scale.text == "0.035 + 0.01 * f" and
      not st.overrides() and sc.frame_end - sc.frame_start == 3,
      "stages.cfg with 4 frames: its scale an expression field, as the "
      "file has it; the timeline the 4 frames")
imported = state.snapshot()
scale.text = "0.03 + 0.02 * f"
check(not st.error and st.overrides() == [
    'planar.scale="0.03 + 0.02 * f"'] and not state.orphans(imported),
      "an expression changed: rebuilt, nothing orphaned (%r)" % st.error)
scale.text = "0.035 + 0.01 * f"
changes = state.differences(imported, state.snapshot())
check(not st.overrides() and not changes and not state.orphans(imported),
      "and changed back: the .blend as the import left it (%s)" % changes)
setting("count").integer = 200
bpy.ops.phyllo.revert()
st = bpy.context.scene.phyllo_structure.phyllo
changes = state.differences(imported, state.snapshot())
check(not st.overrides() and not changes,
      "a change reverted: the .blend as the import left it (%s)" % changes)
# Revert after the file went bad at its last frame since: our message,
# and the .blend and the panel's fields as they were.
gone_bad = os.path.join(here, "stages-bad.cfg")
shutil.copy(stages, gone_bad)
bpy.ops.import_scene.phyllotaxis(filepath=gone_bad, frames=4)
st = bpy.context.scene.phyllo_structure.phyllo
setting("count").integer = 300
with open(gone_bad) as f:
    text = f.read().replace("count = 420;", 'count = "420 - 500 * f";')
with open(gone_bad, "w") as f:
    f.write(text)
before = state.snapshot()
fields = [(s.path, s.value()) for s in st.settings]
try:
    bpy.ops.phyllo.revert()
    report = ""
except RuntimeError as e:
    report = str(e)
st = bpy.context.scene.phyllo_structure.phyllo
changes = state.differences(before, state.snapshot())
check("stages-bad.cfg:10: frame 4 of 4" in report and
      "stages-bad.cfg:10: frame 4 of 4" in st.error and not changes and
      [(s.path, s.value()) for s in st.settings] == fields,
      "Revert of a file gone bad since: its message (%r), the .blend (%s) "
      "and the panel as they were" % (report, changes))

# The whole session, every import, change, undo, save and revert above.
left = state.orphans(start)
check(not left, "nothing orphaned by any of it %s" % left[:8])
done()
