#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Chain-mail screen with Dask: every pair of rings within delta of each other, for the user's
own ring array, answered by circledist scenes inside Dask tasks.

    res = run(rings, delta)                      # one process: one circledist.Scene
    res = run(rings, delta, client=client)       # the same pairs, bit for bit, on a Dask cluster

`rings` is a circledist.Torus array (core circle + wire radius; a Circle array is a torus of
wire 0). The answer is a circledist.ScenePairs sorted by (i, j): ids are positions in `rings`,
distance is the signed clearance (core distance minus both wire radii; negative: the wires
collide), with the closest points. It is pair for pair, bit for bit, the answer of
`circledist.Scene(rings).pairs_within(delta)`.

How the work is split (`plan()`): the ring centres are cut into boxes by a grid whose cut
planes are quantiles of the centres along each axis, more cuts along the longer extents, so the
boxes hold about `per_task` rings each (a sheet gets columns x rows of boxes, a long chain
slabs). A ring belongs to the box holding its centre. Two rings can be within delta only when
their centres are within the reach h = delta + 2 max(R + r) (R + r bounds a torus around its
centre; h is widened by 1e-9 of the coordinates' scale against rounding), so each task holds its box plus a halo: the rings of the *later* boxes (higher flat
box index) whose centres lie within h of its box.

Ownership rule: a pair belongs to the box of its two rings with the lower box index (the box
of both, when they share one). Every such pair lies in that box's task (the other ring is in the
box or its halo), and in no other task (a task holds no ring of an earlier box), so each pair
is answered exactly once. Pairs of two halo rings belong to a later box: the task skips them
with the scene's group filter (halo rings share a group) instead of computing and dropping
them. A task builds a circledist.Scene of its rings in increasing global id, so its local order
is the global order and every pair is answered with the same ring first as in one process:
same (i, j), same distance and points, bit for bit.

Only the partitions travel: the driver cuts the array once and scatters each partition (rows of
doubles, global ids, halo flags) to one worker; only the close pairs come back.

    python3 examples/dask_chainmail.py --rings 1000000                      # LocalCluster
    python3 examples/dask_chainmail.py --rings 1000000 --workers 2 --processes
    python3 examples/dask_chainmail.py --scheduler tcp://host:8786 ...      # any cluster
    python3 examples/dask_chainmail.py --single ...                         # no Dask
    python3 examples/dask_chainmail.py --compare ...                        # both, checked

On a real cluster: start `dask scheduler` on one host and `dask worker tcp://host:8786
--nthreads T` on each node (numpy, circledist and libcircledist installed there), then pass
`--scheduler tcp://host:8786`. For your own data, `run(rings, delta,
client=Client("tcp://host:8786"))`; when this file is imported as a module rather than run,
the workers need it too (`client.upload_file("dask_chainmail.py")`). Choose `per_task` so
that a task takes 0.1-1 s (about 1.5 us of CPU per ring here) and there are several tasks per
worker thread. The driver holds the array and its partitions (about 140 bytes per ring) and
the answers twice while merging them (2 x 136 bytes per pair, plus 24 bytes of keys and
places).

What made the old example 2x slower under Dask than in one process, and what this one does:
- Task size: 32 fixed partitions made ~13 ms tasks at 10^5 rings, so scheduling dominated.
  `per_task` (default 125 000 rings: ~0.2 s of CPU per task) sets the task size from the data,
  and the number of tasks is rounded up to a multiple of the worker threads.
- Work repeated per task: each task regenerated its rings and ran a numpy grid broad phase.
  Now the rings are cut once by the driver (CPU 0.12-0.14 s for 10^6 rings) and each task is
  one scene query; the partitions' queries together take less CPU than the one big scene
  (1.43-1.45 s against 1.65-1.90 s for 10^6 rings, same run: smaller trees stay in cache).
  Merging the answers costs the driver 0.12-0.22 s at 10^6 rings: the keys (i, j) alone are
  sorted (8 bytes a pair) and each 136-byte record is copied once, straight to its place (a
  concatenation followed by a gather in sorted order copied each record twice and took
  0.3-0.45 s, most of it first-touch page faults).
- The workers' glibc settings: distributed's nanny sets MALLOC_TRIM_THRESHOLD_=65536 in each
  worker process (`distributed.nanny.pre-spawn-environ`); setting any malloc threshold turns off
  glibc's dynamic mmap threshold, so every array above 128 KiB is a fresh mmap whose pages are
  faulted in at each use. `local_cluster()` removes that entry (workers keep glibc's defaults;
  `--dask-malloc` keeps it, to compare); on your own cluster remove it from the workers' dask
  config the same way.
- Data movement: the partitions are scattered once (64 bytes per ring, plus the halo) and only
  the answers come back (136 bytes per pair); nothing else travels. Worker processes pay for
  pickling both (scatter 0.15-1.0 s for 10^6 rings here, 6-13 s for 10^7); workers as threads
  of one process (the LocalCluster's default here; `--processes` for processes) do not, and
  still run in parallel: the scene query releases the GIL and takes
  it back only to copy each block of answers (about 1000 blocks per task of 125 000 rings).

Measured on the development machine, today (2026-11-27): 2 cores, nothing else running (a
fuzzer that shares the machine was paused for these runs; the 1-minute load average was
0.8-1.2 before and after each row); release build; wall seconds, minimum of the repeats (5 at
10^6, 2 at 10^7), one process and Dask alternating in the same run; chain-mail sheet, delta 0.1 R
(0.70 pairs per ring); "one process" is one Scene with one thread; the Dask times include
cutting, scattering and merging, not the cluster start; "in-process": workers as threads of
this process (the default), "processes": `--processes`, one thread each:

    rings  cluster                    one process  Dask     Dask / one  Dask phases (cut, scatter, tasks, merge)
    10^6   2 workers, in-process      1.24 s       0.95 s   0.77        0.14  0.04  0.65  0.12
    10^6   1 worker, in-process       1.22 s       1.46 s   1.20        0.14  0.04  1.12  0.15
    10^6   2 workers, processes       1.18 s       1.29 s   1.09        0.13  0.11  0.83  0.22
    10^6   1 worker, processes        1.20 s       1.63 s   1.36        0.13  0.10  1.27  0.12
    10^7   2 workers, in-process      15.11 s      12.10 s  0.80        1.50  0.39  6.60  3.60
    10^7   1 worker, in-process       14.81 s      16.19 s  1.09        1.41  0.39  11.24 3.15

Every run gave the one-process answer bit for bit (702 270 pairs at 10^6, 7 034 993 at 10^7).
With both cores to work on, Dask is faster than one process (0.77x at 10^6, 0.80x at 10^7):
the tasks run in parallel and together cost less CPU than the one big scene, and the driver's
share (cutting, scattering, merging: about 0.3 s at 10^6) is paid back. With one worker it
is slower by that share (1.1-1.4x), and worker processes add the pickling of the partitions
and answers. The merge is the driver's largest part at 10^7 (3-4 s for 7 x 10^6 pairs: the
key sort and the scattered copy of 0.96 GB). The MALLOC_TRIM_THRESHOLD_ entry matters only
for worker processes; at the load of an earlier day its effect was inside the noise.
"""
import argparse
import itertools
import math
import time

import numpy as np

import circledist as cd
from circledist._scene import SCENE_PAIR_DTYPE

#: Geometry of the demo weave (units of the ring radius).
RADIUS, WIRE, SPACING_X, SPACING_Y, TILT = 1.0, 0.11, 2.4, 1.4, math.radians(50)


def make_sheet(cols, rows, seed=1, jitter=0.03):
    """A chain-mail sheet ("4 in 1" weave: rows offset by half a spacing, tilted alternately),
    rows x cols rings with random jitter of positions, tilts and radii: a Torus array (ids row
    major: row * cols + col). The demo input; run() takes any Torus array."""
    rng = np.random.default_rng(seed)
    row, col = np.divmod(np.arange(rows * cols), cols)
    c = np.empty((rows * cols, 3))
    c[:, 0] = SPACING_X * (col + 0.5 * (row % 2))
    c[:, 1] = SPACING_Y * row
    c[:, 2] = 0.0
    c += rng.normal(scale=jitter, size=c.shape)
    s = np.where(row % 2 == 0, 1.0, -1.0)
    n = np.stack([np.zeros(len(s)), s * math.sin(TILT), np.full(len(s), math.cos(TILT))], axis=1)
    n += rng.normal(scale=jitter, size=n.shape)
    n /= np.linalg.norm(n, axis=1)[:, None]
    radius = RADIUS * (1 + rng.normal(scale=jitter / 3, size=len(s)))
    return cd.Torus(cd.Circle(c, n, radius), np.full(len(s), WIRE))


def as_tori(rings):
    """The user's rings as a Torus array: a Torus, a Circle (wire 0) or an (N, 8) array of
    torus rows (center, normal, radius, wire)."""
    if isinstance(rings, cd.Torus):
        return rings
    if isinstance(rings, cd.Circle):
        return cd.Torus(rings, np.zeros(rings.data.reshape(-1, 7).shape[0]))
    return cd.Torus.from_array(np.asarray(rings, dtype=np.float64).reshape(-1, 8))


def _box_counts(extent, parts, reach):
    """Cuts per axis: add one to the axis with the longest box side while the product is below
    `parts`, keeping boxes at least a reach wide (thinner boxes would be mostly halo)."""
    counts = [1, 1, 1]
    while counts[0] * counts[1] * counts[2] < parts:
        side = [extent[k] / (counts[k] + 1) if extent[k] / (counts[k] + 1) >= reach else -1.0
                for k in range(3)]
        k = int(np.argmax(side))
        if side[k] < 0:
            break
        counts[k] += 1
    return counts


def plan(rings, delta, per_task=125000, min_tasks=1):
    """Cut the rings into boxes with halos (see the module docstring). Returns a list of
    partitions, each (ids, halo): global ids in increasing order and a bool array marking the
    halo rings, and the grid (edges per axis)."""
    rows = rings.data.reshape(-1, 8)
    center, extent_r = rows[:, 0:3], rows[:, 6] + rows[:, 7]
    n = len(rows)
    size = float(extent_r.max(initial=0.0))
    scale = float(np.abs(center).max(initial=0.0)) + size
    # widened by 1e-9 of the scale, so that rounding in the queries never decides whether a
    # pair near the reach lands in a task
    reach = float(delta) + 2 * size + 1e-9 * scale
    parts = max(int(min_tasks), -(-n // int(per_task)), 1)
    lo, hi = center.min(axis=0, initial=np.inf), center.max(axis=0, initial=-np.inf)
    counts = _box_counts(np.maximum(hi - lo, 0.0) if n else np.zeros(3), parts, reach)
    edges, cell = [], np.zeros((n, 3), np.int64)
    for k in range(3):
        inner = np.unique(np.quantile(center[:, k], np.linspace(0, 1, counts[k] + 1)[1:-1])) if n else []
        edges.append(np.asarray(inner, dtype=np.float64))
        cell[:, k] = np.searchsorted(edges[k], center[:, k], side="right")
    dims = [len(e) + 1 for e in edges]
    box = (cell[:, 0] * dims[1] + cell[:, 1]) * dims[2] + cell[:, 2]
    if dims[0] * dims[1] * dims[2] < 2 ** 15:
        box = box.astype(np.int16)                 # numpy's stable sort is a radix sort here
    order = np.argsort(box, kind="stable")         # ids of each box, increasing
    start = np.searchsorted(box[order], np.arange(dims[0] * dims[1] * dims[2] + 1))
    bounds = [np.concatenate(([-np.inf], e, [np.inf])) for e in edges]
    by_box = center[order]                         # each box's centres contiguous: views, no gathers
    out = []
    for b in range(dims[0] * dims[1] * dims[2]):
        own = order[start[b]:start[b + 1]]
        if len(own) == 0:
            continue
        cb = np.unravel_index(b, dims)
        # the box (its grid cell, clipped to the centres' extent) widened by the reach
        blo = [max(bounds[k][cb[k]], lo[k]) - reach for k in range(3)]
        bhi = [min(bounds[k][cb[k] + 1], hi[k]) + reach for k in range(3)]
        span = [range(int(np.searchsorted(bounds[k], blo[k], "right")) - 1,
                      int(np.searchsorted(bounds[k], bhi[k], "right"))) for k in range(3)]
        halo = []
        for cq in itertools.product(*span):
            q = (cq[0] * dims[1] + cq[1]) * dims[2] + cq[2]
            if q <= b or start[q] == start[q + 1]:
                continue                           # earlier boxes own those pairs
            c = by_box[start[q]:start[q + 1]]
            inside = np.ones(len(c), bool)
            for k in range(3):
                if cq[k] != cb[k]:                 # along axes where the cells agree it is inside
                    inside &= (c[:, k] >= blo[k]) & (c[:, k] <= bhi[k])
            halo.append(order[start[q]:start[q + 1]][inside])
        halo = np.concatenate(halo) if halo else np.empty(0, np.int64)
        ids = np.concatenate((own, halo))
        flag = np.concatenate((np.zeros(len(own), bool), np.ones(len(halo), bool)))
        k = np.argsort(ids, kind="stable")
        out.append((ids[k], flag[k]))
    return out, edges


def screen_partition(part, delta, threads=1):
    """One task: the pairs within delta owned by one partition (rows, global ids, halo flags),
    as raw scene pairs with global ids."""
    rows, ids, halo = part
    scene = cd.Scene(cd.Torus.from_array(rows), threads=threads)
    if halo.any():
        scene.set_groups(group=halo.astype(np.uint32))    # halo-halo pairs belong to later boxes
    raw = scene.pairs_within(delta).raw
    scene.close()
    raw["i"] = ids[raw["i"].astype(np.int64)]
    raw["j"] = ids[raw["j"].astype(np.int64)]
    return raw


def combine(raws):
    """Task answers as one ScenePairs sorted by (i, j). No pair is in two tasks, so the keys
    (i, j) are distinct: their order (8 bytes a pair) gives each record its place, and each
    record is copied once, straight to it."""
    raws = [r for r in raws if len(r)]
    out = np.empty(sum(len(r) for r in raws), SCENE_PAIR_DTYPE)
    if not raws:
        return cd.ScenePairs(out)
    width = np.uint64(max(int(r["j"].max()) for r in raws) + 1)
    keys = np.concatenate([r["i"] * width + r["j"] for r in raws])
    place = np.empty(len(keys), np.int64)
    place[np.argsort(keys)] = np.arange(len(keys))
    start = 0
    for r in raws:
        out[place[start:start + len(r)]] = r
        start += len(r)
    return cd.ScenePairs(out)


def run(rings, delta, client=None, per_task=125000, threads=1, timings=None):
    """Every pair of `rings` within `delta` (a ScenePairs, ids = positions in rings): on the
    Dask client when given (partitions of about per_task rings), else one Scene here with
    `threads` threads. timings, a dict, receives the phases' wall seconds."""
    rings = as_tori(rings)
    timings = {} if timings is None else timings
    t0 = time.perf_counter()
    if client is None:
        with cd.Scene(rings, threads=threads) as scene:
            res = scene.pairs_within(delta)
        timings["query"] = time.perf_counter() - t0
        return res
    slots = max(1, sum(client.nthreads().values()))
    tasks = max(slots, -(-len(rings.data.reshape(-1, 8)) // int(per_task)))
    parts, _ = plan(rings, delta, per_task, min_tasks=-(-tasks // slots) * slots)  # no idle last round
    rows = rings.data.reshape(-1, 8)
    payload = [(rows[ids], ids, halo) for ids, halo in parts]
    t1 = time.perf_counter()
    futures = client.scatter(payload)
    t2 = time.perf_counter()
    results = client.gather(client.map(screen_partition, futures, delta=delta, threads=1, pure=False))
    t3 = time.perf_counter()
    res = combine(results)
    t4 = time.perf_counter()
    timings.update(tasks=len(parts), cut=t1 - t0, scatter=t2 - t1, compute=t3 - t2, combine=t4 - t3)
    return res


def same_pairs(a, b):
    """True when two answers are the same pairs, bit for bit (ids, distances, points, flags)."""
    return len(a.raw) == len(b.raw) and a.raw.tobytes() == b.raw.tobytes()


def local_cluster(workers, threads, processes=False, dask_malloc=False):
    """A LocalCluster whose worker processes keep glibc's malloc defaults (see the docstring;
    dask_malloc: keep distributed's setting instead)."""
    import dask
    from dask.distributed import LocalCluster
    env = dict(dask.config.get("distributed.nanny.pre-spawn-environ", {}))
    if not dask_malloc:
        env.pop("MALLOC_TRIM_THRESHOLD_", None)
    with dask.config.set({"distributed.nanny.pre-spawn-environ": env}):
        return LocalCluster(n_workers=workers, threads_per_worker=threads, processes=processes,
                            dashboard_address=None)


def report(res, seconds, n, timings):
    col = res.distance < 0
    print("%d rings, %d pairs within delta, %d colliding" % (n, len(res), int(col.sum())))
    if len(res):
        k = int(np.argmin(res.distance))
        print("smallest clearance %.6g between rings %d and %d at %s / %s" % (
            res.distance[k], res.i[k], res.j[k], res.points[k, 0], res.points[k, 1]))
    print("wall %.2f s (%s)" % (seconds, ", ".join("%s %s" % (k, ("%.2f" % v) if isinstance(v, float) else v)
                                                  for k, v in timings.items())))


def _best(runs, res, seconds, tim):
    """Keep the fastest of repeated runs: runs is None or (answer, seconds, timings)."""
    return (res, seconds, tim) if runs is None or seconds < runs[1] else runs


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rings", type=int, default=250000, help="about this many rings (square sheet)")
    ap.add_argument("--delta", type=float, default=0.1, help="report pairs with clearance <= delta")
    ap.add_argument("--per-task", type=int, default=125000, help="rings per task (about)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--scheduler", help="address of a running Dask scheduler (default: a LocalCluster)")
    ap.add_argument("--workers", type=int, default=2, help="LocalCluster workers")
    ap.add_argument("--threads", type=int, default=1, help="threads per LocalCluster worker")
    ap.add_argument("--processes", action="store_true",
                    help="LocalCluster workers as processes (default: threads of this process)")
    ap.add_argument("--dask-malloc", action="store_true",
                    help="keep distributed's MALLOC_TRIM_THRESHOLD_ in the LocalCluster workers")
    ap.add_argument("--single", action="store_true", help="run in this process, without Dask")
    ap.add_argument("--compare", action="store_true",
                    help="also run one process (alternating with Dask) and check pair for pair")
    ap.add_argument("--repeat", type=int, default=1, help="runs to take the minimum wall time of")
    args = ap.parse_args(argv)
    side = int(math.ceil(math.sqrt(args.rings)))
    rings = make_sheet(side, side, args.seed)
    n = side * side
    single = dist = None
    if args.single:
        for _ in range(args.repeat):
            tim = {}
            t = time.perf_counter()
            res = run(rings, args.delta, timings=tim)
            single = _best(single, res, time.perf_counter() - t, tim)
        report(single[0], single[1], n, single[2])
        return single[0]
    from dask.distributed import Client
    if args.scheduler:
        client, cluster = Client(args.scheduler), None
    else:
        cluster = local_cluster(args.workers, args.threads, args.processes, args.dask_malloc)
        client = Client(cluster)
    try:
        client.run(lambda: None)                 # workers up before timing
        for _ in range(args.repeat):
            if args.compare:
                tim = {}
                t = time.perf_counter()
                res = run(rings, args.delta, timings=tim)
                single = _best(single, res, time.perf_counter() - t, tim)
            tim = {}
            t = time.perf_counter()
            res = run(rings, args.delta, client, args.per_task, timings=tim)
            dist = _best(dist, res, time.perf_counter() - t, tim)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    if single is not None:
        print("one process:")
        report(single[0], single[1], n, single[2])
        print("Dask:")
    report(dist[0], dist[1], n, dist[2])
    if single is not None:
        same = same_pairs(single[0], dist[0])
        print("same pairs as one process, bit for bit: %s" % same)
        if not same:
            raise SystemExit(1)
    return dist[0]


if __name__ == "__main__":
    main()
