#!/bin/sh
# golden.sh - tests/golden/NAME.cfg against NAME.csv (numbers compared
# to 1e-8) and NAME.info (exact); tests/bad/NAME.cfg against NAME.err
# (exact), with exit 1, nothing on stdout, and -o's target untouched;
# tests/bad-pov/NAME.cfg and NAME.tmpl the same with --pov (the latter
# as --template for a good scene); tests/bad-gltf/NAME.cfg the same with
# --gltf, the organ meshes (OBJ and .mtl files) it names being bad.
. tests/lib.sh

for cfg in tests/golden/*.cfg; do
	base=${cfg%.cfg}
	name=$(basename "$base")
	if [ -f "$base.csv" ]; then
		try "golden $name.csv" px --csv "$cfg"
		assert "exit 0" '[ $rc -eq 0 ]'
		assert "nothing on stderr" '[ ! -s $OUT/stderr ]'
		assert "numbers match $base.csv" 'csv_close "$base.csv" "$OUT/stdout" >"$OUT/diff"'
		end
	fi
	if [ -f "$base.info" ]; then
		try "golden $name.info" px --info "$cfg"
		assert "exit 0" '[ $rc -eq 0 ]'
		# Not the size estimates: they follow the templates, and
		# limits.sh holds them against the bytes written.
		assert "same as $base.info" 'grep -v "^output-bytes:" "$OUT/stdout" | diff -u "$base.info" - >"$OUT/diff"'
		end
	fi
done

for cfg in tests/bad/*.cfg; do
	base=${cfg%.cfg}
	name=$(basename "$base")
	printf 'precious\n' >"$OUT/target"
	try "bad $name" px --csv -o "$OUT/target" "$cfg"
	assert "exit 1" '[ $rc -eq 1 ]'
	assert "nothing on stdout" '[ ! -s $OUT/stdout ]'
	assert "message as in $base.err" 'diff -u "$base.err" "$OUT/stderr" >"$OUT/diff"'
	assert "-o target untouched" '[ "$(cat "$OUT/target")" = precious ]'
	assert "no temporary file left" '[ -z "$(ls -A "$OUT" | grep "^\.target")" ]'
	end
done

for f in tests/bad-pov/*.cfg tests/bad-pov/*.tmpl; do
	base=${f%.*}
	name=$(basename "$f")
	case $f in
	*.tmpl) set -- --pov --template "$f" tests/golden/vogel90.cfg ;;
	*) set -- --pov "$f" ;;
	esac
	printf 'precious\n' >"$OUT/target"
	try "bad --pov $name" px -o "$OUT/target" "$@"
	assert "exit 1" '[ $rc -eq 1 ]'
	assert "nothing on stdout" '[ ! -s $OUT/stdout ]'
	assert "message as in $base.err" 'diff -u "$base.err" "$OUT/stderr" >"$OUT/diff"'
	assert "-o target untouched" '[ "$(cat "$OUT/target")" = precious ]'
	end
done

for cfg in tests/bad-gltf/*.cfg; do
	base=${cfg%.cfg}
	name=$(basename "$base")
	printf 'precious\n' >"$OUT/target"
	try "bad --gltf $name" px --gltf -o "$OUT/target" "$cfg"
	assert "exit 1" '[ $rc -eq 1 ]'
	assert "nothing on stdout" '[ ! -s $OUT/stdout ]'
	assert "message as in $base.err" 'diff -u "$base.err" "$OUT/stderr" >"$OUT/diff"'
	assert "-o target untouched" '[ "$(cat "$OUT/target")" = precious ]'
	end
done
