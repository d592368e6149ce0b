#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The circledist tool: output format, JSON, bad lines, options.

usage: test_tool.py CIRCLEDIST DATA_DIR
Expected distances come from tests/data (independent reference), never from the tool itself."""
import json
import math
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
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
check(o["method"] == "auto" and o["sqr_distance"] == 29, "method by name, sqr_distance: " + outl[0])
rc, out, err = run(["--format=json", "--method=robust"], "cc 0 0 0  0 0 1  1  3 0 0  0 0 1  1\n")
check(json.loads(out)["method"] in ("robust", "auto"), "method name: " + out)
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
check(rc == 1 and "cannot open" in err and "No such file or directory" in err, "missing file names the reason: " + err)
for m in ("auto", "polynomial", "robust", "iteration"):
    rc, out, err = run(["--method=" + m], "pc 3 4 12  0 0 0  0 0 1  2\n")
    check(rc == 0 and abs(float(out.split()[0]) - math.sqrt(153)) < 1e-14, "method " + m)
# A very long line and binary garbage do not crash the tool.
rc, out, err = run([], "pc " + "1 " * 100000 + "\n\x00\x01\x02\npc\n")
check(rc == 1 and out.count("error:") == 3, "garbage lines: %r" % out[:200])

# Write errors are reported: a full disk gives a message and a non-zero status.
examples = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "examples", "queries.txt")
with open("/dev/full", "w") as full:
    p = subprocess.run([tool, examples], stdout=full, stderr=subprocess.PIPE, text=True, timeout=120)
check(p.returncode == 3 and "cannot write" in p.stderr and "No space left" in p.stderr,
      "write error: rc %d %r" % (p.returncode, p.stderr))

# JSON output is valid JSON (and UTF-8) whatever bytes come in: random byte lines, long kinds
# with multi-byte characters cut at the 20-byte limit, control characters.
rng = random.Random(12345)
junk = [bytes(rng.randrange(1, 256) for _ in range(rng.randrange(1, 60))).replace(b"\n", b" ")
        for _ in range(400)]
junk += ["é" * k + " 1 2" for k in range(1, 15)] + ["€" * k for k in range(1, 12)] + ["\x01\x1f\"\\ 1"]
junk = [x if isinstance(x, bytes) else x.encode() for x in junk]
p = subprocess.run([tool, "--format=json"], input=b"\n".join(junk) + b"\n", capture_output=True, timeout=120)
nobj = 0
for raw in p.stdout.splitlines():
    try:
        o = json.loads(raw.decode("utf-8"))
        nobj += 1
        check("error" in o or "distance" in o, "json object: %r" % raw)
    except (UnicodeDecodeError, ValueError) as e:
        check(False, "invalid JSON/UTF-8 line %r: %s" % (raw, e))
check(nobj > 300, "json objects for the junk lines: %d" % nobj)
rc, out, err = run(["--format=json"], "éééééééééééééééééé 1\n")
check(json.loads(out)["error"] == "unknown query kind 'éééééééééé'...", "cut at a character boundary: " + out)


def max_rss_kb(args, stdin_path):
    """Peak resident memory of one tool run (os.wait4: this child alone)."""
    with open(stdin_path, "rb") as f:
        p = subprocess.Popen([tool] + args, stdin=f, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        out, err = p.stdout.read(), p.stderr.read()
        _, status, usage = os.wait4(p.pid, 0)
        p.returncode = os.waitstatus_to_exitcode(status)
    return usage.ru_maxrss, p.returncode, out.decode(), err.decode()


# A 50 MB line is skipped and reported without being held in memory (peak memory compared with
# a run on a short input: ru_maxrss of the child, which also works under ASan), with and without
# a final newline; the line after it is still answered.
with tempfile.TemporaryDirectory() as tmp:
    small, big, big2 = (os.path.join(tmp, n) for n in ("small", "big", "big2"))
    with open(small, "w") as f:
        f.write("pc 3 4 12  0 0 0  0 0 1  2\n")
    with open(big, "w") as f:
        f.write("pc " + "1 " * 25_000_000)
    with open(big2, "w") as f:
        f.write("pc " + "1 " * 25_000_000 + "\npc 3 4 12  0 0 0  0 0 1  2\n")
    base, rc0, _, _ = max_rss_kb([], small)
    peak, rc, out, err = max_rss_kb([], big)
    check(rc == 1 and out.startswith("error: line 1: line is longer than") and "skipped" in out,
          "long line reported: %d %r" % (rc, out[:200]))
    check(peak < base + 16 * 1024, "long line memory: %d kB vs %d kB on a short input" % (peak, base))
    peak, rc, out, err = max_rss_kb([], big2)
    outl = out.splitlines()
    check(rc == 1 and len(outl) == 2 and outl[0].startswith("error: line 1:")
          and abs(float(outl[1].split()[0]) - math.sqrt(153)) < 1e-14, "line after a long line: %r" % out[:300])
    check(peak < base + 16 * 1024, "long line memory (newline): %d kB vs %d kB" % (peak, base))

# Numbers out of range: overflow and underflow (a non-zero literal that would read as 0) are
# errors naming the number; a subnormal is kept as read; zero with any exponent is zero.
rc, out, err = run([], "pc 1e-999 0 0  0 0 0  0 0 1  1\npc 1e999 0 0  0 0 0  0 0 1  1\n"
                       "pc 0x1p-1100 0 0  0 0 0  0 0 1  1\npc 0e-999 0 0  0 0 0  0 0 1  1\n"
                       "pc 4e-320 0 0  0 0 0  0 0 1  1\n")
outl = out.splitlines()
check(rc == 1 and len(outl) == 5, "underflow lines: %r" % outl)
check("'1e-999'" in outl[0] and "too small" in outl[0], outl[0])
check("'1e999'" in outl[1] and "too large" in outl[1], outl[1])
check("'0x1p-1100'" in outl[2] and "too small" in outl[2], outl[2])
check(outl[3].split()[0] == "1", "0e-999 is zero: " + outl[3])
check(not outl[4].startswith("error") and float(outl[4].split()[0]) == 1.0, "subnormal kept: " + outl[4])

# --normalize: a hand-typed normal is rejected with a hint the CLI user can follow, and
# accepted with the option (distance from the closed form with the normalised normal).
typed = "pc 1 2 3  0 0 0  0.7071 0.7071 0  2\nlc 5 0 0  3 4 0  0 0 0  0 0 3  1\n"
rc, out, err = run([], typed)
check(rc == 1 and out.count("--normalize") == 2 and "cdist_" not in out, "hint: " + out)


def point_circle(P, C, N, r):
    n = math.sqrt(sum(x * x for x in N))
    N = [x / n for x in N]
    D = [P[i] - C[i] for i in range(3)]
    h = sum(D[i] * N[i] for i in range(3))
    rho = math.sqrt(max(sum(x * x for x in D) - h * h, 0))
    return math.hypot(rho - r, h)


rc, out, err = run(["--normalize"], typed)
outl = out.splitlines()
check(rc == 0 and len(outl) == 2, "normalized: %r %r" % (out, err))
check(abs(float(outl[0].split()[0]) - point_circle([1, 2, 3], [0, 0, 0], [0.7071, 0.7071, 0], 2)) < 1e-14,
      "normalized distance " + outl[0])
# the line (5,0,0) + t (0.6,0.8,0) lies in the circle's plane, 4 from its centre: distance 4 - 1
check(abs(float(outl[1].split()[0]) - 3.0) < 1e-14, "normalized line " + outl[1])

# --format=table: a header row naming the columns, then one row per query (distances as the
# reference), a second pair on a continuation row; --header: a '#' line before text output.
rc, out, err = run(["--format=table"], "\n".join(lines[:20]) + "\npc 0 0 5  0 0 0  0 0 1  2\n")
outl = out.splitlines()
check(rc == 0 and outl[0].split()[:5] == ["line", "kind", "distance", "n", "eq"]
      and outl[0].split()[5:] == ["x0", "y0", "z0", "x1", "y1", "z1"], "table header: " + outl[0])
check(max(len(o) for o in outl) <= 110, "table rows fit 110 columns: %d" % max(len(o) for o in outl))
for o, e in zip(outl[1:21], expected[:20]):
    f = o.split()
    check(f[1] == "pc" and abs(float(f[2]) - e) <= 1e-13 * max(1.0, e) and len(f) == 11, "table row: " + o)
check(outl[21].split()[4] == "yes", "equidistant column: " + outl[21])
rc, out, err = run(["--header"], "pc 3 4 12  0 0 0  0 0 1  2\n")
check(out.startswith("# distance num_pairs equidistant") and len(out.splitlines()) == 2, "header: " + out)
rc, out, err = run(["--header", "--no-header"], "pc 3 4 12  0 0 0  0 0 1  2\n")
check(len(out.splitlines()) == 1 and not out.startswith("#"), "--no-header: " + out)
# a pipe is not a terminal: no header by default (scripts read the plain format unchanged)
rc, out, err = run([], "pc 3 4 12  0 0 0  0 0 1  2\n")
check(len(out.splitlines()) == 1 and not out.startswith("#"), "no header into a pipe: " + out)
# on a terminal the header comes first (script(1) gives the tool a pseudo-terminal)
if shutil.which("script"):
    pty = subprocess.run(["script", "-qec", "%s %s" % (tool, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "examples", "queries.txt")), "/dev/null"],
                         capture_output=True, text=True, timeout=60)
    check(pty.stdout.lstrip().startswith("# distance num_pairs"), "header on a terminal: %r" % pty.stdout[:80])

# -j N: the same output, byte for byte, as one thread (every hard file, text and JSON).
allhard = "".join(open(os.path.join(data, f)).read() for f in sorted(os.listdir(data)) if f.endswith("_hard.txt"))
allhard += "pc 1 2\ncc 0 0 0  0 0 2  1  1 0 0  0 1 0  1\n" + "".join(lines)
rc1, out1, _ = run(["-j", "1"], allhard)
rc3, out3, _ = run(["-j", "3"], allhard)
check(rc1 == 1 and rc3 == 1 and out1 == out3 and len(out1.splitlines()) > 1900 and "NOT_UNIT" in out3,
      "-j 3 output equals -j 1 (library errors included)")
rc3, out3j, _ = run(["--jobs=2", "--format=json"], allhard)
rc1, out1j, _ = run(["--format=json"], allhard)
check(out1j == out3j, "--jobs=2 JSON output equals one thread")
cc = open(os.path.join(data, "cc_hard.txt")).read().splitlines()
cce = [float(x) for x in open(os.path.join(data, "cc_hard.expected")).read().split()]
rc, out, _ = run(["-j2"], "\n".join(cc) + "\n")
check(rc == 0 and all(abs(float(o.split()[0]) - e) <= 1e-12 * max(1.0, e) * 1e3
                      for o, e in zip(out.splitlines(), cce)), "-j2 cc_hard against the reference (loose)")
rc, out, err = run(["-j", "0"], "")
check(rc == 2 and "1 to 256" in err, "bad -j: " + err)

# --bench=N: no per-query output, ns_per_query, and one line per kind when mixed.
rc, out, err = run(["--bench=2"], "\n".join(lines[:50]) + "\n")
check(rc == 0 and re.fullmatch(r"ns_per_query=[0-9.]+ queries=50 runs=2 threads=1\n", out) is not None,
      "bench: " + out)
rc, out, err = run(["--bench=2", "-j", "2"], "\n".join(lines[:50] + cc[:20]) + "\n")
outl = out.splitlines()
check(rc == 0 and len(outl) == 3 and outl[0].startswith("ns_per_query=")
      and re.match(r"kind=pc queries=50 ns_per_query=[0-9.]+$", outl[1])
      and re.match(r"kind=cc queries=20 ns_per_query=[0-9.]+$", outl[2]), "bench mixed: " + out)

finish("test_tool")
