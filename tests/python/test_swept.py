# SPDX-License-Identifier: MIT
"""Swept objects (contact queries) and gradients through the Python package.

Independent checks: the swept distance against the core distance from the package's core
queries (or closed forms written here for the cores it has no query for: point-point,
point-segment, segment-segment) minus the radii; gradients against central finite differences
of the Python-level distance."""
import math

import numpy as np
import pytest

import circledist as cd
from circledist import _lib

SWEPT = ["torus_torus", "torus_capsule", "torus_sphere", "torus_rounded_disk", "capsule_capsule",
         "capsule_sphere", "capsule_rounded_disk", "sphere_sphere", "sphere_rounded_disk",
         "rounded_disk_rounded_disk", "torus_line", "torus_ray", "torus_segment",
         "capsule_circle", "capsule_disk", "sphere_circle", "sphere_disk"]
CORE_GRAD = ["point_circle", "point_disk", "line_circle", "ray_circle", "segment_circle",
             "circle_circle", "line_disk", "ray_disk", "segment_disk", "circle_disk", "disk_disk",
             "arc_circle", "arc_arc", "segment_arc", "arc_disk"]
CLASS = {"torus": cd.Torus, "capsule": cd.Capsule, "sphere": cd.Sphere,
         "rounded_disk": cd.RoundedDisk, "line": cd.Line, "ray": cd.Ray, "segment": cd.Segment,
         "circle": cd.Circle, "disk": cd.Disk, "point": cd.Point, "arc": cd.Arc}


def split(name):
    """'capsule_rounded_disk' -> ('capsule', 'rounded_disk')."""
    for a in sorted(CLASS, key=len, reverse=True):
        if name.startswith(a + "_") and name[len(a) + 1:] in CLASS:
            return a, name[len(a) + 1:]
    raise AssertionError(name)


def unit(rng):
    v = rng.standard_normal(3)
    return v / np.linalg.norm(v)


def make(kind, rng, offset=0.0):
    """A random object of `kind` (centre spread around `offset`)."""
    c = rng.standard_normal(3) * 1.2 + offset
    if kind in ("circle", "disk"):
        return CLASS[kind](c, unit(rng), rng.uniform(0.5, 1.5))
    if kind == "point":
        return cd.Point(c)
    if kind in ("line", "ray"):
        return CLASS[kind](c, unit(rng))
    if kind == "segment":
        return cd.Segment(c, c + rng.standard_normal(3))
    if kind == "arc":
        return cd.Arc(cd.Circle(c, unit(rng), rng.uniform(0.5, 1.5)), 2 * rng.standard_normal(3),
                      rng.uniform(-1, 0), rng.uniform(0.5, 2.5))
    r = rng.uniform(0.05, 0.3)
    if kind == "sphere":
        return cd.Sphere(c, r)
    if kind == "capsule":
        return cd.Capsule(cd.Segment(c, c + rng.standard_normal(3)), r)
    if kind == "torus":
        return cd.Torus(cd.Circle(c, unit(rng), rng.uniform(0.5, 1.5)), r)
    if kind == "rounded_disk":
        return cd.RoundedDisk(cd.Disk(c, unit(rng), rng.uniform(0.5, 1.5)), r)
    raise AssertionError(kind)


def core(kind, obj):
    """(core kind, core object, swept radius) of an object."""
    if kind == "torus":
        return "circle", obj.circle, obj.tube_radius
    if kind == "capsule":
        return "segment", obj.segment, obj.radius
    if kind == "sphere":
        return "point", cd.Point(obj.center), obj.radius
    if kind == "rounded_disk":
        return "disk", obj.disk, obj.radius
    return kind, obj, 0.0


def point_segment(p, s):
    d = s.p1 - s.p0
    dd = d @ d
    t = 0.0 if dd == 0 else min(1.0, max(0.0, (p - s.p0) @ d / dd))
    return np.linalg.norm(p - (s.p0 + t * d))


def segment_segment(s, u):
    """Closed form: the ends against the other segment, and the interior critical point."""
    best = min(point_segment(s.p0, u), point_segment(s.p1, u),
               point_segment(u.p0, s), point_segment(u.p1, s))
    d1, d2, r = s.p1 - s.p0, u.p1 - u.p0, s.p0 - u.p0
    a, b, c, e, f = d1 @ d1, d1 @ d2, d2 @ d2, d1 @ r, d2 @ r
    den = a * c - b * b
    if den > 1e-12 * a * c:
        t1 = (b * f - c * e) / den
        t2 = (a * f - b * e) / den
        if 0 < t1 < 1 and 0 < t2 < 1:
            best = min(best, np.linalg.norm(s.p0 + t1 * d1 - u.p0 - t2 * d2))
    return best


def core_distance(ka, a, kb, b):
    """The core distance from the package's core queries or the closed forms above."""
    if (ka, kb) == ("point", "point"):
        return float(np.linalg.norm(a.position - b.position))
    if {ka, kb} == {"point", "segment"}:
        p, s = (a, b) if ka == "point" else (b, a)
        return float(point_segment(p.position, s))
    if (ka, kb) == ("segment", "segment"):
        return float(segment_segment(a, b))
    if ka + "_" + kb in CORE_GRAD:      # every core pair of the swept queries has a _grad
        return getattr(cd, ka + "_" + kb)(a, b).distance
    return getattr(cd, kb + "_" + ka)(b, a).distance


@pytest.mark.parametrize("name", SWEPT)
def test_swept_distance_is_core_distance_minus_radii(name):
    ka, kb = split(name)
    rng = np.random.default_rng(sum(map(ord, name)))
    for _ in range(20):
        a, b = make(ka, rng), make(kb, rng, offset=0.8)
        c = getattr(cd, name)(a, b)
        ca, core_a, ra = core(ka, a)
        cb, core_b, rb = core(kb, b)
        ref = core_distance(ca, core_a, cb, core_b)
        scale = 1 + np.abs(a.data).max() + np.abs(b.data).max()
        assert c.core_distance == pytest.approx(ref, abs=1e-13 * scale)
        assert c.distance == pytest.approx(ref - (ra + rb), abs=1e-13 * scale)
        assert c.num_pairs in (1, 2) and c.points.shape == (c.num_pairs, 2, 3)
        for p in c.pairs:
            assert np.linalg.norm(p.normal) == pytest.approx(1, abs=1e-14)
            assert np.allclose(p.points[0], p.core_points[0] + ra * p.normal, atol=1e-14 * scale)
            assert np.allclose(p.points[1], p.core_points[1] - rb * p.normal, atol=1e-14 * scale)
            assert np.linalg.norm(p.core_points[1] - p.core_points[0]) == \
                pytest.approx(ref, abs=1e-13 * scale)
            if not c.core_touch:
                assert np.allclose(p.normal * ref, p.core_points[1] - p.core_points[0],
                                   atol=1e-13 * scale)


def test_signed_distance_negative_on_overlap():
    c = cd.sphere_sphere(cd.Sphere((0, 0, 0), 1.0), cd.Sphere((1.5, 0, 0), 0.75))
    assert c.distance == pytest.approx(-0.25, abs=1e-15) and c.core_distance == 1.5
    assert not c.core_touch and np.allclose(c.normals, [[1, 0, 0]])
    # the sphere's centre is 0.1 from the torus's core circle: penetration 0.2 + 0.3 - 0.1
    t = cd.Torus(cd.Circle((0, 0, 0), (0, 0, 1), 2.0), 0.2)
    c = cd.torus_sphere(t, cd.Sphere((0, 2.1, 0), 0.3))
    assert c.distance == pytest.approx(math.hypot(0.1, 0) - 0.5, abs=1e-15)
    assert np.allclose(c.normals, [[0, 1, 0]])
    # a capsule through the core circle: the cores cross, the normal follows the documented rule
    k = cd.Capsule(cd.Segment((2, 0, -1), (2, 0, 1)), 0.1)
    c = cd.torus_capsule(t, k)
    assert c.core_touch and c.core_distance == pytest.approx(0, abs=1e-15)
    assert c.distance == pytest.approx(-0.3, abs=1e-15)
    # rule (1): tangent of the circle (0, 1, 0) x segment direction (0, 0, 1) = +-(1, 0, 0),
    # oriented towards the capsule's midpoint (2, 0, 0) from the torus centre
    assert np.allclose(c.normals, [[1, 0, 0]])
    # apart: positive
    assert cd.sphere_disk(cd.Sphere((0, 0, 3), 1), cd.Disk((0, 0, 0), (0, 0, 1), 5)).distance == 2


def _fields(obj):
    """(grad field, data column, width, unit) of each parameter of an object's C struct."""
    circle = [("d_center", 0, 3, False), ("d_normal", 3, 3, True), ("d_radius", 6, 1, False)]
    return {
        cd.Point: [("d_center", 0, 3, False)],
        cd.Circle: circle, cd.Disk: circle,
        cd.Line: [("d_origin", 0, 3, False), ("d_direction", 3, 3, True)],
        cd.Ray: [("d_origin", 0, 3, False), ("d_direction", 3, 3, True)],
        cd.Segment: [("d_p0", 0, 3, False), ("d_p1", 3, 3, False)],
        cd.Arc: circle + [("d_zero_direction", 7, 3, False), ("d_start", 10, 1, False),
                          ("d_end", 11, 1, False)],
        cd.Sphere: [("d_center", 0, 3, False), ("d_radius_swept", 3, 1, False)],
        cd.Capsule: [("d_p0", 0, 3, False), ("d_p1", 3, 3, False), ("d_radius_swept", 6, 1, False)],
        cd.Torus: circle + [("d_radius_swept", 7, 1, False)],
        cd.RoundedDisk: circle + [("d_radius_swept", 7, 1, False)],
    }[type(obj)]


def _check_gradient(name, a, b, grad, h=1e-5):
    """Central differences of the Python-level distance against every gradient field."""
    query = getattr(cd, name)
    objs = [a, b]

    def distance(k, data):
        args = list(objs)
        args[k] = type(objs[k]).from_array(data)
        return query(*args).distance

    checked = 0
    for k, obj in enumerate(objs):
        g = grad.obj[k]
        used = set()
        for field, col, width, is_unit in _fields(obj):
            used.add(field)
            value = np.atleast_1d(getattr(g, field))
            if is_unit:
                n = obj.data[col:col + 3]
                assert abs(value @ n) <= 1e-12 * (1 + np.linalg.norm(value)), (name, k, field)
                t1 = np.cross(n, [1.0, 0, 0] if abs(n[0]) < 0.9 else [0, 1.0, 0])
                t1 /= np.linalg.norm(t1)
                directions = [t1, np.cross(n, t1)]
            else:
                directions = list(np.eye(width))
            for d in directions:
                diffs = []
                for s in (h, -h):
                    data = obj.data.copy()
                    v = data[col:col + width] + s * d
                    data[col:col + width] = v / np.linalg.norm(v) if is_unit else v
                    diffs.append(distance(k, data))
                fd = (diffs[0] - diffs[1]) / (2 * h)
                assert value @ d == pytest.approx(fd, rel=1e-6, abs=1e-7), (name, k, field, d)
                checked += 1
        for field in _lib.GRAD_OBJECT_FIELDS:   # the fields that do not apply are 0
            if field not in used:
                assert not np.any(getattr(g, field)), (name, k, field)
    return checked


@pytest.mark.parametrize("name", SWEPT + CORE_GRAD)
def test_gradient_matches_finite_differences(name):
    ka, kb = split(name)
    rng = np.random.default_rng(1000 + sum(map(ord, name)))
    tested = 0
    for _ in range(12):
        a, b = make(ka, rng), make(kb, rng, offset=1.0)
        res, g = getattr(cd, name + "_grad")(a, b)
        plain = getattr(cd, name)(a, b)
        assert res.distance == plain.distance
        assert isinstance(res, cd.Contact if name in SWEPT else cd.Result)
        if not g.differentiable or res.num_pairs != 1 or (name in SWEPT and res.core_touch):
            continue
        assert _check_gradient(name, a, b, g) > 0
        tested += 1
        if tested == 3:
            break
    assert tested == 3, name


def test_not_differentiable_flag():
    # a sphere centred on the torus's core circle: the cores touch
    t = cd.Torus(cd.Circle((0, 0, 0), (0, 0, 1), 1.0), 0.25)
    c, g = cd.torus_sphere_grad(t, cd.Sphere((1, 0, 0), 0.5))
    assert c.core_touch and not g.differentiable
    assert g.obj[0].d_radius_swept == -1 and g.obj[1].d_radius_swept == -1
    assert not np.any(g.obj[1].d_center)
    # a sphere on the axis of a torus: infinitely many closest pairs
    c, g = cd.torus_sphere_grad(t, cd.Sphere((0, 0, 2), 0.5))
    assert c.equidistant and not g.differentiable
    c, g = cd.torus_sphere_grad(t, cd.Sphere((0, 0.5, 2), 0.5))
    assert g.differentiable and g.flags == 0


def test_struct_layouts_match_library():
    assert _lib.contact_size() == cd.CONTACT_DTYPE.itemsize == 368
    assert _lib.grad_size() == cd.GRAD_DTYPE.itemsize
    for i, cls in enumerate((cd.Sphere, cd.Capsule, cd.Torus, cd.RoundedDisk)):
        assert _lib.swept_size(i) == 8 * cls.WIDTH
    assert (cd.Sphere.WIDTH, cd.Capsule.WIDTH, cd.Torus.WIDTH, cd.RoundedDisk.WIDTH) == (4, 7, 8, 8)
    # the readers of the C structs against the numpy field layout
    raw = np.zeros((), cd.CONTACT_DTYPE)
    raw["distance"], raw["core_distance"], raw["num_pairs"], raw["flags"], raw["method"] = \
        -0.5, 0.25, 2, 1, 2
    raw["pairs"]["point"] = np.arange(12).reshape(2, 2, 3)
    raw["pairs"]["core_point"] = 20 + np.arange(12).reshape(2, 2, 3)
    raw["pairs"]["normal"] = [[0, 0, 1], [0, 1, 0]]
    raw["pairs"]["param"] = [[7, 8], [9, 10]]
    c = cd.Contact(raw)
    assert (c.distance, c.core_distance, c.num_pairs, c.core_touch, c.method) == \
        (-0.5, 0.25, 2, True, cd.Method.ROBUST)
    assert c.pairs[1].points.tolist() == [[6, 7, 8], [9, 10, 11]]
    assert c.pairs[1].core_points.tolist() == [[26, 27, 28], [29, 30, 31]]
    assert c.normals.tolist() == [[0, 0, 1], [0, 1, 0]] and c.params.tolist() == [[7, 8], [9, 10]]
    raw = np.zeros((), cd.GRAD_DTYPE)
    raw["flags"] = 1
    for k in range(2):
        for i, f in enumerate(_lib.GRAD_OBJECT_FIELDS):
            raw["obj"][k][f] = 100 * k + i
    g = cd.Grad(raw)
    assert not g.differentiable and g.flags == 1
    assert g.obj[1].d_p1.tolist() == [105] * 3 and g.obj[0].d_end == 10
    assert g.obj[1].d_radius_swept == 108 and g.obj[0].d_zero_direction.tolist() == [6] * 3
    t = cd.Torus(((1, 2, 3), (0, 0, 1), 4), 0.5)
    assert t.data.tolist() == [1, 2, 3, 0, 0, 1, 4, 0.5]
    assert isinstance(t.circle, cd.Circle) and t.tube_radius == 0.5
    k = cd.Capsule(((0, 0, 0), (1, 0, 0)), 0.25)
    assert k.segment.p1.tolist() == [1, 0, 0] and k.radius == 0.25


def test_every_query_is_exported():
    for name in SWEPT + [s + "_grad" for s in SWEPT + CORE_GRAD]:
        assert name in cd.__all__ and callable(getattr(cd, name))
        assert callable(getattr(cd.Query, name))
    assert not hasattr(cd, "helix_circle_grad")   # the C library has no such variant


def test_method_option_applies_to_the_core_query_only_for_the_call():
    t0 = cd.Torus(((0, 0, 0), (0, 0, 1), 1), 0.1)
    t1 = cd.Torus(((1, 0, 0.3), (0, 1, 0), 1), 0.1)
    with cd.Query() as q:
        assert q.torus_torus(t0, t1, method="polynomial").method == cd.Method.POLYNOMIAL
        assert q.method == cd.Method.AUTO
        c, g = cd.torus_torus_grad(t0, t1, method=cd.Method.ROBUST, query=q)
        assert c.method == cd.Method.ROBUST and q.method == cd.Method.AUTO


def test_errors():
    t = cd.Torus(((0, 0, 0), (0, 0, 1), 1), 0.1)
    with pytest.raises(cd.CircleDistError) as e:
        cd.torus_sphere(t, cd.Sphere((0, 0, 3), -1))
    assert e.value.name == "CDIST_ERR_NEGATIVE_RADIUS"
    with pytest.raises(cd.CircleDistError) as e:
        cd.torus_torus_grad(cd.Torus(((0, 0, 0), (0, 0, 2), 1), 0.1), t)
    assert e.value.name == "CDIST_ERR_NOT_UNIT"
    with pytest.raises(cd.CircleDistError) as e:
        cd.sphere_disk(cd.Sphere((0, 0, math.nan), 1), ((0, 0, 0), (0, 0, 1), 1))
    assert e.value.name == "CDIST_ERR_NOT_FINITE"
    with pytest.raises(cd.CircleDistError):
        cd.circle_circle_grad(((0, 0, 0), (0, 0, 1), -1), ((0, 0, 0), (0, 0, 1), 1))
    # the handle still answers after an error
    assert cd.torus_sphere(t, cd.Sphere((0, 0, 3), 1)).distance > 0
    with pytest.raises(ValueError, match="do not broadcast"):
        cd.sphere_sphere(cd.Sphere(np.zeros((3, 3)), 1.0), cd.Sphere(np.zeros((2, 3)), 1))
    with pytest.raises(ValueError, match="do not broadcast"):
        cd.point_circle_grad(np.zeros((2, 3)), cd.Circle(np.zeros((3, 3)), (0, 0, 1), 1))
    with pytest.raises(TypeError, match="torus_sphere: argument b"):
        cd.torus_sphere(t, t)
    with pytest.raises(TypeError, match="capsule_capsule_grad: argument a"):
        cd.capsule_capsule_grad("capsule", cd.Capsule(((0, 0, 0), (1, 0, 0)), 1))
    with pytest.raises(ValueError, match="Sphere.center"):
        cd.Sphere((0, 0), 1)
    q = cd.Query()
    q.close()
    with pytest.raises(ValueError, match="closed"):
        q.sphere_sphere(((0, 0, 0), 1), ((1, 0, 0), 1))


# ---- arrays: one C call (cdist_batch_contact / cdist_batch_grad) ----------------------------

def stack(objs):
    """An array object of the objects' class holding every object of objs."""
    return type(objs[0]).from_array(np.stack([o.data for o in objs]))


@pytest.mark.parametrize("name", SWEPT + [n + "_grad" for n in SWEPT + CORE_GRAD])
def test_arrays_are_the_single_queries(name):
    """Every entry of an array call is the single query's answer, bit for bit (gradient and
    contact/result), a bad entry gets its status and NaN, broadcasting an object works."""
    base = name[:-5] if name.endswith("_grad") else name
    ka, kb = split(base)
    rng = np.random.default_rng(sum(map(ord, name)) + 7)
    n = 12
    A = [make(ka, rng) for _ in range(n)]
    B = [make(kb, rng, offset=0.8) for _ in range(n)]
    a, b = stack(A), stack(B)
    a.data[5, 0] = np.nan                        # a bad entry
    fn = getattr(cd, name)
    grad = name.endswith("_grad")
    for threads in (1, 2):
        out = fn(a, b, threads=threads)
        res, g = out if grad else (out, None)
        assert res.shape == (n,) and res.status[5] == 2 and np.isnan(res.distance[5])
        for i in range(n):
            if i == 5:
                with pytest.raises(cd.CircleDistError):
                    fn(type(a).from_array(a.data[i]), B[i])
                continue
            one = fn(type(a).from_array(a.data[i]), B[i])
            one_res, one_g = one if grad else (one, None)
            assert res.status[i] == 0
            assert res.distance[i] == one_res.distance and res.num_pairs[i] == one_res.num_pairs
            assert np.array_equal(res.points[i, :one_res.num_pairs], one_res.points)
            if grad:
                assert g.flags[i] == one_g.flags and g.differentiable[i] == one_g.differentiable
                for k in range(2):
                    for f in _lib.GRAD_OBJECT_FIELDS:
                        assert np.array_equal(getattr(g.obj[k], f)[i], getattr(one_g.obj[k], f)), (k, f)
                assert g[i].flags == one_g.flags
        if grad:
            assert np.all(np.isnan(g.obj[0].d_center[5]))
        # broadcast: one second object for every first
        bc = fn(a, B[3], threads=threads)
        bres = bc[0] if grad else bc
        one = fn(type(a).from_array(a.data[3]), B[3])
        assert bres.distance[3] == (one[0] if grad else one).distance


@pytest.mark.parametrize("name", SWEPT)
def test_distance_only_is_the_signed_distance(name):
    ka, kb = split(name)
    rng = np.random.default_rng(sum(map(ord, name)) + 11)
    a = stack([make(ka, rng) for _ in range(100)])
    b = stack([make(kb, rng, offset=0.8) for _ in range(100)])
    full = getattr(cd, name)(a, b)
    d = getattr(cd, name)(a, b, distance_only=True)
    scale = 1 + np.abs(a.data).max() + np.abs(b.data).max()
    assert np.all(d.status == 0) and d.raw is None
    assert np.allclose(d.distance, full.distance, rtol=0, atol=4 * np.finfo(float).eps * scale)


def test_batch_out_buffers_and_shapes():
    rng = np.random.default_rng(3)
    T = stack([make("torus", rng) for _ in range(6)])
    T2 = cd.Torus.from_array(T.data.reshape(2, 3, 8))
    t0 = make("torus", rng)
    c, g = cd.torus_torus_grad(T2, t0)
    assert c.shape == g.shape == (2, 3) and g.obj[1].d_center.shape == (2, 3, 3)
    assert c.normals.shape == (2, 3, 2, 3) and c.core_points.shape == (2, 3, 2, 2, 3)
    again = cd.torus_torus_grad(T2, t0, out=(c, g))
    assert again[0] is c and again[1] is g
    with pytest.raises(ValueError):
        cd.torus_torus_grad(T2, t0, out=c)
    cc = cd.torus_torus(T2, t0)
    assert cd.torus_torus(T2, t0, out=cc) is cc
    with pytest.raises(ValueError):
        cd.torus_torus(T2, t0, out=cd.circle_circle(T2.circle, t0.circle))
    assert isinstance(cc[1, 2], cd.Contact) and cc[1, 2].distance == cc.distance[1, 2]
