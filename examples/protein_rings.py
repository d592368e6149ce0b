#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Aromatic rings of a protein: exact ring-ring geometry against the centroid/angle heuristic.

Each aromatic ring of PHE, TYR, TRP (its five- and six-membered rings) and HIS becomes a disk:
centre = centroid of the ring atoms, normal = the least-squares plane's normal, radius = the mean
distance of the ring atoms from the centroid. The script reports

- every pair of rings (of different residues) whose disks come within 7.5 Å, with the exact disk-disk distance and closest
  points (circledist.disk_disk), and
- every covalent bond (two heavy atoms closer than 1.9 Å; bonds touching the ring's own atoms
  are left out) that pierces a ring: segment-disk distance 0 (circledist.segment_disk),

and compares the pairs with the pi-stacking heuristic of PLIP (centroid distance below
PISTACK_DIST_MAX = 5.5 Å, normals within PISTACK_ANG_DEV = 30° of parallel or perpendicular,
centroid offset below PISTACK_OFFSET_MAX = 2.0 Å; the constants are read from Debian's `plip`
when it is installed). Rings are "in contact" when their disks come within CONTACT = 4.0 Å;
the disagreements listed are the pairs in contact that the heuristic misses and the pairs the
heuristic accepts whose disks are farther apart than that.

Input: a PDB file (default: 1tii.pdb of Debian's pymol-data,
/usr/share/pymol/data/demo/1tii.pdb). Without the file the ring table shipped with the
examples (examples/data/1tii_rings.tsv, made by `--write-table` from that file) is used, and
the bond check is skipped (it needs the atoms).

    python3 examples/protein_rings.py [PDB] [--within 7.5] [--write-table FILE]
"""
import argparse
import itertools
import math
import os
import sys

import numpy as np

import circledist as cd

DEFAULT_PDB = "/usr/share/pymol/data/demo/1tii.pdb"
SHIPPED_TABLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", "1tii_rings.tsv")
#: Ring atoms per residue; TRP has two rings.
RING_ATOMS = {
    "PHE": [("CG", "CD1", "CD2", "CE1", "CE2", "CZ")],
    "TYR": [("CG", "CD1", "CD2", "CE1", "CE2", "CZ")],
    "TRP": [("CG", "CD1", "NE1", "CE2", "CD2"), ("CD2", "CE2", "CE3", "CZ2", "CZ3", "CH2")],
    "HIS": [("CG", "ND1", "CD2", "CE1", "NE2")],
}
BOND_MAX = 1.9   # Å: heavy atoms closer than this are taken as covalently bonded
CONTACT = 4.0    # Å: disks closer than this are "in contact" for the comparison


def plip_constants():
    """PLIP's pi-stacking thresholds: from Debian's plip when installed, else its documented values."""
    try:
        from plip.basic import config
        return dict(source="plip.basic.config", dist_max=config.PISTACK_DIST_MAX,
                    ang_dev=config.PISTACK_ANG_DEV, offset_max=config.PISTACK_OFFSET_MAX,
                    min_dist=config.MIN_DIST)
    except ImportError:
        return dict(source="PLIP 2.2 defaults", dist_max=5.5, ang_dev=30.0, offset_max=2.0, min_dist=0.5)


def read_pdb(path):
    """Atoms of the first model: list of (chain, resseq, resname, atom name, element, xyz)."""
    atoms = []
    with open(path) as f:
        for line in f:
            if line.startswith("ENDMDL"):
                break
            if line.startswith(("ATOM  ", "HETATM")):
                altloc = line[16]
                if altloc not in (" ", "A"):
                    continue
                element = line[76:78].strip() or line[12:14].strip()
                atoms.append((line[21], line[22:27].strip(), line[17:20], line[12:16].strip(), element,
                              (float(line[30:38]), float(line[38:46]), float(line[46:54]))))
    return atoms


def ring_disks(atoms):
    """The aromatic rings: labels, member atom indices, centres (N, 3), unit normals (N, 3), radii (N,)."""
    by_residue = {}
    for i, (chain, resseq, resname, name, _, _) in enumerate(atoms):
        by_residue.setdefault((chain, resseq, resname), {})[name] = i
    labels, members, centres, normals, radii = [], [], [], [], []
    for (chain, resseq, resname), names in by_residue.items():
        for k, ring in enumerate(RING_ATOMS.get(resname, [])):
            if not all(n in names for n in ring):
                continue
            idx = [names[n] for n in ring]
            xyz = np.array([atoms[i][5] for i in idx])
            c = xyz.mean(axis=0)
            normal = np.linalg.svd(xyz - c)[2][2]        # least-squares plane
            labels.append("%s%s:%s%s" % (resname, resseq, chain, "" if len(RING_ATOMS[resname]) == 1 else "/%d" % len(ring)))
            members.append(idx)
            centres.append(c)
            normals.append(normal / np.linalg.norm(normal))
            radii.append(np.linalg.norm(xyz - c, axis=1).mean())
    return labels, members, np.array(centres), np.array(normals), np.array(radii)


def bonds(atoms):
    """Covalent bonds by distance between heavy atoms: (M, 2) atom indices."""
    heavy = np.array([i for i, a in enumerate(atoms) if a[4] != "H"])
    xyz = np.array([atoms[i][5] for i in heavy])
    out = []
    for start in range(0, len(xyz), 512):     # blocks keep the distance matrix small
        d = np.linalg.norm(xyz[start:start + 512, None, :] - xyz[None, :, :], axis=2)
        i, j = np.nonzero((d < BOND_MAX) & (d > 0))
        keep = start + i < j
        out.append(np.stack([heavy[start + i[keep]], heavy[j[keep]]], axis=1))
    return np.concatenate(out) if out else np.zeros((0, 2), int)


def heuristic(ci, ni, cj, nj, k):
    """PLIP's pi-stacking test on two rings: (passed, centroid distance, angle in degrees, offset)."""
    d = float(np.linalg.norm(ci - cj))
    b = math.degrees(math.acos(max(-1.0, min(1.0, float(np.dot(ni, nj))))))
    a = min(b, 180 - b)
    off = min(np.linalg.norm((cj - ci) - np.dot(cj - ci, ni) * ni),
              np.linalg.norm((ci - cj) - np.dot(ci - cj, nj) * nj))
    ok = k["min_dist"] < d < k["dist_max"] and off < k["offset_max"] and (
        0 <= a < k["ang_dev"] or 90 - k["ang_dev"] < a < 90 + k["ang_dev"])
    return ok, d, a, float(off)


def residue(label):
    return label.split("/")[0]


def ring_pairs(labels, centres, normals, radii, within):
    """Every pair of rings of different residues (TRP's two rings share an edge) whose disks come
    within `within`: i, j, distances, closest points (K, 2, 3)."""
    n = len(radii)
    pairs = [(a, b) for a, b in itertools.combinations(range(n), 2) if residue(labels[a]) != residue(labels[b])]
    i, j = np.array(pairs, dtype=int).reshape(-1, 2).T
    res = cd.disk_disk(cd.Disk(centres[i], normals[i], radii[i]), cd.Disk(centres[j], normals[j], radii[j]))
    close = res.distance <= within
    return i[close], j[close], res.distance[close], res.points[close, 0]


def pierced(atoms, members, centres, normals, radii):
    """(ring index, atom i, atom j, distance) for every bond whose segment meets a ring's disk."""
    b = bonds(atoms)
    xyz = np.array([a[5] for a in atoms])
    found = []
    for r, idx in enumerate(members):
        mask = ~np.isin(b, idx).any(axis=1)
        near = mask & (np.linalg.norm(xyz[b[:, 0]] - centres[r], axis=1) < radii[r] + 2 * BOND_MAX)
        if not near.any():
            continue
        bb = b[near]
        res = cd.segment_disk(cd.Segment(xyz[bb[:, 0]], xyz[bb[:, 1]]), cd.Disk(centres[r], normals[r], radii[r]))
        for k in np.nonzero(res.distance == 0)[0]:
            found.append((r, int(bb[k, 0]), int(bb[k, 1]), float(res.distance[k])))
    return found, len(b)


def fmt3(p):
    return "(%.3f, %.3f, %.3f)" % tuple(p)


def write_table(path, source, labels, centres, normals, radii):
    with open(path, "w") as f:
        f.write("# Aromatic rings of %s as disks (centre, unit normal, radius; Å), made by\n"
                "# examples/protein_rings.py --write-table from Debian's pymol-data 2.5.0.\n" % source)
        f.write("label\tcx\tcy\tcz\tnx\tny\tnz\tradius\n")
        for row in zip(labels, centres, normals, radii):
            f.write("%s\t%s\t%s\t%r\n" % (row[0], "\t".join(repr(float(x)) for x in row[1]),
                                         "\t".join(repr(float(x)) for x in row[2]), float(row[3])))


def read_table(path):
    rows = [line.rstrip("\n").split("\t") for line in open(path) if not line.startswith(("#", "label"))]
    labels = [r[0] for r in rows]
    v = np.array([[float(x) for x in r[1:]] for r in rows])
    return labels, v[:, 0:3], v[:, 3:6], v[:, 6]


def analyse(pdb=DEFAULT_PDB, within=7.5, out=sys.stdout, table=None):
    """Runs the whole comparison; returns a dict with the pairs, disagreements and pierced bonds."""
    k = plip_constants()
    if pdb and os.path.exists(pdb):
        atoms = read_pdb(pdb)
        labels, members, centres, normals, radii = ring_disks(atoms)
        source = os.path.basename(pdb)
        if table:
            write_table(table, source, labels, centres, normals, radii)
    else:
        out.write("note: %s not found (install Debian's pymol-data); using the shipped ring table %s; "
                  "the bond check needs the atoms and is skipped\n" % (pdb, SHIPPED_TABLE))
        atoms = None
        labels, centres, normals, radii = read_table(SHIPPED_TABLE)
        source = os.path.basename(SHIPPED_TABLE)
    i, j, dist, points = ring_pairs(labels, centres, normals, radii, within)
    out.write("%s: %d aromatic rings, %d pairs within %.1f Å (PLIP thresholds from %s)\n"
              % (source, len(labels), len(i), within, k["source"]))
    out.write("%-14s %-14s %9s %9s %7s %7s %5s\n" % ("ring", "ring", "disk d/Å", "centr/Å", "angle", "offset", "PLIP"))
    rows, missed, extra = [], [], []
    for n, (a, b) in enumerate(zip(i, j)):
        ok, dc, ang, off = heuristic(centres[a], normals[a], centres[b], normals[b], k)
        d = float(dist[n])
        rows.append((labels[a], labels[b], d, dc, ang, off, ok, points[n]))
        out.write("%-14s %-14s %9.4f %9.4f %7.1f %7.2f %5s\n" % (labels[a], labels[b], d, dc, ang, off, "yes" if ok else "no"))
        if d <= CONTACT and not ok:
            missed.append(rows[-1])
        if ok and d > CONTACT:
            extra.append(rows[-1])
    out.write("\nIn contact (disks within %.1f Å) but not pi-stacked for the heuristic: %d\n" % (CONTACT, len(missed)))
    for r in missed:
        out.write("  %s - %s: disks %.3f Å apart (closest points %s - %s), centroids %.2f Å, angle %.0f°, offset %.2f Å\n"
                  % (r[0], r[1], r[2], fmt3(r[7][0]), fmt3(r[7][1]), r[3], r[4], r[5]))
    out.write("Pi-stacked for the heuristic: %d pairs; of them with disks more than %.1f Å apart: %d\n"
              % (sum(r[6] for r in rows), CONTACT, len(extra)))
    for r in extra:
        out.write("  %s - %s: disks %.3f Å apart, centroids %.2f Å, angle %.0f°, offset %.2f Å\n"
                  % (r[0], r[1], r[2], r[3], r[4], r[5]))
    result = dict(labels=labels, centres=centres, normals=normals, radii=radii, pairs=rows,
                  missed=missed, extra=extra, pierced=None)
    if atoms is not None:
        found, nbonds = pierced(atoms, members, centres, normals, radii)
        out.write("\nBonds (%d, heavy atoms < %.1f Å) piercing a ring's disk: %d\n" % (nbonds, BOND_MAX, len(found)))
        for r, a, b, _ in found:
            out.write("  %s pierced by %s %s%s-%s %s%s\n" % (labels[r], atoms[a][2], atoms[a][1], atoms[a][3],
                                                           atoms[b][2], atoms[b][1], atoms[b][3]))
        result["pierced"] = found
    return result


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("pdb", nargs="?", default=DEFAULT_PDB)
    ap.add_argument("--within", type=float, default=7.5, help="report ring pairs whose disks are this close (Å)")
    ap.add_argument("--write-table", default=None, help="write the ring table (TSV) to this file")
    args = ap.parse_args(argv)
    return analyse(args.pdb, args.within, table=args.write_table)


if __name__ == "__main__":
    main()
