#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The layers of src/ run in one direction (docs/architecture.md):
    base <- api <- point <- lines <- circles <- curves <- swept <- topology <- batch, scene
A file may include, and an object file may call, only its own folder and lower layers, and the
folders form no cycle. Checked on every `#include "..."` of src/**/*.{c,h} (src/internal.h, the
umbrella header, counts as the headers it includes) and, when the library's static archive is
given, on every object's undefined symbols (nm) against the folder that defines them. Prints
every offending edge with the file or symbol behind it.

usage: check_layers.py SOURCE_ROOT [libcircledist_internal.a]
       check_layers.py --self-test   (the checker finds an upward include and a cycle)"""
import os
import re
import subprocess
import sys

LAYER = {"base": 0, "api": 1, "point": 2, "lines": 3, "circles": 4, "curves": 5, "swept": 6,
         "topology": 7, "batch": 8, "scene": 8}
UMBRELLA = "internal.h"

# Edges allowed although they run upward (none: every layer calls only its own folder and lower
# ones). The test fails when an edge here no longer occurs, so the list only shrinks.
ALLOWED = set()

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def folder_of(rel):
    """'api/query.c' -> 'api' (src/base/lanes/... -> 'base'); the umbrella -> None."""
    head = rel.split("/", 1)[0]
    return head if "/" in rel else None


def resolve(src, rel_dir, name):
    """The src-relative path an include names (its own folder first, then src/), or None for a
    header outside src/ (the public header, system and generated headers)."""
    for cand in (os.path.normpath(os.path.join(rel_dir, name)), os.path.normpath(name)):
        if os.path.isfile(os.path.join(src, cand)):
            return cand
    return None


def include_edges(src):
    """(from folder, to folder, why) for every include between folders."""
    files = {}
    for dirpath, _, names in os.walk(src):
        for n in names:
            if n.endswith((".c", ".h", ".def")):
                full = os.path.join(dirpath, n)
                files[os.path.relpath(full, src)] = open(full, encoding="utf-8").read()
    direct = {rel: [r for r in (resolve(src, os.path.dirname(rel), m) for m in INCLUDE.findall(text)) if r]
              for rel, text in files.items()}

    def expand(rel, seen):
        """Includes of rel with the umbrella replaced by what it includes."""
        for r in direct.get(rel, []):
            if r == UMBRELLA:
                if r not in seen:
                    seen.add(r)
                    for x in expand(r, seen):
                        yield x[0], "via " + UMBRELLA
            else:
                yield r, ""

    edges = []
    for rel in sorted(files):
        f = folder_of(rel)
        if f is None:
            continue
        for to, via in expand(rel, set()):
            t = folder_of(to)
            if t is not None and t != f:
                edges.append((f, t, "%s includes %s%s" % (rel, to, " " + via if via else "")))
    return edges


def symbol_edges(archive):
    """(from folder, to folder, why) for every call or reference between folders, from nm."""
    out = subprocess.run(["nm", "-A", archive], check=True, capture_output=True, text=True).stdout
    defined, used = {}, []
    for line in out.splitlines():
        m = re.match(r"^[^:]*:([^:]+):\s*(?:[0-9a-fA-F]+)?\s+([A-Za-z])\s+(\S+)$", line)
        if not m:
            continue
        member, kind, sym = m.groups()
        member = os.path.basename(member)  # a thin archive names its members by path
        parts = member.split("_")
        if len(parts) < 3 or parts[0] != "src" or parts[1] not in LAYER:
            continue
        folder = parts[1]
        if kind == "U":
            used.append((folder, sym, member))
        elif kind.isupper() or kind == "i":
            defined.setdefault(sym, folder)
    edges = []
    for folder, sym, member in used:
        t = defined.get(sym)
        if t is not None and t != folder:
            edges.append((folder, t, "%s calls %s" % (member, sym)))
    return edges


def cycles(edges):
    """Strongly connected sets of more than one folder."""
    graph = {}
    for f, t, _ in edges:
        graph.setdefault(f, set()).add(t)
        graph.setdefault(t, set())
    index, low, stack, on, found = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                found.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def self_test():
    """A made-up tree with one upward include and one cycle at the same layer: both reported."""
    import io
    import contextlib
    import tempfile
    tree = {"base/a.h": '#include "api/b.h"\n', "api/b.h": "", "batch/x.c": '#include "scene/y.h"\n',
            "scene/y.h": "", "scene/y.c": '#include "batch/z.h"\n', "batch/z.h": "",
            "point/p.c": '#include "internal.h"\n', "internal.h": '#include "lines/l.h"\n', "lines/l.h": ""}
    with tempfile.TemporaryDirectory() as root:
        for rel, text in tree.items():
            os.makedirs(os.path.dirname(os.path.join(root, "src", rel)), exist_ok=True)
            open(os.path.join(root, "src", rel), "w").write(text)
        out = io.StringIO()
        sys.argv = [sys.argv[0], root]
        with contextlib.redirect_stdout(out):
            status = main(allowed={})
    text = out.getvalue()
    expect = ["base -> api: base/a.h includes api/b.h", "cycle between folders batch, scene",
              "point -> lines: point/p.c includes lines/l.h via internal.h"]
    missing = [e for e in expect if e not in text]
    print(text, end="")
    if status != 1 or missing:
        print("self-test: the checker missed %s (status %d)" % (missing, status))
        return 1
    print("self-test: the checker reports the upward edges and the cycle")
    return 0


def main(allowed=None):
    global ALLOWED
    if allowed is not None:
        ALLOWED = allowed
    root = sys.argv[1]
    src = os.path.join(root, "src")
    edges = include_edges(src)
    if len(sys.argv) > 2:
        edges += symbol_edges(sys.argv[2])
    live = [e for e in edges if (e[0], e[1]) not in ALLOWED]
    by_pair = {}
    for f, t, why in live:
        by_pair.setdefault((f, t), set()).add(why)

    def show(f, t):
        whys = sorted(by_pair[(f, t)])
        more = " (and %d more)" % (len(whys) - 1) if len(whys) > 1 else ""
        print("  %s -> %s: %s%s" % (f, t, whys[0], more))

    failed = False
    upward = sorted(p for p in by_pair if LAYER[p[1]] > LAYER[p[0]])
    if upward:
        print("upward edges (a layer includes or calls a higher one):")
        for f, t in upward:
            show(f, t)
        failed = True
    for comp in cycles(live):
        print("cycle between folders %s:" % ", ".join(comp))
        for f, t in sorted(p for p in by_pair if p[0] in comp and p[1] in comp and LAYER[p[1]] >= LAYER[p[0]]):
            show(f, t)
        failed = True
    seen = {(e[0], e[1]) for e in edges}
    for f, t in sorted(set(ALLOWED) - seen):
        print("allowed edge %s -> %s no longer occurs: remove it from ALLOWED" % (f, t))
        failed = True
    folders = sorted({f for e in edges for f in e[:2]})
    print("%d edges between %d folders checked%s" % (len(edges), len(folders),
                                                     "" if len(sys.argv) > 2 else " (includes only)"))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(self_test() if sys.argv[1:] == ["--self-test"] else main())
