# SPDX-License-Identifier: MIT
"""Scene.linked_pairs against the O(N^2) loop over the pair linking query (cdist_link_tori /
cdist_link_circles through circledist.link_details) on chain-mail-like, random and degenerate
scenes with 1 and 2 threads; Scene.time_of_impact against the minimum of the pair query over
every pair; and examples/chain.py at a small size, asserting its two invariants (no
interpenetration beyond the stated tolerance, every neighbour pair linked)."""
import pathlib

import numpy as np
import pytest

import circledist as cd

ROOT = pathlib.Path(__file__).resolve().parents[2]


def unit(v):
    v = np.asarray(v, float)
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def chain_mail(rows, cols, seed, jitter=0.05):
    """A 4-in-1 style mail: rings on a grid, tilted alternately, each threaded through its
    grid neighbours, with random jitter (some neighbours linked, some touching, some not)."""
    rng = np.random.default_rng(seed)
    centres, normals = [], []
    for r in range(rows):
        for c in range(cols):
            centres.append([1.4 * c, 1.4 * r, 0.0])
            normals.append([0.5 if (r + c) % 2 else -0.5, 0.3 * (-1) ** r, 1.0])
    centres = np.array(centres) + rng.normal(scale=jitter, size=(rows * cols, 3))
    normals = unit(np.array(normals) + rng.normal(scale=jitter, size=(rows * cols, 3)))
    radii = 1.0 + rng.uniform(-0.1, 0.1, rows * cols)
    tubes = rng.uniform(0.0, 0.12, rows * cols)
    return cd.Torus(cd.Circle(centres, normals, radii), tubes)


def brute_force(rings):
    """Every pair i < j with linking or core_linking not 0, from one batch of pair queries."""
    n = rings.shape[0]
    i, j = np.triu_indices(n, 1)
    cls = type(rings)
    rec, status = cd.link_details(cls.from_array(rings.data[i]), cls.from_array(rings.data[j]))
    assert np.all(status == 0)
    keep = (rec["linking"] != 0) | (rec["core_linking"] != 0)
    return i[keep], j[keep], rec[keep]


def check_scene(rings, threads, extra=None):
    objects = [rings] + ([extra] if extra is not None else [])
    with cd.Scene(objects, threads=threads) as s:
        got = s.linked_pairs()
    bi, bj, rec = brute_force(rings)
    assert np.array_equal(got.i, bi) and np.array_equal(got.j, bj)
    assert np.array_equal(got.linking, rec["linking"])
    assert np.array_equal(got.core_linking, rec["core_linking"])
    # bit for bit the pair query's distances
    assert np.array_equal(got.distance.view(np.int64), rec["distance"].view(np.int64))
    assert np.array_equal(got.core_distance.view(np.int64), rec["core_distance"].view(np.int64))
    assert np.all(got.status == 0)
    return got


@pytest.mark.parametrize("threads", [1, 2])
@pytest.mark.parametrize("seed", [1, 2, 3])
def test_chain_mail_scene(threads, seed):
    rings = chain_mail(9, 11, seed)
    got = check_scene(rings, threads)
    values = set(got.linking.tolist())
    assert {-1, 1} & values, "the scene should hold linked pairs"


@pytest.mark.parametrize("threads", [1, 2])
def test_random_circles_and_tori(threads):
    rng = np.random.default_rng(7)
    n = 300
    circles = cd.Circle(rng.uniform(-4, 4, (n, 3)), unit(rng.normal(size=(n, 3))), rng.uniform(0.2, 2.0, n))
    got = check_scene(circles, threads)
    assert len(got) > 10 and np.any(got.linking != 0)
    tori = cd.Torus(circles, rng.uniform(0, 0.3, n))
    got = check_scene(tori, threads)
    assert np.any(got.linking == cd.LINK_OVERLAP) and np.any(np.abs(got.linking) == 1)


def test_other_kinds_take_no_part():
    rings = chain_mail(3, 3, 5)
    spheres = cd.Sphere(rings.circle.center, 1.0)  # every sphere overlaps the rings
    check_scene(rings, 1, extra=spheres)


def test_degenerate_scenes():
    z = np.array([0.0, 0.0, 1.0])
    x = np.array([1.0, 0.0, 0.0])
    c = [
        ([0, 0, 0], z, 1.0),             # 0
        ([0, 0, 0], z, 1.0),             # 1 identical to 0: touching
        ([0, 0, 0], z, 0.5),             # 2 concentric coplanar: unlinked, apart
        ([1, 0, 0], x * 0 + [0, 1, 0], 1.0),  # 3 through 0's centre: linked with 0, 1, touches?
        ([2.0, 0, 0], z, 1.0),           # 4 coplanar, externally tangent to 0
        ([2.0 + 1e-13, 0, 0], z, 1.0),   # 5 tangent within touching range of 0 ... and 4
        ([10, 0, 0], z, 1e-9),           # 6 tiny
        ([10, 0, 5e-10], x, 1e3),        # 7 huge, through the tiny one's disk
        ([50, 50, 50], z, 0.0),          # 8 a point
    ]
    circles = cd.Circle(np.array([a for a, _, _ in c], float), unit(np.array([b for _, b, _ in c], float)),
                        np.array([r for _, _, r in c]))
    for threads in (1, 2):
        got = check_scene(circles, threads)
        pairs = set(zip(got.i.tolist(), got.j.tolist()))
        assert (0, 1) in pairs and (0, 4) in pairs and (0, 2) not in pairs and (8, 0) not in pairs
    tori = cd.Torus(circles, 0.0)
    check_scene(tori, 2)


def test_updates_and_bad_input():
    rings = chain_mail(4, 4, 9)
    with cd.Scene(rings) as s:
        first = s.linked_pairs()
        moved = chain_mail(4, 4, 10)
        s.update(np.arange(16), moved)
        again = s.linked_pairs()
        bi, bj, _ = brute_force(moved)
        assert np.array_equal(again.i, bi) and np.array_equal(again.j, bj)
        s.remove([0])
        keep = (again.i != 0)
        assert np.array_equal(s.linked_pairs().i, again.i[keep])
    assert len(first) > 0


def _chain_example():
    import importlib.util
    spec = importlib.util.spec_from_file_location("chain_example", ROOT / "examples" / "chain.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_chain_example_small(tmp_path, monkeypatch):
    """8 links, a few dozen frames: the run checks both invariants after every frame (it exits
    on a violation); the final state is checked once more with the single pair queries
    (cdist_torus_torus, cdist_link_tori)."""
    ex = _chain_example()
    monkeypatch.chdir(tmp_path)
    summary = ex.main(["--links", "8", "--frames", "24", "--quiet"])
    assert list(tmp_path.iterdir()) == []          # nothing written without --out
    assert summary["max_overlap"] <= summary["tolerance"] and summary["linked"]
    assert summary["substeps"] >= 24
    final, lk0 = summary["final"], summary["initial_linking"]
    n = final.shape[0]
    for a in range(n):
        for b in range(a + 1, n):
            ta, tb = final[a], final[b]
            assert cd.torus_torus(ta, tb).distance >= -ex.PENETRATION_TOL
            if b == a + 1:
                rec, st = cd.link_details(ta, tb)
                assert st == 0 and rec["core_linking"] == lk0[a]


def test_chain_example_invariants_checked():
    """The checks can fail: a chain with one link moved out of its neighbour, or pushed deep
    into it, is rejected."""
    ex = _chain_example()
    chain = ex.Chain(6)
    expected = cd.chain_invariants(chain.tori())["neighbour_linking"]
    assert np.all(np.abs(expected) == 1)
    depth, lk = ex.check(chain, expected, 0)
    assert depth <= ex.PENETRATION_TOL
    # pull link 3 sideways out of links 2 and 4: unlinked
    chain.x[3] += [0.0, 0.0, 5.0]
    with pytest.raises(SystemExit):
        ex.check(chain, expected, 1)
    chain.x[3] -= [0.0, 0.0, 5.0]
    # thread the last link through link 0 as well (its neighbours untouched): rejected
    far = ex.Chain(6)
    far.x[-1] = far.x[0] + [ex.PITCH, 0.0, 0.0]
    far.axis[-1] = far.axis[1]
    far.x[1] += [0.0, 0.0, 4.0]
    far.x[2] += [0.0, 0.0, 4.0]
    far_expected = cd.chain_invariants(far.tori())["neighbour_linking"]
    with pytest.raises(SystemExit, match="non-neighbours"):
        ex.check(far, far_expected, 3)
    # push link 3 towards link 2 by more than the tolerance
    chain.x[3, 0] -= ex.GAP + 2 * ex.PENETRATION_TOL
    with pytest.raises(SystemExit):
        ex.check(chain, expected, 2)


def test_chain_example_writes_animation(tmp_path):
    ex = _chain_example()
    ex.main(["--links", "4", "--frames", "4", "--quiet", "--out", str(tmp_path)])
    names = sorted(p.name for p in tmp_path.iterdir())
    assert "chain.png" in names and ("chain.gif" in names or any(n.startswith("chain_") for n in names))


# ---- time of impact of a moving scene ---------------------------------------------------------

def moving_scene(seed, n_tori=40, n_spheres=24, speed=3.0, spin=2.0):
    """Tori and spheres on a jittered grid (apart at t = 0), each with a random rigid motion."""
    rng = np.random.default_rng(seed)
    n = n_tori + n_spheres
    g = np.stack(np.meshgrid(np.arange(5), np.arange(5), np.arange(3), indexing="ij"), -1).reshape(-1, 3)
    centres = 4.0 * g[rng.permutation(len(g))[:n]] + rng.uniform(-0.3, 0.3, (n, 3))
    tori = cd.Torus(cd.Circle(centres[:n_tori], unit(rng.normal(size=(n_tori, 3))), rng.uniform(0.8, 1.5, n_tori)),
                    rng.uniform(0.05, 0.3, n_tori))
    spheres = cd.Sphere(centres[n_tori:], rng.uniform(0.2, 1.0, n_spheres))
    pivot = centres + rng.normal(scale=0.5, size=(n, 3))
    motions = (pivot, rng.normal(scale=speed, size=(n, 3)), rng.normal(scale=spin, size=(n, 3)))
    return tori, spheres, motions


def brute_toi(tori, spheres, motions, target, skip=()):
    """The earliest (t, i, j) over every pair, from the pair query (circledist.time_of_impact)."""
    nt = tori.shape[0]
    objs = [(tori, 0), (spheres, nt)]
    best = (np.inf, -1, -1, None)
    for ga, (A, oa) in enumerate(objs):
        for gb, (B, ob) in enumerate(objs):
            if gb < ga:
                continue
            na, nb = A.shape[0], B.shape[0]
            if ga == gb:
                ia, ib = np.triu_indices(na, 1)
            else:
                ia, ib = [x.ravel() for x in np.meshgrid(np.arange(na), np.arange(nb), indexing="ij")]
            i, j = ia + oa, ib + ob
            cls_a, cls_b = type(A), type(B)
            rec, st = cd.time_of_impact(cls_a.from_array(A.data[ia]), cls_b.from_array(B.data[ib]),
                                        tuple(m[i] for m in motions), tuple(m[j] for m in motions),
                                        target=target, tolerance=1e-9)
            assert np.all(st == 0)
            for k in np.nonzero(rec["state"] != cd.TOI_NONE)[0]:
                if (int(i[k]), int(j[k])) in skip:
                    continue
                key = (float(rec["t"][k]), int(i[k]), int(j[k]))
                if key < best[:3]:
                    best = key + (rec[k],)
    return best


@pytest.mark.parametrize("threads", [1, 2])
@pytest.mark.parametrize("seed", [11, 12, 13, 14])
@pytest.mark.parametrize("speed, spin", [(3.0, 2.0), (0.8, 0.4)])
def test_scene_time_of_impact(threads, seed, speed, spin):
    """Fast motions (nearly every pair in reach) and slow ones (about a quarter of the pairs
    in reach): the scene's earliest impact is the brute force's, bit for bit."""
    tori, spheres, motions = moving_scene(seed, speed=speed, spin=spin)
    for target in (0.0, -0.05, 0.2):
        t, i, j, rec = brute_toi(tori, spheres, motions, target)
        with cd.Scene([tori, spheres], threads=threads) as s:
            gi, gj, got = s.time_of_impact(motions, target=target, tolerance=1e-9)
        assert (gi, gj) == (i, j), (target, gi, gj, i, j)
        if i >= 0:
            assert got["t"] == t and got["state"] == rec["state"] and got["distance"] == rec["distance"]
        else:
            assert got["state"] == cd.TOI_NONE


def test_scene_time_of_impact_none_still_and_chain():
    tori, spheres, motions = moving_scene(21, speed=0.01, spin=0.01)
    with cd.Scene([tori, spheres]) as s:
        i, j, rec = s.time_of_impact(motions)
        assert (i, j) == (-1, -1) and rec["state"] == cd.TOI_NONE and rec["t"] == 1.0
        assert s.time_of_impact(None)[:2] == (-1, -1)
    # a chain of linked tori moving as one rigid body: only neighbours are in contact at 0;
    # with the chain filter they are skipped and nothing else can hit
    ex = _chain_example()
    ch = ex.Chain(10)
    tori = ch.tori()
    n = tori.shape[0]
    rigid = (np.zeros((n, 3)), np.tile([3.0, -2.0, 1.0], (n, 1)), np.tile([0.4, 0.2, 0.9], (n, 1)))
    with cd.Scene(tori) as s:
        assert s.time_of_impact(rigid, target=-1e-3)[:2] == (-1, -1)
        s.set_groups(chain=np.ones(n, dtype=np.uint32))
        assert s.time_of_impact(rigid, target=0.05)[:2] == (-1, -1)
        s.set_groups(chain=np.zeros(n, dtype=np.uint32))
        i, j, rec = s.time_of_impact(rigid, target=0.05)
        assert j == i + 1 and rec["t"] == 0.0


def test_scene_time_of_impact_bad_input():
    tori, spheres, motions = moving_scene(5)
    with cd.Scene([tori, spheres]) as s:
        with pytest.raises(cd.CircleDistError):
            s.time_of_impact(motions, tolerance=0.0)
        with pytest.raises(cd.CircleDistError):
            s.time_of_impact(motions, target=np.nan)
        bad = (motions[0], motions[1].copy(), motions[2])
        bad[1][3, 0] = np.inf
        with pytest.raises(cd.CircleDistError):
            s.time_of_impact(bad)


@pytest.mark.parametrize("threads", [1, 2])
def test_scene_time_of_impact_at_the_edge_of_reach(threads):
    """Pairs that meet just before t = 1, moving straight at each other or swinging a far rim
    into reach: their distance at 0 is within a hair of the reach bound, so a reach any
    smaller would drop them."""
    gap = 2.0
    for shrink in (1e-9, 1e-6, 1e-3):
        # sphere 1 translates onto sphere 0: meets at t = 1 - shrink
        spheres = cd.Sphere([[0.0, 0, 0], [1.0 + gap, 0, 0]], 0.5)
        tori = cd.Torus(cd.Circle([[0.0, 40.0, 0]], [0.0, 0.0, 1.0], 1.0), 0.1)
        ang = np.pi / 2 / (1 - shrink)       # the torus turns about a pivot 5 from its centre
        pivot = np.array([0.0, 45.0, 0.0])
        sph_near = cd.Sphere([[6.0, 45.0, 0.0]], 0.2)   # where the far rim arrives at t = 1
        motions = (np.array([[0.0, 0, 0], [1.0 + gap, 0, 0], pivot, [6.0, 45.0, 0.0]]),
                   np.array([[0.0, 0, 0], [-gap / (1 - shrink), 0, 0], [0.0, 0, 0], [0.0, 0, 0]]),
                   np.array([[0.0, 0, 0], [0.0, 0, 0], [0.0, 0.0, ang], [0.0, 0, 0]]))
        objs = [spheres, tori, sph_near]
        with cd.Scene(objs, threads=threads) as s:
            i, j, rec = s.time_of_impact(motions, tolerance=1e-12)
            assert rec["state"] == cd.TOI_HIT and (i, j) in ((0, 1), (2, 3)), (i, j, rec["t"])
            assert rec["t"] < 1.0
            # the brute force over the same pairs
            a = cd.Sphere.from_array(np.concatenate([spheres.data, sph_near.data])[[0]])
            b = cd.Sphere.from_array(np.concatenate([spheres.data, sph_near.data])[[1]])
            r01, _ = cd.time_of_impact(a, b, tuple(m[[0]] for m in motions), tuple(m[[1]] for m in motions),
                                       tolerance=1e-12)
            r23, _ = cd.time_of_impact(tori, sph_near, tuple(m[[2]] for m in motions),
                                       tuple(m[[3]] for m in motions), tolerance=1e-12)
            times = {(0, 1): r01["t"][0] if r01["state"][0] else np.inf,
                     (2, 3): r23["t"][0] if r23["state"][0] else np.inf}
            assert np.isfinite(times[(0, 1)]) and np.isfinite(times[(2, 3)])
            assert rec["t"] == min(times.values()) and times[(i, j)] == rec["t"]
            # each pair alone (the other one held still) is found as well
            still = tuple(m.copy() for m in motions)
            still[1][1] = 0.0
            i2, j2, rec2 = s.time_of_impact(still, tolerance=1e-12)
            assert (i2, j2) == (2, 3) and rec2["t"] == times[(2, 3)]
            still = tuple(m.copy() for m in motions)
            still[2][2] = 0.0
            i2, j2, rec2 = s.time_of_impact(still, tolerance=1e-12)
            assert (i2, j2) == (0, 1) and rec2["t"] == times[(0, 1)]
