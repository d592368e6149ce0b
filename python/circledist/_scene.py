# SPDX-License-Identifier: MIT
"""Scenes: many objects at once (cdist_scene; internal module, see circledist.Scene)."""
import ctypes
import threading

import numpy as np

from . import _lib
from ._objects import (Arc, Capsule, Circle, Disk, GeometricObject, Point, RoundedDisk, Segment,
                       Sphere, Torus, coerce)
from ._interrupt import SigintRecorder
from ._query import CircleDistError, Query
from ._topology import LINK_DTYPE, TOI_DTYPE, _motions

_c = ctypes
_P = _c.c_void_p
_ST = _c.c_int
_SZ = _c.c_size_t
_d = _lib._decl

#: numpy mirror of struct cdist_scene_pair (checked against cdist_scene_pair_size()).
SCENE_PAIR_DTYPE = np.dtype([("i", np.uint64), ("j", np.uint64), ("distance", np.float64),
                             ("status", np.int32), ("num_pairs", np.int32), ("flags", np.int32),
                             ("reserved", np.int32), ("point", np.float64, (2, 2, 3))], align=True)
#: numpy mirror of struct cdist_scene_link (checked against cdist_scene_link_size()).
SCENE_LINK_DTYPE = np.dtype([("i", np.uint64), ("j", np.uint64), ("status", np.int32),
                             ("reserved_int", np.int32), ("link", LINK_DTYPE),
                             ("reserved", np.float64, (2,))], align=True)
#: numpy mirror of struct cdist_scene_toi_result (checked against cdist_scene_toi_size()).
SCENE_TOI_DTYPE = np.dtype([("i", np.uint64), ("j", np.uint64), ("candidates", np.uint64),
                            ("toi", TOI_DTYPE), ("reserved", np.float64, (4,))], align=True)
SCENE_STATS_FIELDS = ("objects", "live", "nodes", "bytes", "box_pairs", "screened", "candidates",
                      "reported", "rebuilds", "refits")

_pair_size = _d("cdist_scene_pair_size", _SZ, required=False)
_new = _d("cdist_scene_new", _P, required=False)
_free = _d("cdist_scene_free", None, _P, required=False)
_add = _d("cdist_scene_add", _ST, _P, _P, _c.c_int, _SZ, _P, _c.c_ssize_t, _P, _P, required=False)
_update = _d("cdist_scene_update", _ST, _P, _P, _SZ, _P, _c.c_int, _P, _c.c_ssize_t, _P, required=False)
_remove = _d("cdist_scene_remove", _ST, _P, _P, _SZ, _P, required=False)
_set_groups = _d("cdist_scene_set_groups", _ST, _P, _P, _SZ, _P, _P, _P, required=False)
_count = _d("cdist_scene_count", _SZ, _P, required=False)
_object_status = _d("cdist_scene_object_status", _ST, _P, _SZ, required=False)
_rebuild = _d("cdist_scene_rebuild", _ST, _P, _P, required=False)
_stats = _d("cdist_scene_get_stats", _ST, _P, _P, required=False)
PAIR_FN = _c.CFUNCTYPE(_c.c_int, _P, _P, _SZ)
_within_fn = _d("cdist_scene_pairs_within_fn", _ST, _P, _P, _c.c_double, PAIR_FN, _P, _P, required=False)
_between = _d("cdist_scene_pairs_between", _ST, _P, _P, _P, _c.c_double, _P, _SZ, _P, required=False)
_closest = _d("cdist_scene_closest_pair", _ST, _P, _P, _P, required=False)
_closest_between = _d("cdist_scene_closest_pair_between", _ST, _P, _P, _P, _P, required=False)
_nearest = _d("cdist_scene_nearest", _ST, _P, _P, _c.c_int, _P, _SZ, _P, _P, required=False)
_within = _d("cdist_scene_within", _ST, _P, _P, _c.c_int, _P, _c.c_double, _P, _SZ, _P, required=False)
_toi_size = _d("cdist_scene_toi_size", _SZ, required=False)
_toi = _d("cdist_scene_toi", _ST, _P, _P, _P, _c.c_ssize_t, _c.c_double, _c.c_double, _c.c_int, _P,
          required=False)
if _toi_size is not None and _toi_size() != SCENE_TOI_DTYPE.itemsize:
    raise ImportError("circledist: the library's cdist_scene_toi_result is %d bytes, this package expects %d"
                      % (_toi_size(), SCENE_TOI_DTYPE.itemsize))
_link_size = _d("cdist_scene_link_size", _SZ, required=False)
_linked = _d("cdist_scene_linked_pairs", _ST, _P, _P, _P, _SZ, _P, required=False)
if _link_size is not None and _link_size() != SCENE_LINK_DTYPE.itemsize:
    raise ImportError("circledist: the library's cdist_scene_link is %d bytes, this package expects %d"
                      % (_link_size(), SCENE_LINK_DTYPE.itemsize))
if _pair_size is not None and _pair_size() != SCENE_PAIR_DTYPE.itemsize:
    raise ImportError("circledist: the library's cdist_scene_pair is %d bytes, this package expects %d"
                      % (_pair_size(), SCENE_PAIR_DTYPE.itemsize))

#: The scene kind (cdist_scene_kind) of each object class.
KINDS = {Point: 0, Segment: 1, Circle: 2, Disk: 3, Arc: 4, Sphere: 5, Capsule: 6, Torus: 7,
         RoundedDisk: 8}
_BAD_KIND = 16  # CDIST_ERR_BAD_KIND: a pair without an exact query (point or sphere vs arc)
_CALLBACK_FAILED = 9  # CDIST_ERR_CALLBACK_FAILED: the pair callback stopped the query


def _kind_rows(obj, what):
    """(kind, contiguous (N, WIDTH) float64 rows) of one object or array of objects."""
    if not isinstance(obj, GeometricObject):
        raise TypeError("%s: expected a circledist object (Torus, Sphere, Capsule, Circle, ...), got %s"
                        % (what, type(obj).__name__))
    kind = KINDS.get(type(obj))
    if kind is None:
        raise TypeError("%s: a scene cannot hold %s objects" % (what, type(obj).__name__))
    rows = np.ascontiguousarray(obj.data.reshape(-1, obj.WIDTH), dtype=np.float64)
    return kind, rows


def _groups(objects, what):
    """objects (one object/array, or a list of them, mixed kinds) as a list of (kind, rows)."""
    if isinstance(objects, GeometricObject):
        return [_kind_rows(objects, what)]
    return [_kind_rows(o, "%s[%d]" % (what, k)) for k, o in enumerate(objects)]


class ScenePairs:
    """Answered pairs of a scene query, as numpy arrays (one entry per pair, sorted by i, j).

    Unpacks as ``i, j, distance, points``.

    Parameters
    ----------
    raw : ndarray of SCENE_PAIR_DTYPE
        The C pair records (the Scene queries build ScenePairs themselves).

    Attributes
    ----------
    i, j : ndarray of int64, shape (n,)
        Ids (j is -1 for a query object).
    distance : ndarray, shape (n,)
        Signed distances.
    points : ndarray, shape (n, 2, 3)
        The closest pair's witness points (points[:, 0] on object i).
    all_points : ndarray, shape (n, 2, 2, 3)
        Both pairs, num_pairs (1 or 2) of them valid.
    num_pairs, equidistant, status : ndarray, shape (n,)
        status is 0, or the status of a pair the library has no exact query for (distance NaN).

    Examples
    --------
    >>> import circledist as cd
    >>> with cd.Scene(cd.Sphere([[0, 0, 0], [1, 0, 0], [5, 0, 0]], 0.25)) as scene:
    ...     i, j, distance, points = scene.pairs_within(1.0)
    >>> i, j, distance
    (array([0]), array([1]), array([0.5]))
    """

    def __init__(self, raw):
        self.raw = raw
        self.i = raw["i"].astype(np.int64)
        self.j = raw["j"].astype(np.int64)  # SIZE_MAX (a query object) wraps to -1
        self.distance = raw["distance"]
        self.all_points = raw["point"]
        self.points = raw["point"][:, 0]
        self.num_pairs = raw["num_pairs"]
        self.equidistant = (raw["flags"] & 1) != 0
        self.status = raw["status"]

    def __len__(self):
        return len(self.raw)

    def __iter__(self):
        return iter((self.i, self.j, self.distance, self.points))

    def __repr__(self):
        return "<ScenePairs: %d pairs>" % len(self.raw)


class SceneLinks:
    """Pairs of rings of Scene.linked_pairs(), as numpy arrays sorted by (i, j).

    Parameters
    ----------
    raw : numpy.ndarray
        The SCENE_LINK_DTYPE records the C call wrote (kept as ``raw``).

    Attributes
    ----------
    i, j : numpy.ndarray of int64
        Ids of the pair (i < j).
    linking, core_linking : numpy.ndarray
        -1, 0, +1, or LINK_TOUCHING (2), LINK_OVERLAP (3), LINK_ERROR (4), as
        circledist.linking gives them.
    distance, core_distance : numpy.ndarray of float64
        The signed distance (tube radii taken off) and the core circles' distance.
    flags, status : numpy.ndarray
        LINK_FLAG_* bits; 0 or why the pair could not be answered.

    Examples
    --------
    Two rings of a Hopf link: the second passes through the first's disk along its normal.

    >>> import circledist as cd
    >>> s = cd.Scene([cd.Circle((0, 0, 0), (0, 0, 1), 1.0), cd.Circle((1, 0, 0), (0, 1, 0), 1.0)])
    >>> i, j, linking = s.linked_pairs()
    >>> i.tolist(), j.tolist(), linking.tolist()
    ([0], [1], [1])
    """

    def __init__(self, raw):
        self.raw = raw
        self.i = raw["i"].astype(np.int64)
        self.j = raw["j"].astype(np.int64)
        self.linking = raw["link"]["linking"]
        self.core_linking = raw["link"]["core_linking"]
        self.distance = raw["link"]["distance"]
        self.core_distance = raw["link"]["core_distance"]
        self.flags = raw["link"]["flags"]
        self.status = raw["status"]

    def __len__(self):
        return len(self.raw)

    def __iter__(self):
        return iter((self.i, self.j, self.linking))

    def __repr__(self):
        return "<SceneLinks: %d pairs>" % len(self.raw)


class Scene:
    """Many objects at once: a certified broad phase over the library's exact queries.

    Ids are the objects' positions in the order given (later add() calls continue the
    numbering). Distances are the signed distances of the swept queries (core distance minus
    the radii), bit for bit those of the pair queries. pairs_within returns to Python between
    blocks of answers, so Ctrl-C interrupts it (KeyboardInterrupt), though not during the broad
    phase before the first block, which lists every candidate pair (docs/scene.md); the other
    queries (pairs_between, within, linked_pairs, time_of_impact, ...) run to their end.

    Parameters
    ----------
    objects : GeometricObject or sequence of GeometricObject, optional
        One object array (e.g. Torus(...) with array fields) or a list of them of any kinds
        (Point, Segment, Circle, Disk, Arc, Sphere, Capsule, Torus, RoundedDisk).
    query : Query, optional
        The handle for the exact queries (default: a new one).
    threads : int, optional
        Worker threads of the handle (default 1).

    Raises
    ------
    CircleDistError
        Invalid objects: they keep their ids and take part in nothing; the error names the
        first one (the valid ones are added).

    Examples
    --------
    >>> import circledist as cd
    >>> balls = cd.Sphere([[0, 0, 0], [1, 0, 0], [5, 0, 0]], 0.25)
    >>> with cd.Scene(balls) as scene:
    ...     print(len(scene), scene.closest_pair()[:3])
    ...     near = scene.nearest((4.0, 0.0, 0.0))
    3 (0, 1, 0.5)
    >>> near.i, near.distance
    (array([2]), array([0.75]))
    """

    def __init__(self, objects=(), query=None, threads=1):
        if _new is None:
            raise RuntimeError("the loaded libcircledist has no scene API (cdist_scene_new)")
        self._query = query if query is not None else Query(threads=threads)
        if query is not None and threads != 1:
            self._query.set_threads(threads)
        self._s = _new()
        if not self._s:
            raise MemoryError("cdist_scene_new failed")
        self._lock = threading.RLock()
        if isinstance(objects, GeometricObject) or len(objects) > 0:
            self.add(objects)

    def close(self):
        """Free the C scene (also done when the object is collected)."""
        if getattr(self, "_s", None):
            _free(self._s)
            self._s = None

    def __del__(self):
        self.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __len__(self):
        return int(_count(self._handle()))

    def _handle(self):
        if not self._s:
            raise ValueError("the Scene is closed")
        return self._s

    def _group_error(self, g, groups):
        """The handle's last message, naming the array of a list (its entries count from 0)."""
        msg = _lib.query_last_error(self._query._handle()).decode()
        return "objects[%d]: %s" % (g, msg) if groups > 1 else msg

    def _check(self, st, allow=()):
        if st != 0 and st not in allow:
            raise CircleDistError(st, _lib.query_last_error(self._query._handle()).decode())

    # ---- objects ---------------------------------------------------------------------------
    def add(self, objects):
        """Add objects; their ids continue the numbering.

        Parameters
        ----------
        objects : GeometricObject or sequence of GeometricObject
            One object array or a list of them (any kinds).

        Returns
        -------
        ndarray of int64
            Their ids, in order.

        Raises
        ------
        CircleDistError
            Invalid objects (they keep their ids; the valid ones are added).
        """
        ids = []
        first_bad = None
        with self._query._lock, self._lock:
            groups = _groups(objects, "objects")
            for g, (kind, rows) in enumerate(groups):
                first = _c.c_size_t()
                st = _add(self._query._handle(), self._handle(), kind, len(rows), rows.ctypes.data,
                          rows.strides[0], _c.byref(first), None)
                if st != 0 and first_bad is None:
                    first_bad = (st, self._group_error(g, len(groups)))
                ids.append(np.arange(first.value, first.value + len(rows), dtype=np.int64))
        if first_bad is not None:
            raise CircleDistError(*first_bad)
        return np.concatenate(ids) if ids else np.empty(0, np.int64)

    def update(self, ids, objects):
        """Move or reshape objects. No rebuild: the tree is refitted before the next query.

        Parameters
        ----------
        ids : array_like of int
            The ids to replace.
        objects : GeometricObject or sequence of GeometricObject
            One array, or a list of arrays of any kinds, replacing ids in order.

        Raises
        ------
        ValueError
            As many objects as ids are needed.
        CircleDistError
            Invalid objects or ids (the first one; every valid entry of every array is applied).
        """
        ids = np.ascontiguousarray(np.asarray(ids, dtype=np.int64).reshape(-1)).astype(np.uintp)
        groups = _groups(objects, "objects")
        total = sum(len(r) for _, r in groups)
        if total != len(ids):
            raise ValueError("update: %d ids for %d objects" % (len(ids), total))
        at = 0
        first_bad = None
        with self._query._lock, self._lock:
            for g, (kind, rows) in enumerate(groups):
                part = np.ascontiguousarray(ids[at:at + len(rows)])
                st = _update(self._query._handle(), self._handle(), len(rows), part.ctypes.data, kind,
                             rows.ctypes.data, rows.strides[0], None)
                if st != 0 and first_bad is None:
                    first_bad = (st, self._group_error(g, len(groups)))
                at += len(rows)
        if first_bad is not None:
            raise CircleDistError(*first_bad)

    def remove(self, ids):
        """Remove objects (their ids are not reused).

        Parameters
        ----------
        ids : array_like of int
            The ids to remove.

        Raises
        ------
        CircleDistError
            A status the library reports for the call.
        """
        ids = np.ascontiguousarray(np.asarray(ids, dtype=np.int64).reshape(-1)).astype(np.uintp)
        with self._query._lock, self._lock:
            self._check(_remove(self._query._handle(), self._handle(), len(ids), ids.ctypes.data))

    def set_groups(self, ids=None, group=None, chain=None):
        """Skip filter: pairs of the same non-zero group are skipped, and consecutive ids i, i + 1
        of the same non-zero chain.

        Parameters
        ----------
        ids : array_like of int, optional
            The objects (None: 0 .. n - 1, n the length of group or chain).
        group : array_like of uint32, optional
            Group of each object (0: none).
        chain : array_like of uint32, optional
            Chain of each object (0: none).

        Raises
        ------
        CircleDistError
            A status the library reports for the call.
        """
        g = None if group is None else np.ascontiguousarray(np.asarray(group, dtype=np.uint32).reshape(-1))
        c = None if chain is None else np.ascontiguousarray(np.asarray(chain, dtype=np.uint32).reshape(-1))
        n = len(g) if g is not None else (len(c) if c is not None else 0)
        idp = None
        if ids is not None:
            ids = np.ascontiguousarray(np.asarray(ids, dtype=np.int64).reshape(-1)).astype(np.uintp)
            n = len(ids)
            idp = ids.ctypes.data
        for a, name in ((g, "group"), (c, "chain")):
            if a is not None and len(a) != n:
                raise ValueError("set_groups: %s has %d entries for %d ids" % (name, len(a), n))
        with self._query._lock, self._lock:
            self._check(_set_groups(self._query._handle(), self._handle(), n, idp,
                                    None if g is None else g.ctypes.data, None if c is None else c.ctypes.data))

    def object_status(self, ids):
        """The status of each object.

        Parameters
        ----------
        ids : array_like of int
            The ids.

        Returns
        -------
        ndarray of int32
            cdist_status of each id (0: live; its validation status when invalid).
        """
        return np.array([_object_status(self._handle(), int(i)) for i in np.asarray(ids).reshape(-1)],
                        dtype=np.int32)

    def rebuild(self):
        """Rebuild the tree now (queries rebuild by themselves when needed)."""
        with self._query._lock, self._lock:
            self._check(_rebuild(self._query._handle(), self._handle()))

    @property
    def stats(self):
        """Counters of the scene and its last query (dict)."""
        buf = (_c.c_size_t * 16)()
        _stats(self._handle(), buf)
        return {name: int(buf[k]) for k, name in enumerate(SCENE_STATS_FIELDS)}

    # ---- queries ---------------------------------------------------------------------------
    def pairs_within(self, delta):
        """Every pair i < j with distance <= delta (one C call).

        Parameters
        ----------
        delta : float
            The largest signed distance reported.

        Returns
        -------
        ScenePairs
            Sorted by (i, j).

        Raises
        ------
        CircleDistError
            A status the library reports for the call.
        """
        chunks = []
        state = {"error": None}
        sigint = SigintRecorder()  # Ctrl-C during the C call: take() stops the query

        def take(user, pairs, n):
            if sigint.hits:
                return 1
            try:
                a = np.empty(n, SCENE_PAIR_DTYPE)
                _c.memmove(a.ctypes.data, pairs, n * SCENE_PAIR_DTYPE.itemsize)
                chunks.append(a)
                return 0
            except BaseException as e:  # KeyboardInterrupt from Ctrl-C: stop the query
                state["error"] = e
                return 1

        fn = PAIR_FN(take)
        with self._query._lock, self._lock:
            with sigint:
                st = _within_fn(self._query._handle(), self._handle(), float(delta), fn, None, None)
            # a handler of the caller's that returns leaves the stopped query's status to raise
            interrupted = sigint.deliver()
            if state["error"] is not None:
                raise state["error"]
            if st == _CALLBACK_FAILED and not interrupted:  # an interrupt take() could not catch
                raise KeyboardInterrupt
            self._check(st, allow=(_BAD_KIND,))
        # joined as bytes: concatenating the structured arrays would promote their dtype per chunk
        raw = np.concatenate([a.view(np.uint8) for a in chunks]).view(SCENE_PAIR_DTYPE) if chunks \
            else np.empty(0, SCENE_PAIR_DTYPE)
        return ScenePairs(raw)

    def _sized(self, call, capacity, dtype=SCENE_PAIR_DTYPE, wrap=ScenePairs, allow=(_BAD_KIND,)):
        """Run call(out, capacity, count) and again with the exact size when it did not fit."""
        while True:
            out = np.zeros(max(capacity, 1), dtype)
            count = _c.c_size_t()
            st = call(out.ctypes.data, capacity, _c.byref(count))
            if count.value <= capacity:
                self._check(st, allow=allow)
                return wrap(out[:count.value])
            capacity = count.value

    def pairs_between(self, other, delta):
        """Every pair (i of this scene, j of other) with distance <= delta.

        Parameters
        ----------
        other : Scene
            The second scene.
        delta : float
            The largest signed distance reported.

        Returns
        -------
        ScenePairs
            Sorted by (i, j).

        Raises
        ------
        CircleDistError
            A status the library reports for the call.
        """
        with self._query._lock, self._lock, other._lock:
            return self._sized(lambda out, cap, cnt: _between(self._query._handle(), self._handle(), other._handle(),
                                                              float(delta), out, cap, cnt), 4 * len(self) + 64)

    def _one_pair(self, st, out):
        self._check(st)
        return ScenePairs(out)

    def closest_pair(self):
        """The closest pair (smallest distance, then smallest (i, j)).

        Returns
        -------
        (i, j, distance, points)
            Two ids, the signed distance and the witness points, shape (2, 3).

        Raises
        ------
        CircleDistError
            A status the library reports for the call.
        """
        out = np.empty(1, SCENE_PAIR_DTYPE)
        with self._query._lock, self._lock:
            st = _closest(self._query._handle(), self._handle(), out.ctypes.data)
            p = self._one_pair(st, out)
        return int(p.i[0]), int(p.j[0]), float(p.distance[0]), p.points[0]

    def closest_pair_between(self, other):
        """The closest pair (i of this scene, j of other).

        Parameters
        ----------
        other : Scene
            The second scene.

        Returns
        -------
        (i, j, distance, points)
            Two ids, the signed distance and the witness points, shape (2, 3).

        Raises
        ------
        CircleDistError
            A status the library reports for the call.
        """
        out = np.empty(1, SCENE_PAIR_DTYPE)
        with self._query._lock, self._lock, other._lock:
            st = _closest_between(self._query._handle(), self._handle(), other._handle(), out.ctypes.data)
            p = self._one_pair(st, out)
        return int(p.i[0]), int(p.j[0]), float(p.distance[0]), p.points[0]

    def _query_object(self, obj):
        if not isinstance(obj, GeometricObject):
            obj = coerce(obj, Point, "obj")
        kind, rows = _kind_rows(obj, "obj")
        if len(rows) != 1:
            raise ValueError("obj: expected one object, got %d" % len(rows))
        return kind, rows

    def nearest(self, obj, k=1):
        """The k objects nearest to obj, by distance then id.

        Parameters
        ----------
        obj : GeometricObject or array_like, shape (3,)
            One object of any kind (a point as its coordinates).
        k : int, optional
            How many (default 1).

        Returns
        -------
        ScenePairs
            i: the ids, j: -1.

        Raises
        ------
        CircleDistError
            A status the library reports for the call.
        """
        kind, rows = self._query_object(obj)
        k = int(k)
        out = np.empty(max(k, 1), SCENE_PAIR_DTYPE)
        count = _c.c_size_t()
        with self._query._lock, self._lock:
            st = _nearest(self._query._handle(), self._handle(), kind, rows.ctypes.data, k, out.ctypes.data,
                          _c.byref(count))
            self._check(st)
        return ScenePairs(out[:count.value])

    def within(self, obj, delta):
        """Every object within delta of obj, sorted by id.

        Parameters
        ----------
        obj : GeometricObject or array_like, shape (3,)
            One object of any kind (a point as its coordinates).
        delta : float
            The largest signed distance reported.

        Returns
        -------
        ScenePairs
            i: the ids, j: -1.

        Raises
        ------
        CircleDistError
            A status the library reports for the call.
        """
        kind, rows = self._query_object(obj)
        with self._query._lock, self._lock:
            return self._sized(lambda out, cap, cnt: _within(self._query._handle(), self._handle(), kind,
                                                             rows.ctypes.data, float(delta), out, cap, cnt), 64)

    def linked_pairs(self):
        """Every pair of rings that is not certified unlinked and apart.

        Circle and Torus objects take part (other kinds do not): linked cores, touching cores
        and overlapping tori are reported (see cdist_scene_linked_pairs). Groups and chains do
        not apply.

        Returns
        -------
        SceneLinks
            Sorted by (i, j).

        Raises
        ------
        CircleDistError
            A status the library reports for the call.

        Examples
        --------
        >>> import circledist as cd
        >>> s = cd.Scene([cd.Circle((0, 0, 0), (0, 0, 1), 1.0), cd.Circle((1, 0, 0), (0, 1, 0), 1.0),
        ...               cd.Circle((9, 0, 0), (0, 0, 1), 1.0)])
        >>> len(s.linked_pairs())
        1
        """
        if _linked is None:
            raise RuntimeError("the loaded libcircledist has no cdist_scene_linked_pairs")
        with self._query._lock, self._lock:
            return self._sized(lambda out, cap, cnt: _linked(self._query._handle(), self._handle(), out, cap, cnt),
                               2 * len(self) + 64, SCENE_LINK_DTYPE, SceneLinks, allow=())

    def time_of_impact(self, motions=None, *, target=0.0, tolerance=1e-9, max_iterations=100000):
        """Earliest time of impact of the moving scene (cdist_scene_toi).

        Parameters
        ----------
        motions : tuple or None
            None (nothing moves) or (center, translation, rotation), each broadcasting to
            (len(scene), 3): the motion of every id over t in [0, 1] as in
            circledist.time_of_impact.
        target : float
            The signed distance that counts as an impact.
        tolerance : float
            How far above the target the reported distance may be.
        max_iterations : int
            Conservative-advancement steps allowed per pair.

        Returns
        -------
        tuple
            (i, j, record): the pair of the earliest time (-1, -1 when no pair reaches the
            target) and its TOI_DTYPE record (state, iterations, t, distance, contact);
            record["t"] is 1 when nothing hits.

        Raises
        ------
        CircleDistError
            A status the library reports for the call.

        Examples
        --------
        Two unit spheres 4 apart; the first moves 3 towards the second: they touch at t = 2/3.

        >>> import circledist as cd
        >>> s = cd.Scene([cd.Sphere((0, 0, 0), 1.0), cd.Sphere((4, 0, 0), 1.0)])
        >>> i, j, rec = s.time_of_impact(([0, 0, 0], [[3, 0, 0], [0, 0, 0]], [0, 0, 0]))
        >>> i, j, abs(float(rec["t"]) - 2 / 3) < 1e-6
        (0, 1, True)
        """
        if _toi is None:
            raise RuntimeError("the loaded libcircledist has no cdist_scene_toi")
        n = len(self)
        m = None
        if motions is not None:
            m = np.ascontiguousarray(np.broadcast_to(_motions(motions, "motions"), (n,)))
        out = np.zeros(1, SCENE_TOI_DTYPE)
        with self._query._lock, self._lock:
            st = _toi(self._query._handle(), self._handle(), m.ctypes.data if m is not None else None,
                      m.dtype.itemsize if m is not None else 0, float(target), float(tolerance),
                      int(max_iterations), out.ctypes.data)
            self._check(st)
        r = out[0]
        none = int(r["i"]) == 2**64 - 1
        return (-1 if none else int(r["i"])), (-1 if none else int(r["j"])), r["toi"].copy()
