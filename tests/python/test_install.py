# SPDX-License-Identifier: MIT
"""The package as users get it: `meson install --destdir` imports with no environment variable
(the library path comes from the generated _build_config.py), and `pip install
--no-build-isolation --no-index` of python/ works with Debian's pip and setuptools.

Needs CIRCLEDIST_BUILD_ROOT (set by meson test)."""
import glob
import os
import shutil
import subprocess
import sys

import pytest

from conftest import SOURCE_ROOT

BUILD_ROOT = os.environ.get("CIRCLEDIST_BUILD_ROOT")
PYTHON = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable

CHECK = r"""
import os, sys, circledist as cd
assert "CIRCLEDIST_LIBRARY" not in os.environ
r = cd.point_circle((3, 4, 12), cd.Circle((0, 0, 0), (0, 0, 1), 2))
assert abs(r.distance ** 2 - 153) < 1e-12, r
print(cd.__file__)
print(cd._lib.lib._name)
"""


def _clean_env(**extra):
    env = {k: v for k, v in os.environ.items()
           if k not in ("CIRCLEDIST_LIBRARY", "PYTHONPATH", "LD_LIBRARY_PATH")}
    env.update(extra)
    return env


@pytest.mark.skipif(not BUILD_ROOT, reason="needs CIRCLEDIST_BUILD_ROOT (run through meson test)")
def test_meson_installed_package_finds_its_library(tmp_path):
    dest = tmp_path / "dest"
    subprocess.run(["meson", "install", "-C", BUILD_ROOT, "--no-rebuild", "--quiet",
                    "--destdir", str(dest)], check=True, capture_output=True)
    inits = glob.glob(str(dest / "**" / "circledist" / "__init__.py"), recursive=True)
    assert len(inits) == 1, inits
    site = os.path.dirname(os.path.dirname(inits[0]))
    assert os.path.exists(os.path.join(site, "circledist", "_build_config.py"))
    for typed in ("py.typed", "__init__.pyi"):
        assert os.path.exists(os.path.join(site, "circledist", typed))
    out = subprocess.run([PYTHON, "-c", CHECK], env=_clean_env(PYTHONPATH=site), cwd=tmp_path,
                         check=True, capture_output=True, text=True).stdout.split("\n")
    assert out[0].startswith(site)
    assert out[1].startswith(str(dest)), "loaded %s, not the library installed with the package" % out[1]


def test_pip_install_without_index(tmp_path):
    src = tmp_path / "src"
    shutil.copytree(os.path.join(SOURCE_ROOT, "python"), src)    # pip builds in the source dir
    venv = tmp_path / "venv"
    subprocess.run([PYTHON, "-m", "venv", "--system-site-packages", str(venv)], check=True)
    pip = subprocess.run([str(venv / "bin" / "python"), "-m", "pip", "install", "--no-build-isolation",
                          "--no-index", str(src)], capture_output=True, text=True)
    assert pip.returncode == 0, pip.stdout + pip.stderr
    lib = os.environ.get("CIRCLEDIST_LIBRARY")
    run = subprocess.run([str(venv / "bin" / "python"), "-c", "import circledist"],
                         env=_clean_env(), cwd=tmp_path, capture_output=True, text=True)
    if run.returncode != 0:  # no system library: the error must say what was tried
        assert "tried:" in run.stderr and "libcircledist.so.1" in run.stderr, run.stderr
    if lib:
        check = CHECK.replace('assert "CIRCLEDIST_LIBRARY" not in os.environ', "")
        out = subprocess.run([str(venv / "bin" / "python"), "-c", check], check=True, cwd=tmp_path,
                             env=_clean_env(CIRCLEDIST_LIBRARY=lib), capture_output=True, text=True)
        assert out.stdout.startswith(str(venv))


def test_import_error_lists_what_was_tried(tmp_path):
    missing = str(tmp_path / "nowhere" / "libcircledist.so.1")
    run = subprocess.run([PYTHON, "-c", "import circledist"], cwd=tmp_path, capture_output=True, text=True,
                         env=_clean_env(CIRCLEDIST_LIBRARY=missing,
                                        PYTHONPATH=os.path.join(SOURCE_ROOT, "python")))
    assert run.returncode != 0
    assert "ImportError" in run.stderr and "tried:" in run.stderr and missing in run.stderr
    assert "$CIRCLEDIST_LIBRARY" in run.stderr
