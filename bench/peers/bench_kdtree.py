#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""circledist.Scene against scipy.spatial.cKDTree.query_pairs on the ring centres followed by our
batch (circle_circle on every candidate pair, full results, then the clearance filter), on the
chain-mail sheet of bench_scene.py; all pairs with clearance <= 0.1 R; CPU seconds, same run.

    CIRCLEDIST_LIBRARY=build/libcircledist.so.1 PYTHONPATH=python python3 bench/peers/bench_kdtree.py [N] [reps]
"""
import os
import sys
import time

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import circledist as cd  # noqa: E402
from bench_scene import RADIUS, WIRE, sheet  # noqa: E402


def kdtree_pairs(tori, delta, screen):
    """Candidates from the tree, then full answers (screen: a distance-only batch first, full
    answers for the close ones only, as examples/dask_chainmail.py does)."""
    c = tori.circle
    reach = 2 * (float(np.max(c.radius)) + WIRE) + delta   # bounding spheres of two rings
    ij = cKDTree(c.center).query_pairs(reach, output_type="ndarray")
    i, j = ij[:, 0], ij[:, 1]
    a, b = cd.Circle.from_array(c.data[i]), cd.Circle.from_array(c.data[j])
    if screen:
        d = cd.circle_circle(a, b, distance_only=True).distance
        close = np.flatnonzero(d - 2 * WIRE <= delta + 1e-9)
        a, b = a[close], b[close]
    r = cd.circle_circle(a, b)
    keep = r.distance - WIRE - WIRE <= delta
    return len(i), np.count_nonzero(keep)


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 10 ** 5
    reps = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    tori = sheet(n)
    delta = 0.1 * RADIUS
    ours = kd = kds = np.inf
    for _ in range(reps):
        t0 = time.process_time()
        scene = cd.Scene(tori)
        pairs = scene.pairs_within(delta)
        ours = min(ours, time.process_time() - t0)
        scene.close()
        t0 = time.process_time()
        candidates, kpairs = kdtree_pairs(tori, delta, False)
        kd = min(kd, time.process_time() - t0)
        t0 = time.process_time()
        kdtree_pairs(tori, delta, True)
        kds = min(kds, time.process_time() - t0)
    print("%d tori, clearance <= 0.1 R: Scene %.3f s (%d pairs); cKDTree.query_pairs (%d candidates) + "
          "full batch %.3f s (%d pairs, %.1fx), + distance-only screen then full batch %.3f s (%.1fx)"
          % (n, ours, len(pairs), candidates, kd, kpairs, kd / ours, kds, kds / ours))


if __name__ == "__main__":
    main()
