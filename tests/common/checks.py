# SPDX-License-Identifier: MIT
"""Shared helpers of the Python tests: check() counts, finish() prints the closing
"N passed, N failed" line and exits non-zero on any failure."""
import sys

_passed = 0
_failed = 0


def check(cond, msg):
    """Record one check; print msg when it fails."""
    global _passed, _failed
    if cond:
        _passed += 1
    else:
        _failed += 1
        print("FAIL:", msg)


def finish(name):
    """Print the summary line and exit with the test's status."""
    print("%s: %d passed, %d failed" % (name, _passed, _failed))
    sys.exit(1 if _failed else 0)
