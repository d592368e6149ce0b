#!/bin/sh
# SPDX-License-Identifier: MIT
# Coverage-guided fuzzing of the parser and every entry point with libFuzzer (clang).
# usage: scripts/fuzz.sh [SECONDS]   (needs a configured ./build for the version header)
set -eu
cd "$(dirname "$0")/.."
secs=${1:-60}
[ -f build/include/circledist_version.h ] || meson setup build >/dev/null
out=build-fuzz
mkdir -p "$out/corpus"
clang -g -O1 -DCDIST_LIBFUZZER -D_GNU_SOURCE -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
  -Iinclude -Ibuild/include -Isrc -Itools \
  src/*.c src/*/*.c tools/query_io.c tests/fuzz/fuzz_entry.c $(pkg-config --cflags --libs gsl) -lm -o "$out/fuzz_entry"
# Seed corpus: a few lines of every shared case file.
for f in tests/data/*.txt examples/queries.txt; do head -n 3 "$f" >"$out/corpus/$(basename "$f")"; done
# -timeout: one input taking longer than 10 s is a bug too (a query must not take minutes).
"$out/fuzz_entry" -max_total_time="$secs" -max_len=4096 -timeout=10 "$out/corpus"
