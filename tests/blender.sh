#!/bin/sh
# blender.sh - the --blender script in every real Blender the suite
# finds (BLENDERS: the system's blender and the Debian roots made by
# tests/tools/blender-root.sh, 3.4 to 5.x).  In each: run twice into a saved
# .blend holding the artist's own Seed object and Bract collection,
# then hold the evaluated instances (object, position, rotation and
# scale) against the CSV; the same for linked duplicates and for an
# empty file (placeholders only); a re-run that keeps the artist's
# edited placeholders; a compound structure of three levels,
# each leaf against --csv --flatten, and its growth over frames read at
# two frames; scripts re-run in one session (frames of two counts, a
# compound, instances and duplicates): nothing orphaned, each re-run
# leaving the .blend as the last did; every example scene in one
# process; a too-old Blender's one-line refusal; the import add-on on
# every example scene (its panel listing every setting, a re-import
# leaving nothing orphaned), on bad scenes (the .blend unchanged), and
# its Phyllotaxis panel.
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
printf 'model = "planar";\ncount = 20;\norgans = ( { object = "Sed"; to = 9; }, { object = "Petal"; from = 10; } );\n' >"$OUT/typo.cfg"
px --blender -o "$OUT/typo.py" "$OUT/typo.cfg"
sed 's/"Bract"/"Leaf"/' "$OUT/head.cfg" >"$OUT/bare.cfg"
px --csv -o "$OUT/bare.csv" "$OUT/bare.cfg"
px --blender -o "$OUT/bare.py" "$OUT/bare.cfg"
for cfg in scenes/*.cfg; do
	px --blender -o "$OUT/scene-$(basename "$cfg" .cfg).py" "$cfg"
done
# A compound of three levels that grows over frames (the artist's own
# Seed in artist.blend is its leaf).
cp -r tests/regress/compound/tree.cfg tests/regress/compound/mid.cfg tests/regress/compound/sub "$OUT/"
px --blender -o "$OUT/tree.py" "$OUT/tree.cfg"
px --csv --flatten -o "$OUT/tree.csv" "$OUT/tree.cfg"
px --blender --frames 3 -o "$OUT/grow.py" "$OUT/tree.cfg"
# The README's growth, re-run in one session with another count of frames.
px --blender --frames 24 -o "$OUT/stages24.py" scenes/stages.cfg
px --blender --frames 4 -o "$OUT/stages4.py" scenes/stages.cfg
# One scene of every model, for the whole frame of every organ: a
# cylinder's organs point u along the axis (Euler's gimbal lock), a
# sphere's face every way.
POSES="scenes/sunflower.cfg:planar tests/regress/cylindrical/cyl813.cfg:cylindrical
scenes/pinecone.cfg:cylindrical scenes/coneflower.cfg:collision
scenes/dandelion.cfg:area scenes/transient.cfg:inhibition"
for s in $POSES; do
	b=$(basename "${s%:*}" .cfg)
	px --csv --set count=300 -o "$OUT/pose-$b.csv" "${s%:*}"
	px --blender --set count=300 -o "$OUT/pose-$b.py" "${s%:*}"
done
px --csv --flatten --frames 3 -o "$OUT/grow%d.csv" "$OUT/tree.cfg"
printf 'model = "planar";\ncount = 0;\n' >"$OUT/bad-addon.cfg"
printf 'model = "planar";\ncount = "100 - 200 * f";\n' >"$OUT/bad-grow.cfg"
# What the add-on imports, each in every Blender: every example scene,
# with 4 frames where it reads f or F (its frames differ), and one with
# a seed wider than Blender's integer fields and numbers as strings.
printf 'model = "planar";\ncount = 30;\nseed = 4000000000L;\nplanar = { scale = "0.1"; };\norgans = ( { object = "Seed"; tilt = "15"; } );\n' >"$OUT/edge.cfg"
IMPORTS="$(pwd)/$OUT/edge.cfg"
for cfg in scenes/*.cfg; do
	b=$(basename "$cfg" .cfg)
	px --csv --flatten --frames 2 -o "$OUT/frames-$b-%d.csv" "$cfg"
	if cmp -s "$OUT/frames-$b-1.csv" "$OUT/frames-$b-2.csv"; then
		IMPORTS="$IMPORTS $(pwd)/$cfg"
	else
		IMPORTS="$IMPORTS $(pwd)/$cfg:4"
	fi
done
# The panel's scene, and --csv of what its changes should build.
cat >"$OUT/panel.cfg" <<'CFG'
# A head for the panel's test: its comments must survive a save.
model = "planar";
count = 200;
planar = { scale = 0.1; dome = 0.2; };
organs = (
  # seeds, then petals
  { object = "Seed"; to = 149; tilt = 15; },
  { object = "Petal"; from = 150; tilt = "20 * rand(1)"; }
);
CFG
px --csv -o "$OUT/base.csv" "$OUT/panel.cfg"
px --csv --set count=300 -o "$OUT/count.csv" "$OUT/panel.cfg"
px --csv --set count=300 --set planar.scale=0.05 -o "$OUT/scale.csv" "$OUT/panel.cfg"
printf 'model = "collision";\ncount = 300;\ncollision = { receptacle = { shape = "hemisphere"; }; radius = 0.08; };\norgans = ( { object = "Seed"; } );\n' >"$OUT/coll.cfg"
px --csv -o "$OUT/coll.csv" "$OUT/coll.cfg"
px --csv --set 'collision.receptacle.shape="cone"' -o "$OUT/cone.csv" "$OUT/coll.cfg"
# An inhibition scene with the Gaussian kernel, which has no exponent:
# the panel's field greyed out until the kernel is the power law's.
printf 'model = "inhibition";\ncount = 60;\ninhibition = { kernel = "gaussian"; growth = 0.1; };\norgans = ( { object = "Seed"; } );\n' >"$OUT/inh.cfg"
px --csv -o "$OUT/inh.csv" "$OUT/inh.cfg"
px --csv --set 'inhibition.kernel="power"' -o "$OUT/inh-power.csv" "$OUT/inh.cfg"
px --csv --set 'inhibition.kernel="power"' --set inhibition.exponent=2 -o "$OUT/inh-exp2.csv" "$OUT/inh.cfg"
# The power law's with its exponent in the file: the Gaussian from the
# menu, and Save, which takes the exponent out (a copy per Blender).
cat >"$OUT/inh-file-exp.cfg" <<'CFG'
# The power law's kernel, its exponent given.
model = "inhibition";
count = 60;
inhibition = {
  kernel = "power";
  # its exponent
  exponent = 3;
  growth = 0.1;
};
organs = ( { object = "Seed"; } );
CFG
# Numbers as typed in the panel.
px --csv --set planar.scale=0.0437 --set divergence=137.36 -o "$OUT/exact.csv" "$OUT/panel.cfg"
# A part's setting changed, as the leaves show it.
px --csv --flatten --set Achene:count=15 -o "$OUT/gb15.csv" scenes/goatsbeard.cfg
cp scenes/stages.cfg "$OUT/stages.cfg"
# The add-on: the zips carrying their program (Blender 4.2 and later
# install the extension for Linux, 3.x the legacy one), and the plain
# one of make install, which finds a phyllo-export on PATH.
ADDON_PLAIN=$TESTBIN/phyllo_import.zip
ADDON_LINUX=$TESTBIN/phyllo_import-${VERSION:-0}-linux-x64.zip
ADDON_LEGACY=$TESTBIN/phyllo_import-${VERSION:-0}-legacy.zip
# A machine with no phyllo-export: this one's PATH without the folders
# holding one, and without any relative folder.
NOPROG_PATH=$(printf '%s\n' "$PATH" | tr : '\n' | while read -r d; do
	case $d in /*) [ -x "$d/phyllo-export" ] || printf '%s:' "$d" ;; esac
done)
NOPROG_PATH=${NOPROG_PATH%:}
# A phyllo-export on PATH for the plain add-on, and a decoy in a scene's
# folder it must not run; the program is the add-on's own (static: it
# runs in the roots, whose libconfig is another soname or none).
mkdir -p "$OUT/bin" "$OUT/decoy"
cp "$TESTBIN/phyllo-export-static" "$OUT/bin/phyllo-export" 2>/dev/null
ADDON_PROG=$(pwd)/$OUT/bin/phyllo-export
printf '#!/bin/sh\ntouch "$(dirname "$0")/ran"\n' >"$OUT/decoy/phyllo-export"
chmod 755 "$OUT/decoy/phyllo-export"
cp scenes/daisy.cfg "$OUT/decoy/"
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

# Python for --python-expr after a 3-frame script: a check line on the
# timeline, which the script sets to the growth's frames.
TIMELINE='import bpy; s = bpy.context.scene
print("check: %s the timeline is the 3 frames of the growth (%d..%d)" % ("ok" if (s.frame_start, s.frame_end) == (1, 3) else "FAILED", s.frame_start, s.frame_end))'

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
	# addon_script NAME ARGS...: tests/blender/NAME, which drives the
	# add-on, with a user folder of its own, on a machine with no
	# phyllo-export (but on $OPATH).
	addon_script() (
		unset PHYLLO_EXPORT
		export BLENDER_USER_RESOURCES="$(pwd)/$D/user" PATH="${OPATH:+$OPATH:}$NOPROG_PATH"
		s=$1
		shift
		blend --factory-startup --python "tests/blender/$s" -- "$@"
	)
	case $ver in
	[0-3].* | 4.[01].*) zip=$ADDON_LEGACY ;;
	*) zip=$ADDON_LINUX ;;
	esac

	try "$V: make the artist's .blend (saved, then reopened)" \
		blend --factory-startup --python tests/blender/make_blend.py -- "$D/artist.blend"
	assert "Blender exit 0" '[ $rc -eq 0 ] && [ -s "$D/artist.blend" ]'
	end

	try "$V: run twice into the artist's .blend: instances of their Seed and Bract at the CSV positions, rotations and scales, one copy" \
		blend "$D/artist.blend" --python "$OUT/head.py" --python "$OUT/head.py" \
		--python tests/blender/check.py -- "$OUT/head.csv" Head instances
	checked instances 6
	assert "says what it did, and that Petal alone is a placeholder" 'grep -q "phyllo-export: built collection .Head.: 200 organs over 1 frame(s) in [0-9.]* s; placeholders for Petal\$" $D/instances.log'
	assert "no traceback" '! grep -q Traceback $D/instances.log'
	end

	try "$V: a placeholder whose name is near one of the .blend's gets a suggestion" \
		blend "$D/artist.blend" --python "$OUT/typo.py"
	assert "Blender exit 0" '[ $rc -eq 0 ]'
	assert "did you mean Seed" 'grep -q "^phyllo-export: no object or collection .Sed. in the .blend (did you mean .Seed.?)\$" $OUT/blender.log'
	assert "none for Petal" '! grep -q "collection .Petal. in the .blend" $OUT/blender.log'
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

	try "$V: a re-run keeps the collection, and placeholders the artist edited or renamed as their organs" \
		blend --factory-startup --python tests/blender/rerun.py -- "$OUT/bare.py" Head
	checked rerun 13
	end

	try "$V: a compound of three levels: every leaf an instance of the artist's Seed where --flatten puts it, run twice" \
		blend "$D/artist.blend" --python "$OUT/tree.py" --python "$OUT/tree.py" \
		--python tests/blender/check.py -- "$OUT/tree.csv" Tree leaves
	checked tree 6
	assert "8 x 9 x 7 leaves" 'grep -q "check: ok 504 placed organs" $D/tree.log'
	end

	for s in $POSES; do
		b=$(basename "${s%:*}" .cfg)
		name=$(px --info "${s%:*}" | sed -n 's/^name: //p')
		try "$V: every organ's whole frame (u, v, w, scale) as the CSV's: ${s#*:} (${s%:*})" \
			blend --factory-startup --python "$OUT/pose-$b.py" \
			--python tests/blender/check.py -- "$OUT/pose-$b.csv" "$name" instances
		checked pose-$b 5
		end
	done

	for f in 1 3; do
		try "$V: --frames 3, one script: at frame $f the leaves of frame $f alone, where its --flatten puts them; the timeline ends at frame 3" \
			blend "$D/artist.blend" --python "$OUT/grow.py" --python "$OUT/grow.py" \
			--python-expr "$TIMELINE" \
			--python tests/blender/check.py -- "$OUT/grow$f.csv" Tree leaves "$f"
		checked grow$f 7
		end
	done

	try "$V: scripts re-run in one session (24 frames, 4, 24 again; a compound's frames; instances, linked duplicates, instances): nothing orphaned, each re-run leaves the .blend as the last run of it did" \
		blend "$D/artist.blend" --python tests/blender/sequence.py -- \
		"$OUT/stages24.py" "$OUT/stages4.py" "$OUT/stages24.py" \
		"$OUT/grow.py" "$OUT/grow.py" \
		"$OUT/head.py" "$OUT/head-obj.py" "$OUT/head.py"
	checked sequence 11
	end

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
	if [ -f "$zip" ] && [ -f "$ADDON_PLAIN" ] && [ -x "$OUT/bin/phyllo-export" ]; then
		rm -rf "$D/user"
		OPATH=
		try "$V: the add-on with its own program ($(basename "$zip")), no phyllo-export on PATH nor PHYLLO_EXPORT: installs, imports, re-imports, and reports a bad scene, and one bad at its last frame, changing nothing" \
			addon_script addon.py "$(pwd)/$zip" "$(pwd)/$OUT/decoy/daisy.cfg" "$DAISY_COUNT" \
			"$(pwd)/$OUT/bad-addon.cfg" "bad-addon.cfg:2:" \
			"$(pwd)/$OUT/bad-grow.cfg" 3 "bad-grow.cfg:2: frame 3 of 3" own
		cp "$OUT/blender.log" "$D/addon.log"
		assert "Blender exit 0" '[ $rc -eq 0 ]'
		assert "all checks" '! grep -q "check: FAILED" $D/addon.log && [ $(grep -c "check: ok" $D/addon.log) -eq 8 ]'
		end
		rm -rf "$D/user"
		# PATH: our folder, then relative ones ("" and . are the
		# current folder, which holds a phyllo-export of its own).
		OPATH="$(pwd)/$OUT/bin::."
		try "$V: the plain add-on (make install's) runs the phyllo-export on PATH" \
			addon_script addon.py "$(pwd)/$ADDON_PLAIN" "$(pwd)/$OUT/decoy/daisy.cfg" "$DAISY_COUNT" \
			"$(pwd)/$OUT/bad-addon.cfg" "bad-addon.cfg:2:" \
			"$(pwd)/$OUT/bad-grow.cfg" 3 "bad-grow.cfg:2: frame 3 of 3" "$ADDON_PROG"
		cp "$OUT/blender.log" "$D/plain.log"
		assert "Blender exit 0" '[ $rc -eq 0 ]'
		assert "all checks" '! grep -q "check: FAILED" $D/plain.log && [ $(grep -c "check: ok" $D/plain.log) -eq 8 ]'
		end
		rm -rf "$D/user" "$OUT/decoy/ran"
		OPATH=".::"
		try "$V: with none on PATH the plain add-on says so, and runs none from the current or the scene's folder" \
			addon_script lookup.py "$(pwd)/$ADDON_PLAIN" "$(pwd)/$OUT/decoy/daisy.cfg" "$(pwd)/$OUT/decoy/ran"
		OPATH=
		cp "$OUT/blender.log" "$D/lookup.log"
		assert "Blender exit 0" '[ $rc -eq 0 ]'
		assert "all checks" '! grep -q "check: FAILED" $D/lookup.log && [ $(grep -c "check: ok" $D/lookup.log) -eq 3 ]'
		end
		rm -rf "$D/user"
		# shellcheck disable=SC2086
		try "$V: the import add-on on every example scene (frames where it reads f): the panel lists every setting of --settings, as the file has it; imported again, nothing orphaned, the .blend as before" \
			addon_script import_all.py "$(pwd)/$zip" "$ADDON_PROG" $IMPORTS
		checked import_all $(( $(echo $IMPORTS | wc -w) * 5 ))
		end
		rm -rf "$D/user" "$D/gb"
		cp "$OUT/panel.cfg" "$OUT/inh-file-exp.cfg" "$D/"
		mkdir -p "$D/gb/parts"
		cp scenes/goatsbeard.cfg "$D/gb/"
		cp scenes/parts/goatsbeard-pappus.cfg "$D/gb/parts/"
		try "$V: the Phyllotaxis panel: count and a model setting changed rebuild as --set says, undo, a bad value and its message wrapped, save to the scene file, numbers as typed, a setting taken out, a part's setting, frames" \
			addon_script panel.py "$(pwd)/$zip" "$(pwd)/$D/panel.cfg" "$(pwd)/$OUT"
		checked panel 54
		end
	else
		skip "$V: import add-on (make $zip $ADDON_PLAIN)"
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
