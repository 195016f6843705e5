#!/usr/bin/env python3
# zip.py - write a zip of files under names of our choosing, for the
# Blender add-on and the release:
#   zip.py [--platform P] [--version V] OUT.zip NAME=FILE ...
# Each FILE goes in as NAME, dated 1980 and in the given order, so that
# the same files make the same zip; a file that may be run keeps its x
# bits.  --platform P makes a blender_manifest.toml an extension for
# platform P alone (Blender's "platforms", as its --split-platforms
# build writes it).  A NAME ending in .txt is for Windows' Notepad: its
# lines end in CR LF, and VERSION in it is --version V's.
import os
import sys
import zipfile


def manifest_for(text, platform):
    """The manifest with platforms = [P] among its top-level keys."""
    lines = text.splitlines(True)
    at = next((i for i, l in enumerate(lines) if l.startswith("[")),
              len(lines))
    while at > 0 and not lines[at - 1].strip():
        at -= 1
    return "".join(lines[:at] + ['platforms = ["%s"]\n' % platform] +
                   lines[at:])


def main(args):
    platform = version = None
    while args[:1] in (["--platform"], ["--version"]) and len(args) > 1:
        if args[0] == "--platform":
            platform = args[1]
        else:
            version = args[1]
        args = args[2:]
    if len(args) < 2 or any("=" not in a for a in args[1:]):
        sys.exit("usage: zip.py [--platform P] [--version V] OUT.zip "
                 "NAME=FILE ...")
    out = args[0]
    with zipfile.ZipFile(out + ".tmp", "w", zipfile.ZIP_DEFLATED) as z:
        for arg in args[1:]:
            name, path = arg.split("=", 1)
            with open(path, "rb") as f:
                data = f.read()
            if platform and os.path.basename(name) == "blender_manifest.toml":
                data = manifest_for(data.decode("utf-8"), platform).encode()
            if name.endswith(".txt"):
                if version:
                    data = data.replace(b"VERSION", version.encode())
                data = data.replace(b"\r\n", b"\n").replace(b"\n", b"\r\n")
            info = zipfile.ZipInfo(name, (1980, 1, 1, 0, 0, 0))
            info.compress_type = zipfile.ZIP_DEFLATED
            mode = 0o755 if os.access(path, os.X_OK) else 0o644
            info.external_attr = (0o100000 | mode) << 16
            z.writestr(info, data)
    os.replace(out + ".tmp", out)


if __name__ == "__main__":
    main(sys.argv[1:])
