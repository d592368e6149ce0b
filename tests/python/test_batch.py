# SPDX-License-Identifier: MIT
"""Vectorised calls: broadcasting, bad rows, threads, views, distance_only, curves. The
reference files are checked in test_reference.py; here every vectorised answer is compared
with the single query of the same entry (which tests/python/test_python.py and the C reference
tests check against independent answers) and with closed forms."""
import math

import numpy as np
import pytest

import circledist as cd

RNG = np.random.default_rng(12)


def _unit(n):
    v = RNG.normal(size=(n, 3))
    return v / np.linalg.norm(v, axis=1)[:, None]


def _circles(n):
    return cd.Circle(RNG.uniform(-1, 1, (n, 3)), _unit(n), RNG.uniform(0.2, 1.5, n))


def _same_as_single(res, name, a_items, b_items):
    for i, (a, b) in enumerate(zip(a_items, b_items)):
        r = getattr(cd, name)(a, b)
        assert res.distance[i] == r.distance
        assert res.num_pairs[i] == r.num_pairs and bool(res.equidistant[i]) == r.equidistant
        assert np.array_equal(res.points[i, :r.num_pairs], r.points)
        assert np.array_equal(res.params[i, :r.num_pairs], r.params, equal_nan=True)


def test_point_circle_closed_form_over_an_array():
    n = 1000
    p = RNG.uniform(-3, 3, (n, 3))
    res = cd.point_circle(p, cd.Circle((0, 0, 0), (0, 0, 1), 2))     # one circle: stride 0
    exact = np.hypot(np.hypot(p[:, 0], p[:, 1]) - 2, p[:, 2])
    assert res.shape == (n,) and res.points.shape == (n, 2, 2, 3) and res.params.shape == (n, 2, 2)
    assert np.all(np.abs(res.distance - exact) <= 4e-16 * 5)
    assert np.all(res.ok) and np.all(res.num_pairs == 1)
    assert np.array_equal(res.points[:, 0, 0], p)


def test_broadcasting_matches_single_queries():
    a = _circles(30)
    one = cd.Circle((0.1, 0.2, 0.3), (0, 0.6, 0.8), 0.7)
    res = cd.circle_circle(a, one)
    _same_as_single(res, "circle_circle", a, [one] * 30)
    # field broadcasting inside one object: shared normal, array of centres and radii
    b = cd.Disk(RNG.uniform(-1, 1, (30, 3)), (0, 0, 1), RNG.uniform(0.1, 1, 30))
    res = cd.circle_disk(one, b)
    _same_as_single(res, "circle_disk", [one] * 30, b)
    # outer product: (5, 1) against (4,) gives (5, 4)
    rows, cols = _circles(5), _circles(4)
    grid = cd.Circle.from_array(rows.data[:, None, :])
    res = cd.circle_circle(grid, cols)
    assert res.shape == (5, 4) and res.points.shape == (5, 4, 2, 2, 3)
    for i in range(5):
        for j in range(4):
            assert res.distance[i, j] == cd.circle_circle(rows[i], cols[j]).distance
    with pytest.raises(ValueError, match="do not broadcast"):
        cd.circle_circle(_circles(3), _circles(4))


def test_bad_rows_get_nan_and_their_status_others_answered():
    a = _circles(8)
    data = a.data.copy()
    data[1, 3:6] = (0, 0, 0)          # zero normal
    data[3, 6] = -1                   # negative radius
    data[5, 0] = np.nan               # not finite
    data[6, 3:6] = (0, 0, 2)          # not unit
    bad = cd.Circle.from_array(data)
    one = cd.Circle((0, 0, 0), (0, 0, 1), 1)
    res = cd.circle_circle(bad, one)
    names = res.status_names()
    assert list(names[[1, 3, 5, 6]]) == ["CDIST_ERR_ZERO_VECTOR", "CDIST_ERR_NEGATIVE_RADIUS",
                                         "CDIST_ERR_NOT_FINITE", "CDIST_ERR_NOT_UNIT"]
    badmask = np.zeros(8, bool)
    badmask[[1, 3, 5, 6]] = True
    assert np.all(np.isnan(res.distance[badmask])) and np.all(res.num_pairs[badmask] == 0)
    assert np.array_equal(res.ok, ~badmask)
    good = np.flatnonzero(~badmask)
    _same_as_single(cd.BatchResult(res.raw[good], res.status[good]), "circle_circle",
                    [a[i] for i in good], [one] * len(good))
    with pytest.raises(cd.CircleDistError) as e:
        res[3]
    assert e.value.name == "CDIST_ERR_NEGATIVE_RADIUS"
    assert res[0].distance == res.distance[0]
    d = cd.circle_circle(bad, one, distance_only=True)
    assert np.array_equal(d.status, res.status) and np.all(np.isnan(d.distance[badmask]))


def test_threads_give_identical_results():
    a, b = _circles(2000), _circles(2000)
    r1 = cd.circle_circle(a, b, threads=1)
    r2 = cd.circle_circle(a, b, threads=2)
    assert r1.raw.tobytes() == r2.raw.tobytes()
    with cd.Query(threads=2) as q:
        assert q.threads == 2
        assert q.circle_circle(a, b).raw.tobytes() == r1.raw.tobytes()
    with pytest.raises(cd.CircleDistError) as e:
        cd.circle_circle(a, b, threads=0)
    assert e.value.name == "CDIST_ERR_BAD_OPTION"


def test_distance_only_and_method_per_call():
    a, b = _circles(500), _circles(500)
    full = cd.circle_circle(a, b)
    d = cd.circle_circle(a, b, distance_only=True)
    L = np.maximum.reduce([a.radius, b.radius, np.linalg.norm(a.center - b.center, axis=1), full.distance])
    # the distance-only batch (the circle-circle kernel) agrees with the full query to 2 ulps of scale
    assert np.all(np.abs(d.distance - full.distance) <= 2 * np.spacing(L))
    with pytest.raises(AttributeError, match="distance_only"):
        d.points
    for m in cd.Method:
        r = cd.circle_circle(a, b, method=m)
        assert np.all(np.abs(r.distance - full.distance) <= 1e-12 * L)
    # one object each, but distance_only: still a (shape ()) batch
    one = cd.circle_circle(a[0], b[0], distance_only=True)
    assert one.shape == () and abs(one.distance - full.distance[0]) <= 2 * np.spacing(L[0])


def test_strided_views_and_empty_batches():
    table = np.zeros((10, 20))
    table[:, 0:3] = RNG.uniform(-1, 1, (10, 3))
    table[:, 3:6] = _unit(10)
    table[:, 6] = 0.5
    rev = cd.Circle.from_array(table[::-2, 0:7])         # negative row stride, no copy
    assert np.shares_memory(rev.data, table)
    res = cd.point_circle(np.zeros(3), rev)
    for i in range(5):
        assert res.distance[i] == cd.point_circle((0, 0, 0), rev[i]).distance
    empty = cd.circle_circle(cd.Circle.from_array(np.empty((0, 7))), cd.Circle((0, 0, 0), (0, 0, 1), 1))
    assert empty.shape == (0,) and empty.points.shape == (0, 2, 2, 3)


def test_curve_against_an_array_of_circles():
    hel = cd.Helix((0, 0, 0), (0, 0, 1), (1, 0, 0), 1.0, 0.5, 0, 9)
    k = 0.5 / (2 * math.pi)

    def f(t):
        return (math.cos(t), math.sin(t), k * t), (-math.sin(t), math.cos(t), k)
    circles = cd.Circle(RNG.uniform(-1, 1, (6, 3)) * 2, _unit(6), 0.8)
    rc = cd.curve_circle(f, 0, 9, circles, threads=2)
    rh = cd.helix_circle(hel, circles)
    assert np.all(rc.ok) and np.all(np.abs(rc.distance - rh.distance) <= 1e-13)
    rd = cd.curve_disk(f, 0, 9, cd.Disk.from_array(circles.data))
    assert np.all(np.abs(rd.distance - cd.helix_disk(hel, cd.Disk.from_array(circles.data)).distance) <= 1e-13)

    def boom(t):
        raise ZeroDivisionError("inside f")
    with pytest.raises(ZeroDivisionError):
        cd.curve_circle(boom, 0, 1, circles)


def test_every_kind_vectorised_equals_single():
    n = 12
    p = RNG.uniform(-2, 2, (n, 3))
    c = _circles(n)
    line = cd.Line(RNG.uniform(-2, 2, (n, 3)), _unit(n))
    seg = cd.Segment(RNG.uniform(-2, 2, (n, 3)), RNG.uniform(-2, 2, (n, 3)))
    arc = cd.Arc(_circles(n), _unit(n), RNG.uniform(-3, 0, n), RNG.uniform(0, 3, n))
    hel = cd.Helix(RNG.uniform(-1, 1, (n, 3)), (0, 0, 1), (1, 0, 0), 0.7, 0.3, 0, 8)
    bez = cd.Bezier3(*(RNG.uniform(-2, 2, (n, 3)) for _ in range(4)))
    args = {"point": cd.Point(p), "circle": c, "disk": cd.Disk.from_array(c.data), "line": line,
            "ray": cd.Ray.from_array(line.data), "segment": seg, "arc": arc, "helix": hel, "bezier3": bez}
    for name in cd._query.QUERY_NAMES:
        if name.startswith("curve"):
            continue
        x, y = name.split("_")
        a, b = args[x], args[y] if y != "arc" or x != "arc" else arc[::-1]
        res = getattr(cd, name)(a, b)
        assert np.all(res.ok), name
        _same_as_single(res, name, [a[i] for i in range(n)], [b[i] for i in range(n)])


def test_out_buffers_are_reused():
    a, b = _circles(50), _circles(50)
    first = cd.circle_circle(a, b)
    again = cd.circle_circle(b, a, out=first)
    assert again is first
    assert np.array_equal(again.distance, cd.circle_circle(b, a).distance)
    d = cd.circle_circle(a, b, distance_only=True)
    assert cd.circle_circle(b, a, distance_only=True, out=d) is d
    with pytest.raises(ValueError, match="out must be"):
        cd.circle_circle(a, b, out=d)
    with pytest.raises(ValueError, match="out must be"):
        cd.circle_circle(a[:10], b[:10], out=first)


def test_python_threads_share_a_query_safely():
    import threading
    a, b = _circles(3000), _circles(3000)
    want = cd.circle_circle(a, b).distance
    q = cd.Query()
    got = {}

    def work(k):
        got[("shared", k)] = q.circle_circle(a, b).distance          # serialised by the lock
        got[("default", k)] = cd.circle_circle(a, b).distance        # this thread's own handle
    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert len(got) == 8 and all(np.array_equal(v, want) for v in got.values())


def test_plain_nested_lists_are_points():
    res = cd.point_disk([[0, 0, 2], [3, 0, 0]], cd.Disk((0, 0, 0), (0, 0, 1), 1))
    assert res.distance.tolist() == [2.0, 2.0]


# ---- progress, cancel and Ctrl-C ---------------------------------------------------------

def _tori(n):
    return cd.Torus(_circles(n), RNG.uniform(0.0, 0.2, n))


def test_progress_callback_stops_the_batch_and_keeps_the_answers():
    T, t0 = _tori(30000), cd.Torus(((0, 0, 0), (0, 0, 1), 1.0), 0.1)
    full = cd.torus_torus(T, t0)
    for threads in (1, 2):
        seen = []
        out = cd.torus_torus(T, t0, threads=threads, progress=lambda done, total: seen.append((done, total)))
        assert out.raw.tobytes() == full.raw.tobytes() and np.all(out.status == 0)
        # one thread reports every 4096 entries; with two, the calling thread reports between its
        # own chunks (maybe only at the end, if the other thread was faster)
        assert seen[-1] == (30000, 30000) and len(seen) >= (8 if threads == 1 else 1)
        assert all(d1 < d2 for (d1, _), (d2, _) in zip(seen, seen[1:]))
        for _attempt in range(20):   # two threads: stopped unless the other thread was faster
            calls = []
            stopped = cd.torus_torus(T, t0, threads=threads, progress=lambda d, t: calls.append(d) or len(calls) >= 2)
            if np.any(stopped.cancelled):
                break
            assert threads > 1
        k = int(np.count_nonzero(stopped.status == 0))
        assert 0 < k < 30000 and len(calls) == 2
        assert np.all(stopped.status[:k] == 0) and np.all(stopped.cancelled[k:])
        assert stopped.raw[:k].tobytes() == full.raw[:k].tobytes()
        assert np.all(np.isnan(stopped.distance[k:])) and np.all(stopped.num_pairs[k:] == 0)
    # an exception in the callback stops the batch and is raised
    with pytest.raises(ZeroDivisionError):
        cd.torus_torus(T, t0, progress=lambda d, t: 1 / 0)


def test_progress_bar_uses_tqdm_when_installed(monkeypatch, capsys):
    import sys
    import types
    updates = []

    class FakeTqdm:
        def __init__(self, total, **kw):
            updates.append(("total", total))

        def update(self, k):
            updates.append(k)

        def close(self):
            updates.append("closed")
    monkeypatch.setitem(sys.modules, "tqdm", types.SimpleNamespace(tqdm=FakeTqdm))
    T, t0 = _tori(20000), cd.Torus(((0, 0, 0), (0, 0, 1), 1.0), 0.1)
    cd.torus_torus(T, t0, distance_only=True, progress=True)
    assert updates[0] == ("total", 20000) and updates[-1] == "closed"
    assert sum(u for u in updates[1:-1]) == 20000
    monkeypatch.setitem(sys.modules, "tqdm", None)      # not installed: a line on stderr
    cd.torus_torus(T, t0, distance_only=True, progress=True)
    assert "100% of 20000 entries" in capsys.readouterr().err


def test_ctrl_c_interrupts_a_long_batch():
    """SIGINT from a timer during a 10^7-entry batch: KeyboardInterrupt long before the batch
    would end (the latency itself, a few milliseconds on an idle machine, is measured by
    examples/bench_python.py --interrupt, not asserted here), the entries answered before it
    intact in out=, the others CDIST_ERR_CANCELLED, the handler restored."""
    import os
    import signal
    import threading
    import time
    n = 10 ** 7
    t0 = cd.Torus(((0, 0, 0), (0, 0, 1), 1.0), 0.1)
    row = cd.Torus(((0.3, 0.8, 0.1), (0.6, 0.0, 0.8), 0.9), 0.05).data
    T = cd.Torus.from_array(np.broadcast_to(row, (n, 8)))  # one torus repeated (stride 0)
    want = cd.torus_torus(cd.Torus.from_array(np.broadcast_to(row, (64, 8))), t0, distance_only=True).distance[0]
    # memory already written, as in a reused out= (writing the cancelled entries into fresh memory
    # adds its page faults, about 0.1 s for these 120 MB)
    out = cd.BatchContact(None, np.full(n, -1, np.int32), np.full(n, -1.0))
    sent = []
    timer = threading.Timer(0.3, lambda: (sent.append(time.monotonic()), os.kill(os.getpid(), signal.SIGINT)))
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            cd.torus_torus(T, t0, distance_only=True, out=out)
        raised = time.monotonic()
    finally:
        timer.cancel()
    assert sent, "the batch ended before the signal (%.2f s)" % (raised - start)
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    k = int(np.count_nonzero(out.status == 0))
    # stopped within a chunk of the signal: far fewer entries answered than the batch holds
    assert 0 < k < n // 2, "%d of %d entries answered, KeyboardInterrupt %.3f s after SIGINT" % (
        k, n, raised - sent[0])
    assert np.all(out.status[:k] == 0) and np.all(out.status[k:] == 17)
    assert np.all(out.distance[:k] == want) and np.all(np.isnan(out.distance[k:]))


def test_batches_release_the_gil_and_report_for_every_kind():
    """Another Python thread runs while a batch is in C (the library is a ctypes.CDLL, whose calls
    release the GIL), and the plain kinds take progress= too."""
    import ctypes
    import sys
    import threading
    import time
    from circledist import _lib
    assert type(_lib.lib) is ctypes.CDLL                # not PyDLL: calls release the GIL
    D = cd.Disk(RNG.uniform(-1, 1, (100000, 3)), _unit(100000), RNG.uniform(0.2, 1.5, 100000))
    d0 = cd.Disk((0, 0, 0), (0, 0, 1), 1.0)
    ticks, stop = [0], threading.Event()

    def count():        # gives the GIL back at every step (sleep(0)): never the one holding it up
        while not stop.is_set():
            ticks[0] += 1
            time.sleep(0)
    # a thread switch forced inside a report would take a second: the counting thread can only
    # run while the batch is in C, and only if the call released the GIL
    interval = sys.getswitchinterval()
    sys.setswitchinterval(1.0)
    t = threading.Thread(target=count)
    t.start()
    try:
        seen, at = [], []
        r = cd.disk_disk(D, d0, progress=lambda d, n: seen.append(d) or at.append(ticks[0]))
    finally:
        stop.set()
        t.join()
        sys.setswitchinterval(interval)
    assert np.all(r.ok) and seen[-1] == 100000 and len(seen) > 10
    steps = np.diff(at)
    assert steps.sum() > 0, "the other thread did not run while the batch was in C"
