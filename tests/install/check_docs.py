#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The man pages are valid roff (groff -ww, when installed) and complete: circledist(1) documents
every option and query kind that `circledist --help` lists; libcircledist(3) names every query
function (every CDIST_API function taking a cdist_result; a gradient form X_grad may be covered
by X's entry mentioning _grad) and every status of the header; the README's query table has a
row for every query function and every tool kind.

usage: check_docs.py SOURCE_DIR TOOL
"""
import os
import re
import shutil
import subprocess
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from checks import check, finish  # noqa: E402

src, tool = sys.argv[1:3]
pages = {name: os.path.join(src, "man", name + ".in") for name in ("circledist.1", "libcircledist.3")}
text = {}
for name, path in pages.items():
    raw = open(path).read()
    # roff escapes to plain text: \- is '-', font changes vanish.
    text[name] = re.sub(r"\\f[BIRP]", "", raw.replace("\\-", "-"))
    if shutil.which("groff"):
        p = subprocess.run(["groff", "-man", "-t", "-ww", "-z", path], capture_output=True, text=True)
        check(p.returncode == 0 and not p.stderr, "%s: groff warnings:\n%s" % (name, p.stderr))

helptext = subprocess.run([tool, "--help"], capture_output=True, text=True, check=True).stdout
options = set(re.findall(r"(?<![\w-])(--[a-z][a-z-]*|-[a-zA-Z])\b", helptext))
check(len(options) >= 2, "options found in --help: %s" % sorted(options))
for opt in sorted(options):
    check(re.search(r"(?<![\w-])" + re.escape(opt) + r"\b", text["circledist.1"]) is not None,
          "circledist.1 does not document %s" % opt)
for value in re.findall(r"--(?:method|format)=([a-z|]+)", helptext):
    for v in value.split("|"):
        check(v in text["circledist.1"], "circledist.1 does not mention '%s'" % v)
kinds = re.findall(r"^  ([A-Za-z][A-Za-z0-9]{1,3}) +\S", helptext.split("Query kinds")[-1], re.M)
check(len(kinds) >= 10, "query kinds found in --help: %d" % len(kinds))
for kind in kinds:
    check(re.search(r"^%s\t" % kind, text["circledist.1"], re.M) is not None,
          "circledist.1 does not list query kind %s" % kind)

header = re.sub(r"/\*.*?\*/", "", open(os.path.join(src, "include", "circledist.h")).read(), flags=re.S)
queries = [name for name, params in re.findall(r"CDIST_API\s[^;(]*?\b(cdist_\w+)\s*\(([^)]*)\)", header, re.S)
           if "cdist_result" in params]
check(len(queries) >= 20, "query functions found: %d" % len(queries))


def documented(q, doc):
    """q is named in doc; a gradient form X_grad may instead be covered by X's entry naming _grad."""
    if re.search(r"\b%s\b" % q, doc):
        return True
    line = re.search(r"^.*\b%s\b.*$" % q[:-len("_grad")], doc, re.M) if q.endswith("_grad") else None
    return line is not None and "_grad" in line.group(0)


for q in queries:
    check(documented(q, text["libcircledist.3"]), "libcircledist.3 does not name %s" % q)
status = re.search(r"typedef enum cdist_status \{(.*?)\}", header, re.S)
for name, number in re.findall(r"\b(CDIST_\w+)\s*=\s*(\d+)", status.group(1) if status else ""):
    check(re.search(r"^%s\t%s$" % (number, name), text["libcircledist.3"], re.M) is not None,
          "libcircledist.3 does not list status %s = %s" % (name, number))
readme = open(os.path.join(src, "README.md")).read()
table = "\n".join(line for line in readme.splitlines() if re.match(r"^\| `cdist_", line))
for q in queries:
    check(documented(q, table), "README query table has no row for %s" % q)
for kind in kinds:
    check("`%s`" % kind in table, "README query table does not give tool kind %s" % kind)

# The README's Python column names functions the package has (no "—" left for existing ones).
python_dir = os.path.join(src, "python")
if os.environ.get("CIRCLEDIST_LIBRARY") and os.path.isdir(python_dir):
    sys.path.insert(0, python_dir)
    import circledist  # noqa: E402
    for line in table.splitlines():
        py = line.rstrip(" |").rsplit(" | ", 1)[-1]
        for name in re.findall(r"`([a-z]\w*)`", py):
            check(hasattr(circledist, name), "README names Python function %s, which the package lacks" % name)
        check("—" not in py, "README row gives no Python name: " + line[:80])

# The README's two quick-start commands are what .ci/run runs: the first installs the
# dependencies with the same script, the second is the test command .ci/run calls.
quick = readme.split("## Quick start", 1)[-1].split("\n## ", 1)[0]
commands = [c.strip() for c in re.findall(r"^    (\S.*)$", quick, re.M)]
ci = open(os.path.join(src, ".ci", "run")).read()
ci_lines = [c.strip() for c in ci.splitlines() if c.strip() and not c.strip().startswith("#")]
check(len(commands) >= 2, "README quick start has %d commands" % len(commands))
if len(commands) >= 2:
    install = commands[0].split("&&")[0].strip()
    check(install in ci_lines, "README's install step '%s' is not a line of .ci/run" % install)
    test_cmds = [c for c in commands[1:] if "scripts/test.sh" in c]
    check(any(c in ci_lines for c in test_cmds),
          "no README test command %s is a line of .ci/run %s" % (test_cmds, ci_lines))
finish("check_docs")
