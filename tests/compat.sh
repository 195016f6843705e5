#!/bin/sh
# compat.sh - what differs between systems stays in src/compat/: no
# other file calls the system's file, process, signal or terminal calls
# by name (on Windows they would miss UTF-8 names, "the same file" and
# replacing a file another program has open), and none asks which
# system it is built for; configure's test programs say what a system
# has (HAVE_* flags).  A file new from another branch is held to it too.
. tests/lib.sh

CALLS='fopen|freopen|stat|lstat|access|unlink|rename|remove|open|creat|opendir|readlink|realpath|mkstemp|tmpfile|isatty|kill|getpid|signal|sigaction|sigprocmask|fchmod|fchown|umask|chmod'
try "only src/compat/ calls the system's calls that take names, processes, signals and terminals" true
found=$(grep -nE "(^|[^A-Za-z0-9_.>])($CALLS)[[:space:]]*\(" src/*.c src/*/*.c src/*.h src/*/*.h |
	grep -v '^src/compat/' | grep -vE ':[0-9]+:[[:space:]]*(/?\*|//)')
assert "none elsewhere (${found:-})" '[ -z "$found" ]'
end

try "no file outside src/compat/ asks which system it is built for" true
found=$(grep -nE '^[[:space:]]*#[[:space:]]*(if|ifdef|ifndef|elif).*(__linux__|_WIN32|_WIN64|__MINGW|__APPLE__|__MACH__|__GLIBC__|__unix__|__FreeBSD__|__OpenBSD__|_MSC_VER)' \
	src/*.c src/*/*.c src/*.h src/*/*.h | grep -v '^src/compat/')
assert "none (${found:-})" '[ -z "$found" ]'
end

try "compat_posix.c and compat_win32.c each define every function compat.h declares" true
for f in $(sed -n 's/^[A-Za-z].*[ *]\(sys_[a-z_]*\)(.*/\1/p' src/compat/compat.h | sort -u); do
	for c in src/compat/compat_posix.c src/compat/compat_win32.c; do
		grep -q "^$f(" "$c" || bad="$bad; $c lacks $f"
	done
done
assert "compat.h declares them" '[ $(sed -n "s/^[A-Za-z].*[ *]\(sys_[a-z_]*\)(.*/\1/p" src/compat/compat.h | sort -u | wc -l) -ge 15 ]'
end
