#!/bin/sh
# pov.sh - --pov include files, rendered by the real POV-Ray: the
# placeholders render alone, the scene's own organs replace them, the
# pixels land where the CSV says (not mirrored), the matrices are the
# CSV frames in POV-Ray's axes, and the include has no side effects.
. tests/lib.sh

if [ -z "${POVRAY:-}" ]; then
	skip "POV-Ray not found: rendering tests (apt-get install povray)"
	exit 0
fi
PPMSTAT=$TESTBIN/ppmstat

# render NAME [OPTION...]: $OUT/NAME.pov to $OUT/NAME.ppm, 100x100, in
# $OUT so that its includes are found.
render() {
	name_=$1
	shift
	(cd "$OUT" && "$POVRAY" -D +FP +W100 +H100 -GA "$@" +I"$name_.pov" \
		+O"$name_.ppm") >"$OUT/$name_.log" 2>&1
}

# A camera straight down on the XZ plane, 4 x 4 units: 25 pixels a unit,
# CSV +X to the right, CSV +Y up, the centre at pixel (50, 50).
TOP='#version 3.7;
camera { orthographic location <0, 10, -0.0001> look_at <0, 0, 0> right x*4 up y*4 }
background { rgb 0 }
light_source { <0, 10, 0> color rgb 1 }'
RED='texture { pigment { rgb <1, 0, 0> } finish { emission 1 diffuse 0 ambient 0 } }'

# count PPM R G B: pixels of that colour.
count() { "$PPMSTAT" "$1" "$2" "$3" "$4" 12 | cut -d' ' -f1; }
# same_pixels A B: the pictures agree (their headers hold render dates).
same_pixels() { [ "$(tail -c 30000 "$1" | cksum)" = "$(tail -c 30000 "$2" | cksum)" ]; }
# near A B PERCENT: A within PERCENT of B.
near() { awk -v a="$1" -v b="$2" -v p="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= b * p / 100) }'; }

# Four organs a right angle apart, at (0, 0), (0, 1), (-1.41, 0) and
# (0, -1.73), scale 0.25: discs that do not touch, all in view, of
# 4 pi (0.25 * 25)^2 = 490.9 pixels from above.
printf 'name = "Five";\nmodel = "planar";\ncount = 4;\ndivergence = 90;\norgans = ( { object = "Seed"; scale = 0.25; } );\n' >"$OUT/five.cfg"
px --pov -o "$OUT/five.inc" "$OUT/five.cfg"

printf '%s\n#include "five.inc"\nobject { Five }\n' "$TOP" >"$OUT/alone.pov"
try "the placeholders render alone" render alone
bg=$(count "$OUT/alone.ppm" 0 0 0)
assert "POV-Ray exit 0" '[ $rc -eq 0 ]'
assert "the spheres cover 4 pi 0.25^2 (490.9 px; got $((10000 - bg)))" 'near $((10000 - bg)) 490.9 5'
end

printf '%s\n#declare Seed = sphere { 0, 1 %s }\n#include "five.inc"\nobject { Five }\n' "$TOP" "$RED" >"$OUT/own.pov"
try "the scene's own organ replaces the placeholder" render own
red=$(count "$OUT/own.ppm" 255 0 0)
bg=$(count "$OUT/own.ppm" 0 0 0)
assert "POV-Ray exit 0" '[ $rc -eq 0 ]'
assert "red covers 490.9 px (got $red)" 'near $red 490.9 5'
assert "nothing but red and background" '[ $((red + bg)) -ge 9990 ]'
end

# warnings NAME: parse $OUT/NAME.pov with POV-Ray's messages on (render
# turns them off), its console lines (wrapped at 80) joined again.
warnings() {
	(cd "$OUT" && "$POVRAY" -D +FP +W10 +H10 +I"$1.pov" +O/dev/null) 2>&1 |
		tr '\n' ' ' | sed 's/ Parse Warning: /\n/g' >"$OUT/$1.warnings"
}
try "a placeholder says so where POV-Ray reports: a #warning naming it" warnings alone
assert "the scene without Seed: its warning" 'grep -q "^phyllo-export: no Seed declared before  *the #include: a placeholder sphere of radius 1 stands in" $OUT/alone.warnings'
warnings own
assert "the scene with its own Seed: none" '! grep -q "phyllo-export: no Seed" $OUT/own.warnings'
end
# Two parts sharing a leaf object, none declared: a warning each, once.
printf 'model = "planar";\ncount = 3;\norgans = ( { object = "Bud"; } );\n' >"$OUT/wbud.cfg"
printf 'model = "planar";\ncount = 4;\norgans = ( { object = ["A", "B"]; scene = ["wbud.cfg", "wb2.cfg"]; } );\n' >"$OUT/wtop.cfg"
printf 'model = "planar";\ncount = 2;\norgans = ( { object = "Bud"; } );\n' >"$OUT/wb2.cfg"
px --pov -o "$OUT/wtop.inc" "$OUT/wtop.cfg"
printf '%s\n#include "wtop.inc"\nobject { Wtop }\n' "$TOP" >"$OUT/wtop.pov"
try "a leaf shared by two parts is warned of once" warnings wtop
assert "one warning for Bud" '[ $(grep -c "^phyllo-export: no Bud declared" $OUT/wtop.warnings) -eq 1 ]'
end

# Organ 0 at (1, 0), organ 1 at (0, 1.5); each a bar from its centre
# outward along u, 0.4 long.  Unmirrored, organ 0's bar covers pixels
# 75-85 of row 50 and organ 1's rows 3-12 of column 50.
printf 'name = "Two";\nmodel = "planar";\ncount = 2;\ndivergence = 90;\nplanar = { inner = 1.0; scale = 0.5; };\norgans = ( { object = "Bar"; scale = 0.4; } );\n' >"$OUT/two.cfg"
px --pov -o "$OUT/two.inc" "$OUT/two.cfg"
printf '%s\n#declare Bar = box { <0, -0.1, -0.1>, <1, 0.1, 0.1> %s }\n#include "two.inc"\nobject { Two }\n' "$TOP" "$RED" >"$OUT/two.pov"
try "organs land where the CSV puts them, facing u, not mirrored" render two
assert "POV-Ray exit 0" '[ $rc -eq 0 ]'
assert "organ 0 at +X: red at (80, 50)" '[ "$($PPMSTAT $OUT/two.ppm at 80 50)" = "255 0 0" ]'
assert "its bar points outward: black at (72, 50)" '[ "$($PPMSTAT $OUT/two.ppm at 72 50)" = "0 0 0" ]'
assert "not mirrored: black at (20, 50)" '[ "$($PPMSTAT $OUT/two.ppm at 20 50)" = "0 0 0" ]'
assert "organ 1 at +Y: red at (50, 7)" '[ "$($PPMSTAT $OUT/two.ppm at 50 7)" = "255 0 0" ]'
assert "not mirrored: black at (50, 93)" '[ "$($PPMSTAT $OUT/two.ppm at 50 93)" = "0 0 0" ]'
end

# The same head included twice, under two names, side by side.
sed 's/"Five"/"FiveB"/' "$OUT/five.cfg" >"$OUT/fiveb.cfg"
px --pov -o "$OUT/fiveb.inc" "$OUT/fiveb.cfg"
printf '%s\n#declare Seed = sphere { 0, 1 %s }\n#include "five.inc"\n#include "fiveb.inc"\nobject { Five scale 0.5 translate -x }\nobject { FiveB scale 0.5 translate x }\n' "$TOP" "$RED" >"$OUT/twice.pov"
try "two includes under two names go in one scene" render twice
red=$(count "$OUT/twice.ppm" 255 0 0)
assert "POV-Ray exit 0" '[ $rc -eq 0 ]'
assert "both show: twice a quarter of 490.9 px (got $red)" 'near $red 245.4 8'
end

# --arrays: the same picture from the scene's own loop.
px --pov --arrays -o "$OUT/fivea.inc" "$OUT/five.cfg"
cat >"$OUT/arrays.pov" <<EOF
$TOP
#declare MySeed = sphere { 0, 1 $RED }
#include "fivea.inc"
#for (I, 0, Five_Count - 1)
  #local U = Five_Frame[I][0];
  #local W = Five_Frame[I][1];
  #local V = Five_Frame[I][2];
  object { MySeed scale Five_Scale[I]
    matrix <U.x, U.y, U.z, W.x, W.y, W.z, V.x, V.y, V.z, 0, 0, 0>
    translate Five_Pos[I] }
#end
EOF
try "--arrays: a #for loop over the arrays draws the same organs" render arrays
red=$(count "$OUT/arrays.ppm" 255 0 0)
assert "POV-Ray exit 0" '[ $rc -eq 0 ]'
assert "same pixels as the union" 'same_pixels $OUT/arrays.ppm $OUT/own.ppm'
assert "object names and indices declared" 'grep -q "Five_Objects = array\[1\]" $OUT/fivea.inc && grep -q "Five_Index = array\[4\]" $OUT/fivea.inc'
end

# The matrices are the CSV frames with y and z swapped, scaled.
px --pov -o "$OUT/sun.inc" scenes/sunflower.cfg
px --csv scenes/sunflower.cfg >"$OUT/sun.csv"
try "each matrix is <u w v>*scale and the position, in POV-Ray's axes" true
sed -n 's/^  object { [A-Za-z0-9_]* matrix <\(.*\)> }$/\1/p' "$OUT/sun.inc" | tr -d ' ' >"$OUT/sun.mat"
assert "one matrix per organ" '[ $(wc -l <$OUT/sun.mat) -eq 630 ]'
assert "numbers agree to 1e-7" 'awk -F, "
	NR == FNR { if (FNR > 1) { for (i = 1; i <= 16; i++) c[FNR - 1, i] = \$i } next }
	{
		s = c[FNR, 15]
		split(\"6 8 7 12 14 13 9 11 10\", col, \" \")
		for (k = 1; k <= 9; k++) want[k] = c[FNR, col[k]] * s
		want[10] = c[FNR, 3]; want[11] = c[FNR, 5]; want[12] = c[FNR, 4]
		for (k = 1; k <= 12; k++) { d = \$k - want[k]; if (d < 0) d = -d; if (d > 1e-7) { print FNR, k, \$k, want[k]; exit 1 } }
	}" $OUT/sun.csv $OUT/sun.mat'
end

try "the include sets no camera, light, background or global settings" true
assert "no such statements" '! grep -Eq "^[[:space:]]*(camera|light_source|background|global_settings|#version|sky_sphere|#include)" $OUT/sun.inc'
assert "declares only NAME, NAME_Count and guarded placeholders" '[ "$(grep -o "#declare [A-Za-z0-9_]*" $OUT/sun.inc | sort -u | tr "\n" " ")" = "#declare Floret #declare PetalA #declare PetalB #declare PetalC #declare PetalD #declare Seed #declare Sunflower #declare Sunflower_Count " ]'
assert "every placeholder is inside #ifndef" '[ $(grep -c "^#ifndef" $OUT/sun.inc) -eq 6 ]'
end

# A scene file whose name is SDL: it only reaches a comment, made safe.
evil="$OUT/x\"} #include \"evil.cfg"
cp "$OUT/five.cfg" "$evil"
px --pov -o "$OUT/evil.inc" "$evil" 2>"$OUT/evil.err"
printf '%s\n#declare Seed = sphere { 0, 1 %s }\n#include "evil.inc"\nobject { Five }\n' "$TOP" "$RED" >"$OUT/evil.pov"
try "a hostile scene file name cannot add SDL" render evil
assert "POV-Ray exit 0" '[ $rc -eq 0 ]'
assert "same picture as without it" 'same_pixels $OUT/evil.ppm $OUT/own.ppm'
assert "the name reaches the comment made safe" 'grep -q "from x____include__evil.cfg\$" $OUT/evil.inc'
end

# A template of the user's: a macro call per organ.
cat >"$OUT/macro.tmpl" <<'EOF'
@@# One macro call per organ; the scene defines Organ().
#declare @NAME@ = union {
@@organs
  Organ(@N@, @T@, @SCALE@, @POS@)
@@end
}
EOF
printf '%s\n#macro Organ(N, T, S, P) sphere { P, S %s } #end\n#include "macro.inc"\nobject { Five }\n' "$TOP" "$RED" >"$OUT/macro.pov"
px --pov --template "$OUT/macro.tmpl" -o "$OUT/macro.inc" "$OUT/five.cfg"
try "--template: a macro call per organ renders the same organs" render macro
red=$(count "$OUT/macro.ppm" 255 0 0)
assert "POV-Ray exit 0" '[ $rc -eq 0 ]'
assert "red covers 490.9 px (got $red)" 'near $red 490.9 5'
end

# The example scenes render (small, quickly).
# One that says "// frames: N" includes the frame_number'th of N includes.
for pov in scenes/*.pov; do
	name=$(basename "$pov" .pov)
	cfg=scenes/$name.cfg
	frames=$(sed -n 's|^// frames: \([0-9]*\)$|\1|p' "$pov")
	cp "$pov" "$OUT/$name.pov"
	if [ -n "$frames" ]; then
		px --pov --frames "$frames" -o "$OUT/$name%03d.inc" "$cfg"
		try "scenes/$name.pov renders its $frames frames" \
			render "$name" +KFI1 +KFF"$frames"
		assert "POV-Ray exit 0" '[ $rc -eq 0 ]'
		for k in $(seq 1 "$frames"); do
			assert "frame $k not just background" '[ -s $OUT/$name$k.ppm ] && [ $(count $OUT/$name$k.ppm 0 0 0) -lt 10000 ]'
		done
		assert "the frames differ" '! same_pixels $OUT/${name}1.ppm $OUT/$name$frames.ppm'
		end
		continue
	fi
	inc=$(sed -n 's/^#include "\(.*\)"$/\1/p' "$pov" | tail -1)
	px --pov -o "$OUT/$inc" "$cfg"
	try "scenes/$name.pov renders" render "$name"
	assert "POV-Ray exit 0" '[ $rc -eq 0 ]'
	assert "not just background" '[ $(count $OUT/$name.ppm 0 0 0) -lt 10000 ]'
	end
done

# Every pose, read back by POV-Ray itself: for one scene of every model
# (a true cylinder's organs point u straight along the axis, a tapering
# one's nearly; a sphere's face every way), where each organ's matrix
# takes the origin and the axes, against
# the CSV in POV-Ray's axes (<x, z, y>): +x to u, +y to w, +z to v,
# times the scale.
for s in scenes/sunflower.cfg:planar tests/regress/cylindrical/cyl813.cfg:cylindrical \
    scenes/pinecone.cfg:cylindrical "scenes/coneflower.cfg --set count=400:collision" \
    scenes/dandelion.cfg:area scenes/transient.cfg:inhibition; do
	model=${s##*:}
	# shellcheck disable=SC2086
	set -- ${s%:*}
	cfg=$1
	shift
	try "POV-Ray reads every organ's matrix as the CSV's frame and scale: $model ($cfg)" \
		px --pov --template tests/pov-frames.tmpl "$@" -o "$OUT/frames.inc" "$cfg"
	px --csv "$@" -o "$OUT/frames.csv" "$cfg"
	printf '#version 3.7;\ncamera { location <0, 5, -5> look_at 0 }\n#include "frames.inc"\n' >"$OUT/frames.pov"
	rm -f "$OUT/frames.txt"
	(cd "$OUT" && "$POVRAY" -D -GA +W1 +H1 +Iframes.pov +O/dev/null) >/dev/null 2>&1
	assert "POV-Ray wrote one line an organ" '[ $(wc -l <$OUT/frames.txt) -eq $(($(wc -l <$OUT/frames.csv) - 1)) ]'
	assert "origin, x, y, z at pos, pos + s u, pos + s w, pos + s v (within 1e-6)" 'awk -F, "
		function abs(x) { return x < 0 ? -x : x }
		function near(a, b) { return abs(a - b) <= 1e-6 * (abs(b) > 1 ? abs(b) : 1) }
		NR == FNR { if (FNR > 1) c[\$1] = \$0; next }
		{
			split(c[\$1], f, \",\"); s = f[15]
			# CSV (x, y, z) is <x, z, y> in POV-Ray.
			p[1] = f[3]; p[2] = f[5]; p[3] = f[4]
			u[1] = f[6]; u[2] = f[8]; u[3] = f[7]
			v[1] = f[9]; v[2] = f[11]; v[3] = f[10]
			w[1] = f[12]; w[2] = f[14]; w[3] = f[13]
			for (k = 1; k <= 3; k++)
				if (!near(\$(1 + k), p[k]) || !near(\$(4 + k), p[k] + s * u[k]) ||
				    !near(\$(7 + k), p[k] + s * w[k]) || !near(\$(10 + k), p[k] + s * v[k])) {
					print \"organ \" \$1 \" axis \" k; exit 1 }
		}" $OUT/frames.csv $OUT/frames.txt'
	end
done
