#!/bin/sh
# SPDX-License-Identifier: MIT
# The README's accuracy and speed table, measured now: for every kind with reference files, the
# largest error of the AUTO method against tests/data (refcheck: |d - d_ref| / L) and the time
# per query (bench_all: thread CPU time, minimum of repeats; random-file mean, hard-file mean and
# max). Prints a Markdown table and the load average at the start.
# usage: scripts/readme-numbers.sh [BUILD_DIR]   (a release build: meson setup build --buildtype=release)
set -eu
cd "$(dirname "$0")/.."
build=${1:-build}
data=tests/data
echo "load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
bench=$(mktemp)
trap 'rm -f "$bench"' EXIT
"$build/bench/bench_all" --reps=3 "$data" >"$bench"
echo
echo "| kind | max error, random / hard | time, random mean | hard mean / max |"
echo "| --- | --- | --- | --- |"
for kind in pc pd lc rc sc ld rd sd cc cd dd ac aa sa ad hc hd bc bd; do
  err() { "$build/tests/refcheck" --tol=1 "$data/${kind}_$1.txt" "$data/${kind}_$1.expected" |
    sed -n 's/.*max error \([^ ]*\) of scale.*/\1/p' | head -n 1; }
  t() { awk -v k="$kind" -v f="$1" -v c="$2" '$1 == k && $2 == "auto" && $3 == f && $4 == "all" { print $c }' "$bench"; }
  ns() { awk -v x="$1" 'BEGIN { if (x >= 1000) printf "%.2f µs", x / 1000; else printf "%.0f ns", x }'; }
  echo "| $kind | $(err random) / $(err hard) | $(ns "$(t random 6)") | $(ns "$(t hard 6)") / $(ns "$(t hard 7)") |"
done
