#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Every tolerance of src/ is named once, in src/base/tolerances.h, with its unit and reason.
A tolerance written in place is a short decimal literal in exponent form (1e-9, 5e-3, 1e3: at
most two significant digits), outside comments and strings; long ones are exact table values
(polynomial coefficients, cos and sin of fixed angles) and hexadecimal ones (0x1p-1022) are
range guards of the floating-point format. Prints every such literal with its file and line.

usage: check_tolerances.py SOURCE_ROOT
       check_tolerances.py --self-test   (the checker finds a literal in code, none in a comment)"""
import os
import re
import sys

NAMED_IN = os.path.join("base", "tolerances.h")
LITERAL = re.compile(r"(?<![\w.])\d(?:\.\d)?[eE][-+]?\d+(?![\w.])")
# comments and string/char literals, replaced by blanks of the same line count
HIDDEN = re.compile(r'/\*.*?\*/|//[^\n]*|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'', re.S)


def literals(text):
    """(line, literal) of every in-place tolerance of a C source text."""
    code = HIDDEN.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)
    out = []
    for no, line in enumerate(code.split("\n"), 1):
        out.extend((no, m.group(0)) for m in LITERAL.finditer(line))
    return out


def scan(src):
    found = []
    for root, _, files in os.walk(src):
        for name in sorted(files):
            if not name.endswith((".c", ".h")):
                continue
            path = os.path.join(root, name)
            if os.path.relpath(path, src) == NAMED_IN:
                continue
            with open(path, encoding="utf-8") as f:
                found.extend((os.path.relpath(path, src), no, lit) for no, lit in literals(f.read()))
    return found


def self_test():
    text = ('/* 1e-9 in a comment */\nx = "1e-3";\nif (d <= 1e-9 * L) y = 6.123233995736766e-17;\n'
            "z = 0x1p-1022; w = 2.5e3; // 1e-6\n")
    got = literals(text)
    want = [(3, "1e-9"), (4, "2.5e3")]
    if got != want:
        print(f"FAIL: self-test found {got}, expected {want}")
        return 1
    print("ok: self-test")
    return 0


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    found = scan(os.path.join(sys.argv[1], "src"))
    for rel, no, lit in found:
        print(f"FAIL: src/{rel}:{no}: tolerance {lit} written in place (name it in src/{NAMED_IN})")
    if not found:
        print("ok: every tolerance of src/ is named in src/base/tolerances.h")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
