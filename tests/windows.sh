#!/bin/sh
# windows.sh - the Windows program (make windows) on Windows' semantics,
# under wine, held against the native program: every example scene and
# regression case at full precision (organs.c) and in every format, each
# bad case's message and exit status, -o's rules (replaced only when
# whole; never an input by another name, a read-only file, a file
# another program holds open, a device's name), Windows paths (C:\,
# backslashes, parts and meshes found beside their scene), non-ASCII
# names, standard input and a binary standard output, and a POV-Ray
# picture from the .exe's include.  Which of the C library's maths
# functions differ is written to tests/out/windows/libm.txt.
. tests/lib.sh

if [ -z "${WINDOWS_EXE:-}" ] || [ -z "${WINE:-}" ]; then
	skip "the Windows program under wine (apt-get install gcc-mingw-w64-x86-64 dpkg-dev wine, then ./configure)"
	exit 0
fi
if ! command -v python3 >/dev/null; then
	skip "python3 not found: the Windows program's outputs are compared by tests/tools/samenums.py (apt-get install python3)"
	exit 0
fi
W=$(dirname "$WINDOWS_EXE")
# One prefix (made once, some seconds) and one wine server kept while
# the script runs: a run then costs a tenth of a second, not three.
WINEPREFIX="$(pwd)/$W/wine" WINEDEBUG=-all
export WINEPREFIX WINEDEBUG
WINESERVER=${WINE%wine}wineserver
[ -x "$WINESERVER" ] || WINESERVER=wineserver
"$WINE" cmd /c exit >/dev/null 2>&1
"$WINESERVER" -p 2>/dev/null
trap '"$WINESERVER" -k 2>/dev/null' EXIT
# wrun PROGRAM ARGS: a Windows program under wine.  Should wine's own
# server go away under it ("wine client error": the emulator's, not the
# program's; seen once in a loaded machine's hundreds of runs), the run
# is made again, once, on a server started afresh.
wrun() {
	"$WINE" "$@" >"$OUT/wrun.out" 2>"$OUT/wrun.err"
	wrc=$?
	if grep -q '^wine client error' "$OUT/wrun.err"; then
		echo "windows.sh: wine's server went away; again: $*" >>"$OUT/wine-again.log"
		"$WINESERVER" -p 2>/dev/null
		"$WINE" "$@" >"$OUT/wrun.out" 2>"$OUT/wrun.err"
		wrc=$?
	fi
	cat "$OUT/wrun.out"
	cat "$OUT/wrun.err" >&2
	return $wrc
}
wx() { wrun "$WINDOWS_EXE" "$@"; }

# same_out A B: the same output but where the C libraries' maths
# differ in the last bits (organs.c holds those to 1e-12 at full
# precision): tests/tools/samenums.py says how that shows in our 9
# printed digits, --blender's float32 and binary glTF.
same_out() {
	cmp -s "$1" "$2" || python3 tests/tools/samenums.py "$1" "$2"
}

# full_close A B: organs.c outputs, every number within 1e-12 of its
# size (at least 1).
full_close() {
	awk '
	NR == FNR { a[FNR] = $0; na = FNR; next }
	bad { next }
	{
		if ($0 == a[FNR]) next
		n = split(a[FNR], p, " "); m = split($0, q, " ")
		if (n != m) { print "line " FNR " fields"; bad = 1 }
		for (i = 1; !bad && i <= n; i++) {
			if (p[i] == q[i]) continue
			d = p[i] - q[i]; if (d < 0) d = -d
			s = p[i] < 0 ? -p[i] : p[i]; if (s < 1) s = 1
			if (p[i] !~ /^-?[0-9]/ || d > 1e-12 * s) {
				print "line " FNR ": " p[i] " vs " q[i]; bad = 1
			}
		}
	}
	END {
		if (!bad && FNR != na) { print na " lines vs " FNR; bad = 1 }
		exit bad
	}
	' "$1" "$2"
}

try "the program needs Windows' own DLLs alone" true
dump=$(command -v x86_64-w64-mingw32-objdump || command -v objdump)
dlls=$("$dump" -p "$WINDOWS_EXE" 2>/dev/null | sed -n 's/^[[:space:]]*DLL Name: //p' | sort -u | tr '\n' ' ')
assert "KERNEL32.dll msvcrt.dll ($dlls)" '[ "$dlls" = "KERNEL32.dll msvcrt.dll " ]'
end

try "it runs: --version" wx --version
assert "exit 0, the version" '[ $rc -eq 0 ] && grep -qx "phyllo-export ${VERSION:-[0-9.]*}" $OUT/stdout'
end

# Which maths functions of the C libraries differ, on 2000 arguments
# each: mingw-w64's own (sin, cos, exp, pow, atan2, expm1, log1p) and
# msvcrt.dll's (tan, asin, acos, atan, log10, hypot: Microsoft's on
# Windows, wine's own here) against glibc's.
wrun "$W/libm.exe" >"$OUT/libm-windows.txt" 2>&1
"$TESTBIN/libm" "$OUT/libm-windows.txt" >"$OUT/libm.txt" 2>&1
try "the C library's maths: every function within 1 ulp of glibc's ($(grep -c differ $OUT/libm.txt) of $(wc -l <$OUT/libm.txt) differ somewhere, $OUT/libm.txt)" true
assert "compared" '[ $(wc -l <$OUT/libm.txt) -ge 15 ]'
assert "1 ulp at most" '! grep -q "by [2-9][0-9]* ulp\|by 1[0-9][0-9]* ulp" $OUT/libm.txt'
end

# Every good case and example scene: its numbers at full precision,
# then every format.
GOOD=
for cfg in tests/regress/*/*.cfg; do
	[ -f "${cfg%.cfg}.err" ] || GOOD="$GOOD $cfg"
done
GOOD="$GOOD $(ls scenes/*.cfg | tr '\n' ' ')"
mkdir -p "$OUT/cmp"
k=0
for cfg in $GOOD; do
	"$TESTBIN/organs" "$cfg" >"$OUT/organs.n" 2>&1
	wrun "$W/organs.exe" "$cfg" >"$OUT/organs.w" 2>&1
	try "$cfg: every organ the same within 1e-12 at full precision" true
	assert "organs placed" '[ $(wc -l <$OUT/organs.n) -gt 1 ]'
	assert "within 1e-12" 'full_close "$OUT/organs.n" "$OUT/organs.w" >"$OUT/diff"'
	end
	# The outputs are compared at the end, in one Python.
	for fmt in csv info pov blender svg gltf; do
		k=$((k + 1))
		px "--$fmt" "$cfg" >"$OUT/cmp/$k.n" 2>"$OUT/n.err"
		nrc=$?
		try "$cfg: --$fmt: the native program's exit status and messages" \
			wx "--$fmt" -o "$OUT/cmp/$k.w" "$cfg"
		assert "exit $nrc" '[ $rc -eq $nrc ]'
		assert "stderr the same" 'diff -u "$OUT/n.err" "$OUT/stderr" >"$OUT/diff"'
		end
		printf '%s: --%s: its output\t%s\t%s\n' "$cfg" $fmt \
			"$OUT/cmp/$k.n" "$OUT/cmp/$k.w" >>"$OUT/cmp/list"
	done
done
python3 tests/tools/samenums.py --each "$OUT/cmp/list"

# Every bad case: the message of its .err, exit 1, nothing written.
for f in tests/regress/*/*.cfg tests/regress/*/*.tmpl; do
	base=${f%.*}
	[ -f "$base.err" ] || continue
	case $f in
	*.tmpl) set -- --template "$f" tests/regress/planar/vogel90.cfg ;;
	*) set -- "$f" ;;
	esac
	printf 'precious\n' >"$OUT/target"
	# shellcheck disable=SC2046
	try "${f#tests/regress/}: the same message, exit 1, nothing written" wx $(err_args "$f") -o "$OUT/target" "$@"
	assert "exit 1" '[ $rc -eq 1 ]'
	assert "message as in $base.err" 'diff -u "$base.err" "$OUT/stderr" >"$OUT/diff"'
	assert "nothing on stdout" '[ ! -s $OUT/stdout ]'
	assert "-o target untouched, no temporary" '[ "$(cat "$OUT/target")" = precious ] && no_tmp "$OUT"'
	end
done

SUN=tests/regress/planar/vogel90.cfg
px --pov "$SUN" >"$OUT/sun-ref.inc"

printf 'precious\n' >"$OUT/sun.inc"
try "-o replaces an existing file with the whole output" wx --pov -o "$OUT/sun.inc" "$SUN"
assert "exit 0, silent" '[ $rc -eq 0 ] && [ ! -s $OUT/stderr ] && [ ! -s $OUT/stdout ]'
assert "the whole include, as the native program's" 'same_out "$OUT/sun-ref.inc" "$OUT/sun.inc" >"$OUT/diff"'
assert "no temporary" 'no_tmp "$OUT"'
end

try "standard input (-) as the native program's" sh -c '"$0" "$1" --pov - <"$2"' "$WINE" "$WINDOWS_EXE" "$SUN"
assert "exit 0" '[ $rc -eq 0 ]'
px --pov - <"$SUN" >"$OUT/stdin-ref.inc"
assert "the same" 'same_out "$OUT/stdin-ref.inc" "$OUT/stdout" >"$OUT/diff"'
end

px --gltf -o "$OUT/sun-ref.glb" scenes/sunflower.cfg
try "--gltf to a redirected standard output: binary, byte for byte" wx --gltf scenes/sunflower.cfg
assert "exit 0" '[ $rc -eq 0 ]'
assert "the native program's, no CR added" 'same_out "$OUT/sun-ref.glb" "$OUT/stdout" >"$OUT/diff"'
end

# -o never names an input: here by another spelling, as Windows allows
# (backslashes, another case; the file index says it is the same file).
cp "$SUN" "$OUT/Scene.cfg"
back=$(printf '%s' "$OUT" | tr / '\\')
try "-o naming the scene by another spelling (${back}\\SCENE.CFG) is refused" wx --pov -o "$back\\SCENE.CFG" "$OUT/Scene.cfg"
assert "exit 2" '[ $rc -eq 2 ]'
assert "says it is the scene" 'grep -q "would replace $OUT/Scene.cfg, the scene file (the same file by another name): give another output file" $OUT/stderr'
assert "the scene intact" 'cmp -s "$SUN" "$OUT/Scene.cfg"'
end

# A read-only file (Windows' attribute: wine's for a file without write
# permission) is not replaced, as by cmd's copy.
printf 'precious\n' >"$OUT/ro.inc"
chmod 444 "$OUT/ro.inc"
try "-o refuses a read-only file" wx --pov -o "$OUT/ro.inc" "$SUN"
assert "exit 3" '[ $rc -eq 3 ]'
assert "says why" 'grep -qx "phyllo-export: $OUT/ro.inc: Permission denied: -o replaces only a file you may write" $OUT/stderr'
assert "the file as it was, no temporary" '[ "$(cat $OUT/ro.inc)" = precious ] && no_tmp "$OUT"'
end
chmod 644 "$OUT/ro.inc"

# A target another program holds open (POV-Ray rendering it, an
# editor): Windows refuses to replace it; the run says so, after a
# second's retries, and leaves it whole.
printf 'precious\n' >"$OUT/held.inc"
rm -f "$OUT/hold.fifo"
mkfifo "$OUT/hold.fifo"
"$WINE" "$W/hold.exe" "$OUT/held.inc" <"$OUT/hold.fifo" >"$OUT/hold.out" 2>&1 &
holder=$!
exec 3>"$OUT/hold.fifo"
i=0
while [ $i -lt 100 ] && ! grep -q held "$OUT/hold.out"; do
	sleep 0.1
	i=$((i + 1))
done
try "-o refuses a file another program has open" wx --pov -o "$OUT/held.inc" "$SUN"
assert "the other program had it open" 'grep -q held "$OUT/hold.out"'
assert "exit 3" '[ $rc -eq 3 ]'
assert "says so" 'grep -qx "phyllo-export: $OUT/held.inc: another program has the file open: close it there and run again" $OUT/stderr'
assert "the file as it was, no temporary" '[ "$(cat $OUT/held.inc)" = precious ] && no_tmp "$OUT"'
end
exec 3>&-
wait $holder
try "once it is closed, the file is replaced" wx --pov -o "$OUT/held.inc" "$SUN"
assert "exit 0, the include" '[ $rc -eq 0 ] && same_out "$OUT/sun-ref.inc" "$OUT/held.inc" >"$OUT/diff"'
end

# Ctrl-C while writing (wine gives the program SIGINT as Windows'
# console event): the temporary removed, the target whole, and the exit
# status Windows' for it, STATUS_CONTROL_C_EXIT (0xC000013A; 58 here).
# A run killed outright leaves its temporary, named for its (Windows')
# process, and the next run to the file removes it.
printf 'model = "planar";\ncount = 5000000;\n' >"$OUT/big.cfg"
printf 'precious\n' >"$OUT/sig.csv"
tmp_of() { ls -A "$OUT" | grep '^sig.csv.phyllo-export-[0-9]*.tmp$'; }
# A shell's background job ignores SIGINT, and wine then makes no
# Ctrl-C of it: env gives the signal back its default.
env --default-signal=INT "$WINE" "$WINDOWS_EXE" --csv -o "$OUT/sig.csv" "$OUT/big.cfg" 2>/dev/null &
pid=$!
i=0
while [ $i -lt 200 ] && [ -z "$(tmp_of)" ]; do
	sleep 0.05
	i=$((i + 1))
done
kill -INT $pid 2>/dev/null
wait $pid
status=$?
try "Ctrl-C while writing removes the temporary and leaves the target" true
assert "the temporary had appeared" '[ $i -lt 200 ]'
assert "ended by it (status $status)" '[ $status -eq 58 ]'
assert "target unchanged, no temporary" '[ "$(cat $OUT/sig.csv)" = precious ] && no_tmp "$OUT"'
end
"$WINE" "$WINDOWS_EXE" --csv -o "$OUT/sig.csv" "$OUT/big.cfg" 2>/dev/null &
pid=$!
i=0
while [ $i -lt 200 ] && [ -z "$(tmp_of)" ]; do
	sleep 0.05
	i=$((i + 1))
done
left=$(tmp_of)
kill -KILL $pid 2>/dev/null
wait $pid 2>/dev/null
try "a run killed outright leaves its temporary, which the next run removes" wx --csv -o "$OUT/sig.csv" "$SUN"
assert "it had been left ($left)" '[ -n "$left" ]'
assert "exit 0, the file written" '[ $rc -eq 0 ] && [ "$(head -c 2 $OUT/sig.csv)" = n, ]'
assert "the temporary removed" '[ ! -e "$OUT/$left" ] && no_tmp "$OUT"'
end

# Devices' names, characters Windows forbids, and a path past MAX_PATH.
for name in NUL con.inc Aux.pov "lpt1 .txt" "a:b.inc" "dot.inc."; do
	try "-o \"$name\" is refused with a clear message" wx --pov -o "$OUT/$name" "$SUN"
	refused "^phyllo-export: -o $OUT/$name: .*: give another name$"
	assert "one line" '[ $(wc -l <$OUT/stderr) -eq 1 ]'
	assert "nothing written" '[ ! -s $OUT/stdout ] && no_tmp "$OUT"'
	end
done
long=$OUT
while [ ${#long} -lt 300 ]; do
	long=$long/abcdefghijklmnopqrstuvwxyz
done
try "-o past Windows' 259 characters says the name is too long" wx --pov -o "$long/x.inc" "$SUN"
assert "exit 3" '[ $rc -eq 3 ]'
assert "says so" 'grep -qx "phyllo-export: $long/x.inc: file name too long" $OUT/stderr'
end

# A scene by a Windows path, C:\...: its parts and meshes found beside
# it through backslashes, its messages in the user's spelling.
C=$WINEPREFIX/drive_c/phyllo-test
rm -rf "$C" && mkdir -p "$C/out"
cp -r scenes/goatsbeard.cfg scenes/sunflower.cfg scenes/parts scenes/organs "$C/"
for s in goatsbeard:pov sunflower:gltf goatsbeard:csv; do
	name=${s%:*} fmt=${s#*:}
	px "--$fmt" -o "$OUT/c-ref.$fmt" "$C/$name.cfg"
	try "C:\\phyllo-test\\$name.cfg --$fmt -o C:\\phyllo-test\\out\\$name.$fmt: as the native program's" \
		wx "--$fmt" -o "C:\\phyllo-test\\out\\$name.$fmt" "C:\\phyllo-test\\$name.cfg"
	assert "exit 0, silent" '[ $rc -eq 0 ] && [ ! -s $OUT/stderr ]'
	if [ $fmt = gltf ]; then
		assert "the same, every mesh and colour read" 'same_out "$OUT/c-ref.$fmt" "$C/out/$name.$fmt" >"$OUT/diff"'
	else
		assert "the same output" 'same_out "$OUT/c-ref.$fmt" "$C/out/$name.$fmt" >"$OUT/diff"'
	fi
	end
done
sed 's|parts/goatsbeard-pappus.cfg|parts/missing.cfg|' scenes/goatsbeard.cfg >"$C/broken.cfg"
try "a bad part of a C:\\ scene: one line, its FILE:LINE in the user's spelling" wx --pov "C:\\phyllo-test\\broken.cfg"
assert "exit 1" '[ $rc -eq 1 ]'
assert "one line naming C:\\phyllo-test\\broken.cfg and the part beside it" '[ $(wc -l <$OUT/stderr) -eq 1 ] && grep -q "^phyllo-export: C:\\\\phyllo-test\\\\broken.cfg:[0-9]*: scene file C:\\\\phyllo-test\\\\parts/missing.cfg of organ object" $OUT/stderr'
end

# Names in UTF-8 on our side, UTF-16 on Windows': letters outside any
# code page, in a folder, a scene, its part and -o.
U="$OUT/φύλλα ひまわり"
mkdir -p "$U/parts"
sed 's|parts/goatsbeard-pappus.cfg|parts/pappus-été.cfg|' scenes/goatsbeard.cfg >"$U/tournesol-été.cfg"
cp scenes/parts/goatsbeard-pappus.cfg "$U/parts/pappus-été.cfg"
px --pov -o "$OUT/u-ref.inc" "$U/tournesol-été.cfg"
try "non-ASCII names: a scene, its part and -o, as the native program's" wx --pov -o "$U/résultat.inc" "$U/tournesol-été.cfg"
assert "exit 0, silent" '[ $rc -eq 0 ] && [ ! -s $OUT/stderr ]'
assert "the same include" 'same_out "$OUT/u-ref.inc" "$U/résultat.inc" >"$OUT/diff"'
end
printf 'count = 0;\n' >"$U/défaut.cfg"
px --csv "$U/défaut.cfg" 2>"$OUT/u-ref.err" >/dev/null
try "non-ASCII names: a message names the file as the native program does" wx --csv "$U/défaut.cfg"
assert "exit 1" '[ $rc -eq 1 ]'
assert "the same bytes" 'cmp "$OUT/u-ref.err" "$OUT/stderr"'
end

# The include the .exe wrote renders as the native one's.
if [ -n "$POVRAY" ]; then
	for name in sunflower coneflower; do
		mkdir -p "$OUT/pov-n" "$OUT/pov-w"
		px --pov -o "$OUT/pov-n/$name.inc" "scenes/$name.cfg"
		wx --pov -o "$OUT/pov-w/$name.inc" "scenes/$name.cfg"
		for d in pov-n pov-w; do
			cp "scenes/$name.pov" "$OUT/$d/"
			(cd "$OUT/$d" && "$POVRAY" -D +A +W240 +H180 +FP +I$name.pov +O$name.ppm >$name.log 2>&1)
		done
		try "POV-Ray renders the .exe's $name include as the native one's" true
		assert "both rendered" '[ -s $OUT/pov-n/$name.ppm ] && [ -s $OUT/pov-w/$name.ppm ]'
		assert "the same picture" '[ "$("$TESTBIN/ppmstat" $OUT/pov-n/$name.ppm diff $OUT/pov-w/$name.ppm | cut -d" " -f1)" = 0 ]'
		end
	done
else
	skip "POV-Ray not found: the .exe's include rendered"
fi
