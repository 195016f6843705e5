# import_all.py - the import add-on on many scenes in one Blender
# process: each imported (with frames where the scene reads f or F), its
# panel listing every setting phyllo-export --settings lists, the scene's
# and its parts', each field holding the file's value as it is (nothing
# shows as changed), then imported again: nothing orphaned, and the
# .blend as the first import left it.  Between scenes, what the last one
# made is removed.  Usage:
#   blender -b --factory-startup --python import_all.py -- ZIP PROGRAM \
#       SCENE[:FRAMES]...
# Prints "check: ..." lines like check.py.
import json
import os
import subprocess
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import state  # noqa: E402 (after the path)
from install import install_addon  # noqa: E402
from checks import check, done  # noqa: E402

args = sys.argv[sys.argv.index("--") + 1:]
zip_path, program, scenes = args[0], args[1], args[2:]


def clear(base):
    """Remove every data-block that was not in snapshot base."""
    had = {(k, name) for k, blocks in base.items() for name, _ in blocks}
    made = [d for k in state.kinds() for d in getattr(bpy.data, k)
            if (k, d.name) not in had]
    bpy.data.batch_remove(made)


def imported(path, frames):
    """The import, or the error it reported."""
    try:
        done = bpy.ops.import_scene.phyllotaxis(filepath=path, frames=frames)
        return "" if done == {"FINISHED"} else "ended %s" % done
    except RuntimeError as e:
        return str(e).strip()


install_addon(zip_path)
base = state.snapshot()
sc = bpy.context.scene
for arg in scenes:
    path, _, frames = arg.partition(":")
    frames = int(frames or 0)
    name = os.path.basename(path) + (" (%d frames)" % frames if frames
                                     else "")
    clear(base)
    sc.frame_start, sc.frame_end = 1, 250
    before = state.snapshot()
    error = imported(path, frames)
    top = sc.phyllo_structure
    check(not error and top is not None,
          "%s: imported (%s), the panel on it" % (name, error or "ok"))
    if error or top is None:
        continue
    listed = [s["path"] for s in json.loads(subprocess.run(
        [program, "--settings", path], stdout=subprocess.PIPE,
        check=True, universal_newlines=True).stdout)["settings"]]
    shown = [s.path for s in top.phyllo.settings]
    missing = [p for p in listed if p not in shown]
    check(shown == listed, "%s: the panel lists the %d settings --settings "
          "does, in its order (%d shown; missing %s)"
          % (name, len(listed), len(shown), missing[:6]))
    changed = ["%s (%s: %r for %r)" % (s.path, s.kind, s.value(), s.written)
               for s in top.phyllo.settings if s.changed()]
    check(not changed, "%s: every field holds the file's value as it is "
          "(shown changed: %s)" % (name, changed[:4]))
    if frames:
        check(sc.frame_end - sc.frame_start == frames - 1,
              "%s: the timeline is the frames (%d..%d)"
              % (name, sc.frame_start, sc.frame_end))
    first = state.snapshot()
    left = state.orphans(before)
    check(not left, "%s: nothing orphaned %s" % (name, left[:6]))
    error = imported(path, frames)
    left = state.orphans(before)
    diff = state.differences(first, state.snapshot())
    check(not error and not left and not diff,
          "%s: imported again (%s): nothing orphaned %s, the .blend as "
          "the first import left it (%s)"
          % (name, error or "ok", left[:6], diff))
done()
