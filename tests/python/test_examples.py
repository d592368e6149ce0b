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


def _disk_samples(c, n, r, k=30):
    """Points of a disk: k rings of k points (polar grid), for a sampled brute force."""
    u = np.cross(n, [1.0, 0, 0] if abs(n[0]) < 0.9 else [0, 1.0, 0])
    u /= np.linalg.norm(u)
    v = np.cross(n, u)
    rr, aa = np.meshgrid(np.linspace(0, r, k), np.linspace(-np.pi, np.pi, 2 * k, endpoint=False))
    return c + (rr * np.cos(aa)).reshape(-1, 1) * u + (rr * np.sin(aa)).reshape(-1, 1) * v


def _check_rings(pr, res):
    labels, c, n, r = res["labels"], res["centres"], res["normals"], res["radii"]
    assert len(labels) == 80 and np.allclose(np.linalg.norm(n, axis=1), 1)
    index = {lab: k for k, lab in enumerate(labels)}
    assert res["pairs"] and all(p[2] <= 7.5 for p in res["pairs"])
    for a, b, d, dc, _, _, _, pts in res["pairs"][:12]:
        i, j = index[a], index[b]
        pa, pb = _disk_samples(c[i], n[i], r[i]), _disk_samples(c[j], n[j], r[j])
        brute = np.min(np.linalg.norm(pa[:, None, :] - pb[None, :, :], axis=2))
        # the exact distance lies below every sampled pair and within the grid's resolution of it
        assert d <= brute + 1e-12 and brute - d < 0.2, (a, b, d, brute)
        assert abs(np.linalg.norm(pts[1] - pts[0]) - d) < 1e-9 and d <= dc
    # every pair of different residues closer than 7.5 is listed (no pair lost)
    listed = {(p[0], p[1]) for p in res["pairs"]}
    for i in range(len(labels)):
        for j in range(i + 1, len(labels)):
            if pr.residue(labels[i]) == pr.residue(labels[j]):
                continue
            lower = np.linalg.norm(c[i] - c[j]) - r[i] - r[j]   # disks are at least this far apart
            if lower < 7.0 and (labels[i], labels[j]) not in listed:
                pa, pb = _disk_samples(c[i], n[i], r[i], 12), _disk_samples(c[j], n[j], r[j], 12)
                assert np.min(np.linalg.norm(pa[:, None, :] - pb[None, :, :], axis=2)) > 7.5 - 1e-9
    for row in res["missed"]:
        assert row[2] <= pr.CONTACT and not row[6]
    for row in res["extra"]:
        assert row[2] > pr.CONTACT and row[6]


def test_protein_rings_shipped_table():
    import io
    pr = _example("protein_rings")
    out = io.StringIO()
    res = pr.analyse(pdb="/nonexistent/1tii.pdb", out=out)
    assert "using the shipped ring table" in out.getvalue() and res["pierced"] is None
    _check_rings(pr, res)


def test_protein_rings_from_pdb(tmp_path):
    import io
    pr = _example("protein_rings")
    if not os.path.exists(pr.DEFAULT_PDB):
        pytest.skip("%s absent (Debian's pymol-data not installed): the shipped table is tested alone" % pr.DEFAULT_PDB)
    table = tmp_path / "rings.tsv"
    res = pr.analyse(pdb=pr.DEFAULT_PDB, out=io.StringIO(), table=str(table))
    _check_rings(pr, res)
    # the shipped table is what the PDB file gives (its provenance)
    shipped = pr.read_table(pr.SHIPPED_TABLE)
    made = pr.read_table(str(table))
    assert shipped[0] == made[0] and all(np.array_equal(x, y) for x, y in zip(shipped[1:], made[1:]))
    assert res["pierced"] == []   # a well-formed structure: no bond passes through a ring
    # the piercing check finds a bond through a ring's face and none beside it
    atoms = pr.read_pdb(pr.DEFAULT_PDB)
    labels, members, c, n, r = pr.ring_disks(atoms)
    k = 7
    through = [("Z", "1", "XXX", "P1", "C", tuple(c[k] - 0.7 * n[k])), ("Z", "1", "XXX", "P2", "C", tuple(c[k] + 0.7 * n[k]))]
    beside = [("Z", "2", "XXX", "Q1", "C", tuple(c[k] + 1.6 * r[k] * np.cross(n[k], [0, 0, 1]) / np.linalg.norm(np.cross(n[k], [0, 0, 1])) + s * 0.7 * n[k]))
              for s in (-1, 1)]
    found, _ = pr.pierced(atoms + through + beside, members, c, n, r)
    got = {(ring, atoms_i) for ring, atoms_i, _, _ in found}
    assert got == {(k, len(atoms))}, found
