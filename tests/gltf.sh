#!/bin/sh
# gltf.sh - --gltf as a user meets it (standard output, -o, frames,
# warnings, inputs, JSON escaping), then its files in the real clients,
# not a reader of our own: the Khronos glTF-Validator, three.js's
# GLTFLoader in headless Chromium, Blender's importer (4.0 and newer
# read EXT_mesh_gpu_instancing) and gltfpack (0.21 and newer).  The
# Node packages (src/viewer/package.json) are installed by npm where missing.
. tests/lib.sh

: "${NODE:=}" "${NPM:=}" "${CHROMIUM:=}" "${GLTFPACKS:=}"
: "${BLENDERS:=${BLENDER:-}}"

# glb_header FILE: "MAGIC VERSION LENGTH" of a .glb, as numbers.
glb_header() { od -An -tu4 -N12 "$1" | awk '{ print $1, $2, $3 }'; }
GLB_MAGIC=1179937895	# "glTF", little-endian

# --- The command line. ---
try "--gltf to standard output: a .glb whose header says its length" px --gltf scenes/sunflower.cfg
cp "$OUT/stdout" "$OUT/sun-stdout.glb"
assert "exit 0, nothing on stderr (every object has its mesh)" '[ $rc -eq 0 ] && [ ! -s $OUT/stderr ]'
assert "magic glTF, version 2, length the bytes written" '[ "$(glb_header $OUT/stdout)" = "$GLB_MAGIC 2 $(wc -c <$OUT/stdout)" ]'
end

try "-o writes the same bytes" px --gltf -o "$OUT/sun.glb" scenes/sunflower.cfg
assert "exit 0, the bytes of standard output" '[ $rc -eq 0 ] && cmp -s $OUT/sun.glb $OUT/sun-stdout.glb'
end

try "an object with no mesh: a placeholder, and one warning line naming it" px --gltf -o "$OUT/vogel.glb" tests/regress/planar/vogel90.cfg
assert "exit 0, written" '[ $rc -eq 0 ] && [ -s $OUT/vogel.glb ]'
assert "one line" '[ $(wc -l <$OUT/stderr) -eq 1 ]'
assert "names the object at its scene's line" 'grep -q "^phyllo-export: tests/regress/planar/vogel90.cfg:[0-9]*: warning: organ object \"Seed\" has no mesh (organs.mesh names an OBJ file): a placeholder stands in$" $OUT/stderr'
end

# A scene copied without its organs/ folder: --info still measures it
# (only the glTF's size needs the meshes); --gltf needs them.
mkdir -p "$OUT/alone"
cp scenes/sunflower.cfg "$OUT/alone/"
try "--info of a scene whose meshes are missing: a warning, the rest measured" px --info "$OUT/alone/sunflower.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "the parastichies" 'grep -qx "parastichies: 55 89" $OUT/stdout'
assert "the sizes but the glTF's" 'grep "^output-bytes: " $OUT/stdout | grep -q " csv " && ! grep "^output-bytes: " $OUT/stdout | grep -q gltf'
assert "a warning a missing mesh, saying what is skipped" '[ $(grep -c "warning: mesh .*No such file or directory: the glTF.s size is not estimated$" $OUT/stderr) -eq 6 ]'
end
try "--gltf of it is an error at the mesh's line" px --gltf -o "$OUT/alone.glb" "$OUT/alone/sunflower.cfg"
assert "exit 1, nothing written" '[ $rc -eq 1 ] && [ ! -e $OUT/alone.glb ]'
assert "names the mesh" 'grep -q "^phyllo-export: $OUT/alone/sunflower.cfg:[0-9]*: mesh $OUT/alone/organs/seed.obj of organ object \"Seed\": No such file or directory$" $OUT/stderr'
end
try "--info of the scene with its meshes estimates the glTF too" px --info scenes/sunflower.cfg
assert "gltf among the sizes" 'grep "^output-bytes: " $OUT/stdout | grep -q " gltf [0-9]"'
end

printf 'model = "planar";\ncount = "10 + 20 * F";\norgans = ( { object = "Seed"; mesh = "../../../tests/gltf/arrow.obj"; } );\n' >"$OUT/grow.cfg"
try "--frames 3: one .glb a frame, named by -o's %d, each its frame's organs" px --gltf --frames 3 -o "$OUT/grow%d.glb" "$OUT/grow.cfg"
assert "exit 0, nothing on stderr" '[ $rc -eq 0 ] && [ ! -s $OUT/stderr ]'
for F in 1 2 3; do
	assert "frame $F is a .glb" '[ "$(glb_header $OUT/grow$F.glb | cut -d" " -f1)" = $GLB_MAGIC ]'
done
# 20 organs more each frame, 40 bytes an organ.
assert "each frame 800 bytes more than the last" '[ $(($(wc -c <$OUT/grow2.glb) - $(wc -c <$OUT/grow1.glb))) -eq 800 ] &&
	[ $(($(wc -c <$OUT/grow3.glb) - $(wc -c <$OUT/grow2.glb))) -eq 800 ]'
end
try "--frames without %d in -o is a usage error" px --gltf --frames 3 -o "$OUT/grow.glb" "$OUT/grow.cfg"
assert "exit 2" '[ $rc -eq 2 ] && [ ! -e $OUT/grow.glb ]'
end

# The meshes and their libraries are inputs: -o never names them.
mkdir -p "$OUT/in"
cp tests/gltf/turned.cfg tests/gltf/arrow.obj tests/gltf/arrow.mtl "$OUT/in/"
cp "$OUT/in/arrow.obj" "$OUT/in/arrow.orig"
for f in csv gltf; do
	try "--$f -o naming an organ mesh is a usage error" px --$f -o "$OUT/in/arrow.obj" "$OUT/in/turned.cfg"
	refused "would replace $OUT/in/arrow.obj, the mesh of organ object \"Arrow\""
	assert "the mesh is as it was" 'cmp -s $OUT/in/arrow.obj $OUT/in/arrow.orig'
	end
done
try "--gltf -o naming a mesh's material library is a usage error" px --gltf -o "$OUT/in/arrow.mtl" "$OUT/in/turned.cfg"
refused "would replace $OUT/in/arrow.mtl, a material library of an organ mesh"
end

# Bad meshes beyond tests/regress/gltf: bytes a repository does not hold.
printf 'model = "planar";\ncount = 5;\norgans = ( { object = "A"; mesh = "bad.obj"; } );\n' >"$OUT/bad.cfg"
printf 'v 0 0 0\nv 1 0 0\n\001\002\000\003\n' >"$OUT/bad.obj"
try "an OBJ file with a NUL byte: refused at its line, nothing written" px --gltf "$OUT/bad.cfg"
assert "exit 1, nothing on stdout" '[ $rc -eq 1 ] && [ ! -s $OUT/stdout ]'
assert "says where" 'grep -qx "phyllo-export: $OUT/bad.obj:3: NUL byte: an OBJ file is text" $OUT/stderr'
end

# Names reach the JSON escaped: material names are any bytes.
printf 'model = "planar";\ncount = 5;\norgans = ( { object = "Petal"; mesh = "esc.obj"; } );\n' >"$OUT/esc.cfg"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a"b\\c\001d\nf 1 2 3\nusemtl x\377y\nf 1 3 2\nusemtl Bl\303\274te\nf 2 1 3\n' >"$OUT/esc.obj"
try "material names of any bytes are escaped JSON, valid UTF-8" px --gltf -o "$OUT/esc.glb" "$OUT/esc.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
if [ -n "$NODE" ]; then
	"$NODE" tests/gltf/json.mjs "$OUT/esc.glb" >"$OUT/esc.json" 2>"$OUT/esc.err"
	assert "strict JSON.parse and UTF-8 decoding take it" '[ -s $OUT/esc.json ] && [ ! -s $OUT/esc.err ]'
	assert "quote, backslash and control character come back as they were" 'grep -qF "\"name\": \"a\\\"b\\\\c\\u0001d\"" $OUT/esc.json'
	assert "a byte that is no UTF-8 is U+FFFD, UTF-8 passes" 'grep -q "\"name\": \"x$(printf "\357\277\275")y\"" $OUT/esc.json &&
		grep -q "\"name\": \"Bl$(printf "\303\274")te\"" $OUT/esc.json'
fi
end

try "--info's gltf estimate is the size written (to its three digits: 0.5%)" true
for cfg in scenes/sunflower.cfg scenes/goatsbeard.cfg tests/gltf/turned.cfg; do
	est=$(px --info "$cfg" 2>/dev/null | sed -n 's/^output-bytes:.* gltf \([0-9.e+]*\);.*/\1/p')
	n=$(px --gltf "$cfg" 2>/dev/null | wc -c)
	awk -v e="$est" -v n="$n" 'BEGIN { exit !((e - n) ^ 2 <= (n / 200) ^ 2) }' ||
		bad="$bad; $cfg: estimate $est, written $n"
done
end

# --- Files for the clients, and what --csv says of them. ---
# name:scene:csv options:OBJECT=OBJ files whose meshes to hold it to:
# instances drawn, when not one an organ (a mesh of two materials is
# drawn twice):where the three.js picture looks from, when not the
# default (the coneflower as scenes/blender-render.py sees it)
CASES="sunflower:scenes/sunflower.cfg::Seed=scenes/organs/seed.obj,PetalA=scenes/organs/petala.obj::
coneflower:scenes/coneflower.cfg::RayFloret=scenes/organs/rayfloret.obj,ClosedFloret=scenes/organs/closedfloret.obj::0,-5.6,2.55
turned:tests/gltf/turned.cfg::Arrow=tests/gltf/arrow.obj:250:
pinecone:scenes/pinecone.cfg::::0,-5,2
dandelion:scenes/dandelion.cfg::::
tree:tests/regress/compound/tree.cfg:--flatten:::"
for c in $CASES; do
	IFS=: read -r name cfg flat objs draws view <<EOF
$c
EOF
	# shellcheck disable=SC2086
	px --csv $flat -o "$OUT/$name.csv" "$cfg"
	px --gltf -o "$OUT/$name.glb" "$cfg" 2>/dev/null
done
for cfg in scenes/*.cfg; do
	px --gltf -o "$OUT/scene-$(basename "$cfg" .cfg).glb" "$cfg" 2>/dev/null
done

# --- The Node clients: glTF-Validator, and three.js in Chromium. ---
# npm_ready: the packages of src/viewer/package.json, at its versions.
npm_ready() {
	"$NODE" -e '
		const fs = require("fs"), read = f => JSON.parse(fs.readFileSync(f));
		const want = read("src/viewer/package.json").devDependencies;
		for (const [n, v] of Object.entries(want))
			if (read(`src/viewer/node_modules/${n}/package.json`).version !== v)
				process.exit(1);
	' 2>/dev/null
}
if [ -z "$NODE" ]; then
	skip "Node.js not found: glTF-Validator and three.js tests (apt-get install nodejs npm)"
else
	if ! npm_ready; then
		try "npm installs src/viewer/package.json's packages (three, gltf-validator, playwright-core)" \
			"${NPM:-npm}" ci --prefix src/viewer --no-audit --no-fund
		assert "npm exit 0" '[ $rc -eq 0 ]'
		assert "the packages are there" 'npm_ready'
		end
	fi
	if npm_ready; then
		"$NODE" tests/gltf/validate.mjs "$OUT"/scene-*.glb "$OUT/turned.glb" "$OUT/tree.glb" \
			"$OUT/esc.glb" "$OUT/vogel.glb" "$OUT"/grow[123].glb
		if [ -z "$CHROMIUM" ]; then
			skip "Chromium not found: three.js tests (apt-get install chromium)"
		else
			set --
			for c in $CASES; do
				IFS=: read -r name cfg flat objs draws view <<EOF
$c
EOF
				set -- "$@" "$name:$OUT/$name.glb:$OUT/$name.csv:$objs:$view"
			done
			"$NODE" tests/gltf/three.mjs "$CHROMIUM" "$OUT" "$@" \
				>"$OUT/three.out" 2>"$OUT/three.log"
			rc=$?
			cat "$OUT/three.out"
			# A failure it could not even report is one too.
			[ $rc -eq 0 ] || grep -q '^not ok' "$OUT/three.out" ||
				notok "three.js: the test page failed: $(tail -3 "$OUT/three.log")"
		fi
	fi
fi

# --- Blender's glTF importer, 4.0 and newer. ---
for b in $BLENDERS; do
	use_blender "$b"
	ver=$(bl --version 2>/dev/null | sed -n 's/^Blender \([0-9.]*\).*/\1/p' | head -1)
	if [ "${ver%%.*}" -lt 4 ] 2>/dev/null; then
		skip "Blender $ver: its glTF importer predates EXT_mesh_gpu_instancing (4.0)"
		continue
	fi
	set --
	for c in $CASES; do
		IFS=: read -r name cfg flat objs draws view <<EOF
$c
EOF
		set -- "$@" ${1:+--} "$OUT/$name.glb" "$OUT/$name.csv" $(echo "$objs" | tr , ' ')
	done
	try "Blender $ver imports each .glb: every organ an object at the CSV's position with its u, v, w and scale; the OBJ meshes' tips where they belong" \
		bl -b --factory-startup --python-exit-code 1 --python tests/blender/gltf_import.py -- "$@"
	cp "$OUT/stdout" "$OUT/blender-$ver.log"
	assert "Blender exit 0" '[ $rc -eq 0 ]'
	assert "every check" '! grep -q "check: FAILED" $OUT/stdout && [ $(grep -c "check: ok" $OUT/stdout) -eq 15 ]'
	end
done

# --- gltfpack, 0.21 and newer: commands or Debian roots. ---
if [ -z "$GLTFPACKS" ]; then
	skip "no gltfpack 0.21 or newer (Debian 13's, in tests/tools/blender-root.sh's roots): gltfpack tests"
fi
for g in $GLTFPACKS; do
	for c in $CASES; do
		IFS=: read -r name cfg flat objs draws view <<EOF
$c
EOF
		n=${draws:-$(($(wc -l <"$OUT/$name.csv") - 1))}
		rm -f "$OUT/$name-packed.glb"
		if [ -d "$g" ]; then
			try "gltfpack of $g reads $name.glb: $n instances" \
				sh tests/tools/in-root.sh "$g" gltfpack -v -i "$OUT/$name.glb" -o "$OUT/$name-packed.glb"
		else
			try "$g reads $name.glb: $n instances" "$g" -v -i "$OUT/$name.glb" -o "$OUT/$name-packed.glb"
		fi
		assert "exit 0, a file written" '[ $rc -eq 0 ] && [ -s $OUT/$name-packed.glb ]'
		assert "no error or warning" '! grep -qi "error\|warning" $OUT/stdout $OUT/stderr'
		assert "it counts $n instances" 'grep -q "draw calls ($n instances" $OUT/stdout $OUT/stderr'
		end
	done
done
