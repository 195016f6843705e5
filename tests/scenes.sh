#!/bin/sh
# scenes.sh - every example scene exports, and the organ vocabulary
# scenes give each index range its objects.
. tests/lib.sh

for cfg in scenes/*.cfg; do
	try "scene $cfg exports to CSV" px --csv "$cfg"
	assert "exit 0" '[ $rc -eq 0 ]'
	assert "stderr empty" '[ ! -s $OUT/stderr ]'
	assert "one line per organ" '[ $(($(wc -l <$OUT/stdout) - 1)) -eq $(px --info "$cfg" | sed -n "s/^count: //p") ]'
	end
done

for cfg in scenes/*.cfg; do
	n=$(px --info "$cfg" | sed -n "s/^count: //p")
	k=$(px --info "$cfg" | sed -n "s/^objects: //p" | wc -w)
	try "scene $cfg draws as SVG: one circle per organ, a colour per object" px --svg "$cfg"
	assert "exit 0" '[ $rc -eq 0 ]'
	assert "$n circles and $k in the key" '[ $(grep -c "^<circle " $OUT/stdout) -eq $((n + k)) ]'
	assert "$k colours" '[ $(grep -o "fill=\"hsl([0-9]*" $OUT/stdout | sort -u | wc -l) -eq $k ]'
	if command -v python3 >/dev/null; then
		assert "well-formed XML" 'python3 -c "import sys, xml.etree.ElementTree as E; E.parse(sys.argv[1])" $OUT/stdout'
	fi
	end
done

# objects CSV FROM TO NAME...: organs FROM..TO are all among NAMES.
objects() {
	awk -F, -v from="$2" -v to="$3" -v names="$4" '
	BEGIN { n = split(names, a, " "); for (i = 1; i <= n; i++) ok[a[i]] = 1 }
	NR > 1 && $1 >= from && $1 <= to && !($2 in ok) { print "organ " $1 " is " $2; bad = 1; exit }
	END { exit bad }' "$1"
}

px --csv scenes/sunflower.cfg >"$OUT/sun.csv"
try "sunflower: ABOP's ranges get seeds, florets and four petals" true
assert "0-440 Seed" 'objects $OUT/sun.csv 0 440 Seed'
assert "441-565 Floret" 'objects $OUT/sun.csv 441 565 Floret'
assert "566-580 PetalA" 'objects $OUT/sun.csv 566 580 PetalA'
assert "581-595 PetalB" 'objects $OUT/sun.csv 581 595 PetalB'
assert "596-610 PetalC" 'objects $OUT/sun.csv 596 610 PetalC'
assert "611-629 PetalD" 'objects $OUT/sun.csv 611 629 PetalD'
end

px --csv scenes/daisy.cfg >"$OUT/daisy.csv"
try "daisy: lowered disc florets, three ray variants" true
assert "0-379 DiscFloret" 'objects $OUT/daisy.csv 0 379 DiscFloret'
assert "380-419 rays" 'objects $OUT/daisy.csv 380 419 "RayA RayB RayC"'
assert "all three rays appear" '[ $(awk -F, "NR > 1 && \$1 >= 380 { print \$2 }" $OUT/daisy.csv | sort -u | wc -l) -eq 3 ]'
assert "the centre lies below floret 100" 'awk -F, "NR == 2 { z0 = \$5 } NR == 102 { exit !(z0 < \$5) }" $OUT/daisy.csv'
end

px --csv scenes/zinnia.cfg >"$OUT/zinnia.csv"
try "zinnia: petals sink, grow and flatten with n" true
assert "0-139 Floret" 'objects $OUT/zinnia.csv 0 139 Floret'
assert "140-259 Petal" 'objects $OUT/zinnia.csv 140 259 Petal'
assert "scale grows" 'awk -F, "NR > 1 && \$1 >= 141 && \$15 <= prev { exit 1 } NR > 1 && \$1 >= 140 { prev = \$15 }" $OUT/zinnia.csv'
assert "u flattens: its z falls" 'awk -F, "NR > 1 && \$1 >= 141 && \$8 >= prev { exit 1 } NR > 1 && \$1 >= 140 { prev = \$8 }" $OUT/zinnia.csv'
end

# The SVG draws the measured families as a botanist would: smooth
# chains of contact steps of one family through the organs' centres,
# spirals (turning one way, moving one way), each family in one colour
# and counted once, no count over another, a key to the organ objects;
# and the legend names the pair --info measures.
if command -v python3 >/dev/null; then
	for cfg in scenes/*.cfg; do
		objs=$(px --info "$cfg" | sed -n 's/^objects: //p')
		px --svg "$cfg" >"$OUT/d.svg"
		px --csv "$cfg" >"$OUT/d.csv"
		try "scene $cfg: its parastichies drawn as spirals of one family each, counted apart, with a key" \
			python3 tests/svgcheck.py "$OUT/d.svg" "$OUT/d.csv" $objs
		assert "all as it should be: $(head -c 300 $OUT/stdout)" '[ $rc -eq 0 ] && [ ! -s $OUT/stdout ]'
		end
	done
	# The same of every other picture the suite makes: the regression
	# cases' (their goldens too), a sweep of the divergence (137.7 has
	# 115 at the rim) and an emerged head's.
	for cfg in tests/regress/*/*.cfg; do
		[ -f "${cfg%.cfg}.svg" ] || continue
		objs=$(px --info "$cfg" | sed -n 's/^objects: //p')
		px --csv "$cfg" >"$OUT/d.csv"
		try "${cfg%.cfg}.svg, the golden file: its parastichies as they should be" \
			python3 tests/svgcheck.py "${cfg%.cfg}.svg" "$OUT/d.csv" $objs
		assert "all as it should be" '[ $rc -eq 0 ] && [ ! -s $OUT/stdout ]'
		end
	done
	objs=$(px --info scenes/sunflower.cfg | sed -n 's/^objects: //p')
	for a in 137.3 137.45 137.7 138; do
		px --svg --set divergence=$a scenes/sunflower.cfg >"$OUT/d.svg" 2>/dev/null
		px --csv --set divergence=$a scenes/sunflower.cfg >"$OUT/d.csv" 2>/dev/null
		try "sunflower at divergence $a: its parastichies as they should be" \
			python3 tests/svgcheck.py "$OUT/d.svg" "$OUT/d.csv" $objs
		assert "all as it should be" '[ $rc -eq 0 ] && [ ! -s $OUT/stdout ]'
		end
	done
	for g in 0.01 0.002; do
		printf 'model = "inhibition";\ncount = 600;\ninhibition = { growth = %s; radii = "%s"; };\n' $g vogel >"$OUT/inh.cfg"
		for radii in vogel grown; do
			px --svg --set inhibition.radii="\"$radii\"" "$OUT/inh.cfg" >"$OUT/d.svg"
			px --csv --set inhibition.radii="\"$radii\"" "$OUT/inh.cfg" >"$OUT/d.csv"
			try "an emerged head at G = $g, radii $radii: its parastichies as they should be" \
				python3 tests/svgcheck.py "$OUT/d.svg" "$OUT/d.csv" Organ
			assert "all as it should be" '[ $rc -eq 0 ] && [ ! -s $OUT/stdout ]'
			end
		done
	done
else
	skip "python3 not found: the SVG's parastichies"
fi
for s in pinecone sunflower; do
	px --svg "scenes/$s.cfg" >"$OUT/$s.svg"
	pair=$(px --info "scenes/$s.cfg" | sed -n 's/^parastichies: //p' | sed 's/ / and /')
	try "$s: the SVG's legend names the pair --info measures ($pair)" true
	assert "the legend names the pair" 'grep -q ">parastichies $pair at the" $OUT/$s.svg'
	end
done
try "a tall cone is unrolled, a flat head seen from above" true
assert "pinecone unrolled" 'grep -q "cylindrical model, [0-9]* organs, unrolled" $OUT/pinecone.svg'
assert "sunflower from above" 'grep -q "planar model, [0-9]* organs, from above" $OUT/sunflower.svg'
end

# A first scene of any model, only model and count set, gives a head a
# scene can frame (extent 0.05 to 100 units, organ sizes within 100
# times of each other) or one line naming the setting it needs by its
# full path.  The models are the program's own list, so a sixth is
# tried as it is added.
models=$(printf 'model = "?";\n' | px --info - 2>&1 | sed -n 's/.*is not one of: \([a-z ]*\).*/\1/p')
for m in $models; do
	printf 'model = "%s";\ncount = 600;\n' "$m" >"$OUT/first.cfg"
	try "model $m with only a count: a picture or one line naming what it needs" px --csv "$OUT/first.cfg"
	if [ $rc -eq 0 ]; then
		assert "extent between 0.05 and 100, sizes within 100x" 'awk -F, "NR > 1 {
			for (k = 3; k <= 5; k++) { if (n == 0 || \$k < lo[k]) lo[k] = \$k; if (n == 0 || \$k > hi[k]) hi[k] = \$k }
			if (n == 0 || \$15 < s0) s0 = \$15; if (\$15 > s1) s1 = \$15; n++ }
			END { e = 0; for (k = 3; k <= 5; k++) if (hi[k] - lo[k] > e) e = hi[k] - lo[k]
			exit !(n == 600 && e >= 0.05 && e <= 100 && s0 > 0 && s1 <= 100 * s0) }" $OUT/stdout'
	else
		assert "exit 1, one line" '[ $rc -eq 1 ] && [ $(wc -l <$OUT/stderr) -eq 1 ]'
		assert "names a $m. setting by its full path" 'grep -q "^phyllo-export: .*first.cfg:[0-9]*: .*\\<$m\\.[a-z.]*" $OUT/stderr'
	fi
	end
done
try "the models' list was read from the program" true
assert "five or more" '[ $(echo $models | wc -w) -ge 5 ]'
end
