#!/bin/sh
# run.sh SECONDS [HARNESS...] - run each fuzz harness (every
# tests/fuzz/fuzz_*.c unless named) for SECONDS on its corpus in
# build-fuzz/corpus/NAME, seeded from the scenes, test inputs, templates,
# organ meshes and points files; crashes are written to
# build-fuzz/crash-NAME-*.
set -u
t=${1:-60}
# libconfig 1.5 leaks on one kind of syntax error: not ours.
LSAN_OPTIONS=suppressions=$(pwd)/tests/tools/lsan.supp:print_suppressions=0
export LSAN_OPTIONS
[ $# -gt 0 ] && shift
all=$(for h in tests/fuzz/fuzz_*.c; do basename "$h" .c; done)
for f in ${*:-$all}; do
	c=build-fuzz/corpus/$f
	mkdir -p "$c"
	case $f in
	# The regression cases' scenes but pov/ and gltf/'s, whose errors
	# are the writers' (they were not seeds before the move either).
	fuzz_scene) cp scenes/*.cfg $(ls tests/regress/*/*.cfg |
		grep -v '^tests/regress/\(pov\|gltf\)/') "$c"/
		# Naming the two parts the harness provides.
		printf 'model = "planar";\ncount = "5 + F";\norgans = ( { object = ["P", "N"];\n  scene = ["part.cfg", "nested.cfg"]; scale = "r * f"; } );\n' >"$c/compound.cfg"
		printf 'model = "planar";\ncount = "3 * F";\norgans = ( { object = "D"; scene = "deep.cfg"; tilt = "10 * f"; } );\n' >"$c/deep-compound.cfg"
		# Collision scenes run only with a count (see the harness).
		for s in scenes/*.cfg; do
			{ echo 'count = 400;'; cat "$s"; } >"$c/count-${s##*/}"
		done ;;
	fuzz_expr) grep -ho '"[^"]*"' scenes/*.cfg tests/regress/expr/*.cfg |
		tr -d '"' | awk '{ f = sprintf("%s/seed%d", c, NR); printf "%s", $0 > f; close(f) }' c="$c" ;;
	fuzz_template) cp templates/*.tmpl tests/regress/pov/*.tmpl "$c"/ ;;
	fuzz_set) i=0
		# An argument, then a scene, as the harness reads them.
		for a in 'count=300' 'planar.scale=0.05' 'organs.1.tilt="20 * f"' \
		    'planar={ scale = 0.1; }' 'stretch=[1.0, 2.0, 1.0]' \
		    'collision.receptacle.shape="cone"' 'Floret:count=3' \
		    'organs.9.scale=1' 'count.x=1' 'count=1+' 'divergence=100' \
		    'inhibition.exponent=4'; do
			for s in scenes/sunflower.cfg scenes/coneflower.cfg \
			    scenes/pinecone.cfg scenes/sunflower-emerged.cfg; do
				{ printf '%s\n' "$a"; cat "$s"; } >"$c/seed$i"
				i=$((i + 1))
			done
		done ;;
	# Points files: the example, the bad cases', and our own --csv.
	fuzz_points) cp scenes/points/*.csv tests/regress/measured/points/*.csv "$c"/
		./phyllo-export --csv tests/regress/planar/vogel90.cfg >"$c/vogel90.csv" 2>/dev/null ;;
	fuzz_obj) cp scenes/organs/*.obj scenes/organs/*.mtl tests/gltf/*.obj \
		tests/gltf/*.mtl tests/regress/gltf/*.obj tests/regress/gltf/*.mtl "$c"/ ;;
	# Names of every kind: identifiers, the materials, and the bytes
	# of the escaping test.
	fuzz_json) grep -h '^usemtl\|^newmtl' scenes/organs/* tests/gltf/* |
		awk '{ f = sprintf("%s/seed%d", c, NR); printf "%s", $2 > f; close(f) }' c="$c"
		printf 'a"b\\c\001d\377\303\274\355\240\200' >"$c/bytes"
		# ff before continuation bytes, once copied out raw.
		printf '\241p\377\241\241\241' >"$c/stray-ff" ;;
	esac
	echo "== $f, $t s"
	./build-fuzz/$f -max_total_time="$t" -max_len=8192 -timeout=10 \
		-rss_limit_mb=2048 -close_fd_mask=2 -print_final_stats=1 \
		-artifact_prefix=build-fuzz/crash-$f- "$c" 2>&1 |
		grep -E '^(#[0-9]+.*(DONE|pulse)|stat::|==[0-9]+==ERROR|SUMMARY|artifact)' | tail -8
done
