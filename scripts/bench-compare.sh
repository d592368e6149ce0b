#!/bin/sh
# SPDX-License-Identifier: MIT
# Before/after speed: builds REV (release) in a temporary git worktree and the current tree
# (release) in a temporary build directory, compiles the CURRENT bench/bench_all.c +
# tools/query_io.c against each library (with that library's own header), runs both in this
# session (before, after, before, after; min of the two runs per row) and prints
# kind method file family before_ns after_ns after/before.
# REV must have every public function tools/query_io.c calls.
# usage: scripts/bench-compare.sh REV [bench_all options, e.g. --kinds=cc,lc --reps=3]
set -eu
[ $# -ge 1 ] || { echo "usage: scripts/bench-compare.sh REV [bench_all options]" >&2; exit 2; }
rev=$1
shift
root=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
cleanup() { git -C "$root" worktree remove --force "$tmp/old" 2>/dev/null || true; rm -rf "$tmp"; }
trap cleanup EXIT
git -C "$root" worktree add --detach "$tmp/old" "$rev" >/dev/null
CC=${CC:-cc}
build() { # NAME SOURCE_DIR
  meson setup "$tmp/build-$1" "$2" --buildtype=release >/dev/null
  meson compile -C "$tmp/build-$1" >/dev/null
  lib=$(dirname "$(find "$tmp/build-$1" -maxdepth 2 -name 'libcircledist.so.1' | head -1)")
  # tools/query_io.c leaves out the swept kinds for a library that has none
  extra=""
  grep -q cdist_torus_torus "$2/include/circledist.h" || extra="-DCDQ_NO_SWEPT"
  "$CC" -std=c17 -D_GNU_SOURCE -O2 $extra -I "$2/include" -I "$tmp/build-$1/include" -I "$root/tools" \
    "$root/bench/bench_all.c" "$root/tools/query_io.c" -L "$lib" -lcircledist -lm \
    -Wl,-rpath,"$lib" -o "$tmp/bench-$1"
}
build old "$tmp/old"
build new "$root"
for run in 1 2; do
  for side in old new; do
    "$tmp/bench-$side" --csv "$tmp/$side-$run.csv" "$@" "$root/tests/data" >/dev/null
  done
done
python3 - "$rev" "$tmp" <<'PY'
import csv, sys
rev, tmp = sys.argv[1], sys.argv[2]
def load(side):
    best = {}
    for run in (1, 2):
        for r in csv.DictReader(open("%s/%s-%d.csv" % (tmp, side, run))):
            k = (r["kind"], r["method"], r["file"], r["family"])
            v = float(r["mean_ns"]), float(r["max_ns"] or "nan")
            best[k] = tuple(min(a, b) for a, b in zip(best.get(k, v), v))
    return best
old, new = load("old"), load("new")
print("%-4s %-10s %-6s %-30s %12s %12s %7s %12s %12s" % ("kind", "method", "file", "family",
      "mean before", "mean after", "ratio", "max before", "max after"))
for k in new:
    if k not in old:
        print("%-4s %-10s %-6s %-30s %12s %12.1f" % (k + ("-", new[k][0])))
        continue
    (ob, om), (nb, nm) = old[k], new[k]
    print("%-4s %-10s %-6s %-30s %12.1f %12.1f %7.2f %12s %12s" % (k + (ob, nb, nb / ob,
          "-" if om != om else "%.1f" % om, "-" if nm != nm else "%.1f" % nm)))
print("(before = %s, after = working tree; ns/query, min of 2 runs x bench_all repeats)" % rev)
PY
