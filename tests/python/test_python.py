# SPDX-License-Identifier: MIT
"""The ctypes binding: layout check, queries, errors (run by meson with CIRCLEDIST_LIBRARY set)."""
import math
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "python"))
import circledist as cd  # noqa: E402


def test_version():
    assert cd.version().startswith("1.")


def test_point_circle_matches_closed_form():
    with cd.Query() as q:
        r = q.point_circle((3, 4, 12), cd.Circle((0, 0, 0), (0, 0, 1), 2))
    assert r.distance == pytest.approx(math.sqrt(153), rel=1e-15)
    assert len(r.pairs) == 1 and not r.equidistant
    assert r.pairs[0].points[1] == pytest.approx((1.2, 1.6, 0), abs=1e-15)


def test_axis_point_is_equidistant():
    with cd.Query() as q:
        r = q.point_circle((0, 0, 5), cd.Circle((0, 0, 0), (0, 0, 1), 2))
    assert r.equidistant and r.distance == pytest.approx(math.sqrt(29), rel=1e-15)
    assert math.isnan(r.pairs[0].params[0])


def test_reference_file_through_binding():
    data = os.path.join(os.path.dirname(__file__), "..", "data")
    lines = [l.split() for l in open(os.path.join(data, "pd_random.txt")) if l.strip()][:200]
    expected = [float(x) for x in open(os.path.join(data, "pd_random.expected")).read().split()[:200]]
    with cd.Query() as q:
        for f, e in zip(lines, expected):
            v = [float(x) for x in f[1:]]
            r = q.point_disk(v[0:3], cd.Circle(v[3:6], v[6:9], v[9]))
            L = max(v[9], math.dist(v[0:3], v[3:6]), e)
            assert abs(r.distance - e) <= 1e-13 * L


@pytest.mark.parametrize("circle,name", [
    (cd.Circle((0, 0, 0), (0, 0, 0), 1), "CDIST_ERR_ZERO_VECTOR"),
    (cd.Circle((0, 0, 0), (0, 0, 2), 1), "CDIST_ERR_NOT_UNIT"),
    (cd.Circle((0, 0, 0), (0, 0, 1), -1), "CDIST_ERR_NEGATIVE_RADIUS"),
    (cd.Circle((0, float("nan"), 0), (0, 0, 1), 1), "CDIST_ERR_NOT_FINITE"),
])
def test_bad_input_raises(circle, name):
    with cd.Query() as q:
        with pytest.raises(cd.CircleDistError) as e:
            q.point_circle((1, 2, 3), circle)
        assert e.value.name == name and e.value.message
        # the handle is still usable
        assert q.point_circle((1, 0, 0), cd.Circle((0, 0, 0), (0, 0, 1), 1)).distance == 0.0


def test_bad_method():
    with cd.Query() as q:
        with pytest.raises(cd.CircleDistError) as e:
            q.set_method(9)
        assert e.value.name == "CDIST_ERR_BAD_OPTION"


def test_unit_tolerance_option():
    with cd.Query(unit_tolerance=float("inf")) as q:
        r = q.point_circle((3, 4, 12), cd.Circle((0, 0, 0), (0, 0, 7), 2))
    assert r.distance == pytest.approx(math.sqrt(153), rel=1e-15)
