# SPDX-License-Identifier: MIT
"""The swept tool kinds (TT TK ... Sd): every kind is listed in --help with its columns, parses
its documented number of columns, and answers hand-computed configurations (objects apart or
overlapping along the x axis, distances by elementary geometry), with witness points on the
surfaces at the signed distance from each other."""
import json
import math
import subprocess
import sys

tool = sys.argv[1]

T = lambda cx, R, rt, n=(0, 0, 1): [cx, 0, 0, *n, R, rt]       # torus centred on the x axis
K = lambda x0, x1, r: [x0, 0, 0, x1, 0, 0, r]                   # capsule along the x axis
S = lambda x, r: [x, 0, 0, r]                                   # sphere
R = lambda cx, Rd, r, n=(0, 0, 1): [cx, 0, 0, *n, Rd, r]        # rounded disk
C = lambda cx, Rc, n=(0, 0, 1): [cx, 0, 0, *n, Rc]              # circle / disk

# (kind, numbers, expected signed distance)
cases = [
    ("TT", T(0, 1, 0.1) + T(5, 1, 0.2), 5 - 2 - 0.3),
    ("TT", T(0, 1, 0.1) + T(2.1, 1, 0.2), 0.1 - 0.3),
    ("TK", T(0, 1, 0.1) + K(3, 4, 0.5), 2 - 0.6),
    ("TS", T(0, 1, 0.25) + S(3, 0.5), 2 - 0.75),
    ("TS", T(0, 1, 0.25) + S(0, 0.5), 1 - 0.75),       # sphere at the centre of the hole
    ("TR", T(0, 1, 0.1) + R(4, 1, 0.2), 2 - 0.3),
    ("TR", T(0, 1, 0.1) + R(0.5, 1, 0.2, (1, 0, 0)), -(0.3)),  # the disk cuts through the ring: cores cross
    ("KK", K(0, 1, 0.1) + K(3, 4, 0.2), 2 - 0.3),
    ("KK", K(0, 1, 0.5) + K(1.5, 4, 0.5), 0.5 - 1.0),
    ("KS", K(0, 1, 0.1) + S(-2, 0.4), 2 - 0.5),
    ("KR", K(0, 1, 0.1) + R(4, 1, 0.4), 2 - 0.5),
    ("SS", S(0, 1) + S(3, 1), 1),
    ("SS", S(0, 1) + S(1, 1), -1),
    ("SR", S(0, 0.5) + R(3, 1, 0.5), 2 - 1),
    ("RR", R(0, 1, 0.1) + R(5, 1, 0.2), 3 - 0.3),
    ("Tl", T(0, 1, 0.1) + [0, 0, 3, 1, 0, 0], 3 - 0.1),   # line parallel to x at height 3 (over the ring)
    ("Tr", T(0, 1, 0.1) + [3, 0, 0, 1, 0, 0], 2 - 0.1),
    ("Ts", T(0, 1, 0.1) + [3, 0, 0, 5, 0, 0], 2 - 0.1),
    ("Kc", K(3, 4, 0.3) + C(0, 1), 2 - 0.3),
    ("Kd", K(3, 4, 0.3) + C(0, 1), 2 - 0.3),
    ("Sc", S(3, 0.5) + C(0, 1), 2 - 0.5),
    ("Sd", S(0, 0.5) + C(0, 1, (1, 0, 0)), -0.5),
]

kinds = ["TT", "TK", "TS", "TR", "KK", "KS", "KR", "SS", "SR", "RR", "Tl", "Tr", "Ts", "Kc", "Kd", "Sc", "Sd"]
fails = 0


def fail(msg):
    global fails
    fails += 1
    print("FAIL:", msg)


help_text = subprocess.run([tool, "--help"], capture_output=True, text=True, check=True).stdout
for k in kinds:
    if not any(line.split()[:1] == [k] for line in help_text.splitlines()):
        fail(f"kind {k} not in --help")
if {c[0] for c in cases} != set(kinds):
    fail("a kind has no case")

text = "".join(f"{k} {' '.join(repr(float(x)) for x in v)}\n" for k, v, _ in cases)
out = subprocess.run([tool, "--format=json"], input=text, capture_output=True, text=True)
if out.returncode != 0:
    fail(f"tool failed: {out.stderr}")
lines = out.stdout.splitlines()
if len(lines) != len(cases):
    fail(f"{len(lines)} output lines for {len(cases)} cases")
for (k, v, want), line in zip(cases, lines):
    o = json.loads(line)
    d = o.get("distance")
    if d is None or abs(d - want) > 1e-14 * (1 + abs(want)):
        fail(f"{k} {v}: distance {d} expected {want}")
        continue
    if "sqr_distance" in o:
        fail(f"{k}: a signed distance has no sqr_distance field")
    if o.get("method") not in ("auto", "polynomial", "robust", "iteration"):
        fail(f"{k}: method {o.get('method')!r} is not a method name")
    p0, p1 = o["pairs"][0]["points"]
    sep = math.dist(p0, p1)
    if abs(sep - abs(d)) > 1e-13:
        fail(f"{k}: witness points {sep} apart, |distance| {abs(d)}")

# column count is enforced
bad = subprocess.run([tool], input="SS 0 0 0 1  1 0 0\n", capture_output=True, text=True)
if bad.returncode != 1 or "takes 8 numbers" not in bad.stdout:
    fail(f"short SS line not rejected: {bad.stdout!r}")
# text layout: distance num_pairs equidistant then 2 x 3 point coordinates per pair
t = subprocess.run([tool], input="SS 0 0 0 1  3 0 0 1\n", capture_output=True, text=True).stdout.split()
if [float(x) for x in t] != [1, 1, 0, 1, 0, 0, 2, 0, 0]:
    fail(f"text layout {t}")

print(f"swept tool: {len(cases)} cases, {fails} failures")
sys.exit(1 if fails else 0)
