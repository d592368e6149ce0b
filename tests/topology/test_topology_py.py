# SPDX-License-Identifier: MIT
"""The Python forms of linking and time of impact (circledist.linking, link_details,
time_of_impact): scalars, broadcasting in one C call, bad entries, and the vectorised answers
equal to one-object calls."""
import os
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import circledist as cd  # noqa: E402


def test_linking_scalar_and_sign():
    a = cd.Circle((0, 0, 0), (0, 0, 1), 1)
    assert cd.linking(a, cd.Circle((1, 0, 0), (0, 1, 0), 1)) == 1
    assert cd.linking(a, cd.Circle((1, 0, 0), (0, -1, 0), 1)) == -1
    assert cd.linking(cd.Circle((1, 0, 0), (0, 1, 0), 1), a) == 1
    assert cd.linking(a, cd.Circle((3, 0, 0), (0, 1, 0), 1)) == 0
    assert cd.linking(a, cd.Circle((0, 0, 0), (1, 0, 0), 1)) == cd.LINK_TOUCHING


def test_linking_broadcast_and_bad_entry():
    a = cd.Circle((0, 0, 0), (0, 0, 1), 1)
    xs = np.array([1.0, 3.0, 1.0, 1.0])
    normals = np.array([[0, 1, 0], [0, 1, 0], [0, 0, 0], [0, -1, 0]], float)
    b = cd.Circle(np.stack([xs, 0 * xs, 0 * xs], 1), normals, 1.0)
    lk = cd.linking(a, b)
    assert lk.tolist() == [1, 0, cd.LINK_ERROR, -1]
    rec, status = cd.link_details(a, b)
    assert status.tolist() == [0, 0, 3, 0]
    assert np.isnan(rec["distance"][2])
    with pytest.raises(cd.CircleDistError):
        cd.linking(a, cd.Circle((1, 0, 0), (0, 0, 0), 1))
    with pytest.raises(TypeError):
        cd.linking(a, cd.Torus(a, 0.1))


def test_linking_tori():
    a = cd.Torus(cd.Circle((0, 0, 0), (0, 0, 1), 1), 0.1)
    b = cd.Torus(cd.Circle((1, 0, 0), (0, 1, 0), 1), np.array([0.1, 0.9]))
    rec, status = cd.link_details(a, b)
    assert status.tolist() == [0, 0]
    assert rec["linking"].tolist() == [1, cd.LINK_OVERLAP]
    assert rec["core_linking"].tolist() == [1, 1]


def test_time_of_impact_threading_and_clip():
    a = cd.Torus(cd.Circle((0, 0, 0), (0, 0, 1), 2.0), 0.2)
    x = np.array([0.0, 1.45])
    centers = np.stack([x, 0 * x, np.full(2, -3.0)], 1)
    b = cd.Torus(cd.Circle(centers, (0, 0, 1), 0.5), 0.1)
    rec, status = cd.time_of_impact(a, b, None, (centers, (0, 0, 6), (4 * np.pi, 0, 0)))
    assert status.tolist() == [0, 0]
    assert rec["state"].tolist() == [cd.TOI_NONE, cd.TOI_HIT]
    assert abs(rec["distance"][1]) <= 1e-9
    # The same entries one at a time.
    for i in range(2):
        bi = cd.Torus(cd.Circle(centers[i], (0, 0, 1), 0.5), 0.1)
        one, st = cd.time_of_impact(a, bi, None, (centers[i], (0, 0, 6), (4 * np.pi, 0, 0)))
        assert st == 0 and one["state"] == rec["state"][i] and one["t"] == rec["t"][i]


def test_time_of_impact_mixed_shapes_and_errors():
    s = cd.Sphere((0, 5, 0), 0.0)
    ring = cd.Torus(cd.Circle((0, 0, 0), (1, 0, 0), 1.0), 0.0)
    rec, status = cd.time_of_impact(s, ring, ((0, 5, 0), (0, -5, 0), (0, 0, 0)))
    assert status == 0 and rec["state"] == cd.TOI_HIT and abs(rec["t"] - 0.8) < 1e-6
    rec, status = cd.time_of_impact(s, ring, ((0, 5, 0), (0, -5, 0), (0, 0, 0)), tolerance=0.0)
    assert status == 7 and np.isnan(rec["t"])
    with pytest.raises(TypeError):
        cd.time_of_impact(s, cd.Circle((0, 0, 0), (0, 0, 1), 1))


def _chain(n, spacing=1.5, tube=0.1):
    x = np.arange(n) * spacing
    centers = np.stack([x, 0 * x, 0 * x], 1)
    normals = np.where((np.arange(n) % 2 == 0)[:, None], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0])
    return centers, normals, tube


def test_chain_invariants():
    centers, normals, tube = _chain(12)
    tori = cd.Torus(cd.Circle(centers, normals, 1.0), tube)
    inv = cd.chain_invariants(tori)
    assert inv["status_ok"] and inv["max_penetration"] == 0.0 and inv["worst_pair"] is None
    lk = inv["neighbour_linking"]
    assert set(np.abs(lk).tolist()) == {1}
    # Pull link 5 out of link 4 (move it far along z): the linking of pairs (4, 5), (5, 6) breaks.
    moved = centers.copy()
    moved[5, 2] += 5.0
    inv2 = cd.chain_invariants(cd.Torus(cd.Circle(moved, normals, 1.0), tube), lk)
    assert not inv2["linking_kept"]
    assert inv2["neighbour_linking"][4] == 0 and inv2["neighbour_linking"][5] == 0
    # Thick tubes: neighbours overlap, the deepest pair is reported, the cores stay linked.
    inv3 = cd.chain_invariants(cd.Torus(cd.Circle(centers, normals, 1.0), 0.4), lk)
    assert inv3["max_penetration"] > 0 and inv3["worst_pair"][1] == inv3["worst_pair"][0] + 1
    assert inv3["linking_kept"]
