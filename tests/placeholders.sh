#!/bin/sh
# placeholders.sh - every placeholder common to the templates, written
# through tests/placeholders.tmpl and held against what it means: the
# organ fields against --csv, PHI against the position's angle, H
# against the height before altitude, T against n/(N-1), the object
# lines against the organs, the header against --info.
. tests/lib.sh

cat >"$OUT/p.cfg" <<'CFG'
name = "Head";
model = "planar";
count = 60;
seed = 7;
planar = { scale = 0.1; dome = 0.3; };
organs = (
  { object = "Seed"; to = 39; altitude = 0.05; },
  { object = ["Bract", "Leaf"]; from = 40; tilt = 20; roll = 30; }
);
CFG
px --csv -o "$OUT/p.csv" "$OUT/p.cfg"
px --info -o "$OUT/p.info" "$OUT/p.cfg"

for fmt in pov blender; do
	try "--$fmt --template: every common placeholder says what it means" \
		px --$fmt --template tests/placeholders.tmpl "$OUT/p.cfg"
	assert "exit 0" '[ $rc -eq 0 ]'
	grep -v '^name=\|^object,' "$OUT/stdout" >"$OUT/organs"
	# The first 16 fields are the CSV's, in its order.
	{ head -1 "$OUT/p.csv"; cut -d, -f1-16 "$OUT/organs"; } >"$OUT/as.csv"
	assert "X..WZ, SCALE, RADIUS, N, OBJECT match --csv" 'csv_close "$OUT/p.csv" "$OUT/as.csv" >"$OUT/diff"'
	assert "PHI is the angle of (X, Y), H the height before altitude, T n/(N-1), COMMA all but last" 'awk -F, "
		function abs(x) { return x < 0 ? -x : x }
		{
			phi = atan2(\$4, \$3) * 45 / atan2(1, 1); if (phi < 0) phi += 360
			if (abs(phi - \$17) > 1e-6 && abs(abs(phi - \$17) - 360) > 1e-6) { print \"phi \" NR; exit 1 }
			alt = \$1 < 40 ? 0.05 : 0
			if (abs(\$5 - \$18 - alt * \$14) > 1e-8) { print \"h \" NR; exit 1 }
			if (abs(\$19 - \$1 / 59) > 1e-8) { print \"t \" NR; exit 1 }
			if ((NF == 22) != (NR < 60)) { print \"comma \" NR; exit 1 }
			seen[\$20 \" \" \$2] = 1
		}
		END { if (NR != 60) exit 1 }" "$OUT/organs"'
	assert "OBJECT_INDEX, OBJECT and OBJECT_ORGANS agree with the organs" '
		grep "^object," "$OUT/stdout" | while IFS=, read -r _ i name k comma; do
			[ "$(awk -F, -v i="$i" -v o="$name" "\$20 == i && \$2 == o" "$OUT/organs" | wc -l)" -eq "$k" ] || exit 1
		done && [ "$(grep -c "^object," "$OUT/stdout")" -eq 3 ]'
	assert "the header agrees with --info" '
		grep -q "^name=Head count=60 model=planar divergence=$(sed -n "s/^divergence: //p" "$OUT/p.info") seed=7 version=$("$PHYLLO" --version | cut -d" " -f2) scene=p.cfg objects=3\$" "$OUT/stdout"'
	end
done
