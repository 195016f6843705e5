#!/bin/sh
# libconfig.sh TARGET DIR - the static libconfig a cross build links,
# made from Debian's own source package: DIR/include/libconfig.h and
# DIR/lib/libconfig.a.  TARGET is windows-x64 (Debian's mingw-w64) or
# wasm (Debian's emscripten).  Nothing of libconfig is kept in our tree:
# the source package is fetched with apt-get source through a sources
# list of DIR's own (the machine's apt configuration is only read for
# its keyring), checked against Debian's signed index, and unpacked
# into DIR/src.  A second run with DIR/lib/libconfig.a there does nothing.
set -eu
target=${1:?usage: libconfig.sh windows-x64|wasm DIR}
dir=${2:?usage: libconfig.sh windows-x64|wasm DIR}
case $dir in /*) ;; *) dir=$(pwd)/$dir ;; esac

case $target in
windows-x64)
	host=x86_64-w64-mingw32
	need=$host-gcc wrap= ;;
wasm)
	# libconfig's config.sub (2014) knows no emscripten: any cross host
	# makes its configure use emcc's CC without running what it builds.
	host=i686-pc-linux-gnu
	need=emcc wrap=emconfigure ;;
*)
	echo "libconfig.sh: unknown target '$target' (windows-x64 or wasm)" >&2
	exit 2 ;;
esac

[ -f "$dir/lib/libconfig.a" ] && exit 0
command -v "$need" >/dev/null 2>&1 || {
	case $target in
	windows-x64) pkg=gcc-mingw-w64-x86-64 ;;
	wasm) pkg=emscripten ;;
	esac
	echo "libconfig.sh: $need not found: apt-get install $pkg" >&2
	exit 1
}
command -v dpkg-source >/dev/null 2>&1 || {
	echo "libconfig.sh: dpkg-source not found: apt-get install dpkg-dev" >&2
	exit 1
}

# The suite this machine runs, so the library is the one its own
# libconfig-dev is built from.
suite=$(sed -n 's/^VERSION_CODENAME=//p' /etc/os-release 2>/dev/null)
apt=$dir/apt
rm -rf "$dir/src" "$apt"
mkdir -p "$apt/lists/partial" "$apt/cache/archives/partial" "$dir/src"
echo "deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg]" \
	"http://deb.debian.org/debian ${suite:-bookworm} main" >"$apt/sources.list"
set -- -o Dir::Etc::SourceList="$apt/sources.list" \
	-o Dir::Etc::SourceParts=/dev/null -o Dir::State::Lists="$apt/lists" \
	-o Dir::Cache="$apt/cache" -o Debug::NoLocking=1 \
	-o APT::Sandbox::User=root
log=$dir/build.log
echo "libconfig.sh: fetching Debian's libconfig source (log: $log)"
{
	apt-get "$@" -q update &&
	(cd "$dir/src" && apt-get "$@" -q source --download-only libconfig) &&
	(cd "$dir/src" && dpkg-source -x libconfig_*.dsc libconfig)
} >"$log" 2>&1 || { tail "$log" >&2; exit 1; }

echo "libconfig.sh: building it for $target"
{
	cd "$dir/src/libconfig" &&
	$wrap ./configure --host=$host --prefix="$dir" --disable-shared \
		--enable-static --disable-cxx --disable-examples &&
	${wrap:+emmake} make -C lib &&
	make -C lib install
} >>"$log" 2>&1 || { tail "$log" >&2; exit 1; }
rm -rf "$dir/src" "$apt"
