# checks.py - how every script of tests/blender/ reports: a line
# "check: ok WHAT" or "check: FAILED WHAT" a check (tests/blender.sh
# reads them), and at the end done(), which exits non-zero if any
# failed.
failures = []


def check(ok, what):
    print("check: %s %s" % ("ok" if ok else "FAILED", what))
    if not ok:
        failures.append(what)


def done():
    if failures:
        raise SystemExit("check: %d failed" % len(failures))
