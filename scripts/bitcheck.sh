#!/bin/sh
# SPDX-License-Identifier: MIT
# Every answer of the circledist tool TOOL, to the last bit (JSON, %.17g), on every
# tests/data/*.txt file for every method, one thread and through cdist_batch (-j 2), and on a
# fixed random file of the swept kinds; written to OUTDIR (one file per input and mode).
# Two trees answer identically when `diff -r` of their OUTDIRs is empty:
#   scripts/bitcheck.sh old/build/circledist /tmp/old; scripts/bitcheck.sh build/circledist /tmp/new
#   diff -r /tmp/old /tmp/new
# usage: scripts/bitcheck.sh TOOL OUTDIR
set -eu
[ $# -eq 2 ] || { echo "usage: scripts/bitcheck.sh TOOL OUTDIR" >&2; exit 2; }
tool=$1
out=$2
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
/usr/bin/python3 - "$out/swept.txt" <<'PY'
import random, sys
rng = random.Random(20261126)
def u():
    while True:
        v = [rng.gauss(0, 1) for _ in range(3)]
        n = sum(x * x for x in v) ** 0.5
        if n > 1e-3:
            return [x / n for x in v]
def p(s=3.0): return [rng.uniform(-s, s) for _ in range(3)]
def torus(): return p() + u() + [rng.uniform(0.5, 2), rng.uniform(0.05, 0.4)]
def capsule(): return p() + p() + [rng.uniform(0.05, 0.5)]
def sphere(): return p() + [rng.uniform(0.05, 1)]
def rdisk(): return p() + u() + [rng.uniform(0.2, 2), rng.uniform(0.02, 0.3)]
def line(): return p() + u()
def seg(): return p() + p()
kinds = {"TT": (torus, torus), "TK": (torus, capsule), "TS": (torus, sphere), "TR": (torus, rdisk),
         "KK": (capsule, capsule), "KS": (capsule, sphere), "KR": (capsule, rdisk),
         "SS": (sphere, sphere), "SR": (sphere, rdisk), "RR": (rdisk, rdisk),
         "Tl": (torus, line), "Tr": (torus, line), "Ts": (torus, seg)}
with open(sys.argv[1], "w") as f:
    for k, (a, b) in kinds.items():
        for _ in range(200):
            f.write(k + " " + " ".join(repr(x) for x in a() + b()) + "\n")
PY
for f in "$root"/tests/data/*.txt "$out/swept.txt"; do
  name=$(basename "$f" .txt)
  # a list of reference lines, not queries (its error messages would name the checkout)
  [ "$name" = revision2_recomputed ] && continue
  for m in auto polynomial robust iteration; do
    "$tool" --format=json --no-header --method=$m "$f" > "$out/$name.$m.json" 2>&1 || true
  done
  "$tool" --format=json --no-header -j 2 "$f" > "$out/$name.batch.json" 2>&1 || true
done
