#!/bin/sh
# docs.sh - every example of README.md and the man pages held against
# the program (tests/docs.py): the output shown, the commands shown
# running, the excerpts of scene files their own lines.
. tests/lib.sh

if ! command -v python3 >/dev/null; then
	skip "python3 not found: the examples of the README and man pages"
	exit 0
fi
python3 tests/docs.py "$(cd "$(dirname "$PHYLLO")" && pwd)/$(basename "$PHYLLO")" "$OUT/work"
