#!/bin/sh
# limits.sh - every promise of phyllo-export(5)'s LIMITS, tried under a
# memory limit (ulimit -v) and a file size limit (ulimit -f): a clean
# message, the exit status the man page gives, and no file left behind
# or damaged.  Then -o against the run's own inputs, output through a
# link, permissions, and the exit status of each kind of part that
# cannot be read.
. tests/lib.sh

# Address space a run may take, KiB: a frame of 100,000 organs needs
# some 30 MB, the largest scene 1.1 GB.  ASan reserves far more address
# space than it uses, and valgrind counts what exit() leaves when memory
# runs out, so under them the memory limit is left out (the file size
# limit stays).
VMEM=300000
FBLOCKS=20000	# blocks of 512 or 1024 bytes: 10 to 20 MB
if [ -n "$RUN" ] || ! sh -c 'ulimit -v '$VMEM' && exec "$@"' sh "$PHYLLO" --version >/dev/null 2>&1; then
	VMEM=
fi

# limited ARGS: px ARGS under the limits.
limited() {
	# shellcheck disable=SC2086
	sh -c '[ -z "$1" ] || ulimit -v "$1"; ulimit -f "$2"; shift 2; exec "$@"' \
		sh "$VMEM" "$FBLOCKS" $RUN "$PHYLLO" "$@"
}

# untouched: -o's target as it was, and no temporary file beside it.
untouched() {
	assert "-o target untouched" '[ "$(cat "$OUT/target")" = precious ]'
	assert "no temporary file left" 'no_tmp "$OUT"'
}

# refused_under_limits WHAT STATUS PATTERN ARGS: run ARGS -o target
# under the limits; STATUS, PATTERN (grep) on the first line of stderr
# and no more lines than $LINES (1 unless set), nothing written.
refused_under_limits() {
	w=$1 st=$2 pat=$3
	shift 3
	printf 'precious\n' >"$OUT/target"
	try "$w${VMEM:+ (ulimit -v $VMEM)}" limited -o "$OUT/target" "$@"
	assert "exit $st" '[ $rc -eq $st ]'
	assert "says \"$pat\"" 'head -n 1 "$OUT/stderr" | grep -q -- "$pat"'
	assert "${LINES:-1} line(s)" '[ $(wc -l <"$OUT/stderr") -eq ${LINES:-1} ]'
	untouched
	end
}

# --- Every bad scene, refused the same way under the limits. ---
# (Under valgrind regress.sh runs them already, and each run costs a
# second: the loops over every file are left to the plain runs.)  Each
# runs with its group's option, as regress.sh runs it.
[ -n "$RUN" ] && skip "every bad scene under the limits (regress.sh runs them under valgrind)"
for cfg in tests/regress/*/*.cfg; do
	[ -n "$RUN" ] && break
	base=${cfg%.cfg}
	[ -f "$base.err" ] || continue
	printf 'precious\n' >"$OUT/target"
	# shellcheck disable=SC2046
	try "under the limits: bad ${base#tests/regress/}" limited $(err_args "$cfg") -o "$OUT/target" "$cfg"
	assert "exit 1" '[ $rc -eq 1 ]'
	assert "message as in $base.err" 'diff -u "$base.err" "$OUT/stderr" >"$OUT/diff"'
	untouched
	end
done

# --- The limits that need files made here. ---
{
	echo 'model = "planar"; count = 10;'
	yes '# a line of padding, seventeen times a million bytes in all' | head -c 17000000
} >"$OUT/huge.cfg"
refused_under_limits "a scene file over 16 MiB" 1 "huge.cfg: scene file is larger than 16777216 bytes" --csv "$OUT/huge.cfg"

printf 'model = "planar";\ncount = 10;\n# a\0b\n' >"$OUT/nul.cfg"
refused_under_limits "a NUL byte in a scene file" 1 "nul.cfg:3: NUL byte in scene file" --csv "$OUT/nul.cfg"

{
	echo '// @NAME@'
	yes '// a line of padding in a template of more than a megabyte' | head -c 1100000
} >"$OUT/huge.tmpl"
refused_under_limits "a template over 1 MiB" 1 "huge.tmpl: template is larger than 1048576 bytes" \
	--pov --template "$OUT/huge.tmpl" tests/regress/planar/vogel90.cfg

# Organ meshes: 100 MB of junk is refused by its size, unread; so is
# a material library over 4 MiB.
printf 'model = "planar";\ncount = 5;\norgans = ( { object = "A"; mesh = "junk.obj"; } );\n' >"$OUT/junk.cfg"
truncate -s 100M "$OUT/junk.obj"
refused_under_limits "an OBJ file over 64 MiB" 1 "junk.obj: OBJ file is larger than 67108864 bytes" --gltf "$OUT/junk.cfg"
rm -f "$OUT/junk.obj"
printf 'mtllib big.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$OUT/junk.obj"
yes '# a line of padding in a material library of more than 4 MiB' | head -c 4300000 >"$OUT/big.mtl"
refused_under_limits "a material library over 4 MiB" 1 "big.mtl: material library is larger than 4194304 bytes" --gltf "$OUT/junk.cfg"
rm -f "$OUT/junk.obj" "$OUT/big.mtl" "$OUT/junk.cfg"

# A chain of 17 scenes, each placing the next.
mkdir -p "$OUT/chain"
i=1
while [ $i -le 17 ]; do
	printf 'model = "planar";\ncount = 2;\norgans = ( { object = "L%d"; scene = "c%d.cfg"; } );\n' \
		$i $((i + 1)) >"$OUT/chain/c$i.cfg"
	i=$((i + 1))
done
printf 'model = "planar";\ncount = 2;\n' >"$OUT/chain/c18.cfg"
# The error, then a line for each scene that included the next.
LINES=16
refused_under_limits "more than 16 scenes in one chain" 1 "c16.cfg:3: more than 16 scenes in one chain of includes" \
	--csv "$OUT/chain/c1.cfg"
unset LINES

# 257 parts, each its own object (one file may make several).
{
	printf 'model = "planar";\ncount = 257;\norgans = (\n'
	i=0
	while [ $i -lt 257 ]; do
		printf '  { object = "P%d"; from = %d; to = %d; scene = "leaf.cfg"; },\n' $i $i $i
		i=$((i + 1))
	done
	printf '  { object = "Last"; from = 257; }\n);\n'
} >"$OUT/parts.cfg"
printf 'model = "planar";\ncount = 3;\n' >"$OUT/leaf.cfg"
refused_under_limits "more than 256 parts in one structure" 1 "parts.cfg:260: more than 256 parts in one structure" \
	--csv "$OUT/parts.cfg"

refused_under_limits "more than 100000 frames" 2 "give a whole number from 1 to 100000" \
	--csv --frames 100001 tests/regress/planar/vogel90.cfg

# The largest scene the man page allows needs about 1.1 GB: under the
# memory limit it is out of memory, cleanly.
if [ -n "$VMEM" ]; then
	printf 'model = "planar";\ncount = 10000000;\n' >"$OUT/largest.cfg"
	refused_under_limits "10000000 organs out of memory" 3 "^phyllo-export: out of memory$" --csv "$OUT/largest.cfg"
else
	skip "out of memory under ulimit -v (not under ASan or valgrind)"
fi

# --- The output's size, known before writing. ---
printf 'model = "planar";\ncount = "10 + 5*F";\n' >"$OUT/grow.cfg"
refused_under_limits "--blender --frames 100000: refused before writing, with the estimate" 1 \
	"grow.cfg: the output would be about [0-9.]* GiB in 100000 frames, over the limit of 4 GiB: --max-output [0-9]*G allows it" \
	--blender --frames 100000 "$OUT/grow.cfg"

# Three levels of 1,000: a billion leaves.
printf 'model = "planar";\ncount = 1000;\norgans = ( { object = "A"; scene = "a.cfg"; } );\n' >"$OUT/top.cfg"
printf 'model = "planar";\ncount = 1000;\norgans = ( { object = "B"; scene = "b.cfg"; } );\n' >"$OUT/a.cfg"
printf 'model = "planar";\ncount = 1000;\norgans = ( { object = "Leaf"; } );\n' >"$OUT/b.cfg"
refused_under_limits "--csv --flatten of a billion leaves: refused before writing" 1 \
	"top.cfg: the output would be about 1[0-9][0-9] GiB, over the limit of 4 GiB: --max-output 1[0-9]*G allows it" \
	--csv --flatten "$OUT/top.cfg"

try "--info gives each format's size" px --info "$OUT/top.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "leaves: 1e+09" 'grep -qx "leaves: 1e+09" $OUT/stdout'
assert "csv-flatten about 1.2e+11 bytes" 'grep -q "^output-bytes: .*; csv-flatten 1\.[0-9]*e+11;" $OUT/stdout'
end

# The estimate against what is written, every scene and format (the
# SVG's is a bound: it keeps room for every zone's paths and labels).
try "the estimate is within 3% of what is written (svg: at least it)" true
for cfg in scenes/*.cfg; do
	[ -n "$RUN" ] && break
	px --info "$cfg" >"$OUT/info" 2>/dev/null || continue
	for w in pov blender gltf csv svg csv-flatten; do
		est=$(sed -n "s/^output-bytes:.* $w \([0-9.e+]*\)\(;.*\)*$/\1/p" "$OUT/info")
		[ -n "$est" ] || continue
		case $w in
		csv-flatten) n=$(px --csv --flatten "$cfg" | wc -c) ;;
		# No mesh is a warning: placeholders stand in.
		gltf) n=$(px --gltf "$cfg" 2>/dev/null | wc -c) ;;
		*) n=$(px --$w "$cfg" | wc -c) ;;
		esac
		awk -v e="$est" -v n="$n" -v w="$w" 'BEGIN {
			exit !(w == "svg" ? e >= n : e >= 0.97 * n && e <= 1.03 * n) }' ||
			bad="$bad; $cfg --$w: estimate $est, written $n"
	done
done
end

refused_under_limits "--max-output 100K refuses a bigger output" 1 \
	"over the limit of 100 KiB: --max-output [0-9]*K allows it" \
	--max-output 100K --csv scenes/coneflower.cfg
try "--max-output 0 lifts the limit" px --max-output 0 --csv -o "$OUT/lifted.csv" scenes/coneflower.cfg
assert "exit 0, written" '[ $rc -eq 0 ] && [ -s $OUT/lifted.csv ]'
end
for v in 4X -1 abc 1KB ""; do
	try "--max-output '$v' is a usage error" px --max-output "$v" --csv tests/regress/planar/vogel90.cfg
	refused "give a size in bytes"
	end
done

# An estimate is from the first and last frames: a frame between them
# that is far larger meets the limit while it is written, and the run
# stops there, writing nothing in place.
printf 'model = "planar";\ncount = "F == 2 ? 100000 : 10";\n' >"$OUT/bulge.cfg"
refused_under_limits "the limit holds while writing, whatever the estimate" 1 \
	"the output passed the limit of 1 MiB while being written (it was estimated at [0-9.]* KiB), so it was stopped" \
	--max-output 1M --blender --frames 3 "$OUT/bulge.cfg"

# A file size limit below the output: a write error, not a signal.
printf 'model = "planar";\ncount = 200000;\n' >"$OUT/tall.cfg"
refused_under_limits "a file size limit (ulimit -f) is a clean write error" 3 "target: File too large" \
	--csv "$OUT/tall.cfg"

# --- Memory follows one frame, and the parts, not the leaves. ---
if [ -n "$VMEM" ]; then
	# 200 frames of 10,000 organs held at once took some 220 MB.
	printf 'model = "planar";\ncount = 10000;\nplanar = { scale = "0.01 + 0.01 * f"; };\n' >"$OUT/ten.cfg"
	try "--blender --frames 200 of 10,000 organs in 100 MB (ulimit -v)" \
		sh -c 'ulimit -v 100000; exec "$@"' sh "$PHYLLO" --blender --frames 200 -o /dev/null "$OUT/ten.cfg"
	assert "exit 0" '[ $rc -eq 0 ]'
	end
	# The merged part of a million leaves took 116 MB.
	try "--blender of three levels of 1,000 in 60 MB (ulimit -v)" \
		sh -c 'ulimit -v 60000; exec "$@"' sh "$PHYLLO" --blender -o /dev/null "$OUT/top.cfg"
	assert "exit 0" '[ $rc -eq 0 ]'
	end
	# A million leaves as organs would take 112 MB; glTF walks them.
	printf 'model = "planar";\ncount = 100;\norgans = ( { object = "A"; scene = "a100.cfg"; } );\n' >"$OUT/top100.cfg"
	printf 'model = "planar";\ncount = 100;\norgans = ( { object = "B"; scene = "b100.cfg"; } );\n' >"$OUT/a100.cfg"
	printf 'model = "planar";\ncount = 100;\norgans = ( { object = "Leaf"; } );\n' >"$OUT/b100.cfg"
	try "--gltf of three levels of 100, a million leaves, in 60 MB (ulimit -v)" \
		sh -c 'ulimit -v 60000; exec "$@"' sh "$PHYLLO" --gltf -o "$OUT/million.glb" "$OUT/top100.cfg"
	assert "exit 0" '[ $rc -eq 0 ]'
	assert "40 bytes a leaf and the placeholder" '[ $(wc -c <$OUT/million.glb) -gt 40000000 ] && [ $(wc -c <$OUT/million.glb) -lt 40010000 ]'
	end
	rm -f "$OUT/million.glb"
else
	skip "memory of frames and parts under ulimit -v (not under ASan or valgrind)"
fi

# --- -o never names an input. ---
cp tests/regress/planar/vogel90.cfg "$OUT/my.cfg"
cp "$OUT/my.cfg" "$OUT/my.orig"
mkdir -p "$OUT/dir"
ln -sf my.cfg "$OUT/link.cfg"
ln -f "$OUT/my.cfg" "$OUT/hard.cfg"
for o in "$OUT/my.cfg" "$OUT/dir/../my.cfg" "$OUT/link.cfg" "$OUT/hard.cfg"; do
	try "-o $o, the scene file, is a usage error" px --pov -o "$o" "$OUT/my.cfg"
	refused "would replace $OUT/my.cfg, the scene file"
	assert "the scene is as it was" 'cmp -s $OUT/my.cfg $OUT/my.orig'
	assert "nothing on stdout, no temporary file" '[ ! -s $OUT/stdout ] && no_tmp $OUT'
	end
done
cp tests/regress/compound/tree.cfg tests/regress/compound/mid.cfg "$OUT/"
cp -r tests/regress/compound/sub "$OUT/"
cp "$OUT/mid.cfg" "$OUT/mid.orig"
try "-o naming a part's scene is a usage error" px --pov -o "$OUT/mid.cfg" "$OUT/tree.cfg"
refused "would replace .*mid.cfg, the scene of organ object"
assert "the part is as it was" 'cmp -s $OUT/mid.cfg $OUT/mid.orig'
end
cp templates/pov.tmpl "$OUT/my.tmpl"
try "-o naming the template in use is a usage error" px --pov --template "$OUT/my.tmpl" -o "$OUT/my.tmpl" tests/regress/planar/vogel90.cfg
refused "would replace $OUT/my.tmpl, the template in use"
assert "the template is as it was" 'cmp -s $OUT/my.tmpl templates/pov.tmpl'
end
cp "$OUT/my.cfg" "$OUT/s2.cfg"
try "--frames: -o whose frame 2 is the scene is a usage error" px --pov --frames 3 -o "$OUT/s%d.cfg" "$OUT/s2.cfg"
refused "would replace $OUT/s2.cfg, the scene file"
assert "no frame written" '[ ! -e $OUT/s1.cfg ] && [ ! -e $OUT/s3.cfg ]'
end

# Every input of a run, tried as -o by every writer: the scene, a part's
# scene, the template in use, an organ mesh and its material library,
# and the templates the program ships (installed, and the source files
# of this build's built-in ones, which make would embed next time).
mkdir -p "$OUT/all/parts"
cp tests/gltf/arrow.obj tests/gltf/arrow.mtl "$OUT/all/"
cp templates/pov.tmpl "$OUT/all/my.tmpl"
printf 'model = "planar";\ncount = 4;\norgans = ( { object = "Leaf"; mesh = "../arrow.obj"; } );\n' >"$OUT/all/parts/bud.cfg"
printf 'model = "planar";\ncount = 6;\norgans = ( { object = "Arrow"; to = 2; mesh = "arrow.obj"; },\n  { object = "Tuft"; from = 3; scene = "parts/bud.cfg"; } );\n' >"$OUT/all/all.cfg"
(cd "$OUT/all" && sha256sum all.cfg parts/bud.cfg arrow.obj arrow.mtl my.tmpl) >"$OUT/all.sums"
(sha256sum templates/*.tmpl) >"$OUT/templates.sums"
# Should the protection fail, the tree's templates are put back.
mkdir -p "$OUT/templates.orig" && cp templates/*.tmpl "$OUT/templates.orig/"
# (Under valgrind, two writers: the check is one and the same code.)
writers="pov blender gltf csv svg info settings cfg"
[ -n "$RUN" ] && writers="pov csv"
for w in $writers; do
	tmpl=
	[ $w = pov ] && tmpl="--template $OUT/all/my.tmpl"
	for f in all.cfg parts/bud.cfg arrow.obj arrow.mtl ${tmpl:+my.tmpl} ../../../../templates/$w.tmpl; do
		[ -e "$OUT/all/$f" ] || continue
		# shellcheck disable=SC2086
		try "--$w -o $f, an input of the run, is a usage error" px --$w $tmpl -o "$OUT/all/$f" "$OUT/all/all.cfg"
		refused "would replace"
		assert "every input as it was" '(cd $OUT/all && sha256sum -c --quiet ../all.sums) && sha256sum -c --quiet $OUT/templates.sums'
		end
	done
done
try "-o refuses the source tree's templates/pov.tmpl, which make embeds" px --csv -o templates/pov.tmpl "$OUT/all/all.cfg"
refused "would replace .*templates/pov.tmpl, a template phyllo-export is built from"
end
sha256sum -c --quiet "$OUT/templates.sums" >/dev/null 2>&1 ||
	cp "$OUT/templates.orig/"*.tmpl templates/

# -o through a link writes the link's target; an existing file keeps
# its permissions.
printf 'old\n' >"$OUT/real.inc"
chmod 640 "$OUT/real.inc"
ln -sf real.inc "$OUT/out.inc"
try "-o through a symbolic link replaces its target, keeping its mode" px --pov -o "$OUT/out.inc" tests/regress/planar/vogel90.cfg
assert "exit 0" '[ $rc -eq 0 ]'
assert "still a link" '[ -L $OUT/out.inc ]'
assert "the target written" 'grep -q "^#declare Vogel90 = union" $OUT/real.inc'
assert "mode 640 kept" '[ "$(stat -c %a $OUT/real.inc)" = 640 ]'
end
ln -sf nowhere.inc "$OUT/dangling.inc"
try "-o through a dangling link makes its target" px --pov -o "$OUT/dangling.inc" tests/regress/planar/vogel90.cfg
assert "exit 0, link kept, target made" '[ $rc -eq 0 ] && [ -L $OUT/dangling.inc ] && [ -s $OUT/nowhere.inc ]'
end

# --- Exit status: a part that cannot be read is the scene's error. ---
mkdir -p "$OUT/parts/dirpart"
printf 'model = "planar";\ncount = 3;\n' >"$OUT/parts/ok.cfg"
cp "$OUT/parts/ok.cfg" "$OUT/parts/locked.cfg"
chmod 000 "$OUT/parts/locked.cfg"
mkfifo "$OUT/parts/fifo.cfg"
printf 'model = "planar";\ncount = 3;\norgans = ( { object = "C"; scene = "cycle.cfg"; } );\n' >"$OUT/parts/cycle.cfg"
# As root every file is readable: run that case as nobody.
as_user=
if [ "$(id -u)" = 0 ] && command -v setpriv >/dev/null; then
	chmod o+rx "$OUT" "$OUT/parts"
	as_user="setpriv --reuid=nobody --regid=nogroup --clear-groups"
fi
for part in missing.cfg:"No such file or directory" dirpart:"Is a directory" \
    locked.cfg:"Permission denied" fifo.cfg:"not a regular file" \
    cycle.cfg:"scenes include each other"; do
	name=${part%%:*}
	why=${part#*:}
	printf 'model = "planar";\ncount = 3;\norgans = ( { object = "P"; scene = "%s"; } );\n' "$name" >"$OUT/parts/top.cfg"
	chmod o+r "$OUT/parts/top.cfg" "$OUT/parts/cycle.cfg"
	if [ "$name" = locked.cfg ] && [ "$(id -u)" = 0 ] && [ -z "$as_user" ]; then
		skip "an unreadable part (root reads everything; no setpriv)"
		continue
	fi
	# shellcheck disable=SC2086
	try "a part scene $name: exit 1, at the line naming it" timeout 10 $as_user "$PHYLLO" --csv "$OUT/parts/top.cfg"
	assert "exit 1" '[ $rc -eq 1 ]'
	assert "says \"$why\"" 'grep -q "top.cfg:3.*$why" $OUT/stderr || grep -q "$why" $OUT/stderr'
	assert "nothing on stdout" '[ ! -s $OUT/stdout ]'
	end
done
try "a missing main scene is a system error (exit 3)" px --csv "$OUT/parts/no-such.cfg"
assert "exit 3" '[ $rc -eq 3 ]'
end
try "a main scene that is a directory is a system error (exit 3)" px --csv "$OUT/parts/dirpart"
assert "exit 3" '[ $rc -eq 3 ]'
end
try "a usage error is exit 2" px --csv --frobnicate "$OUT/parts/ok.cfg"
assert "exit 2" '[ $rc -eq 2 ]'
end
