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

# Each scene: its file, its organ count, and the altitude of organ n.
cat >"$OUT/c.cfg" <<'CFG'
name = "Cone";
model = "collision";
seed = 7;
collision = { receptacle = { shape = "cone"; height = 1.5; }; radius = 0.08; };
organs = ( { object = "Seed"; to = 19; altitude = 0.05; }, { object = ["Bract", "Leaf"]; from = 20; } );
CFG
px --csv -o "$OUT/c.csv" "$OUT/c.cfg"
px --info -o "$OUT/c.info" "$OUT/c.cfg"

for scene in "p Head planar 39" "c Cone collision 19"; do
set -- $scene
S=$1 NAME=$2 MODEL=$3 LASTALT=$4
N=$(sed -n 's/^count: //p' "$OUT/$S.info")
for fmt in pov blender; do
	try "--$fmt --template, $MODEL: every common placeholder says what it means" \
		px --$fmt --template tests/placeholders.tmpl "$OUT/$S.cfg"
	assert "exit 0" '[ $rc -eq 0 ]'
	grep -v '^name=\|^object,' "$OUT/stdout" >"$OUT/organs"
	# The first 16 fields are the CSV's, in its order.
	{ head -1 "$OUT/$S.csv"; cut -d, -f1-16 "$OUT/organs"; } >"$OUT/as.csv"
	assert "X..WZ, SCALE, RADIUS, N, OBJECT match --csv" 'csv_close "$OUT/$S.csv" "$OUT/as.csv" >"$OUT/diff"'
	assert "PHI is the angle of (X, Y), H the height before altitude, T n/(N-1), COMMA all but last" 'awk -F, -v N=$N -v last=$LASTALT "
		function abs(x) { return x < 0 ? -x : x }
		{
			rho = sqrt(\$3 * \$3 + \$4 * \$4)
			phi = atan2(\$4, \$3) * 45 / atan2(1, 1); if (phi < 0) phi += 360
			if (rho > 1e-6 && abs(phi - \$17) > 1e-5 && abs(abs(phi - \$17) - 360) > 1e-5) { print \"phi \" NR; exit 1 }
			alt = \$1 <= last ? 0.05 : 0
			if (abs(\$5 - \$18 - alt * \$14) > 1e-8) { print \"h \" NR; exit 1 }
			if (abs(\$19 - \$1 / (N - 1)) > 1e-8) { print \"t \" NR; exit 1 }
			if ((NF == 22) != (NR < N)) { print \"comma \" NR; exit 1 }
		}
		END { if (NR != N) exit 1 }" "$OUT/organs"'
	assert "OBJECT_INDEX, OBJECT and OBJECT_ORGANS agree with the organs" '
		grep "^object," "$OUT/stdout" | while IFS=, read -r _ i name k comma; do
			[ "$(awk -F, -v i="$i" -v o="$name" "\$20 == i && \$2 == o" "$OUT/organs" | wc -l)" -eq "$k" ] || exit 1
		done && [ "$(grep -c "^object," "$OUT/stdout")" -eq 3 ]'
	assert "the header agrees with --info" '
		grep -q "^name=$NAME count=$N model=$MODEL divergence=$(sed -n "s/^divergence: //p" "$OUT/$S.info") seed=7 version=$("$PHYLLO" --version | cut -d" " -f2) scene=$S.cfg objects=3\$" "$OUT/stdout"'
	end
done
done
