#!/bin/sh
# run.sh - the whole suite: every script's "ok"/"not ok" lines, counted.
# Ends with "N passed, N failed" and exits non-zero on any failure.

: "${TESTBIN:=build}"
mkdir -p tests/out
log=tests/out/run.log
{
	# A test program that dies is a failure, whatever it printed.
	for t in test_numfmt test_geometry test_planar test_organs test_scene test_expr test_cylindrical test_collision test_area test_inhibition test_parastichy; do
		$RUN "$TESTBIN/$t" || echo "not ok - $t exited with status $?"
	done
	for t in regress limits set placeholders cli scenes compound pov blender gltf man docs; do
		sh "tests/$t.sh"
	done
} 2>&1 | tee "$log" | grep -v '^ok - ' | grep -v '^ok - # SKIP'

pass=$(grep -c '^ok - ' "$log")
skip=$(grep -c '^ok - # SKIP' "$log")
fail=$(grep -c '^not ok - ' "$log")
pass=$((pass - skip))
echo "$pass passed, $fail failed, $skip skipped"
[ "$fail" -eq 0 ] && [ "$pass" -gt 0 ]
