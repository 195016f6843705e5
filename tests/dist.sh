#!/bin/sh
# dist.sh - the release make dist wrote in build/dist: its SHA256SUMS
# hold; the source tarball, unpacked in an empty folder, builds with
# ./configure && make and the program it makes runs; the Windows zip
# holds the program, its manuals as HTML, the templates and every
# scene with the meshes and parts it names, and (under wine) runs one
# of its scenes as it lies; each add-on zip holds its program for its
# platform, said in its manifest: statically linked on Linux, Windows'
# own DLLs alone on Windows; the legacy zip has no manifest.
. tests/lib.sh

DIST=build/dist
V=${VERSION:-0}
if [ -z "${CHECK_DIST:-}" ] || [ ! -f "$DIST/SHA256SUMS" ]; then
	skip "the release (make check makes it with make dist where configure finds mingw-w64, wine and mandoc in a git clone; not under a sanitizer or valgrind)"
	exit 0
fi
unzip_to() { python3 -m zipfile -e "$1" "$2"; }

try "SHA256SUMS holds for every file" sh -c 'cd "$0" && sha256sum -c --quiet SHA256SUMS' "$DIST"
assert "exit 0" '[ $rc -eq 0 ]'
assert "six files, each listed" '[ $(ls $DIST | wc -l) -eq 6 ] && [ $(wc -l <$DIST/SHA256SUMS) -eq 5 ]'
end

# The source, as a user gets it: an empty folder, the two commands.
mkdir -p "$OUT/src"
tar -xzf "$DIST/phyllo-export-$V.tar.gz" -C "$OUT/src"
S=$OUT/src/phyllo-export-$V
try "the source tarball unpacks into phyllo-export-$V/ and builds with ./configure && make" \
	sh -c 'cd "$0" && ./configure && make' "$S"
assert "exit 0" '[ $rc -eq 0 ]'
assert "nothing built or generated was packed" '! tar -tzf "$DIST/phyllo-export-$V.tar.gz" | grep -q "/build/\|/tests/out/\|/phyllo-export$"'
assert "the program runs" '"$S/phyllo-export" --info "$S/scenes/sunflower.cfg" | grep -qx "count: 630"'
end

rm -rf "$OUT/win"
unzip_to "$DIST/phyllo-export-$V-windows-x64.zip" "$OUT/win"
Z=$OUT/win/phyllo-export-$V
try "the Windows zip: the program, the manuals as HTML, a README, the templates and the scenes" true
for f in phyllo-export.exe README.txt LICENSE.txt doc/phyllo-export.1.html \
	doc/phyllo-export.5.html templates/pov.tmpl templates/blender.tmpl \
	scenes/sunflower.cfg scenes/sunflower.pov scenes/goatsbeard.cfg; do
	[ -s "$Z/$f" ] || bad="$bad; no $f"
done
assert "README in CR LF, for Notepad, with the version" 'grep -q "^phyllo-export $V for 64-bit Windows$(printf "\r")\$" "$Z/README.txt"'
assert "the manuals are HTML" 'grep -q "<title>PHYLLO-EXPORT(5)</title>" "$Z/doc/phyllo-export.5.html"'
end
# Every file a scene names (meshes, parts) is in the zip beside it.
try "every mesh and part the zip's scenes name is in the zip" true
for cfg in "$Z"/scenes/*.cfg; do
	for f in $(sed -n 's/.*\(mesh\|scene\) = "\([^"]*\)".*/\2/p' "$cfg"); do
		[ -f "$Z/scenes/$f" ] || bad="$bad; $(basename "$cfg") names $f"
	done
done
end
if [ -n "${WINE:-}" ] && [ -n "${WINDOWS_EXE:-}" ]; then
	export WINEPREFIX="$(pwd)/$(dirname "$WINDOWS_EXE")/wine" WINEDEBUG=-all
	# The prefix is made on wine's first run, which says so on stderr:
	# made here if tests/windows.sh (after this script) has not yet.
	"$WINE" cmd /c exit >/dev/null 2>&1
	try "the zip's program runs its sunflower, meshes and all, from the unpacked folder" \
		sh -c 'cd "$0" && "$1" phyllo-export.exe --gltf -o sunflower.glb scenes\\sunflower.cfg' "$Z" "$WINE"
	assert "exit 0, silent" '[ $rc -eq 0 ] && [ ! -s $OUT/stderr ]'
	assert "a glTF with every organ object's mesh" '[ "$(head -c 4 $Z/sunflower.glb)" = glTF ] && [ $(wc -c <$Z/sunflower.glb) -gt 40000 ]'
	end
else
	skip "wine not found: the Windows zip's program run"
fi

for p in linux-x64 windows-x64 legacy; do
	rm -rf "$OUT/$p"
	unzip_to "$DIST/phyllo_import-$V-$p.zip" "$OUT/$p"
	A=$OUT/$p/phyllo_import
	try "the add-on zip for $p: the add-on and its program" true
	assert "__init__.py" '[ -s $A/__init__.py ]'
	case $p in
	linux-x64 | legacy)
		assert "bin/phyllo-export, statically linked" '[ -s $A/bin/phyllo-export ] && ! LC_ALL=C readelf -d $A/bin/phyllo-export 2>/dev/null | grep -q NEEDED'
		;;
	windows-x64)
		dump=$(command -v x86_64-w64-mingw32-objdump || command -v objdump)
		assert "bin/phyllo-export.exe, Windows' own DLLs alone" '[ "$("$dump" -p $A/bin/phyllo-export.exe | sed -n "s/^[[:space:]]*DLL Name: //p" | sort | tr "\n" " ")" = "KERNEL32.dll msvcrt.dll " ]'
		;;
	esac
	if [ $p = legacy ]; then
		assert "no manifest: Blender 3.x reads bl_info" '[ ! -e $A/blender_manifest.toml ]'
	else
		assert "a manifest for $p alone" 'grep -qx "platforms = \[\"$p\"\]" $A/blender_manifest.toml'
	fi
	end
done
