# SPDX-License-Identifier: MIT
"""Every query kind against the shared reference files (tests/data, else /work/shared/cases),
answered by ONE vectorised call per file: the file's columns are exactly the C structs, so the
objects are zero-copy views (Circle.from_array(table[:, 3:10]) ...). Error = |d - expected| / L
with the scale L of tools/query_io.c (cdq_scale) (revision 2 of the shared reference)."""
import math
import os

import numpy as np
import pytest

import circledist as cd
from conftest import SOURCE_ROOT

DATA = [os.path.join(SOURCE_ROOT, "tests", "data"), "/work/shared/cases"]

# file kind -> (query function, first class, second class, tolerance of scale)
KINDS = {
    "pc": ("point_circle", cd.Point, cd.Circle, 1e-13), "pd": ("point_disk", cd.Point, cd.Disk, 1e-13),
    "lc": ("line_circle", cd.Line, cd.Circle, 1e-13), "ld": ("line_disk", cd.Line, cd.Disk, 1e-12),
    "rc": ("ray_circle", cd.Ray, cd.Circle, 1e-13), "rd": ("ray_disk", cd.Ray, cd.Disk, 1e-12),
    "sc": ("segment_circle", cd.Segment, cd.Circle, 1e-13), "sd": ("segment_disk", cd.Segment, cd.Disk, 1e-12),
    "cc": ("circle_circle", cd.Circle, cd.Circle, 1e-12), "cd": ("circle_disk", cd.Circle, cd.Disk, 1e-12),
    "dd": ("disk_disk", cd.Disk, cd.Disk, 1e-12),
    "ac": ("arc_circle", cd.Arc, cd.Circle, 1e-12), "aa": ("arc_arc", cd.Arc, cd.Arc, 1e-12),
    "sa": ("segment_arc", cd.Segment, cd.Arc, 1e-12), "ad": ("arc_disk", cd.Arc, cd.Disk, 1e-12),
    "hc": ("helix_circle", cd.Helix, cd.Circle, 1e-12), "hd": ("helix_disk", cd.Helix, cd.Disk, 1e-12),
    "bc": ("bezier3_circle", cd.Bezier3, cd.Circle, 1e-12), "bd": ("bezier3_disk", cd.Bezier3, cd.Disk, 1e-12),
}



def _find(name):
    for d in DATA:
        if os.path.exists(os.path.join(d, name)):
            return os.path.join(d, name)
    return None


def _load(kind, which):
    path = _find("%s_%s.txt" % (kind, which))
    if path is None:
        pytest.skip("no %s_%s reference file" % (kind, which))
    rows = []
    for no, line in enumerate(open(path), 1):
        f = line.split()
        if f and not f[0].startswith("#"):
            assert f[0] == kind
            rows.append([float(x) for x in f[1:]])
    expected = np.array([float(x) for x in open(path[:-4] + ".expected").read().split()])
    return np.array(rows), expected


def _norm(x):
    return np.linalg.norm(x, axis=-1)


def _line_center_dist(b, m, c):
    """Distance from c to its nearest point on the line b + t m (m not necessarily unit)."""
    t = np.einsum("ij,ij->i", c - b, m) / np.einsum("ij,ij->i", m, m)
    return _norm(b + t[:, None] * m - c)


def _scale(kind, v, expected):
    """tools/query_io.c cdq_scale, vectorised."""
    L = np.abs(expected)
    if kind[0] == "p":
        return np.maximum.reduce([L, v[:, 9], _norm(v[:, 0:3] - v[:, 3:6])])
    if kind in ("lc", "rc", "ld", "rd"):
        return np.maximum.reduce([L, v[:, 12], _line_center_dist(v[:, 0:3], v[:, 3:6], v[:, 6:9])])
    if kind in ("sc", "sd"):
        m = v[:, 3:6] - v[:, 0:3]
        degenerate = ~np.any(m != 0, axis=1)
        m[degenerate] = 1.0
        lc = np.where(degenerate, _norm(v[:, 0:3] - v[:, 6:9]), _line_center_dist(v[:, 0:3], m, v[:, 6:9]))
        return np.maximum.reduce([L, v[:, 12], lc, _norm(v[:, 0:3] - v[:, 3:6])])
    if kind in ("cc", "cd", "dd"):
        return np.maximum.reduce([L, v[:, 6], v[:, 13], _norm(v[:, 0:3] - v[:, 7:10])])
    if kind in ("ac", "ad", "aa"):
        return np.maximum.reduce([L, v[:, 6], v[:, 18], _norm(v[:, 0:3] - v[:, 12:15])])
    if kind == "sa":
        return np.maximum.reduce([L, v[:, 12], _norm(v[:, 0:3] - v[:, 6:9]), _norm(v[:, 3:6] - v[:, 6:9])])
    if kind[0] == "h":
        ext = np.abs(v[:, 10]) * np.maximum(np.abs(v[:, 11]), np.abs(v[:, 12])) / (2 * math.pi)
        return np.maximum.reduce([L, v[:, 9], v[:, 19], _norm(v[:, 0:3] - v[:, 13:16]) + ext])
    if kind[0] == "b":
        return np.maximum.reduce([L, v[:, 18]] + [_norm(v[:, 3 * i:3 * i + 3] - v[:, 12:15]) for i in range(4)])
    raise AssertionError(kind)


@pytest.mark.parametrize("which", ["random", "hard"])
@pytest.mark.parametrize("kind", sorted(KINDS))
def test_reference_file_vectorised(kind, which):
    name, cls_a, cls_b, tol = KINDS[kind]
    table, expected = _load(kind, which)
    wa = cls_a.WIDTH
    assert table.shape[1] == wa + cls_b.WIDTH
    a, b = cls_a.from_array(table[:, :wa]), cls_b.from_array(table[:, wa:])
    assert np.shares_memory(a.data, table) and np.shares_memory(b.data, table)   # no copies
    res = getattr(cd, name)(a, b, threads=2)
    assert res.shape == (len(table),)
    assert np.all(res.status == 0), res.status_names()[res.status != 0]
    L = _scale(kind, table, expected)
    err = np.abs(res.distance - expected) / L
    worst = int(np.argmax(err))
    assert err[worst] <= tol, "%s_%s line %d: %.17g expected %.17g, error %.3g of scale" % (
        kind, which, worst + 1, res.distance[worst], expected[worst], err[worst])
    # every reported pair is a pair of points at the reported distance
    k = res.num_pairs
    assert np.all((k >= 1) & (k <= 2))
    for i in (0, 1):
        has = k > i
        pts = res.points[has, i]
        gap = _norm(pts[:, 0] - pts[:, 1])
        # points far from the origin carry rounding of their own size (ulps of the coordinates)
        big = np.max(np.abs(pts), axis=(1, 2))
        bad = np.abs(gap - res.distance[has]) > 1e-12 * L[has] + 16 * np.finfo(float).eps * big
        assert not np.any(bad), "pair %d of lines %s" % (i, np.flatnonzero(has)[bad][:5] + 1)
    # the screening call agrees with the full one
    d = getattr(cd, name)(a, b, distance_only=True)
    assert np.all(d.status == 0)
    assert np.all(np.abs(d.distance - res.distance) <= 4 * np.finfo(float).eps * L)
