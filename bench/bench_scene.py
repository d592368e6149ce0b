#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""circledist.Scene on the chain-mail sheet of bench_scene.c (the weave of
examples/dask_chainmail.py): build + all pairs with clearance <= 0.1 R, CPU seconds of the
process (min of repeats), to compare with bench_scene's C numbers.

    CIRCLEDIST_LIBRARY=build/libcircledist.so.1 PYTHONPATH=python python3 bench/bench_scene.py [N] [reps]
"""
import math
import sys
import time

import numpy as np

import circledist as cd

RADIUS, WIRE, SPACING_X, SPACING_Y, TILT, JITTER = 1.0, 0.11, 2.4, 1.4, math.radians(50), 0.03


def sheet(n, seed=1):
    rng = np.random.default_rng(seed)
    cols = int(math.ceil(math.sqrt(n)))
    k = np.arange(n)
    row, col = k // cols, k % cols
    c = np.stack([SPACING_X * (col + 0.5 * (row % 2)), SPACING_Y * row, np.zeros(n)], axis=1)
    c += rng.normal(scale=JITTER, size=(n, 3))
    s = np.where(row % 2 == 0, 1.0, -1.0)
    nrm = np.stack([np.zeros(n), s * math.sin(TILT), np.full(n, math.cos(TILT))], axis=1)
    nrm += rng.normal(scale=JITTER, size=(n, 3))
    nrm /= np.linalg.norm(nrm, axis=1)[:, None]
    radius = RADIUS * (1 + rng.normal(scale=JITTER / 3, size=n))
    return cd.Torus(cd.Circle(c, nrm, radius), WIRE)


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 10 ** 6
    reps = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    tori = sheet(n)
    best = math.inf
    for _ in range(reps):
        t0 = time.process_time()
        scene = cd.Scene(tori)
        scene.rebuild()
        pairs = scene.pairs_within(0.1 * RADIUS)
        best = min(best, time.process_time() - t0)
        scene.close()
    print("python Scene: %d tori, %d pairs within 0.1 R: build + query %.3f s CPU (min of %d)"
          % (n, len(pairs), best, reps))


if __name__ == "__main__":
    main()
