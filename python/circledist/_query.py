# SPDX-License-Identifier: MIT
"""Query handles, results and the query functions (internal module; see the package docs)."""
import contextlib
import ctypes
import enum
import functools
import inspect
import math
import struct
import sys
import threading

import numpy as np

from . import _docs, _lib
from ._interrupt import SigintRecorder
from ._objects import (Arc, Bezier3, Capsule, Circle, Disk, Helix, Line, Point, Ray,
                       RoundedDisk, Segment, Sphere, Torus, _plain, as_float_array, coerce)


class Method(enum.IntEnum):
    """Algorithms of the library (cdist_method).

    A query kind without the chosen method answers with AUTO; Result.method says which one
    answered. ``str(m)`` is the lower-case name the tool prints.

    Parameters
    ----------
    value : int or str
        The number (0..3); ``Method["ROBUST"]`` looks up a name.

    Examples
    --------
    >>> import circledist as cd
    >>> cd.Method.ROBUST, int(cd.Method.ROBUST), str(cd.Method.ROBUST)
    (<Method.ROBUST: 2>, 2, 'robust')
    >>> cd.Method(1)
    <Method.POLYNOMIAL: 1>
    """
    AUTO = 0
    POLYNOMIAL = 1
    ROBUST = 2
    ITERATION = 3

    def __str__(self):
        """The name as the tool and cdist_method_name() spell it: print(r.method) shows 'robust'."""
        return self.name.lower()


class CircleDistError(Exception):
    """A query or option was rejected by the library.

    Parameters
    ----------
    status : int
        The cdist_status code.
    message : str
        The library's explanation (cdist_query_last_error).

    Attributes
    ----------
    status : int
        The cdist_status code.
    name : str
        Its name, e.g. "CDIST_ERR_NOT_UNIT".
    message : str
        The explanation.

    Examples
    --------
    >>> import circledist as cd
    >>> try:
    ...     cd.circle_circle(cd.Circle((0, 0, 0), (0, 0, 2), 1.0), cd.Circle((1, 0, 0), (0, 1, 0), 1.0))
    ... except cd.CircleDistError as e:
    ...     print(e.status, e.name)
    ...     print(e.message)
    4 CDIST_ERR_NOT_UNIT
    first circle normal has length 2, not 1 (tolerance 1e-06; see cdist_query_set_unit_tolerance)
    """

    def __init__(self, status, message):
        self.status = int(status)
        self.name = status_name(status)
        self.message = message
        super().__init__("%s: %s" % (self.name, message))


def status_name(status):
    """The name of a status code (cdist_status_name).

    Parameters
    ----------
    status : int
        A cdist_status code, e.g. an entry of BatchResult.status.

    Returns
    -------
    str
        Its name.

    Examples
    --------
    >>> import circledist as cd
    >>> cd.status_name(0), cd.status_name(4)
    ('CDIST_OK', 'CDIST_ERR_NOT_UNIT')
    """
    return _lib.status_name(int(status)).decode()


def status_string(status):
    """A one-line English description of a status code (cdist_status_string).

    Parameters
    ----------
    status : int
        A cdist_status code.

    Returns
    -------
    str
        The description.

    Examples
    --------
    >>> import circledist as cd
    >>> cd.status_string(4)
    'a normal or direction was not unit length'
    """
    return _lib.status_string(int(status)).decode()


def version():
    """The loaded C library's version (cdist_version_string).

    Returns
    -------
    str
        "MAJOR.MINOR.PATCH".

    Examples
    --------
    >>> import circledist as cd
    >>> cd.version().count(".")
    2
    """
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
    """One closest pair of a Result: a tuple (points, params).

    Parameters
    ----------
    points : ndarray, shape (2, 3)
        The point on the first object and the point on the second.
    params : ndarray, shape (2,)
        The parameter of each point on its object (NaN where meaningless).

    Examples
    --------
    >>> import circledist as cd
    >>> r = cd.point_circle((3.0, 0.0, 0.0), cd.Circle((0, 0, 0), (0, 0, 1), 1.0))
    >>> r.pairs
    [Pair(points=[[3.0, 0.0, 0.0], [1.0, 0.0, 0.0]], params=[nan, 0.0])]
    >>> points, params = r.pairs[0]
    """
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
    """The answer to one query (struct cdist_result), returned by the query functions.

    Parameters
    ----------
    raw : numpy structured scalar or 0-d array of RESULT_DTYPE
        One cdist_result (the query functions build Results themselves).

    Attributes
    ----------
    distance, sqr_distance : float
        The minimum distance and its square.
    num_pairs : int
        1, or 2 for two symmetric closest pairs.
    pairs : list of Pair
        The closest pairs (points, params).
    points : ndarray, shape (num_pairs, 2, 3)
        points[i, 0] on the first object, points[i, 1] on the second.
    params : ndarray, shape (num_pairs, 2)
        Line parameter, circle angle (in the basis of circle_basis()), curve parameter; NaN
        where meaningless.
    equidistant : bool
        Infinitely many closest pairs exist (one representative is given).
    method : Method
        The method that answered.
    iterations : int
        Iterations used by Method.ITERATION (else 0).

    Examples
    --------
    >>> import circledist as cd
    >>> r = cd.point_circle((3.0, 0.0, 0.0), cd.Circle((0, 0, 0), (0, 0, 1), 1.0))
    >>> r.distance, r.num_pairs, r.equidistant
    (2.0, 1, False)
    >>> r.points
    array([[[3., 0., 0.],
            [1., 0., 0.]]])
    """

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


class _Batch:
    """What every batch answer has: status (S, int32 cdist_status), distance (S), raw (the C
    structs, None for distance_only)."""

    def __init__(self, raw, status, distance=None):
        self.raw = raw
        self.status = status
        self.distance = raw["distance"] if raw is not None else distance

    def _field(self, name):
        if self.raw is None:
            raise AttributeError("%s: not computed (distance_only=True)" % name)
        return self.raw[name]

    num_pairs = property(lambda self: self._field("num_pairs"), doc="pairs given (0 on error)")
    equidistant = property(lambda self: self._field("equidistant") != 0, doc="infinitely many pairs")
    method = property(lambda self: self._field("method"), doc="Method that answered")

    @property
    def ok(self):
        """Boolean mask of the entries answered without error."""
        return self.status == 0

    @property
    def cancelled(self):
        """Boolean mask of the entries not answered because the batch was stopped
        (CDIST_ERR_CANCELLED: progress= returned True, or Ctrl-C with out=)."""
        return self.status == _lib.STATUS_CANCELLED

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
        """The answer of one entry (a Result, Contact or Grad; raises CircleDistError for a
        failed entry)."""
        st = int(self.status[index])
        if st != 0:
            raise CircleDistError(st, "entry %r: %s" % (index, status_string(st)))
        if self.raw is None:
            raise TypeError("distance_only batch: index .distance instead")
        return self._one(self.raw[index])

    def __repr__(self):
        return "<%s shape=%s, %d failed>" % (type(self).__name__, self.shape,
                                            int(np.count_nonzero(self.status)))


class BatchResult(_Batch):
    """Answers to an array of queries, as numpy arrays of the broadcast batch shape S.

    The arrays are views of one buffer of C result structs (raw, numpy dtype RESULT_DTYPE),
    not copies; indexing one entry gives its Result.

    Parameters
    ----------
    raw : ndarray of RESULT_DTYPE or None
        The results (None for distance_only).
    status : ndarray of int32
        The status of each entry.
    distance : ndarray of float64, optional
        The distances when raw is None.

    Attributes
    ----------
    distance : ndarray, shape S
        NaN for a bad entry.
    status : ndarray of int32, shape S
        cdist_status of each entry, 0 = OK (see status_names(), ok).
    sqr_distance, num_pairs, equidistant, method, iterations : ndarray, shape S
        As in Result (not with distance_only=True).
    points : ndarray, shape S + (2, 2, 3)
        [..., i, j] is pair i's point on object j; only pairs i < num_pairs are meaningful.
    params : ndarray, shape S + (2, 2)
        The parameters of the points.

    Examples
    --------
    >>> import numpy as np
    >>> import circledist as cd
    >>> points = np.array([[3.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, np.nan]])
    >>> b = cd.point_circle(points, cd.Circle((0, 0, 0), (0, 0, 1), 1.0))
    >>> b.distance.round(9)
    array([2.        , 1.41421356,        nan])
    >>> b.status_names()
    array(['CDIST_OK', 'CDIST_OK', 'CDIST_ERR_NOT_FINITE'], dtype=object)
    >>> b[0]
    Result(distance=2.0, num_pairs=1, equidistant=False, method=AUTO)
    """

    sqr_distance = property(lambda self: self._field("sqr_distance"), doc="squared distances")
    iterations = property(lambda self: self._field("iterations"), doc="iterations (ITERATION)")
    points = property(lambda self: self._field("pairs")["point"], doc="S + (2, 2, 3) points")
    params = property(lambda self: self._field("pairs")["param"], doc="S + (2, 2) parameters")
    _one = Result


class ContactPair(tuple):
    """One closest pair of a Contact: a tuple (points, core_points, normal, params).

    points[0] = core_points[0] + r0 normal and points[1] = core_points[1] - r1 normal.

    Parameters
    ----------
    points : ndarray, shape (2, 3)
        The witness points on the two surfaces.
    core_points : ndarray, shape (2, 3)
        The closest pair of the cores.
    normal : ndarray, shape (3,)
        The unit contact normal from the first object to the second.
    params : ndarray, shape (2,)
        The core points' parameters (NaN for a point core).

    Examples
    --------
    >>> import circledist as cd
    >>> c = cd.sphere_sphere(cd.Sphere((0, 0, 0), 1.0), cd.Sphere((3, 0, 0), 0.5))
    >>> c.pairs
    [ContactPair(points=[[1.0, 0.0, 0.0], [2.5, 0.0, 0.0]], normal=[1.0, 0.0, 0.0])]
    """
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

    Parameters
    ----------
    raw : numpy structured scalar or 0-d array of CONTACT_DTYPE
        One cdist_contact (the query functions build Contacts themselves).

    Attributes
    ----------
    distance : float
        The signed distance core_distance - (r0 + r1), negative when the solids overlap
        (-distance is then the penetration depth).
    core_distance : float
        The distance of the cores (point, segment, circle, disk; plain objects are their own
        core, radius 0).
    pairs : list of ContactPair
        1 or 2 closest pairs; also as arrays: points, core_points (num_pairs, 2, 3), normals
        (num_pairs, 3), params (num_pairs, 2).
    equidistant : bool
        Infinitely many closest pairs (from the core query).
    flags : int
        Bits of cdist_contact_flag; core_touch: the cores touch or cross, so the normal is
        chosen by the documented rule (CDIST_CONTACT_CORE_TOUCH, see docs/swept.md).
    method : Method
        The method that answered the core query.

    Examples
    --------
    >>> import circledist as cd
    >>> c = cd.sphere_sphere(cd.Sphere((0, 0, 0), 1.0), cd.Sphere((3, 0, 0), 0.5))
    >>> c.distance, c.core_distance, c.core_touch
    (1.5, 3.0, False)
    >>> c.normals
    array([[1., 0., 0.]])
    """

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
    cdist_grad_object).

    Fields that do not apply to the object are 0. Normal and direction derivatives lie in the
    tangent space of the unit sphere (dD = d_normal . dN for a dN keeping N unit).

    Parameters
    ----------
    values : array_like, shape (25,)
        The doubles of one cdist_grad_object up to its reserved area.

    Attributes
    ----------
    d_center, d_normal, d_origin, d_direction, d_p0, d_p1, d_zero_direction : ndarray, shape (3,)
        Derivatives with respect to the vector fields.
    d_radius : float
        A circle's, disk's or arc's radius (the core radius of a torus or rounded disk).
    d_radius_swept : float
        The sphere or capsule radius, torus tube radius or rounded-disk radius (-1).
    d_start, d_end : float
        An arc's angles.

    Examples
    --------
    >>> import circledist as cd
    >>> r, g = cd.point_circle_grad((3.0, 0.0, 0.0), cd.Circle((0, 0, 0), (0, 0, 1), 1.0))
    >>> g.obj[1]
    GradObject(d_center=[-1.0, -0.0, -0.0], d_radius=-1.0)
    """

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
    """The gradient of one query's distance (struct cdist_grad).

    Parameters
    ----------
    raw : numpy structured scalar or 0-d array of GRAD_DTYPE
        One cdist_grad (the _grad query functions build Grads themselves).

    Attributes
    ----------
    obj : tuple of two GradObject
        obj[0] for the first object, obj[1] for the second.
    flags : int
        Bits of cdist_grad_flag.
    differentiable : bool
        False when CDIST_GRAD_NOT_DIFFERENTIABLE is set: at a (core) distance above 0, two
        closest pairs, an equidistant result, an arc of radius 0 or a segment (capsule core)
        of length 0 (the gradient of pairs[0] is given); at (core)
        distance 0 (the gradient is 0 there, swept radii -1) unless the distance stays 0 nearby
        (a stable crossing of a disk). The rules are in circledist.h ("gradients").

    Examples
    --------
    >>> import circledist as cd
    >>> r, g = cd.point_circle_grad((3.0, 0.0, 0.0), cd.Circle((0, 0, 0), (0, 0, 1), 1.0))
    >>> g.differentiable, g.obj[0].d_center
    (True, array([1., 0., 0.]))
    """

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

class BatchContact(_Batch):
    """Answers to an array of contact (swept-object) queries, as numpy arrays of the broadcast
    batch shape S: views of one buffer of C contact structs (raw, numpy dtype CONTACT_DTYPE).
    With distance_only=True only distance and status exist.

    Parameters
    ----------
    raw : ndarray of CONTACT_DTYPE or None
        The contacts (None for distance_only).
    status : ndarray of int32
        The status of each entry.
    distance : ndarray of float64, optional
        The signed distances when raw is None.

    Attributes
    ----------
    distance, core_distance : ndarray, shape S
        Signed distances and core distances (NaN for a bad entry).
    status : ndarray of int32, shape S
        cdist_status of each entry, 0 = OK.
    num_pairs, equidistant, flags, core_touch, method : ndarray, shape S
        As in Contact.
    points, core_points : ndarray, shape S + (2, 2, 3)
        [..., i, j] is pair i's point on object j; only pairs i < num_pairs are meaningful.
    normals : ndarray, shape S + (2, 3)
        Contact normals.
    params : ndarray, shape S + (2, 2)
        Core parameters.

    Examples
    --------
    >>> import circledist as cd
    >>> balls = cd.Sphere([[3.0, 0.0, 0.0], [1.0, 0.0, 0.0]], 0.5)
    >>> b = cd.sphere_sphere(balls, cd.Sphere((0, 0, 0), 1.0))
    >>> b.distance, b.core_distance
    (array([ 1.5, -0.5]), array([3., 1.]))
    """

    core_distance = property(lambda self: self._field("core_distance"), doc="core distances")
    flags = property(lambda self: self._field("flags"), doc="bits of cdist_contact_flag")
    core_touch = property(lambda self: (self._field("flags") & _lib.CONTACT_CORE_TOUCH) != 0,
                          doc="the cores touch or cross")
    points = property(lambda self: self._field("pairs")["point"], doc="S + (2, 2, 3) witness points")
    core_points = property(lambda self: self._field("pairs")["core_point"],
                           doc="S + (2, 2, 3) closest points of the cores")
    normals = property(lambda self: self._field("pairs")["normal"], doc="S + (2, 3) contact normals")
    params = property(lambda self: self._field("pairs")["param"], doc="S + (2, 2) core parameters")
    _one = Contact


class BatchGradObject:
    """The derivatives with respect to one object of every entry: the fields of
    cdist_grad_object as arrays (d_center etc. S + (3,), d_radius etc. S), views of the
    BatchGrad's buffer.

    Parameters
    ----------
    raw : ndarray of the cdist_grad_object dtype
        One object's part of the gradient buffer.

    Examples
    --------
    >>> import circledist as cd
    >>> points = [[3.0, 0.0, 0.0], [0.0, 0.0, 3.0]]
    >>> res, grads = cd.point_circle_grad(points, cd.Circle((0, 0, 0), (0, 0, 1), 1.0))
    >>> grads.obj[0].d_radius_swept
    array([0., 0.])
    """

    __slots__ = ("_raw",)

    def __init__(self, raw):
        self._raw = raw

    def __getattr__(self, name):
        if name in _lib.GRAD_OBJECT_FIELDS:
            return self._raw[name]
        raise AttributeError(name)

    def __dir__(self):
        return list(_lib.GRAD_OBJECT_FIELDS)

    def __repr__(self):
        return "<BatchGradObject shape=%s>" % (self._raw.shape,)


class BatchGrad:
    """Gradients of an array of queries (struct cdist_grad per entry); a bad entry's gradient
    is NaN.

    Parameters
    ----------
    raw : ndarray of GRAD_DTYPE
        The buffer.
    status : ndarray of int32
        The status of each entry (shared with the BatchResult or BatchContact of the call).

    Attributes
    ----------
    obj : tuple of two BatchGradObject
        obj[k].d_center is S + (3,), obj[k].d_radius is S, ...
    flags, differentiable, status, ok : ndarray, shape S
        As in Grad, per entry.

    Examples
    --------
    >>> import circledist as cd
    >>> points = [[3.0, 0.0, 0.0], [0.0, 3.0, 0.0]]
    >>> res, grads = cd.point_circle_grad(points, cd.Circle((0, 0, 0), (0, 0, 1), 1.0))
    >>> grads.obj[0].d_center
    array([[1., 0., 0.],
           [0., 1., 0.]])
    >>> grads.differentiable
    array([ True,  True])
    """

    def __init__(self, raw, status):
        self.raw = raw
        self.status = status
        self.obj = (BatchGradObject(raw["obj"][..., 0]), BatchGradObject(raw["obj"][..., 1]))

    flags = property(lambda self: self.raw["flags"], doc="bits of cdist_grad_flag")
    differentiable = property(lambda self: (self.raw["flags"] & _lib.GRAD_NOT_DIFFERENTIABLE) == 0,
                              doc="False where CDIST_GRAD_NOT_DIFFERENTIABLE is set")
    ok = property(lambda self: self.status == 0, doc="entries answered without error")
    shape = property(lambda self: self.status.shape, doc="the batch shape")

    def __len__(self):
        return len(self.status)

    _one = Grad
    __getitem__ = _Batch.__getitem__
    __repr__ = _Batch.__repr__


# Status codes that concern the whole call (not one entry): raised as CircleDistError.
_CALL_ERRORS = {1, 11, 13, 15, 16, _lib.STATUS_OVERLAP}
#: Batches of at least this many entries report progress (Ctrl-C, progress=); the C library
#: reports after every _PROGRESS_EVERY entries, a few milliseconds of the fast kinds.
_PROGRESS_MIN = 8192
_PROGRESS_EVERY = 4096

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
#: name -> docstring maker of each generated query (module=False: the Query method).
_DOCS = {}


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


class _TextBar:
    """A minimal progress line on stderr, when tqdm is not installed."""

    def __init__(self, total):
        self.total, self.done, self.shown = total, 0, -1

    def update(self, k):
        self.done += k
        pct = 100 * self.done // max(self.total, 1)
        if pct != self.shown:
            self.shown = pct
            sys.stderr.write("\rcircledist: %3d%% of %d entries" % (pct, self.total))
            sys.stderr.flush()

    def close(self):
        sys.stderr.write("\n")


def _progress_bar(total):
    """A tqdm bar when tqdm is importable (never a dependency), else a line on stderr."""
    try:
        from tqdm import tqdm
    except ImportError:
        return _TextBar(total)
    return tqdm(total=total, unit="entries", unit_scale=True)


class Query:
    """A query handle: the library's options and workspaces (cdist_query).

    Use one per thread (calls on one handle from several threads are serialised by a lock).
    Every query kind is a method, e.g. q.circle_circle(a, b); the module-level functions of the
    same names use a per-thread default handle (default_query()). Use as a context manager or
    call close().

    Parameters
    ----------
    method : Method, str or int, optional
        The algorithm (default Method.AUTO).
    unit_tolerance : float, optional
        Relative tolerance on the length of unit normals and directions (library default 1e-6).
    curve_samples : int, optional
        Sampling intervals for callback curves, helices (per turn) and Beziers (default 512).
    max_iterations : int, optional
        Iteration limit of Method.ITERATION.
    threads : int, optional
        Worker threads of the vectorised calls (default 1).

    Raises
    ------
    CircleDistError
        An option the library rejects.

    Examples
    --------
    >>> import circledist as cd
    >>> with cd.Query(method="robust") as q:
    ...     r = q.circle_circle(cd.Circle((0, 0, 2), (0, 0, 1), 1.0), cd.Circle((1, 0, 0), (0, 1, 0), 1.0))
    ...     print(q.method, r.method)
    robust robust
    """

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
        """Set the algorithm of the handle.

        Parameters
        ----------
        method : Method, str or int
            A Method, its name such as "robust", or its number.
        """
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
        """Set the worker threads used by the vectorised calls.

        Creating threads has a cost, so the count is kept until changed; results are identical
        for every count.

        Parameters
        ----------
        threads : int
            1..256.
        """
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

    @contextlib.contextmanager
    def _call_options(self, method, threads=None):
        """The handle under the lock, with `method` for this call only and `threads` (kept)."""
        with self._lock:
            q = self._handle()
            old = self._override_method(q, method)
            try:
                if threads is not None:
                    self.set_threads(threads)
                yield q
            finally:
                if old is not None:
                    _lib.query_set_method(q, old)

    def _run(self, name, kind, a, b, method, threads, distance_only, single_call, out=None,
             progress=None):
        with self._call_options(method, threads) as q:
            if a.shape == () and b.shape == () and not distance_only and out is None:
                self._check(single_call(q, a, b, self._one_addr))
                return Result._from_buffer(self._one_buffer)
            return self._batch(name, kind, a, b, "distance" if distance_only else "result", out,
                               progress)

    def _new_outputs(self, mode, contact, shape):
        """Fresh output buffers of a batch: a BatchResult / BatchContact, with a BatchGrad for
        mode "grad"."""
        status = np.empty(shape, np.int32)
        if mode == "distance":
            return (BatchContact if contact else BatchResult)(None, status, np.empty(shape, np.float64))
        res = BatchContact(np.empty(shape, _lib.CONTACT_DTYPE), status) if contact else \
            BatchResult(np.empty(shape, _lib.RESULT_DTYPE), status)
        return (res, BatchGrad(np.empty(shape, _lib.GRAD_DTYPE), status)) if mode == "grad" else res

    @staticmethod
    def _check_out(name, mode, contact, shape, out):
        """out= of a batch: the type, shape and distance_only of what the call would return."""
        cls = BatchContact if contact else BatchResult
        res, grad = out if mode == "grad" and isinstance(out, tuple) and len(out) == 2 else (out, None)
        ok = isinstance(res, cls) and res.shape == shape and (res.raw is None) == (mode == "distance")
        if mode == "grad":
            ok = ok and isinstance(grad, BatchGrad) and grad.shape == shape and grad.status is res.status
        if not ok:
            raise ValueError("%s: out must be %s of shape %s from a call like this one%s"
                             % (name, "the (%s, BatchGrad) pair" % cls.__name__ if mode == "grad"
                                else "a " + cls.__name__, shape,
                                "" if mode == "grad" else " (distance_only=%s)" % (mode == "distance")))
        return out

    def _batch(self, name, kind, a, b, mode, out=None, progress=None):
        """One C call for the broadcast batch of a and b. mode: "result" (cdist_batch),
        "distance", "contact" (cdist_batch_contact) or "grad" (cdist_batch_grad)."""
        needed = {"result": _lib.batch, "distance": _lib.batch_distance,
                  "contact": _lib.batch_contact, "grad": _lib.batch_grad}[mode]
        if needed is None:
            raise RuntimeError("%s: the loaded libcircledist has no %s; arrays of objects need a "
                               "library with it" % (name, {"result": "batch API (cdist_batch)",
                                                          "distance": "cdist_batch_distance",
                                                          "contact": "cdist_batch_contact (1.1)",
                                                          "grad": "cdist_batch_grad (1.1)"}[mode]))
        try:
            shape = np.broadcast_shapes(a.shape, b.shape)
        except ValueError:
            raise ValueError("%s: the batch shapes of the arguments do not broadcast: %s and %s"
                             % (name, a.shape, b.shape)) from None
        n = math.prod(shape)
        pa, sa, keep_a = a.rows(shape, n) if isinstance(a, _CurveArg) else _rows(a.data, shape, n, a.WIDTH)
        pb, sb, keep_b = _rows(b.data, shape, n, b.WIDTH)
        contact = kind >= KIND_FIRST_CONTACT
        if out is not None:
            res = self._check_out(name, mode, contact, shape, out)
        else:
            res = self._new_outputs(mode, contact, shape)
        first = res[0] if mode == "grad" else res
        status = first.status.ctypes.data
        q = self._q
        if mode == "distance":
            args = (first.distance.ctypes.data, status)
        elif mode == "grad":
            args = (first.raw.ctypes.data, res[1].raw.ctypes.data, status)
        else:
            args = (first.raw.ctypes.data, status)
        st = self._call(n, lambda: needed(q, kind, n, pa, sa, pb, sb, *args), progress) if n else 0
        del keep_a, keep_b
        if st in _CALL_ERRORS:
            self._check(st)
        return res

    def _call(self, n, c_call, progress):
        """Run one batch call: with progress reports (progress=, a tqdm bar) and Ctrl-C when the
        batch is long enough. While the C call runs (GIL released) a SIGINT only sets a flag
        here (a temporary handler in the main thread); the library's progress callback, run in
        this thread between chunks of entries, returns non-zero when it is set, so the batch
        stops within a chunk and KeyboardInterrupt is raised after the call (the entries
        answered are in the outputs, e.g. an out= buffer; the others have CDIST_ERR_CANCELLED)."""
        sigint = SigintRecorder()
        if _lib.query_set_progress is None or not (progress or (sigint.catching and n >= _PROGRESS_MIN)):
            return c_call()
        bar = _progress_bar(n) if progress is True else None
        user_fn = progress if callable(progress) else None
        seen, errors = [0], []

        def report(_user, done, total):
            try:
                if bar is not None:
                    bar.update(done - seen[0])
                    seen[0] = done
                stop = bool(user_fn(done, total)) if user_fn is not None else False
            except BaseException as e:  # noqa: B036 - re-raised after the C call returns
                errors.append(e)
                return 1
            return 1 if stop or sigint.hits else 0

        c_report = _lib.PROGRESS_FN(report)
        self._check(_lib.query_set_progress(self._q, c_report, None, _PROGRESS_EVERY))
        try:
            with sigint:
                st = c_call()
        finally:
            _lib.query_set_progress(self._q, _lib.PROGRESS_FN(), None, 0)
            if bar is not None:
                bar.close()
        if errors:
            raise errors[0]
        sigint.deliver()
        return st

    # ---- swept objects and gradients -------------------------------------------------------
    def _swept(self, name, kind, c_fn, a, b, method, threads, mode, out, progress):
        """A contact or gradient query: one object each through the single C query (fast path),
        arrays of objects through one batch call."""
        contact, grad = kind >= KIND_FIRST_CONTACT, mode == "grad"
        if a.shape or b.shape or out is not None or mode == "distance":
            with self._call_options(method, threads):
                return self._batch(name, kind, a, b, mode, out, progress)
        if c_fn is None:
            raise RuntimeError("%s: the loaded libcircledist has no cdist_%s" % (name, name))
        with self._call_options(method) as q:
            out_addr = self._contact_addr if contact else self._one_addr
            if grad:
                st = c_fn(q, a.address, b.address, out_addr, self._grad_addr)
            else:
                st = c_fn(q, a.address, b.address, out_addr)
            if st:
                self._check(st)
            res = Contact._from_buffer(self._contact_buffer) if contact else \
                Result._from_buffer(self._one_buffer)
            return (res, Grad._from_buffer(self._grad_buffer)) if grad else res

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

    def query(self, a, b, *, method=None, threads=None, distance_only=False, out=None,
              progress=None):
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
        return self._run(name, kind, a, b, method, threads, distance_only, single, out, progress)

    query.__name__ = name
    _DOCS[name] = functools.partial(_docs.query_doc, name, cls_a.__name__, cls_b.__name__, "result")
    query.__doc__ = _DOCS[name](module=False)
    return query


for _name, _kind, _ca, _cb in _KINDS:
    setattr(Query, _name, _make_method(_name, _kind, _ca, _cb))


# Contact (swept) kinds: name, first and second object class; kind numbers 21.. in this order.
KIND_FIRST_CONTACT = 21
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
if _lib.batch_contact is not None:  # the contact kinds must be the library's
    for _i, (_name, _ca, _cb) in enumerate(_SWEPT_KINDS):
        _kind = KIND_FIRST_CONTACT + _i
        if (_lib.kind_name(_kind) or b"").decode() != _name or \
                (_lib.kind_size_a(_kind), _lib.kind_size_b(_kind)) != (8 * _ca.WIDTH, 8 * _cb.WIDTH):
            raise ImportError("circledist: the library's batch kind %d is not %s(%s, %s)"
                              % (_kind, _name, _ca.__name__, _cb.__name__))


def _make_swept_method(name, kind, cls_a, cls_b, grad):
    contact = kind >= KIND_FIRST_CONTACT
    c_name = name + "_grad" if grad else name
    c_fn = _lib.grad_query(name) if grad else _lib.contact_query(name)

    def coerce_both(a, b):
        if type(a) is not cls_a:
            a = coerce(a, cls_a, "%s: argument a (the %s)" % (c_name, cls_a.__name__))
        if type(b) is not cls_b:
            b = coerce(b, cls_b, "%s: argument b (the %s)" % (c_name, cls_b.__name__))
        return a, b

    if grad:
        def query(self, a, b, *, method=None, threads=None, out=None, progress=None):
            a, b = coerce_both(a, b)
            return self._swept(c_name, kind, c_fn, a, b, method, threads, "grad", out, progress)
    else:
        def query(self, a, b, *, method=None, threads=None, distance_only=False, out=None,
                  progress=None):
            a, b = coerce_both(a, b)
            return self._swept(c_name, kind, c_fn, a, b, method, threads,
                               "distance" if distance_only else "contact", out, progress)

    query.__name__ = c_name
    _DOCS[c_name] = functools.partial(_docs.query_doc, c_name, cls_a.__name__, cls_b.__name__,
                                      ("contact" if contact else "result") + ("_grad" if grad else ""))
    query.__doc__ = _DOCS[c_name](module=False)
    return query


SINGLE_NAMES = []
for _i, (_name, _ca, _cb) in enumerate(_SWEPT_KINDS):
    for _grad in (False, True):
        setattr(Query, _name + "_grad" * _grad,
                _make_swept_method(_name, KIND_FIRST_CONTACT + _i, _ca, _cb, _grad))
        SINGLE_NAMES.append(_name + "_grad" * _grad)
for _name, _kind, _ca, _cb in _KINDS:
    if _name in _GRAD_CORE:
        setattr(Query, _name + "_grad", _make_swept_method(_name, _kind, _ca, _cb, True))
        SINGLE_NAMES.append(_name + "_grad")


def _curve_method(name, kind):
    def query(self, f, t0, t1, other, *, method=None, threads=None, distance_only=False, out=None):
        other = coerce(other, Circle if kind == KIND_CURVE_CIRCLE else Disk, "%s: argument other" % name)
        return self._curve(name, kind, f, t0, t1, other, method, threads, distance_only, out)
    query.__name__ = name
    _DOCS[name] = functools.partial(_docs.curve_doc, name,
                                    "Circle" if kind == KIND_CURVE_CIRCLE else "Disk")
    query.__doc__ = _DOCS[name](module=False)
    return query


Query.curve_circle = _curve_method("curve_circle", KIND_CURVE_CIRCLE)
Query.curve_disk = _curve_method("curve_disk", KIND_CURVE_DISK)


def circle_basis(circle):
    """The basis in which circle angles are measured (cdist_circle_basis).

    With N the normalised normal and k the index of N's smallest-magnitude component,
    U = e_k - N_k N normalised and V = N x U.

    Parameters
    ----------
    circle : Circle or Disk
        One circle (or a (center, normal, radius) tuple).

    Returns
    -------
    (U, V) : tuple of two ndarray, shape (3,)

    Raises
    ------
    CircleDistError
        A circle the library rejects (e.g. a zero normal).
    ValueError
        An array of circles.

    Examples
    --------
    >>> import circledist as cd
    >>> cd.circle_basis(cd.Circle((0, 0, 0), (0, 0, 1), 1.0))
    (array([1., 0., 0.]), array([0., 1., 0.]))
    """
    c = coerce(circle, Circle, "circle_basis: circle")
    if c.shape:
        raise ValueError("circle_basis: circle must be one Circle, got an array of shape %s" % (c.shape,))
    u, v = np.empty(3), np.empty(3)
    st = _lib.circle_basis(c.data.ctypes.data, u.ctypes.data, v.ctypes.data)
    if st:
        raise CircleDistError(st, status_string(st))
    return u, v


def circle_point(circle, angle):
    """The point of one circle at an angle: C + r (cos a U + sin a V) (cdist_circle_point).

    Parameters
    ----------
    circle : Circle or Disk
        One circle (or a (center, normal, radius) tuple).
    angle : float or array_like
        Radians, in the basis of circle_basis().

    Returns
    -------
    ndarray, shape angle.shape + (3,)

    Raises
    ------
    CircleDistError
        A circle the library rejects.
    ValueError
        An array of circles.

    Examples
    --------
    >>> import circledist as cd
    >>> cd.circle_point(cd.Circle((0, 0, 1), (0, 0, 1), 2.0), [0.0, 0.0])
    array([[2., 0., 1.],
           [2., 0., 1.]])
    """
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
    """This thread's default Query handle, used by the module-level query functions.

    Returns
    -------
    Query
        Created on first use in each thread.

    Examples
    --------
    >>> import circledist as cd
    >>> cd.default_query() is cd.default_query()
    True
    """
    q = getattr(_default, "query", None)
    if q is None:
        q = _default.query = Query()
    return q


def _module_function(name):
    """The module-level form of Query.<name>: this thread's default Query unless query= is
    given; threads defaults to 1 here."""
    unbound = getattr(Query, name)
    sig = inspect.signature(unbound)
    params = [p for p in sig.parameters.values() if p.name != "self"]
    params = [p.replace(default=1) if p.name == "threads" else p for p in params]

    def query(*args, query=None, **kwargs):
        h = query if query is not None else default_query()
        kwargs.setdefault("threads", 1)
        return getattr(h, name)(*args, **kwargs)
    query.__signature__ = sig.replace(parameters=params + [
        inspect.Parameter("query", inspect.Parameter.KEYWORD_ONLY, default=None)])
    query.__name__ = name
    query.__doc__ = _DOCS[name](module=True)
    return query


QUERY_NAMES = [k[0] for k in _KINDS] + ["curve_circle", "curve_disk"]
FUNCTIONS = {name: _module_function(name) for name in QUERY_NAMES}
FUNCTIONS.update({name: _module_function(name) for name in SINGLE_NAMES})
