# Tree: 8 organs placed by phyllo-export 0.1.0 from tree.cfg
# (model planar, divergence 137.507764 degrees).
#
# Run it in Blender: "blender your.blend --python THIS_FILE", or open it
# in the Text Editor and Run Script (one undo step).  It builds the
# collection "Tree": for each organ object a point cloud whose
# geometry-nodes modifier puts an instance of that object on every organ.
# An object or collection of that name in the .blend is used as it is:
# built at the origin, outward along +X, up along +Z, of unit size.
# Otherwise a placeholder icosphere of that name is made, hidden, in
# "Tree placeholders".  To swap an organ, pick another object in the
# modifier's "Organ" field.  An organ made of another scene (a part) is
# built once as a collection in the hidden "Tree parts" and instanced,
# unless the .blend has an object or collection of its name.  With
# frames, each frame's structure is shown at its own frame alone, by
# keyframed visibility, and the timeline ends at the last frame of the
# growth.  Running the script again replaces what it made
# and the artist left as it was, in the same collection: a placeholder
# you edit (its mesh) or rename stays, as your own organ.

import array
import base64
import difflib
import hashlib
import sys
import time

import bmesh
import bpy

NAME = "Tree"
# True: one linked duplicate per organ instead of instances (editable,
# heavier; phyllo-export --blender-objects).
LINKED_DUPLICATES = False
# Frames of growth (phyllo-export --frames): frame F is shown at scene
# frame FIRST_FRAME + F - 1, by keyframed visibility.
FRAMES = 1
FIRST_FRAME = bpy.context.scene.frame_start
# Every structure, frame by frame; in each frame the parts (organs made
# of another scene) come before the structures that place them, and the
# structure NAME last.  Each is (frame, name, organ count, organ objects
# with how many organs each, in the order of the data, data).  The data
# is base64 of little-endian float32: every position (x, y, z), then
# every rotation (Euler XYZ, radians), then every scale.
STRUCTURES = [
    (1, "Mid", 63, [
        ("Seed", 63),
    ],
     "HuGgPwAAAADEG7c90r2OP4IZjT7mnLc+wQqYP2cjE79gEUQ8zIeiP9+PDz+lArm+tk1SPy2JEb7X40k/IN6lP/yx+r7+SDa/9ipqPzcPdz8i5Xo+r1Vkv1wsUT+yHRk/bGN4v0h0Bz9bZls/aUvwvj0Qlz+jAgY//xCiv5sT2z54Nyg+cMv6vuldIj9PoKI/SCAav75nmD87ZjG+AWGjvy47ub1wVj8/jBjQPVMylL+kNos/+h+wPnh9gL9nA6s/6vvdvhgLkr8cAoI/VZsePxMmkL/Hsys/oLuEvYLnQ7+6xd0/eTixvsFHnr8xXrE+wZF2P2GKQ78gdZ0/caYtP/J+Yj+YXcc/GizQPmWrbj+50uU/HemFP7CzBj8Xgr4/IpmVPgl8mT8lLJQ/d1kKPwTD/j4QNQtAXxaGP7XyJj+Otlg/6kg/vub/lD8rvtg/MIyGv4hlPr7bgQBA4aNjv0hUyr6PEA9A/yKKv8hHnD5Egfg/rLB7v0ZxKL+2/c8/rYMzvzy3sbq8RiZApPeUv//+XT5v3qk/GtUevxNbcb8rwwhA81ZcP3wpDL9+FBxAf4ZhP3cMl75K9ylAjEMQP+p0ab/Q/xdA6jOPP2nGL75NpwRAjm/8Pr6m5r7eF0BAZqQuPyTMZ78M4eQ/I9CFP+RUhz7Q5iNAv0mBvvx4cD+zZjZAi8Lbvn0iRj+JnUNAodNDPpeRgD+VfjJANTQtv4m7Vz9qDyBA7rtkvSbMIT9vqFhATujSPcsQij+TsQ5AosZnv1RK+T4Cyj1AUlvavl83Ur95eE9AOnRIvq9gUb9KA1xAmqJHv9PyFL/yvEtABUSKvf9+g782NzpAuk67vn829L5r+G9A2khEv1NdMb9lsilA5DilPjFCbL/AbFZAPiZTPww5mj4RQmdAPCkpP2+05D5WJXNAxTVrP+sDvr0xtWNAr9w0PyAJLT8vFlNAV4APP+xWyj3xBoNAuGN7PwVczbtnaUNAPhy7PpFH"
    "Wj/U0W1AAAAAANQDYz8AAAAA2tWQP0H4e7/vOe0/BvCZvwejyj7KI7C/+0OfP4J3Az5we8U/sUqIv+vHIL8KB/O/VlVqP97SlT/IkWQ/KGIsP/uDi7+sEyRAAAAAAMamYj//mBlALIWQPznee78myAHAj76Zv/d+yj5FIYM/FhWfPxFtAz7+yxXARhSIv+mpIL/8FQA/wJtpP6O1lT/8jD/AgvQrP/5ci797tai/bndJo2zhYT9t272/YdqPP2eme790v8A+sFWZvyMyyj7j4TbAobGeP7JWAz4LqXE9+6CHv/xpIL+rfDlAtxRoP1d3lT/LNxm/mA0rPy0Ki7+/4oo/4avIJH8LYT8jrWo/viGPP/hoe7+7/TFAEOSYv1HeyT5lmOm+1EWePxk+Az6/WB1AMCSHv0EkIL9tuny/x3BmP1YzlT8L1eU/yRUqPzewir+O3jLAAAAAANIiYD9t2z3AhFmOPxEle7+Aa4y/jmiYv4SCyT5N+/g/lNCdP/AiAz7oara/rpyGv+jXH7+AhbQ/paxkP9PolD8FBAbAKQspPyhOir+pVci+AAAAANQkXz+3CRG/qH+NP6fZer98e6c/z+GXv40dyT5+3ve/l1CdP80EAz5/bXk/BAmGv/SDH78Wbx7AhMRiP9mWlD/1J5k+gOsnP9viib+tzQBAAAAAAHUOXj8jreo/wJGMP3iFer87ZiTAO06Xv/+tyD68L+4+U8ScPzHjAj5INDrAfWeFvzgnH793paC9+bNgPz88lD/hRCxAPLQmP/Vsib8k6e6/AAAAAAjcXD8kMAPA7YyLP/Umer9CESa+5quWvx4yyD7vfTdA7SmcP3+9Aj55lAK/EbaEv0bAHr83YBRA3nVeP5/Xkz9xipm/V2IlP9TqiL9hugk/bDxEJPE2XD/aRrM+3wCLPz7zeb/zcQ9Af1SWv+juxz5D8IG/vtabP+GoAj4s3fE/pVaEv2+IHr9ohMi/30NdPwehkz+lG5k/"
    "U64kP5GkiL8KLzxAdexGPnXsRj517EY+dexGPnXsRj517EY+dexGPsp2Pz7Kdj8+ynY/Psp2Pz7Kdj8+ynY/Psp2Pz4fATg+HwE4Ph8BOD4fATg+HwE4Ph8BOD4fATg+dIswPnSLMD50izA+dIswPnSLMD50izA+dIswPsoVKT7KFSk+yhUpPsoVKT7KFSk+yhUpPsoVKT4foCE+H6AhPh+gIT4foCE+H6AhPh+gIT4foCE+dCoaPnQqGj50Kho+dCoaPnQqGj50Kho+dCoaPsm0Ej7JtBI+ybQSPsm0Ej7JtBI+ybQSPsm0Ej4ePws+Hj8LPh4/Cz4ePws+Hj8LPh4/Cz4ePws+"),
    (1, "Tree", 8, [
        ("Mid", 8),
    ],
     "AAAAAAAAAADNzMw+NcS8vu/srD75iq8+QjZ9PYNTNL8lSZI+duQGP3rxLz+hDmo+LxZ8v8FcMr75ii8+Mn9xP9ueGb+hDuo9N8qivoFklz+hDmo9yRYcvxtFlr8AAAAAAAAAAAAAAICSCgY/yQvpPcbZRj5t0TtAnhUkPmgMij7rGHC/zBxIPs0dpj4id7w/rxpmPtWVvD4uqBnArhmAPkVszz5UVQ48tcCLPiKp3z68vxpA0laWPjfs7T6/Zrq/ngjDPp4Iwz6eCMM+ngjDPp4Iwz6eCMM+ngjDPp4Iwz4="),
]

TAG = "phyllo_export"   # custom property on everything this script makes
OLDEST = (3, 4, 0)      # the first Blender this script is tested in


def api_missing():
    """What this Blender lacks of what the script uses, or None."""
    if bpy.app.version < OLDEST:
        return "Blender %d.%d or newer (point-cloud attributes and the " \
            "geometry nodes this script builds)" % OLDEST[:2]
    for node in ("GeometryNodeInstanceOnPoints", "GeometryNodeObjectInfo",
                 "GeometryNodeCollectionInfo",
                 "GeometryNodeInputNamedAttribute"):
        if not hasattr(bpy.types, node):
            return "the geometry node %s" % node
    if "attributes" not in bpy.types.Mesh.bl_rna.properties:
        return "mesh attributes (Mesh.attributes)"
    return None


# Where Blender's API changed, one helper each, named for the version.

def add_socket(group, name, in_out, socket_type):
    if hasattr(group, "interface"):
        # Blender 4.0 moved group sockets to the tree's interface.
        return group.interface.new_socket(name=name, in_out=in_out,
                                          socket_type=socket_type)
    sockets = group.inputs if in_out == "INPUT" else group.outputs
    return sockets.new(socket_type, name)


def set_modifier_input(mod, identifier, value):
    inputs = getattr(getattr(mod, "properties", None), "inputs", None)
    if inputs is not None:
        # Blender 5.2 gave the modifier's inputs RNA properties; they
        # are no longer custom properties of the modifier.
        getattr(inputs, identifier).value = value
    else:
        mod[identifier] = value


def offer_as_modifier(group):
    # Blender 4.0 lists only groups flagged as modifiers in the picker.
    if hasattr(group, "is_modifier"):
        group.is_modifier = True


def output_of_type(node, socket_type):
    # By type, not name: Collection Info's "Geometry" became "Instances"
    # in Blender 3.5, and 3.x hides the outputs of other data types.
    return next(s for s in node.outputs
                if s.type == socket_type and s.enabled)


def unpack(data, n):
    values = array.array("f")
    values.frombytes(base64.b64decode(data))
    if sys.byteorder == "big":
        values.byteswap()
    return values[0:3 * n], values[3 * n:6 * n], values[6 * n:7 * n]


def walk(collection):
    yield collection
    for child in collection.children:
        yield from walk(child)


def ours(data):
    """Whether this script made data (and the artist has it not)."""
    return data is not None and data.get(TAG) == NAME


def structure_collection():
    """The collection an earlier run built, found by its mark: one of
    the artist's that has the structure's name is not ours."""
    return next((c for c in bpy.data.collections
                 if ours(c) and c.get("phyllo_structure")), None)


def mesh_print(mesh):
    """A fingerprint of a mesh's vertices and faces, so that a placeholder
    the artist has modelled is told from the one this script made."""
    co = array.array("f", [0.0]) * (3 * len(mesh.vertices))
    mesh.vertices.foreach_get("co", co)
    return "%d %d %s" % (len(mesh.vertices), len(mesh.polygons),
                         hashlib.sha1(co.tobytes()).hexdigest()[:16])


def edited(ob):
    """Whether the artist made a placeholder their own: renamed it, gave
    it another mesh, or edited the mesh."""
    return (ob.name != ob.get("phyllo_organ") or not ours(ob.data) or
            mesh_print(ob.data) != ob.data.get("phyllo_print"))


def remove_previous():
    """Empty the collection of an earlier run of what it made and the
    artist left as it was; keep the collection itself (its settings,
    its links from other scenes), the artist's own objects and
    collections in it, and placeholders the artist edited or renamed,
    which become the artist's organs.  Returns the collection (or
    None) and the names of the placeholders kept."""
    top = structure_collection()
    if top is None:
        return None, []
    kept = []
    meshes, groups, actions = set(), set(), set()
    collections = list(walk(top))
    for collection in collections:
        for ob in list(collection.objects):
            if not ours(ob):
                continue        # the artist's own: left where it is
            if ob.get("phyllo_organ") and edited(ob):
                del ob[TAG]     # now the artist's organ, kept as theirs
                if ours(ob.data):
                    del ob.data[TAG]
                kept.append(ob.name)
                continue
            if ours(ob.data):
                meshes.add(ob.data)
            for mod in ob.modifiers:
                if mod.type == "NODES" and mod.node_group is not None:
                    groups.add(mod.node_group)
            # The frames' visibility keys (an Action, which outlives
            # its object, orphaned).
            anim = ob.animation_data
            if anim is not None and ours(anim.action):
                actions.add(anim.action)
            bpy.data.objects.remove(ob)
    for collection in reversed(collections):
        # Ours, unless it holds what the artist keeps (a placeholder
        # they edited, an object or collection of theirs put in it).
        if collection is not top and ours(collection) and \
                not collection.objects and not collection.children:
            bpy.data.collections.remove(collection)
    for mesh in meshes:
        if mesh.users == 0:
            bpy.data.meshes.remove(mesh)
    for group in groups:
        if group.users == 0 and ours(group):
            bpy.data.node_groups.remove(group)
    for action in actions:
        if action.users == 0:
            bpy.data.actions.remove(action)
    return top, kept


def placeholder(name, collection):
    """A unit icosphere standing in for an organ the .blend lacks; the
    artist may edit it in place, and a later run keeps it."""
    bm = bmesh.new()
    bmesh.ops.create_icosphere(bm, subdivisions=2, radius=1.0)
    mesh = bpy.data.meshes.new(name)
    bm.to_mesh(mesh)
    bm.free()
    mesh[TAG] = NAME
    mesh["phyllo_print"] = mesh_print(mesh)
    ob = bpy.data.objects.new(name, mesh)
    ob[TAG] = NAME
    ob["phyllo_organ"] = name
    collection.objects.link(ob)
    return ob


def instancer_group(kind):
    """Points in, instances of the "Organ" input out, placed by the
    rotation and scale attributes."""
    group = bpy.data.node_groups.new(NAME + " " + kind.lower(),
                                     "GeometryNodeTree")
    group[TAG] = NAME
    offer_as_modifier(group)
    add_socket(group, "Geometry", "INPUT", "NodeSocketGeometry")
    organ = add_socket(group, "Organ", "INPUT",
                       "NodeSocketObject" if kind == "OBJECT"
                       else "NodeSocketCollection")
    add_socket(group, "Geometry", "OUTPUT", "NodeSocketGeometry")
    nodes, links = group.nodes, group.links
    inp = nodes.new("NodeGroupInput")
    out = nodes.new("NodeGroupOutput")
    if kind == "OBJECT":
        info = nodes.new("GeometryNodeObjectInfo")
        info.transform_space = "ORIGINAL"
        info.inputs["As Instance"].default_value = True
        links.new(inp.outputs["Organ"], info.inputs["Object"])
    else:
        info = nodes.new("GeometryNodeCollectionInfo")
        info.transform_space = "ORIGINAL"
        links.new(inp.outputs["Organ"], info.inputs["Collection"])
    rot = nodes.new("GeometryNodeInputNamedAttribute")
    rot.data_type = "FLOAT_VECTOR"
    rot.inputs["Name"].default_value = "phyllo_rotation"
    scale = nodes.new("GeometryNodeInputNamedAttribute")
    scale.data_type = "FLOAT"
    scale.inputs["Name"].default_value = "phyllo_scale"
    place = nodes.new("GeometryNodeInstanceOnPoints")
    links.new(inp.outputs["Geometry"], place.inputs["Points"])
    links.new(output_of_type(info, "GEOMETRY"), place.inputs["Instance"])
    rotation = output_of_type(rot, "VECTOR")
    if place.inputs["Rotation"].type == "ROTATION":
        # A rotation socket (Blender 4.x) takes Euler angles through this
        # node; linked straight, a vector is not read as Euler angles on
        # every version.
        euler = nodes.new("FunctionNodeEulerToRotation")
        links.new(rotation, euler.inputs["Euler"])
        rotation = euler.outputs["Rotation"]
    links.new(rotation, place.inputs["Rotation"])
    links.new(output_of_type(scale, "VALUE"), place.inputs["Scale"])
    links.new(place.outputs["Instances"], out.inputs["Geometry"])
    return group, organ.identifier


def points(name, co, rot, scale, first, n):
    mesh = bpy.data.meshes.new(name)
    mesh[TAG] = NAME
    mesh.vertices.add(n)
    mesh.vertices.foreach_set("co", co[3 * first:3 * (first + n)])
    attr = mesh.attributes.new("phyllo_rotation", "FLOAT_VECTOR", "POINT")
    attr.data.foreach_set("vector", rot[3 * first:3 * (first + n)])
    attr = mesh.attributes.new("phyllo_scale", "FLOAT", "POINT")
    attr.data.foreach_set("value", scale[first:first + n])
    mesh.update()
    return mesh


def hidden_collection(top, suffix):
    """A child of top, hidden: what the organs instance, not the scene
    (the one of an earlier run, where it holds what the artist kept)."""
    for child in top.children:
        if ours(child) and child.name == NAME + " " + suffix:
            return child
    collection = bpy.data.collections.new(NAME + " " + suffix)
    collection[TAG] = NAME
    top.children.link(collection)
    collection.hide_viewport = collection.hide_render = True
    return collection


def show_only_at(objects, frame):
    """Keyframe objects visible at frame F alone (of FRAMES)."""
    at = FIRST_FRAME + frame - 1
    for ob in objects:
        for hidden, when in ((frame != 1, FIRST_FRAME), (False, at),
                             (True, at + 1)):
            if when == at + 1 and frame == FRAMES:
                continue
            ob.hide_viewport = ob.hide_render = hidden
            ob.keyframe_insert("hide_viewport", frame=when)
            ob.keyframe_insert("hide_render", frame=when)
        # Marked, so that a re-run removes it with its object.
        ob.animation_data.action[TAG] = NAME


class Builder:
    """Builds every structure, each part once per frame, and finds the
    object or collection each organ name stands for."""

    def __init__(self, top):
        if top is None:
            top = bpy.data.collections.new(NAME)
            top[TAG] = NAME
            top["phyllo_structure"] = True
            bpy.context.scene.collection.children.link(top)
        self.top = top
        self.placeholders = self.parts = None
        self.made = {}          # (frame, part name): its collection
        self.groups = {}
        self.organs = 0
        self.stand_ins = []     # organs a placeholder stands in for

    def organ(self, frame, name):
        """What organ name is: a part we built, the artist's own object
        or collection, or a placeholder."""
        if (frame, name) in self.made:
            return self.made[(frame, name)], "COLLECTION"
        if bpy.data.objects.get(name) is not None:
            return bpy.data.objects[name], "OBJECT"
        if bpy.data.collections.get(name) is not None:
            return bpy.data.collections[name], "COLLECTION"
        for ob in bpy.data.objects:
            # A placeholder the artist renamed stands for its organ still.
            if ob.get("phyllo_organ") == name and not ours(ob):
                return ob, "OBJECT"
        if self.placeholders is None:
            self.placeholders = hidden_collection(self.top, "placeholders")
        self.stand_ins.append(name)
        return placeholder(name, self.placeholders), "OBJECT"

    def structure(self, frame, name, count, objects, data):
        main = name == NAME
        if main:
            into = self.top
        elif (bpy.data.objects.get(name) is not None or
              bpy.data.collections.get(name) is not None):
            return          # the artist's own stands for this part
        else:
            if self.parts is None:
                self.parts = hidden_collection(self.top, "parts")
            into = bpy.data.collections.new(
                name if FRAMES == 1 else "%s %d" % (name, frame))
            into[TAG] = NAME
            self.parts.children.link(into)
            self.made[(frame, name)] = into
        label = name if FRAMES == 1 else "%s %d" % (name, frame)
        co, rot, scale = unpack(data, count)
        first, built = 0, []
        for organ_name, n in objects:
            organ, kind = self.organ(frame, organ_name)
            if LINKED_DUPLICATES:
                built += duplicates(into, organ, kind, label, organ_name,
                                    co, rot, scale, first, n)
            else:
                if kind not in self.groups:
                    self.groups[kind] = instancer_group(kind)
                group, socket = self.groups[kind]
                ob_name = label + "." + organ_name
                ob = bpy.data.objects.new(ob_name, points(
                    ob_name, co, rot, scale, first, n))
                ob[TAG] = NAME
                into.objects.link(ob)
                mod = ob.modifiers.new("phyllo-export", "NODES")
                mod.node_group = group
                set_modifier_input(mod, socket, organ)
                built.append(ob)
            first += n
        if main:
            self.organs += count
            if FRAMES > 1:
                show_only_at(built, frame)


def main():
    start = time.time()
    top, kept = remove_previous()
    for name in kept:
        print("phyllo-export: kept %r, a placeholder you edited, as your "
              "own organ" % name)
    builder = Builder(top)
    for structure in STRUCTURES:
        builder.structure(*structure)
    if FRAMES > 1:
        # The timeline plays the growth, as the add-on's import sets it:
        # past its end only the last frame would show, held.
        bpy.context.scene.frame_end = FIRST_FRAME + FRAMES - 1
    print("phyllo-export: built collection %r: %d organs over %d "
          "frame(s) in %.2f s%s" % (
              NAME, builder.organs, FRAMES, time.time() - start,
              "; placeholders for " + ", ".join(builder.stand_ins)
              if builder.stand_ins else ""))
    # A name near one the artist has is likely a slip of the scene's.
    theirs = [d.name for d in list(bpy.data.objects) +
              list(bpy.data.collections) if not ours(d)]
    for name in builder.stand_ins:
        near = difflib.get_close_matches(name, theirs, n=1, cutoff=0.75)
        if near:
            print("phyllo-export: no object or collection %r in the "
                  ".blend (did you mean %r?)" % (name, near[0]))


def duplicates(into, organ, kind, label, organ_name, co, rot, scale, first,
               n):
    """One object per organ sharing the organ's data (linked duplicates)."""
    made = []
    for i in range(first, first + n):
        ob = bpy.data.objects.new("%s.%s.%d" % (label, organ_name, i),
                                  organ.data if kind == "OBJECT" else None)
        if kind == "COLLECTION":
            ob.instance_type = "COLLECTION"
            ob.instance_collection = organ
        ob[TAG] = NAME
        ob.location = co[3 * i:3 * i + 3]
        ob.rotation_euler = rot[3 * i:3 * i + 3]
        ob.scale = (scale[i],) * 3
        into.objects.link(ob)
        made.append(ob)
    return made


missing = api_missing()
if missing:
    # One line, not a traceback: what this Blender lacks.  Exit only
    # from a command line (-b); in the Text Editor that would quit Blender.
    print("phyllo-export: this script needs %s; this is Blender %s"
          % (missing, bpy.app.version_string), file=sys.stderr)
    if bpy.app.background:
        sys.exit(1)
else:
    main()
