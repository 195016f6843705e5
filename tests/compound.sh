#!/bin/sh
# compound.sh - organs made of other scenes, and frames: --csv --flatten
# carries every leaf into the world as an independent composition of
# the parts' own CSVs says; parts are declared once, before their use,
# and render in POV-Ray where --flatten puts them; --frames writes one
# file a frame with f and F, or none at all when a frame fails.
. tests/lib.sh

# tests/regress/compound/tree.cfg: three levels, no frame the identity.
T=tests/regress/compound
cp -r "$T/tree.cfg" "$T/mid.cfg" "$T/sub" "$OUT/"
mv "$OUT/tree.cfg" "$OUT/top.cfg"

px --csv -o "$OUT/top.csv" "$OUT/top.cfg"
px --csv -o "$OUT/mid.csv" "$OUT/mid.cfg"
px --csv -o "$OUT/bud.csv" "$OUT/sub/bud.cfg"

try "--csv of a compound lists the organs that place the parts" px --csv "$OUT/top.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "8 organs, each a Mid" '[ $(grep -c ",Mid," $OUT/stdout) -eq 8 ] && [ $(wc -l <$OUT/stdout) -eq 9 ]'
end

# compose TOP MID BUD: every leaf as the three CSVs compose by hand.
compose() {
	python3 - "$@" <<'PY'
import csv, sys
def rows(p):
    return [{k: (v if k == "object" else float(v)) for k, v in r.items()}
            for r in csv.DictReader(open(p))]
def frame(o):
    return ([o["ux"], o["uy"], o["uz"]], [o["vx"], o["vy"], o["vz"]],
            [o["wx"], o["wy"], o["wz"]])
def apply(o, p):
    # o's place: p -> o.pos + o.scale * (p.x u + p.y v + p.z w)
    u, v, w = frame(o)
    return [o[k] + o["scale"] * (p[0] * u[i] + p[1] * v[i] + p[2] * w[i])
            for i, k in enumerate("xyz")]
def turn(o, a):
    u, v, w = frame(o)
    return [a[0] * u[i] + a[1] * v[i] + a[2] * w[i] for i in range(3)]
top, mid, bud = (rows(p) for p in sys.argv[1:4])
print("n,object,x,y,z,ux,uy,uz,vx,vy,vz,wx,wy,wz,scale,radius")
n = 0
for t in top:
    for m in mid:
        for b in bud:
            pos = apply(t, apply(m, [b["x"], b["y"], b["z"]]))
            axes = [turn(t, turn(m, a)) for a in frame(b)]
            k = t["scale"] * m["scale"]
            vals = pos + axes[0] + axes[1] + axes[2] + [k * b["scale"], k * b["radius"]]
            print("%d,%s,%s" % (n, b["object"], ",".join("%.12g" % x for x in vals)))
            n += 1
PY
}

if command -v python3 >/dev/null; then
	compose "$OUT/top.csv" "$OUT/mid.csv" "$OUT/bud.csv" >"$OUT/want.csv"
	try "--csv --flatten: 8 x 9 x 7 leaves where the parts' own CSVs, composed by hand, put them" \
		px --csv --flatten -o "$OUT/flat.csv" "$OUT/top.cfg"
	assert "exit 0" '[ $rc -eq 0 ]'
	assert "504 leaves" '[ $(($(wc -l <$OUT/flat.csv) - 1)) -eq 504 ]'
	assert "positions, frames, scales and radii agree" 'csv_close $OUT/want.csv $OUT/flat.csv 1e-8'
	end
else
	skip "--csv --flatten against a composition by hand (needs python3)"
fi

try "--info names the parts with their counts and counts the leaves" px --info "$OUT/top.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "parts: Mid 9" 'grep -qx "parts: Mid 9" $OUT/stdout'
assert "leaves: 504" 'grep -qx "leaves: 504" $OUT/stdout'
end

try "--flatten of a structure without parts is its --csv" px --csv --flatten scenes/sunflower.cfg
assert "exit 0" '[ $rc -eq 0 ]'
assert "the same bytes" 'px --csv scenes/sunflower.cfg | cmp -s - $OUT/stdout'
end

try "--flatten goes with --csv only" px --pov --flatten "$OUT/top.cfg"
refused "--flatten goes with --csv"
end

# A part used at two levels is declared once, before either use.
cat >"$OUT/twice.cfg" <<'CFG'
name = "Twice";
model = "planar";
count = 6;
organs = ( { object = ["Mid", "Bud"]; scene = ["mid.cfg", "sub/bud.cfg"]; } );
CFG
try "--pov declares each part once, before the structures that use it" px --pov "$OUT/twice.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
line_of() { grep -n "^#declare $1 = union" "$OUT/stdout" | cut -d: -f1; }
assert "Bud declared once" '[ $(grep -c "^#declare Bud = union" $OUT/stdout) -eq 1 ]'
assert "Mid declared once" '[ $(grep -c "^#declare Mid = union" $OUT/stdout) -eq 1 ]'
assert "Bud before Mid before Twice" '[ $(line_of Bud) -lt $(line_of Mid) ] && [ $(line_of Mid) -lt $(line_of Twice) ]'
assert "each part inside #ifndef of its name" 'grep -q "^#ifndef (Bud)$" $OUT/stdout && grep -q "^#ifndef (Mid)$" $OUT/stdout'
end

try "--pov --arrays declares each part's arrays too" px --pov --arrays "$OUT/twice.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "Bud_Pos, Mid_Pos, Twice_Pos" 'grep -q "^#declare Bud_Pos = " $OUT/stdout && grep -q "^#declare Mid_Pos = " $OUT/stdout && grep -q "^#declare Twice_Pos = " $OUT/stdout'
end

# A template from before compound structures still works: it writes the
# main structure, with a warning that parts are placeholders.
printf '@@organs\n@OBJECT@ @X@\n@@end\n' >"$OUT/old.tmpl"
try "a template without @@structures writes the main structure and warns" px --pov --template "$OUT/old.tmpl" "$OUT/top.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "8 lines of Mid" '[ $(grep -c "^Mid " $OUT/stdout) -eq 8 ] && [ $(wc -l <$OUT/stdout) -eq 8 ]'
assert "warns" 'grep -q "warning: the template has no @@structures" $OUT/stderr'
end

# --- POV-Ray: nested instances land where --flatten says. ---
if [ -n "${POVRAY:-}" ] && command -v python3 >/dev/null; then
	# Four Pairs a right angle apart, each a Pair of Seeds 0.5 apart
	# along the organ's u, seen from above 6 x 6 units in 150 pixels.
	cat >"$OUT/pairs.cfg" <<'CFG'
name = "Pairs";
model = "planar";
count = 4;
divergence = 90;
planar = { scale = 1.2; };
organs = ( { object = "Pair"; scene = "pair.cfg"; scale = 1; roll = 45; } );
CFG
	cat >"$OUT/pair.cfg" <<'CFG'
model = "planar";
count = 2;
divergence = 180;
planar = { scale = 0.5; };
organs = ( { object = "Seed"; scale = 0.2; } );
CFG
	px --pov -o "$OUT/pairs.inc" "$OUT/pairs.cfg"
	px --csv --flatten -o "$OUT/pairs.csv" "$OUT/pairs.cfg"
	CAM='#version 3.7;
camera { orthographic location <0, 10, -0.0001> look_at <0, 0, 0> right x*6 up y*6 }
background { rgb 0 }
light_source { <0, 10, 0> color rgb 1 }'
	RED='texture { pigment { rgb <1, 0, 0> } finish { emission 1 diffuse 0 ambient 0 } }'
	printf '%s\n#declare Seed = sphere { 0, 1 %s }\n#include "pairs.inc"\nobject { Pairs }\n' "$CAM" "$RED" >"$OUT/pairs.pov"
	(cd "$OUT" && "$POVRAY" -D +FP +W150 +H150 -GA +Ipairs.pov +Opairs.ppm) >"$OUT/pairs.log" 2>&1
	povrc=$?
	# redat PPM CSV: every leaf's centre is red, and red covers 8 discs.
	redat() {
		python3 - "$1" "$2" <<'PY'
import csv, math, sys
data = open(sys.argv[1], "rb").read()
parts, pos = [], 0
while len(parts) < 4:
    while data[pos:pos + 1].isspace():
        pos += 1
    if data[pos:pos + 1] == b"#":          # a comment to the line's end
        pos = data.index(b"\n", pos)
        continue
    end = pos
    while not data[end:end + 1].isspace():
        end += 1
    parts.append(data[pos:end])
    pos = end
w, h = int(parts[1]), int(parts[2])
px = data[pos + 1:]
def red(x, y):
    r, g, b = px[3 * (y * w + x):3 * (y * w + x) + 3]
    return r > 200 and g < 60 and b < 60
leaves = list(csv.DictReader(open(sys.argv[2])))
bad = [l["n"] for l in leaves
       if not red(int(round(75 + 25 * float(l["x"]))),
                  int(round(75 - 25 * float(l["y"]))))]
area = sum(red(x, y) for x in range(w) for y in range(h))
want = len(leaves) * math.pi * (0.2 * 25) ** 2
print("leaves %d, not red at %s, red %d px of %.0f" % (len(leaves), bad, area, want))
sys.exit(1 if bad or len(leaves) != 8 or abs(area - want) > 0.08 * want else 0)
PY
	}
	try "POV-Ray: parts of parts render at the --flatten positions" redat "$OUT/pairs.ppm" "$OUT/pairs.csv"
	assert "POV-Ray exit 0" '[ $povrc -eq 0 ] && [ -s $OUT/pairs.ppm ]'
	assert "every leaf centre red, 8 discs of red ($(cat $OUT/stdout))" '[ $rc -eq 0 ]'
	end

	# Declared before the include, the artist's Pair wins: one big disc
	# at each of the four parent organs instead of two small ones.
	printf '%s\n#declare Pair = sphere { 0, 0.5 %s }\n#include "pairs.inc"\nobject { Pairs }\n' "$CAM" "$RED" >"$OUT/own.pov"
	(cd "$OUT" && "$POVRAY" -D +FP +W150 +H150 -GA +Iown.pov +Oown.ppm) >"$OUT/own.log" 2>&1
	try "POV-Ray: an object declared before the include replaces the part" \
		"$TESTBIN/ppmstat" "$OUT/own.ppm" 255 0 0 12
	red=$(cut -d' ' -f1 "$OUT/stdout")
	assert "red covers 4 pi (0.5 * 25)^2 = 1963 px (got $red)" 'awk -v a="$red" "BEGIN { exit !(a > 1963 * 0.93 && a < 1963 * 1.07) }"'
	end
else
	skip "POV-Ray: nested instances at the --flatten positions (needs povray, python3)"
fi

# --- Frames. ---
cat >"$OUT/grow.cfg" <<'CFG'
name = "Grow";
model = "planar";
count = "10 + 5 * F";
divergence = "137.5 + 2 * f";
planar = { scale = "0.1 + 0.1 * f"; };
organs = ( { object = "Seed"; scale = "r * (1 + f)"; } );
CFG
try "--frames 3 -o grow%03d.csv writes three files, F and f as the frame says" \
	px --csv --frames 3 -o "$OUT/grow%03d.csv" "$OUT/grow.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "15, 20, 25 organs" '[ $(wc -l <$OUT/grow001.csv) -eq 16 ] && [ $(wc -l <$OUT/grow002.csv) -eq 21 ] && [ $(wc -l <$OUT/grow003.csv) -eq 26 ]'
# Frame 2 is f = 0.5: the same as the numbers written out.
sed -e 's/"10 + 5 \* F"/20/' -e 's/"137.5 + 2 \* f"/138.5/' -e 's/"0.1 + 0.1 \* f"/0.15/' \
	-e 's/"r \* (1 + f)"/"1.5 * r"/' "$OUT/grow.cfg" >"$OUT/grow-mid.cfg"
assert "frame 2 equals the scene with f = 0.5, F = 2 written out" 'px --csv "$OUT/grow-mid.cfg" | cmp -s - $OUT/grow002.csv'
assert "nothing else written" '[ $(ls $OUT | grep -c "^grow0") -eq 3 ] && no_tmp $OUT'
end

try "--info --frames says which frame: F, N and f" px --info --frames 3 -o "$OUT/gi%d.txt" "$OUT/grow.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "frame: F 2; of 3; f 0.5" 'grep -qx "frame: F 2; of 3; f 0.5" $OUT/gi2.txt'
end

try "without --frames, f = 0 and F = 1" px --csv "$OUT/grow.cfg"
assert "exit 0, frame 1 of 3's count" '[ $rc -eq 0 ] && [ $(wc -l <$OUT/stdout) -eq 16 ]'
end

try "--frames -o with %% and a width" px --info --frames 2 -o "$OUT/g%%%4d.txt" "$OUT/grow.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "g%   1.txt and g%   2.txt" '[ -s "$OUT/g%   1.txt" ] && [ -s "$OUT/g%   2.txt" ]'
end

# One frame fails (count 0 at F = 3): no frame is written, and an older
# file of the set is left as it was.
sed 's/"10 + 5 \* F"/"F == 3 ? 0 : 10"/' "$OUT/grow.cfg" >"$OUT/fails.cfg"
echo old >"$OUT/fail001.csv"
try "a frame that fails leaves no frame behind" px --csv --frames 4 -o "$OUT/fail%03d.csv" "$OUT/fails.cfg"
assert "exit 1" '[ $rc -eq 1 ]'
assert "names the scene, the line and the frame" 'grep -qx "phyllo-export: $OUT/fails.cfg:3: frame 3 of 4 (f = 0.666666667): count 0 is out of range: must be between 1 and 10000000" $OUT/stderr'
assert "fail001.csv untouched, no other" '[ "$(cat $OUT/fail001.csv)" = old ] && [ $(ls -A $OUT | grep -c "fail0") -eq 1 ]'
end

# The issue's own case: the last frame of three fails; and an error in
# a part's expression says its frame too.
printf 'model = "planar";\ncount = "200 - 300*f";\n' >"$OUT/failframe.cfg"
try "an error in frame 3 of 3 says so, with f" px --pov --frames 3 -o "$OUT/ff%d.inc" "$OUT/failframe.cfg"
assert "exit 1" '[ $rc -eq 1 ]'
assert "frame 3 of 3 (f = 1)" 'grep -qx "phyllo-export: $OUT/failframe.cfg:2: frame 3 of 3 (f = 1): count -100 is out of range: must be between 1 and 10000000" $OUT/stderr'
assert "one line" '[ $(wc -l <$OUT/stderr) -eq 1 ]'
assert "no file" '[ -z "$(ls -A $OUT | grep "ff[0-9]")" ]'
end
try "without --frames, no frame in the message" px --pov "$OUT/fails.cfg"
assert "exit 0 (frame 1 of 1 is fine)" '[ $rc -eq 0 ]'
end

for o in "" "-o $OUT/plain.csv" "-o $OUT/two%d%d.csv" "-o $OUT/s%s.csv" "-o $OUT/x%-3d.csv"; do
	# shellcheck disable=SC2086
	try "--frames ${o:-to standard output} is a usage error" px --csv --frames 2 $o "$OUT/grow.cfg"
	refused "needs one %d"
	assert "nothing written" '[ ! -s $OUT/stdout ] && [ ! -e $OUT/plain.csv ]'
	end
done
for n in 0 -1 abc 100001 2x; do
	try "--frames $n is a usage error" px --csv --frames "$n" -o "$OUT/n%d.csv" "$OUT/grow.cfg"
	refused "give a whole number from 1 to 100000"
	end
done
try "--frames reads a file, not standard input" \
	sh -c '"$0" --csv --frames 2 -o "$1" - <"$2"' "$PHYLLO" "$OUT/in%d.csv" "$OUT/grow.cfg"
refused "not standard input"
end

try "--blender --frames 3 writes one script to standard output" px --blender --frames 3 "$OUT/grow.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "FRAMES = 3, three structures" 'grep -q "^FRAMES = 3$" $OUT/stdout && [ $(grep -c "^    ([123], \"Grow\", " $OUT/stdout) -eq 3 ]'
end

# One file of every frame is written frame by frame, as the frames are
# made: that takes one @@structures block.
printf '# @NAME@\n@@structures\n# first @NAME@ @COUNT@\n@@end\n@@structures\n# again @NAME@\n@@end\n' >"$OUT/two.tmpl"
try "--blender --frames with a template of two @@structures blocks is an error" \
	px --blender --frames 2 --template "$OUT/two.tmpl" "$OUT/grow.cfg"
assert "exit 1" '[ $rc -eq 1 ]'
assert "names the template" 'grep -qx "phyllo-export: $OUT/two.tmpl: 2 @@structures blocks: with --frames a template has one, written frame by frame" $OUT/stderr'
assert "nothing written" '[ ! -s $OUT/stdout ]'
end
try "... and without --frames it writes both" px --blender --template "$OUT/two.tmpl" "$OUT/grow.cfg"
assert "exit 0, the second block written" '[ $rc -eq 0 ] && grep -q "^# again Grow$" $OUT/stdout'
end

try "--pov --frames: frames of a compound, parts in every frame" px --pov --frames 2 -o "$OUT/tf%d.inc" "$OUT/top.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "Bud and Mid declared in each" '(for k in 1 2; do grep -q "^#declare Bud = union" $OUT/tf$k.inc && grep -q "^#declare Mid = union" $OUT/tf$k.inc || exit 1; done)'
end
