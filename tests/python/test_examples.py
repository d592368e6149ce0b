# SPDX-License-Identifier: MIT
"""The Python examples at small size: examples/torus_chain.py (clearances against a brute force
over sampled core circles, the picture written) and examples/dask_chainmail.py (a Dask
LocalCluster gives the single-process scene's answer bit for bit; the partitions own each pair
once; both against all pairs through the circle-circle query)."""
import importlib.util
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


def _all_close_pairs(rings, delta, tol=1e-9):
    """Reference without scenes or partitions: every pair through the vectorised circle-circle
    query, clearance = core distance - both wires. Returns (pairs surely within delta,
    pairs possibly within delta, clearance of each pair)."""
    data = rings.data.reshape(-1, 8)
    i, j = np.triu_indices(len(data), 1)
    d = cd.circle_circle(cd.Circle.from_array(data[i, :7]), cd.Circle.from_array(data[j, :7]),
                         distance_only=True).distance
    clear = d - data[i, 7] - data[j, 7]
    pairs = lambda m: set(zip(i[m].tolist(), j[m].tolist()))
    return pairs(clear <= delta - tol), pairs(clear <= delta + tol), dict(zip(zip(i.tolist(), j.tolist()), clear))


def _check_against_reference(res, rings, delta):
    sure, maybe, clear = _all_close_pairs(rings, delta)
    got = list(zip(res.i.tolist(), res.j.tolist()))
    assert len(set(got)) == len(got)                       # each pair once
    assert sure <= set(got) <= maybe
    assert np.allclose(res.distance, [clear[p] for p in got], rtol=0, atol=1e-9)


def test_dask_chainmail_matches_single_process():
    dc = _example("dask_chainmail")
    from dask.distributed import Client
    rings, delta = dc.make_sheet(30, 24), 0.1
    single = dc.run(rings, delta)
    assert len(single) > 100 and np.any(single.distance < 0)   # the jitter makes collisions
    with dc.local_cluster(2, 1, processes=False) as cl, Client(cl) as client:
        timings = {}
        dist = dc.run(rings, delta, client=client, per_task=60, timings=timings)
    assert timings["tasks"] >= 8                           # halos cross several boxes
    assert dc.same_pairs(single, dist)                     # same (i, j), distances, points, bit for bit
    assert np.array_equal(single.i, dist.i) and np.array_equal(single.distance, dist.distance)
    _check_against_reference(single, rings, delta)


@pytest.mark.parametrize("shape", ["cloud", "chain"])
def test_dask_chainmail_partitions_own_each_pair_once(shape):
    """Partitions of data that is not a sheet: a 3D cloud of rings of mixed sizes (boxes in
    three axes, halos wider than some boxes) and a long chain (slabs); each partition answered
    here, as a task would, and merged."""
    dc = _example("dask_chainmail")
    rng = np.random.default_rng(7)
    n = 500
    if shape == "cloud":
        c = rng.uniform(0, 16, (n, 3)) * [1, 1, 0.6]
        r = np.where(rng.random(n) < 0.1, 1.5, rng.uniform(0.05, 0.6, n))
    else:
        c = np.stack([np.arange(n) * 0.9, rng.normal(0, 0.05, n), rng.normal(0, 0.05, n)], axis=1)
        r = np.full(n, 0.5)
    normal = rng.normal(size=(n, 3))
    rings = cd.Torus(cd.Circle(c, normal / np.linalg.norm(normal, axis=1)[:, None], r),
                     rng.uniform(0, 0.1, n))
    delta = 0.2
    single = dc.run(rings, delta)
    parts, edges = dc.plan(rings, delta, per_task=40)
    assert len(parts) >= 8 and (shape == "chain") == (sum(len(e) > 0 for e in edges) == 1)
    owned = np.concatenate([ids[~halo] for ids, halo in parts])
    assert np.array_equal(np.sort(owned), np.arange(n))    # every ring owned by one partition
    rows = rings.data.reshape(-1, 8)
    merged = dc.combine([dc.screen_partition((rows[ids], ids, halo), delta) for ids, halo in parts])
    assert dc.same_pairs(single, merged)
    _check_against_reference(single, rings, delta)


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
