# SPDX-License-Identifier: MIT
"""Query handles, results and the query functions (internal module; see the package docs)."""
import ctypes
import enum
import inspect
import math
import struct
import threading

import numpy as np

from . import _lib
from ._objects import (Arc, Bezier3, Capsule, Circle, Disk, Helix, Line, Point, Ray,
                       RoundedDisk, Segment, Sphere, Torus, _plain, as_float_array, coerce)


class Method(enum.IntEnum):
    """Algorithms (cdist_method). A query without the chosen method answers with AUTO;
    Result.method says which one answered."""
    AUTO = 0
    POLYNOMIAL = 1
    ROBUST = 2
    ITERATION = 3


class CircleDistError(Exception):
    """A query or option was rejected by the library.

    Attributes: status (int, a cdist_status), name (e.g. "CDIST_ERR_NOT_UNIT"), message (the
    library's explanation, cdist_query_last_error)."""

    def __init__(self, status, message):
        self.status = int(status)
        self.name = status_name(status)
        self.message = message
        super().__init__("%s: %s" % (self.name, message))


def status_name(status):
    """The name of a status code, e.g. status_name(4) == "CDIST_ERR_NOT_UNIT"."""
    return _lib.status_name(int(status)).decode()


def status_string(status):
    """A one-line English description of a status code."""
    return _lib.status_string(int(status)).decode()


def version():
    """The loaded C library's version string, e.g. "1.0.0"."""
    return _lib.version_string().decode()


def _method_value(method):
    if isinstance(method, str):
        try:
            return Method[method.upper()]
        except KeyError:
            raise ValueError("method: expected one of %s, got %r" % (
                ", ".join(m.name.lower() for m in Method), method)) from None
    if isinstance(method, (bool, float)) or not isinstance(method, (int, np.integer)):
        raise TypeError("method: expected a Method, its name or its number, got %r" % (method,))
    return int(method)


def _threads_value(threads):
    if isinstance(threads, bool) or not isinstance(threads, (int, np.integer)):
        raise TypeError("threads: expected an int, got %r" % (threads,))
    return int(threads)


class Pair(tuple):
    """One closest pair: points (2, 3) array (on the first and second object) and params (2,)
    (the parameter of each point on its object; NaN where meaningless)."""
    __slots__ = ()

    def __new__(cls, points, params):
        return tuple.__new__(cls, (points, params))

    points = property(lambda self: self[0], doc="the two points, shape (2, 3)")
    params = property(lambda self: self[1], doc="their parameters, shape (2,)")

    def __repr__(self):
        return "Pair(points=%r, params=%r)" % (self[0].tolist(), self[1].tolist())


# struct cdist_result up to its reserved area: distance, sqr_distance, num_pairs, equidistant,
# pairs (2 x (point[2][3], param[2])), method, iterations -- checked against RESULT_DTYPE below.
_RESULT_HEAD = struct.Struct("=2d2i16d2i")
_METHODS = tuple(Method)
_OFFSETS = {k: v[1] for k, v in _lib.RESULT_DTYPE.fields.items()}
assert (_OFFSETS["pairs"], _OFFSETS["num_pairs"], _OFFSETS["equidistant"], _OFFSETS["method"],
        _OFFSETS["iterations"], _lib.PAIR_DTYPE.itemsize, _RESULT_HEAD.size) == \
    (24, 16, 20, 152, 156, 64, 160), _OFFSETS
# struct cdist_contact up to its reserved area: distance, core_distance, num_pairs,
# equidistant, flags, method, pairs (2 x (point[2][3], core_point[2][3], normal, param[2])).
_CONTACT_HEAD = struct.Struct("=2d4i34d")
# struct cdist_grad: obj[2] (7 vec3, 4 doubles, reserved[8] each), flags, reserved_int, ...
_GRAD_OBJECT_DOUBLES = _lib.GRAD_OBJECT_DTYPE.itemsize // 8
_GRAD_FLAGS = struct.Struct("=i")
_GRAD_OFFSETS = {k: v[1] for k, v in _lib.GRAD_DTYPE.fields.items()}
_C_OFFSETS = {k: v[1] for k, v in _lib.CONTACT_DTYPE.fields.items()}
assert (_C_OFFSETS["pairs"], _C_OFFSETS["method"], _lib.CONTACT_PAIR_DTYPE.itemsize,
        _CONTACT_HEAD.size, _lib.GRAD_OBJECT_DTYPE.fields["d_end"][1], _GRAD_OBJECT_DOUBLES,
        _GRAD_OFFSETS["flags"]) == (32, 28, 136, 304, 192, 33, 528), (_C_OFFSETS, _GRAD_OFFSETS)


class Result:
    """The answer to one query.

    distance, sqr_distance: the minimum distance and its square.
    pairs: list of 1 or 2 Pair (points, params); points: array (num_pairs, 2, 3) with
    points[i, 0] on the first object and points[i, 1] on the second; params: array
    (num_pairs, 2) (line parameter, circle angle in the basis of circle_basis(), curve
    parameter; NaN where meaningless). equidistant: True when infinitely many closest pairs
    exist (one representative is given). method: the Method that answered; iterations: used by
    Method.ITERATION (else 0)."""

    __slots__ = ("distance", "sqr_distance", "num_pairs", "equidistant", "method", "iterations",
                 "_pairs", "_points", "_params")

    def __init__(self, raw):
        """raw: one cdist_result as a numpy structured scalar or 0-d array (RESULT_DTYPE)."""
        self._read(np.ascontiguousarray(np.asarray(raw).reshape(1)).data)

    @classmethod
    def _from_buffer(cls, buffer):
        r = cls.__new__(cls)
        r._read(buffer)
        return r

    def _read(self, buffer):
        v = _RESULT_HEAD.unpack_from(buffer)
        self.distance, self.sqr_distance, k, eq = v[0], v[1], v[2], v[3]
        self.num_pairs, self.equidistant = k, bool(eq)
        self.method, self.iterations = _METHODS[v[20]], v[21]
        self._pairs = v[4:4 + 8 * k]
        self._points = self._params = None

    @property
    def points(self):
        """Closest points, shape (num_pairs, 2, 3): [i, 0] on the first object, [i, 1] on the second."""
        if self._points is None:
            self._points = np.array(self._pairs).reshape(-1, 8)[:, :6].reshape(-1, 2, 3)
        return self._points

    @property
    def params(self):
        """Parameters of the closest points, shape (num_pairs, 2)."""
        if self._params is None:
            self._params = np.array(self._pairs).reshape(-1, 8)[:, 6:]
        return self._params

    @property
    def pairs(self):
        """The closest pairs as a list of Pair(points, params)."""
        return [Pair(p, t) for p, t in zip(self.points, self.params)]

    def __repr__(self):
        return "Result(distance=%r, num_pairs=%d, equidistant=%r, method=%s)" % (
            self.distance, self.num_pairs, self.equidistant, self.method.name)


class BatchResult:
    """Answers to an array of queries, as numpy arrays of the broadcast batch shape S.

    distance (S), status (S, int32 cdist_status, 0 = OK; a bad entry has its status and NaN),
    and unless distance_only was asked: sqr_distance (S), num_pairs (S), equidistant (S, bool),
    points (S + (2, 2, 3): [..., i, j] is pair i's point on object j; only pairs
    i < num_pairs are meaningful), params (S + (2, 2)), method (S). The arrays are views of one buffer of C result
    structs (raw, numpy dtype RESULT_DTYPE), not copies."""

    def __init__(self, raw, status, distance=None):
        self.raw = raw
        self.status = status
        self.distance = raw["distance"] if raw is not None else distance

    def _field(self, name):
        if self.raw is None:
            raise AttributeError("%s: not computed (distance_only=True)" % name)
        return self.raw[name]

    sqr_distance = property(lambda self: self._field("sqr_distance"), doc="squared distances")
    num_pairs = property(lambda self: self._field("num_pairs"), doc="pairs given (0 on error)")
    equidistant = property(lambda self: self._field("equidistant") != 0, doc="infinitely many pairs")
    method = property(lambda self: self._field("method"), doc="Method that answered")
    iterations = property(lambda self: self._field("iterations"), doc="iterations (ITERATION)")
    points = property(lambda self: self._field("pairs")["point"], doc="S + (2, 2, 3) points")
    params = property(lambda self: self._field("pairs")["param"], doc="S + (2, 2) parameters")

    @property
    def ok(self):
        """Boolean mask of the entries answered without error."""
        return self.status == 0

    @property
    def shape(self):
        """The batch shape."""
        return self.status.shape

    def __len__(self):
        return len(self.status)

    def status_names(self):
        """The status names as an array of str (e.g. "CDIST_OK", "CDIST_ERR_NOT_UNIT")."""
        codes, inverse = np.unique(self.status, return_inverse=True)
        return np.array([status_name(c) for c in codes], dtype=object)[inverse].reshape(self.shape)

    def __getitem__(self, index):
        """Result of one entry (raises CircleDistError for a failed entry)."""
        st = int(self.status[index])
        if st != 0:
            raise CircleDistError(st, "entry %r: %s" % (index, status_string(st)))
        if self.raw is None:
            raise TypeError("distance_only batch: index .distance instead")
        return Result(self.raw[index])

    def __repr__(self):
        return "<BatchResult shape=%s, %d failed>" % (self.shape, int(np.count_nonzero(self.status)))


class ContactPair(tuple):
    """One closest pair of a contact (swept-object) query: points (2, 3) witness points on the
    two surfaces, core_points (2, 3) the closest pair of the cores, normal (3,) the unit
    contact normal from the first object to the second, params (2,) the core points'
    parameters (NaN for a point core). points[0] = core_points[0] + r0 normal,
    points[1] = core_points[1] - r1 normal."""
    __slots__ = ()

    def __new__(cls, points, core_points, normal, params):
        return tuple.__new__(cls, (points, core_points, normal, params))

    points = property(lambda self: self[0], doc="witness points on the surfaces, shape (2, 3)")
    core_points = property(lambda self: self[1], doc="closest points of the cores, shape (2, 3)")
    normal = property(lambda self: self[2], doc="unit normal from the first object, shape (3,)")
    params = property(lambda self: self[3], doc="core parameters, shape (2,)")

    def __repr__(self):
        return "ContactPair(points=%r, normal=%r)" % (self[0].tolist(), self[2].tolist())


class Contact:
    """The answer to one swept-object query (struct cdist_contact).

    distance: the signed distance core_distance - (r0 + r1), negative when the solids overlap
    (-distance is then the penetration depth); core_distance: the distance of the cores (point,
    segment, circle, disk; plain objects are their own core, radius 0). pairs: list of 1 or 2
    ContactPair; points, core_points (num_pairs, 2, 3), normals (num_pairs, 3), params
    (num_pairs, 2) as arrays. equidistant: infinitely many closest pairs (from the core query).
    flags: bits of cdist_contact_flag; core_touch: the cores touch or cross, so the normal is
    chosen by the documented rule (CDIST_CONTACT_CORE_TOUCH, see docs/swept.md). method: the
    Method that answered the core query."""

    __slots__ = ("distance", "core_distance", "num_pairs", "equidistant", "flags", "method",
                 "points", "core_points", "normals", "params")

    def __init__(self, raw):
        """raw: one cdist_contact as a numpy structured scalar or 0-d array (CONTACT_DTYPE)."""
        self._read(np.ascontiguousarray(np.asarray(raw).reshape(1)).data)

    @classmethod
    def _from_buffer(cls, buffer):
        c = cls.__new__(cls)
        c._read(buffer)
        return c

    def _read(self, buffer):
        v = _CONTACT_HEAD.unpack_from(buffer)
        self.distance, self.core_distance = v[0], v[1]
        k = self.num_pairs = v[2]
        self.equidistant, self.flags, self.method = bool(v[3]), v[4], _METHODS[v[5]]
        pairs = np.array(v[6:6 + 17 * k]).reshape(k, 17)   # point[2], core_point[2], normal, param
        self.points = pairs[:, 0:6].reshape(k, 2, 3)
        self.core_points = pairs[:, 6:12].reshape(k, 2, 3)
        self.normals = pairs[:, 12:15]
        self.params = pairs[:, 15:17]

    @property
    def core_touch(self):
        """True when CDIST_CONTACT_CORE_TOUCH is set (the cores touch or cross)."""
        return bool(self.flags & _lib.CONTACT_CORE_TOUCH)

    @property
    def pairs(self):
        """The closest pairs as a list of ContactPair(points, core_points, normal, params)."""
        return [ContactPair(*v) for v in zip(self.points, self.core_points, self.normals, self.params)]

    def __repr__(self):
        return "Contact(distance=%r, core_distance=%r, num_pairs=%d, equidistant=%r, " \
            "core_touch=%r, method=%s)" % (self.distance, self.core_distance, self.num_pairs,
                                           self.equidistant, self.core_touch, self.method.name)


class GradObject:
    """Derivatives of the distance with respect to one object's parameters (struct
    cdist_grad_object): d_center, d_normal, d_origin, d_direction, d_p0, d_p1, d_zero_direction
    (arrays (3,)), d_radius, d_radius_swept, d_start, d_end (floats). Fields that do not apply
    to the object are 0. Normal and direction derivatives lie in the tangent space of the unit
    sphere (dD = d_normal . dN for a dN keeping N unit). d_radius is a circle's, disk's or arc's
    radius (the core radius of a torus or rounded disk); d_radius_swept the sphere or capsule
    radius, torus tube radius or rounded-disk radius (-1)."""

    __slots__ = _lib.GRAD_OBJECT_FIELDS

    def __init__(self, values):
        """values: the 25 doubles of one cdist_grad_object up to its reserved area."""
        values = np.asarray(values, dtype=np.float64)
        for i, f in enumerate(_lib.GRAD_OBJECT_FIELDS[:7]):
            setattr(self, f, values[3 * i:3 * i + 3])
        for i, f in enumerate(_lib.GRAD_OBJECT_FIELDS[7:]):
            setattr(self, f, float(values[21 + i]))

    def __repr__(self):
        return "GradObject(%s)" % ", ".join(
            "%s=%r" % (f, _plain(getattr(self, f))) for f in _lib.GRAD_OBJECT_FIELDS
            if np.any(getattr(self, f)))


class Grad:
    """The gradient of one query's distance (struct cdist_grad): obj[0] (GradObject) for the
    first object, obj[1] for the second; flags (bits of cdist_grad_flag). differentiable is
    False when CDIST_GRAD_NOT_DIFFERENTIABLE is set: at a (core) distance above 0, two closest
    pairs or an equidistant result (the gradient of pairs[0] is given); at (core) distance 0
    (the gradient is 0 there, swept radii -1) unless the distance stays 0 nearby (a stable
    crossing of a disk). The rules are in circledist.h ("gradients")."""

    __slots__ = ("obj", "flags")

    def __init__(self, raw):
        """raw: one cdist_grad as a numpy structured scalar or 0-d array (GRAD_DTYPE)."""
        self._read(np.ascontiguousarray(np.asarray(raw).reshape(1)).data)

    @classmethod
    def _from_buffer(cls, buffer):
        g = cls.__new__(cls)
        g._read(buffer)
        return g

    def _read(self, buffer):
        values = np.frombuffer(buffer, np.float64, 2 * _GRAD_OBJECT_DOUBLES).copy()
        self.obj = (GradObject(values[:25]), GradObject(values[_GRAD_OBJECT_DOUBLES:][:25]))
        self.flags = _GRAD_FLAGS.unpack_from(buffer, _GRAD_OFFSETS["flags"])[0]

    @property
    def differentiable(self):
        """False when CDIST_GRAD_NOT_DIFFERENTIABLE is set."""
        return not self.flags & _lib.GRAD_NOT_DIFFERENTIABLE

    def __repr__(self):
        return "Grad(differentiable=%r, obj=(%r, %r))" % (self.differentiable, *self.obj)

# Status codes that concern the whole call (not one entry): raised as CircleDistError.
_CALL_ERRORS = {1, 11, 13, 15, 16}

# name, kind number (cdist_kind), first and second object class, C function of one query
_KINDS = [
    ("point_circle", 0, Point, Circle), ("point_disk", 1, Point, Disk),
    ("line_circle", 2, Line, Circle), ("ray_circle", 3, Ray, Circle),
    ("segment_circle", 4, Segment, Circle), ("circle_circle", 5, Circle, Circle),
    ("line_disk", 6, Line, Disk), ("ray_disk", 7, Ray, Disk), ("segment_disk", 8, Segment, Disk),
    ("circle_disk", 9, Circle, Disk), ("disk_disk", 10, Disk, Disk),
    ("arc_circle", 13, Arc, Circle), ("arc_arc", 14, Arc, Arc), ("segment_arc", 15, Segment, Arc),
    ("arc_disk", 16, Arc, Disk), ("helix_circle", 17, Helix, Circle), ("helix_disk", 18, Helix, Disk),
    ("bezier3_circle", 19, Bezier3, Circle), ("bezier3_disk", 20, Bezier3, Disk),
]
KIND_CURVE_CIRCLE, KIND_CURVE_DISK = 11, 12
if _lib.kind_name is not None:  # the batch kinds must be the C library's, with the same structs
    for _name, _kind, _ca, _cb in _KINDS:
        if (_lib.kind_name(_kind) or b"").decode() != _name or \
                (_lib.kind_size_a(_kind), _lib.kind_size_b(_kind)) != (8 * _ca.WIDTH, 8 * _cb.WIDTH):
            raise ImportError("circledist: the library's batch kind %d is not %s(%s, %s)"
                              % (_kind, _name, _ca.__name__, _cb.__name__))
    if _lib.kind_size_a(KIND_CURVE_CIRCLE) != ctypes.sizeof(_lib.Curve):
        raise ImportError("circledist: the library's cdist_curve does not match this package")
_SINGLE = {name: _lib.single_query(name) for name, _, _, _ in _KINDS}


def _rows(data, shape, n, width):
    """(pointer, byte stride, keep-alive) of `data` (batch shape + (width,)) seen as n rows of
    the broadcast batch `shape`: stride 0 for one object, a view where possible, else a copy."""
    if data.ndim == 1 or data.size == width:          # one object for every entry
        a = np.ascontiguousarray(data.reshape(width))
        return a.ctypes.data, 0, a
    if data.shape[:-1] != shape:                      # general broadcasting: materialise
        data = np.broadcast_to(data, shape + (width,))
    a = data.reshape(n, width)                        # a view unless the batch axes are strided
    if a.strides[1] != 8:
        a = np.ascontiguousarray(a)
    return a.ctypes.data, a.strides[0], a


class Query:
    """A query handle: the library's options and workspaces (cdist_query). Use one per thread
    (calls on one handle from several threads are serialised by a lock).

    Query(method=Method.AUTO, unit_tolerance=None, curve_samples=None, max_iterations=None,
    threads=1). Every query kind is a method, e.g. q.circle_circle(a, b); the module-level
    functions of the same names use a per-thread default handle. Use as a context manager or
    call close()."""

    def __init__(self, method=Method.AUTO, unit_tolerance=None, curve_samples=None,
                 max_iterations=None, threads=1):
        self._lock = threading.RLock()
        self._one = np.zeros(1, _lib.RESULT_DTYPE)        # result buffer of single queries
        self._one_buffer = self._one.data
        self._one_addr = self._one.ctypes.data
        self._contact = np.zeros(1, _lib.CONTACT_DTYPE)   # buffers of swept / gradient queries
        self._contact_buffer = self._contact.data
        self._contact_addr = self._contact.ctypes.data
        self._grad = np.zeros(1, _lib.GRAD_DTYPE)
        self._grad_buffer = self._grad.data
        self._grad_addr = self._grad.ctypes.data
        self._q = _lib.query_new()
        if not self._q:
            raise MemoryError("cdist_query_new failed")
        self.set_method(method)
        if unit_tolerance is not None:
            self._check(_lib.query_set_unit_tolerance(self._q, float(unit_tolerance)))
        if curve_samples is not None:
            self._check(_lib.query_set_curve_samples(self._q, int(curve_samples)))
        if max_iterations is not None:
            self._check(_lib.query_set_max_iterations(self._q, int(max_iterations)))
        self._threads = 1
        if threads != 1:
            self.set_threads(threads)

    # ---- options ---------------------------------------------------------------------------
    def _check(self, st):
        if st != 0:
            raise CircleDistError(st, _lib.query_last_error(self._handle()).decode())

    def _handle(self):
        if not self._q:
            raise ValueError("the Query handle is closed")
        return self._q

    def set_method(self, method):
        """Set the algorithm (a Method, its name such as "robust", or its number)."""
        self._check(_lib.query_set_method(self._handle(), _method_value(method)))

    @property
    def method(self):
        """The handle's Method."""
        return Method(_lib.query_get_method(self._handle()))

    @property
    def unit_tolerance(self):
        """Relative tolerance on the length of unit normals and directions (default 1e-6)."""
        return _lib.query_get_unit_tolerance(self._handle())

    @property
    def curve_samples(self):
        """Sampling intervals for callback curves, helices (per turn) and Beziers."""
        return _lib.query_get_curve_samples(self._handle())

    def set_threads(self, threads):
        """Worker threads used by the vectorised calls (1..256; creating them has a cost, so
        the count is kept until changed). Results are identical for every count."""
        threads = _threads_value(threads)
        if threads == self._threads:
            return
        if _lib.query_set_threads is None:
            raise RuntimeError("the loaded libcircledist has no batch API (cdist_query_set_threads)")
        self._check(_lib.query_set_threads(self._handle(), threads))
        self._threads = threads

    @property
    def threads(self):
        """The handle's worker thread count."""
        return self._threads

    def close(self):
        """Free the C handle (also done when the object is garbage collected)."""
        if getattr(self, "_q", None):
            _lib.query_free(self._q)
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

    # ---- the one query path ----------------------------------------------------------------
    def _override_method(self, q, method):
        """Set `method` for one call; returns the method to restore afterwards (None: none)."""
        if method is None:
            return None
        m = _method_value(method)
        old = _lib.query_get_method(q)
        if m == old:
            return None
        self._check(_lib.query_set_method(q, m))
        return old

    def _run(self, name, kind, a, b, method, threads, distance_only, single_call, out=None):
        with self._lock:
            q = self._handle()
            old = self._override_method(q, method)
            try:
                if threads is not None:
                    self.set_threads(threads)
                if a.shape == () and b.shape == () and not distance_only and out is None:
                    self._check(single_call(q, a, b, self._one_addr))
                    return Result._from_buffer(self._one_buffer)
                return self._batch(name, kind, a, b, distance_only, out)
            finally:
                if old is not None:
                    _lib.query_set_method(q, old)

    def _batch(self, name, kind, a, b, distance_only, out=None):
        if _lib.batch is None:
            raise RuntimeError("%s: the loaded libcircledist has no batch API (cdist_batch); "
                               "arrays of objects need a library with it" % name)
        try:
            shape = np.broadcast_shapes(a.shape, b.shape)
        except ValueError:
            raise ValueError("%s: the batch shapes of the arguments do not broadcast: %s and %s"
                             % (name, a.shape, b.shape)) from None
        n = math.prod(shape)
        pa, sa, keep_a = a.rows(shape, n) if isinstance(a, _CurveArg) else _rows(a.data, shape, n, a.WIDTH)
        pb, sb, keep_b = _rows(b.data, shape, n, b.WIDTH)
        if out is not None:
            if not isinstance(out, BatchResult) or out.shape != shape or \
                    (out.raw is None) != bool(distance_only):
                raise ValueError("%s: out must be a BatchResult of shape %s from a call with "
                                 "distance_only=%s" % (name, shape, bool(distance_only)))
            res = out
        elif distance_only:
            res = BatchResult(None, np.empty(shape, np.int32), np.empty(shape, np.float64))
        else:
            res = BatchResult(np.empty(shape, _lib.RESULT_DTYPE), np.empty(shape, np.int32))
        status = res.status
        if distance_only:
            st = _lib.batch_distance(self._q, kind, n, pa, sa, pb, sb, res.distance.ctypes.data,
                                     status.ctypes.data) if n else 0
        else:
            st = _lib.batch(self._q, kind, n, pa, sa, pb, sb, res.raw.ctypes.data,
                            status.ctypes.data) if n else 0
        del keep_a, keep_b
        if st in _CALL_ERRORS:
            self._check(st)
        return res

    # ---- swept objects and gradients: one object each (the batch API has no such kinds) ----
    def _single(self, name, c_fn, a, b, method, contact, grad):
        if c_fn is None:
            raise RuntimeError("%s: the loaded libcircledist has no cdist_%s%s"
                               % (name, name.replace("_grad", ""), "_grad" if grad else ""))
        if a.shape or b.shape:
            raise ValueError("%s: takes one object each (cdist_batch has no swept or gradient "
                             "kinds; loop over the entries in Python), got batch shapes %s and %s"
                             % (name, a.shape, b.shape))
        with self._lock:
            q = self._handle()
            old = self._override_method(q, method)
            try:
                out = self._contact_addr if contact else self._one_addr
                if grad:
                    st = c_fn(q, a.address, b.address, out, self._grad_addr)
                else:
                    st = c_fn(q, a.address, b.address, out)
                if st:
                    self._check(st)
                res = Contact._from_buffer(self._contact_buffer) if contact else \
                    Result._from_buffer(self._one_buffer)
                return (res, Grad._from_buffer(self._grad_buffer)) if grad else res
            finally:
                if old is not None:
                    _lib.query_set_method(q, old)

    # ---- curves ----------------------------------------------------------------------------
    def _curve(self, name, kind, f, t0, t1, other, method, threads, distance_only, out):
        if not callable(f):
            raise TypeError("%s: f must be callable as f(t) -> (position, derivative), got %s"
                            % (name, type(f).__name__))
        t0, t1 = (float(as_float_array(t, "%s: %s" % (name, w))) for t, w in ((t0, "t0"), (t1, "t1")))
        curve = _CurveArg(f, t0, t1)
        c_single = _lib.curve_circle if kind == KIND_CURVE_CIRCLE else _lib.curve_disk

        def single(q, _a, b, r):
            return c_single(q, curve.fn, None, t0, t1, b.address, r)
        try:
            res = self._run(name, kind, curve, other, method, threads, distance_only, single, out)
        except CircleDistError as e:
            if curve.errors:
                raise curve.errors[0] from e
            raise
        if curve.errors:      # a vectorised call: the failing entries have their status
            raise curve.errors[0]
        return res


class _CurveArg:
    """A Python callable as a cdist_curve (the C callback wrapper lives as long as this)."""

    shape = ()

    def __init__(self, f, t0, t1):
        self.errors = []
        errors = self.errors

        def call(_user, t, pos, der):
            try:
                p, d = f(t)
                pos[0], pos[1], pos[2] = p
                der[0], der[1], der[2] = d
                return 0
            except BaseException as e:  # noqa: B036 - reported after the C call returns
                errors.append(e)
                return 1
        self.fn = _lib.CURVE_FN(call)
        self.struct = _lib.Curve(self.fn, None, t0, t1)

    def rows(self, shape, n):
        return ctypes.addressof(self.struct), 0, self


def _make_method(name, kind, cls_a, cls_b):
    c_fn = _SINGLE[name]
    na, nb = name.split("_")

    def single(q, a, b, r):
        return c_fn(q, a.address, b.address, r)

    def query(self, a, b, *, method=None, threads=None, distance_only=False, out=None):
        if type(a) is not cls_a:
            a = coerce(a, cls_a, "%s: argument a (the %s)" % (name, na))
        if type(b) is not cls_b:
            b = coerce(b, cls_b, "%s: argument b (the %s)" % (name, nb))
        if a.data.ndim == 1 and b.data.ndim == 1 and method is None and not distance_only and \
                out is None and (threads is None or threads == self._threads):
            with self._lock:       # the common single query, kept short
                st = c_fn(self._handle(), a.address, b.address, self._one_addr)
                if st:
                    self._check(st)
                return Result._from_buffer(self._one_buffer)
        return self._run(name, kind, a, b, method, threads, distance_only, single, out)

    query.__name__ = name
    query.__doc__ = """Minimum distance from a %(A)s (a) to a %(B)s (b): cdist_%(name)s.

        a: %(A)s, b: %(B)s -- one object each, or arrays of objects (see the classes), whose
        batch shapes broadcast. One object each: returns a Result and raises CircleDistError
        on bad input. Arrays: one C call (cdist_batch) answers all entries and returns a
        BatchResult; a bad entry gets its status and NaN, the others are answered.
        method: a Method (or its name) for this call only; threads: worker threads for the
        vectorised call (kept on the handle); distance_only: only distances (and statuses),
        through cdist_batch_distance (SIMD screening path); always returns a BatchResult.
        out: a BatchResult of the same shape (and distance_only) to write into instead of
        allocating new buffers (saves the page faults of fresh memory in repeated calls).""" % {
        "A": cls_a.__name__, "B": cls_b.__name__, "name": name}
    return query


for _name, _kind, _ca, _cb in _KINDS:
    setattr(Query, _name, _make_method(_name, _kind, _ca, _cb))


# Swept queries: name, first and second object class (one object each; cdist_<name>).
_SWEPT_KINDS = [
    ("torus_torus", Torus, Torus), ("torus_capsule", Torus, Capsule),
    ("torus_sphere", Torus, Sphere), ("torus_rounded_disk", Torus, RoundedDisk),
    ("capsule_capsule", Capsule, Capsule), ("capsule_sphere", Capsule, Sphere),
    ("capsule_rounded_disk", Capsule, RoundedDisk), ("sphere_sphere", Sphere, Sphere),
    ("sphere_rounded_disk", Sphere, RoundedDisk),
    ("rounded_disk_rounded_disk", RoundedDisk, RoundedDisk),
    ("torus_line", Torus, Line), ("torus_ray", Torus, Ray), ("torus_segment", Torus, Segment),
    ("capsule_circle", Capsule, Circle), ("capsule_disk", Capsule, Disk),
    ("sphere_circle", Sphere, Circle), ("sphere_disk", Sphere, Disk),
]
# Core queries with a cdist_<name>_grad variant.
_GRAD_CORE = ["point_circle", "point_disk", "line_circle", "ray_circle", "segment_circle",
              "circle_circle", "line_disk", "ray_disk", "segment_disk", "circle_disk", "disk_disk",
              "arc_circle", "arc_arc", "segment_arc", "arc_disk"]
if _lib.swept_size is not None:  # the swept structs must be the C library's
    for _i, _cls in enumerate((Sphere, Capsule, Torus, RoundedDisk)):
        if _lib.swept_size(_i) != 8 * _cls.WIDTH:
            raise ImportError("circledist: the library's %s is %d bytes, this package expects %d"
                              % (_cls.__name__, _lib.swept_size(_i), 8 * _cls.WIDTH))


def _make_single_method(name, cls_a, cls_b, contact, grad):
    c_name = name + "_grad" if grad else name
    c_fn = _lib.grad_query(name) if grad else _lib.contact_query(name)

    def query(self, a, b, *, method=None):
        if type(a) is not cls_a:
            a = coerce(a, cls_a, "%s: argument a (the %s)" % (c_name, cls_a.__name__))
        if type(b) is not cls_b:
            b = coerce(b, cls_b, "%s: argument b (the %s)" % (c_name, cls_b.__name__))
        return self._single(c_name, c_fn, a, b, method, contact, grad)

    query.__name__ = c_name
    what = {"A": cls_a.__name__, "B": cls_b.__name__, "name": c_name}
    if contact:
        doc = """Signed distance from a %(A)s (a) to a %(B)s (b)%(G)s: cdist_%(name)s.

        a: %(A)s, b: %(B)s -- one object each (arrays are refused: the C batch API has no
        swept kinds; loop in Python, one C call per entry). Contact.distance =
        core_distance - (r0 + r1), negative when the solids overlap; witness points, core
        points, normals. Raises CircleDistError on bad input (e.g. a negative radius).
        method: a Method (or its name) for the core query of this call only.
        Returns %(R)s."""
        what.update(G=" with its gradient" if grad else "",
                    R="(Contact, Grad); Grad holds the derivatives of the signed distance\n"
                    "        (d_radius_swept = -1 for each swept object)" if grad else "a Contact")
    else:
        doc = """Minimum distance from a %(A)s (a) to a %(B)s (b) with its gradient: cdist_%(name)s.

        a: %(A)s, b: %(B)s -- one object each (arrays are refused: the C batch API has no
        gradient kinds; loop in Python, one C call per entry). Returns (Result, Grad).
        Raises CircleDistError on bad input. method: a Method (or its name) for this call only."""
    query.__doc__ = doc % what
    return query


SINGLE_NAMES = []
for _name, _ca, _cb in _SWEPT_KINDS:
    for _grad in (False, True):
        setattr(Query, _name + "_grad" * _grad, _make_single_method(_name, _ca, _cb, True, _grad))
        SINGLE_NAMES.append(_name + "_grad" * _grad)
for _name, _kind, _ca, _cb in _KINDS:
    if _name in _GRAD_CORE:
        setattr(Query, _name + "_grad", _make_single_method(_name, _ca, _cb, False, True))
        SINGLE_NAMES.append(_name + "_grad")


def _curve_method(name, kind):
    def query(self, f, t0, t1, other, *, method=None, threads=None, distance_only=False, out=None):
        other = coerce(other, Circle if kind == KIND_CURVE_CIRCLE else Disk, "%s: argument other" % name)
        return self._curve(name, kind, f, t0, t1, other, method, threads, distance_only, out)
    query.__name__ = name
    query.__doc__ = """Minimum distance from the curve f(t), t in [t0, t1], to a %s: cdist_%s.

        f(t) -> (position, derivative): two length-3 sequences, the point of the curve and its
        exact derivative at t (the curve must be continuously differentiable). other may be an
        array of objects (one vectorised call; the same curve for every entry).
        Cost: the library samples the curve (curve_samples intervals, default 512) and refines
        each bracketed minimum, so one query calls f hundreds of times (829 for 1.4 turns of a
        helix); each call from C into Python costs several microseconds (the ctypes callback
        and conversions, against 0.2 us for f itself), which dominates: that query took ~7 ms,
        about 7x the same curve as a built-in Helix (use Helix, Bezier3, Arc or Segment when the
        curve is one of them). With threads > 1 the callbacks still run one at a time (GIL). An exception raised by f aborts the query and is re-raised
        (chained to the CircleDistError CDIST_ERR_CALLBACK_FAILED); in the vectorised form the
        first exception is re-raised after the call and the other answers are discarded.""" % (
        "circle" if kind == KIND_CURVE_CIRCLE else "disk", name)
    return query


Query.curve_circle = _curve_method("curve_circle", KIND_CURVE_CIRCLE)
Query.curve_disk = _curve_method("curve_disk", KIND_CURVE_DISK)


def circle_basis(circle):
    """(U, V): the basis in which circle angles are measured (cdist_circle_basis). With N the
    normalised normal and k the index of N's smallest-magnitude component, U = e_k - N_k N
    normalised and V = N x U. circle: one Circle (or Disk)."""
    c = coerce(circle, Circle, "circle_basis: circle")
    if c.shape:
        raise ValueError("circle_basis: circle must be one Circle, got an array of shape %s" % (c.shape,))
    u, v = np.empty(3), np.empty(3)
    st = _lib.circle_basis(c.data.ctypes.data, u.ctypes.data, v.ctypes.data)
    if st:
        raise CircleDistError(st, status_string(st))
    return u, v


def circle_point(circle, angle):
    """The point of one circle at `angle` (radians, in the basis of circle_basis()):
    C + r (cos a U + sin a V) (cdist_circle_point). angle may be an array: returns (..., 3)."""
    c = coerce(circle, Circle, "circle_point: circle")
    if c.shape:
        raise ValueError("circle_point: circle must be one Circle, got an array of shape %s" % (c.shape,))
    a = as_float_array(angle, "circle_point: angle")
    out = np.empty(a.shape + (3,))
    flat = out.reshape(-1, 3)
    for i, t in enumerate(a.reshape(-1)):
        st = _lib.circle_point(c.data.ctypes.data, float(t), flat[i].ctypes.data)
        if st:
            raise CircleDistError(st, "%s (angle %r)" % (status_string(st), float(t)))
    return out if a.ndim else out.reshape(3)


_default = threading.local()


def default_query():
    """This thread's default Query handle (used by the module-level query functions)."""
    q = getattr(_default, "query", None)
    if q is None:
        q = _default.query = Query()
    return q


def _module_function(name):
    unbound = getattr(Query, name)

    def query(*args, method=None, threads=1, distance_only=False, out=None, query=None):
        h = query if query is not None else default_query()
        return getattr(h, name)(*args, method=method, threads=threads, distance_only=distance_only,
                                out=out)
    sig = inspect.signature(unbound)
    params = [p for p in sig.parameters.values() if p.name != "self"]
    params = [p.replace(default=1) if p.name == "threads" else p for p in params]
    query.__signature__ = sig.replace(parameters=params + [
        inspect.Parameter("query", inspect.Parameter.KEYWORD_ONLY, default=None)])
    query.__name__ = name
    query.__doc__ = unbound.__doc__ + """

        Module-level form: uses this thread's default Query unless query= is given; threads
        defaults to 1 here."""
    return query


def _single_module_function(name):
    unbound = getattr(Query, name)

    def query(a, b, *, method=None, query=None):
        h = query if query is not None else default_query()
        return getattr(h, name)(a, b, method=method)
    sig = inspect.signature(unbound)
    query.__signature__ = sig.replace(parameters=[
        p for p in sig.parameters.values() if p.name != "self"] + [
        inspect.Parameter("query", inspect.Parameter.KEYWORD_ONLY, default=None)])
    query.__name__ = name
    query.__doc__ = unbound.__doc__ + """

        Module-level form: uses this thread's default Query unless query= is given."""
    return query


QUERY_NAMES = [k[0] for k in _KINDS] + ["curve_circle", "curve_disk"]
FUNCTIONS = {name: _module_function(name) for name in QUERY_NAMES}
FUNCTIONS.update({name: _single_module_function(name) for name in SINGLE_NAMES})
