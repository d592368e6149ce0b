#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""A chain of linked tori that does not explode: it hangs from a fixed ring, starts out
horizontal, swings down and falls onto a peg.

Dynamics: position-based (Mueller et al.'s rigid-body PBD, Jacobi form, in numpy). Each link is
a rigid solid torus (core radius R, tube radius a) with a position and an axis (a torus is
symmetric about its axis, so the spin about it is left out); the fixed ring and the peg (a
capsule) do not move. Every substep predicts the free motion under gravity, then asks the
library's scene for the pairs within DELTA (cdist_scene_pairs_within: exact signed distances and
witness points of the torus-torus and torus-capsule contacts) and pushes every overlapping pair
apart along the contact normal; velocities are the position change over the substep.

Substeps: at the start of each frame the pairs within reach of the frame's motion get a time of
impact (circledist.time_of_impact, conservative advancement: it never tunnels) for reaching an
overlap of TOI_DEPTH under the links' current velocities; the frame is cut into enough substeps
that no substep's free motion reaches that depth, so a tube can never jump through another.

Self-checks, after every frame (circledist.chain_invariants, every pair of links, and the scene
for the peg): no two solids overlap by more than PENETRATION_TOL, and the linking number of
every neighbour pair is that of the first frame; besides, Scene.linked_pairs() finds no link
threaded through any but its two neighbours. A violation stops the run with exit status 1.

    python3 examples/chain.py [--links 120] [--frames 150] [--out DIR]

--out DIR writes chain.gif (matplotlib's PillowWriter; PNG frames instead when Pillow is
missing) and chain.png (the last frame) into DIR; without --out nothing is written. The README's
animation: `python3 examples/chain.py --links 120 --frames 150 --out docs/`.
"""
import argparse
import importlib.util
import os
import sys
import time

import numpy as np

import circledist as cd

R, TUBE = 1.0, 0.15                 # core and tube radius of every link
GAP = 0.02                          # initial clearance between neighbours' tubes
PITCH = 2 * R - 2 * TUBE - GAP      # centre spacing of the straight initial chain
GRAVITY = np.array([0.0, 0.0, -9.81 * 4])
DELTA = 0.01                        # contacts: pairs within this signed distance
PENETRATION_TOL = 0.5 * TUBE        # the stated tolerance: no overlap deeper than this
TOI_DEPTH = 0.25 * TUBE             # no substep's free motion may reach this overlap
DAMPING = 0.2                       # velocity damping per second
FPS = 30
PEG_RADIUS = 4.0
ITERATIONS = 3                      # projection passes per substep (each with fresh contacts)
RELAX = 1.0                         # Jacobi: a body's corrections averaged over its contacts


def axis_rotate(n, w):
    """Unit axes n (k, 3) rotated by rotation vectors w (k, 3) (Rodrigues)."""
    th = np.linalg.norm(w, axis=1)
    safe = np.where(th > 0, th, 1.0)
    k = w / safe[:, None]
    c, s = np.cos(th)[:, None], np.sin(th)[:, None]
    out = n * c + np.cross(k, n) * s + k * np.sum(k * n, axis=1)[:, None] * (1 - c)
    return out / np.linalg.norm(out, axis=1)[:, None]


class Chain:
    """State of the chain: body 0 is the fixed ring, bodies 1 .. n the links; the peg is the
    scene's last object."""

    def __init__(self, links, peg_at=None):
        n = links + 1
        self.n = n
        self.x = np.zeros((n, 3))
        self.x[:, 0] = PITCH * np.arange(n)
        self.axis = np.where((np.arange(n) % 2 == 0)[:, None], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0])
        rng = np.random.default_rng(1)   # a small tilt, so that the swing is not planar
        self.axis = axis_rotate(self.axis, rng.normal(scale=0.03, size=(n, 3)))
        self.v = np.zeros((n, 3))
        self.w = np.zeros((n, 3))
        self.inv_mass = np.ones(n)
        self.inv_mass[0] = 0.0
        # thin hoop of mass 1: I = R^2 about the axis, R^2 / 2 about a diameter
        self.inv_i_axis, self.inv_i_diam = self.inv_mass / R**2, 2 * self.inv_mass / R**2
        length = PITCH * links
        peg_x = 0.35 * length if peg_at is None else peg_at
        peg_z = -max(0.5 * length, PEG_RADIUS + 3 * R)   # below the straight chain
        self.peg = cd.Capsule(cd.Segment([peg_x, -6.0, peg_z], [peg_x, 6.0, peg_z]), PEG_RADIUS)
        self.scene = cd.Scene([self.tori(), self.peg])
        self.ids = np.arange(n)
        self.substeps = []

    def tori(self):
        return cd.Torus(cd.Circle(self.x, self.axis, R), TUBE)

    def inv_inertia_times(self, b, t):
        """World inverse inertia of bodies b applied to vectors t."""
        n = self.axis[b]
        along = np.sum(n * t, axis=1)[:, None] * n
        return self.inv_i_axis[b, None] * along + self.inv_i_diam[b, None] * (t - along)

    # ---- contacts --------------------------------------------------------------------------
    def contacts(self):
        """(i, j, distance, point_i, point_j, normal) of the pairs within DELTA; normal points
        from body i to j (j == n: the peg). Pairs of neighbours included (no skip filter)."""
        self.scene.update(self.ids, self.tori())
        p = self.scene.pairs_within(DELTA)
        if np.any(p.status != 0):
            raise RuntimeError("a contact could not be answered")
        i, j = p.i, p.j
        pi, pj = p.all_points[:, 0, 0], p.all_points[:, 0, 1]
        # The witness point on torus i is its closest core point plus TUBE times the normal,
        # and that core point is the projection of the witness point onto the core circle.
        q = pi - self.x[i]
        ax = self.axis[i]
        flat = q - np.sum(q * ax, axis=1)[:, None] * ax
        core = self.x[i] + R * flat / np.linalg.norm(flat, axis=1)[:, None]
        normal = (pi - core) / TUBE
        return i, j, p.distance, pi, pj, normal

    def project(self):
        """One Jacobi pass over the overlapping pairs: move each apart along its normal, the
        correction shared by the two bodies' generalized inverse masses."""
        i, j, d, pi, pj, nrm = self.contacts()
        hit = d < 0
        if not np.any(hit):
            return 0
        i, j, d, pi, pj, nrm = i[hit], j[hit], d[hit], pi[hit], pj[hit], nrm[hit]
        peg = j == self.n
        jb = np.where(peg, 0, j)              # the peg: no body (weight 0 below)
        ri, rj = pi - self.x[i], pj - self.x[jb]
        ci, cj = np.cross(ri, nrm), np.cross(rj, nrm)
        wi = self.inv_mass[i] + np.sum(ci * self.inv_inertia_times(i, ci), axis=1)
        wj = np.where(peg, 0.0, self.inv_mass[jb] + np.sum(cj * self.inv_inertia_times(jb, cj), axis=1))
        lam = -d / np.maximum(wi + wj, 1e-300)
        imp = lam[:, None] * nrm                 # pushes j along +normal, i along -normal
        dx = np.zeros_like(self.x)
        dw = np.zeros_like(self.x)
        cnt = np.zeros(self.n)
        np.add.at(dx, i, -imp * self.inv_mass[i, None])
        np.add.at(dw, i, -self.inv_inertia_times(i, np.cross(ri, imp)))
        np.add.at(cnt, i, 1)
        jm = ~peg
        np.add.at(dx, jb[jm], imp[jm] * self.inv_mass[jb[jm], None])
        np.add.at(dw, jb[jm], self.inv_inertia_times(jb[jm], np.cross(rj[jm], imp[jm])))
        np.add.at(cnt, jb[jm], 1)
        scale = RELAX / np.maximum(cnt, 1.0)[:, None]
        self.x += dx * scale
        self.axis = axis_rotate(self.axis, dw * scale)
        return int(hit.sum())

    # ---- time stepping ---------------------------------------------------------------------
    def substeps_for(self, dt, smallest=24, largest=400):
        """Substeps of the next frame: the earliest time of impact (overlap TOI_DEPTH) of the
        pairs within reach under the current velocities over dt (each pair also with either
        body held still), as a fraction of dt."""
        trans = self.v * dt + 0.5 * GRAVITY * dt**2 * (self.inv_mass[:, None] > 0)
        rot = self.w * dt
        reach = 2 * float(np.max(np.linalg.norm(trans, axis=1) + np.linalg.norm(rot, axis=1) * (R + TUBE)))
        p = self.scene.pairs_within(reach)
        t_first = 1.0
        if len(p):
            tori = self.tori()
            torus_pair = p.j < self.n
            i, j = p.i[torus_pair], p.j[torus_pair]
            if len(i):
                # Each pair three times: both moving, and each moving against the other held
                # still (a link stopped by the peg or by its neighbours mid-frame).
                i3, j3 = np.tile(i, 3), np.tile(j, 3)
                k = len(i)
                ti, tj, ri, rj = trans[i3].copy(), trans[j3].copy(), rot[i3].copy(), rot[j3].copy()
                ti[k:2 * k] = ri[k:2 * k] = 0.0
                tj[2 * k:] = rj[2 * k:] = 0.0
                a, b = cd.Torus.from_array(tori.data[i3]), cd.Torus.from_array(tori.data[j3])
                rec, st = cd.time_of_impact(a, b, (self.x[i3], ti, ri), (self.x[j3], tj, rj),
                                            target=-TOI_DEPTH, tolerance=1e-6)
                t_first = min(t_first, float(np.min(np.where(rec["state"] == cd.TOI_NONE, 1.0, rec["t"]))))
            k = p.i[~torus_pair]
            if len(k):
                rec, st = cd.time_of_impact(cd.Torus.from_array(tori.data[k]), self.peg, (self.x[k], trans[k], rot[k]),
                                            None, target=-TOI_DEPTH, tolerance=1e-6)
                t_first = min(t_first, float(np.min(np.where(rec["state"] == cd.TOI_NONE, 1.0, rec["t"]))))
        return int(np.clip(np.ceil(1.0 / max(t_first, 1e-9)), smallest, largest))

    def frame(self, dt):
        steps = self.substeps_for(dt)
        self.substeps.append(steps)
        h = dt / steps
        moving = self.inv_mass[:, None] > 0
        for _ in range(steps):
            x0, a0 = self.x.copy(), self.axis.copy()
            self.v += GRAVITY * h * moving
            self.x += self.v * h
            self.axis = axis_rotate(self.axis, self.w * h)
            for _ in range(ITERATIONS):
                if self.project() == 0:
                    break
            self.v = (self.x - x0) / h * (1 - DAMPING * h)
            # the axis' turn over the substep (the spin about the axis is not tracked)
            self.w = np.cross(a0, self.axis) / h * (1 - DAMPING * h)
        return steps


def check(chain, expected, frame):
    """The run's two invariants; returns (max overlap depth, neighbour linking numbers)."""
    inv = cd.chain_invariants(chain.tori(), expected)
    chain.scene.update(chain.ids, chain.tori())
    peg_pairs = chain.scene.within(chain.peg, 0.0)
    peg_depth = float(np.max(-peg_pairs.distance[peg_pairs.i < chain.n], initial=0.0))
    depth = max(inv["max_penetration"], peg_depth)
    if not inv["status_ok"]:
        raise SystemExit("frame %d: a link is not a valid torus" % frame)
    if depth > PENETRATION_TOL:
        raise SystemExit("frame %d: overlap %.4g > tolerance %.4g (pair %s)"
                         % (frame, depth, PENETRATION_TOL, inv["worst_pair"]))
    if not inv["linking_kept"]:
        bad = np.nonzero(inv["neighbour_linking"] != expected)[0]
        raise SystemExit("frame %d: neighbours %s are no longer linked as at the start" % (frame, bad[:5]))
    # and no link is threaded through any but its neighbours (the scene's linked pairs)
    links = chain.scene.linked_pairs()
    threaded = links.core_linking != 0
    if not np.array_equal(links.j[threaded] - links.i[threaded], np.ones(chain.n - 1, dtype=np.int64)):
        far = [(int(a), int(b)) for a, b in zip(links.i[threaded], links.j[threaded]) if b != a + 1]
        raise SystemExit("frame %d: links threaded through non-neighbours: %s" % (frame, far[:5]))
    return depth, inv["neighbour_linking"]


def draw(ax, chain, title):
    """Side view (x, z): each link's core circle as a band of the tube's width."""
    from matplotlib.collections import LineCollection
    from matplotlib.patches import Circle as Disc
    t = np.linspace(0, 2 * np.pi, 41)
    n = chain.axis
    u = np.cross(n, [0.0, 1.0, 0.0])
    u_bad = np.linalg.norm(u, axis=1) < 1e-6
    u[u_bad] = np.cross(n[u_bad], [1.0, 0.0, 0.0])
    u /= np.linalg.norm(u, axis=1)[:, None]
    v = np.cross(n, u)
    pts = chain.x[:, None, :] + R * (np.cos(t)[None, :, None] * u[:, None, :] + np.sin(t)[None, :, None] * v[:, None, :])
    segs = pts[:, :, [0, 2]]
    colours = np.where((np.arange(chain.n) % 2 == 0)[:, None], [0.15, 0.35, 0.7, 1.0], [0.8, 0.45, 0.1, 1.0])
    colours[0] = [0.1, 0.1, 0.1, 1.0]
    ax.add_collection(LineCollection(segs, colors=colours, linewidths=1.6))
    p0 = chain.peg.data[:3]
    ax.add_patch(Disc((p0[0], p0[2]), PEG_RADIUS, color="0.55", zorder=0))
    ax.set_title(title, fontsize=9)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--links", type=int, default=120)
    ap.add_argument("--frames", type=int, default=150)
    ap.add_argument("--out", default=None, help="directory for chain.gif and chain.png (default: write nothing)")
    ap.add_argument("--quiet", action="store_true")
    args = ap.parse_args(argv)
    chain = Chain(args.links)
    expected = cd.chain_invariants(chain.tori())["neighbour_linking"]
    if not np.all(np.abs(expected) == 1):
        raise SystemExit("the initial chain is not linked")
    keep = args.out is not None
    frames = [(chain.x.copy(), chain.axis.copy())] if keep else []
    worst = 0.0
    steps = 0
    t0 = time.perf_counter()
    sim_time = 0.0
    for f in range(args.frames):
        s0 = time.perf_counter()
        steps += chain.frame(1.0 / FPS)
        sim_time += time.perf_counter() - s0
        depth, _ = check(chain, expected, f)
        worst = max(worst, depth)
        if keep:
            frames.append((chain.x.copy(), chain.axis.copy()))
        if not args.quiet and (f % 10 == 0 or f == args.frames - 1):
            print("frame %4d  substeps %3d  deepest overlap %.2e" % (f, chain.substeps[-1], depth))
    total = time.perf_counter() - t0
    summary = {"links": args.links, "frames": args.frames, "substeps": steps, "max_overlap": worst,
               "tolerance": PENETRATION_TOL, "linked": True,
               "ms_per_substep": 1e3 * sim_time / max(steps, 1), "ms_per_frame": 1e3 * sim_time / max(args.frames, 1),
               "final": chain.tori(), "initial_linking": expected}
    print("%d links, %d frames, %d substeps: deepest overlap %.3g (tolerance %.3g), every neighbour pair linked;"
          " %.2f ms per substep, %.1f ms per frame (checks: %.1f s)"
          % (args.links, args.frames, steps, worst, PENETRATION_TOL, summary["ms_per_substep"],
             summary["ms_per_frame"], total - sim_time))
    if keep:
        write(args.out, chain, frames)
    return summary


def write(out, chain, frames):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib import animation
    os.makedirs(out, exist_ok=True)
    allx = np.concatenate([x for x, _ in frames])
    lo, hi = allx.min(axis=0) - 2 * R, allx.max(axis=0) + 2 * R
    fig, ax = plt.subplots(figsize=(6, 5), dpi=80)

    def show(k):
        ax.clear()
        chain.x, chain.axis = frames[k]
        draw(ax, chain, "%d linked tori, t = %.2f s" % (chain.n - 1, k / FPS))
        ax.set_xlim(lo[0], hi[0])
        ax.set_ylim(lo[2], max(hi[2], 2 * R))
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
    if importlib.util.find_spec("PIL") is not None:   # PillowWriter needs Pillow
        anim = animation.FuncAnimation(fig, show, frames=range(0, len(frames), 2))
        anim.save(os.path.join(out, "chain.gif"), writer=animation.PillowWriter(fps=FPS // 2))
    else:
        for k in range(0, len(frames), 2):
            show(k)
            fig.savefig(os.path.join(out, "chain_%04d.png" % k))
    show(len(frames) - 1)
    fig.savefig(os.path.join(out, "chain.png"))
    plt.close(fig)


if __name__ == "__main__":
    main(sys.argv[1:])
