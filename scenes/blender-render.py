# blender-render.py - render an example scene in Blender as make renders
# does: build simple but shaped organ models (a teardrop seed, a strap
# petal, a five-pointed tubular floret, a bud), light and a camera, run
# the script phyllo-export --blender wrote, and render with Cycles on the
# CPU at a small sample count.  Usage:
#   blender -b --factory-startup --python blender-render.py -- \
#       IMPORT.py OUT.png sunflower|coneflower
# Organs follow phyllo-export's convention: built at the origin, outward
# along +X, up along +Z, of unit size.  With --obj DIR instead of
# IMPORT.py OUT.png, the organ models are written to DIR as Wavefront
# OBJ files with their .mtl colours, as Blender's OBJ export writes them
# (Y up, so outward +X, up +Y), for --gltf's organs.mesh: scenes/organs.
import math
import runpy
import sys

import bmesh
import bpy

script, out, kind = sys.argv[sys.argv.index("--") + 1:][:3]
obj_dir = out if script == "--obj" else None
bpy.ops.wm.read_factory_settings(use_empty=True)


def material(name, rgb, rough=0.5):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    bsdf = m.node_tree.nodes.get("Principled BSDF")
    bsdf.inputs["Base Color"].default_value = (*rgb, 1)
    bsdf.inputs["Roughness"].default_value = rough
    m.diffuse_color = (*rgb, 1)
    return m


def organ(name, bm, mat):
    """An object from a bmesh, smooth shaded, kept out of the render
    itself (only its instances show)."""
    mesh = bpy.data.meshes.new(name)
    bm.to_mesh(mesh)
    bm.free()
    for p in mesh.polygons:
        p.use_smooth = True
    mesh.materials.append(mat)
    ob = bpy.data.objects.new(name, mesh)
    stash.objects.link(ob)
    return ob


def deform(bm, f):
    for v in bm.verts:
        v.co = f(v.co.x, v.co.y, v.co.z)


def seed(name, rgb):
    """A teardrop: blunt outward (+X), pointed towards the centre."""
    bm = bmesh.new()
    bmesh.ops.create_uvsphere(bm, u_segments=16, v_segments=10, radius=1)
    deform(bm, lambda x, y, z: (0.95 * x, 0.75 * y * (0.55 + 0.45 * x),
                                0.45 * z * (0.6 + 0.4 * x) + 0.2))
    return organ(name, bm, material(name, rgb, 0.4))


def petal(name, rgb, length=1.0):
    """A strap from the origin outward, widest past its middle, its tip
    rounded, curving slightly down."""
    bm = bmesh.new()
    n, m = 24, 6
    rows = []
    for i in range(n + 1):
        s = i / n
        half = 0.16 * math.sin(math.pi * min(s * 1.15, 1.0)) + 0.01
        row = []
        for j in range(m + 1):
            t = -1 + 2 * j / m
            x = length * s
            row.append(bm.verts.new((x, half * t, -0.12 * s * s +
                                     0.02 * (1 - t * t))))
        rows.append(row)
    for i in range(n):
        for j in range(m):
            bm.faces.new((rows[i][j], rows[i + 1][j], rows[i + 1][j + 1],
                          rows[i][j + 1]))
    bmesh.ops.recalc_face_normals(bm, faces=bm.faces)
    return organ(name, bm, material(name, rgb, 0.6))


def floret(name, rgb, points=5):
    """A tube standing on the surface, opening into pointed lobes."""
    bm = bmesh.new()
    bmesh.ops.create_cone(bm, cap_ends=True, segments=points * 2,
                          radius1=0.8, radius2=0.55, depth=1.0)
    deform(bm, lambda x, y, z: (x, y, z + 0.5))
    for i in range(points):
        a = 2 * math.pi * i / points
        tip = bmesh.ops.create_cone(bm, cap_ends=True, segments=6,
                                    radius1=0.25, radius2=0.0, depth=0.6)
        for v in tip["verts"]:
            x, y, z = v.co
            z += 1.25
            x += 0.45
            v.co = (x * math.cos(a) - y * math.sin(a),
                    x * math.sin(a) + y * math.cos(a), z)
    return organ(name, bm, material(name, rgb, 0.5))


def bud(name, rgb):
    bm = bmesh.new()
    bmesh.ops.create_uvsphere(bm, u_segments=14, v_segments=10, radius=1)
    deform(bm, lambda x, y, z: (0.9 * x, 0.9 * y,
                                1.1 * z * (1.0 + 0.25 * z) + 0.3))
    return organ(name, bm, material(name, rgb, 0.5))


def revolve(name, profile, rgb, segments=64):
    """A surface of revolution about Z through (radius, height) points."""
    bm = bmesh.new()
    rings = []
    for rho, z in profile:
        rings.append([bm.verts.new((rho * math.cos(2 * math.pi * k /
                                                   segments),
                                    rho * math.sin(2 * math.pi * k /
                                                   segments), z))
                      for k in range(segments)])
    for a, b in zip(rings, rings[1:]):
        for k in range(segments):
            bm.faces.new((a[k], a[(k + 1) % segments], b[(k + 1) % segments],
                          b[k]))
    bmesh.ops.remove_doubles(bm, verts=bm.verts, dist=1e-9)
    bmesh.ops.recalc_face_normals(bm, faces=bm.faces)
    mesh = bpy.data.meshes.new(name)
    bm.to_mesh(mesh)
    bm.free()
    for p in mesh.polygons:
        p.use_smooth = True
    mesh.materials.append(material(name, rgb, 0.8))
    ob = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(ob)
    return ob


def bezier(points, steps=24):
    """Points along one cubic Bezier segment of (radius, height)."""
    (a, b, c, d) = points
    out = []
    for i in range(steps + 1):
        t = i / steps
        u = 1 - t
        out.append(tuple(u ** 3 * a[k] + 3 * u * u * t * b[k] +
                         3 * u * t * t * c[k] + t ** 3 * d[k]
                         for k in range(2)))
    return out


stash = bpy.data.collections.new("Organ models")
bpy.context.scene.collection.children.link(stash)
stash.hide_render = True

if kind == "sunflower":
    seed("Seed", (0.10, 0.05, 0.02))
    floret("Floret", (0.45, 0.24, 0.03))
    for n, rgb in zip("ABCD", [(1.0, 0.70, 0.03), (0.97, 0.62, 0.02),
                               (1.0, 0.75, 0.05), (0.95, 0.58, 0.02)]):
        petal("Petal" + n, rgb)
    camera, target, sky = (0, -3.5, 4.0), (0, -0.15, -0.4), (0.62, 0.76, 0.90)
    # The head under the seeds: the scene's paraboloid dome, lowered.
    revolve("Head", [(0.86 * i / 16, 0.08 * (1 - (0.86 * i / 16) ** 2) -
                      0.03) for i in range(17)] + [(0.86, -0.15), (0, -0.2)],
            (0.18, 0.12, 0.04))
else:
    petal("RayFloret", (0.95, 0.72, 0.05))
    floret("OpenFloret", (0.55, 0.52, 0.12))
    bud("ClosedFloret", (0.25, 0.42, 0.08))
    camera, target, sky = (0, -5.6, 2.8), (0, 0, 0.25), (0.78, 0.84, 0.90)
    # The scene's receptacle profile, and a stem.
    revolve("Receptacle", bezier(((1, 0), (0.8, 0.5), (0.35, 1.1),
                                  (0, 1.2))) + [(0.3, -0.1)],
            (0.35, 0.30, 0.10))
    revolve("Stem", [(0.12, 0.05), (0.12, -3)], (0.25, 0.42, 0.12))

if obj_dir is not None:
    for ob in stash.objects:
        bpy.ops.object.select_all(action="DESELECT")
        ob.select_set(True)
        path = "%s/%s.obj" % (obj_dir, ob.name.lower())
        bpy.ops.wm.obj_export(filepath=path, export_selected_objects=True,
                              forward_axis="NEGATIVE_Z", up_axis="Y",
                              export_uv=False)
        print("blender-render: wrote %s" % path)
    sys.exit(0)

runpy.run_path(script, run_name="__main__")

scene = bpy.context.scene
cam = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
cam.data.angle = math.radians(42)
cam.location = camera
d = [t - c for t, c in zip(target, camera)]
cam.rotation_euler = (math.atan2(math.hypot(d[0], d[1]), -d[2]), 0,
                      math.atan2(d[1], d[0]) - math.pi / 2)
scene.collection.objects.link(cam)
scene.camera = cam
sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
sun.data.energy = 4.0
sun.rotation_euler = (math.radians(40), math.radians(-20), math.radians(30))
scene.collection.objects.link(sun)
world = bpy.data.worlds.new("World")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Color"].default_value = (*sky, 1)
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.8
scene.world = world

scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = 16
if hasattr(scene.cycles, "use_denoising"):
    scene.cycles.use_denoising = False
scene.render.resolution_x, scene.render.resolution_y = 640, 480
scene.render.resolution_percentage = 100
scene.render.image_settings.file_format = "PNG"
scene.render.filepath = out
bpy.ops.render.render(write_still=True)
print("blender-render: wrote %s" % out)
