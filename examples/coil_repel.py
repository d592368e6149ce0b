#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Push planar circular coils apart with the distance gradient of libcircledist.

N coils (circles: centre, unit normal, radius) start at target poses that are too close
(some even linked). Gradient descent on

    loss = sum_i |c_i - t_i|^2 + 0.5 sum_i |n_i - m_i|^2
         + k * sum_{i<j} max(0, d_min - D_ij)^2

moves centres and normals (normals stay unit: their gradient is tangent to the sphere, the
step is followed by a renormalisation) until every coil-coil distance D_ij is at least about
d_min while staying near the targets. D_ij and its gradient come from
cdist_circle_circle_grad() (closest pair + envelope theorem). Writes a plot of the smallest
coil-coil distance per step (matplotlib, Agg backend, PNG).

This uses ctypes directly on the built library (a minimal binding for this example; the
package in python/ is the full one):

    CIRCLEDIST_LIBRARY=build/libcircledist.so python3 examples/coil_repel.py --out coil.png
"""
import argparse
import ctypes
import math
import os
import random
import sys


class Vec3(ctypes.Structure):
    _fields_ = [("x", ctypes.c_double), ("y", ctypes.c_double), ("z", ctypes.c_double)]


class Circle(ctypes.Structure):
    _fields_ = [("center", Vec3), ("normal", Vec3), ("radius", ctypes.c_double)]


class Pair(ctypes.Structure):
    _fields_ = [("point", Vec3 * 2), ("param", ctypes.c_double * 2)]


class Result(ctypes.Structure):
    _fields_ = [("distance", ctypes.c_double), ("sqr_distance", ctypes.c_double),
                ("num_pairs", ctypes.c_int), ("equidistant", ctypes.c_int),
                ("pairs", Pair * 2), ("method", ctypes.c_int), ("iterations", ctypes.c_int),
                ("reserved", ctypes.c_double * 8)]


class GradObject(ctypes.Structure):
    _fields_ = [("d_center", Vec3), ("d_normal", Vec3), ("d_origin", Vec3), ("d_direction", Vec3),
                ("d_p0", Vec3), ("d_p1", Vec3), ("d_zero_direction", Vec3),
                ("d_radius", ctypes.c_double), ("d_radius_swept", ctypes.c_double),
                ("d_start", ctypes.c_double), ("d_end", ctypes.c_double),
                ("reserved", ctypes.c_double * 8)]


class Grad(ctypes.Structure):
    _fields_ = [("obj", GradObject * 2), ("flags", ctypes.c_int), ("reserved_int", ctypes.c_int),
                ("reserved", ctypes.c_double * 8)]


def load():
    path = os.environ.get("CIRCLEDIST_LIBRARY")
    if not path:
        here = os.path.dirname(os.path.abspath(__file__))
        path = os.path.join(here, "..", "build", "libcircledist.so")
    lib = ctypes.CDLL(path)
    lib.cdist_query_new.restype = ctypes.c_void_p
    lib.cdist_query_free.argtypes = [ctypes.c_void_p]
    lib.cdist_result_size.restype = ctypes.c_size_t
    lib.cdist_grad_size.restype = ctypes.c_size_t
    lib.cdist_query_last_error.restype = ctypes.c_char_p
    lib.cdist_query_last_error.argtypes = [ctypes.c_void_p]
    lib.cdist_circle_circle_grad.argtypes = [ctypes.c_void_p, ctypes.POINTER(Circle), ctypes.POINTER(Circle),
                                             ctypes.POINTER(Result), ctypes.POINTER(Grad)]
    lib.cdist_circle_circle_grad.restype = ctypes.c_int
    # the layouts above must match the library's
    assert lib.cdist_result_size() == ctypes.sizeof(Result)
    assert lib.cdist_grad_size() == ctypes.sizeof(Grad)
    return lib


def vec(v):
    return Vec3(*v)


def unit(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--coils", type=int, default=6)
    ap.add_argument("--steps", type=int, default=600)
    ap.add_argument("--dmin", type=float, default=0.3)
    ap.add_argument("--out", default="coil_repel.png")
    ap.add_argument("--seed", type=int, default=3)
    args = ap.parse_args()

    lib = load()
    q = ctypes.c_void_p(lib.cdist_query_new())
    rnd = random.Random(args.seed)
    n = args.coils
    # targets: coils of radius 1 on a ring of radius 1.2 (neighbours overlap), random tilts
    target_c = [[1.2 * math.cos(2 * math.pi * i / n), 1.2 * math.sin(2 * math.pi * i / n), 0.1 * rnd.uniform(-1, 1)]
                for i in range(n)]
    target_n = [unit([rnd.uniform(-0.5, 0.5), rnd.uniform(-0.5, 0.5), 1.0]) for _ in range(n)]
    radius = [1.0] * n
    c = [list(t) for t in target_c]
    nn = [list(t) for t in target_n]
    k, lr = 20.0, 0.005
    history = []
    res, grad = Result(), Grad()
    for step in range(args.steps):
        gc = [[2 * (c[i][a] - target_c[i][a]) for a in range(3)] for i in range(n)]
        gn = [[(nn[i][a] - target_n[i][a]) for a in range(3)] for i in range(n)]
        dmin_now = math.inf
        for i in range(n):
            for j in range(i + 1, n):
                ci = Circle(vec(c[i]), vec(nn[i]), radius[i])
                cj = Circle(vec(c[j]), vec(nn[j]), radius[j])
                st = lib.cdist_circle_circle_grad(q, ctypes.byref(ci), ctypes.byref(cj), ctypes.byref(res),
                                                  ctypes.byref(grad))
                if st != 0:
                    sys.exit("query failed: " + lib.cdist_query_last_error(q).decode())
                d = res.distance
                dmin_now = min(dmin_now, d)
                if d < args.dmin:
                    # d/dx of k (dmin - D)^2 = -2 k (dmin - D) dD/dx; at D = 0 (linked coils
                    # crossing) the library returns the zero subgradient, so push along the
                    # centre difference instead
                    f = -2 * k * (args.dmin - d)
                    for s, idx in ((0, i), (1, j)):
                        g = grad.obj[s]
                        dc = [g.d_center.x, g.d_center.y, g.d_center.z]
                        if d == 0 or all(x == 0 for x in dc):
                            sgn = -1 if s == 0 else 1
                            dc = unit([sgn * (c[j][a] - c[i][a]) for a in range(3)])
                        gc[idx] = [gc[idx][a] + f * dc[a] for a in range(3)]
                        dn = [g.d_normal.x, g.d_normal.y, g.d_normal.z]
                        gn[idx] = [gn[idx][a] + f * dn[a] for a in range(3)]
        history.append(dmin_now)
        for i in range(n):
            c[i] = [c[i][a] - lr * gc[i][a] for a in range(3)]
            # tangent step on the unit sphere, then back onto it
            nd = sum(gn[i][a] * nn[i][a] for a in range(3))
            tang = [gn[i][a] - nd * nn[i][a] for a in range(3)]
            nn[i] = unit([nn[i][a] - lr * tang[a] for a in range(3)])
    lib.cdist_query_free(q)
    drift = max(math.dist(c[i], target_c[i]) for i in range(n))
    print(f"smallest coil-coil distance: start {history[0]:.4f}, end {history[-1]:.4f} (target {args.dmin}); "
          f"largest centre drift {drift:.4f}")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(history, label="smallest coil-coil distance")
    ax.axhline(args.dmin, color="gray", linestyle="--", label="d_min")
    ax.set_xlabel("gradient step")
    ax.set_ylabel("distance")
    ax.set_title(f"{n} coils pushed apart (cdist_circle_circle_grad)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.out, dpi=100)
    print("wrote", args.out)
    # the end state must be close to the requested spacing
    return 0 if history[-1] > 0.9 * args.dmin else 1


if __name__ == "__main__":
    sys.exit(main())
