#!/bin/sh
# measured.sh - the measured model through the program: the models' own
# organs, rows shuffled, read back and measured as the models measure
# them; the published figures it must reproduce (Vogel's spacing
# constant, van Iterson's square and triple points); a photograph's
# coordinates; -o never naming the points file; a large file of junk
# refused at once.
. tests/lib.sh

# measure CFG POINTS [SETTINGS]: a measured scene reading POINTS.
measure() {
	printf 'model = "measured";\nmeasured = { points = "%s"; %s };\n' \
	    "$2" "${3:-}" >"$1"
}

# shuffled: the rows of a CSV on stdin, header first, in a fixed
# random order.
shuffled() {
	awk 'BEGIN { srand(7) } NR == 1 { print; next } { print rand() "\t" $0 }' |
	    { IFS= read -r head; echo "$head"; sort -n | cut -f2-; }
}

# field KEY LABEL: a value from --info's "KEY: ...; LABEL v; ..." line.
field() {
	sed -n "s/^$1: .*$2 \\([^;]*\\).*/\\1/p" "$OUT/stdout"
}

# close A B TOL: |A - B| <= TOL.
close() {
	awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; exit !(a != "" && (d < 0 ? -d : d) <= t) }'
}

# --- Every scene's organs, shuffled, read as the model reads them. ---
# test_measured.c holds the measurement to parastichy.c organ by organ
# in the process; here the same through the program and a CSV file: the
# rim's pair the model's own --info gives, where its rim zone is more
# than a sliver (two rings, 2 n organs, which the measurement may read
# with the zone next to it), and the contacts read the ones the file's
# n confirms (order-agrees).  Under 60 organs is too few to read
# without an order.
for cfg in scenes/*.cfg; do
	name=${cfg##*/}
	name=${name%.cfg}
	grep -q 'model = "measured"' "$cfg" && continue
	px --info "$cfg" >"$OUT/$name.model" 2>/dev/null
	[ "$(sed -n 's/^count: //p' "$OUT/$name.model")" -ge 60 ] || continue
	px --csv "$cfg" 2>/dev/null | shuffled >"$OUT/$name.csv"
	measure "$OUT/$name-m.cfg" "$name.csv"
	try "scenes/$name: its organs shuffled, measured without their order, as the model reads them" px --info "$OUT/$name-m.cfg"
	assert "exit 0" '[ $rc -eq 0 ]'
	rim=$(sed -n 's/^parastichies: //p' "$OUT/$name.model")
	got=$(sed -n 's/^parastichies: //p' "$OUT/stdout")
	# The rim's zone and how many organs it holds, from the model's
	# zones: the first or last by its rim_last (the collision, area
	# and cylindrical models count from the base).
	sliver=$(sed -n 's/^parastichies-along: //p' "$OUT/$name.model" | tr ';' '\n' |
	    sed -n 's/^ *\([0-9]*\)\/\([0-9]*\) from organ \([0-9]*\).*/\1 \2 \3/p' |
	    awk -v n="$(sed -n 's/^count: //p' "$OUT/$name.model")" -v planar="$(grep -c '^model: planar' "$OUT/$name.model")" '
		{ m[NR] = $1; k[NR] = $2; from[NR] = $3 }
		END {
			if (NR == 0) { print 0; exit }
			if (planar) size = n - from[NR]; else size = (NR > 1 ? from[2] : n) - from[1]
			big = planar ? k[NR] : k[1]
			print size <= 2 * big
		}')
	# The inhibition model's oldest organs, its angle settling, may
	# show no clear pair (test_measured.c says why).
	if grep -q '^model: inhibition' "$OUT/$name.model" &&
	    echo "$got" | grep -Eq '^(none clear|transition)'; then
		:
	elif ! echo "$rim" | grep -q '^[0-9]'; then
		assert "no pair at the rim, as the model says ($got)" 'echo "$got" | grep -Eq "^(none|transition)"'
	elif [ "$sliver" = 1 ]; then
		assert "the rim's pair one the model's analysis shows ($got)" 'grep "^parastichies-along:" $OUT/$name.model | grep -q " $(echo $got | tr " " /) "'
	else
		assert "the rim's pair $rim (measured: $got)" '[ "$got" = "$rim" ]'
	fi
	assert "the order confirms nine in ten contacts read (order-agrees)" 'close "$(sed -n "s/^order-agrees: //p" $OUT/stdout)" 1 0.1'
	end
done

# --- A cone unrolled: each family drawn all the way round. ---
# A spiral that runs off one side of the unrolled page goes on from the
# other; every organ lies on a curve of each family drawn.
px --svg "$OUT/conical-m.cfg" >"$OUT/conical.svg" 2>/dev/null
try "a measured cone's SVG: every family through nine in ten organs at least" python3 -c '
import re, sys
import xml.etree.ElementTree as E
ns = "{http://www.w3.org/2000/svg}"
root = E.parse(sys.argv[1]).getroot()
organs = {(round(float(c.get("cx")), 6), round(float(c.get("cy")), 6))
          for c in root.iter(ns + "circle")}
on = {}
for p in root.iter(ns + "path"):
    for sub in p.get("d").split("M")[1:]:
        v = [float(x) for x in re.findall(r"[-\d.e+]+", sub)]
        pts = [v[0:2]] + [v[k + 4:k + 6] for k in range(2, len(v), 6)]
        on.setdefault(p.get("stroke"), set()).update(
            (round(x, 6), round(y, 6)) for x, y in pts)
shares = sorted(len(s & organs) / len(organs) for s in on.values())
print(" ".join("%.2f" % x for x in shares))
sys.exit(not (len(shares) >= 2 and shares[0] >= 0.9))' "$OUT/conical.svg"
assert "each family's share of the organs ($(cat $OUT/stdout))" '[ $rc -eq 0 ]'
end

# --- Published figures. ---
# Vogel (1979): c = 0.6242 puts the closest pair 1 apart, organs 1 and 4.
printf 'model = "planar";\ncount = 500;\nplanar = { scale = 0.6242; };\n' >"$OUT/vogel.cfg"
# Vogel counts from n = 1; organ 0 of the planar model sits on the axis.
px --csv "$OUT/vogel.cfg" | awk 'NR != 2' | shuffled >"$OUT/vogel.csv"
measure "$OUT/vogel-m.cfg" vogel.csv
try "Vogel's c = 0.6242: the closest florets 1 apart, 1 and 4; c measured back" px --info "$OUT/vogel-m.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "closest pair 1.000 apart (c to four digits)" 'close "$(field closest distance)" 1 0.0001'
assert "organs 1 and 4" 'grep -Eq "^closest: .*organ (1; organ 4|4; organ 1)$" $OUT/stdout'
c=$(field vogel c)
e=$(field vogel c-error)
assert "c = $c +- $e within three errors of 0.6242" 'close "$c" 0.6242 "$(awk -v e="$e" "BEGIN { print 3 * e }")"'
assert "divergence the golden angle" 'close "$(field divergence-measured mean)" 137.50776405 0.00005'
end

# Van Iterson on a cylinder of circumference 1 (ABOP Table 4.1 scaled by
# 2 pi): the (3, 5, 8) triple point has h = 0.017674 and circles of
# diameter 1/7; the square point of (5, 8) h = 1/(5^2 + 8^2) and
# contact 1/sqrt(89).  The cylindrical model's rise is for radius 1.
R=0.15915494309189535
printf 'model = "cylindrical";\ncount = 600;\ndivergence = 135.918365;\ncylindrical = { radius = %s; rise = 0.111049; };\n' $R >"$OUT/triple.cfg"
px --csv "$OUT/triple.cfg" 2>/dev/null | cut -d, -f2- | shuffled >"$OUT/triple.csv"
measure "$OUT/triple-m.cfg" triple.csv
try "van Iterson's (3, 5, 8) triple point: h 0.017674, contact 1/7, 135.918365 degrees" px --info "$OUT/triple-m.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "rise 0.017674" 'close "$(field rise mean)" 0.017674 0.0000006'
assert "contact 1/7" 'close "$(sed -n "s/^contact: //p" $OUT/stdout)" 0.142857143 0.000001'
assert "divergence 135.918365" 'close "$(field divergence-measured mean)" 135.918365 0.000001'
end

awk -v r=$R 'BEGIN { printf "model = \"cylindrical\";\ncount = 600;\ndivergence = %.12f;\ncylindrical = { radius = %s; rise = %.12f; };\n", 360 * 34 / 89, r, 8 * atan2(1, 1) / 89 }' >"$OUT/square.cfg"
px --csv "$OUT/square.cfg" 2>/dev/null | cut -d, -f2- | shuffled >"$OUT/square.csv"
measure "$OUT/square-m.cfg" square.csv
try "van Iterson's square point of (5, 8): h 1/89, contact 1/sqrt 89, pair 5 8" px --info "$OUT/square-m.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "parastichies 5 8" 'grep -q "^parastichies: 5 8$" $OUT/stdout'
assert "rise 1/89" 'close "$(field rise mean)" 0.011235955 0.0000005'
assert "contact 1/sqrt(89)" 'close "$(sed -n "s/^contact: //p" $OUT/stdout)" 0.105999788 0.000001'
end

# --- Frames, as any model's. ---
# Each organ's u, v, w right-handed and unit; on a head w is +Z and u
# points out from the centre; on a cone w is the surface's normal,
# pointing away from the axis, and u lies along the surface.
px --csv scenes/pinecone.cfg | cut -d, -f3-5 | sed '1s/.*/x,y,z/' >"$OUT/cone.csv"
printf 'model = "planar";\ncount = 500;\n' >"$OUT/flat.cfg"
px --csv "$OUT/flat.cfg" | cut -d, -f3,4 | sed '1s/.*/x,y/' >"$OUT/flat.csv"
measure "$OUT/cone-m.cfg" cone.csv
measure "$OUT/flat-m.cfg" flat.csv
frames='NR > 1 {
	ux = $6; uy = $7; uz = $8; vx = $9; vy = $10; vz = $11; wx = $12; wy = $13; wz = $14
	# (u x v) . w, and u . w
	h = (uy * vz - uz * vy) * wx + (uz * vx - ux * vz) * wy + (ux * vy - uy * vx) * wz
	if (h < 0.999999 || h > 1.000001 || (ux * wx + uy * wy + uz * wz) ^ 2 > 1e-12) bad++
	r = sqrt($3 * $3 + $4 * $4)
	if (r > 0 && head && (wz < 0.999999 || (ux * $3 + uy * $4) < 0.99 * r)) bad++
	if (r > 0 && !head && (wx * $3 + wy * $4) <= 0) bad++
	n++
} END { exit !(n > 0 && bad == 0) }'
try "a head's frames: w up, u out from the centre, right-handed" px --csv "$OUT/flat-m.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "every organ's" 'awk -F, -v head=1 "$frames" $OUT/stdout'
end
try "a cone's frames: w the surface's outward normal, u along it, right-handed" px --csv "$OUT/cone-m.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "every organ's" 'awk -F, -v head=0 "$frames" $OUT/stdout'
end

# --- A photograph's coordinates. ---
# The sunflower's organs as pixels, y down, off in a corner.
px --csv scenes/sunflower.cfg | awk -F, 'NR == 1 { print "x,y"; next } { printf "%.6f,%.6f\n", 900 + 400 * $3, 700 - 400 * $4 }' >"$OUT/pixels.csv"
measure "$OUT/pixels-m.cfg" pixels.csv 'yaxis = "down"; outer = 1;'
px --csv scenes/sunflower.cfg | cut -d, -f3,4 | sed '1s/.*/x,y/' >"$OUT/plain.csv"
measure "$OUT/plain-m.cfg" plain.csv 'outer = 1;'
try "image coordinates (y down) give the head unmirrored, centred and scaled" px --csv "$OUT/pixels-m.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
px --csv "$OUT/plain-m.cfg" >"$OUT/plain.out"
assert "the same organs as the plain coordinates" 'csv_close "$OUT/plain.out" "$OUT/stdout" 1e-6'
assert "outer 1: the farthest organ 1 from the axis" 'awk -F, "NR > 1 { r = sqrt(\$3 * \$3 + \$4 * \$4); if (r > m) m = r } END { exit !(m > 0.999999 && m < 1.000001) }" $OUT/stdout'
end

px --info "$OUT/plain-m.cfg" >"$OUT/plain.info"
c=$(sed -n 's/^centre: x \([^;]*\); y \(.*\)/\1 \2/p' "$OUT/plain.info")
measure "$OUT/guess-m.cfg" plain.csv "outer = 1; centre = $(echo "$c" | awk '{ printf "[%.6f, %.6f, 0.0]", $1 + 0.1, $2 - 0.05 }');"
try "a centre guessed a tenth of the radius off: the same spirals" px --info "$OUT/guess-m.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
pairs() { grep "^parastichies" "$1" | sed 's/ from [^;]*//g'; }
assert "the same pairs along" '[ "$(pairs $OUT/stdout)" = "$(pairs $OUT/plain.info)" ]'
end

# --- What a user's points may hide, said. ---
# A stray click far off: warned of at its line, the run goes on.
(cat "$OUT/plain.csv"; echo "9,9") >"$OUT/stray.csv"
measure "$OUT/stray-m.cfg" stray.csv
try "a stray click: a warning at its line" px --info "$OUT/stray-m.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "the line ($(wc -l <"$OUT/stray.csv")) and what it is" 'grep -q "stray.csv:$(wc -l <"$OUT/stray.csv"): warning: this point is [0-9.]* spacings from any other: a stray click?" $OUT/stderr'
end
try "the same head without it: no warning" px --info "$OUT/plain-m.cfg"
assert "exit 0, nothing on stderr" '[ $rc -eq 0 ] && [ ! -s $OUT/stderr ]'
end
# A head the picture's frame cut past its centre: the centre found, and
# the divergence, may be far off; cut at 0.7 of the radius, the trials'
# depth, it is read as it is.
awk -F, 'NR == 1 || $1 <= 0.15' "$OUT/plain.csv" >"$OUT/cut15.csv"
awk -F, 'NR == 1 || $1 <= 0.7' "$OUT/plain.csv" >"$OUT/cut70.csv"
measure "$OUT/cut15-m.cfg" cut15.csv
measure "$OUT/cut70-m.cfg" cut70.csv
try "a head cut past its centre: a warning that the centre may be off" px --info "$OUT/cut15-m.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "the share it reaches, and what to do" 'grep -q "cut15.csv: warning: the points reach 0.1[0-9]* of the head.s radius on one side .*give measured.centre" $OUT/stderr'
end
try "a head cut at 0.7 of its radius: no warning, the rim's pair" px --info "$OUT/cut70-m.cfg"
assert "nothing on stderr" '[ ! -s $OUT/stderr ]'
assert "55 89" 'grep -q "^parastichies: 55 89$" $OUT/stdout'
end
# A small head, whole: no side is short (eight points a side at least).
printf 'model = "planar";\ncount = 31;\n' >"$OUT/small.cfg"
px --csv "$OUT/small.cfg" | awk -F, 'NR == 1 { print "x,y"; next } NR > 2 { print $3 "," $4 }' >"$OUT/small.csv"
measure "$OUT/small-m.cfg" small.csv
try "a whole head of 30 organs: no warning of a cut" px --info "$OUT/small-m.cfg"
assert "exit 0, nothing on stderr" '[ $rc -eq 0 ] && [ ! -s $OUT/stderr ]'
end
# A centre given outside the head: said, and nothing measured.
measure "$OUT/outside-m.cfg" plain.csv 'centre = [5.0, 5.0, 0.0];'
try "a centre given outside the head: a warning; divergence none, not 0" px --info "$OUT/outside-m.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "the warning" 'grep -q "warning: about measured.centre the points reach 0 of" $OUT/stderr'
assert "divergence: none" 'grep -q "^divergence: none$" $OUT/stdout'
end
px --svg "$OUT/outside-m.cfg" >"$OUT/outside.svg" 2>/dev/null
try "its SVG says no pair is clear, not a transition" true
assert "the title" 'grep -q ">no pair clear at the rim<" $OUT/outside.svg && ! grep -q "transition" $OUT/outside.svg'
end
# A European spreadsheet: ';' between fields, a decimal comma.
sed 's/,/;/; s/\./,/g' "$OUT/plain.csv" >"$OUT/comma.csv"
measure "$OUT/comma-m.cfg" comma.csv 'outer = 1;'
try "';' between fields and decimal commas: the same organs" px --csv "$OUT/comma-m.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
px --csv "$OUT/plain-m.cfg" >"$OUT/plain.out"
assert "as the plain file's" 'cmp -s "$OUT/plain.out" "$OUT/stdout"'
end

# --- The points file is an input. ---
cp "$OUT/plain.csv" "$OUT/keep.csv"
measure "$OUT/keep-m.cfg" keep.csv
try "-o naming the points file is a usage error, the file untouched" px --csv -o "$OUT/keep.csv" "$OUT/keep-m.cfg"
refused "would replace .*keep.csv, the points file"
assert "unchanged" 'cmp -s "$OUT/keep.csv" "$OUT/plain.csv"'
end
ln -s keep.csv "$OUT/link.csv"
try "-o naming it by a link is refused too" px --svg -o "$OUT/link.csv" "$OUT/keep-m.cfg"
refused "the points file (the same file by another name)"
assert "unchanged" 'cmp -s "$OUT/keep.csv" "$OUT/plain.csv"'
end
try "--cfg -o naming it is refused too" px --cfg -o "$OUT/keep.csv" "$OUT/keep-m.cfg"
refused "the points file"
end

# --- Junk. ---
head -c 100000000 /dev/urandom >"$OUT/junk.csv" 2>/dev/null
measure "$OUT/junk-m.cfg" junk.csv
# In 200 MB of address space; not under ASan, whose shadow needs more,
# nor valgrind (as limits.sh).
vmem=200000
if [ -n "$RUN" ] || ! sh -c 'ulimit -v '$vmem' && exec "$@"' sh "$PHYLLO" --version >/dev/null 2>&1; then
	vmem=
fi
start=$(date +%s)
try "100 MB of junk: refused at its first line, at once${vmem:+, in little memory}" sh -c '[ -z "$1" ] || ulimit -v "$1"; shift; exec "$@"' sh "$vmem" $RUN "$PHYLLO" --csv "$OUT/junk-m.cfg"
assert "exit 1" '[ $rc -eq 1 ]'
assert "FILE:LINE" 'grep -q "junk.csv:[0-9]*: " $OUT/stderr'
assert "in a second or two" '[ $(($(date +%s) - start)) -le 2 ]'
assert "nothing written" '[ ! -s $OUT/stdout ]'
end
rm -f "$OUT/junk.csv"

try "the example's SVG marks the centre it used" px --svg scenes/measured-head.cfg
assert "exit 0" '[ $rc -eq 0 ]'
assert "a centre mark" 'grep -q "<title>centre</title>" $OUT/stdout'
assert "the divergence measured, with its error" 'grep -q "divergence 137.50[0-9]* ± [0-9.]* degrees, measured" $OUT/stdout'
end
