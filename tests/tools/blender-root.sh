#!/bin/sh
# blender-root.sh SUITE [DIR] - make a Debian SUITE root (trixie, sid, ...)
# holding that suite's Blender (and gltfpack), for testing our scripts
# and files in the programs artists run; if DIR already has a Blender,
# only adds what a root made before the glTF tests lacks. Needs root and
# debootstrap. DIR defaults to $PHYLLO_ROOTS/SUITE, and PHYLLO_ROOTS to
# /var/cache/phyllo-export (outside the tree, so `make clean` keeps it).
# Run its Blender with tests/tools/in-root.sh DIR blender ARGS.
set -eu
suite=${1:?usage: blender-root.sh SUITE [DIR]}
dir=${2:-${PHYLLO_ROOTS:-/var/cache/phyllo-export}/$suite}

# Blender 5's extension code imports the first two at start-up, and says
# so on every run without them; only a Recommends, so installed by name.
# The glTF importer needs numpy (also only a Recommends), and gltfpack
# 0.21 or newer (Debian 13's) is the one that reads --gltf's instancing.
extras() {
	for p in python3-cattr python3-requests python3-numpy gltfpack; do
		chroot "$dir" sh -c "DEBIAN_FRONTEND=noninteractive apt-get \
			install -y -q --no-install-recommends $p" \
			>>"$dir.log" 2>&1 || :
	done
	chroot "$dir" apt-get clean
}

if [ -x "$dir/usr/bin/blender" ]; then
	# A root made before the glTF tests lacks what they run.
	if [ ! -x "$dir/usr/bin/gltfpack" ] ||
	    [ ! -d "$dir/usr/lib/python3/dist-packages/numpy" ]; then
		extras
	fi
	echo "$dir: Blender already there"
	exit 0
fi
command -v debootstrap >/dev/null ||
	{ echo "blender-root.sh: debootstrap not found: apt-get install debootstrap" >&2; exit 1; }
[ "$(id -u)" -eq 0 ] ||
	{ echo "blender-root.sh: making a root needs root (debootstrap, chroot)" >&2; exit 1; }

# A half-made root from an interrupted run is started afresh.
rm -rf "$dir"
mkdir -p "$dir"
debootstrap --variant=minbase "$suite" "$dir" >"$dir.log" 2>&1 ||
	{ tail "$dir.log" >&2; exit 1; }
# A mirror of a moving suite (sid) may serve a Release file past its
# Valid-Until date; its packages are no less what the suite ships.
chroot "$dir" sh -c 'apt-get -o Acquire::Check-Valid-Until=false update -q &&
	DEBIAN_FRONTEND=noninteractive apt-get install -y -q \
	--no-install-recommends blender' >>"$dir.log" 2>&1 ||
	{ tail "$dir.log" >&2; exit 1; }
extras
echo "$dir: $(chroot "$dir" blender --version 2>/dev/null | head -1)"
