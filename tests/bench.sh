#!/bin/sh
# bench.sh - speed, measured side by side in one run (make bench).
# Not part of make check: timings depend on the machine.
: "${PHYLLO:=./phyllo-export}" "${TESTBIN:=build}"
OUT=tests/out/bench
mkdir -p "$OUT" || exit 1

now() { date +%s.%N; }

# best SECONDS-OF-3 CMD...: the fastest of three runs.
best() {
	b=
	for i in 1 2 3; do
		t0=$(now)
		"$@" >/dev/null || { echo "bench: $* failed" >&2; exit 1; }
		t1=$(now)
		b=$(echo "$t0 $t1 ${b:-1e9}" | awk '{ d = $2 - $1; print d < $3 ? d : $3 }')
	done
	echo "$b"
}

N=1000000
printf 'model = "planar";\ncount = %d;\nplanar = { scale = 0.01; dome = 0.2; };\n' $N >"$OUT/planar.cfg"

echo "== expressions"
"$TESTBIN/bench_expr"

echo "== number formatting"
"$TESTBIN/bench_numfmt"

echo "== planar emission, $N organs, one core"
model=$(best "$PHYLLO" --info "$OUT/planar.cfg")
csv=$(best "$PHYLLO" --csv -o /dev/null "$OUT/planar.cfg")
bytes=$("$PHYLLO" --csv "$OUT/planar.cfg" | wc -c)
echo "$model $csv $bytes $N" | awk '{
	printf "model only (--info):  %.3f s\n", $1
	printf "model + CSV (--csv):  %.3f s  = %.2f M organs/s, %.0f MB/s (%d bytes)\n", $2, $4 / $2 / 1e6, $3 / $2 / 1e6, $3
	printf "CSV writing share:    %.0f%%\n", 100 * ($2 - $1) / $2
}'
