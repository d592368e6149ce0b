# SPDX-License-Identifier: MIT
"""circledist.Scene against brute force over the pair queries of the package: the same pairs,
distances and points bit for bit (tori, spheres, capsules and circles mixed), closest pair,
nearest, within, updates, groups and bad input."""
import math

import numpy as np
import pytest

import circledist as cd


def random_scene(n, seed=3, box=6.0):
    rng = np.random.default_rng(seed)
    def normals(k):
        v = rng.normal(size=(k, 3))
        return v / np.linalg.norm(v, axis=1)[:, None]
    k = n // 4
    tori = cd.Torus(cd.Circle(rng.uniform(-box, box, (k, 3)), normals(k), rng.uniform(0.5, 1.5, k)),
                    rng.uniform(0.0, 0.2, k))
    spheres = cd.Sphere(rng.uniform(-box, box, (k, 3)), rng.uniform(0.0, 0.5, k))
    p0 = rng.uniform(-box, box, (k, 3))
    capsules = cd.Capsule(cd.Segment(p0, p0 + rng.normal(size=(k, 3))), rng.uniform(0.0, 0.3, k))
    circles = cd.Circle(rng.uniform(-box, box, (n - 3 * k, 3)), normals(n - 3 * k), rng.uniform(0.5, 1.5, n - 3 * k))
    return [tori, spheres, capsules, circles]


def flat(objects):
    """(kind name, single object) per id."""
    out = []
    for arr in objects:
        for m in range(len(arr)):
            out.append(arr[m])
    return out


def pair_distance(a, b):
    """The brute-force answer of the pair (a first) from the package's pair queries."""
    name = {cd.Torus: "torus", cd.Sphere: "sphere", cd.Capsule: "capsule", cd.Circle: "circle"}
    na, nb = name[type(a)], name[type(b)]
    fn = getattr(cd, na + "_" + nb, None)
    if fn is not None and na != "circle" and nb != "circle":
        c = fn(a, b)
        return c.distance, c.pairs[0].points
    fn = getattr(cd, nb + "_" + na, None)
    if fn is not None and na != "circle" and nb != "circle":
        c = fn(b, a)
        return c.distance, np.array(c.pairs[0].points)[::-1]
    if na == "circle" and nb == "circle":
        r = cd.circle_circle(a, b)
        return r.distance, r.pairs[0].points
    # a circle and a swept object: the swept query with the circle second, swapped back
    swept, circle, swap = (b, a, True) if na == "circle" else (a, b, False)
    sname = name[type(swept)]
    c = getattr(cd, sname + "_circle")(swept, circle) if sname != "torus" else None
    if c is None:  # torus-circle: circle-circle minus the tube
        r = cd.circle_circle(swept.circle, circle)
        d = r.distance - swept.tube_radius
        return d, None
    pts = np.array(c.pairs[0].points)
    return c.distance, (pts[::-1] if swap else pts)


def test_pairs_within_brute_force():
    objects = random_scene(160)
    scene = cd.Scene(objects)
    items = flat(objects)
    delta = 0.4
    want = {}
    for i in range(len(items)):
        for j in range(i + 1, len(items)):
            d, pts = pair_distance(items[i], items[j])
            if d <= delta:
                want[(i, j)] = (d, pts)
    for threads in (1, 2):
        scene._query.set_threads(threads)
        i, j, dist, points = scene.pairs_within(delta)
        got = {(int(a), int(b)): (d, p) for a, b, d, p in zip(i, j, dist, points)}
        assert list(zip(i.tolist(), j.tolist())) == sorted(got)
        assert set(got) == set(want)
        for key, (d, pts) in want.items():
            assert got[key][0] == d  # bit for bit
            if pts is not None:
                assert np.array_equal(got[key][1], np.asarray(pts))


def test_closest_nearest_within():
    objects = random_scene(120, seed=5)
    scene = cd.Scene(objects)
    items = flat(objects)
    best = min((pair_distance(items[i], items[j])[0], i, j)
               for i in range(len(items)) for j in range(i + 1, len(items)))
    i, j, d, _ = scene.closest_pair()
    assert (d, i, j) == best
    probe = cd.Sphere((0.5, -0.3, 0.2), 0.25)
    dist = [pair_distance(items[m], probe)[0] if not isinstance(items[m], cd.Circle)
            else cd.sphere_circle(probe, items[m]).distance for m in range(len(items))]
    order = sorted(range(len(items)), key=lambda m: (dist[m], m))
    near = scene.nearest(probe, 7)
    assert near.i.tolist() == order[:7]
    assert near.distance.tolist() == [dist[m] for m in order[:7]]
    w = scene.within(probe, 2.0)
    assert w.i.tolist() == [m for m in range(len(items)) if dist[m] <= 2.0]


def test_update_remove_add_groups():
    rng = np.random.default_rng(7)
    objects = random_scene(80, seed=7)
    scene = cd.Scene(objects)
    items = flat(objects)
    tori = objects[0]
    moved = cd.Torus(cd.Circle(tori.circle.center + rng.normal(scale=0.3, size=tori.circle.center.shape),
                               tori.circle.normal, tori.circle.radius), tori.tube_radius)
    scene.update(np.arange(len(tori)), moved)
    for m in range(len(tori)):
        items[m] = moved[m]
    scene.remove([3, 40])
    extra = cd.Sphere(rng.uniform(-3, 3, (5, 3)), 0.4)
    ids = scene.add(extra)
    assert ids.tolist() == list(range(len(items), len(items) + 5))
    items += [extra[m] for m in range(5)]
    scene.set_groups(ids=[0, 1, 2], group=[9, 9, 9])
    live = [m for m in range(len(items)) if m not in (3, 40)]
    want = set()
    for a in live:
        for b in live:
            if a < b and not (a < 3 and b < 3) and pair_distance(items[a], items[b])[0] <= 1.0:
                want.add((a, b))
    got = scene.pairs_within(1.0)
    assert set(zip(got.i.tolist(), got.j.tolist())) == want
    assert scene.stats["refits"] + scene.stats["rebuilds"] >= 1


def test_between():
    a, b = random_scene(60, seed=11), random_scene(60, seed=12)
    sa, sb = cd.Scene(a), cd.Scene(b)
    ia, ib = flat(a), flat(b)
    want = {(i, j) for i in range(len(ia)) for j in range(len(ib)) if pair_distance(ia[i], ib[j])[0] <= 0.3}
    got = sa.pairs_between(sb, 0.3)
    assert set(zip(got.i.tolist(), got.j.tolist())) == want
    best = min((pair_distance(ia[i], ib[j])[0], i, j) for i in range(len(ia)) for j in range(len(ib)))
    i, j, d, _ = sa.closest_pair_between(sb)
    assert (d, i, j) == best


def test_bad_input():
    t = cd.Torus(cd.Circle([[0, 0, 0], [3, 0, 0], [6, 0, 0]], [[0, 0, 1], [0, 0, 0], [0, 0, 1]], 1.0), 0.1)
    with pytest.raises(cd.CircleDistError) as e:
        cd.Scene(t)
    assert e.value.name == "CDIST_ERR_ZERO_VECTOR"
    scene = cd.Scene()
    with pytest.raises(cd.CircleDistError):
        scene.add(t)
    assert scene.object_status([0, 1, 2]).tolist() == [0, 3, 0]
    assert len(scene) == 3
    assert len(scene.pairs_within(10.0)) == 1
    with pytest.raises(cd.CircleDistError) as e:
        scene.pairs_within(math.nan)
    assert e.value.name == "CDIST_ERR_NOT_FINITE"
    with pytest.raises(cd.CircleDistError) as e:
        scene.remove([7])
    assert e.value.name == "CDIST_ERR_OUT_OF_RANGE"
    with pytest.raises(TypeError):
        cd.Scene([cd.Line((0, 0, 0), (1, 0, 0))])


def test_update_list_with_a_bad_array():
    """A list of arrays is one update: every valid entry of every array is applied, and the error
    names the array of the first invalid entry (as cdist_scene_update does for one array)."""
    def fresh():
        return cd.Scene([cd.Sphere((0, 0, 0), 1.0), cd.Sphere((10, 0, 0), 1.0), cd.Sphere((20, 0, 0), 1.0)])
    bad, good = cd.Sphere((math.nan, 0, 0), 1.0), cd.Sphere((1.5, 0, 0), 1.0)
    for ids, objects, where in (([1, 2], [bad, good], "objects[0]: "), ([2, 1], [good, bad], "objects[1]: ")):
        s = fresh()
        with pytest.raises(cd.CircleDistError) as e:
            s.update(ids, objects)
        assert where in str(e.value)
        i, j, d, _ = s.pairs_within(0.0)
        assert list(zip(i, j)) == [(0, 2)], (ids, list(zip(i, j)))
        assert d[0] == -0.5


# The interrupt may land in ctypes' own trampoline, which reports it as unraisable.
@pytest.mark.filterwarnings("ignore::pytest.PytestUnraisableExceptionWarning")
def test_interrupt():
    """Ctrl-C (a KeyboardInterrupt raised by a signal handler) stops a long pairs_within: the
    library returns to Python between blocks of answers."""
    import signal
    tori = random_scene(4 * 60000, seed=13, box=60.0)
    scene = cd.Scene(tori)
    scene.rebuild()

    def interrupt(signum, frame):
        raise KeyboardInterrupt

    old = signal.signal(signal.SIGALRM, interrupt)
    try:
        signal.setitimer(signal.ITIMER_REAL, 0.005)
        with pytest.raises(KeyboardInterrupt):
            scene.pairs_within(1.0)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
    assert len(scene.pairs_within(0.0)) >= 0  # the scene is still usable


def test_ctrl_c_not_unraisable():
    """SIGINT (Ctrl-C) during a long pairs_within: KeyboardInterrupt after the C call, never an
    exception raised inside the ctypes callback (which ctypes prints to stderr as unraisable),
    and the SIGINT handler is restored."""
    import os
    import signal
    import sys
    import threading
    scene = cd.Scene(random_scene(4 * 60000, seed=13, box=60.0))
    scene.rebuild()
    seen = []
    old_hook = sys.unraisablehook
    sys.unraisablehook = seen.append
    timer = threading.Timer(0.005, os.kill, (os.getpid(), signal.SIGINT))
    try:
        with pytest.raises(KeyboardInterrupt):
            timer.start()
            scene.pairs_within(1.0)
    finally:
        timer.cancel()
        sys.unraisablehook = old_hook
    assert not seen, [str(u.exc_value) for u in seen]
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_ctrl_c_handler_that_returns():
    """A SIGINT handler of the caller's that returns (does not raise) during a long pairs_within:
    it is run once after the C call, which it stopped, and the stopped query is an error (no
    partial list of pairs), not a KeyboardInterrupt; the handler is restored."""
    import os
    import signal
    import threading
    scene = cd.Scene(random_scene(4 * 60000, seed=13, box=60.0))
    scene.rebuild()
    calls = []

    def handler(signum, frame):
        calls.append(signum)

    old = signal.signal(signal.SIGINT, handler)
    timer = threading.Timer(0.005, os.kill, (os.getpid(), signal.SIGINT))
    try:
        with pytest.raises(cd.CircleDistError) as e:
            timer.start()
            scene.pairs_within(1.0)
        assert e.value.status == 9  # CDIST_ERR_CALLBACK_FAILED
        assert calls == [signal.SIGINT]
        assert signal.getsignal(signal.SIGINT) is handler
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, old)
