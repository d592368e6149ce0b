# SPDX-License-Identifier: MIT
"""The Python examples at small size: examples/torus_chain.py (clearances against a brute force
over sampled core circles, the picture written) and examples/dask_chainmail.py (a Dask
LocalCluster gives exactly the single-process answer; the spatial grid misses no pair)."""
import importlib.util
import itertools
import os

import numpy as np
import pytest

import circledist as cd
from conftest import SOURCE_ROOT


def _example(name):
    spec = importlib.util.spec_from_file_location(name, os.path.join(SOURCE_ROOT, "examples", name + ".py"))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_torus_chain_writes_nothing_unless_asked(tmp_path, monkeypatch):
    tc = _example("torus_chain")
    monkeypatch.chdir(tmp_path)
    tc.main(["--rings", "3"])
    assert list(tmp_path.iterdir()) == []


def test_torus_chain(tmp_path):
    tc = _example("torus_chain")
    png = tmp_path / "chain.png"
    clearance, res = tc.main(["--rings", "5", "--png", str(png)])
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and png.stat().st_size > 20000
    cores, tube = tc.make_chain(5)
    a = np.linspace(-np.pi, np.pi, 3001)
    for k in range(4):
        p = cd.circle_point(cores[k], a)
        q = cd.circle_point(cores[k + 1], a)
        # brute force, refined: the sampled minimum is within (spacing * R)^2 / ... of the true one
        brute = np.min(np.linalg.norm(p[:, None, :] - q[None, ::3, :], axis=2))
        assert res.distance[k] <= brute + 1e-12 and res.distance[k] == pytest.approx(brute, abs=5e-3)
        assert clearance[k] == res.distance[k] - tube[k] - tube[k + 1]
    seg = tc.tube_segments(res, tube)
    assert np.allclose(np.linalg.norm(seg[:, 1] - seg[:, 0], axis=1), clearance, atol=1e-12)


def test_dask_chainmail_matches_single_process():
    dc = _example("dask_chainmail")
    from dask.distributed import Client, LocalCluster
    cols, rows, parts, margin = 30, 24, 5, 0.05
    single = dc.run(cols, rows, parts, margin)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=False, dashboard_address=None) as cl, \
            Client(cl) as client:
        dist = dc.run(cols, rows, parts, margin, client=client)
    for k in ("i", "j", "clearance", "points", "num_pairs"):
        assert np.array_equal(single[k], dist[k]), k
    assert single["candidates"] == dist["candidates"] and len(single["i"]) > 10
    assert np.any(single["clearance"] < 0)                 # the jitter makes some collisions
    # completeness, without the grid or the partitions: every pair of the sheet
    ids, rings, wire = dc.make_rings(cols, 0, rows)
    i, j = (np.array(x) for x in zip(*itertools.combinations(range(len(ids)), 2)))
    d = cd.circle_circle(cd.Circle.from_array(rings.data[i]), cd.Circle.from_array(rings.data[j]),
                         distance_only=True).distance
    close = d - wire[i] - wire[j] < margin
    assert np.array_equal(i[close], single["i"]) and np.array_equal(j[close], single["j"])


def test_candidate_grid_against_all_pairs():
    dc = _example("dask_chainmail")
    rng = np.random.default_rng(5)
    pts = rng.uniform(0, 10, (400, 3))
    i, j = dc.candidate_pairs(pts, 1.3, 300)
    got = set(zip(i.tolist(), j.tolist()))
    assert all(a < b and a < 300 for a, b in got) and len(got) == len(i)
    dist = np.linalg.norm(pts[:, None] - pts[None], axis=2)
    want = {(a, b) for a, b in zip(*np.nonzero(dist < 1.3)) if a < b and a < 300}
    assert want <= got
