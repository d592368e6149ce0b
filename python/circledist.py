# SPDX-License-Identifier: MIT
"""ctypes binding for libcircledist (libcircledist.so.1).

    from circledist import Query, Circle
    with Query() as q:
        r = q.circle_circle(Circle((0, 0, 0), (0, 0, 1), 1), Circle((1, 0, 0), (0, 1, 0), 1))
        print(r.distance, r.pairs)

The library is found through $CIRCLEDIST_LIBRARY (a path), else the system's
libcircledist.so.1. Errors raise CircleDistError(status, name, message).
"""
import ctypes
import ctypes.util
import math
import os
from collections import namedtuple

__all__ = ["Query", "Circle", "Line", "Ray", "Segment", "Arc", "Result", "Pair", "CircleDistError",
           "METHOD_AUTO", "METHOD_POLYNOMIAL", "METHOD_ROBUST", "METHOD_ITERATION", "version"]

METHOD_AUTO, METHOD_POLYNOMIAL, METHOD_ROBUST, METHOD_ITERATION = 0, 1, 2, 3


def _load():
    path = os.environ.get("CIRCLEDIST_LIBRARY")
    if path:
        return ctypes.CDLL(path)
    name = ctypes.util.find_library("circledist") or "libcircledist.so.1"
    return ctypes.CDLL(name)


_lib = _load()


class _Vec3(ctypes.Structure):
    _fields_ = [("x", ctypes.c_double), ("y", ctypes.c_double), ("z", ctypes.c_double)]


class _Circle(ctypes.Structure):
    _fields_ = [("center", _Vec3), ("normal", _Vec3), ("radius", ctypes.c_double)]


class _Line(ctypes.Structure):
    _fields_ = [("origin", _Vec3), ("direction", _Vec3)]


class _Segment(ctypes.Structure):
    _fields_ = [("p0", _Vec3), ("p1", _Vec3)]


class _Arc(ctypes.Structure):
    _fields_ = [("circle", _Circle), ("zero_direction", _Vec3), ("start", ctypes.c_double),
                ("end", ctypes.c_double)]


class _Pair(ctypes.Structure):
    _fields_ = [("point", _Vec3 * 2), ("param", ctypes.c_double * 2)]


class _Result(ctypes.Structure):
    _fields_ = [("distance", ctypes.c_double), ("sqr_distance", ctypes.c_double),
                ("num_pairs", ctypes.c_int), ("equidistant", ctypes.c_int),
                ("pairs", _Pair * 2), ("method", ctypes.c_int), ("iterations", ctypes.c_int),
                ("reserved", ctypes.c_double * 8)]


_lib.cdist_result_size.restype = ctypes.c_size_t
if _lib.cdist_result_size() != ctypes.sizeof(_Result):
    raise ImportError("libcircledist result layout (%d bytes) does not match this binding (%d)"
                      % (_lib.cdist_result_size(), ctypes.sizeof(_Result)))

_lib.cdist_query_new.restype = ctypes.c_void_p
_lib.cdist_query_free.argtypes = [ctypes.c_void_p]
_lib.cdist_query_set_method.argtypes = [ctypes.c_void_p, ctypes.c_int]
_lib.cdist_query_set_unit_tolerance.argtypes = [ctypes.c_void_p, ctypes.c_double]
_lib.cdist_query_last_error.argtypes = [ctypes.c_void_p]
_lib.cdist_query_last_error.restype = ctypes.c_char_p
_lib.cdist_status_name.argtypes = [ctypes.c_int]
_lib.cdist_status_name.restype = ctypes.c_char_p
_lib.cdist_version_string.restype = ctypes.c_char_p

Circle = namedtuple("Circle", "center normal radius")
Line = namedtuple("Line", "origin direction")
Ray = namedtuple("Ray", "origin direction")
Segment = namedtuple("Segment", "p0 p1")
Arc = namedtuple("Arc", "circle zero_direction start end")
Pair = namedtuple("Pair", "points params")
Result = namedtuple("Result", "distance sqr_distance equidistant pairs method iterations")


class CircleDistError(Exception):
    """A query failed: .status (int), .name (e.g. 'CDIST_ERR_NOT_UNIT'), .message."""

    def __init__(self, status, message):
        self.status = status
        self.name = _lib.cdist_status_name(status).decode()
        self.message = message
        super().__init__("%s: %s" % (self.name, message))


def version():
    """The loaded library's version string."""
    return _lib.cdist_version_string().decode()


def _vec(v):
    x, y, z = v
    return _Vec3(float(x), float(y), float(z))


def _circle(c):
    return _Circle(_vec(c[0]), _vec(c[1]), float(c[2]))


def _arc(a):
    return _Arc(_circle(a[0]), _vec(a[1]), float(a[2]), float(a[3]))


_CONVERT = {"vec": (_Vec3, _vec), "circle": (_Circle, _circle), "line": (_Line, lambda l: _Line(_vec(l[0]), _vec(l[1]))),
            "segment": (_Segment, lambda s: _Segment(_vec(s[0]), _vec(s[1]))), "arc": (_Arc, _arc)}

# (python name, C function, kinds of the two objects)
_QUERIES = [
    ("point_circle", "cdist_point_circle", "vec", "circle"),
    ("point_disk", "cdist_point_disk", "vec", "circle"),
    ("line_circle", "cdist_line_circle", "line", "circle"),
    ("ray_circle", "cdist_ray_circle", "line", "circle"),
    ("segment_circle", "cdist_segment_circle", "segment", "circle"),
    ("circle_circle", "cdist_circle_circle", "circle", "circle"),
    ("line_disk", "cdist_line_disk", "line", "circle"),
    ("ray_disk", "cdist_ray_disk", "line", "circle"),
    ("segment_disk", "cdist_segment_disk", "segment", "circle"),
    ("circle_disk", "cdist_circle_disk", "circle", "circle"),
    ("disk_disk", "cdist_disk_disk", "circle", "circle"),
    ("arc_circle", "cdist_arc_circle", "arc", "circle"),
    ("arc_arc", "cdist_arc_arc", "arc", "arc"),
    ("segment_arc", "cdist_segment_arc", "segment", "arc"),
    ("arc_disk", "cdist_arc_disk", "arc", "circle"),
]


def _make_query(cname, k0, k1):
    fn = getattr(_lib, cname)
    t0, conv0 = _CONVERT[k0]
    t1, conv1 = _CONVERT[k1]
    fn.argtypes = [ctypes.c_void_p, ctypes.POINTER(t0), ctypes.POINTER(t1), ctypes.POINTER(_Result)]
    fn.restype = ctypes.c_int

    def query(self, a, b):
        r = _Result()
        st = fn(self._q, ctypes.byref(conv0(a)), ctypes.byref(conv1(b)), ctypes.byref(r))
        return self._finish(st, r)

    query.__doc__ = "%s(a, b) -> Result; raises CircleDistError on bad input." % cname
    return query


class Query:
    """A query handle. One per thread. Use as a context manager or call close()."""

    def __init__(self, method=METHOD_AUTO, unit_tolerance=None):
        self._q = _lib.cdist_query_new()
        if not self._q:
            raise MemoryError("cdist_query_new failed")
        self.set_method(method)
        if unit_tolerance is not None:
            self._check(_lib.cdist_query_set_unit_tolerance(self._q, float(unit_tolerance)))

    def _check(self, st):
        if st != 0:
            raise CircleDistError(st, _lib.cdist_query_last_error(self._q).decode())

    def set_method(self, method):
        self._check(_lib.cdist_query_set_method(self._q, int(method)))

    def _finish(self, st, r):
        self._check(st)
        pairs = []
        for i in range(r.num_pairs):
            p = r.pairs[i]
            pairs.append(Pair(((p.point[0].x, p.point[0].y, p.point[0].z),
                               (p.point[1].x, p.point[1].y, p.point[1].z)),
                              (p.param[0], p.param[1])))
        return Result(r.distance, r.sqr_distance, bool(r.equidistant), pairs, r.method, r.iterations)

    def close(self):
        if self._q:
            _lib.cdist_query_free(self._q)
            self._q = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        try:
            self.close()
        except Exception:
            pass


for _name, _cname, _k0, _k1 in _QUERIES:
    setattr(Query, _name, _make_query(_cname, _k0, _k1))
del _name, _cname, _k0, _k1
