# SPDX-License-Identifier: MIT
"""pytest setup: the tests import the package from the source tree (python/), and meson sets
CIRCLEDIST_LIBRARY to the freshly built library (see tests/meson.build). The installed-package
test (test_install.py) runs its own interpreter without either."""
import os
import sys

SOURCE_ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(SOURCE_ROOT, "python"))
