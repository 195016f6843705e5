# Coll_cone: 205 organs placed by phyllo-export 0.1.0 from coll-cone.cfg
# (model collision, divergence 137.507764 degrees).
#
# Run it in Blender: "blender your.blend --python THIS_FILE", or open it
# in the Text Editor and Run Script (one undo step).  It builds the
# collection "Coll_cone": for each organ object a point cloud whose
# geometry-nodes modifier puts an instance of that object on every organ.
# An object or collection of that name in the .blend is used as it is:
# built at the origin, outward along +X, up along +Z, of unit size.
# Otherwise a placeholder icosphere of that name is made, hidden, in
# "Coll_cone placeholders".  To swap an organ, pick another object in the
# modifier's "Organ" field.  An organ made of another scene (a part) is
# built once as a collection in the hidden "Coll_cone parts" and instanced,
# unless the .blend has an object or collection of its name.  With
# frames, each frame's structure is shown at its own frame alone, by
# keyframed visibility.  Running the script again replaces what it made
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

NAME = "Coll_cone"
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
    (1, "Coll_cone", 205, [
        ("Organ", 205),
    ],
     "AACAPwAAAAAAAAAANcQ8v+/sLD8AAAAAQgyzPREFf78AAAAApsIbP2spSz8AAAAALxZ8v8FcMr4AAAAAWQBYPwJnCb8AAAAA2+qEvho5dz8AAAAAAfzrvtIvY78AAAAAXHdwP8Kirz4AAAAA6aFsv11bwz4AAAAAWALZPjTeZ78AAAAAvDuZPhpEdD8AAAAAe35dvz9cAL8AAAAAbAd6P2nfW74AAAAArzsTv4psUT8AAAAATpgDvpXgfb8AAAAACcBDP3r6JD8AAAAACch/v+I8KT0AAAAA2HU1P8iTNL8AAAAAPjM9vQy6fz8AAAAAhAUkv3mNRL8AAAAAz51wP5d/AT6TlZ49s0pHv3ypCj+TlZ49liVVPmDdbL+TlZ49b2rxPr+mUj+TlZ49l0xnv92Uk76TlZ4902VcP6Coy76TlZ49nHW7vlv2Xz+TlZ49j1ekvtR0ZL+TlZ49EOlWP9rm4T6TlZ499sNqv6CIdz6TlZ49nk4DP3Q2TL+TlZ493HwkPtpGbz+TlZ49gPM/v2SoFL+TlZ49gndrP0UQnL2zt+w9z3Igv6twLT+zt+w9p4iTO05FbL+zt+w9qr8eP0z/Lj+zt+w96kNrv0dvrr2zt+w9tzQ8P3LXDr+zt+w9Bigpvk11aD+zt+w9ZK77viv5R7+zt+w9Sh5cPx1NcT4JlyY+vA5Lv11p0D4JlyY+Oa2ePmMAVr8JlyY+0RusPuxjUz8JlyY+8z5Ov9F8w74JlyY+shpaP958hr4JlyY+K83mvi/pRD8JlyY+h6w/vuQlX78JlyY+YxE6P4csBD8JlyY+n3tivxzP4T0JlyY+Wu8TP9HMLb8JlyY++BQFPVkVZD8JlyY+hzMgvymQIr8JlyY+j9lcP9usND2BK1E+v3kqv/zaDD+BK1E+k3T0PVkEW7+BK1E+AtP6PiAjNj+BK1E+xoFXv75ZRr6BK1E+cWdAP1QE2r6BK1E+LHqIvrVYUj+BK1E+PYq3vo8y"
    "Sb+BK1E+Po9DP8TupT71tII+Ez5Iv/PXjT71tII+v33HPq+OO7/1tII+VJNUPhitTT/1tII+bx4yv6SF5771tII+5ohRPwXWC771tII+0+MCv/5QJz/1tII+Jg2Eve3JU7/1tII+izsbPzsEET/1tII+wmtUv/6kBLz1tII+WAgeP8T1Db/1tII+5BWlvShtUz/1tII+YjP/vqTWKb/1tII+u0xJP1+LFj7yopk+4Notv9py2D7yopk+81xcPhQ9Rb/yopk+mDi5PqCmNj/yopk+wqo/v0M/kL7yopk+Tgw+PzmTmL7yopk+QzWxvrCgOD/yopk+fIVtvmj9Q7/yopk+TiYoP+lMxz4En7U+Ek0/v/pqID4En7U+Q/DjPjbLHr8En7U+as+5PSITQj8En7U+0DgUv8LU/r4En7U+uVxDP3NyxbwEn7U+1uILv9eDCD8En7U+7O0uPVMnQ78En7U+eob3Pg9JFz8En7U+VnNBvxGf370En7U+soYhPwQg3L4En7U+ZAgzvhtEPj8En7U+BAq/vq2HKr8En7U+AOMxPwOtaj5/EM4+Z8wqv9jMmT5/EM4+Df6TPpATLL9/EM4+oLF2PhXeMD9/EM4+yfIkv3eDsb5/EM4+B5U1P/DlN75/EM4+4azNvqOOHD9/EM4+dWPvvf7nOL9/EM4+ejMLPyv92z4Owus+V/Ewv4DCTj0Owus+cnzzPj8NAb8Owus+dSomvB5lMT8Owus+CdTrvjKPBL8Owus+IH0wPyXDkD0Owus+S1wOv0K/0z4Owus+mNIFPiM7Lr8Owus+XQu6Pk0SFz8Owus+laMqv0Q9Qr4Owus+JqAeP77qnr4Owus+JSt9voG9JT8Owus+k5KCvgX3JL8Owus+3x0XP6vckj4D+wM/2gchv4C6Pz4D+wM//risPkoeEL8D+wM/d64GPsaaJD8D+wM/KwQIv7VCxb4D+wM/AesmP8o0mb0D+wM/tUncvs2+/T4D+wM/"
    "OIGPvAD0J78D+wM/GiXcPjbL4z71aBI/qxkevy0ZGr31aBI//Cr2PhBjx771aBI/lFS7vSSnHD/1aBI/JBqxvhVUA7/1aBI/rN8XP80JEj4JsxU/GaYIvx5Wlz4JsxU//JZGPq8ZFL8JsxU/N7p9Pq69Dj8JsxU/WzEPv9meeb4JsxU/br0TP8fWSr4JsxU/rV6Vvk4wCT8JsxU/sGUWvoybF78JsxU/Zh/xPkwToD5B7yY/ffYOv5ldsz1B7yY/84q0Pmc04r5B7yY/LWEdPSdgED9B7yY/8o3Rvqqgx75B7yY/ah4OP7qBMTz8xyo/wVXVvtXouz78xyo/FAFzPQlVDb/8xyo/BjikPt4T3z4nPzA/aOMHv8A/1r0nPzA/lZTsPlsWkL4nPzA/ITwavtIGBT8nPzA/b7R1voBF+L4nPzA/l3rwPgJcOj4nkz4/fEPwvnd3Oz4nkz4/pLFjPmpp574nkz4/Cb0QPtKJ9z4nkz4/k5LcvnOkhb4nkz4/ODv3Pj1Exb1m7EI/3/yUvu5dyz5m7EI/gRtcvaOY+r5m7EI/j2e3Pi3MoD7lEEk/ntrzvn9EKjzlEEk/VTewPvmkqL7lEEk/IyYAva1i8z7lEEk/x5eYvghJvr7lEEk/dBHcPsH5hz3I/Vg/5ju5vv4sdz7I/Vg/12nUPexA2L7I/Vg/RddVPllUwz7I/Vg/ccjSvsGcD77I/Vg/GRXGPn69Lb6Sx10/gcIuvqnbxT6Sx10/onAKvizrzL6Sx10/HhyyPuQuRD60f2c/spfFvlntvz20f2c/I5NiPiXaqL60f2c/6C90PeUHyT60f2c/J02evjM7f760f2c/jOS3PnIKurwUznU/KXx/vqTKhD4UznU/RM4PPIc0uL4UznU/XOVnPj7whD5rs3s/iEuvvqCfHb1rs3s/9pCOPnfDT75rs3s/qs+LvbzmrD5rs3s/RAo2vjEal75rs3s/JiWSPmKKrD2424Y/deaIvoHT"
    "BT6424Y/v/zePX3Qjb6424Y/uBzNPWlbhT7oa4o/1Mh/vjrI/r3oa4o/WVSJPgSxnb3oa4o/9EMVvviqcz7oa4o/ViBavQ5AjL7oa4o/bo84PjWZCD6h8pQ/JVxkvtKPvzyh8pQ/8zUYPlDpK76h8pQ/JYJhO5UBUD5F/pg/tRoPvkX/Fr5F/pg/254gPsS8NTz2zqE/6Df8vYk+yD32zqE/FNzKPDIDH772zqE/KWdMPXvPmj3tm64/5O6zvRp3tLztm64/1b8TOxPin7oCgr8/AAAAAF+Yez8AAAAAWsFmpF+Yez//mBlAWsFmo1+Yez9t272/WsFmJF+Yez8jrWo/AAAAAF+Yez9t2z3AAAAAAF+Yez+3CRG/AAAAAF+Yez8jreo/AAAAAF+Yez8kMAPAAAAAAF+Yez/aRrM+WsFmpF+Yez/bATBAAAAAAF+Yez+3CZG/WsFmpF+Yez9IKKI/AAAAAF+Yez+ScifAWsFmpF+Yez8nmV2+AAAAAF+Yez9tvwtAWsFmo1+Yez+Sjtm/AAAAAF+Yez/aRjM/WsHmIl+Yez+2akZAWsFmpF+Yez8BcEi/WsHmol+Yez/++c4/AAAAAF+Yez+3CRHAWsFmo1+Yez+M9Ag+AAAAAF+Yez9IKCJAWsHmI1+Yez/cvKy/AAAAAF+Yez8jdYY/WsFmpF+Yez8kTDXAWsFmJF+Yez8nmd2+AAAAAF+Yez+1y/s/AAAAAF+Yez+3QfW/AAAAAF+Yez8fwfc+WsHmo1+Yez8jkThAWsFmJF+Yez9K1n+/WsHmI1+Yez/aRrM/WsHmJF+Yez9J4x7AAAAAAF+Yez84Sam9WsFmpF+Yez+2ThRAWsFmIV+Yez8BcMi/WsHmpF+Yez/8g1U/AAAAAF+Yez+3JUPAWsFmJF+Yez/eMia/WsHmo1+Yez+QGOA/WsFmJF+Yez9uegjAWsHmI1+Yez+M9Ig+AAAAAF+Yez+RtypAWsFmpF+Yez9Knpu/"
    "WsFmpF+Yez+1k5c/WsFmpF+Yez/cvCzAWsFmJF+Yez/iHpm+AAAAAF+Yez8jdQZAAAAAAF+Yez8lI+S/WsFmJF+Yez+zHR4/WsFmI1+Yez9sIEFAWsFmJF+Yez8nmV2/AAAAAF+Yez9rZcQ/WsFmJF+Yez8AVBbAAAAAAF+Yez+/P1E9WsFmpF+Yez/+3RxAAAAAAF+Yez9vUbe/WsFmpF+Yez8fwXc/WsHmo1+Yez9uljrAWsFmpF+Yez+79QO/AAAAAF+Yez8hN/E/AAAAAF+Yez9K1v+/AAAAAF+Yez/Rbs0+WsFmJF+Yez/aRjNAAAAAAF+Yez+5f4q/AAAAAF+Yez9Gsqg/AAAAAF+Yez+TLSTAAAAAAF+Yez84SSm+AAAAAF+Yez9sBA9AAAAAAF+Yez+UBNO/AAAAAF+Yez/WWkA/AAAAAF+Yez8BcEjAWsFmJF+Yez8FXDu/WsFmo1+Yez/8g9U/AAAAAF+Yez+4xA3AAAAAAF+Yez97RD0+AAAAAF+Yez9HbSVAAAAAAF+Yez/eMqa/AAAAAF+Yez8h/4w/AAAAAF+Yez8lBzLAAAAAAF+Yez8wccO+AAAAAF+Yez/ZKgFAAAAAAF+Yez+5t+6/AAAAAF+Yez+M9Ag/AAAAAF+Yez8i1jtAWsFmpF+Yez9OwnK/AAAAAF+Yez/Y0Lk/WsFmpF+Yez9KnhvAWsFmIl+Yez+wUgG9WsHmJF+Yez+1kxdAWsHmol+Yez8D5sG/WsFmJF+Yez/4l2I/AAAAAF+Yez+44D/AWsFmJF+Yez/iHhm/AAAAAF+Yez+OouY/WsFmpF+Yez9vNQXAWsFmpF+Yez+EHKM+AAAAAF+Yez+Q/C1AWsFmpF+Yez9MFJW/WsFmJF+Yez+zHZ4/AAAAAF+Yez/ddynAAAAAAF+Yez/U7X2+WsFmpF+Yez8iuglAWsHmo1+Yez8nmd2/WsFmJF+Yez+vMSs/AAAAAF+Yez9rZURAAAAAAF+Y"
    "ez8shVC/AAAAAF+Yez9p78o/WsFmpF+Yez8BDxPAWsFmo1+Yez+/P9E9AAAAAF+Yez/9IiBAAAAAAF+Yez9xx7C/WsFmJF+Yez+OaoI/AAAAAF+Yez9vUTfAAAAAAF+Yez99w+2+WsFmJF+Yez8fwfc/WsFmpF+Yez9MTPm/AAAAAF+Yez/Jluc+AAAAAF+Yez/ZizZAWsFmJF+Yez+79YO/AAAAAF+Yez9EPK8/WsFmJF+Yez+U6CDAWsFmo1+Yez+Q8um9WsFmJF+Yez9rSRJAWsFmol+Yez+Wesy/AAAAAF+Yez/Rbk0/AAAAAF+Yez8CK0XAWsFmJF+Yez8JSC6/AAAAAF+Yez/6Ddw/AAAAAF+Yez+5fwrAAAAAAF+Yez9rlHE+WsFmpF+Yez9GsihAAAAAAF+Yez/gqJ+/WsFmJF+Yez8fiZM/AAAAAF+Yez8mwi7AAAAAAF+Yez84Sam+WsFmpF+Yez/YbwRAAAAAAF+Yez+7Lei/AAAAAF+Yez+ICBY/AAAAAF+Yez8hGz9AWsFmpF+Yez9SrmW/WsFmo1+Yez/WWsA/WsFmpF+Yez9LWRjAWsFmol+Yez8e2p88AAAAAF+Yez+02BpAAAAAAF+Yez8FXLu/WsFmJF+Yez/0q28/AAAAAF+Yez+5mzzAAAAAAF+Yez/mCgy/AAAAAF+Yez+MLO0/WsFmpF+Yez9w8AHAAAAAAF+Yez97RL0+AAAAAF+Yez+PQTFAWsFmJF+Yez9Oio6/WsHmI1+Yez+xp6Q/AAAAAF+Yez/eMibAAAAAAF+Yez/knUm+WsFmJF+Yez8h/wxAWsFmo1+Yez8qD9e/AAAAAF+Yez+qRTg/WsFmol+Yez9qqkdAWsFmpF+Yez8wcUO/WsHmIl+Yez9nedE/WsFmpF+Yez8Cyg/AAAAAAF+Yez/P7xw+AAAAAF+Yez/8ZyNAWsHmI1+Yez9zPaq/WsFmJF+Yez+M9Ig/AAAAAF+Yez9wDDTA"
    "WsFmpF+Yez+Gm9O+WsFmpF+Yez8dS/4/WsFmpF+Yez9OwvK/AAAAAF+Yez9h3wA/WsHmo1+Yez/Y0DlAAAAAAF+Yez9513q/AAAAAF+Yez9CxrU/WsFmpF+Yez+Vox3AAAAAAF+Yez+wUoG9WsFmpF+Yez9qjhVAAAAAAF+Yez+Y8MW/AAAAAF+Yez/Nglo/WsFmI1+Yez8D5kHAWsFmpF+Yez8NNCG/WsFmpF+Yez/4l+I/AAAAAF+Yez+6OgfAAAAAAF+Yez8u8pI+AAAAAF+Yez9F9ytAWsFmJF+Yez/iHpm/WsFmpF+Yez8dE5o/WsFmJF+Yez8nfSvAWsHmI1+Yez9AIY++WsFmpF+Yez/XtAdAWsHmI1+Yez+9o+G/WsFmJF+Yez+EHCM/AAAAAF+Yez8gYEJAAAAAAF+Yez9Xmli/WsFmIl+Yez/T5MY/WsFmJF+Yez9MFBXAAAAAAF+Yez9nlpA9AAAAAF+Yez+zHR5AWsHmo1+Yez8H0rS/AAAAAF+Yez/wv3w/WsHmo1+Yez+6VjnAWsFmpF+Yez/U7f2+CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrX"
    "oz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQrXoz0K16M9CtejPQ=="),
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
    meshes, groups = set(), set()
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
