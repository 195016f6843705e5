#!/bin/sh
# cli.sh - the command line as a user meets it: exit codes, stdout vs
# stderr, standard input, -o replacing files only on success, write
# errors, and broken scene files no golden file can hold.
. tests/lib.sh

SUN=scenes/sunflower.cfg
GOOD=tests/regress/planar/vogel90.cfg

try "--help prints usage on stdout and exits 0" px --help
assert "exit 0" '[ $rc -eq 0 ]'
assert "usage on stdout" 'grep -q "^usage: phyllo-export" $OUT/stdout'
assert "lists --csv and --info" 'grep -q -- "--csv" $OUT/stdout && grep -q -- "--info" $OUT/stdout'
assert "stderr empty" '[ ! -s $OUT/stderr ]'
end

try "--help lists only formats that work" px --help
formats() { awk '/one format:/ { on = 1; getline; next } on && /^$/ { exit } on' "$OUT/stdout" | grep -o -- '^  --[a-z]*' | sed 's/^  --//'; }
assert "lists formats" '[ -n "$(formats)" ]'
for f in $(formats); do
	px "--$f" "$GOOD" >/dev/null 2>&1 || bad="$bad; --$f fails"
done
end

# The manual's model sections are the list to hold --help against.
try "--help names every model the manual describes, and each is accepted" px --help
man_models=$(sed -n 's/^\.Sh THE \([A-Z-]*\) MODEL$/\1/p' man/phyllo-export.5 | tr 'A-Z' 'a-z')
assert "the manual describes models" '[ $(echo $man_models | wc -w) -ge 3 ]'
for m in $man_models; do
	grep -q "^  $m  " "$OUT/stdout" || bad="$bad; --help misses $m"
	printf 'model = "%s";\n' "$m" | px --info - 2>&1 | grep -q 'is not one of' &&
		bad="$bad; model \"$m\" refused"
done
end

try "--version prints the version" px --version
assert "exit 0" '[ $rc -eq 0 ]'
assert "name and number" 'grep -Eq "^phyllo-export [0-9]+\.[0-9]+" $OUT/stdout'
end

try "no format is a usage error" px "$GOOD"
refused "no output format given"
assert "stdout empty" '[ ! -s $OUT/stdout ]'
end

try "two formats are a usage error" px --csv --info "$GOOD"
refused "choose one of --csv and --info"
end

try "an unknown option is a usage error" px --csv --frobnicate "$GOOD"
refused "unknown option --frobnicate"
end
try "a slip of an option's name says which it was meant to be" px --inof "$GOOD"
refused "unknown option --inof (did you mean --info?)"
end
try "and of one with an argument, the argument left out of it" px --csv --tempalte=x.tmpl "$GOOD"
refused "unknown option --tempalte=x.tmpl (did you mean --template?)"
end
try "a shortening of two options names both" px --csv --se count=3 "$GOOD"
refused "option --se is ambiguous: --settings, --set"
end
try "an option without an argument given one says so" px --csv=x "$GOOD"
refused "option --csv takes no argument"
end
try "an unknown short option in a cluster is named, not the word before it" px --csv -qx "$GOOD"
refused "unknown option -q\$"
end

try "-o without a file is a usage error" px --csv "$GOOD" -o
refused "option -o needs an argument"
end

try "--template goes with --pov only" px --csv --template templates/pov.tmpl "$GOOD"
refused "^phyllo-export: --csv has no template"
end

try "--arrays goes with --pov only" px --blender --arrays "$GOOD"
assert "exit 2" '[ $rc -eq 2 ]'
end

try "--blender-objects goes with --blender only" px --pov --blender-objects "$GOOD"
assert "exit 2" '[ $rc -eq 2 ]'
end

try "--template and --arrays exclude each other" px --pov --arrays --template templates/pov.tmpl "$GOOD"
assert "exit 2" '[ $rc -eq 2 ]'
end

try "a missing template is an error naming it" px --pov --template tests/no-such.tmpl "$GOOD"
assert "exit 1" '[ $rc -eq 1 ]'
assert "message" 'grep -qx "phyllo-export: tests/no-such.tmpl: cannot read template: No such file or directory" $OUT/stderr'
assert "stdout empty" '[ ! -s $OUT/stdout ]'
end

printf '// a\0b @NAME@\n' >"$OUT/nul.tmpl"
try "a template with a NUL byte is an error" px --pov --template "$OUT/nul.tmpl" "$GOOD"
assert "exit 1" '[ $rc -eq 1 ]'
assert "message" 'grep -q "NUL byte in template" $OUT/stderr'
end

try "the default template is the installed or built-in templates/pov.tmpl" px --pov "$GOOD"
px --pov --template templates/pov.tmpl "$GOOD" >"$OUT/explicit.inc"
assert "exit 0" '[ $rc -eq 0 ]'
assert "same output" 'cmp -s $OUT/stdout $OUT/explicit.inc'
end

# Scene file names are the one string from outside that reaches the
# POV-Ray and Python outputs (in their header comments).
for weird in 'q"uote' "back\\slash" 'new
line' 'tri"""ple' 'hash#brace}' "$(printf 'lat\351in')"; do
	f="$OUT/$weird.cfg"
	cp "$GOOD" "$f"
	try "a scene file named $(printf %s "$weird" | od -An -c | tr -s ' \n' ' ')stays inert" true
	px --pov -o "$OUT/weird.inc" "$f" && px --blender -o "$OUT/weird.py" "$f"
	rc=$?
	assert "both written" '[ $rc -eq 0 ]'
	if command -v python3 >/dev/null; then
		assert "Python parses it" 'python3 -c "import ast, sys; ast.parse(open(sys.argv[1], \"rb\").read())" $OUT/weird.py'
	fi
	assert "only safe characters reach the headers" '[ -z "$(grep -h " from " $OUT/weird.inc $OUT/weird.py | head -2 | sed "s/.* from //" | tr -d "A-Za-z0-9._ ()-")" ]'
	end
done

try "in a template @@ writes one @, other @s stay" sh -c 'printf "a@@b c@d @e@ @NAME@@@\n" >"$0/at.tmpl" && "$1" --pov --template "$0/at.tmpl" "$2"' "$OUT" "$PHYLLO" "$GOOD"
assert "exit 0" '[ $rc -eq 0 ]'
assert "text" '[ "$(cat $OUT/stdout)" = "a@b c@d @e@ Vogel90@" ]'
end

try "no scene file is a usage error" px --csv
assert "exit 2" '[ $rc -eq 2 ]'
end

try "a missing scene file is a system error" px --csv tests/no-such.cfg
assert "exit 3" '[ $rc -eq 3 ]'
assert "names file and reason" 'grep -q "^phyllo-export: tests/no-such.cfg: No such file" $OUT/stderr'
end

try "- reads the scene from standard input" sh -c '"$0" "$@" < '"$SUN" "$PHYLLO" --csv -
px --csv "$SUN" >"$OUT/from-file" 2>/dev/null
assert "exit 0" '[ $rc -eq 0 ]'
assert "same as from the file" 'cmp -s $OUT/stdout $OUT/from-file'
end

try "errors from standard input name <stdin>" sh -c 'printf "model = \"planar\";\ncount = -1;\n" | "$0" --csv -' "$PHYLLO"
assert "exit 1" '[ $rc -eq 1 ]'
assert "message" 'grep -q "^phyllo-export: <stdin>:2: count -1 is out of range" $OUT/stderr'
end

try "the default name comes from the file name" px --info tests/regress/planar/rings.cfg
assert "name: Rings" 'grep -q "^name: Rings$" $OUT/stdout'
end

cp "$GOOD" "$OUT/cone.cfg"
try "a file named like a POV-Ray keyword gives a capitalised name" px --pov "$OUT/cone.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "declares Cone" 'grep -q "^#declare Cone = union" $OUT/stdout'
end

try "a scene from standard input is named Phyllotaxis" sh -c '"$0" --info - <"$1"' "$PHYLLO" "$GOOD"
assert "name: Phyllotaxis" 'grep -q "^name: Phyllotaxis$" $OUT/stdout'
end

cp "$GOOD" "$OUT/my-head.v2.cfg"
try "a file name that is no identifier still gives one" px --info "$OUT/my-head.v2.cfg"
assert "name: My_head" 'grep -q "^name: My_head$" $OUT/stdout'
end

try "-o writes the file and nothing to stdout" px --csv -o "$OUT/a.csv" "$GOOD"
px --csv "$GOOD" >"$OUT/a-ref.csv"
assert "exit 0" '[ $rc -eq 0 ]'
assert "stdout empty" '[ ! -s $OUT/stdout ]'
assert "file written" 'cmp -s $OUT/a.csv $OUT/a-ref.csv'
assert "mode follows the umask" '[ "$(umask 022; px --csv -o $OUT/m.csv $GOOD; stat -c %a $OUT/m.csv)" = 644 ]'
end

printf 'precious\n' >"$OUT/keep.csv"
try "-o leaves its target alone on a scene error" px --csv -o "$OUT/keep.csv" tests/regress/scene/count-negative.cfg
assert "exit 1" '[ $rc -eq 1 ]'
assert "target unchanged" '[ "$(cat $OUT/keep.csv)" = precious ]'
assert "no temporary file" 'no_tmp $OUT'
end

try "-o into a missing directory says the directory does not exist" px --csv -o "$OUT/no/such/dir/x.csv" "$GOOD"
assert "exit 3" '[ $rc -eq 3 ]'
assert "says so" 'grep -qx "phyllo-export: $OUT/no/such/dir/x.csv: directory $OUT/no/such/dir does not exist" $OUT/stderr'
end
touch "$OUT/plain"
try "-o under a file says it is not a directory" px --csv -o "$OUT/plain/x.csv" "$GOOD"
assert "exit 3" '[ $rc -eq 3 ]'
assert "says so" 'grep -qx "phyllo-export: $OUT/plain/x.csv: $OUT/plain is not a directory" $OUT/stderr'
end

# A read-only target, as an ordinary user: the shell's > and cp refuse
# it, and so must -o's rename, which the directory alone would allow.
# As root, the test runs the program as nobody (setpriv, util-linux).
as_user=
if [ "$(id -u)" -ne 0 ]; then
	as_user=env
elif command -v setpriv >/dev/null; then
	as_user="setpriv --reuid=65534 --regid=65534 --clear-groups"
fi
if [ -n "$as_user" ] && mkdir -p "$OUT/ro" && chmod 777 "$OUT/ro" &&
    $as_user sh -c 'echo precious >"$0/keep.inc" && chmod 444 "$0/keep.inc"' "$OUT/ro" 2>/dev/null &&
    $as_user test -x "$PHYLLO"; then
	try "-o refuses a read-only file, as an ordinary user" $as_user $RUN "$PHYLLO" --pov -o "$OUT/ro/keep.inc" "$GOOD"
	assert "exit 3" '[ $rc -eq 3 ]'
	assert "says why" 'grep -qx "phyllo-export: $OUT/ro/keep.inc: Permission denied: -o replaces only a file you may write" $OUT/stderr'
	assert "the file is as it was, mode 444" '[ "$(cat $OUT/ro/keep.inc)" = precious ] && [ "$(stat -c %a $OUT/ro/keep.inc)" = 444 ]'
	assert "no temporary file" '[ "$(ls -A $OUT/ro)" = keep.inc ]'
	end
	$as_user sh -c 'echo precious >"$0/f2.inc" && chmod 444 "$0/f2.inc"' "$OUT/ro"
	try "--frames: a read-only frame file stops the run before any is written" $as_user $RUN "$PHYLLO" --pov --frames 3 -o "$OUT/ro/f%d.inc" "$GOOD"
	assert "exit 3" '[ $rc -eq 3 ]'
	assert "says which" 'grep -q "^phyllo-export: $OUT/ro/f2.inc: Permission denied" $OUT/stderr'
	assert "nothing written" '[ "$(ls -A $OUT/ro | tr "\n" " ")" = "f2.inc keep.inc " ]'
	end
	ln -s keep.inc "$OUT/ro/link.inc"
	try "-o refuses a read-only file through a link too" $as_user $RUN "$PHYLLO" --pov -o "$OUT/ro/link.inc" "$GOOD"
	assert "exit 3, the file as it was" '[ $rc -eq 3 ] && [ "$(cat $OUT/ro/keep.inc)" = precious ]'
	end
else
	skip "no ordinary user to try a read-only -o as (setpriv)"
fi

try "-o with a %d but no --frames writes the file as named, with a warning" px --csv -o "$OUT/g%d.csv" "$GOOD"
assert "exit 0" '[ $rc -eq 0 ]'
assert "the file as named" '[ -s "$OUT/g%d.csv" ]'
assert "warns" 'grep -qx "phyllo-export: warning: -o $OUT/g%d.csv: a %d in the name is filled in only with --frames; writing the file as named" $OUT/stderr'
end
try "-o with %%d (a % sign) is no pattern: no warning" px --csv -o "$OUT/g%%d.csv" "$GOOD"
assert "exit 0, silent" '[ $rc -eq 0 ] && [ ! -s $OUT/stderr ]'
end

if [ -w /dev/full ]; then
	try "a full disk is a system error (-o /dev/full)" px --csv -o /dev/full "$SUN"
	assert "exit 3" '[ $rc -eq 3 ]'
	assert "says why" 'grep -q "No space left on device" $OUT/stderr'
	end

	try "a full disk is a system error (stdout to /dev/full)" sh -c '"$0" --csv "$1" >/dev/full' "$PHYLLO" "$SUN"
	assert "exit 3" '[ $rc -eq 3 ]'
	assert "says why" 'grep -q "No space left on device" $OUT/stderr'
	end
else
	skip "no writable /dev/full"
fi

if command -v script >/dev/null; then
	# script(1) gives the program a terminal as standard output.
	try "--gltf refuses a terminal as standard output, as gzip does" script -qec "$PHYLLO --gltf $GOOD; echo status \$?" /dev/null
	assert "exit 2" 'grep -aq "^status 2" $OUT/stdout'
	assert "says why" 'grep -aq "phyllo-export: --gltf writes binary data, not to a terminal: give -o FILE or redirect standard output" $OUT/stdout'
	assert "no glTF bytes" '! grep -aq glTF $OUT/stdout'
	end
	try "text formats still go to a terminal" script -qec "$PHYLLO --csv $GOOD; echo status \$?" /dev/null
	assert "exit 0" 'grep -aq "^status 0" $OUT/stdout'
	end
else
	skip "script(1) not found: --gltf to a terminal"
fi

try "a closed stdout is a system error" sh -c '"$0" --csv "$1" >&-' "$PHYLLO" "$SUN"
assert "exit 3" '[ $rc -eq 3 ]'
assert "says so" 'grep -q "^phyllo-export: <stdout>: " $OUT/stderr'
end

# Inputs too awkward to keep as golden files.
printf 'model = "planar";\ncount = 3;\nname = "a\0b";\n' >"$OUT/nul.cfg"
try "a NUL byte is an error with its line" px --csv "$OUT/nul.cfg"
assert "exit 1" '[ $rc -eq 1 ]'
assert "message" 'grep -qx "phyllo-export: $OUT/nul.cfg:3: NUL byte in scene file" $OUT/stderr'
assert "stdout empty" '[ ! -s $OUT/stdout ]'
end

# What editors write: no newline after a last-line comment, and (on
# Windows) a UTF-8 byte-order mark.  libconfig 1.5 calls both a syntax
# error; they are the same scene as without them.
printf 'model = "planar";\ncount = 100;\n' >"$OUT/plain.cfg"
px --csv "$OUT/plain.cfg" >"$OUT/plain.csv"
printf 'model = "planar";\ncount = 100; # organs' >"$OUT/nonl.cfg"
printf 'model = "planar";\ncount = 100; // organs' >"$OUT/nonl2.cfg"
printf '\357\273\277model = "planar";\ncount = 100;\n' >"$OUT/bom.cfg"
for f in nonl nonl2 bom; do
	try "$f.cfg: read as the same scene" px --csv "$OUT/$f.cfg"
	assert "exit 0, the same organs" '[ $rc -eq 0 ] && cmp -s $OUT/stdout $OUT/plain.csv'
	end
done
printf '\357\273\277model = "planar";\ncount = 100;\nname = 3;\n' >"$OUT/bom-bad.cfg"
try "an error after a byte-order mark keeps its line" px --csv "$OUT/bom-bad.cfg"
assert "exit 1, line 3" '[ $rc -eq 1 ] && grep -q "^phyllo-export: $OUT/bom-bad.cfg:3: " $OUT/stderr'
end
try "--cfg keeps the byte-order mark and sets what the file has" px --cfg --set count=50 --set divergence=137 "$OUT/bom.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "the mark kept, count set in place, divergence added" '[ "$(od -An -c -N3 $OUT/stdout | tr -d " ")" = "357273277" ] && [ "$(sed -n 2p $OUT/stdout)" = "count = 50;" ] && [ "$(sed -n 3p $OUT/stdout)" = "divergence = 137;" ]'
end
try "--cfg after a last-line comment without a newline: on a line of its own" px --cfg --set divergence=137 "$OUT/nonl.cfg"
assert "exit 0, the comment kept, the setting after it" '[ $rc -eq 0 ] && [ "$(sed -n 2p $OUT/stdout)" = "count = 100; # organs" ] && [ "$(sed -n 3p $OUT/stdout)" = "divergence = 137;" ]'
end

head -c 4096 "$PHYLLO" | tr -d '\000' >"$OUT/garbage.cfg"
try "binary garbage is a clean error" px --csv "$OUT/garbage.cfg"
assert "exit 1" '[ $rc -eq 1 ]'
assert "one line FILE:LINE: message" '[ $(wc -l <$OUT/stderr) -eq 1 ] && grep -Eq "^phyllo-export: $OUT/garbage.cfg:[0-9]+: " $OUT/stderr'
end

awk 'BEGIN { printf "model = \"planar\";\ncount = 3;\nname = \""; for (i = 0; i < 1048576; i++) printf "x"; print "\";" }' >"$OUT/long.cfg"
try "a 1 MB string is a clean error" px --csv "$OUT/long.cfg"
assert "exit 1" '[ $rc -eq 1 ]'
assert "message" 'grep -qx "phyllo-export: $OUT/long.cfg:3: name is longer than 32 characters" $OUT/stderr'
end

awk 'BEGIN { printf "model = \"planar\";\ncount = 3;\nplanar = "; for (i = 0; i < 20000; i++) printf "{ a = "; printf "1;"; for (i = 0; i < 20000; i++) printf " };"; print "" }' >"$OUT/deep.cfg"
try "deeply nested groups are a clean error" px --csv "$OUT/deep.cfg"
assert "exit 1" '[ $rc -eq 1 ]'
assert "message" 'grep -qx "phyllo-export: $OUT/deep.cfg:3: groups or lists nested too deeply" $OUT/stderr'
end

awk 'BEGIN { printf "model = \"planar\";\ncount = 3;\nplanar = { a = { b = { c = 1; }; }; };\n" }' >"$OUT/nested.cfg"
try "a nested unknown group names its full path" px --csv "$OUT/nested.cfg"
assert "exit 1" '[ $rc -eq 1 ]'
assert "message" 'grep -qx "phyllo-export: $OUT/nested.cfg:3: unknown setting .planar.a." $OUT/stderr'
end

printf 'model = "planar";\nname = "Bad\001\nName";\ncount = 3;\n' >"$OUT/ctrl.cfg"
try "control characters in a bad name are escaped in the message" px --csv "$OUT/ctrl.cfg"
assert "exit 1" '[ $rc -eq 1 ]'
assert "one line" '[ $(wc -l <$OUT/stderr) -eq 1 ]'
assert "escaped" 'grep -q "Bad\\\\x01\\\\x0aName" $OUT/stderr'
end

# Found by fuzzing: a profile a billion units tall once made the cover
# map millions of rows of one column, fifteen seconds to set up.
printf 'model = "collision";\ncount = 400;\ncollision = {\n  receptacle = { profile = ((1, 1), (1.05, 0.4), (1.05, 0.8), (0.95, 1.2), (0.8, 1444444415), (0.4, 148), (0, 1.8)); };\n  radius = 0.08;\n};\n' >"$OUT/tall.cfg"
try "collision: a profile a billion units tall places its primordia" px --info "$OUT/tall.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "400 placed" 'grep -qx "primordia: 400" $OUT/stdout'
end

# Big outputs: skipped under valgrind (RUN set), where they take minutes.
if [ -n "$RUN" ]; then
	skip "big outputs under $RUN"
	exit 0
fi

# A run killed while writing leaves neither a temporary file nor a
# changed target.  5 M organs take seconds to write, time to catch it.
printf 'model = "planar";\ncount = 5000000;\n' >"$OUT/big.cfg"
for sig in TERM INT; do
	printf 'precious\n' >"$OUT/sig.csv"
	try "SIG$sig while writing removes the temporary file" true
	# A shell started in the background ignores SIGINT in its children;
	# the program sets its own handlers, so it still sees it.
	"$PHYLLO" --csv -o "$OUT/sig.csv" "$OUT/big.cfg" 2>/dev/null &
	pid=$!
	i=0
	while [ $i -lt 200 ] && [ -z "$(ls -A "$OUT" | grep '^sig.csv.phyllo-export-')" ]; do
		sleep 0.05
		i=$((i + 1))
	done
	kill -$sig $pid 2>/dev/null
	wait $pid 2>/dev/null
	rc=$?
	assert "the temporary file had appeared" '[ $i -lt 200 ]'
	assert "killed by the signal" '[ $rc -gt 128 ]'
	assert "target unchanged" '[ "$(cat $OUT/sig.csv)" = precious ]'
	assert "no temporary file" 'no_tmp $OUT'
	end
done

# SIGKILL cannot be caught: the temporary stays, named for what it is,
# and the next run to the same file removes it; a running process's is
# left alone.
printf 'precious\n' >"$OUT/sig.csv"
try "after SIGKILL the temporary is named for us, and the next run removes it" true
"$PHYLLO" --csv -o "$OUT/sig.csv" "$OUT/big.cfg" 2>/dev/null &
pid=$!
i=0
while [ $i -lt 200 ] && [ ! -e "$OUT/sig.csv.phyllo-export-$pid.tmp" ]; do
	sleep 0.05
	i=$((i + 1))
done
kill -KILL $pid 2>/dev/null
wait $pid 2>/dev/null
assert "the temporary had appeared, visible, with the pid" '[ $i -lt 200 ]'
assert "it stays after SIGKILL" '[ -e "$OUT/sig.csv.phyllo-export-$pid.tmp" ]'
sleep 600 &
alive=$!
: >"$OUT/sig.csv.phyllo-export-$alive.tmp"
: >"$OUT/other.csv.phyllo-export-$pid.tmp"
px --csv -o "$OUT/sig.csv" "$GOOD" 2>/dev/null
assert "the next run removed it" '[ ! -e "$OUT/sig.csv.phyllo-export-$pid.tmp" ]'
assert "and wrote the file" 'cmp -s "$OUT/sig.csv" "$OUT/a-ref.csv"'
assert "a running process's temporary stays" '[ -e "$OUT/sig.csv.phyllo-export-$alive.tmp" ]'
assert "another file's stays" '[ -e "$OUT/other.csv.phyllo-export-$pid.tmp" ]'
kill $alive 2>/dev/null
wait $alive 2>/dev/null
end

printf 'model = "planar";\ncount = 1000000;\n' >"$OUT/million.cfg"
try "a million organs are written in full" sh -c '"$0" --csv "$1" | wc -l' "$PHYLLO" "$OUT/million.cfg"
assert "1000001 lines" '[ "$(cat $OUT/stdout)" -eq 1000001 ]'
end

# The collision model's default bound: a radius small enough to hold
# more than a million stops there, says so, and succeeds.
printf 'model = "collision";\ncollision = { receptacle = { shape = "hemisphere"; }; radius = 0.0011; };\n' >"$OUT/many.cfg"
try "collision: the default bound stops a million primordia with a warning" px --info "$OUT/many.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "1000000 placed" 'grep -qx "primordia: 1000000" $OUT/stdout'
assert "one warning line" '[ $(wc -l <$OUT/stderr) -eq 1 ] && grep -q "warning: stopped at 1000000 primordia, the default bound" $OUT/stderr'
assert "no progress line off a terminal" '! grep -q placed $OUT/stderr'
end

# A radius a thousand times smaller: only a band at the sphere's pole
# is reached by the bound, and that is all the placement may look at.
printf 'model = "collision";\ncollision = { receptacle = { shape = "sphere"; }; radius = 1e-6; };\n' >"$OUT/tiny.cfg"
try "collision: a tiny radius stops at the default bound too, in seconds" timeout 120 "$PHYLLO" --info "$OUT/tiny.cfg"
assert "exit 0 (not killed by the timeout)" '[ $rc -eq 0 ]'
assert "1000000 placed" 'grep -qx "primordia: 1000000" $OUT/stdout'
assert "the warning" 'grep -q "warning: stopped at 1000000 primordia, the default bound" $OUT/stderr'
end

# On a terminal (script(1) gives it one), a long placement shows how
# far it has got, and rubs the line out at the end.
if command -v script >/dev/null; then
	try "collision: a progress line on a terminal" script -qec "$PHYLLO --info $OUT/many.cfg" /dev/null
	assert "counts placed primordia and their rate" 'grep -aq "placed [0-9]* primordia, [0-9]* a second" $OUT/stdout'
	assert "rubbed out: the line is overwritten with blanks" 'tr "\r" "\n" <$OUT/stdout | grep -aq "^ \{20,\}$"'
	assert "the result follows" 'grep -aq "primordia: 1000000" $OUT/stdout'
	end
else
	skip "script(1) not found: the progress line on a terminal"
fi

# 137.5 degrees is 55/144 of a turn: organs n and n + 144 share a ray.
printf 'model = "planar";\ncount = 1000;\ndivergence = 137.5;\n' >"$OUT/rays.cfg"
try "--info says how many rays a divergence makes, and warns of it on stderr" px --info "$OUT/rays.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "rays: 144" 'grep -qx "rays: 144" $OUT/stdout'
assert "the warning names the line, the fraction and the organ, once" '[ "$(cat $OUT/stderr)" = "phyllo-export: $OUT/rays.cfg:3: warning: divergence 137.5 is 55/144 of a turn: from organ 144 on, organs line up on 144 rays instead of spirals" ]'
px --csv "$OUT/rays.cfg" >"$OUT/rays.csv" 2>/dev/null
assert "and organs n and n+144 do lie on one ray" 'awk -F, "NR > 1 { a[\$1] = atan2(\$4, \$3) } END { for (n = 0; n + 144 < 1000; n++) { d = a[n + 144] - a[n]; if (d < 0) d = -d; if (d > 1e-7 && d < 6.283185) exit 1 } }" $OUT/rays.csv'
end
# A line of several values names each (phyllo-export(1), --info).
printf 'model = "inhibition";\ncount = 300;\n' >"$OUT/inh.cfg"
try "--info: the inhibition model's settled line names its mean and spread" px --info "$OUT/inh.cfg"
assert "settled: mean M; spread S" 'grep -Eq "^settled: mean [0-9.e+-]+; spread [0-9.e+-]+$" $OUT/stdout'
assert "regime: fibonacci" 'grep -qx "regime: fibonacci" $OUT/stdout'
end
# The pair at the meristem, against the lattice the growth makes: on
# log-polar coordinates (angle in radians, ln r), which keep angles,
# primordium k plastochrons older sits k*divergence round and k*G out,
# and the contact pair is the shortest step turning each way.
for G in 0.02 0.01 0.002; do
	printf 'model = "inhibition";\ncount = 800;\ninhibition = { growth = %s; radii = "grown"; };\n' $G >"$OUT/inh-g.cfg"
	try "--info: the pair at the meristem at G = $G is the log-polar lattice's" px --info "$OUT/inh-g.cfg"
	want=$(awk -v G=$G '/^settled:/ { d = $3 + 0 }
		END {
			for (k = 1; k <= 400; k++) {
				t = k * d / 360; f = t - int(t + 0.5)
				x = 2 * 3.14159265358979 * f; y = k * G; l = x * x + y * y
				if (f > 0 && (!p || l < lp)) { p = k; lp = l }
				if (f < 0 && (!m || l < lm)) { m = k; lm = l }
			}
			print (p < m ? p " " m : m " " p)
		}' "$OUT/stdout")
	assert "parastichies-meristem: $want" 'grep -qx "parastichies-meristem: $want" $OUT/stdout'
	end
done
try "--info: alternate leaves have no pair at the meristem" px --info scenes/distichous.cfg
assert "parastichies-meristem: none" 'grep -qx "parastichies-meristem: none" $OUT/stdout'
end
try "the golden angle makes no rays" px --info "$SUN"
assert "no rays line, no warning" '! grep -q "^rays:" $OUT/stdout && [ ! -s $OUT/stderr ]'
end
for w in pov blender csv svg; do
	try "--$w warns of the rays too, once" px --$w "$OUT/rays.cfg"
	assert "exit 0, one line on stderr" '[ $rc -eq 0 ] && [ $(grep -c "warning: divergence 137.5 is 55/144 of a turn" $OUT/stderr) -eq 1 ] && [ $(wc -l <$OUT/stderr) -eq 1 ]'
	end
done
try "--frames: once a run, not once a frame" px --csv --frames 3 -o "$OUT/rays%d.csv" "$OUT/rays.cfg"
assert "one line" '[ $(grep -c "warning: divergence" $OUT/stderr) -eq 1 ]'
end
