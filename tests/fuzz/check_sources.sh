#!/bin/sh
# SPDX-License-Identifier: MIT
# The sources scripts/fuzz.sh compiles (its --list, read from meson.build) are exactly the .c
# files under src/: the libFuzzer build cannot silently drop a library file. The build itself
# runs in scripts/test.sh (clang is not needed here).
# usage: check_sources.sh SOURCE_ROOT
set -eu
root=$1
listed=$(sh "$root/scripts/fuzz.sh" --list | sort)
present=$(cd "$root" && find src -name '*.c' | sort)
if [ "$listed" != "$present" ]; then
  echo "scripts/fuzz.sh compiles:"; echo "$listed"
  echo "src/ has:"; echo "$present"
  echo "fuzz-sources: 0 passed, 1 failed"
  exit 1
fi
echo "fuzz-sources: $(echo "$listed" | wc -l) files; 1 passed, 0 failed"
