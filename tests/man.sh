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
