# lib.sh - sourced by the test scripts: result lines, try/assert, helpers.
# Each check prints "ok - WHAT" or "not ok - WHAT"; run.sh counts them.

: "${PHYLLO:=./phyllo-export}" "${RUN:=}" "${TESTBIN:=build}"
OUT=tests/out/$(basename "$0" .sh)
rm -rf "$OUT" && mkdir -p "$OUT" || exit 1

# printf, not echo: dash's echo would turn a \n in a name into a newline.
ok() { printf 'ok - %s\n' "$*"; }
notok() { printf 'not ok - %s\n' "$*"; }
skip() { printf 'ok - # SKIP %s\n' "$*"; }

# px ARGS: run phyllo-export, under valgrind when RUN says so.
px() {
	# shellcheck disable=SC2086
	$RUN "$PHYLLO" "$@"
}

# try WHAT CMD...: run CMD keeping $rc, $OUT/stdout and $OUT/stderr;
# the asserts that follow collect failures and "end" reports them.
try() {
	what=$1
	shift
	bad=
	"$@" >"$OUT/stdout" 2>"$OUT/stderr"
	rc=$?
}
assert() {
	eval "$2" || bad="$bad; $1"
}
# refused MESSAGE: the command just tried was a usage error: exit 2, and
# MESSAGE (a grep pattern) on standard error.
refused() {
	msg=$1
	assert "exit 2" '[ $rc -eq 2 ]'
	assert "says \"$msg\"" 'grep -q -- "$msg" "$OUT/stderr"'
}
end() {
	if [ -z "$bad" ]; then
		ok "$what"
	else
		notok "$what:$bad (exit $rc; stderr: $(head -c 300 "$OUT/stderr"))"
	fi
}

# no_tmp DIR: no temporary file of -o's (FILE.phyllo-export-PID.tmp)
# is left in DIR.
no_tmp() {
	[ -z "$(ls -A "$1" | grep '\.phyllo-export-[0-9]*\.tmp$')" ]
}

# csv_close A B [TOL]: same CSV, numbers equal within TOL, 1e-8 (our 9
# digits print to 5e-9), relative
# to max(1, |value|)); text fields must match exactly.
csv_close() {
	awk -F, -v tol="${3:-1e-8}" '
	NR == FNR { a[FNR] = $0; na = FNR; next }
	{
		if (!(FNR in a)) { print "extra line " FNR; bad = 1; exit }
		n = split(a[FNR], f, ",")
		if (n != NF) { print "line " FNR ": " n " vs " NF " fields"; bad = 1; exit }
		for (i = 1; i <= NF; i++) {
			if (f[i] ~ /^-?[0-9.]+(e[-+]?[0-9]+)?$/) {
				d = f[i] - $i; if (d < 0) d = -d
				m = $i < 0 ? -$i : $i; if (m < 1) m = 1
				if (d > tol * m) { print "line " FNR " field " i ": " f[i] " vs " $i; bad = 1; exit }
			} else if (f[i] != $i) { print "line " FNR " field " i ": " f[i] " vs " $i; bad = 1; exit }
		}
	}
	END { if (!bad && FNR != na) { print "missing lines"; bad = 1 } exit bad }
	' "$1" "$2"
}

# err_args FILE: the option a bad case of tests/regress/GROUP/ runs
# with: the group's file "args" holds it, else --csv.
err_args() {
	cat "${1%/*}/args" 2>/dev/null || echo --csv
}

# use_blender B: bl then runs Blender B, a command, or a Debian root made
# by tests/tools/blender-root.sh (through tests/tools/in-root.sh).
use_blender() {
	if [ -d "$1" ]; then
		BL_ROOT=$1
	else
		BL_ROOT= BL_CMD=$1
	fi
}
bl() {
	if [ -n "$BL_ROOT" ]; then
		sh tests/tools/in-root.sh "$BL_ROOT" blender "$@"
	else
		"$BL_CMD" "$@"
	fi
}
