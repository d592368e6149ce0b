#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""test_layout.c asserts every public struct (its size and every field's offset) and every
public enumerator's number: a struct, field or enumerator added to the header without its
assertion fails here.

usage: check_layout_coverage.py HEADER TEST_LAYOUT_C
"""
import os
import re
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from checks import check, finish  # noqa: E402

header, layout = sys.argv[1:3]
hdr = re.sub(r"/\*.*?\*/", "", open(header).read(), flags=re.S)
test = open(layout).read()
sizes = set(re.findall(r"\bSIZE\((\w+),", test))
offsets = set(re.findall(r"\bOFF\((\w+), (\w+),", test))
values = set(re.findall(r"\bVALUE\((\w+),", test))

structs = re.findall(r"typedef struct (\w+) \{(.*?)\}\s*\w+;", hdr, re.S)
check(len(structs) >= 10, "public structs found: %d" % len(structs))
for name, body in structs:
    check(name in sizes, "test_layout.c: no SIZE(%s, ...)" % name)
    for decl in body.split(";"):
        field = re.search(r"(\w+)\s*(\[[^]]*\])?\s*$", decl.strip())
        if field:
            check((name, field.group(1)) in offsets, "test_layout.c: no OFF(%s, %s, ...)" % (name, field.group(1)))
enums = re.findall(r"typedef enum (\w+) \{(.*?)\}", hdr, re.S)
check(len(enums) >= 2, "public enums found: %d" % len(enums))
for name, body in enums:
    check(name in sizes, "test_layout.c: no SIZE(%s, ...)" % name)
    for enumerator in re.findall(r"\b(CDIST_\w+)\s*=", body):
        check(enumerator in values, "test_layout.c: no VALUE(%s, ...)" % enumerator)
    check(not re.search(r"\bCDIST_\w+\s*[,}]", body + "}"), "%s: every enumerator has an explicit number" % name)
finish("check_layout_coverage")
