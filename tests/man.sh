#!/bin/sh
# man.sh - the man pages are clean mdoc, and phyllo-export(5) lists
# exactly the settings of the tables (src/scene/settings.c, each model's own
# file in src/models/, src/geometry/receptacle.c), with their types and defaults.
. tests/lib.sh

if [ -n "${MANDOC:-}" ]; then
	try "man pages are clean under mandoc -Tlint" "$MANDOC" -Tlint -Wwarning man/phyllo-export.1 man/phyllo-export.5
	assert "no messages" '[ ! -s $OUT/stdout ] && [ ! -s $OUT/stderr ]'
	end
else
	skip "mandoc not found: man page lint"
fi

# Each setting is an ".It Cm PATH Ar TYPE Pq default Li VALUE" line.
"$TESTBIN/settings_list" >"$OUT/table"
sed -n 's/^\.It Cm \([a-z.]*\) Ar \([a-z]*\)\( Pq default Li \(.*\)\)\{0,1\}$/\1	\2	\4/p' \
	man/phyllo-export.5 >"$OUT/man"
try "phyllo-export(5) lists every setting of the table with type and default" diff -u "$OUT/table" "$OUT/man"
assert "same list" '[ $rc -eq 0 ]'
end

# What the pages say, as a reader sees it: mdoc's quoting macros nest
# where a Ql runs into the next (‘500M, ‘1.5G’’), and a parenthesis
# opened inside .Pq closes early; an example must not write into the
# tree (povray +Iscenes/x.pov alone writes scenes/x.png, a tracked file).
if [ -n "${MANDOC:-}" ]; then
	for page in man/phyllo-export.1 man/phyllo-export.5; do
		"$MANDOC" -Tutf8 "$page" 2>/dev/null | sed 's/.\x08//g' >"$OUT/page.txt"
		try "$page: no quotes inside quotes, as nested Ql macros make" true
		assert "none" '! grep -n "‘[^’]*‘" $OUT/page.txt'
		end
		try "$page: every paragraph's parentheses balance" true
		# (Half-open intervals, [0, 1) and (0, 4], are no parentheses.)
		assert "each closes what opened" 'awk "BEGIN { RS = \"\" } { t = \$0; gsub(/\\[[^]()[]*\\)|\\([^]()[]*\\]/, \"\", t); o = gsub(/\\(/, \"\", t); c = gsub(/\\)/, \"\", t); if (o != c) { print; bad = 1 } } END { exit bad }" $OUT/page.txt'
		end
	done
else
	skip "mandoc not found: the pages as rendered"
fi
try "the examples render POV-Ray scenes to files of their own (+O), not beside the tree's" true
assert "every povray +I has its +O" '! grep "^\$ povray" man/phyllo-export.1 README.md | grep -v "+O"'
end
