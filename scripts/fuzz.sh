#!/bin/sh
# SPDX-License-Identifier: MIT
# Coverage-guided fuzzing of the parser and every entry point with libFuzzer (clang), under
# ASan and UBSan. The library's sources are the list in meson.build (lib_sources), so a moved or
# added file is fuzzed without editing this script. Exits non-zero when the build fails or the
# fuzzer reports anything (a contract violation aborts; see tests/fuzz/fuzz_entry.c).
# usage: scripts/fuzz.sh [SECONDS] [extra libFuzzer options...]
#        scripts/fuzz.sh --list   (prints the library sources it compiles, and exits)
#   FUZZ_OUT=DIR    build and corpus directory (default build-fuzz; the corpus is kept there)
#   FUZZ_TIMEOUT=S  seconds one input may take before it is reported (default 10)
#   CC_FUZZ=PATH    the clang to use (default clang, else clang-14)
#   FUZZ_SANITIZE=L sanitizers besides fuzzer (default address,undefined; "undefined" at -O2
#                   runs many times faster, for long runs that count executions)
set -eu
cd "$(dirname "$0")/.."
secs=${1:-60}
[ $# -gt 0 ] && shift
out=${FUZZ_OUT:-build-fuzz}
# The library's sources: the files(...) block that starts at "lib_sources = files(".
srcs=$(sed -n '/^lib_sources = files(/,/^)/p' meson.build | grep -o "'src/[^']*\.c'" | tr -d "'")
[ -n "$srcs" ] || { echo "fuzz.sh: no library sources found in meson.build" >&2; exit 1; }
for f in $srcs; do [ -f "$f" ] || { echo "fuzz.sh: $f (from meson.build) is missing" >&2; exit 1; }; done
if [ "$secs" = --list ]; then
  printf '%s\n' $srcs
  exit 0
fi
[ -f build/include/circledist_version.h ] || meson setup build >/dev/null
mkdir -p "$out/corpus"
# The project's own flags (meson.build): _GNU_SOURCE, no fp contraction, no math errno.
# shellcheck disable=SC2086
san=${FUZZ_SANITIZE-address,undefined}
opt=-O1
case "$san" in *address*) ;; *) opt=-O2 ;; esac
${CC_FUZZ:-$(command -v clang || command -v clang-14)} -std=c17 -g $opt -DCDIST_LIBFUZZER -D_GNU_SOURCE -ffp-contract=off -fno-math-errno -pthread \
  -fsanitize=fuzzer${san:+,$san} -fno-sanitize-recover=all \
  -Iinclude -Ibuild/include -Isrc -Itools \
  $srcs tools/query_io.c tests/fuzz/fuzz_entry.c -lm -o "$out/fuzz_entry"
# Seed corpus: a few lines of every shared case file.
for f in tests/data/*.txt examples/queries.txt; do head -n 3 "$f" >"$out/corpus/$(basename "$f")"; done
# -timeout: one input taking longer than this is a bug too (a query must not take minutes).
# Crash reproducers go to $out (artifact_prefix), not the source tree.
"$out/fuzz_entry" -max_total_time="$secs" -max_len=4096 -timeout="${FUZZ_TIMEOUT:-10}" \
  -artifact_prefix="$out/" -print_final_stats=1 "$@" "$out/corpus"
