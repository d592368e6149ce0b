#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Chain-mail screen with Dask: every pair of nearby rings of a sheet of up to 10^6 rings,
answered by the vectorised circledist calls inside Dask tasks.

The sheet is a lattice of `rows` x `cols` rings (a "4 in 1" weave: rows offset by half a
spacing and tilted alternately), each a torus: core circle of radius ~R plus a wire (tube) of
radius r, with random manufacturing jitter of positions, tilts and sizes. The screen reports
every pair of rings whose wires come closer than `--margin` (clearance = core-circle distance
minus the two wire radii; negative = the wires collide), the closest points of each, and the
smallest clearance.

How the work is split: the sheet is cut into partitions of whole rows. A task regenerates its
rings (plus the halo rows that can reach them: the generator is deterministic, so no ring data
is shipped), finds candidate pairs with a spatial grid (cells of the interaction reach, 27
neighbour cells, pairs (i, j) owned by the partition of i < j, filtered by bounding spheres),
screens them with one `circle_circle(..., distance_only=True)` call and answers the close ones
with one full `circle_circle` call. Only the close pairs travel back.

    python3 examples/dask_chainmail.py --rings 1000000 --partitions 64       # LocalCluster
    python3 examples/dask_chainmail.py --workers 4 --threads 1 ...           # its size
    python3 examples/dask_chainmail.py --scheduler tcp://host:8786 ...       # any cluster
    python3 examples/dask_chainmail.py --single ...                          # no Dask

Workers of a remote cluster need numpy, circledist and libcircledist installed (the task
functions travel with the tasks). Each task uses its thread's default circledist.Query, and
the C calls release the GIL, so threaded workers run queries in parallel too.

Scaling, measured on the development machine: 2 cores shared with other jobs (load average
5-16 during the runs, so the numbers are rough), release build, `--scaling --workers N`:

    rings      candidate pairs  single process  1 worker   2 workers  3 workers
    10^5       0.2 million      1.65-1.88 s     1.46-2.82  1.29-2.69  0.89-1.91 s
    10^6       2.0 million      17.9 s          13.8 s     16.0 s     (load ~12)
    10^6       2.0 million      14.1 s          14.1 s     9.2 s      (load ~6)

In a task about 40% of the time is the circledist calls (screen of every candidate pair with
distance_only, then full answers for the ~9% closer than the margin: 1.8-4.4 us per
candidate pair, depending on the load) and 60% numpy work (ring generation, grid, gathers).
Tasks are independent (no ring data is shipped; results are the close pairs only), so
throughput grows with workers while there are idle cores: 2 workers gave 1.5x (142k -> 217k
candidate pairs/s) when the machine was moderately loaded, nothing when it was saturated by
other jobs. Expect near-linear scaling up to the core count on an idle machine; use more
partitions than workers (4-8 per worker) to balance the load.
"""
import argparse
import itertools
import math
import time

import numpy as np

import circledist as cd

#: Geometry of the weave (units of the ring radius).
RADIUS, WIRE, SPACING_X, SPACING_Y, TILT = 1.0, 0.11, 2.4, 1.4, math.radians(50)


def make_rings(cols, row0, row1, seed=1, jitter=0.03):
    """Rings of lattice rows row0..row1-1 (row-major ids row * cols + col): (ids, Circle,
    wire radii). Row by row from its own seed, so any range of rows is reproducible alone."""
    centers, normals, radius, wire = [], [], [], []
    for row in range(row0, row1):
        rng = np.random.default_rng([seed, row])
        c = np.zeros((cols, 3))
        c[:, 0] = SPACING_X * (np.arange(cols) + 0.5 * (row % 2))
        c[:, 1] = SPACING_Y * row
        s = 1.0 if row % 2 == 0 else -1.0
        n = np.tile([0.0, s * math.sin(TILT), math.cos(TILT)], (cols, 1))
        c += rng.normal(scale=jitter, size=(cols, 3))
        n += rng.normal(scale=jitter, size=(cols, 3))
        centers.append(c)
        normals.append(n / np.linalg.norm(n, axis=1)[:, None])
        radius.append(RADIUS * (1 + rng.normal(scale=jitter / 3, size=cols)))
        wire.append(np.full(cols, WIRE))
    ids = np.arange(row0 * cols, row1 * cols)
    if not centers:
        return ids, cd.Circle.from_array(np.empty((0, 7))), np.empty(0)
    return (ids, cd.Circle(np.concatenate(centers), np.concatenate(normals), np.concatenate(radius)),
            np.concatenate(wire))


def candidate_pairs(centers, reach, owned):
    """Index pairs (i, j), i < j, i < owned, whose centres may be closer than `reach`: a uniform
    grid of cell size `reach`, each point against the points of its 27 neighbour cells (no
    Python loop over points; the loop is over the 9 neighbour columns of cells)."""
    n = len(centers)
    if n == 0:
        return np.empty(0, np.int64), np.empty(0, np.int64)
    cell = np.floor(centers / reach).astype(np.int64)
    cell -= cell.min(axis=0) - 1
    dims = cell.max(axis=0) + 2
    key = (cell[:, 0] * dims[1] + cell[:, 1]) * dims[2] + cell[:, 2]
    order = np.argsort(key, kind="stable")
    skey = key[order]
    out_i, out_j = [], []
    for dx, dy in itertools.product((-1, 0, 1), repeat=2):
        # the three cells dz = -1, 0, 1 of a column are one contiguous range of keys
        nkey = key[:owned] + (dx * dims[1] + dy) * dims[2]
        lo = np.searchsorted(skey, nkey - 1, "left")
        cnt = np.searchsorted(skey, nkey + 1, "right") - lo
        total = int(cnt.sum())
        if total == 0:
            continue
        start = np.cumsum(cnt) - cnt
        i = np.repeat(np.arange(owned), cnt)
        j = order[np.repeat(lo - start, cnt) + np.arange(total)]
        keep = i < j
        out_i.append(i[keep])
        out_j.append(j[keep])
    return np.concatenate(out_i), np.concatenate(out_j)


def screen_rows(cols, rows, row0, row1, margin, seed=1, threads=1):
    """One task: the pairs owned by rows row0..row1-1 whose wires come closer than margin."""
    reach = 2 * (RADIUS * 1.2 + WIRE)                      # bounding spheres (radius jitter < 20%)
    halo = int(math.ceil((reach + margin) / SPACING_Y)) + 1
    ids, rings, wire = make_rings(cols, row0, min(rows, row1 + halo), seed)
    owned = (row1 - row0) * cols
    i, j = candidate_pairs(rings.center, reach + margin, owned)
    sep = np.linalg.norm(rings.center[i] - rings.center[j], axis=1)
    keep = sep <= rings.radius[i] + rings.radius[j] + wire[i] + wire[j] + margin
    i, j = i[keep], j[keep]
    a, b = cd.Circle.from_array(rings.data[i]), cd.Circle.from_array(rings.data[j])
    t0 = time.perf_counter()
    screen = cd.circle_circle(a, b, distance_only=True, threads=threads)
    clearance = screen.distance - wire[i] - wire[j]
    close = np.flatnonzero(clearance < margin)
    full = cd.circle_circle(a[close], b[close], threads=threads)
    seconds = time.perf_counter() - t0
    if not (np.all(screen.ok) and np.all(full.ok)):
        raise RuntimeError("bad rings in rows %d..%d" % (row0, row1))
    return {"candidates": len(i), "query_seconds": seconds,
            "i": ids[i[close]], "j": ids[j[close]], "clearance": clearance[close],
            "points": full.points[:, 0].copy(), "num_pairs": full.num_pairs.copy()}


def partitions(rows, parts):
    edges = np.linspace(0, rows, max(1, min(parts, rows)) + 1).round().astype(int)
    return [(int(a), int(b)) for a, b in zip(edges[:-1], edges[1:]) if b > a]


def combine(parts):
    """Merge task outputs into one report, sorted by (i, j)."""
    out = {k: np.concatenate([p[k] for p in parts]) for k in ("i", "j", "clearance", "points", "num_pairs")}
    order = np.lexsort((out["j"], out["i"]))
    out = {k: v[order] for k, v in out.items()}
    out["candidates"] = sum(p["candidates"] for p in parts)
    out["query_seconds"] = sum(p["query_seconds"] for p in parts)
    return out


def run(cols, rows, parts=8, margin=0.05, seed=1, client=None, threads=1):
    """The whole screen: on a Dask client when given, else one partition after another here."""
    blocks = partitions(rows, parts)
    if client is None:
        results = [screen_rows(cols, rows, r0, r1, margin, seed, threads) for r0, r1 in blocks]
    else:
        futures = [client.submit(screen_rows, cols, rows, r0, r1, margin, seed, threads, pure=False)
                   for r0, r1 in blocks]
        results = client.gather(futures)
    return combine(results)


def report(res, seconds, n):
    col = res["clearance"] < 0
    print("%d rings, %d candidate pairs, %d closer than the margin, %d colliding" % (
        n, res["candidates"], len(res["i"]), int(col.sum())))
    if len(res["i"]):
        k = int(np.argmin(res["clearance"]))
        print("smallest clearance %.6g between rings %d and %d at %s / %s" % (
            res["clearance"][k], res["i"][k], res["j"][k], res["points"][k, 0], res["points"][k, 1]))
    print("wall %.2f s, %.0f candidate pairs/s (query time summed over tasks %.2f s)" % (
        seconds, res["candidates"] / seconds, res["query_seconds"]))


def timed_run(args, cols, rows, client, label=None):
    """Run on the client; print the report, or one timing line when label is given."""
    client.run(lambda: None)                      # workers up before timing
    t = time.perf_counter()
    res = run(cols, rows, args.partitions, args.margin, args.seed, client)
    seconds = time.perf_counter() - t
    if label:
        print("%s%.2f s, %.0f candidate pairs/s" % (label, seconds, res["candidates"] / seconds))
    else:
        report(res, seconds, cols * rows)
    return res


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rings", type=int, default=250000, help="about this many rings (square sheet)")
    ap.add_argument("--partitions", type=int, default=32)
    ap.add_argument("--margin", type=float, default=0.05, help="report pairs with clearance below this")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--scheduler", help="address of a running Dask scheduler (default: a LocalCluster)")
    ap.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes")
    ap.add_argument("--threads", type=int, default=1, help="threads per LocalCluster worker")
    ap.add_argument("--single", action="store_true", help="run in this process, without Dask")
    ap.add_argument("--scaling", action="store_true", help="time 1..--workers workers and print a table")
    args = ap.parse_args(argv)
    side = int(math.ceil(math.sqrt(args.rings)))
    cols = rows = side
    if args.single:
        t = time.perf_counter()
        res = run(cols, rows, args.partitions, args.margin, args.seed)
        report(res, time.perf_counter() - t, cols * rows)
        return res
    from dask.distributed import Client, LocalCluster
    if args.scheduler:
        with Client(args.scheduler) as client:
            return timed_run(args, cols, rows, client)
    res = None
    for w in (range(1, args.workers + 1) if args.scaling else [args.workers]):
        with LocalCluster(n_workers=w, threads_per_worker=args.threads, processes=True,
                          dashboard_address=None) as cluster, Client(cluster) as client:
            res = timed_run(args, cols, rows, client, "workers %d: " % w if args.scaling else None)
    return res


if __name__ == "__main__":
    main()
