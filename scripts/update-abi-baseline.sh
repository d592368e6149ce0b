#!/bin/sh
# SPDX-License-Identifier: MIT
# Regenerates the ABI baseline abi/libcircledist.so.1.abi from a build with debug info (the
# functions and types that test abi/abidiff then holds the library to). Run at a release, after
# the version script and the header are final (docs/abi.md).
# usage: scripts/update-abi-baseline.sh [BUILD_DIR]   (default build-abi, created if missing)
set -eu
cd "$(dirname "$0")/.."
build=${1:-build-abi}
[ -d "$build" ] || meson setup "$build" --buildtype=debugoptimized -Ddefault_library=shared
meson compile -C "$build" circledist:shared_library
lib="$build/libcircledist.so.1"
readelf -S -W "$lib" | grep -q '\.debug_info' ||
  { echo "$lib has no debug info: use a debug or debugoptimized build" >&2; exit 1; }
mkdir -p abi
abidw --no-corpus-path --no-comp-dir-path --short-locs --drop-private-types --headers-dir include \
  --type-id-style hash --out-file abi/libcircledist.so.1.abi "$lib"
echo "wrote abi/libcircledist.so.1.abi ($(grep -c '<elf-symbol ' abi/libcircledist.so.1.abi) symbols)"
