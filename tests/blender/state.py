# state.py - the whole of an open .blend as the tests compare it: every
# data-block of every kind bpy.data holds in this Blender (objects,
# meshes, collections, node groups, actions, point clouds, materials,
# ...), by name with its user count.  Imported by the test scripts that
# hold Blender to "a re-run leaves the .blend as the first run did,
# nothing orphaned" and "a failed import or panel change leaves it as
# it was".
import bpy


def kinds():
    """The names of bpy.data's collections of data-blocks, as this
    Blender has them (found, not listed: a kind a newer Blender adds is
    compared too)."""
    def is_id(struct):
        while struct is not None and struct.identifier != "ID":
            struct = struct.base
        return struct is not None
    return sorted(p.identifier for p in bpy.data.bl_rna.properties
                  if p.type == "COLLECTION" and is_id(p.fixed_type))


def snapshot():
    """{kind: sorted [(name, users)]}, every data-block of the .blend."""
    return {k: sorted((d.name, d.users) for d in getattr(bpy.data, k))
            for k in kinds()}


def orphans(since=None):
    """Data-blocks no one uses ("kind name"), but those that were so
    already in the snapshot since."""
    old = set()
    for k, blocks in (since or {}).items():
        old.update((k, name) for name, users in blocks if users == 0)
    return ["%s %s" % (k, name) for k, blocks in snapshot().items()
            for name, users in blocks if users == 0 and (k, name) not in old]


def differences(a, b, most=8):
    """What differs between snapshots a and b, a few at most: "" if
    nothing."""
    out = []
    for k in sorted(set(a) | set(b)):
        x, y = dict(a.get(k, [])), dict(b.get(k, []))
        if len(a.get(k, [])) != len(b.get(k, [])):
            out.append("%s: %d -> %d" % (k, len(a.get(k, [])),
                                          len(b.get(k, []))))
        for name in sorted(set(x) | set(y)):
            if x.get(name) != y.get(name):
                out.append("%s %r: users %s -> %s" % (k, name, x.get(name),
                                                      y.get(name)))
    return "; ".join(out[:most]) + ("; ..." if len(out) > most else "")
