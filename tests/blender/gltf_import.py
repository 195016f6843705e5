# gltf_import.py - import .glb files phyllo-export --gltf wrote with
# Blender's own glTF importer (4.0 and newer read EXT_mesh_gpu_instancing
# as one object per instance under the node's), each into an empty file,
# and hold every organ against the CSV: its object, position, the whole
# frame u, v, w and its scale; and, for objects whose OBJ mesh is named,
# where the mesh's own outward (+X), up (+Y) and side (+Z) tips land.
# Usage:
#   blender -b --factory-startup --python gltf_import.py -- \
#       GLB CSV [OBJECT=OBJ ...] [-- GLB CSV ...]
# Prints "check: ok ..." / "check: FAILED ..." lines; exits 1 on a failure.
import csv
import math
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, done  # noqa: E402


def obj_tips(path):
    """The OBJ file's vertices furthest along +X, +Y and +Z."""
    vs = []
    for line in open(path):
        f = line.split()
        if f and f[0] == "v":
            vs.append(tuple(float(x) for x in f[1:4]))
    return [max(vs, key=lambda v: v[k]) for k in range(3)]


def one(glb, csv_path, meshes):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=glb)
    rows = list(csv.DictReader(open(csv_path)))
    size = 0.0
    for a in ("x", "y", "z"):
        vals = [float(r[a]) for r in rows]
        size += (max(vals) - min(vals)) ** 2
    tol = 1e-5 * max(math.sqrt(size), 1e-9)
    # The organs of each object, in CSV order; the importer names an
    # instance's parent after the glTF node, the organ object.
    want = {}
    for r in rows:
        want.setdefault(r["object"], []).append(r)
    got = {}
    for ob in bpy.data.objects:
        if ob.type == "MESH" and ob.parent is not None and \
                ob.parent.name in want:
            got.setdefault(ob.parent.name, []).append(ob)
    counts = {k: len(v) for k, v in want.items()}
    check({k: len(v) for k, v in got.items()} == counts,
          "%s: an object per organ under each organ object's node, as "
          "the CSV counts them %s" % (glb, counts))
    worst, matched = 0.0, 0
    tips_worst = 0.0
    for name, rs in want.items():
        pool = list(got.get(name, []))
        tips = obj_tips(meshes[name]) if name in meshes else None
        for r in rs:
            f = {k: float(r[k]) for k in r if k != "object"}
            s = f["scale"]
            u = (f["ux"], f["uy"], f["uz"])
            v = (f["vx"], f["vy"], f["vz"])
            w = (f["wx"], f["wy"], f["wz"])
            p = (f["x"], f["y"], f["z"])
            cols = [tuple(c * s for c in u), tuple(c * s for c in v),
                    tuple(c * s for c in w), p]
            best, bi = None, -1
            for i, ob in enumerate(pool):
                m = ob.matrix_world
                d = max(abs(m[i3][j] - cols[j][i3])
                        for j in range(4) for i3 in range(3))
                if best is None or d < best:
                    best, bi = d, i
            if best is None:
                continue
            ob = pool.pop(bi)
            matched += 1
            worst = max(worst, best)
            if tips is None:
                continue
            # The OBJ is the organ outward +X, up +Y, side +Z = u x w.
            world = [ob.matrix_world @ vert.co for vert in ob.data.vertices]
            for t in tips:
                e = [p[k] + s * (t[0] * u[k] + t[1] * w[k] - t[2] * v[k])
                     for k in range(3)]
                d = min(max(abs(x[k] - e[k]) for k in range(3))
                        for x in world)
                tips_worst = max(tips_worst, d)
    check(matched == len(rows) and worst <= tol,
          "%s: every organ's matrix is the CSV's u, v, w times scale at "
          "its position (%d matched, worst %.2g, allowed %.2g)"
          % (glb, matched, worst, tol))
    if meshes:
        check(tips_worst <= tol, "%s: the OBJ meshes' +X, +Y and +Z tips "
              "land at u, w and -v from each organ (worst %.2g)"
              % (glb, tips_worst))


args = sys.argv[sys.argv.index("--") + 1:]
groups, cur = [], []
for a in args:
    if a == "--":
        groups.append(cur)
        cur = []
    else:
        cur.append(a)
groups.append(cur)
for g in groups:
    one(g[0], g[1], dict(m.split("=", 1) for m in g[2:]))
done()
