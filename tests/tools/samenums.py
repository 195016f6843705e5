#!/usr/bin/env python3
# samenums.py A B - whether two outputs of one run by two builds (the
# Windows program's and the native one's: tests/windows.sh) are the
# same but where their C libraries' maths differ in the last bits;
# samenums.py --each LIST does it for every line "WHAT<tab>A<tab>B" of
# LIST, printing "ok - WHAT" or "not ok - WHAT: why" (one start of
# Python for hundreds of pairs).  The same means:
#   text      every line the same but for numbers, each equal, or within
#             1e-12 of its size (at least 1), or one unit apart in the
#             last of the 9 digits we print (two values within 1e-12 on
#             either side of a rounding);
#   --blender the organs' float32 (STRUCTURES' base64): each value equal,
#             within 1e-12 of its size, or the next float32;
#   .glb      the JSON chunk as text, the binary chunk byte for byte but
#             for the accessors of floats, compared as float32 above.
# A B prints the first difference that is none of these and exits 1.
import ast
import base64
import json
import math
import re
import struct
import sys

NUM = re.compile(rb'-?[0-9]+(?:\.[0-9]*)?(?:[eE][-+]?[0-9]+)?')


def near(x, y):
    d, m = abs(x - y), max(abs(x), abs(y))
    if d <= 1e-12 * max(m, 1):
        return True
    return d <= 1.0000001 * 10 ** (math.floor(math.log10(m)) - 8)


def f32_ulps(a, b):
    def key(f):
        i = struct.unpack("<i", struct.pack("<f", f))[0]
        return i if i >= 0 else -0x80000000 - i
    return abs(key(a) - key(b))


def same_floats(a, b, where, angles=range(0)):
    """Float32 a and b the same, those at indices angles (radians) as
    angles: pi and -pi are one (atan2() of a -0 or a +0)."""
    if len(a) != len(b) or len(a) % 4:
        return "%s: %d bytes vs %d" % (where, len(a), len(b))
    fa = struct.unpack("<%df" % (len(a) // 4), a)
    fb = struct.unpack("<%df" % (len(b) // 4), b)
    for k, (x, y) in enumerate(zip(fa, fb)):
        if k in angles and abs(abs(x - y) - 2 * math.pi) < 1e-6:
            continue
        if x != y and abs(x - y) > 1e-12 * max(abs(x), 1) and \
                f32_ulps(x, y) > 1:
            return "%s: float %d: %r vs %r" % (where, k, x, y)
    return None


def same_line(x, y, where):
    nx, ny = NUM.split(x), NUM.split(y)
    vx, vy = NUM.findall(x), NUM.findall(y)
    if nx != ny or len(vx) != len(vy) or not all(
            u == v or near(float(u), float(v)) for u, v in zip(vx, vy)):
        return "%s: %r vs %r" % (where, x[:200], y[:200])
    return None


def blobs(text):
    """--blender's organs, the base64 of each structure's float32, and
    the text with each structure's other fields in their place."""
    if b"\nSTRUCTURES = [" not in text:
        return [], text
    for node in ast.parse(text).body:
        if isinstance(node, ast.Assign) and \
                getattr(node.targets[0], "id", "") == "STRUCTURES":
            value = ast.literal_eval(node.value)
            lines = text.split(b"\n")
            fields = repr([s[:-1] for s in value]).encode()
            return [(base64.b64decode(s[-1]), s[2]) for s in value], \
                b"\n".join(
                lines[:node.lineno - 1] + [fields] + lines[node.end_lineno:])
    return [], text


def same_text(a, b):
    (xa, a), (xb, b) = blobs(a), blobs(b)
    if len(xa) != len(xb):
        return "%d base64 strings vs %d" % (len(xa), len(xb))
    # Each structure's count n: positions, Euler angles, scales.
    for k, ((x, n), (y, _)) in enumerate(zip(xa, xb)):
        why = x != y and same_floats(x, y, "structure %d's organs" % (k + 1),
                                     range(3 * n, 6 * n))
        if why:
            return why
    la, lb = a.split(b"\n"), b.split(b"\n")
    if len(la) != len(lb):
        return "%d lines vs %d" % (len(la), len(lb))
    for n, (x, y) in enumerate(zip(la, lb), 1):
        # An estimate made of the numbers' printed lengths.
        if x != y and not x.startswith(b"output-bytes: "):
            why = same_line(x, y, "line %d" % n)
            if why:
                return why
    return None


def chunks(glb):
    at, out = 12, {}
    while at + 8 <= len(glb):
        size, kind = struct.unpack_from("<I4s", glb, at)
        out[kind] = glb[at + 8:at + 8 + size]
        at += 8 + size
    return out


def same_glb(a, b):
    ca, cb = chunks(a), chunks(b)
    why = same_text(ca.get(b"JSON", b"").rstrip(b" "),
                    cb.get(b"JSON", b"").rstrip(b" "))
    if why:
        return "JSON " + why
    ba, bb = ca.get(b"BIN\0", b""), cb.get(b"BIN\0", b"")
    if len(ba) != len(bb):
        return "BIN %d bytes vs %d" % (len(ba), len(bb))
    doc, floats = json.loads(ca[b"JSON"]), set()
    comps = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}
    for acc in doc.get("accessors", []):
        if acc.get("componentType") != 5126:
            continue
        view = doc["bufferViews"][acc["bufferView"]]
        start = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
        n = acc["count"] * comps[acc["type"]]
        floats.update(range(start, start + 4 * n, 4))
    for at in range(0, len(ba), 4):
        x, y = ba[at:at + 4], bb[at:at + 4]
        if x == y:
            continue
        if at not in floats:
            return "BIN byte %d: not a float, and not the same" % at
        why = same_floats(x, y, "BIN byte %d" % at)
        if why:
            return why
    return None


def differ(path_a, path_b):
    """Why the two files differ beyond the maths' last bits, or None."""
    a, b = (open(p, "rb").read() for p in (path_a, path_b))
    if a == b:
        return None
    if a[:4] == b"glTF" and b[:4] == b"glTF":
        return same_glb(a, b)
    return same_text(a, b)


def main():
    if sys.argv[1:2] != ["--each"]:
        why = differ(sys.argv[1], sys.argv[2])
        if why:
            print(why)
        return 1 if why else 0
    # --each LIST: lines "WHAT<tab>A<tab>B", a test's line for each.
    bad = 0
    for line in open(sys.argv[2], encoding="utf-8"):
        what, a, b = line.rstrip("\n").split("\t")
        why = differ(a, b)
        print("not ok - %s: %s" % (what, why) if why else "ok - " + what)
        bad |= why is not None
    return bad


if __name__ == "__main__":
    sys.exit(main())
