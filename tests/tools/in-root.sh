#!/bin/sh
# in-root.sh ROOT PROGRAM [ARGS...] - run a program of a Debian root made
# by tests/tools/blender-root.sh (blender, gltfpack) on our files: the
# current directory is bound at the same path inside ROOT, so relative
# and absolute paths under it mean the same file inside and out.  Needs
# root (chroot).
set -eu
root=${1:?usage: in-root.sh ROOT PROGRAM [ARGS...]}
prog=${2:?usage: in-root.sh ROOT PROGRAM [ARGS...]}
shift 2
[ -x "$root/usr/bin/$prog" ] ||
	{ echo "in-root.sh: no $prog in $root (tests/tools/blender-root.sh installs it)" >&2; exit 1; }
here=$(pwd -P)
mkdir -p "$root$here"
mount --bind "$here" "$root$here"
trap 'umount "$root$here"' EXIT
trap 'exit 130' INT TERM
chroot "$root" sh -c 'cd "$1" && shift && exec "$@"' sh "$here" "$prog" "$@"
