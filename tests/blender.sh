#!/bin/sh
# blender.sh - the --blender script in the real Blender (blender -b):
# run twice into a .blend with the artist's own Seed object and Bract
# collection, then compare the evaluated instances with the CSV; the
# same for linked duplicates and for an empty file (placeholders only).
. tests/lib.sh

if [ -z "${BLENDER:-}" ]; then
	skip "Blender not found: Blender tests (apt-get install blender)"
	exit 0
fi

# blend ARGS...: Blender without a window, failing on a Python error.
blend() {
	"$BLENDER" -b --python-exit-code 1 "$@" >"$OUT/blender.log" 2>&1
}

blend --factory-startup --python tests/blender/make_blend.py -- "$OUT/artist.blend" ||
	notok "make the test .blend: $(tail -3 "$OUT/blender.log")"

cat >"$OUT/head.cfg" <<'CFG'
name = "Head";
model = "planar";
count = 200;
planar = { scale = 0.1; dome = 0.3; };
organs = (
  { object = "Seed"; to = 99; },
  { object = "Bract"; from = 100; to = 149; tilt = 30; },
  { object = "Petal"; from = 150; roll = "20 * rand(1)"; }
);
CFG
px --csv -o "$OUT/head.csv" "$OUT/head.cfg"
px --blender -o "$OUT/head.py" "$OUT/head.cfg"
px --blender --blender-objects -o "$OUT/head-obj.py" "$OUT/head.cfg"

# Blender depends on python3, so it is here whenever Blender is.
try "the script is Python that names organs only as data" python3 -c '
import ast, sys
tree = ast.parse(open(sys.argv[1]).read())
objs = [n for n in tree.body if isinstance(n, ast.Assign) and n.targets[0].id == "OBJECTS"][0]
assert ast.literal_eval(objs.value) == [("Seed", 100), ("Bract", 50), ("Petal", 50)]
' "$OUT/head.py"
assert "parses, OBJECTS is a literal" '[ $rc -eq 0 ]'
end

try "run twice into the artist's .blend: instances of their Seed and Bract at the CSV frames, one copy" \
	blend "$OUT/artist.blend" --python "$OUT/head.py" --python "$OUT/head.py" \
	--python tests/blender/check.py -- "$OUT/head.csv" Head instances
cp "$OUT/blender.log" "$OUT/instances.log"
assert "Blender exit 0" '[ $rc -eq 0 ]'
assert "all checks" '! grep -q "check: FAILED" $OUT/instances.log && [ $(grep -c "check: ok" $OUT/instances.log) -ge 6 ]'
assert "says what it did" 'grep -q "phyllo-export: built collection .Head.: 200 organs of 3 objects" $OUT/instances.log'
end

try "--blender-objects: linked duplicates sharing the organ's mesh, run twice" \
	blend "$OUT/artist.blend" --python "$OUT/head-obj.py" --python "$OUT/head-obj.py" \
	--python tests/blender/check.py -- "$OUT/head.csv" Head objects
cp "$OUT/blender.log" "$OUT/objects.log"
assert "Blender exit 0" '[ $rc -eq 0 ]'
assert "all checks" '! grep -q "check: FAILED" $OUT/objects.log && [ $(grep -c "check: ok" $OUT/objects.log) -ge 6 ]'
end

# Nothing in the file: every organ gets a placeholder.
sed 's/"Bract"/"Leaf"/' "$OUT/head.cfg" >"$OUT/bare.cfg"
px --csv -o "$OUT/bare.csv" "$OUT/bare.cfg"
px --blender -o "$OUT/bare.py" "$OUT/bare.cfg"
try "in an empty file placeholders stand in for every organ" \
	blend --factory-startup --python "$OUT/bare.py" --python "$OUT/bare.py" \
	--python tests/blender/check.py -- "$OUT/bare.csv" Head instances
cp "$OUT/blender.log" "$OUT/bare.log"
assert "Blender exit 0" '[ $rc -eq 0 ]'
assert "all checks" '! grep -q "check: FAILED" $OUT/bare.log && [ $(grep -c "check: ok" $OUT/bare.log) -ge 5 ]'
end

# Every example scene builds.
for cfg in scenes/*.cfg; do
	px --blender -o "$OUT/scene.py" "$cfg"
	try "scene $cfg builds in Blender" blend --factory-startup --python "$OUT/scene.py"
	assert "Blender exit 0" '[ $rc -eq 0 ]'
	assert "built" 'grep -q "phyllo-export: built collection" $OUT/blender.log'
	end
done
