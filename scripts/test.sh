#!/bin/sh
# SPDX-License-Identifier: MIT
# The whole test suite: a release-style build and an ASan/UBSan build, every meson test in
# both except the `slow` suite (long brute-force runs), which runs too when CIRCLEDIST_SLOW=1
# (as .ci/run does), together with a static-only build; the threaded tests under
# ThreadSanitizer; and libFuzzer through scripts/fuzz.sh (20000 inputs from seed 1; 150000 with CIRCLEDIST_SLOW=1). Prints a closing "N passed, N failed" line.
# usage: [CIRCLEDIST_SLOW=1] scripts/test.sh
set -u
cd "$(dirname "$0")/.."
total_ok=0
total_fail=0
count() { # DIR: add the results of the last meson test run in DIR
  log="$1/meson-logs/testlog.json"
  ok=$(grep -c '"result": "OK"' "$log" 2>/dev/null || true)
  fail=$(grep -c '"result": "\(FAIL\|TIMEOUT\|ERROR\)"' "$log" 2>/dev/null || true)
  total_ok=$((total_ok + ok))
  total_fail=$((total_fail + fail))
}
run_suite() { # DIR [meson -D options...]
  dir=$1
  shift
  if [ ! -d "$dir" ]; then
    meson setup "$dir" "$@" || return 1
  elif [ $# -gt 0 ]; then
    meson configure "$dir" "$@" || return 1
  fi
  meson compile -C "$dir" || return 1
  rc=0
  meson test -C "$dir" --print-errorlogs --num-processes 2 --no-suite slow || rc=1
  count "$dir"
  if [ "${CIRCLEDIST_SLOW:-0}" = 1 ]; then
    meson test -C "$dir" --print-errorlogs --num-processes 2 --suite slow || rc=1
    count "$dir"
  fi
  return $rc
}
status=0
run_suite build || status=1
# libFuzzer (ASan + UBSan) through scripts/fuzz.sh, the script a developer runs, so the fuzz build
# cannot rot: a fixed number of inputs from a fixed seed (the same inputs on every run, so a pass
# here is a pass in CI), 20000 inputs, 150000 with CIRCLEDIST_SLOW=1. Counts as one test. Long
# exploratory runs: scripts/fuzz.sh SECONDS (a random seed each time).
fuzz_runs=20000
[ "${CIRCLEDIST_SLOW:-0}" = 1 ] && fuzz_runs=150000
if sh scripts/fuzz.sh 3600 -seed=1 -runs="$fuzz_runs" >build/fuzz.log 2>&1; then
  total_ok=$((total_ok + 1))
else
  echo "fuzz: FAILED (log: build/fuzz.log)"
  tail -n 40 build/fuzz.log
  total_fail=$((total_fail + 1))
  status=1
fi
# Sanitizers: ASan + UBSan, aborting on any report. Optimised (-O2 -g): the brute-force tests
# run about 3x faster than at -O0 and ASan still reports every bad access it can see.
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
  run_suite build-sanitize -Db_sanitize=address,undefined -Db_lundef=false -Dbuildtype=debugoptimized || status=1
# ThreadSanitizer: the tests that run threads (the batch suite: threads 1, 2 and 7 bit-identical,
# a second batch on a busy handle; the handle's in-use flag; scenes with 1 and 2 threads),
# halting on any report.
run_tsan() { # DIR
  if [ ! -d "$1" ]; then
    meson setup "$1" -Db_sanitize=thread -Db_lundef=false -Dbuildtype=debugoptimized || return 1
  fi
  meson compile -C "$1" || return 1
  rc=0
  TSAN_OPTIONS=halt_on_error=1 meson test -C "$1" --print-errorlogs --num-processes 2 --suite batch || rc=1
  count "$1"
  TSAN_OPTIONS=halt_on_error=1 meson test -C "$1" --print-errorlogs handle || rc=1
  count "$1"
  TSAN_OPTIONS=halt_on_error=1 meson test -C "$1" --print-errorlogs scene || rc=1
  count "$1"
  return $rc
}
run_tsan build-tsan || status=1
# With CIRCLEDIST_SLOW=1 (CI): also a static-only build (-Ddefault_library=static), whose tests
# skip only what needs a shared library (ctypes, exported-symbol checks).
if [ "${CIRCLEDIST_SLOW:-0}" = 1 ]; then
  run_suite build-static -Ddefault_library=static -Dbench=false || status=1
  # A packager's build: the library, the tool and the Python package only (-Dtests=false
  # -Dbench=false) configure, compile and install.
  pk=build-packager
  if { [ -d $pk ] || meson setup $pk -Dtests=false -Dbench=false >/dev/null; } &&
    meson compile -C $pk >/dev/null && rm -rf $pk/dest && meson install -C $pk --destdir dest >/dev/null &&
    [ -n "$(find $pk/dest -name libcircledist.so.1)" ] && [ -z "$(find $pk -name 'test_*' -type f)" ]; then
    total_ok=$((total_ok + 1))
  else
    echo "FAIL: packager build (-Dtests=false -Dbench=false)"
    total_fail=$((total_fail + 1))
    status=1
  fi
fi
[ "$status" -ne 0 ] && [ "$total_fail" -eq 0 ] && total_fail=1
echo "test suites: $total_ok passed, $total_fail failed"
exit $status
