#!/bin/sh
# set.sh - settings from the command line: --set changes a scene exactly
# as editing its file would (the same output, the same checks, messages
# naming the override), into parts and across frames; --settings lists
# every setting from the loader's tables, held against phyllo-export(5);
# --cfg writes the overrides into the file, comments kept, and reads
# back the same.
. tests/lib.sh

SUN=scenes/sunflower.cfg

# edited FILE SED: FILE with the sed script applied, in $OUT/edited.cfg.
edited() {
	sed "$2" "$1" >"$OUT/edited.cfg"
}

# --- The same as editing the file. ---
edited "$SUN" 's/^count = 630;/count = 300;/; s/scale = 0.04; dome = 0.08;/scale = 0.05; dome = 0.08; inner = 0.1;/'
try "--set count and planar settings equal the edited file" \
	px --csv --set count=300 --set planar.scale=0.05 --set planar.inner=0.1 "$SUN"
assert "exit 0" '[ $rc -eq 0 ]'
assert "the same CSV as the edited file" 'px --csv "$OUT/edited.cfg" | cmp -s - $OUT/stdout'
assert "and not the unedited one" '! px --csv "$SUN" | cmp -s - $OUT/stdout'
end

# Entry 3 is PetalB's; its tilt stands on the line after its name.
at=$(($(grep -n '"PetalB"' "$SUN" | cut -d: -f1) + 1))
edited "$SUN" "${at}s/tilt = \"-10 \\* rand(2)\"; },\$/tilt = \"-10 * rand(2)\"; altitude = 0.02; },/"
try "--set into an organs entry by number (organs.3.altitude)" px --csv --set organs.3.altitude=0.02 "$SUN"
sed -n ${at}p "$OUT/edited.cfg" | grep -q altitude || bad="$bad; the edit missed entry 3"
assert "the same CSV as the edited file" 'px --csv "$OUT/edited.cfg" | cmp -s - $OUT/stdout'
end

try "the last --set of a path wins, as in the file" px --info --set count=100 --set count=200 "$SUN"
assert "count: 200" 'grep -qx "count: 200" $OUT/stdout'
end

try "--set a whole group" px --info --set 'planar={ scale = 0.1; }' "$SUN"
assert "scale 0.1, the dome gone with the group" 'grep -qx "scale: 0.1" $OUT/stdout && px --csv --set "planar={ scale = 0.1; }" "$SUN" | awk -F, "NR > 1 && \$5 != 0 { n++ } END { exit n }"'
end

# Into a part, by its object name; other parts and the main untouched.
try "--set OBJECT:PATH changes the part making OBJECT" px --info --set Achene:count=7 scenes/goatsbeard.cfg
assert "parts: Achene 7" 'grep -qx "parts: Achene 7" $OUT/stdout'
assert "the main's count as before" '[ "$(sed -n "s/^count: //p" $OUT/stdout)" = "$(px --info scenes/goatsbeard.cfg | sed -n "s/^count: //p")" ]'
end

# Across frames: a value may be an expression of f, as in the file.
try "--set with --frames: an expression of f" px --info --frames 3 --set 'count="100 + 100 * f"' -o "$OUT/fr%d.txt" "$SUN"
assert "100, 150, 200" '[ "$(cat $OUT/fr1.txt $OUT/fr2.txt $OUT/fr3.txt | sed -n "s/^count: //p" | tr "\n" " ")" = "100 150 200 " ]'
end

# --- Checked as the file is: the same messages, naming the override. ---
while IFS='|' read -r arg message; do
	try "--set $arg: exit 1, \"$message\"" px --csv --set "$arg" "$SUN"
	assert "exit 1" '[ $rc -eq 1 ]'
	assert "message" 'grep -qxF -- "phyllo-export: --set $arg: $message" $OUT/stderr'
	assert "nothing on stdout" '[ ! -s $OUT/stdout ]'
	end
done <<'EOF'
planar.scael=0.1|unknown setting 'planar.scael' (did you mean planar.scale?)
count=0|count 0 is out of range: must be between 1 and 10000000
count="n + 1"|count: variable 'n' is not available here (it may use f and F)
model="planr"|model "planr" is not one of: planar cylindrical collision area inhibition measured (did you mean planar?)
organs.2.tilt="1 + q"|organs.tilt: unknown variable 'q'
planar.scale="0"|planar.scale 0 is out of range: must be greater than 0
cuont=5|unknown setting 'cuont' (did you mean count?)
collision.radius=0.1|'collision' does not apply to model "planar"
EOF
# The inhibition model's growth summed past e^700: at what was raised,
# with what would do.  count 600 at growth 0.02 and start 2 adds to 28.
printf 'model = "inhibition";\ncount = 600;\n' >"$OUT/inh.cfg"
try "--set count past the growth's sum: the message at count, with the most primordia" \
	px --csv --set count=40000 "$OUT/inh.cfg"
assert "exit 1" '[ $rc -eq 1 ]'
assert "message" 'grep -qxF -- "phyllo-export: --set count=40000: count 40000 is more than inhibition.growth allows: it adds up to 816 over them, past the 700 the model holds (the oldest would lie e^816 meristem radii out): at most 34208 primordia at this growth, or growth at most 0.0171 for 40000" $OUT/stderr'
assert "and what it says does: 34208 and 0.0171 run" 'px --info --set count=34208 "$OUT/inh.cfg" >/dev/null && px --info --set count=40000 --set inhibition.growth=0.0171 "$OUT/inh.cfg" >/dev/null'
end
try "--set growth past the sum: the message at growth" \
	px --csv --set inhibition.growth=2 "$OUT/inh.cfg"
assert "exit 1, at growth" '[ $rc -eq 1 ] && grep -qF -- "phyllo-export: --set inhibition.growth=2: inhibition.growth adds up to 1198 over 600 primordia" $OUT/stderr'
end
try "an error found placing, at the override too" px --csv --set 'organs.0.scale="1 / (n - 3) + 1"' "$SUN"
assert "exit 1, names the override and the organ" '[ $rc -eq 1 ] && grep -qxF "phyllo-export: --set organs.0.scale=\"1 / (n - 3) + 1\": organs.scale: division by zero at organ 3" $OUT/stderr'
end
try "an error in a part's override names it, then the line including the part" \
	px --csv --set Achene:planar.scal=7 scenes/goatsbeard.cfg
assert "exit 1" '[ $rc -eq 1 ]'
assert "first line" 'head -1 $OUT/stderr | grep -qxF "phyllo-export: --set Achene:planar.scal=7: unknown setting '"'"'planar.scal'"'"' (did you mean planar.scale?)"'
end

# --- What the command line gets wrong: usage errors, exit 2. ---
while IFS='|' read -r arg message; do
	try "--set '$arg' is a usage error" px --csv --set "$arg" "$SUN"
	refused "^phyllo-export: --set $arg: $message"
	assert "nothing on stdout" '[ ! -s $OUT/stdout ]'
	end
done <<'EOF'
count|give PATH=VALUE
=3|give PATH=VALUE
.x=3|'' is not a setting's name
planar..scale=1|'' is not a setting's name
planar.=1|the path ends in '.'
plan ar=1|'plan ar' is not a setting's name
count=1+|not a value in scene-file syntax
count=|not a value in scene-file syntax
count=5; seed = 3|more than one value
count.x=1|the path goes through count, which is one value, not a group
planar.2.x=1|the path goes through planar, which is a group: name a setting in it
leaves.0.tilt=1|the scene has no leaves to number: give the whole list, as leaves=({ ... })
organs.scale=1|the path goes through organs, which is a list: step into its entries by number (organs.0.scale)
organs.9.scale=1|organs has 6 entries, numbered from 0
organs.1=1|set a whole entry, array or list by its name
Floret:count=30|no organ object "Floret" is made of a scene (this structure has no parts)
9x:count=1|'9x' is not an organ object's name
EOF
try "--set OBJECT:PATH for a part that does not exist lists the parts" px --csv --set Nothing:count=3 scenes/goatsbeard.cfg
refused 'no organ object "Nothing" is made of a scene (the parts: Achene)'
end

# --- --settings: every setting, from the tables. ---
if command -v python3 >/dev/null; then
	for cfg in scenes/*.cfg tests/regress/*/*.cfg; do
		[ -f "${cfg%.cfg}.err" ] && continue
		px --settings "$cfg" >"$OUT/s.json" 2>"$OUT/stderr" || { bad="$bad; $cfg: exit $?"; continue; }
		python3 - "$OUT/s.json" "$OUT/table" >>"$OUT/paths" <<'PY' || bad="$bad; $cfg: $(tail -1 "$OUT/paths")"
import json, re, sys
d = json.load(open(sys.argv[1]))
for s in d["settings"]:
    for k in ("path", "type", "from", "default", "doc"):
        assert k in s, (s["path"], k)
    # The path as phyllo-export(5) lists it: no part, no entry number.
    path = re.sub(r"\.[0-9]+\.", ".", s["path"].split(":")[-1])
    print("%s\t%s\t%s" % (path, s["type"], s["default"]))
PY
	done
	try "--settings is JSON naming every setting as phyllo-export(5) lists it (path, type, default)" true
	"$TESTBIN/settings_list" >"$OUT/table"
	sort -u "$OUT/paths" >"$OUT/listed"
	assert "every listed setting is in the man page's list" '[ -z "$(comm -23 $OUT/listed $(sort "$OUT/table" >$OUT/table.s; echo $OUT/table.s))" ]'
	# Every model's settings appear in some scene above, and the
	# organs entries' too: the list covers the man page's.
	assert "and every one of the man page's settings is listed by some scene" '[ -z "$(comm -13 $OUT/listed $OUT/table.s | grep -v "	group	\|	list	")" ]'
	end
else
	skip "python3 not found: --settings JSON"
fi

try "--settings: values as written, defaults, ranges, --set marked" \
	px --settings --set planar.inner=0.1 "$SUN"
assert "exit 0" '[ $rc -eq 0 ]'
line=$(grep -n '^count = 630;' "$SUN" | cut -d: -f1)
assert "count as written at its line" 'grep -q "{ \"path\": \"count\", \"type\": \"integer\", \"value\": \"630\", \"from\": \"file\", \"line\": $line, \"default\": \"none\", \"min\": 1, \"max\": 10000000, \"unit\": \"organs\"" $OUT/stdout'
assert "planar.inner from --set" 'grep -q "{ \"path\": \"planar.inner\", \"type\": \"number\", \"value\": \"0.1\", \"from\": \"set\"" $OUT/stdout'
assert "divergence from its default, the table's number" 'grep -q "{ \"path\": \"divergence\", \"type\": \"number\", \"value\": \"137.50776405003785\", \"from\": \"default\"" $OUT/stdout'
assert "an expression quoted as the file quotes it" 'grep -qF "{ \"path\": \"organs.0.scale\", \"type\": \"expression\", \"value\": \"\\\"1.1 * r\\\"\"" $OUT/stdout'
end
try "--settings of a compound lists each part's settings as OBJECT:PATH" px --settings scenes/goatsbeard.cfg
assert "the part and its count" 'grep -q "\"object\": \"Achene\", \"scene\": \"scenes/parts/goatsbeard-pappus.cfg\"" $OUT/stdout && grep -q "{ \"path\": \"Achene:count\"" $OUT/stdout'
end
# What the loader refuses given, the panel must not offer: divergence
# where the angle emerges, the power law's exponent with the Gaussian.
# --settings lists them as not applying, with the loader's reason.
try "--settings lists the settings that do not apply as such" \
	px --settings --set 'inhibition.kernel="gaussian"' scenes/sunflower-emerged.cfg
assert "exit 0" '[ $rc -eq 0 ]'
assert "divergence: applies false, why" 'grep "\"path\": \"divergence\"" $OUT/stdout | grep -qF "\"applies\": false, \"why\": \"does not apply to model \\\"inhibition\\\", whose angle emerges\""'
assert "inhibition.exponent: applies false, why" 'grep "\"path\": \"inhibition.exponent\"" $OUT/stdout | grep -qF "\"applies\": false, \"why\": \"does not apply with inhibition.kernel \\\"gaussian\\\", which has no exponent\""'
assert "no other is flagged" '[ $(grep -c "\"applies\"" $OUT/stdout) -eq 2 ]'
assert "the kernel and the growth still there" 'grep -q "\"path\": \"inhibition.kernel\"" $OUT/stdout && grep -q "\"path\": \"inhibition.growth\"" $OUT/stdout'
end
# The panel finds out from --settings which fields apply after a change,
# even where the change leaves one the artist changed unused.
try "--settings lists one given that does not apply, not refused" \
	px --settings --set 'inhibition.kernel="gaussian"' --set inhibition.exponent=2 scenes/sunflower-emerged.cfg
assert "exit 0" '[ $rc -eq 0 ]'
assert "from --set, value 2, applies false" 'grep "\"path\": \"inhibition.exponent\"" $OUT/stdout | grep -q "\"value\": \"2\", \"from\": \"set\".*\"applies\": false"'
end
try "and the same scene is refused by every other option" \
	px --info --set 'inhibition.kernel="gaussian"' --set inhibition.exponent=2 scenes/sunflower-emerged.cfg
assert "exit 1, the loader's message" '[ $rc -eq 1 ] && grep -qF "phyllo-export: --set inhibition.exponent=2: '"'"'inhibition.exponent'"'"' does not apply with inhibition.kernel \"gaussian\", which has no exponent" $OUT/stderr'
end
# A file that gives the exponent, switched to the Gaussian by --set: the
# file's exponent ignored with a warning (so the panel's menu works).
printf 'model = "inhibition";\ncount = 40;\ninhibition = { kernel = "power"; exponent = 3; growth = 0.1; };\n' >"$OUT/inh-exp.cfg"
printf 'model = "inhibition";\ncount = 40;\ninhibition = { kernel = "gaussian"; growth = 0.1; };\n' >"$OUT/inh-gauss.cfg"
px --csv -o "$OUT/inh-gauss.csv" "$OUT/inh-gauss.cfg"
try "--set that leaves a setting of the file unused: it is ignored, with a warning" \
	px --csv --frames 2 -o "$OUT/inh-set%d.csv" --set 'inhibition.kernel="gaussian"' "$OUT/inh-exp.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "one warning, at the file's line, saying why" '[ $(wc -l <$OUT/stderr) -eq 1 ] && grep -qF "phyllo-export: $OUT/inh-exp.cfg:3: warning: frame 1 of 2 (f = 0): '"'"'inhibition.exponent'"'"' does not apply with inhibition.kernel \"gaussian\", which has no exponent, as --set made it: ignored" $OUT/stderr'
assert "the Gaussian's structure" 'cmp -s "$OUT/inh-set1.csv" "$OUT/inh-gauss.csv"'
end
printf 'model = "inhibition";\ncount = 40;\ninhibition = { kernel = "gaussian"; exponent = 3; growth = 0.1; };\n' >"$OUT/inh-bad.cfg"
try "a file that gives a setting its own others leave unused is refused, --set or not" \
	px --csv --set count=30 --set inhibition.growth=0.2 "$OUT/inh-bad.cfg"
assert "exit 1, at the file's line" '[ $rc -eq 1 ] && grep -qxF "phyllo-export: $OUT/inh-bad.cfg:3: '"'"'inhibition.exponent'"'"' does not apply with inhibition.kernel \"gaussian\", which has no exponent" $OUT/stderr'
end
# --cfg: the file's unused one taken out (the file would not load with
# it), saying so; every comment kept, one after it on its line too.
try "--cfg takes out of the file the setting a --set leaves unused, with a warning" \
	px --cfg --set 'inhibition.kernel="gaussian"' "$OUT/inh-exp.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "one warning, at the file's line, saying why" '[ $(wc -l <$OUT/stderr) -eq 1 ] && grep -qxF "phyllo-export: $OUT/inh-exp.cfg:3: warning: '"'"'inhibition.exponent'"'"' does not apply with inhibition.kernel \"gaussian\", which has no exponent, as --set makes it: taken out of the file written" $OUT/stderr'
assert "the group without it, the rest as it was" 'printf "model = \"inhibition\";\ncount = 40;\ninhibition = { kernel = \"gaussian\"; growth = 0.1; };\n" | cmp -s - $OUT/stdout'
assert "the file written makes the structure of the Gaussian kernel" 'px --csv - <$OUT/stdout | cmp -s - "$OUT/inh-gauss.csv"'
end
cat >"$OUT/inh-lines.cfg" <<'CFG'
# An inhibition head.
model = "inhibition";
count = 40;
inhibition = {
  kernel = "power";   # the power law
  # its exponent
  exponent = 3;
  growth = 0.1;
  dome = 0.1;
  start = 2; # the young meristem
};
CFG
try "--cfg takes a setting alone on its line out with the line, and keeps every comment" \
	px --cfg --set 'inhibition.kernel="gaussian"' "$OUT/inh-lines.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "every comment kept" '[ "$(grep -c "#" $OUT/stdout)" = "$(grep -c "#" $OUT/inh-lines.cfg)" ]'
assert "the kernel changed, the line of the exponent taken out, nothing else" 'diff "$OUT/inh-lines.cfg" $OUT/stdout >$OUT/diff; [ "$(grep -c "^>" $OUT/diff)" = 1 ] && [ "$(grep -c "^<" $OUT/diff)" = 2 ] && grep -qx "<   exponent = 3;" $OUT/diff && grep -qxF ">   kernel = \"gaussian\";   # the power law" $OUT/diff'
assert "loads as the --set run" 'px --csv - <$OUT/stdout >$OUT/a.csv && px --csv --set "inhibition.kernel=\"gaussian\"" "$OUT/inh-lines.cfg" 2>/dev/null | cmp -s - $OUT/a.csv'
end
# A part's setting that does not apply: listed as the main scene's are.
printf 'model = "inhibition";\ncount = 20;\ninhibition = { kernel = "gaussian"; growth = 0.1; };\n' >"$OUT/part-gauss.cfg"
printf 'model = "planar";\ncount = 3;\norgans = ( { object = "Head"; scene = "part-gauss.cfg"; } );\n' >"$OUT/main-parts.cfg"
try "--settings lists a part's setting that does not apply, given by --set" \
	px --settings --set Head:inhibition.exponent=2 "$OUT/main-parts.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
assert "Head:inhibition.exponent from --set, applies false" 'grep "\"path\": \"Head:inhibition.exponent\"" $OUT/stdout | grep -q "\"from\": \"set\".*\"applies\": false"'
end
try "and --info refuses it" px --info --set Head:inhibition.exponent=2 "$OUT/main-parts.cfg"
assert "exit 1, the loader's message" '[ $rc -eq 1 ] && grep -qF "phyllo-export: --set Head:inhibition.exponent=2: '"'"'inhibition.exponent'"'"' does not apply with inhibition.kernel \"gaussian\", which has no exponent" $OUT/stderr'
end
try "--cfg refuses them as the loader does" px --cfg --set divergence=100 scenes/sunflower-emerged.cfg
assert "exit 1, the message" '[ $rc -eq 1 ] && grep -qx "phyllo-export: --set divergence=100: '"'"'divergence'"'"' does not apply to model \"inhibition\", whose angle emerges" $OUT/stderr'
assert "nothing written" '[ ! -s $OUT/stdout ]'
end
try "--settings with --frames is a usage error" px --settings --frames 2 -o "$OUT/x%d" "$SUN"
refused "gives the scene as written: --frames does not go with it"
end

# --- --cfg: the overrides written into the file. ---
cp "$SUN" "$OUT/sun.cfg"
try "--cfg writes each --set into the file, the rest as it was" \
	px --cfg --set count=300 --set planar.inner=0.05 --set organs.2.tilt='"-20 * rand(2)"' --set seed=7 "$OUT/sun.cfg"
assert "exit 0" '[ $rc -eq 0 ]'
cp "$OUT/stdout" "$OUT/saved.cfg"
assert "the same CSV as the same --set" 'px --csv "$OUT/saved.cfg" >$OUT/a.csv && px --csv --set count=300 --set planar.inner=0.05 --set organs.2.tilt="\"-20 * rand(2)\"" --set seed=7 "$OUT/sun.cfg" | cmp -s - $OUT/a.csv'
assert "every comment kept" '[ "$(grep -c "#" $OUT/saved.cfg)" = "$(grep -c "#" $OUT/sun.cfg)" ]'
assert "three lines changed, one added" '[ "$(diff $OUT/sun.cfg $OUT/saved.cfg | grep -c "^>")" = 4 ] && [ "$(diff $OUT/sun.cfg $OUT/saved.cfg | grep -c "^<")" = 3 ]'
assert "the new member in its group, indented as its neighbours" 'grep -qx "planar = { scale = 0.04; dome = 0.08; inner = 0.05; };" $OUT/saved.cfg'
end
try "--cfg adds a group's member on a line of its own where the group has lines" \
	px --cfg --set collision.parastichies='[13, 21]' scenes/coneflower.cfg
assert "exit 0, indented as the radius" '[ $rc -eq 0 ] && grep -qx "  parastichies = \[13, 21\];" $OUT/stdout'
end
try "--cfg of a part's setting is a usage error" px --cfg --set Achene:count=7 scenes/goatsbeard.cfg
refused "--cfg writes the main scene"
end
try "--cfg -o the scene itself is refused: write a copy" px --cfg --set count=5 -o "$OUT/sun.cfg" "$OUT/sun.cfg"
refused "would replace"
assert "the scene as it was" 'cmp -s "$OUT/sun.cfg" "$SUN"'
end
