# sequence.py - generated scripts run one after another into the open
# .blend, as an artist re-runs them in one session (a 24-frame growth,
# a 4-frame one, the 24-frame one again): after each, no data-block of
# any kind (state.py) that no one uses and that was not so before the
# first, and after a script that ran before, the .blend exactly as that
# run left it: the same data-blocks, names and user counts.  Usage:
#   blender -b [FILE.blend] --python sequence.py -- SCRIPT...
# Prints "check: ..." lines like check.py.
import os
import runpy
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import state  # noqa: E402 (after the path)
from checks import check, done  # noqa: E402

scripts = sys.argv[sys.argv.index("--") + 1:]


start = state.snapshot()
after = {}
for i, script in enumerate(scripts):
    runpy.run_path(script, run_name="__main__")
    now = state.snapshot()
    what = "run %d (%s)" % (i + 1, os.path.basename(script))
    left = state.orphans(start)
    check(not left, "%s: nothing orphaned %s" % (what, left[:8]))
    if script in after:
        diff = state.differences(after[script], now)
        check(not diff, "%s: the .blend as its last run left it (%s)"
              % (what, diff))
    after[script] = now
done()
