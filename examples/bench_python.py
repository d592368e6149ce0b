#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Per-query cost of the vectorised Python calls against the bare C batch call.

    python3 examples/bench_python.py [--n 1000000] [--repeats 5] [--threads 1] [--interrupt]

"C batch": one cdist_batch / cdist_batch_distance / cdist_batch_contact call on ready (N, 7) or
(N, 8) arrays and result buffers (through ctypes: one call, so the binding adds nothing per
query). "Python": the whole user-level call, circledist.circle_circle(Circle(centers, normals,
radii), ...) or circledist.torus_torus(Torus(Circle(...), tube), ...), including packing the
field arrays into the C layout, allocating the results, the Ctrl-C progress callback of long
batches and wrapping the results as numpy views. Minimum over repeats (the machine is noisy);
random unit-scale pairs. --cpu: this thread's CPU time instead of wall time. --interrupt: instead, the time from a SIGINT (sent by a timer 0.3 s
into a 10^7-entry torus-torus distance batch) to the KeyboardInterrupt, over the repeats.
"""
import argparse
import time

import numpy as np

import circledist as cd
from circledist import _lib


#: the clock of the measurements: wall time, or with --cpu this thread's CPU time (user and
#: system, so page faults count; steadier on a loaded machine; for threads=1)
clock = time.perf_counter


def best(f, repeats):
    t = []
    for _ in range(repeats):
        t0 = clock()
        f()
        t.append(clock() - t0)
    return min(t)


def interrupt_latency(repeats, threads):
    """Seconds from SIGINT to KeyboardInterrupt during a long batch, one per repeat."""
    import os
    import signal
    import threading
    n = 10 ** 7
    t0 = cd.Torus(((0, 0, 0), (0, 0, 1), 1.0), 0.1)
    row = cd.Torus(((0.3, 0.8, 0.1), (0.6, 0.0, 0.8), 0.9), 0.05).data
    tori = cd.Torus.from_array(np.broadcast_to(row, (n, 8)))
    out = cd.BatchContact(None, np.full(n, -1, np.int32), np.full(n, -1.0))
    q = cd.Query(threads=threads)
    latency = []
    for _ in range(repeats):
        sent = []
        timer = threading.Timer(0.3, lambda: (sent.append(time.perf_counter()),
                                              os.kill(os.getpid(), signal.SIGINT)))
        timer.start()
        try:
            q.torus_torus(tori, t0, distance_only=True, out=out)
        except KeyboardInterrupt:
            latency.append(time.perf_counter() - sent[0])
        finally:
            timer.cancel()
    return latency


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, default=1000000)
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--interrupt", action="store_true")
    ap.add_argument("--cpu", action="store_true")
    args = ap.parse_args(argv)
    global clock
    if args.cpu:
        clock = time.thread_time
    if args.interrupt:
        lat = sorted(interrupt_latency(args.repeats, args.threads))
        print("Ctrl-C during a 10^7-entry batch: KeyboardInterrupt %s ms after SIGINT (min %.1f, "
              "median %.1f, max %.1f)" % (", ".join("%.1f" % (1e3 * x) for x in lat), 1e3 * lat[0],
                                          1e3 * lat[len(lat) // 2], 1e3 * lat[-1]))
        return
    n = args.n
    rng = np.random.default_rng(1)

    def unit():
        v = rng.normal(size=(n, 3))
        return v / np.linalg.norm(v, axis=1)[:, None]
    fields = [(rng.uniform(-1, 1, (n, 3)), unit(), rng.uniform(0.2, 1.5, n)) for _ in range(2)]
    packed = [cd.Circle(*f).data for f in fields]
    q = cd.Query(threads=args.threads)
    raw = np.empty(n, _lib.RESULT_DTYPE)
    dist = np.empty(n)
    status = np.empty(n, np.int32)
    A, B = packed

    def c_full():
        _lib.batch(q._q, 5, n, A.ctypes.data, 56, B.ctypes.data, 56, raw.ctypes.data, status.ctypes.data)

    def c_full_fresh():  # as a one-shot C caller: malloc'ed (not yet touched) result buffers
        r, s = np.empty(n, _lib.RESULT_DTYPE), np.empty(n, np.int32)
        _lib.batch(q._q, 5, n, A.ctypes.data, 56, B.ctypes.data, 56, r.ctypes.data, s.ctypes.data)

    def c_dist():
        _lib.batch_distance(q._q, 5, n, A.ctypes.data, 56, B.ctypes.data, 56, dist.ctypes.data,
                            status.ctypes.data)

    def py_full():
        return q.circle_circle(cd.Circle(*fields[0]), cd.Circle(*fields[1]))

    reuse = py_full()

    def py_full_out():
        return q.circle_circle(cd.Circle(*fields[0]), cd.Circle(*fields[1]), out=reuse)

    def py_dist():
        return q.circle_circle(cd.Circle(*fields[0]), cd.Circle(*fields[1]), distance_only=True)

    def py_view():
        return q.circle_circle(cd.Circle.from_array(A), cd.Circle.from_array(B), out=reuse)

    tubes = [rng.uniform(0.0, 0.2, n) for _ in range(2)]
    TA, TB = (cd.Torus(cd.Circle(*f), t).data for f, t in zip(fields, tubes))
    contacts = np.empty(n, _lib.CONTACT_DTYPE)

    def c_tt():
        _lib.batch_contact(q._q, 21, n, TA.ctypes.data, 64, TB.ctypes.data, 64, contacts.ctypes.data,
                           status.ctypes.data)

    def c_tt_fresh():
        r, s = np.empty(n, _lib.CONTACT_DTYPE), np.empty(n, np.int32)
        _lib.batch_contact(q._q, 21, n, TA.ctypes.data, 64, TB.ctypes.data, 64, r.ctypes.data, s.ctypes.data)

    def py_tt():
        return q.torus_torus(cd.Torus(cd.Circle(*fields[0]), tubes[0]), cd.Torus(cd.Circle(*fields[1]), tubes[1]))

    reuse_tt = py_tt()

    def py_tt_out():
        return q.torus_torus(cd.Torus(cd.Circle(*fields[0]), tubes[0]), cd.Torus(cd.Circle(*fields[1]), tubes[1]),
                             out=reuse_tt)

    def py_tt_view():
        return q.torus_torus(cd.Torus.from_array(TA), cd.Torus.from_array(TB), out=reuse_tt)

    rows = [("full, fresh buffers", c_full_fresh, py_full), ("full, reused buffers", c_full, py_full_out),
            ("full, from_array+out", c_full, py_view), ("distance only", c_dist, py_dist),
            ("torus-torus, fresh", c_tt_fresh, py_tt), ("torus-torus, reused", c_tt, py_tt_out),
            ("torus-torus, from_array+out", c_tt, py_tt_view)]
    print("%d circle-circle queries, threads=%d, min of %d (C and Python interleaved)" % (
        n, args.threads, args.repeats))
    print("%-28s %12s %12s %7s" % ("", "C batch", "Python", "ratio"))
    for name, c, p in rows:
        tc, tp = [], []
        for _ in range(args.repeats):
            tc.append(best(c, 1))
            tp.append(best(p, 1))
        tc, tp = min(tc), min(tp)
        print("%-28s %9.3f us %9.3f us %7.3f" % (name, 1e6 * tc / n, 1e6 * tp / n, tp / tc))
    # Noise-free view of the same thing: inside one Python call, the time spent in the C call
    # against the whole call (everything else is the binding's overhead).
    inner = []
    saved = (_lib.batch, _lib.batch_distance, _lib.batch_contact)
    for fn_name in ("batch", "batch_distance", "batch_contact"):
        real = getattr(_lib, fn_name)

        def timed(*a, _real=real):
            t0 = clock()
            st = _real(*a)
            inner.append(clock() - t0)
            return st
        setattr(_lib, fn_name, timed)
    try:
        for name, p in (("full results", py_full), ("distance only", py_dist), ("torus-torus", py_tt),
                        ("torus-torus, out=", py_tt_out)):
            ratios = []
            for _ in range(args.repeats):
                inner.clear()
                t0 = clock()
                p()
                total = clock() - t0
                ratios.append((total - inner[0], total / inner[0]))
            over, ratio = min(ratios)
            print("%-22s overhead outside the C call %.3f us/query, whole call / C call %.3f" % (
                name, 1e6 * over / n, ratio))
    finally:
        _lib.batch, _lib.batch_distance, _lib.batch_contact = saved
    # the Python answer is the C answer
    assert np.array_equal(py_full().distance, (c_full(), raw["distance"])[1])
    assert py_tt().raw.tobytes() == (c_tt(), contacts)[1].tobytes()


if __name__ == "__main__":
    main()
