#!/bin/sh
# bench.sh - speed, measured side by side in one run (make bench).
# Not part of make check: timings depend on the machine.
: "${PHYLLO:=./phyllo-export}" "${TESTBIN:=build}"
. tests/lib.sh
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

# The code before this round of issue 38's work (8d64d91: the layout of
# issue 37 in place, the inhibition model's grid bound not yet), built
# here with today's bench programs, so that each figure below is printed
# beside the old code's in the same run (BENCH_BASE=<commit> for
# another, of this layout: tests/bench/, models/model_ctx; none outside
# git).
BASE=${BENCH_BASE:-8d64d91}
OLD=
if [ "$BASE" != none ] && git rev-parse -q --verify "$BASE^{commit}" >/dev/null 2>&1; then
	OLD=$OUT/old
	rm -rf "$OLD" && mkdir -p "$OLD" &&
		git archive "$BASE" | tar -x -C "$OLD" &&
		cp tests/bench/bench_*.c tests/bench/clock.h "$OLD/tests/bench/" &&
		cp tests/unit/dense.h "$OLD/tests/unit/" &&
		(cd "$OLD" && ./configure >/dev/null 2>&1 &&
		make -s phyllo-export build/bench_phases build/bench_inhibition \
		build/bench_matrix >/dev/null 2>&1) || OLD=
	[ -n "$OLD" ] && echo "old code: $BASE ($(git log -1 --format=%s "$BASE" | cut -c1-60)...)" ||
		echo "old code: $BASE did not build; figures for today's code only"
fi

# side NEW OLD: two bench outputs, line by line, today's then the old.
side() {
	if [ -n "$OLD" ]; then
		paste -d '\n' "$1" "$2" | awk '{ printf "%s %s\n", NR % 2 ? "now:" : "old:", $0 }'
	else
		cat "$1"
	fi
}

echo "== a run's three costs, each timed on its own (model, parastichy analysis, CSV writing), one core"
phases() {
	"$TESTBIN/bench_phases" "$@" >"$OUT/phases.new" || exit 1
	[ -z "$OLD" ] || "$OLD/build/bench_phases" "$@" >"$OUT/phases.old" || exit 1
	side "$OUT/phases.new" "$OUT/phases.old"
}
echo "planar, $N organs (the analysis' target: 0.25 s):"
phases "model = \"planar\"; count = $N; planar = { scale = 0.01; dome = 0.2; };" pairs
echo "area model on a hemisphere, $N organs:"
phases "model = \"area\"; count = $N; area = { receptacle = { shape = \"hemisphere\"; }; };"
echo "collision model on the dome, r = 0.0012 (about $N organs):"
phases "model = \"collision\"; count = 2000000; collision = { receptacle = { shape = \"hemisphere\"; }; radius = 0.0012; };"
echo "inhibition model, 100,000 at G = 0.005, grown radii (from 1 to e^500):"
phases "model = \"inhibition\"; count = 100000; inhibition = { growth = 0.005; radii = \"grown\"; };"

echo "== planar emission through the program, $N organs, one core"
info=$(best "$PHYLLO" --info "$OUT/planar.cfg")
csv=$(best "$PHYLLO" --csv -o /dev/null "$OUT/planar.cfg")
bytes=$("$PHYLLO" --csv "$OUT/planar.cfg" | wc -c)
echo "$info $csv $bytes $N" | awk '{
	printf "--info (model and analysis):  %.3f s\n", $1
	printf "--csv (model and CSV):        %.3f s  = %.2f M organs/s, %.0f MB/s (%d bytes)\n", $2, $4 / $2 / 1e6, $3 / $2 / 1e6, $3
}'

echo "== the count limit, one core: time and peak memory of a run of each model at its largest"
# 10,000,000 organs (the count limit), 5,000,000 for the collision
# model (its own limit); the inhibition model's limit is its growth
# summed, under 700: at G = 0.005 some 137,000 primordia.
if [ -x /usr/bin/time ]; then
	printf 'model = "planar";\ncount = 10000000;\n' >"$OUT/max-planar.cfg"
	printf 'model = "cylindrical";\ncount = 10000000;\ncylindrical = { parastichies = [34, 55]; };\n' >"$OUT/max-cylindrical.cfg"
	printf 'model = "area";\ncount = 10000000;\narea = { receptacle = { shape = "hemisphere"; }; };\n' >"$OUT/max-area.cfg"
	printf 'model = "collision";\ncount = 5000000;\ncollision = { receptacle = { shape = "hemisphere"; }; radius = 0.00053; };\n' >"$OUT/max-collision.cfg"
	printf 'model = "inhibition";\ncount = 137000;\ninhibition = { growth = 0.005; };\n' >"$OUT/max-inhibition.cfg"
	for m in planar cylindrical area collision inhibition; do
		for how in --csv --info; do
			/usr/bin/time -f "%e %M" -o "$OUT/max.time" "$PHYLLO" $how -o "$OUT/max.out" "$OUT/max-$m.cfg" 2>"$OUT/max.err" ||
				{ echo "$m $how: failed: $(head -1 "$OUT/max.err")"; continue; }
			n=$("$PHYLLO" --info "$OUT/max-$m.cfg" 2>/dev/null | sed -n 's/^count: //p')
			[ "$how" = --csv ] && b=$(wc -c <"$OUT/max.out") || b=0
			echo "$m $how $n $(tail -1 "$OUT/max.time") $b"
		done
	done | awk '$3 == "failed:" { print; next } { printf "%-12s %-7s %9d organs: %6.2f s, peak %6.0f MB = %4.0f bytes an organ%s\n", $1, $2, $3, $4, $5 / 1024, $5 * 1024 / $3, $6 ? sprintf("; %.2f GB of CSV", $6 / 1e9) : "" }'
	rm -f "$OUT/max.out"
fi

echo "== collision model: exact placement, one core"
"$TESTBIN/bench_collision"

echo "== collision model on every receptacle, fill and radius law, one core"
# Round after round, today's code then the old (MATRIX_ROUNDS, 3): a
# row's figure is its best round, so a row that one round caught on a
# slow minute does not set it, and the two codes' rows are measured
# minutes apart, not a run apart.  The first round's own lines first.
# BENCH_CPU=1: each case's CPU time, not the clock's (a shared machine).
R=${MATRIX_ROUNDS:-3}
i=1
while [ "$i" -le "$R" ]; do
	"$TESTBIN/bench_matrix" 1 2>/dev/null >"$OUT/matrix.new.$i"
	[ "$i" -gt 1 ] || cat "$OUT/matrix.new.1"
	[ -z "$OLD" ] || "$OLD/build/bench_matrix" 1 2>/dev/null >"$OUT/matrix.old.$i"
	i=$((i + 1))
done
echo "-- best of $R rounds a row${OLD:+, today's code beside the old}"
# Each row's us a primordium, and its ratio to the best dome of its
# code; 300k over 100k from the two rows' best times.
files=$(i=1; while [ "$i" -le "$R" ]; do echo "$OUT/matrix.new.$i"; [ -z "$OLD" ] || echo "$OUT/matrix.old.$i"; i=$((i + 1)); done)
# shellcheck disable=SC2086
awk -v old="${OLD:+1}" '
	FNR == 1 { f = FILENAME ~ /\.old\./ ? 2 : 1; head = "first cases" }
	/^[a-z].*(radius|bound):$/ { head = $0; sub(/:$/, "", head) }
	/ us each/ {
		us = $0; sub(/ us each.*/, "", us); sub(/.*= */, "", us)
		row = $0; sub(/^  /, "", row); sub(/  +[0-9]+ in .*/, "", row)
		key = head " / " row
		if (!(key in seen)) {
			seen[key] = 1; order[++n] = key
			if (row ~ /300,000$/) {
				base = key; sub(/300,000$/, "100,000", base)
				order[++n] = head " / 300k over 100k"; pair[n] = base SUBSEP key
			}
		}
		if (!((f, key) in t) || us + 0 < t[f, key]) t[f, key] = us + 0
		if (row ~ /^full dome/ && (!(f in dome) || us + 0 < dome[f])) dome[f] = us + 0
	}
	function cell(g, k,   a, b, p) {
		if (k ~ /300k over 100k$/) {
			for (p in pair) if (order[p] == k) { split(pair[p], a, SUBSEP) }
			if (!((g, a[1]) in t) || !((g, a[2]) in t)) return sprintf("%16s", "-")
			return sprintf("%7.1f%9s", 3 * t[g, a[2]] / t[g, a[1]], "")
		}
		if (!((g, k) in t)) return sprintf("%16s", "-")
		return sprintf("%7.2f (%4.2fx)", t[g, k], t[g, k] / dome[g])
	}
	END {
		printf "%-72s %16s%s\n", "case (us a primordium; for 300k over 100k, the time ratio)", "now (x dome)", old ? "     old (x dome)" : ""
		for (i = 1; i <= n; i++)
			printf "%-72s %s%s\n", order[i], cell(1, order[i]), old ? " " cell(2, order[i]) : ""
	}' $files

echo "== inhibition model, one core (target: 20 us a primordium at every G)"
"$TESTBIN/bench_inhibition" >"$OUT/inhib.new" || exit 1
[ -z "$OLD" ] || "$OLD/build/bench_inhibition" >"$OUT/inhib.old" || exit 1
side "$OUT/inhib.new" "$OUT/inhib.old"

echo "== area model alone (model_run, no output), one core"
"$TESTBIN/bench_area"
echo "== area model through --info (with the parastichy analysis)"
printf 'model = "area";\ncount = %d;\narea = { receptacle = { shape = "hemisphere"; }; };\n' $N >"$OUT/area.cfg"
# The collision model on the same receptacle, with the radius at which
# it places the same count (a little under the area model's even radius).
r=$("$PHYLLO" --info "$OUT/area.cfg" | awk '/^radius:/ { print $2 * 0.93 }')
printf 'model = "collision";\ncount = %d;\ncollision = { receptacle = { shape = "hemisphere"; }; radius = %s; };\n' $N "$r" >"$OUT/area-coll.cfg"
ta=$(best "$PHYLLO" --info "$OUT/area.cfg")
tc=$(best "$PHYLLO" --info "$OUT/area-coll.cfg")
nc=$("$PHYLLO" --info "$OUT/area-coll.cfg" | sed -n 's/^count: //p')
echo "$ta $tc $N $nc" | awk '{
	printf "area model: %.3f s = %.1f M organs/s; collision model, same receptacle: %.3f s for %d = %.2f M/s; ratio %.1fx\n", $1, $3 / $1 / 1e6, $2, $4, $4 / $2 / 1e6, ($2 / $4) / ($1 / $3)
}'

echo "== glTF (.glb), $N organs, one core"
# Against --csv of the same scene: the issue asks for 1.3x at most, and
# 48 bytes an organ beyond the mesh (the placeholder here).
gltf=$(best "$PHYLLO" --gltf -o /dev/null "$OUT/planar.cfg" 2>/dev/null)
"$PHYLLO" --gltf -o "$OUT/planar.glb" "$OUT/planar.cfg" 2>/dev/null
printf 'model = "planar";\ncount = 1;\n' >"$OUT/one.cfg"
one=$("$PHYLLO" --gltf "$OUT/one.cfg" 2>/dev/null | wc -c)
echo "$gltf $csv $(wc -c <"$OUT/planar.glb") $one $N" | awk '{
	printf "model + glTF (--gltf): %.3f s = %.2f M organs/s, %.2fx --csv (%.3f s)\n", $1, $5 / $1 / 1e6, $1 / $2, $2
	printf "glTF size: %d bytes, %.2f bytes an organ beyond the mesh (a one-organ file is %d)\n", $3, ($3 - $4) / ($5 - 1), $4
}'
if [ -n "${NODE:-}" ] && [ -n "${CHROMIUM:-}" ] && [ -d src/viewer/node_modules/three ]; then
	# three.js in headless Chromium (software GL): fetch, GLTFLoader's
	# parse into InstancedMeshes, and the first frame drawn.
	"$NODE" tests/gltf/three.mjs --time "$CHROMIUM" "$OUT/planar.glb" |
		"$NODE" -e 'let s = ""; process.stdin.on("data", d => s += d).on("end", () => {
			const f = JSON.parse(s);
			console.log(`three.js, ${f.organs} organs (${(f.bytes / 1e6).toFixed(1)} MB): fetch ${f.fetchMs.toFixed(0)} ms, parse ${f.parseMs.toFixed(0)} ms, first frame ${f.firstFrameMs.toFixed(0)} ms${f.errors.length ? "; errors: " + f.errors : ""}`);
		})'
fi

# The WebAssembly build (make web, in WEB where configure found emcc):
# the module in Node.js beside the native program, and the page.
if [ -n "${WEB:-}" ] && [ -n "${NODE:-}" ]; then
	echo "== the WebAssembly build (make web), one core"
	"$NODE" tests/bench/web.mjs "$PHYLLO" "$WEB" "$OUT" ${CHROMIUM:+"$CHROMIUM"}
fi

echo "== POV-Ray include, $N organs"
pov=$(best "$PHYLLO" --pov -o /dev/null "$OUT/planar.cfg")
echo "$pov $N" | awk '{ printf "model + include:      %.3f s  = %.2f M organs/s\n", $1, $2 / $1 / 1e6 }'

if [ -n "${POVRAY:-}" ]; then
	# POV-Ray parsing 100,000 organs from our include, against its own
	# #while loop placing the same Vogel pattern with the same matrices.
	M=100000
	printf 'name = "Head";\nmodel = "planar";\ncount = %d;\nplanar = { scale = 0.01; };\norgans = ( { object = "Seed"; scale = 0.005; } );\n' $M >"$OUT/head.cfg"
	"$PHYLLO" --pov -o "$OUT/head.inc" "$OUT/head.cfg"
	printf '#version 3.7;\ncamera { location <0, 5, -0.001> look_at 0 }\n#declare Seed = sphere { 0, 1 }\n#include "head.inc"\nobject { Head }\n' >"$OUT/inc.pov"
	{
		printf '#version 3.7;\ncamera { location <0, 5, -0.001> look_at 0 }\n#declare Seed = sphere { 0, 1 }\n'
		printf '#declare A = radians(137.50776405003785);\n#declare Head = union {\n#declare I = 0;\n#while (I < %d)\n' $M
		printf '  #declare R = 0.01 * sqrt(I);\n  #declare C = cos(I * A);\n  #declare S = sin(I * A);\n'
		printf '  object { Seed matrix <C * 0.005, 0, S * 0.005,  0, 0.005, 0,  -S * 0.005, 0, C * 0.005,  R * C, 0, R * S> }\n'
		printf '  #declare I = I + 1;\n#end\n}\nobject { Head }\n'
	} >"$OUT/loop.pov"
	# Parse and a 1-pixel render: the parse is what differs.
	parse() { (cd "$OUT" && "$POVRAY" -D -GA +W1 +H1 +I"$1" +O/dev/null 2>/dev/null); }
	tinc=$(best parse inc.pov)
	tloop=$(best parse loop.pov)
	mem=0
	if [ -x /usr/bin/time ]; then
		(cd "$OUT" && /usr/bin/time -f %M -o mem "$POVRAY" -D -GA +W1 +H1 +Iinc.pov +O/dev/null 2>/dev/null)
		mem=$(tail -1 "$OUT/mem")
	fi
	echo "$tinc $tloop $mem $(wc -c <"$OUT/head.inc") $M" | awk '{
		printf "POV-Ray, %d organs: our include %.2f s, SDL #while loop %.2f s, ratio %.2fx (loop / include)\n", $5, $1, $2, $2 / $1
		printf "POV-Ray peak memory with the include: %.0f MB; include size %.1f MB\n", $3 / 1024, $4 / 1e6
	}'
fi

echo "== compound: a broccoli of 1,000 florets x 1,000 buds, one core"
# The floret is a part; --pov and --blender should cost what the 1,000
# florets and one floret of 1,000 cost, not what a million buds would.
printf 'name = "Broccoli";\nmodel = "planar";\ncount = 1000;\nplanar = { scale = 0.05; dome = 0.5; };\norgans = ( { object = "Floret"; scene = "floret.cfg"; } );\n' >"$OUT/broccoli.cfg"
printf 'model = "planar";\ncount = 1000;\nplanar = { scale = 0.03; dome = 0.3; };\norgans = ( { object = "Bud"; } );\n' >"$OUT/floret.cfg"
printf 'model = "planar";\ncount = 2000;\nplanar = { scale = 0.05; dome = 0.5; };\n' >"$OUT/two-thousand.cfg"
tpov=$(best "$PHYLLO" --pov -o /dev/null "$OUT/broccoli.cfg")
tbl=$(best "$PHYLLO" --blender -o /dev/null "$OUT/broccoli.cfg")
t2k=$(best "$PHYLLO" --pov -o /dev/null "$OUT/two-thousand.cfg")
tflat=$(best "$PHYLLO" --csv --flatten -o /dev/null "$OUT/broccoli.cfg")
tmil=$(best "$PHYLLO" --csv -o /dev/null "$OUT/planar.cfg")
"$PHYLLO" --pov -o "$OUT/broccoli.inc" "$OUT/broccoli.cfg"
"$PHYLLO" --blender -o "$OUT/broccoli.py" "$OUT/broccoli.cfg"
echo "$tpov $tbl $t2k $tflat $tmil $(wc -c <"$OUT/broccoli.inc") $(wc -c <"$OUT/broccoli.py")" | awk '{
	printf "--pov %.3f s (%d bytes), --blender %.3f s (%d bytes); a plain 2,000-organ --pov %.3f s: ratio %.2fx\n", $1, $6, $2, $7, $3, $1 / $3
	printf "--csv --flatten, 1,000,000 leaves: %.3f s = %.2f M leaves/s; a plain 1,000,000-organ --csv %.3f s: ratio %.2fx\n", $4, 1 / $4, $5, $4 / $5
}'
if [ -n "${POVRAY:-}" ]; then
	printf '#version 3.7;\ncamera { location <0, 5, -0.001> look_at 0 }\n#declare Bud = sphere { 0, 1 }\n#include "broccoli.inc"\nobject { Broccoli }\n' >"$OUT/broccoli.pov"
	tparse=$(best parse broccoli.pov)
	echo "$tparse" | awk '{ printf "POV-Ray parses the broccoli include (1,000,000 buds by nested instancing): %.2f s\n", $1 }'
fi

echo "== frames: --blender --frames N of a 10,000-organ scene, one core"
# One script animating every frame, written as the frames are made:
# memory should be one frame's whatever N, and time N frames'.
if [ -x /usr/bin/time ]; then
	printf 'model = "planar";\ncount = 10000;\nplanar = { scale = "0.01 + 0.01 * f"; };\norgans = ( { object = "Seed"; tilt = "30 * f"; } );\n' >"$OUT/frames.cfg"
	for n in 1 100 1000; do
		/usr/bin/time -f "%e %M" -o "$OUT/frames$n" "$PHYLLO" --blender --frames $n -o "$OUT/frames.py" "$OUT/frames.cfg" || exit 1
		echo "$n $(cat "$OUT/frames$n") $(wc -c <"$OUT/frames.py")"
	done | awk '
		NR == 1 { rss1 = $3 }
		{ t[NR] = $2; printf "%5d frames: %6.2f s, %.2f ms a frame, max RSS %6.1f MB (%.2fx one frame), %4.0f MB written\n", $1, $2, 1000 * $2 / $1, $3 / 1024, $3 / rss1, $4 / 1e6 }
		END { printf "time 1000 frames / 100 frames: %.1f (10 is linear)\n", t[3] / t[2] }'
fi

# Blender: each one the suite finds (BLENDERS: the system's and the
# Debian roots of tests/tools/blender-root.sh), timed inside Blender.
: "${BLENDERS:=${BLENDER:-}}"
if [ -n "$BLENDERS" ]; then
	for M in 100000 1000000; do
		printf 'name = "Head";\nmodel = "planar";\ncount = %d;\norgans = ( { object = "Seed"; } );\n' $M >"$OUT/b$M.cfg"
		"$PHYLLO" --blender -o "$OUT/b$M.py" "$OUT/b$M.cfg"
	done
	# The loop a user would write: one operator call per organ.
	N=${NAIVE:-2000}
	printf 'model = "planar";\ncount = %d;\n' $N >"$OUT/naive.cfg"
	"$PHYLLO" --blender -o "$OUT/ours.py" "$OUT/naive.cfg"
	"$PHYLLO" --csv "$OUT/naive.cfg" | awk -F, 'NR == 1 {
		print "import bpy"; print "organs = ["; next }
		{ printf "(%s, %s, %s, %s),\n", $3, $4, $5, $15 }
		END { print "]"
		print "for x, y, z, s in organs:"
		print "    bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=2, radius=s, location=(x, y, z))" }' >"$OUT/naive.py"
	s1=$(wc -c <"$OUT/b100000.py")
	echo "== Blender import (bpy, no numpy), seconds inside Blender beyond start-up"
	echo "script size for 100,000 organs: $s1 bytes = $(echo "$s1" | awk '{ printf "%.1f", $1 / 100000 }') bytes an organ"
	for b in $BLENDERS; do
		use_blender "$b"
		ver=$(bl --version 2>/dev/null | sed -n 's/^Blender \([0-9.]*\).*/\1/p' | head -1)
		# inside SCRIPT: the seconds timeit.py measures, best of three.
		inside() {
			for i in 1 2 3; do
				bl -b --factory-startup --python tests/blender/timeit.py -- "$1" 2>/dev/null |
					sed -n 's/^timeit: //p'
			done | sort -n | head -1
		}
		t1=$(inside "$OUT/b100000.py")
		t2=$(inside "$OUT/b1000000.py")
		to=$(inside "$OUT/ours.py")
		tbr=$(inside "$OUT/broccoli.py")
		tn=$(bl -b --factory-startup --python tests/blender/timeit.py -- "$OUT/naive.py" 2>/dev/null | sed -n 's/^timeit: //p')
		echo "$ver $t1 $t2 $to $tn $N" | awk '{
			printf "Blender %s: 100,000 organs %.2f s, 1,000,000 %.2f s; %d organs: ours %.3f s, per-organ bpy.ops loop %.1f s (one run): %.0fx\n", $1, $2, $3, $6, $4, $5, $5 / $4
		}'
		echo "$ver $tbr" | awk '{ printf "Blender %s: the broccoli (1,000 florets instancing one 1,000-bud floret) %.2f s\n", $1, $2 }'
		# The panel: a setting changed until the structure is built again.
		if [ -f "$TESTBIN/phyllo_import.zip" ] && [ -x "$TESTBIN/phyllo-export-static" ]; then
			for M in 10000 100000; do
				printf 'model = "planar";\ncount = %d;\nplanar = { scale = 0.01; };\norgans = ( { object = "Seed"; } );\n' $M >"$OUT/panel$M.cfg"
				rm -rf "$OUT/user"
				BLENDER_USER_RESOURCES="$(pwd)/$OUT/user" PHYLLO_EXPORT="$(pwd)/$TESTBIN/phyllo-export-static" \
					bl -b --factory-startup --python tests/blender/roundtrip.py -- \
					"$(pwd)/$TESTBIN/phyllo_import.zip" "$(pwd)/$OUT/panel$M.cfg" 2>/dev/null |
					sed -n 's/^roundtrip: //p'
			done | awk -v v="$ver" '{ t[NR] = $1; n[NR] = $2 }
				END { printf "Blender %s: panel round trip (setting changed -> structure rebuilt), best of 3: %d organs %.3f s (target 0.3), %d organs %.3f s (target 1)\n", v, n[1], t[1], n[2], t[2] }'
		fi
	done
fi

echo "== measured model: 100,000 clicked florets read and analysed, one core (target: 1 s)"
# A head as a photograph gives it (Vogel's, jittered 15%, 5% missed);
# the phases in the process, then the program's own --info, best of 3,
# and its CPU time (the machine is shared: wall time follows the load).
"$TESTBIN/bench_measured" csv 100000 >"$OUT/measured.csv"
printf 'model = "measured";\nmeasured = { points = "measured.csv"; };\n' >"$OUT/measured.cfg"
"$TESTBIN/bench_measured" speed "$OUT/measured.csv"
t=$(best "$PHYLLO" --info "$OUT/measured.cfg")
if [ -x /usr/bin/time ]; then
	/usr/bin/time -f "%U %S" -o "$OUT/measured.time" "$PHYLLO" --info "$OUT/measured.cfg" >/dev/null
	cpu=$(awk '{ print $1 + $2 }' "$OUT/measured.time")
fi
echo "phyllo-export --info of the points file: $t s (CPU ${cpu:-?} s)"

echo "== measured model: heads and cones at each distortion, read as in order (of ${MEASURED_SEEDS:-50} seeds)"
"$TESTBIN/bench_measured" trials "${MEASURED_SEEDS:-50}"
