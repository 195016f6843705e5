#!/bin/sh
# layers.sh - the folders of src/ stand in the data's order, and nothing
# calls back up: every #include "..." of src/**/*.c and .h names a file
# of its own folder or of one below it in the order HACKING.md gives
# (its line "Layers, bottom to top:"; src/ itself, main.c's, on top),
# no folders include each other round a cycle, and no two files do
# (a file and its header, NAME.c and NAME.h, counting as one).  Not C:
# src/web, src/viewer, src/phyllo_import; src/compat/test-*.c are
# configure's test programs.
. tests/lib.sh

# "from to" for every include, paths from src/ ("base/diag.c base/diag.h").
find src -name '*.[ch]' ! -path 'src/web/*' ! -path 'src/viewer/*' \
    ! -path 'src/phyllo_import/*' ! -path 'src/compat/test-*' | sort |
while read -r f; do
	sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$f" |
	while read -r inc; do
		printf '%s %s\n' "${f#src/}" "$inc"
	done
done >"$OUT/includes"
order=$(sed -n 's/^Layers, bottom to top: *//p' HACKING.md | tr -d '`<' | tr -s ' ')

try "every include names a file of src/ (paths from src/, as -Isrc finds them)" true
while read -r from inc; do
	[ -f "src/$inc" ] || bad="$bad; $from includes \"$inc\", not a file of src/"
done <"$OUT/includes"
assert "some includes read" '[ $(wc -l <"$OUT/includes") -gt 100 ]'
end

# graph KIND: the cycles of the graph of folders (KIND folders) or of
# files (KIND files, NAME.c and NAME.h one node) from the includes, one
# a line ("a -> b -> a"); nothing when there is none.  Nodes that reach
# no cycle are taken off, those pointing only at nodes taken off, until
# none is left or every one left points at one left: then a walk from
# any of them comes round.
graph() {
	awk -v kind="$1" '
	function node(p) {
		if (kind == "files")
			return substr(p, 1, length(p) - 2)
		if (p !~ /\//)
			return "src"
		sub(/\/[^\/]*$/, "", p)
		return p
	}
	{
		a = node($1); b = node($2)
		nodes[a]; nodes[b]
		if (a != b && !((a, b) in edge)) {
			edge[a, b]; out[a]++; to[a, out[a]] = b
		}
	}
	function prune(   n, i, left, gone) {
		do {
			gone = 0
			for (n in nodes) {
				if (n in off)
					continue
				left = 0
				for (i = 1; i <= out[n]; i++)
					if (!(to[n, i] in off))
						left++
				if (left == 0) {
					off[n]; gone++
				}
			}
		} while (gone > 0)
	}
	END {
		prune()
		for (n in nodes) {
			if (n in off)
				continue
			# A walk through nodes left comes round to one it met.
			split("", met); path = ""; m = n; k = 0
			while (!(m in met)) {
				met[m] = ++k; seq[k] = m
				for (i = 1; i <= out[m]; i++)
					if (!(to[m, i] in off)) {
						m = to[m, i]
						break
					}
			}
			for (i = met[m]; i <= k; i++)
				path = path seq[i] " -> "
			print path m
			for (i = met[m]; i <= k; i++)
				off[seq[i]]
			prune()
		}
	}' "$OUT/includes"
}

try "no folders of src/ include each other round a cycle (src/ itself one)" true
cycles=$(graph folders)
assert "none (${cycles:-})" '[ -z "$cycles" ]'
end

try "no files include each other round a cycle (NAME.c and NAME.h one)" true
cycles=$(graph files)
assert "none (${cycles:-})" '[ -z "$cycles" ]'
end

try "every include names its own folder or one below it, in HACKING.md's order" true
assert "HACKING.md gives the order" '[ $(echo $order | wc -w) -ge 5 ]'
for d in $order; do
	if [ "$d" = src ]; then
		ls src/*.c >/dev/null 2>&1 || bad="$bad; no file is in src/ itself"
	elif [ ! -d "src/$d" ]; then
		bad="$bad; src/$d in the order is no folder"
	fi
done
wrong=$(awk -v order="$order" '
	function folder(p) {
		if (p !~ /\//)
			return "src"
		sub(/\/[^\/]*$/, "", p)
		return p
	}
	BEGIN { n = split(order, o, " "); for (i = 1; i <= n; i++) rank[o[i]] = i }
	{
		a = folder($1); b = folder($2)
		if (!(a in rank))
			print "src/" $1 ": its folder is not in the order"
		else if (!(b in rank))
			print "src/" $1 " includes " $2 ", of a folder not in the order"
		else if (rank[b] > rank[a])
			print "src/" $1 " includes " $2 ", of a folder above its own"
	}' "$OUT/includes" | sort -u | tr '\n' ';')
assert "none upward (${wrong:-})" '[ -z "$wrong" ]'
end
