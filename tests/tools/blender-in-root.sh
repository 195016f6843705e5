#!/bin/sh
# blender-in-root.sh ROOT [ARGS...] - run the Blender of a Debian root
# made by tests/tools/blender-root.sh on our files: the current directory is
# bound at the same path inside ROOT, so relative and absolute paths
# under it mean the same file inside and out.  Needs root (chroot).
set -eu
root=${1:?usage: blender-in-root.sh ROOT [ARGS...]}
shift
[ -x "$root/usr/bin/blender" ] ||
	{ echo "blender-in-root.sh: no Blender in $root (tests/tools/blender-root.sh makes one)" >&2; exit 1; }
here=$(pwd -P)
mkdir -p "$root$here"
mount --bind "$here" "$root$here"
trap 'umount "$root$here"' EXIT
trap 'exit 130' INT TERM
chroot "$root" sh -c 'cd "$1" && shift && exec blender "$@"' sh "$here" "$@"
