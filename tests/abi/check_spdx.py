#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Every source file carries an SPDX licence line near its top, naming the project's licence.

usage: check_spdx.py SOURCE_ROOT
Sources: *.c *.h *.cpp *.py *.sh *.h.in, meson.build, meson_options.txt and scripts starting
with '#!'. Build directories (they hold meson-private/), .git and __pycache__ are skipped.
"""
import os
import re
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from checks import check, finish  # noqa: E402

root = sys.argv[1]
SUFFIXES = (".c", ".h", ".cpp", ".py", ".sh", ".h.in")
NAMES = ("meson.build", "meson_options.txt", "meson.options")
HEAD_LINES = 3  # a shebang, then the SPDX line (or the SPDX line first)
licence = re.search(r"license:\s*'([^']+)'", open(os.path.join(root, "meson.build")).read())
check(licence is not None, "meson.build declares a license")
want = "SPDX-License-Identifier: " + (licence.group(1) if licence else "?")
check(os.path.isfile(os.path.join(root, "LICENSE")), "LICENSE file present")

sources = []
for d, subdirs, files in os.walk(root):
    if "meson-private" in subdirs or "meson-info" in subdirs:
        subdirs[:] = []
        continue
    subdirs[:] = [s for s in subdirs if s not in (".git", "__pycache__", "subprojects")]
    for f in files:
        path = os.path.join(d, f)
        if f.endswith(SUFFIXES) or f in NAMES:
            sources.append(path)
        elif os.access(path, os.X_OK):
            with open(path, "rb") as fh:
                if fh.read(2) == b"#!":
                    sources.append(path)

check(len(sources) > 50, "sources found: %d" % len(sources))
for path in sorted(sources):
    with open(path, errors="replace") as fh:
        head = [fh.readline() for _ in range(HEAD_LINES)]
    check(any(want in line for line in head),
          "%s: no '%s' in its first %d lines" % (os.path.relpath(path, root), want, HEAD_LINES))
finish("check_spdx")
