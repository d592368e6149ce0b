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
    """The full cdist_link records (LINK_DTYPE) of a against b, broadcast, from one C call.

    a, b: both Circle or both Torus (single objects or arrays). Returns (records, status), two
    arrays of the broadcast batch shape. Entries with a bad object get their status (see
    circledist.status_name) and linking == LINK_ERROR; the others are answered."""
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
    """Linking number of circles (or solid tori) a and b: -1, 0 or +1, LINK_TOUCHING (2) when
    they meet (distance <= 2^-40 of the scale), for tori LINK_OVERLAP (3) when the solids
    overlap. Arrays of objects broadcast and are answered by one C call; the result is then an
    int array (LINK_ERROR (4) for a bad entry), else an int (a bad object raises
    CircleDistError). Sign: +1 when b passes through a's disk along a's normal, each circle
    oriented counterclockwise about its own normal (docs/linking.md)."""
    out, status = link_details(a, b, query=query)
    if out.shape == ():
        if status != 0:
            h = query if query is not None else default_query()
            raise CircleDistError(int(status), _lib.query_last_error(h._handle()).decode())
        return int(out["linking"])
    return out["linking"].copy()
