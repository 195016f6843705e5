# check.py - after the generated script has run (twice), compare what
# Blender built with the CSV: every organ an instance (or a linked
# duplicate) of the right object, with the CSV's frame and scale, one
# copy only, no orphan data.  Usage:
#   blender -b FILE.blend --python script.py --python script.py
#       --python check.py -- CSV NAME instances|objects|leaves [FRAME]
# leaves: a compound structure against its --csv --flatten, every leaf
# an instance (parts are instanced collections, not counted); FRAME:
# the scene frame to evaluate, for --frames.
# Prints "check: ..." lines and exits 1 (with --python-exit-code 1) on
# a failure.
import csv
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, done  # noqa: E402

args = sys.argv[sys.argv.index("--") + 1:]
csv_path, name, mode = args[:3]
if len(args) > 3:
    bpy.context.scene.frame_set(int(args[3]))
TAG = "phyllo_export"
rows = list(csv.DictReader(open(csv_path)))


def organ_parts(organ):
    """The object names an instance of this organ shows."""
    ob = bpy.data.objects.get(organ)
    if ob is not None:
        return [ob.name]
    return sorted(o.name for o in bpy.data.collections[organ].objects)


def expected():
    out = []
    for r in rows:
        f = {k: float(r[k]) for k in r if k != "object"}
        s = f["scale"]
        cols = [(f["ux"] * s, f["uy"] * s, f["uz"] * s),
                (f["vx"] * s, f["vy"] * s, f["vz"] * s),
                (f["wx"] * s, f["wy"] * s, f["wz"] * s),
                (f["x"], f["y"], f["z"])]
        for part in organ_parts(r["object"]):
            out.append((part, cols))
    return out


def columns(m):
    return [tuple(m[i][j] for i in range(3)) for j in range(4)]


def built():
    top = bpy.data.collections[name]
    ours = {o.name for c in [top] + list(top.children_recursive)
            for o in c.objects}
    dg = bpy.context.evaluated_depsgraph_get()
    out = []
    if mode in ("instances", "leaves"):
        for inst in dg.object_instances:
            if not inst.is_instance or inst.parent.name not in ours:
                continue
            if mode == "leaves" and inst.instance_object.name in ours \
                    and inst.instance_object.modifiers:
                continue        # a part's own point cloud, not a leaf
            out.append((inst.instance_object.name,
                        columns(inst.matrix_world)))
    else:
        for o in top.objects:
            if o.instance_type == "COLLECTION":
                for part in o.instance_collection.objects:
                    out.append((part.name, columns(o.matrix_world)))
            else:
                out.append((o.data.name if o.data.get(TAG) else
                            [p.name for p in bpy.data.objects
                             if p.data == o.data and p.get(TAG) is None][0],
                            columns(o.matrix_world)))
    return out


want, got = expected(), built()
check(len(got) == len(want), "%d placed organs (parts), CSV says %d"
      % (len(got), len(want)))
pool = {}
for part, cols in got:
    pool.setdefault(part, []).append(cols)
worst, missing = 0.0, 0
for part, cols in want:
    cands = pool.get(part, [])
    best, bi = None, -1
    for i, c in enumerate(cands):
        d = max(abs(a - b) for u, v in zip(c, cols) for a, b in zip(u, v))
        if best is None or d < best:
            best, bi = d, i
    if best is None:
        missing += 1
        continue
    worst = max(worst, best)
    cands.pop(bi)
check(missing == 0, "every organ is the right object (%d missing)" % missing)
check(worst < 2e-5, "matrices equal the CSV frames times scale, at the "
      "CSV positions (worst %.2g)" % worst)
if mode == "leaves":
    top = bpy.data.collections[name]
    points = sum(len(o.data.vertices) for c in [top] + list(top.children_recursive)
                 for o in c.objects if o.modifiers)
    check(points < len(want), "instanced, not copied: %d points in the point "
          "clouds place %d leaves" % (points, len(want)))
check(len([c for c in bpy.data.collections if c.name == name or
           c.name.startswith(name + ".")]) == 1, "one collection %r" % name)
orphans = [d.name for d in list(bpy.data.meshes) + list(bpy.data.node_groups)
           if d.users == 0]
check(not orphans, "no orphan meshes or node groups %s" % orphans)
groups = [g for g in bpy.data.node_groups if g.get(TAG) == name]
if mode != "objects":
    check(groups and all(getattr(g, "is_modifier", True) for g in groups),
          "the node groups are offered in the modifier's picker "
          "(is_modifier where Blender has it)")
seed = bpy.data.objects.get("Seed")
if seed is not None and seed.get(TAG) is None:
    check(tuple(seed.location) == (5, 5, 5) and len(seed.data.vertices) == 8,
          "the artist's Seed is untouched")
done()
