# SPDX-License-Identifier: MIT
"""Prints where `meson install` puts the circledist package for PREFIX, then 'searched' or
'not-searched': the first directory of this interpreter's search path that lies in PREFIX's lib
directory (Debian: /usr/lib/python3/dist-packages for /usr, /usr/local/lib/python3.X/dist-packages
for /usr/local), else the standard <prefix>/lib/python3.X/site-packages.

usage: site_dir.py PREFIX"""
import os
import sys
import sysconfig

prefix = os.path.normpath(sys.argv[1])
lib = os.path.join(prefix, "lib") + os.sep
for entry in sys.path:
    if entry and os.path.normpath(entry).startswith(lib) and entry.rstrip("/").endswith(("-packages")):
        print(os.path.normpath(entry))
        print("searched")
        break
else:
    print(sysconfig.get_path("purelib", "posix_prefix", vars={"base": prefix, "platbase": prefix}))
    print("not-searched")
