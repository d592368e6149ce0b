#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The circledist tool: output format, JSON, bad lines, options.

usage: test_tool.py CIRCLEDIST DATA_DIR
Expected distances come from tests/data (independent reference), never from the tool itself."""
import json
import math
import os
import subprocess
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "common"))
from checks import check, finish  # noqa: E402

tool, data = sys.argv[1], sys.argv[2]


def run(args, stdin=""):
    p = subprocess.run([tool] + args, input=stdin, capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


# Text output on the shared point-circle cases agrees with the reference distances.
lines = open(f"{data}/pc_random.txt").read().splitlines()[:50]
expected = [float(x) for x in open(f"{data}/pc_random.expected").read().split()[:50]]
rc, out, err = run([], "\n".join(lines) + "\n")
check(rc == 0, "rc %d err %s" % (rc, err))
outl = out.splitlines()
check(len(outl) == 50, "one line per query")
for o, e in zip(outl, expected):
    f = o.split()
    check(len(f) == 3 + 6 * int(f[1]), "field count: " + o)
    check(abs(float(f[0]) - e) <= 1e-13 * max(1.0, e), "distance %s vs %r" % (f[0], e))

# Comments, blank lines and a bad line in the middle: every other line is still answered.
text = """# comment
pc 3 4 12  0 0 0  0 0 1  2

pc 1 2 3  0 0 0  0 0 1
pc 1 2 x  0 0 0  0 0 1  2
zz 1 2 3
pc 1 2 3  0 0 0  0 0 0  2
pc 1 2 3  0 0 0  0 0 1  -1
pc nan 2 3  0 0 0  0 0 1  1
pc 0 0 5  0 0 0  0 0 1  2   # trailing comment
"""
rc, out, err = run([], text)
outl = out.splitlines()
check(rc == 1, "exit status 1 with bad lines")
check(len(outl) == 8, "eight answers: %r" % outl)
check(abs(float(outl[0].split()[0]) - math.sqrt(153)) < 1e-14, "first line answered")
check(outl[1].startswith("error: line 4: ") and "10 numbers" in outl[1], outl[1])
check(outl[2].startswith("error: line 5: ") and "'x'" in outl[2], outl[2])
check(outl[3].startswith("error: line 6: ") and "unknown" in outl[3], outl[3])
check(outl[4].startswith("error: line 7: ") and "CDIST_ERR_ZERO_VECTOR" in outl[4], outl[4])
check(outl[5].startswith("error: line 8: ") and "NEGATIVE_RADIUS" in outl[5], outl[5])
check(outl[6].startswith("error: line 9: ") and "NOT_FINITE" in outl[6], outl[6])
check(err.count("error: line") == 6, "errors also on stderr")

# JSON: one object per line, the equidistant case flagged.
rc, out, err = run(["--format=json"], "pc 0 0 5  0 0 0  0 0 1  2\npc 1 1\n")
outl = out.splitlines()
check(len(outl) == 2, "json lines")
o = json.loads(outl[0])
check(o["equidistant"] is True and o["num_pairs"] == 1 and abs(o["distance"] - math.sqrt(29)) < 1e-15, outl[0])
check(o["pairs"][0]["params"][0] is None, "NaN param is null")
e = json.loads(outl[1])
check(e["line"] == 2 and "error" in e, outl[1])

# Options.
rc, out, err = run(["--help"])
check(rc == 0 and "usage" in out and " cc " in out, "help")
rc, out, err = run(["--version"])
check(rc == 0 and out.startswith("circledist 1."), "version: " + out)
rc, out, err = run(["--bogus"])
check(rc == 2 and "unknown option" in err, "bad option")
rc, out, err = run(["/nonexistent/file"])
check(rc == 1 and "cannot open" in err, "missing file")
for m in ("auto", "polynomial", "robust", "iteration"):
    rc, out, err = run(["--method=" + m], "pc 3 4 12  0 0 0  0 0 1  2\n")
    check(rc == 0 and abs(float(out.split()[0]) - math.sqrt(153)) < 1e-14, "method " + m)
# A very long line and binary garbage do not crash the tool.
rc, out, err = run([], "pc " + "1 " * 100000 + "\n\x00\x01\x02\npc\n")
check(rc == 1 and out.count("error:") == 3, "garbage lines: %r" % out[:200])

finish("test_tool")
