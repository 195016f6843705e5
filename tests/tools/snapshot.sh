#!/bin/sh
# snapshot.sh PROG DIR - write every writer's output for every scene file
# under scenes/ and tests/ into DIR, each beside its standard error and
# exit status (NAME.FORMAT, NAME.FORMAT.err).  A change that must not
# change output (moving code, splitting a file) is proven by a snapshot
# before and after it, from the same tree of scenes, and diff -r of the
# two.  About 30 MB and 10 s; nothing of it is kept in the repository,
# since checksums or copies of it would pin libm's last bits on one
# machine.
prog=${1:?usage: snapshot.sh PROG DIR}
dir=${2:?usage: snapshot.sh PROG DIR}
find scenes tests -name '*.cfg' ! -path 'tests/out/*' | sort |
while read -r cfg; do
	base=$dir/${cfg%.cfg}
	mkdir -p "$(dirname "$base")" || exit 1
	for w in csv info pov pov-arrays blender blender-objects svg gltf \
	    settings cfg; do
		case $w in
		pov-arrays) set -- --pov --arrays ;;
		blender-objects) set -- --blender --blender-objects ;;
		*) set -- "--$w" ;;
		esac
		timeout 120 "$prog" "$@" "$cfg" >"$base.$w" 2>"$base.$w.err"
		echo "exit $?" >>"$base.$w.err"
	done
done
