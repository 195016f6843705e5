#!/bin/sh
# site.sh WEB OBJ THREE VERSION NODE - put the web build together in WEB,
# a static folder that any HTTP server serves as it is, offline:
#	phyllo.mjs, phyllo-core.mjs, phyllo.wasm	the module (OBJ holds
#			emscripten's output, as phyllo.mjs and phyllo.wasm)
#	index.html, page.css, *.mjs	the page (src/web/)
#	three/		the files of three.js (npm, at THREE) the page imports
#	scenes/		the example scenes, their parts, organ meshes and
#			measured points, and index.json listing them
#	package.json	the module's npm package (npm pack in WEB)
# index.html's Content-Security-Policy names its import map by hash:
# the hash is worked out here, with NODE.
set -eu
web=$1 obj=$2 three=$3 version=$4 node=$5

rm -rf "$web"
mkdir -p "$web/scenes/parts" "$web/scenes/organs" "$web/scenes/points" \
	"$web/three/build" \
	"$web/three/examples/jsm/loaders" "$web/three/examples/jsm/controls" \
	"$web/three/examples/jsm/utils"

cp "$obj/phyllo.wasm" "$web/phyllo.wasm"
cp "$obj/phyllo.mjs" "$web/phyllo-core.mjs"
for f in src/web/*.mjs src/web/*.css src/web/*.html src/web/*.svg src/web/README.md LICENSE; do
	cp "$f" "$web/"
done

# three.js: the module, and the add-ons the page uses with theirs.
for f in build/three.module.js build/three.core.js \
	examples/jsm/loaders/GLTFLoader.js \
	examples/jsm/controls/OrbitControls.js \
	examples/jsm/utils/BufferGeometryUtils.js \
	examples/jsm/utils/SkeletonUtils.js LICENSE; do
	cp "$three/$f" "$web/three/$f"
done

cp scenes/*.cfg "$web/scenes/"
cp scenes/parts/*.cfg "$web/scenes/parts/"
cp scenes/organs/*.obj scenes/organs/*.mtl "$web/scenes/organs/"
cp scenes/points/*.csv "$web/scenes/points/"

sed "s/@VERSION@/$version/" src/web/package.json >"$web/package.json"

# The list of examples (each with its opening comment, which says what
# it is) and of every file they may read, and index.html with its
# import map's hash.
(cd "$web" && "$node" --input-type=module -e '
import fs from "node:fs";
import crypto from "node:crypto";
const list = d => fs.readdirSync(d).sort().map(f => `${d}/${f}`);
const files = [...list("scenes").filter(f => f.endsWith(".cfg")),
  ...list("scenes/parts"), ...list("scenes/organs"), ...list("scenes/points")];
const examples = list("scenes").filter(f => f.endsWith(".cfg")).map(scene => {
  const lines = fs.readFileSync(scene, "utf8").split("\n");
  const start = lines.findIndex(l => l.startsWith("#"));
  const head = [];
  for (let i = start; i >= 0 && i < lines.length && /^#\s*\S/.test(lines[i]); i++)
    head.push(lines[i].replace(/^#\s*/, ""));
  return { scene, about: head.join(" ") };
});
fs.writeFileSync("scenes/index.json", JSON.stringify({ examples, files }, null, 1) + "\n");
let html = fs.readFileSync("index.html", "utf8");
const map = html.match(/<script type="importmap">([^]*?)<\/script>/)[1];
const hash = crypto.createHash("sha256").update(map).digest("base64");
fs.writeFileSync("index.html", html.replace("@IMPORTMAP_HASH@", `sha256-${hash}`));
')
echo "$web: the page (index.html) and the module (phyllo.mjs); serve it, e.g. node src/viewer/serve.mjs $web"
