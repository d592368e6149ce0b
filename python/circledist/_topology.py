# SPDX-License-Identifier: MIT
"""Linking numbers of circles and tori (internal module; see circledist.linking).

One C call per vectorised query (cdist_link_circles_batch / cdist_link_tori_batch), with byte
strides and stride 0 for a broadcast object."""
import ctypes
import math

import numpy as np

from . import _lib
from ._objects import Circle, Torus
from ._query import CircleDistError, _rows, default_query

_c = ctypes
_P = _c.c_void_p

#: numpy mirror of struct cdist_link (checked against cdist_link_size()).
LINK_DTYPE = np.dtype([("linking", np.int32), ("core_linking", np.int32),
                       ("distance", np.float64), ("core_distance", np.float64),
                       ("scale", np.float64), ("flags", np.int32), ("reserved_int", np.int32),
                       ("reserved", np.float64, (4,))], align=True)

#: Values of the linking field besides -1, 0, +1 (cdist_link_value).
LINK_TOUCHING, LINK_OVERLAP, LINK_ERROR = 2, 3, 4
#: Flags (cdist_link_flag).
LINK_FLAG_EXTENDED, LINK_FLAG_UNRESOLVED = 1, 2

_link_size = _lib._decl("cdist_link_size", _c.c_size_t, required=False)
_BATCH = {
    Circle: _lib._decl("cdist_link_circles_batch", _c.c_int, _P, _c.c_size_t, _P, _c.c_ssize_t,
                       _P, _c.c_ssize_t, _P, _P, required=False),
    Torus: _lib._decl("cdist_link_tori_batch", _c.c_int, _P, _c.c_size_t, _P, _c.c_ssize_t,
                      _P, _c.c_ssize_t, _P, _P, required=False),
}
if _link_size is not None and _link_size() != LINK_DTYPE.itemsize:
    raise ImportError("circledist: the library's cdist_link is %d bytes, this package expects %d"
                      % (_link_size(), LINK_DTYPE.itemsize))


def link_details(a, b, *, query=None):
    """The full cdist_link records of a against b, broadcast, from one C call.

    Parameters
    ----------
    a, b : Circle or Torus
        Both Circle or both Torus, single objects or arrays.
    query : Query, optional
        The handle (default: default_query()).

    Returns
    -------
    records : ndarray of LINK_DTYPE
        linking, core_linking, distance, core_distance, scale, flags; broadcast batch shape.
    status : ndarray of int32
        Entries with a bad object get their status (see status_name) and linking ==
        LINK_ERROR; the others are answered.

    Raises
    ------
    TypeError
        Not two Circles or two Tori.

    Examples
    --------
    >>> import circledist as cd
    >>> rec, status = cd.link_details(cd.Circle((0, 0, 0), (0, 0, 1), 1.0),
    ...                               cd.Circle((1, 0, 0), (0, 1, 0), 1.0))
    >>> int(rec["linking"]), float(rec["distance"]), int(status)
    (1, 1.0, 0)
    """
    if type(a) is not type(b) or type(a) not in _BATCH:
        raise TypeError("linking: expected two Circle or two Torus objects, got %s and %s"
                        % (type(a).__name__, type(b).__name__))
    fn = _BATCH[type(a)]
    if fn is None:
        raise RuntimeError("linking: the loaded libcircledist has no cdist_link_*_batch")
    try:
        shape = np.broadcast_shapes(a.shape, b.shape)
    except ValueError:
        raise ValueError("linking: the batch shapes of the arguments do not broadcast: %s and %s"
                         % (a.shape, b.shape)) from None
    n = math.prod(shape)
    h = query if query is not None else default_query()
    out = np.zeros(shape, LINK_DTYPE)
    status = np.zeros(shape, np.int32)
    if n:
        pa, sa, keep_a = _rows(a.data, shape, n, a.WIDTH)
        pb, sb, keep_b = _rows(b.data, shape, n, b.WIDTH)
        with h._lock:
            q = h._handle()
            st = fn(q, n, pa, sa, pb, sb, out.ctypes.data, status.ctypes.data)
            if st in (1, 13):  # a NULL argument or a busy handle: nothing was answered
                raise CircleDistError(st, _lib.query_last_error(q).decode())
        del keep_a, keep_b
    return out, status


def linking(a, b, *, query=None):
    """Linking number of circles (or solid tori) a and b.

    Sign: +1 when b passes through a's disk along a's normal, each circle oriented
    counterclockwise about its own normal (docs/linking.md).

    Parameters
    ----------
    a, b : Circle or Torus
        Both Circle or both Torus; arrays broadcast and are answered by one C call.
    query : Query, optional
        The handle (default: default_query()).

    Returns
    -------
    int or ndarray of int32
        -1, 0 or +1; LINK_TOUCHING (2) when they meet (distance <= 2^-40 of the scale); for
        tori LINK_OVERLAP (3) when the solids overlap; for arrays LINK_ERROR (4) for a bad
        entry.

    Raises
    ------
    CircleDistError
        A bad object (single objects only).
    TypeError
        Not two Circles or two Tori.

    Examples
    --------
    >>> import circledist as cd
    >>> a = cd.Circle((0, 0, 0), (0, 0, 1), 1.0)
    >>> cd.linking(a, cd.Circle((1, 0, 0), (0, 1, 0), 1.0))
    1
    >>> cd.linking(a, cd.Circle((5, 0, 0), (0, 1, 0), 1.0))
    0
    """
    out, status = link_details(a, b, query=query)
    if out.shape == ():
        if status != 0:
            h = query if query is not None else default_query()
            raise CircleDistError(int(status), _lib.query_last_error(h._handle()).decode())
        return int(out["linking"])
    return out["linking"].copy()


# ---- time of impact --------------------------------------------------------------------------

from ._objects import Capsule, RoundedDisk, Sphere, as_float_array  # noqa: E402

#: numpy mirrors of struct cdist_shape, cdist_motion and cdist_toi_result.
SHAPE_DTYPE = np.dtype([("type", np.int32), ("reserved_int", np.int32), ("u", np.float64, (10,))],
                       align=True)
MOTION_DTYPE = np.dtype([("center", np.float64, (3,)), ("translation", np.float64, (3,)),
                         ("rotation", np.float64, (3,))], align=True)
TOI_DTYPE = np.dtype([("state", np.int32), ("iterations", np.int32), ("t", np.float64),
                      ("distance", np.float64), ("contact", _lib.CONTACT_DTYPE),
                      ("reserved", np.float64, (4,))], align=True)
#: Outcomes of a time-of-impact query (cdist_toi_state).
TOI_NONE, TOI_HIT, TOI_ITERATION_LIMIT = 0, 1, 2
_SHAPE_TYPES = {Sphere: 0, Capsule: 1, Torus: 2, RoundedDisk: 3}

_shape_size = _lib._decl("cdist_shape_size", _c.c_size_t, required=False)
_toi_size = _lib._decl("cdist_toi_result_size", _c.c_size_t, required=False)
_toi_batch = _lib._decl("cdist_toi_batch", _c.c_int, _P, _c.c_size_t, _P, _c.c_ssize_t, _P,
                        _c.c_ssize_t, _P, _c.c_ssize_t, _P, _c.c_ssize_t, _c.c_double,
                        _c.c_double, _c.c_int, _P, _P, required=False)
for _fn, _dt, _what in ((_shape_size, SHAPE_DTYPE, "cdist_shape"),
                        (_toi_size, TOI_DTYPE, "cdist_toi_result")):
    if _fn is not None and _fn() != _dt.itemsize:
        raise ImportError("circledist: the library's %s is %d bytes, this package expects %d"
                          % (_what, _fn(), _dt.itemsize))


def _shapes(obj, what):
    """A Sphere/Capsule/Torus/RoundedDisk (single or array) as a SHAPE_DTYPE array."""
    kind = _SHAPE_TYPES.get(type(obj))
    if kind is None:
        raise TypeError("%s: expected a Sphere, Capsule, Torus or RoundedDisk, got %s"
                        % (what, type(obj).__name__))
    out = np.zeros(obj.shape, SHAPE_DTYPE)
    out["type"] = kind
    out["u"][..., :obj.WIDTH] = obj.data
    return out


def _motions(motion, what):
    """None (no motion) or (center, translation, rotation), each broadcasting to (..., 3)."""
    if motion is None:
        return None
    if len(motion) != 3:
        raise ValueError("%s: expected (center, translation, rotation)" % what)
    parts = [as_float_array(v, "%s.%s" % (what, f), 3)
             for v, f in zip(motion, ("center", "translation", "rotation"))]
    shape = np.broadcast_shapes(*(p.shape[:-1] for p in parts))
    out = np.zeros(shape, MOTION_DTYPE)
    for p, f in zip(parts, ("center", "translation", "rotation")):
        out[f] = p
    return out


def _rec_rows(arr, shape, n):
    """(pointer, byte stride, keep-alive) of a record array broadcast to `shape` (stride 0 for
    one record)."""
    if arr.ndim == 0 or arr.size == 1:
        a = np.ascontiguousarray(arr.reshape(1))
        return a.ctypes.data, 0, a
    a = np.ascontiguousarray(np.broadcast_to(arr, shape)).reshape(n)
    return a.ctypes.data, arr.dtype.itemsize, a


def time_of_impact(a, b, motion_a=None, motion_b=None, *, target=0.0, tolerance=1e-9,
                   max_iterations=100000, query=None):
    """First time t in [0, 1] at which swept objects a and b, moving rigidly, reach a signed
    distance, by conservative advancement (never tunnels; docs/toi.md).

    Parameters
    ----------
    a, b : Sphere, Capsule, Torus or RoundedDisk
        Single objects or arrays (broadcast).
    motion_a, motion_b : tuple (center, translation, rotation) or None, optional
        None: still. Else x(t) = c + t T + R(t w)(x - c), w the rotation vector (axis times
        angle over [0, 1]).
    target : float, optional
        The signed distance to reach (default 0: contact).
    tolerance : float, optional
        Accuracy of the distance at the reported time.
    max_iterations : int, optional
        Advancement steps before TOI_ITERATION_LIMIT.
    query : Query, optional
        The handle (default: default_query()).

    Returns
    -------
    records : ndarray of TOI_DTYPE
        state (TOI_NONE / TOI_HIT / TOI_ITERATION_LIMIT), iterations, t, distance, contact.
    status : ndarray of int32
        The status of each entry (one C call, cdist_toi_batch).

    Raises
    ------
    TypeError, ValueError
        Objects of another type, or shapes that do not broadcast.

    Examples
    --------
    >>> import circledist as cd
    >>> ball = cd.Sphere((0, 0, 0), 0.5)
    >>> rec, status = cd.time_of_impact(ball, cd.Sphere((3, 0, 0), 0.5),
    ...                                 ((0, 0, 0), (4, 0, 0), (0, 0, 0)))
    >>> int(rec["state"]) == cd.TOI_HIT, round(float(rec["t"]), 6)
    (True, 0.5)
    """
    if _toi_batch is None:
        raise RuntimeError("time_of_impact: the loaded libcircledist has no cdist_toi_batch")
    sa, sb = _shapes(a, "time_of_impact a"), _shapes(b, "time_of_impact b")
    ma, mb = _motions(motion_a, "motion_a"), _motions(motion_b, "motion_b")
    shapes = [sa.shape, sb.shape] + [m.shape for m in (ma, mb) if m is not None]
    try:
        shape = np.broadcast_shapes(*shapes)
    except ValueError:
        raise ValueError("time_of_impact: the batch shapes do not broadcast: %s" % shapes) from None
    n = math.prod(shape)
    out = np.zeros(shape, TOI_DTYPE)
    status = np.zeros(shape, np.int32)
    if n:
        pa, stra, ka = _rec_rows(sa, shape, n)
        pb, strb, kb = _rec_rows(sb, shape, n)
        pma, strma, kma = _rec_rows(ma, shape, n) if ma is not None else (None, 0, None)
        pmb, strmb, kmb = _rec_rows(mb, shape, n) if mb is not None else (None, 0, None)
        h = query if query is not None else default_query()
        with h._lock:
            q = h._handle()
            st = _toi_batch(q, n, pa, stra, pma, strma, pb, strb, pmb, strmb, float(target),
                            float(tolerance), int(max_iterations), out.ctypes.data,
                            status.ctypes.data)
            if st in (1, 13):
                raise CircleDistError(st, _lib.query_last_error(q).decode())
        del ka, kb, kma, kmb
    return out, status


# ---- invariants of a chain of linked rings ------------------------------------------------------

def chain_invariants(tori, expected_linking=None, *, query=None):
    """The two invariants a simulated chain of solid tori must keep, from one C call over every
    pair (N (N - 1) / 2 pairs: meant for chains of hundreds of links).

    Parameters
    ----------
    tori : Torus array, shape (N,)
        In chain order (link i hangs in links i - 1 and i + 1).
    expected_linking : array_like, shape (N - 1,), optional
        The neighbours' core linking numbers to compare with (e.g. those of the first frame);
        None: only report them.
    query : Query, optional
        The handle (default: default_query()).

    Returns
    -------
    dict
        max_penetration: largest overlap depth -signed distance over all pairs (0 if none);
        worst_pair: (i, j) of that overlap, or None; neighbour_linking: core linking numbers
        of the pairs (i, i + 1) (-1, 0, +1, or LINK_TOUCHING when the core circles meet);
        linking_kept: neighbour_linking equals expected_linking (True when not given);
        status_ok: every pair was answered (no invalid torus).

    Raises
    ------
    TypeError
        tori is not a Torus array of shape (N,).

    Examples
    --------
    >>> import numpy as np
    >>> import circledist as cd
    >>> centers = [[0, 0, 0], [1, 0, 0], [2, 0, 0]]
    >>> normals = [[0, 0, 1], [0, 1, 0], [0, 0, 1]]
    >>> chain = cd.Torus(cd.Circle(np.array(centers, float), np.array(normals, float), 0.6), 0.05)
    >>> inv = cd.chain_invariants(chain)
    >>> inv["max_penetration"], inv["worst_pair"], inv["neighbour_linking"].tolist(), inv["status_ok"]
    (0.0, None, [1, -1], True)
    """
    if not isinstance(tori, Torus) or len(tori.shape) != 1:
        raise TypeError("chain_invariants: expected a Torus array of shape (N,)")
    n = tori.shape[0]
    i, j = np.triu_indices(n, 1)
    rec, status = link_details(Torus.from_array(tori.data[i]), Torus.from_array(tori.data[j]),
                               query=query)
    depth = np.where(status == 0, -rec["distance"], np.nan)
    worst = int(np.nanargmax(depth)) if depth.size and np.any(depth > 0) else None
    neighbour = (j == i + 1)
    lk = rec["core_linking"][neighbour]
    kept = True if expected_linking is None else bool(
        np.array_equal(lk, np.asarray(expected_linking, dtype=lk.dtype)))
    return {"max_penetration": float(depth[worst]) if worst is not None else 0.0,
            "worst_pair": (int(i[worst]), int(j[worst])) if worst is not None else None,
            "neighbour_linking": lk.copy(), "linking_kept": kept,
            "status_ok": bool(np.all(status == 0))}
