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
the answers twice while merging them (2 x 136 bytes per pair).

What made the old example 2x slower under Dask than in one process, and what this one does:
- Task size: 32 fixed partitions made ~13 ms tasks at 10^5 rings, so scheduling dominated.
  `per_task` (default 125 000 rings: ~0.2 s of CPU per task) sets the task size from the data,
  and the number of tasks is rounded up to a multiple of the worker threads.
- Work repeated per task: each task regenerated its rings and ran a numpy grid broad phase.
  Now the rings are cut once by the driver (CPU 0.12-0.14 s for 10^6 rings) and each task is
  one scene query; the partitions' queries together take less CPU than the one big scene
  (1.43-1.45 s against 1.65-1.90 s for 10^6 rings, same run: smaller trees stay in cache).
  Merging the answers costs the driver 0.1-0.5 s (concatenation, sort by (i, j), gather of
  ~95 MB; most of the spread is first-touch page faults).
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

Measured on the development machine, today: 2 cores shared with four other jobs (the 1-minute
load average was 7-12 throughout, so a second worker found no idle core: on this machine even
the library's own threads gave nothing then, 2.49-3.77 s with one thread against 2.67-3.69 s
with two); release build; wall seconds, minimum of the repeats, single process and Dask
alternating in the same run; chain-mail sheet, delta 0.1 R (0.70 pairs per ring); "one process"
is one Scene with one thread; the Dask times include cutting, scattering and merging, not the
cluster start; "N workers": N worker processes of one thread each (`--processes`), "in-process":
workers as threads of this process (the default since these runs):

    rings  cluster                         one process  Dask     Dask / one  load (before -> after)
    10^6   2 workers                       1.79 s       3.15 s   1.76        8.0 -> 6.8
    10^6   1 worker                        2.93 s       6.01 s   2.05        6.8 -> 8.9
    10^6   2 workers, --dask-malloc        1.68 s       3.77 s   2.24        8.9 -> 10.7
    10^6   1 worker of 2 threads, in-process  1.99 s    2.21 s   1.11        10.7 -> 9.4
    10^6   2 workers, in-process           5.46 s       6.52 s   1.19        7.0 -> 11.0
    10^6   1 worker of 2 threads, in-process  4.08 s    5.84 s   1.43        11.0 -> 11.5
    10^6   2 workers                       3.16 s       6.93 s   2.19        11.5 -> 11.8
    10^6   2 workers                       4.15 s       5.81 s   1.40        9.3 -> 10.6
    10^6   1 worker                        4.90 s       4.26 s   0.87        10.6 -> 11.3
    10^7   2 workers                       21.5 s       34.2 s   1.59        11.3 -> 7.2
    10^7   1 worker                        57.2 s       93.9 s   1.64        7.2 -> 10.6
    10^7   2 workers, in-process           50.05 s      50.34 s  1.01        7.1 -> 7.2

(minimum of 5 alternating runs per row at 10^6, except the last two 10^6 rows: 3; 2 at 10^7 with
worker processes, 1 in-process; the first of the 1-worker pair at 10^7 overlapped with another
run of ours.) At 10^7, 84 tasks: with 2 worker processes cut 2.45 s, scatter 6.1 s, tasks
21.0 s, merge 4.6 s, the driver peaking at 7.4 GB resident; in-process cut 3.9 s, scatter
0.9 s, tasks 33.4 s, merge 12.1 s, 5.8 GB. Every run gave the one-process answer bit for bit
(702 270 pairs at 10^6, 7 034 993 at 10^7).

So on this machine, as loaded today, Dask was at best as fast as one process (1.01x at 10^7
and 1.11x at 10^6 in-process, 0.87x in one 10^6 run with one worker process) and mostly slower
(up to 2.2x with worker processes): with no idle core a second worker adds no CPU, and what
Dask adds (cutting, scattering, merging: about 0.5 s of driver CPU at 10^6, and with worker
processes the pickling) is not paid back. The done-criterion "no slower than one process at
10^6" is therefore not shown here. What should scale: the tasks are independent and together
cheaper than the one scene, so on idle cores the task phase divides by the number of workers
and the driver's share is what remains; that was not measurable on this machine today.
The MALLOC_TRIM_THRESHOLD_ entry matters only for worker processes; at this load its effect
(1.68/3.77 s with it against 1.79/3.15 s without, one pair of runs each) is inside the noise.
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
    """Task answers as one ScenePairs sorted by (i, j)."""
    raw = np.concatenate(raws) if raws else np.empty(0, SCENE_PAIR_DTYPE)
    # each task's pairs are sorted already: a stable sort of the runs is a merge
    key = raw["i"] * np.uint64(max(1, int(raw["j"].max(initial=0)) + 1)) + raw["j"]
    raw = raw[np.argsort(key, kind="stable")]
    return cd.ScenePairs(raw)


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
