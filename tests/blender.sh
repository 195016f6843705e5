#!/bin/sh
# blender.sh - the --blender script in every real Blender the suite
# finds (BLENDERS: the system's blender and the Debian roots made by
# tests/blender-root.sh, 3.4 to 5.x).  In each: run twice into a saved
# .blend holding the artist's own Seed object and Bract collection,
# then hold the evaluated instances (object, position, rotation and
# scale) against the CSV; the same for linked duplicates and for an
# empty file (placeholders only); a compound structure of three levels,
# each leaf against --csv --flatten, and its growth over frames read at
# two frames; every example scene in one process;
# a too-old Blender's one-line refusal; the import add-on.
. tests/lib.sh

: "${BLENDERS:=${BLENDER:-}}"
if [ -z "$BLENDERS" ]; then
	skip "Blender not found: Blender tests (apt-get install blender)"
	exit 0
fi

cat >"$OUT/head.cfg" <<'CFG'
name = "Head";
model = "planar";
count = 200;
planar = { scale = 0.1; dome = 0.3; };
organs = (
  { object = "Seed"; to = 99; tilt = 15; roll = "40 * rand(2)"; },
  { object = "Bract"; from = 100; to = 149; tilt = 30; },
  { object = "Petal"; from = 150; roll = "20 * rand(1)"; }
);
CFG
px --csv -o "$OUT/head.csv" "$OUT/head.cfg"
px --blender -o "$OUT/head.py" "$OUT/head.cfg"
px --blender --blender-objects -o "$OUT/head-obj.py" "$OUT/head.cfg"
sed 's/"Bract"/"Leaf"/' "$OUT/head.cfg" >"$OUT/bare.cfg"
px --csv -o "$OUT/bare.csv" "$OUT/bare.cfg"
px --blender -o "$OUT/bare.py" "$OUT/bare.cfg"
for cfg in scenes/*.cfg; do
	px --blender -o "$OUT/scene-$(basename "$cfg" .cfg).py" "$cfg"
done
# A compound of three levels that grows over frames (the artist's own
# Seed in artist.blend is its leaf).
cp -r tests/compound/tree.cfg tests/compound/mid.cfg tests/compound/sub "$OUT/"
px --blender -o "$OUT/tree.py" "$OUT/tree.cfg"
px --csv --flatten -o "$OUT/tree.csv" "$OUT/tree.cfg"
px --blender --frames 3 -o "$OUT/grow.py" "$OUT/tree.cfg"
px --csv --flatten --frames 3 -o "$OUT/grow%d.csv" "$OUT/tree.cfg"
printf 'model = "planar";\ncount = 0;\n' >"$OUT/bad-addon.cfg"
ADDON_ZIP=$TESTBIN/phyllo_import.zip
# Statically linked: it runs inside the roots, whose libconfig differs.
ADDON_PROG=$(pwd)/$TESTBIN/phyllo-export-static
DAISY_COUNT=$(px --info scenes/daisy.cfg | sed -n 's/^count: //p')

# Blender depends on python3, so it is here whenever Blender is.
try "the script is Python that names organs only as data" python3 -c '
import ast, sys
tree = ast.parse(open(sys.argv[1]).read())
objs = [n for n in tree.body if isinstance(n, ast.Assign) and n.targets[0].id == "STRUCTURES"][0]
(frame, name, count, objects, data), = ast.literal_eval(objs.value)
assert (frame, name, count) == (1, "Head", 200), (frame, name, count)
assert objects == [("Seed", 100), ("Bract", 50), ("Petal", 50)], objects
' "$OUT/head.py"
assert "parses, STRUCTURES is a literal" '[ $rc -eq 0 ]'
end

# checked NAME MIN: after a check.py run, keep its log as NAME.log and
# assert Blender succeeded with no check failed and at least MIN passed.
checked() {
	L=$D/$1.log N=$2
	cp "$OUT/blender.log" "$L"
	assert "Blender exit 0" '[ $rc -eq 0 ]'
	assert "all checks" '! grep -q "check: FAILED" $L && [ $(grep -c "check: ok" $L) -ge $N ]'
}

for b in $BLENDERS; do
	use_blender "$b"
	ver=$(bl --version 2>/dev/null | sed -n 's/^Blender \([0-9.]*\).*/\1/p' | head -1)
	V="Blender ${ver:-?}"
	# blend ARGS...: this Blender without a window, failing on a Python error.
	blend() { bl -b --python-exit-code 1 "$@" >"$OUT/blender.log" 2>&1; }
	D=$OUT/$ver
	mkdir -p "$D"
	# addon ARGS...: tests/blender/addon.py with a user folder of its own.
	addon() (
		export BLENDER_USER_RESOURCES="$(pwd)/$D/user" PHYLLO_EXPORT="$ADDON_PROG"
		blend --factory-startup --python tests/blender/addon.py -- "$@"
	)

	try "$V: make the artist's .blend (saved, then reopened)" \
		blend --factory-startup --python tests/blender/make_blend.py -- "$D/artist.blend"
	assert "Blender exit 0" '[ $rc -eq 0 ] && [ -s "$D/artist.blend" ]'
	end

	try "$V: run twice into the artist's .blend: instances of their Seed and Bract at the CSV positions, rotations and scales, one copy" \
		blend "$D/artist.blend" --python "$OUT/head.py" --python "$OUT/head.py" \
		--python tests/blender/check.py -- "$OUT/head.csv" Head instances
	checked instances 6
	assert "says what it did" 'grep -q "phyllo-export: built collection .Head.: 200 organs over 1 frame" $D/instances.log'
	assert "no traceback" '! grep -q Traceback $D/instances.log'
	end

	try "$V: --blender-objects: linked duplicates sharing the organ's mesh, run twice" \
		blend "$D/artist.blend" --python "$OUT/head-obj.py" --python "$OUT/head-obj.py" \
		--python tests/blender/check.py -- "$OUT/head.csv" Head objects
	checked objects 6
	end

	try "$V: in an empty file placeholders stand in for every organ" \
		blend --factory-startup --python "$OUT/bare.py" --python "$OUT/bare.py" \
		--python tests/blender/check.py -- "$OUT/bare.csv" Head instances
	checked bare 5
	end

	try "$V: a compound of three levels: every leaf an instance of the artist's Seed where --flatten puts it, run twice" \
		blend "$D/artist.blend" --python "$OUT/tree.py" --python "$OUT/tree.py" \
		--python tests/blender/check.py -- "$OUT/tree.csv" Tree leaves
	checked tree 6
	assert "8 x 9 x 7 leaves" 'grep -q "check: ok 504 placed organs" $D/tree.log'
	end

	for f in 1 3; do
		try "$V: --frames 3, one script: at frame $f the leaves of frame $f alone, where its --flatten puts them" \
			blend "$D/artist.blend" --python "$OUT/grow.py" --python "$OUT/grow.py" \
			--python tests/blender/check.py -- "$OUT/grow$f.csv" Tree leaves "$f"
		checked grow$f 6
		end
	done

	# Every example scene, in one Blender process.
	blend --factory-startup --python tests/blender/run_all.py -- "$OUT"/scene-*.py
	cp "$OUT/blender.log" "$D/scenes.log"
	for cfg in scenes/*.cfg; do
		s=$OUT/scene-$(basename "$cfg" .cfg).py
		what="$V: scene $cfg builds"
		if grep -q "^run_all: ok $s\$" "$D/scenes.log"; then
			ok "$what"
		else
			notok "$what: $(grep "^run_all: FAILED $s" "$D/scenes.log" || tail -3 "$D/scenes.log")"
		fi
	done

	# The add-on, installed into a user folder of its own.
	if [ -f "$ADDON_ZIP" ] && [ -x "$ADDON_PROG" ]; then
		rm -rf "$D/user"
		try "$V: the import add-on installs, imports, re-imports and reports a bad scene" \
			addon "$(pwd)/$ADDON_ZIP" "$(pwd)/scenes/daisy.cfg" "$DAISY_COUNT" \
			"$(pwd)/$OUT/bad-addon.cfg" "bad-addon.cfg:2:"
		cp "$OUT/blender.log" "$D/addon.log"
		assert "Blender exit 0" '[ $rc -eq 0 ]'
		assert "all checks" '! grep -q "check: FAILED" $D/addon.log && [ $(grep -c "check: ok" $D/addon.log) -eq 6 ]'
		end
	else
		skip "$V: import add-on (make $ADDON_ZIP $TESTBIN/phyllo-export-static)"
	fi

	# As if this Blender were older than the oldest the script knows.
	sed 's/^OLDEST = (3, 4, 0)/OLDEST = (99, 0, 0)/' "$OUT/head.py" >"$D/future.py"
	try "$V: a Blender the script does not know gets one line, not a traceback" \
		blend --factory-startup --python "$D/future.py"
	assert "exit 1" '[ $rc -eq 1 ]'
	assert "one line naming the version and what is missing" 'grep -q "^phyllo-export: this script needs Blender 99.0 or newer .*; this is Blender $ver" $OUT/blender.log'
	assert "no traceback, nothing built" '! grep -q "Traceback\|built collection" $OUT/blender.log'
	end
done
