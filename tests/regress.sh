#!/bin/sh
# regress.sh - the regression cases, mandoc's regress/ in small: under
# tests/regress/GROUP/ (a model or a feature), each case NAME.cfg runs
# once for every expected file beside it, and the two are compared:
#	NAME.csv	--csv: numbers to 1e-8 (csv_close), text exactly
#	NAME.info	--info: exactly, but for the output-bytes: line
#	NAME.pov	--pov, exactly
#	NAME.py		--blender, exactly
#	NAME.svg	--svg, exactly
#	NAME.err	a bad scene: exit 1, nothing on stdout, standard
#			error exactly NAME.err, -o's target untouched and no
#			temporary file left beside it
# A good case also exits 0 and prints nothing on standard error.
# NAME.tmpl with NAME.err is a bad template: the same, with it as
# --template for the good scene $TMPL_SCENE.  A group's file "args"
# holds the option its .err cases run with instead of --csv (pov/args:
# --pov).  Sub-folders (parts/, sub/) hold the files cases name.
. tests/lib.sh

TMPL_SCENE=tests/regress/planar/vogel90.cfg

# Under valgrind the exact .pov, .py and .svg are left to the plain run:
# the bytes are the same, scenes.sh and pov.sh run those writers under
# valgrind already, and each run there costs half a second.
EXTS="csv info pov py svg"
if [ -n "$RUN" ]; then
	EXTS="csv info"
	skip "the writers' exact .pov, .py and .svg (the plain run compares them)"
fi

for cfg in tests/regress/*/*.cfg; do
	base=${cfg%.cfg}
	name=${base#tests/regress/}
	for ext in $EXTS; do
		[ -f "$base.$ext" ] || continue
		case $ext in
		py) fmt=--blender ;;
		*) fmt=--$ext ;;
		esac
		try "$name.$ext" px $fmt "$cfg"
		assert "exit 0" '[ $rc -eq 0 ]'
		assert "nothing on stderr" '[ ! -s $OUT/stderr ]'
		case $ext in
		csv) assert "numbers match $base.csv" 'csv_close "$base.csv" "$OUT/stdout" >"$OUT/diff"' ;;
		# Not the size estimates: they follow the templates, and
		# limits.sh holds them against the bytes written.
		info) assert "same as $base.info" 'grep -v "^output-bytes:" "$OUT/stdout" | diff -u "$base.info" - >"$OUT/diff"' ;;
		*) assert "same as $base.$ext" 'diff -u "$base.$ext" "$OUT/stdout" >"$OUT/diff"' ;;
		esac
		end
	done
done

for f in tests/regress/*/*.cfg tests/regress/*/*.tmpl; do
	base=${f%.*}
	[ -f "$base.err" ] || continue
	name=${f#tests/regress/}
	case $f in
	*.tmpl) set -- --template "$f" "$TMPL_SCENE" ;;
	*) set -- "$f" ;;
	esac
	printf 'precious\n' >"$OUT/target"
	# shellcheck disable=SC2046
	try "$name" px $(err_args "$f") -o "$OUT/target" "$@"
	assert "exit 1" '[ $rc -eq 1 ]'
	assert "nothing on stdout" '[ ! -s $OUT/stdout ]'
	assert "message as in $base.err" 'diff -u "$base.err" "$OUT/stderr" >"$OUT/diff"'
	assert "-o target untouched" '[ "$(cat "$OUT/target")" = precious ]'
	assert "no temporary file left" 'no_tmp "$OUT"'
	end
done
