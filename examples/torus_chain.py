#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""A chain of linked tori: the clearance and closest pairs between neighbours, and a picture.

Each torus is a core circle (centre, unit axis, major radius R) swept by a tube of radius r.
The distance between two tori is the distance between their core circles minus the two tube
radii (negative: they overlap), and the closest points of the tubes lie on the segment between
the closest core points. All neighbour pairs are answered by one vectorised call:

    circledist.circle_circle(cores[:-1], cores[1:])

Neighbouring rings are linked (each passes through the other's disk), so some pairs sit
close to touching. Run:

    python3 examples/torus_chain.py [--rings 9] [--png FILE]

It prints one line per neighbour pair and, with --png, writes a PNG (matplotlib, Agg backend) of
the rings with their closest segments drawn in red (the README's picture is
`--png docs/torus_chain.png`). Without --png nothing is written.
"""
import argparse

import numpy as np

import circledist as cd


def make_chain(n, seed=3):
    """Core circles and tube radii of n linked tori along x, alternately lying flat and
    standing up, with random tilts and sizes so that every neighbour pair is different."""
    rng = np.random.default_rng(seed)
    R = rng.uniform(0.9, 1.1, n)                      # major radii
    tube = rng.uniform(0.06, 0.1, n)                  # tube radii
    step = 1.45                                       # < R_i + R_j: neighbours are linked
    centers = np.zeros((n, 3))
    centers[:, 0] = step * np.arange(n)
    centers[:, 1:] = rng.normal(scale=0.08, size=(n, 2))
    flat, up = np.array([0.0, 0, 1]), np.array([0.0, 1, 0])
    normals = np.where((np.arange(n) % 2 == 0)[:, None], flat, up) + rng.normal(scale=0.2, size=(n, 3))
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    return cd.Circle(centers, normals, R), tube


def neighbours(cores, tube):
    """(clearance (n-1,), result): one vectorised circle-circle call for all neighbour pairs."""
    res = cd.circle_circle(cores[:-1], cores[1:])
    if not np.all(res.ok):
        raise RuntimeError("bad rings: %s" % res.status_names()[~res.ok])
    return res.distance - tube[:-1] - tube[1:], res


def tube_segments(res, tube):
    """The closest segment between the tube surfaces of each neighbour pair (its first closest
    pair): the core points moved towards each other by the tube radii."""
    p = res.points[:, 0]                               # (n-1, 2, 3): first pair, both cores
    d = p[:, 1] - p[:, 0]
    u = d / np.maximum(np.linalg.norm(d, axis=1), 1e-300)[:, None]
    return np.stack([p[:, 0] + tube[:-1, None] * u, p[:, 1] - tube[1:, None] * u], axis=1)


def torus_mesh(core, r, nu=72, nv=16):
    """Surface points (nu, nv, 3) of the torus around one core circle."""
    u_ax, v_ax = cd.circle_basis(core)
    n = np.asarray(core.normal)
    a = np.linspace(0, 2 * np.pi, nu)[:, None, None]
    b = np.linspace(0, 2 * np.pi, nv)[None, :, None]
    radial = np.cos(a) * u_ax + np.sin(a) * v_ax
    return core.center + (core.radius + r * np.cos(b)) * radial + r * np.sin(b) * n


def draw(cores, tube, res, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(10, 10), dpi=110)  # 3D axes are square: crop below
    ax = fig.add_subplot(projection="3d")
    colors = plt.cm.viridis(np.linspace(0.15, 0.85, len(tube)))
    for i in range(len(tube)):
        m = torus_mesh(cores[i], tube[i])
        ax.plot_surface(m[..., 0], m[..., 1], m[..., 2], color=colors[i], alpha=0.35, linewidth=0,
                        antialiased=True, shade=True)
        ring = cd.circle_point(cores[i], np.linspace(-np.pi, np.pi, 200))
        ax.plot(ring[:, 0], ring[:, 1], ring[:, 2], color=colors[i], linewidth=0.8)
    clearance = res.distance - tube[:-1] - tube[1:]
    for k, seg in enumerate(tube_segments(res, tube)):
        ax.plot(seg[:, 0], seg[:, 1], seg[:, 2], color="red", linewidth=3, zorder=10)
        ax.scatter(seg[:, 0], seg[:, 1], seg[:, 2], color="red", s=12, depthshade=False)
        mid = seg.mean(axis=0)
        ax.text(mid[0], mid[1], mid[2] + 0.45, "%.3f" % clearance[k], color="darkred", fontsize=9,
                ha="center")
    c = cores.center
    span = np.ptp(c, axis=0).max() / 2 + 1.3
    mid = c.mean(axis=0)
    ax.set_xlim(mid[0] - span, mid[0] + span)
    ax.set_ylim(mid[1] - span / 3, mid[1] + span / 3)
    ax.set_zlim(mid[2] - span / 3, mid[2] + span / 3)
    ax.set_box_aspect((3, 1, 1), zoom=1.15)
    ax.view_init(elev=28, azim=-75)
    ax.set_axis_off()
    fig.subplots_adjust(left=0, right=1, bottom=0, top=1)
    fig.text(0.5, 0.68, "Linked tori: closest segments between neighbours (red) and their clearance",
             ha="center", fontsize=11)
    from matplotlib.transforms import Bbox
    fig.savefig(path, bbox_inches=Bbox([[0, 3.3], [10, 7.0]]))
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rings", type=int, default=7)
    ap.add_argument("--seed", type=int, default=3)
    ap.add_argument("--png", default="", help="write the picture to this file (default: none)")
    args = ap.parse_args(argv)
    cores, tube = make_chain(args.rings, args.seed)
    clearance, res = neighbours(cores, tube)
    print("pair  core distance        clearance            pairs equidistant")
    for i in range(len(clearance)):
        print("%2d-%-2d %.17f %+.17f %d     %s" % (i, i + 1, res.distance[i], clearance[i],
                                                  res.num_pairs[i], bool(res.equidistant[i])))
    print("tightest link: %d-%d, clearance %.6g%s" % (
        int(np.argmin(clearance)), int(np.argmin(clearance)) + 1, clearance.min(),
        " (overlap!)" if clearance.min() < 0 else ""))
    if args.png:
        draw(cores, tube, res, args.png)
        print("wrote", args.png)
    return clearance, res


if __name__ == "__main__":
    main()
