# SPDX-License-Identifier: MIT
"""Geometric objects as numpy arrays laid out exactly like the C structs (internal module).

Every object holds one float64 array ``data`` of shape ``batch_shape + (WIDTH,)`` whose last axis
is the C struct's fields in order (all C object structs are plain doubles). A single object has
``batch_shape == ()``; an array of objects comes from array-valued fields, which broadcast
against each other with numpy's rules. ``from_array`` wraps an existing array without copying.
"""
import inspect
import types

import numpy as np


class One:
    """Shape marker for type annotations: a single object (batch shape ``()``).

    ``Circle[One]`` is a Circle built from plain numbers and tuples; queries on such objects
    return a ``Result`` (``Contact``, ``(Result, Grad)``, ...). The marker exists at runtime so
    annotations evaluate; it has no instances.

    Examples
    --------
    >>> import circledist as cd
    >>> ring: cd.Circle[cd.One] = cd.Circle((0, 0, 0), (0, 0, 1), 1.0)
    >>> ring.shape
    ()
    """


class Many:
    """Shape marker for type annotations: an array of objects (any batch shape).

    ``Circle[Many]`` is a Circle built from numpy arrays (or ``from_array``); queries involving
    one return a ``BatchResult`` (``BatchContact``, ``(BatchResult, BatchGrad)``, ...).

    Examples
    --------
    >>> import numpy as np
    >>> import circledist as cd
    >>> rings: cd.Circle[cd.Many] = cd.Circle(np.zeros((4, 3)), (0, 0, 1), 1.0)
    >>> rings.shape
    (4,)
    """


def as_float_array(value, what, width=None):
    """value as a float64 array; width: required size of the last axis (None: any shape).

    Raises TypeError for non-numeric input and ValueError for a wrong shape, naming `what`."""
    if value is None or isinstance(value, (str, bytes)):
        raise TypeError("%s: expected numbers, got %s" % (what, type(value).__name__))
    try:
        a = np.asarray(value)
    except Exception as e:  # ragged nested sequences and the like
        raise ValueError("%s: cannot be read as a numeric array (%s)" % (what, e)) from None
    if a.dtype.kind not in "iuf":
        raise TypeError("%s: expected real numbers, got an array of %s" % (what, a.dtype))
    a = a.astype(np.float64, copy=False)
    if width is not None and (a.ndim == 0 or a.shape[-1] != width):
        raise ValueError("%s: expected shape (%d,) or (..., %d), got %s" % (what, width, width, a.shape))
    return a


class GeometricObject:
    """Base class: one object or an array of objects of one type, stored as ``data``.

    ``data`` has shape ``shape + (WIDTH,)``, the C struct's doubles in field order; ``shape``
    is () for one object. Indexing an array of objects gives a view.

    Parameters
    ----------
    *values
        The fields of the subclass, in order (see each class).

    Examples
    --------
    >>> import circledist as cd
    >>> isinstance(cd.Circle((0, 0, 0), (0, 0, 1), 1.0), cd.GeometricObject)
    True
    >>> cd.Circle.WIDTH, [f[0] for f in cd.Circle.FIELDS]
    (7, ['center', 'normal', 'radius'])
    """

    __slots__ = ("data", "_addr")
    #: (name, width, object class or None); width None is a scalar field.
    FIELDS = ()
    WIDTH = 0

    def __class_getitem__(cls, shape):
        """``Circle[One]`` / ``Circle[Many]`` in annotations (a typing alias; see One, Many)."""
        return types.GenericAlias(cls, shape)

    def __init__(self, *values):
        name = type(self).__name__
        if len(values) != len(self.FIELDS):
            raise TypeError("%s() takes %d arguments (%s), got %d" % (
                name, len(self.FIELDS), ", ".join(f[0] for f in self.FIELDS), len(values)))
        flat = _flat_single(self.FIELDS, values)
        if flat is not None:  # one object from plain numbers: the fast path
            self.data = np.array(flat, dtype=np.float64)
            return
        arrays = []
        for (field, width, cls), v in zip(self.FIELDS, values):
            what = "%s.%s" % (name, field)
            if cls is not None:
                a = coerce(v, cls, what).data
            else:
                a = as_float_array(v, what, width)
                if width is None:
                    a = a[..., None]
            arrays.append(a)
        try:
            shape = np.broadcast_shapes(*(a.shape[:-1] for a in arrays))
        except ValueError:
            raise ValueError("%s: the shapes of its fields do not broadcast: %s" % (name, ", ".join(
                "%s %s" % (f[0], a.shape[:-1]) for f, a in zip(self.FIELDS, arrays)))) from None
        data = np.empty(shape + (self.WIDTH,))
        col = 0
        for a in arrays:
            data[..., col:col + a.shape[-1]] = a
            col += a.shape[-1]
        self.data = data

    @property
    def address(self):
        """Address of ``data`` (for the C calls; cached, ``data`` is never replaced)."""
        try:
            return self._addr
        except AttributeError:
            self._addr = self.data.ctypes.data
            return self._addr

    @classmethod
    def from_array(cls, array):
        """Wrap an array of shape (..., WIDTH) in the C struct's field order.

        No copy when it is float64 with contiguous rows (any row stride, e.g. a column slice of
        a wider table, works).

        Parameters
        ----------
        array : array_like, shape (..., WIDTH)
            The fields of each object in order.

        Returns
        -------
        GeometricObject
            An object of this class with ``data`` a view of the array where possible.

        Raises
        ------
        ValueError, TypeError
            A last axis other than WIDTH, or non-numeric input.

        Examples
        --------
        >>> import numpy as np
        >>> import circledist as cd
        >>> table = np.array([[0, 0, 0, 0, 0, 1, 1.0], [0, 0, 5, 0, 0, 1, 2.0]])
        >>> rings = cd.Circle.from_array(table)
        >>> rings.radius
        array([1., 2.])
        >>> np.shares_memory(rings.data, table)
        True
        """
        a = as_float_array(array, cls.__name__ + ".from_array", cls.WIDTH)
        if a.strides[-1] != a.itemsize:
            a = np.ascontiguousarray(a)
        obj = cls.__new__(cls)
        obj.data = a
        return obj

    @property
    def shape(self):
        """The batch shape: () for one object, (N,) for N objects."""
        return self.data.shape[:-1]

    def __len__(self):
        if not self.shape:
            raise TypeError("a single %s has no len()" % type(self).__name__)
        return self.shape[0]

    def __getitem__(self, index):
        if not self.shape:
            raise TypeError("a single %s cannot be indexed" % type(self).__name__)
        return type(self).from_array(self.data[index])

    def __repr__(self):
        if self.shape:
            return "<%s array of shape %s>" % (type(self).__name__, self.shape)
        return "%s(%s)" % (type(self).__name__, ", ".join(
            "%s=%r" % (f[0], _plain(getattr(self, f[0]))) for f in self.FIELDS))


_NUMBER = (int, float)


def _flat_single(fields, values):
    """The doubles of one object given as Python numbers and short tuples/lists, else None
    (numpy input, batches and errors take the general path)."""
    flat = []
    for (_, width, cls), v in zip(fields, values):
        if cls is not None:
            if isinstance(v, cls) and v.data.ndim == 1:
                flat.extend(v.data.tolist())
                continue
            if not isinstance(v, (tuple, list)):
                return None
            sub = _flat_single(cls.FIELDS, v) if len(v) == len(cls.FIELDS) else None
            if sub is None:
                return None
            flat.extend(sub)
        elif width is None:
            if type(v) not in _NUMBER:
                return None
            flat.append(v)
        else:
            if type(v) not in (tuple, list) or len(v) != width:
                return None
            for x in v:
                if type(x) not in _NUMBER:
                    return None
            flat.extend(v)
    return flat


def _plain(v):
    return v.tolist() if isinstance(v, np.ndarray) else v


def _field_property(start, width, cls, doc):
    if cls is not None:
        def get(self):
            return cls.from_array(self.data[..., start:start + width])
    elif width is None:
        def get(self):
            v = self.data[..., start]
            return float(v) if v.ndim == 0 else v
    else:
        def get(self):
            return self.data[..., start:start + width]
    return property(get, doc=doc)


def _parameters_doc(cls):
    """The numpydoc Parameters section of a class's constructor, from its field specs."""
    lines = ["Parameters", "----------"]
    for field, width, sub, doc in cls._SPEC:
        if sub is not None:
            kind = "%s, tuple of its fields, or array of %s" % (sub.__name__, sub.__name__)
        elif width is None:
            kind = "float or array_like, shape (...)"
        else:
            kind = "array_like, shape (%d,) or (..., %d)" % (width, width)
        lines += ["%s : %s" % (field, kind), "    " + doc + "."]
    lines += ["", "The fields broadcast against each other: arrays give an array of objects of the",
              "broadcast batch shape (shape), Python numbers and tuples one object (shape ())."]
    return "\n".join("    " + line if line else "" for line in lines)


def _define(cls):
    if "Parameters" not in cls.__doc__:
        head, sep, examples = cls.__doc__.partition("    Examples\n")
        cls.__doc__ = head.rstrip() + "\n\n" + _parameters_doc(cls) + "\n\n" + sep + examples
    col = 0
    for field, width, sub, doc in cls._SPEC:
        w = sub.WIDTH if sub is not None else (width or 1)
        setattr(cls, field, _field_property(col, width if sub is None else w, sub, doc))
        col += w
    cls.FIELDS = tuple((f, w if s is None else s.WIDTH, s) for f, w, s, _ in cls._SPEC)
    cls.WIDTH = col
    # help() and inspect show the fields instead of the generic ``*values``.
    cls.__signature__ = inspect.Signature([
        inspect.Parameter(f, inspect.Parameter.POSITIONAL_ONLY) for f, _, _ in cls.FIELDS])
    return cls


@_define
class Point(GeometricObject):
    """A point (x, y, z); Point(positions) with positions of shape (3,) or (N, 3).

    Query functions take points as any (..., 3) sequence or array; this class is optional.

    Examples
    --------
    >>> import circledist as cd
    >>> cd.Point((1.0, 0.0, 2.0))
    Point(position=[1.0, 0.0, 2.0])
    >>> cd.Point([[0, 0, 0], [1, 2, 3]]).shape
    (2,)
    """
    __slots__ = ()
    _SPEC = (("position", 3, None, "the coordinates, shape (..., 3)"),)


@_define
class Circle(GeometricObject):
    """A circle: Circle(center, normal, radius).

    center (..., 3), normal (..., 3) unit length (within the handle's unit tolerance),
    radius (...) >= 0; the fields broadcast, so Circle(centers, (0, 0, 1), radii) is N circles
    in parallel planes. C struct: cdist_circle (7 doubles).

    Examples
    --------
    >>> import numpy as np
    >>> import circledist as cd
    >>> cd.Circle((0, 0, 2), (0, 0, 1), 1.0)
    Circle(center=[0.0, 0.0, 2.0], normal=[0.0, 0.0, 1.0], radius=1.0)
    >>> rings = cd.Circle(np.zeros((4, 3)), (0, 0, 1), [1.0, 2.0, 3.0, 4.0])
    >>> rings
    <Circle array of shape (4,)>
    >>> rings.radius
    array([1., 2., 3., 4.])
    >>> rings[2]
    Circle(center=[0.0, 0.0, 0.0], normal=[0.0, 0.0, 1.0], radius=3.0)
    """
    __slots__ = ()
    _SPEC = (("center", 3, None, "centre, shape (..., 3)"),
             ("normal", 3, None, "unit normal of the plane, shape (..., 3)"),
             ("radius", None, None, "radius (float or array)"))


@_define
class Disk(GeometricObject):
    """A disk (a circle plus its interior): Disk(center, normal, radius), like Circle.

    Circle and Disk hold the same data; the query function (``*_disk`` or ``*_circle``) decides
    whether the interior counts, so either class is accepted by both.

    Examples
    --------
    >>> import circledist as cd
    >>> cd.Disk((0, 0, 2), (0, 0, 1), 1.0)
    Disk(center=[0.0, 0.0, 2.0], normal=[0.0, 0.0, 1.0], radius=1.0)
    """
    __slots__ = ()
    _SPEC = Circle._SPEC


@_define
class Line(GeometricObject):
    """An infinite line origin + t * direction: Line(origin, direction), direction unit length.
    Line parameters in results refer to the direction as passed. C struct: cdist_line.

    Examples
    --------
    >>> import circledist as cd
    >>> cd.Line((1, 0, 2), (1, 0, 0))
    Line(origin=[1.0, 0.0, 2.0], direction=[1.0, 0.0, 0.0])
    """
    __slots__ = ()
    _SPEC = (("origin", 3, None, "a point of the line, shape (..., 3)"),
             ("direction", 3, None, "unit direction, shape (..., 3)"))


@_define
class Ray(GeometricObject):
    """A ray origin + t * direction, t >= 0: Ray(origin, direction). C struct: cdist_ray.

    Examples
    --------
    >>> import circledist as cd
    >>> cd.Ray((1, 0, 2), (1, 0, 0))
    Ray(origin=[1.0, 0.0, 2.0], direction=[1.0, 0.0, 0.0])
    """
    __slots__ = ()
    _SPEC = Line._SPEC


@_define
class Segment(GeometricObject):
    """A segment from p0 (s = 0) to p1 (s = 1): Segment(p0, p1). C struct: cdist_segment.

    Examples
    --------
    >>> import circledist as cd
    >>> cd.Segment((0, 0, 2), (2, 0, 2))
    Segment(p0=[0.0, 0.0, 2.0], p1=[2.0, 0.0, 2.0])
    """
    __slots__ = ()
    _SPEC = (("p0", 3, None, "start point, shape (..., 3)"),
             ("p1", 3, None, "end point, shape (..., 3)"))


@_define
class Arc(GeometricObject):
    """An arc of a circle: Arc(circle, zero_direction, start, end).

    Angles (radians) are measured from zero_direction (projected into the circle's plane; it
    must not be parallel to the normal) towards normal x zero_direction, from start to end.
    circle is a Circle (or a (center, normal, radius) tuple). C struct: cdist_arc.

    Examples
    --------
    >>> import circledist as cd
    >>> cd.Arc(((0, 0, 2), (0, 0, 1), 1.0), (1, 0, 0), -1.0, 1.0)  # doctest: +NORMALIZE_WHITESPACE
    Arc(circle=Circle(center=[0.0, 0.0, 2.0], normal=[0.0, 0.0, 1.0], radius=1.0),
        zero_direction=[1.0, 0.0, 0.0], start=-1.0, end=1.0)
    """
    __slots__ = ()
    _SPEC = (("circle", None, Circle, "the supporting Circle"),
             ("zero_direction", 3, None, "direction of angle 0, shape (..., 3)"),
             ("start", None, None, "first angle, radians"),
             ("end", None, None, "last angle, radians"))


@_define
class Helix(GeometricObject):
    """A circular helix: Helix(center, axis, zero_direction, radius, pitch, t0, t1).

    The point at angle t is center + radius (cos t U + sin t V) + pitch t / (2 pi) axis, with U
    zero_direction made perpendicular to the unit axis and V = axis x U; t runs over [t0, t1].
    C struct: cdist_helix.

    Examples
    --------
    >>> import circledist as cd
    >>> cd.Helix((0, 0, 0), (0, 0, 1), (1, 0, 0), 1.0, 0.5, 0.0, 6.0).pitch
    0.5
    """
    __slots__ = ()
    _SPEC = (("center", 3, None, "point on the axis at t = 0, shape (..., 3)"),
             ("axis", 3, None, "unit axis direction, shape (..., 3)"),
             ("zero_direction", 3, None, "direction of angle 0, not parallel to the axis"),
             ("radius", None, None, "radius >= 0"),
             ("pitch", None, None, "axial advance per turn (may be 0 or negative)"),
             ("t0", None, None, "first angle, radians"),
             ("t1", None, None, "last angle, radians, >= t0"))


@_define
class Bezier3(GeometricObject):
    """A cubic Bezier curve: Bezier3(p0, p1, p2, p3), parameter t in [0, 1].
    C struct: cdist_bezier3.

    Examples
    --------
    >>> import circledist as cd
    >>> cd.Bezier3((0, 0, 2), (0.5, 0, 2), (1.5, 0, 2), (2, 0, 2)).p3
    array([2., 0., 2.])
    """
    __slots__ = ()
    _SPEC = (("p0", 3, None, "control point 0 (t = 0)"),
             ("p1", 3, None, "control point 1"),
             ("p2", 3, None, "control point 2"),
             ("p3", 3, None, "control point 3 (t = 1)"))


@_define
class Sphere(GeometricObject):
    """A sphere (a point swept by a ball): Sphere(center, radius), radius >= 0 (0: a point).
    C struct: cdist_sphere (4 doubles).

    Examples
    --------
    >>> import circledist as cd
    >>> cd.Sphere((1, 0, 2), 0.25)
    Sphere(center=[1.0, 0.0, 2.0], radius=0.25)
    """
    __slots__ = ()
    _SPEC = (("center", 3, None, "centre, shape (..., 3)"),
             ("radius", None, None, "radius >= 0"))


@_define
class Capsule(GeometricObject):
    """A capsule (a segment swept by a ball): Capsule(segment, radius).

    segment is a Segment (or a (p0, p1) tuple; p0 == p1 is a sphere), radius >= 0.
    C struct: cdist_capsule (7 doubles).

    Examples
    --------
    >>> import circledist as cd
    >>> cd.Capsule(((0, 0, 2), (2, 0, 2)), 0.25)
    Capsule(segment=Segment(p0=[0.0, 0.0, 2.0], p1=[2.0, 0.0, 2.0]), radius=0.25)
    """
    __slots__ = ()
    _SPEC = (("segment", None, Segment, "the core Segment"),
             ("radius", None, None, "radius of the ball, >= 0"))


@_define
class Torus(GeometricObject):
    """A solid torus (a circle swept by a ball): Torus(circle, tube_radius).

    circle is the centre line of the tube, a Circle (or a (center, normal, radius) tuple);
    tube_radius >= 0 (larger than circle.radius: a spindle torus). C struct: cdist_torus
    (8 doubles).

    Examples
    --------
    >>> import circledist as cd
    >>> t = cd.Torus(((0, 0, 2), (0, 0, 1), 1.0), 0.25)
    >>> t.circle
    Circle(center=[0.0, 0.0, 2.0], normal=[0.0, 0.0, 1.0], radius=1.0)
    >>> t.tube_radius
    0.25
    """
    __slots__ = ()
    _SPEC = (("circle", None, Circle, "the core Circle"),
             ("tube_radius", None, None, "tube radius, >= 0"))


@_define
class RoundedDisk(GeometricObject):
    """A rounded disk (a disk swept by a ball, a coin with rounded rim):
    RoundedDisk(disk, radius), disk a Disk (or a (center, normal, radius) tuple), radius >= 0.
    C struct: cdist_rounded_disk (8 doubles).

    Examples
    --------
    >>> import circledist as cd
    >>> cd.RoundedDisk(((0, 0, 2), (0, 0, 1), 1.0), 0.25)
    RoundedDisk(disk=Disk(center=[0.0, 0.0, 2.0], normal=[0.0, 0.0, 1.0], radius=1.0), radius=0.25)
    """
    __slots__ = ()
    _SPEC = (("disk", None, Disk, "the core Disk"),
             ("radius", None, None, "radius of the ball, >= 0"))


# Classes with the same C struct are interchangeable (the query decides the meaning).
_SAME_LAYOUT = {Circle: (Circle, Disk), Disk: (Circle, Disk), Line: (Line, Ray), Ray: (Line, Ray)}


def coerce(value, cls, what):
    """value as a `cls` object: an instance (or one of the same C layout), a tuple of its
    fields, or for Point any (..., 3) array. Errors name `what`."""
    accepted = _SAME_LAYOUT.get(cls, (cls,))
    if isinstance(value, accepted):
        return value if type(value) is cls else cls.from_array(value.data)
    if isinstance(value, GeometricObject):
        raise TypeError("%s: expected %s, got %s" % (what, " or ".join(c.__name__ for c in accepted),
                                                     type(value).__name__))
    if cls is Point:
        flat = _flat_single(Point.FIELDS, (value,))
        if flat is not None:
            p = Point.__new__(Point)
            p.data = np.array(flat, dtype=np.float64)
            return p
        return Point.from_array(as_float_array(value, what, 3))
    if isinstance(value, (tuple, list)):
        try:
            return cls(*value)
        except (TypeError, ValueError) as e:
            raise type(e)("%s: %s" % (what, e)) from None
    raise TypeError("%s: expected %s (or a tuple of its fields), got %s" % (
        what, cls.__name__, type(value).__name__))
