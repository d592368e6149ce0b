# SPDX-License-Identifier: MIT
"""Single queries through the package: results against closed forms and the shared reference,
the Query API kept from the old one-module binding, objects, errors, basis functions and
callback curves (run by meson with CIRCLEDIST_LIBRARY set)."""
import math
import os

import numpy as np
import pytest

import circledist as cd


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


def test_method_prints_its_name():
    r = cd.circle_circle(cd.Circle((0, 0, 0), (0, 0, 1), 1), cd.Circle((3, 0, 0), (0, 1, 0), 1))
    assert isinstance(r.method, cd.Method) and str(r.method) == cd._lib.method_name(int(r.method)).decode()
    assert [str(m) for m in cd.Method] == ["auto", "polynomial", "robust", "iteration"]
    assert "method=" + r.method.name in repr(r)


def test_unit_tolerance_option():
    with cd.Query(unit_tolerance=float("inf")) as q:
        r = q.point_circle((3, 4, 12), cd.Circle((0, 0, 0), (0, 0, 7), 2))
    assert r.distance == pytest.approx(math.sqrt(153), rel=1e-15)


def test_result_layout_matches_library():
    assert cd.RESULT_DTYPE.itemsize == cd._lib.result_size()
    # the numpy view of the result struct reads what the C query wrote
    r = cd.point_circle((3, 4, 12), cd.Circle((0, 0, 0), (0, 0, 1), 2))
    assert r.sqr_distance == pytest.approx(153, rel=1e-15)
    assert r.points.shape == (1, 2, 3) and r.params.shape == (1, 2)
    assert r.points[0, 0] == pytest.approx((3, 4, 12)) and r.method == cd.Method.AUTO


def test_module_functions_and_methods_by_name():
    a, b = cd.Circle((0, 0, 0), (0, 0, 1), 1), cd.Circle((0.5, 0, 0), (0, 1, 0), 1)
    t = np.linspace(-np.pi, np.pi, 200001)
    pb = np.stack([0.5 + np.cos(t), np.zeros_like(t), np.sin(t)], axis=1)
    brute = np.min(np.hypot(np.hypot(pb[:, 0], pb[:, 1]) - 1, pb[:, 2]))
    for m in ("auto", "polynomial", "robust", "iteration", cd.Method.ROBUST, 1):
        r = cd.circle_circle(a, b, method=m)
        assert r.distance == pytest.approx(brute, abs=1e-9)
    with cd.Query(method="polynomial") as q:
        assert q.method == cd.Method.POLYNOMIAL
        q.circle_circle(a, b, method="robust")
        assert q.method == cd.Method.POLYNOMIAL  # method= is for that call only


def test_every_kind_once_against_brute_force():
    """Each single-query function against a brute-force minimum over sampled points."""
    c = cd.Circle((0.2, -0.1, 0.3), (0, 0.6, 0.8), 0.9)
    d = cd.Disk((0.2, -0.1, 0.3), (0, 0.6, 0.8), 0.9)
    t = np.linspace(0, 1, 4001)

    def circle_pts(circ, n=4001):
        u, v = cd.circle_basis(circ)
        a = np.linspace(-np.pi, np.pi, n)[:, None]
        return circ.center + circ.radius * (np.cos(a) * u + np.sin(a) * v)

    def disk_dist(p):  # exact point-disk distance
        w = p - d.center
        h = w @ d.normal
        rho = np.linalg.norm(w - h[:, None] * d.normal, axis=1)
        return np.hypot(np.maximum(rho - d.radius, 0), h)

    def circle_dist(p):
        w = p - c.center
        h = w @ c.normal
        rho = np.linalg.norm(w - h[:, None] * c.normal, axis=1)
        return np.hypot(rho - c.radius, h)

    seg = cd.Segment((-1, 1, 1), (1.5, -0.5, -0.2))
    seg_pts = seg.p0 + t[:, None] * (seg.p1 - seg.p0)
    arc = cd.Arc(cd.Circle((1, 1, 0), (1, 0, 0), 0.7), (0, 1, 0), -0.5, 2.0)
    au, av = np.array([0, 1.0, 0]), np.cross([1.0, 0, 0], [0, 1.0, 0])
    ang = np.linspace(-0.5, 2.0, 4001)[:, None]
    arc_pts = arc.circle.center + 0.7 * (np.cos(ang) * au + np.sin(ang) * av)
    hel = cd.Helix((0, 0, -1), (0, 0, 1), (1, 0, 0), 0.5, 0.4, 0, 12)
    ht = np.linspace(0, 12, 20001)[:, None]
    hel_pts = np.hstack([0.5 * np.cos(ht), 0.5 * np.sin(ht), -1 + 0.4 * ht / (2 * np.pi)])
    bez = cd.Bezier3((-1, 0, 1), (0, 2, -1), (1, -1, 0.5), (2, 0, 0))
    P = [np.array(x) for x in ((-1, 0, 1), (0, 2, -1), (1, -1, 0.5), (2, 0, 0))]
    tt = t[:, None]
    bez_pts = (1 - tt) ** 3 * P[0] + 3 * (1 - tt) ** 2 * tt * P[1] + 3 * (1 - tt) * tt ** 2 * P[2] + tt ** 3 * P[3]
    cases = [
        (cd.segment_circle(seg, c), circle_dist(seg_pts)),
        (cd.segment_disk(seg, d), disk_dist(seg_pts)),
        (cd.arc_circle(arc, c), circle_dist(arc_pts)),
        (cd.arc_disk(arc, d), disk_dist(arc_pts)),
        (cd.helix_circle(hel, c), circle_dist(hel_pts)),
        (cd.helix_disk(hel, d), disk_dist(hel_pts)),
        (cd.bezier3_circle(bez, c), circle_dist(bez_pts)),
        (cd.bezier3_disk(bez, d), disk_dist(bez_pts)),
        (cd.circle_disk(cd.Circle((0, 0, 1.5), (1, 0, 0), 1), d), disk_dist(circle_pts(cd.Circle((0, 0, 1.5), (1, 0, 0), 1)))),
        (cd.point_disk((0.3, 2, 2), d), disk_dist(np.array([[0.3, 2, 2]]))),
    ]
    for r, brute in cases:
        assert r.distance <= brute.min() + 1e-12
        assert r.distance == pytest.approx(brute.min(), abs=2e-3)  # sampling spacing
    # segment-arc and arc-arc: brute force over both parameters (coarser)
    r = cd.segment_arc(seg, arc)
    dd = np.linalg.norm(seg_pts[::10, None, :] - arc_pts[None, ::10, :], axis=2)
    assert r.distance <= dd.min() + 1e-12 and r.distance == pytest.approx(dd.min(), abs=1e-3)
    assert cd.arc_arc(arc, arc).distance == 0.0


def test_lines_and_rays():
    c = cd.Circle((0, 0, 0), (0, 0, 1), 1)
    # a line along x at height 1 passes over the circle: distance 1, two pairs (x = +-1)
    r = cd.line_circle(cd.Line((0, 0, 1), (1, 0, 0)), c)
    assert r.distance == pytest.approx(1, abs=1e-15) and r.num_pairs == 2
    assert sorted(r.params[:, 0]) == pytest.approx([-1, 1], abs=1e-12)
    # the ray from (2, 0, 1) going +x only reaches the circle's far side: distance sqrt(2)
    r = cd.ray_circle(cd.Ray((2, 0, 1), (1, 0, 0)), c)
    assert r.distance == pytest.approx(math.sqrt(2), rel=1e-15) and r.params[0, 0] == 0
    assert cd.ray_disk(cd.Ray((0.5, 0, 1), (0, 0, -1)), c).distance == 0
    assert cd.line_disk(cd.Line((5, 0, 1), (1, 0, 0)), c).distance == pytest.approx(1, abs=1e-15)
    assert cd.disk_disk(c, cd.Disk((0, 0, 3), (0, 1, 0), 1)).distance == pytest.approx(2, abs=1e-15)


def test_malformed_python_input_names_the_argument():
    c = cd.Circle((0, 0, 0), (0, 0, 1), 1)
    with pytest.raises(ValueError, match=r"Circle\.center.*\(2,\)"):
        cd.Circle((0, 0), (0, 0, 1), 1)
    with pytest.raises(TypeError, match=r"Circle\.radius"):
        cd.Circle((0, 0, 0), (0, 0, 1), None)
    with pytest.raises(TypeError, match=r"Circle\.normal.*str"):
        cd.Circle((0, 0, 0), "up", 1)
    with pytest.raises(ValueError, match=r"point_circle: argument a"):
        cd.point_circle([[1, 2, 3, 4]], c)
    with pytest.raises(TypeError, match=r"line_circle: argument a.*Line or Ray, got Segment"):
        cd.line_circle(cd.Segment((0, 0, 0), (1, 0, 0)), c)
    with pytest.raises(TypeError, match=r"argument b"):
        cd.circle_circle(c, 3.0)
    with pytest.raises(TypeError, match=r"Circle\(\) takes 3 arguments"):
        cd.Circle((0, 0, 0), (0, 0, 1))
    with pytest.raises(ValueError, match=r"do not broadcast"):
        cd.Circle(np.zeros((4, 3)), np.tile([0, 0, 1.0], (5, 1)), 1)
    with pytest.raises(TypeError, match=r"f must be callable"):
        cd.curve_circle(None, 0, 1, c)
    with pytest.raises(TypeError, match=r"threads"):
        cd.circle_circle(c, c, threads=1.5)


def test_old_tuple_style_arguments_still_work():
    r = cd.Query().arc_circle(((((0, 0, 0), (0, 0, 1), 1)), (1, 0, 0), 0, 1), ((3, 0, 0), (0, 0, 1), 1))
    assert r.distance == pytest.approx(1, abs=1e-15)
    assert r.pairs[0].params[0] == pytest.approx(0, abs=1e-15)


def test_objects_are_views_of_c_struct_arrays():
    table = np.arange(40.0).reshape(4, 10)
    circles = cd.Circle.from_array(table[:, 2:9])      # strided rows: no copy
    assert np.shares_memory(circles.data, table) and circles.shape == (4,)
    assert circles.radius.tolist() == [8, 18, 28, 38] and circles[1].center.tolist() == [12, 13, 14]
    h = cd.Helix((0, 0, 0), (0, 0, 1), (1, 0, 0), 2, 0.5, 0, 7)
    assert h.data.shape == (13,) and h.pitch == 0.5 and h.t1 == 7
    assert cd.Arc(cd.Circle((0, 0, 0), (0, 0, 1), 1), (1, 0, 0), 0, 1).data.shape == (12,)
    assert cd.Bezier3((0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)).WIDTH == 12
    assert "Circle(center=[0.0, 0.0, 0.0]" in repr(cd.Circle((0, 0, 0), (0, 0, 1), 1))


def test_circle_basis_and_point():
    c = cd.Circle((1, 2, 3), (0.6, 0, 0.8), 2)
    u, v = cd.circle_basis(c)
    # the documented rule: k = index of the smallest |N_k| (here y), U = e_k - N_k N normalised
    assert u == pytest.approx([0, 1, 0], abs=1e-16)
    assert v == pytest.approx(np.cross([0.6, 0, 0.8], [0, 1, 0]), abs=2e-16)
    p = cd.circle_point(c, [0.0, math.pi / 2])
    assert p[0] == pytest.approx([1, 4, 3], abs=1e-15)
    assert p[1] == pytest.approx(np.array([1, 2, 3]) + 2 * v, abs=1e-15)
    assert cd.circle_point(c, 0.0).shape == (3,)
    with pytest.raises(cd.CircleDistError):
        cd.circle_basis(cd.Circle((0, 0, 0), (0, 0, 0), 1))


def _helix_callback(r, pitch):
    k = pitch / (2 * math.pi)
    return lambda t: ((r * math.cos(t), r * math.sin(t), k * t), (-r * math.sin(t), r * math.cos(t), k))


def test_callback_curve_matches_builtin_helix():
    c = cd.Circle((1.5, 0.2, 0.7), (0.6, 0, 0.8), 0.8)
    d = cd.Disk((1.5, 0.2, 0.7), (0.6, 0, 0.8), 0.8)
    hel = cd.Helix((0, 0, 0), (0, 0, 1), (1, 0, 0), 1.0, 0.5, 0, 9)
    f = _helix_callback(1.0, 0.5)
    rc, rh = cd.curve_circle(f, 0, 9, c), cd.helix_circle(hel, c)
    assert rc.distance == pytest.approx(rh.distance, abs=1e-14)
    assert rc.params[0, 0] == pytest.approx(rh.params[0, 0], abs=1e-7)
    assert cd.curve_disk(f, 0, 9, d).distance == pytest.approx(cd.helix_disk(hel, d).distance, abs=1e-14)


def test_callback_errors():
    c = cd.Circle((0, 0, 0), (0, 0, 1), 1)

    def boom(t):
        raise KeyError("from the callback")
    with pytest.raises(KeyError, match="from the callback") as e:
        cd.curve_circle(boom, 0, 1, c)
    assert isinstance(e.value.__cause__, cd.CircleDistError)
    assert e.value.__cause__.name == "CDIST_ERR_CALLBACK_FAILED"
    with pytest.raises(cd.CircleDistError) as e:
        cd.curve_circle(lambda t: ((t, float("nan"), 0), (1, 0, 0)), 0, 1, c)
    assert e.value.name == "CDIST_ERR_CALLBACK_NOT_FINITE"
    with pytest.raises(cd.CircleDistError) as e:
        cd.curve_circle(lambda t: ((t, 0, 0), (1, 0, 0)), 1, 0, c)
    assert e.value.name == "CDIST_ERR_BAD_INTERVAL"
