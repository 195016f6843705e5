#!/bin/sh
# web.sh - the WebAssembly build (make web, in $WEB) against the native
# program: the module in Node.js run by run (tests/web/cli.mjs), the npm
# package installed from its tarball into a scratch project, and the
# page in headless Chromium (tests/web/page.mjs).  make check builds and
# names $WEB where ./configure found emcc; check-asan and check-valgrind
# leave it out, since they would run the same WebAssembly again.
. tests/lib.sh

: "${WEB:=}" "${NODE:=}" "${NPM:=}" "${CHROMIUM:=}"

if [ -z "$WEB" ]; then
	skip "the web build: make check tests it where ./configure found emcc and dpkg-source (apt-get install emscripten dpkg-dev), not under check-asan or check-valgrind"
	exit 0
fi
top=$(pwd)

try "make web's folder: the page, the module, three.js and the examples" true
for f in index.html page.mjs worker.mjs phyllo.mjs phyllo-core.mjs phyllo.wasm \
	package.json three/build/three.module.js \
	three/examples/jsm/loaders/GLTFLoader.js scenes/index.json \
	scenes/sunflower.cfg scenes/organs/seed.obj scenes/parts/goatsbeard-pappus.cfg; do
	assert "$WEB/$f" '[ -s "$WEB/$f" ]'
done
end

# No string reaches the page as markup or code: none of the ways there
# is in its code, and its policy allows no inline script or eval.
try "the page's code makes no markup or code of text: no innerHTML, outerHTML, insertAdjacentHTML, document.write, eval or Function" \
	grep -n -E 'innerHTML|outerHTML|insertAdjacentHTML|document\.write|eval\(|new Function|setAttribute\(.on' \
	src/web/page.mjs src/web/editor.mjs src/web/panel.mjs src/web/view.mjs src/web/runner.mjs src/web/worker.mjs src/web/phyllo.mjs
assert "none" '[ $rc -eq 1 ]'
end
csp=$(sed -n 's/.*http-equiv="Content-Security-Policy" content="\([^"]*\)".*/\1/p' "$WEB/index.html")
try "the page's Content-Security-Policy: no unsafe-inline or unsafe-eval; 'wasm-unsafe-eval' and the import map's hash" true
assert "a policy ($csp)" '[ -n "$csp" ]'
assert "no unsafe-inline, no unsafe-eval" '! echo "$csp" | grep -q "'"'"'unsafe-inline'"'"'\|'"'"'unsafe-eval'"'"'"'
assert "wasm-unsafe-eval" 'echo "$csp" | grep -q "'"'"'wasm-unsafe-eval'"'"'"'
assert "the import map by its hash" 'echo "$csp" | grep -q "'"'"'sha256-[A-Za-z0-9+/=]*'"'"'"'
end

# --- The module in Node.js, run by run against the native program. ---
"$NODE" tests/web/cli.mjs "$PHYLLO" "$WEB" "$OUT" >"$OUT/cli.out" 2>"$OUT/cli.log"
rc=$?
cat "$OUT/cli.out"
[ $rc -eq 0 ] || grep -q '^not ok' "$OUT/cli.out" ||
	notok "the module's tests failed: $(tail -3 "$OUT/cli.log")"

# --- The npm package, from its tarball, in a scratch project. ---
pkg=$OUT/pkg
mkdir -p "$pkg/project"
try "npm pack makes the module's package" sh -c 'cd "$1" && "$2" pack --silent --pack-destination "$3"' sh "$WEB" "${NPM:-npm}" "$top/$pkg"
tgz=$(ls "$pkg"/phyllo-export-*.tgz 2>/dev/null | head -1)
assert "a tarball" '[ $rc -eq 0 ] && [ -s "$tgz" ]'
assert "holding the module, its code, README, LICENSE and package.json, nothing else" \
	'[ "$(tar tzf "$tgz" | sort | tr "\n" " ")" = "package/LICENSE package/README.md package/package.json package/phyllo-core.mjs package/phyllo.mjs package/phyllo.wasm " ]'
end
printf '{ "name": "scratch", "version": "1.0.0", "private": true, "type": "module" }\n' >"$pkg/project/package.json"
printf '%s\n' "import { run } from 'phyllo-export';" \
	"import fs from 'node:fs';" \
	"const r = await run(['--csv', 'sun.cfg'], { 'sun.cfg': fs.readFileSync(process.argv[2]) });" \
	"process.stdout.write(r.stdout);" \
	"process.stderr.write(r.stderr);" \
	"process.exitCode = r.status;" >"$pkg/project/use.mjs"
try "npm installs the tarball into a scratch project, offline" sh -c 'cd "$1" && "$2" install --offline --no-audit --no-fund "$3"' sh "$pkg/project" "${NPM:-npm}" "$top/$tgz"
assert "npm exit 0" '[ $rc -eq 0 ]'
assert "node_modules/phyllo-export/phyllo.wasm" '[ -s "$pkg/project/node_modules/phyllo-export/phyllo.wasm" ]'
end
px --csv scenes/sunflower.cfg >"$pkg/native.csv"
try "the installed package runs in Node.js: import 'phyllo-export', --csv of the sunflower as native --csv" \
	sh -c 'cd "$1" && "$2" use.mjs "$3"' sh "$pkg/project" "$NODE" "$top/scenes/sunflower.cfg"
assert "exit 0, nothing on stderr" '[ $rc -eq 0 ] && [ ! -s "$OUT/stderr" ]'
assert "the rows of native --csv, to 1e-8" 'csv_close "$pkg/native.csv" "$OUT/stdout" >"$OUT/diff"'
end

# --- The page in Chromium. ---
if [ -z "$CHROMIUM" ]; then
	skip "Chromium not found: the page's tests (apt-get install chromium)"
else
	"$NODE" tests/web/page.mjs "$CHROMIUM" "$PHYLLO" "$WEB" "$OUT" >"$OUT/page.out" 2>"$OUT/page.log"
	rc=$?
	cat "$OUT/page.out"
	[ $rc -eq 0 ] || grep -q '^not ok' "$OUT/page.out" ||
		notok "the page's tests failed: $(tail -3 "$OUT/page.log")"
fi
