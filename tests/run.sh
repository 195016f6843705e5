#!/bin/sh
# run.sh - the whole suite: every script's "ok"/"not ok" lines, counted.
# Ends with "N passed, N failed" and exits non-zero on any failure.
# Nothing here is a list kept by hand: the unit tests are every
# tests/unit/test_*.c (built into $TESTBIN by make), run first since
# they are fast, then the scripts are every tests/*.sh but this one and
# lib.sh, in the order of their names (each is independent: it writes
# only its own tests/out/NAME).  Says how long each took.

: "${TESTBIN:=build}"
mkdir -p tests/out
log=tests/out/run.log
# How long each part took, for CI's budget: "unit 12 s, blender 250 s".
times=tests/out/run.times
: >"$times"
took() { printf '%s%s %s s' "$(if [ -s "$times" ]; then echo ', '; fi)" "$1" $(($(date +%s) - $2)) >>"$times"; }
{
	# A test program that dies is a failure, whatever it printed.
	t0=$(date +%s)
	for c in tests/unit/test_*.c; do
		t=$(basename "$c" .c)
		$RUN "$TESTBIN/$t" || echo "not ok - $t exited with status $?"
	done
	took unit "$t0"
	for s in tests/*.sh; do
		case $s in
		tests/lib.sh|tests/run.sh) continue ;;
		esac
		t0=$(date +%s)
		sh "$s"
		took "$(basename "$s" .sh)" "$t0"
	done
} 2>&1 | tee "$log" | grep -v '^ok - ' | grep -v '^ok - # SKIP'

pass=$(grep -c '^ok - ' "$log")
skip=$(grep -c '^ok - # SKIP' "$log")
fail=$(grep -c '^not ok - ' "$log")
pass=$((pass - skip))
echo "seconds: $(cat "$times")"
echo "$pass passed, $fail failed, $skip skipped"
[ "$fail" -eq 0 ] && [ "$pass" -gt 0 ]
