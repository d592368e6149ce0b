# SPDX-License-Identifier: MIT
"""The package as users get it: `meson install --destdir` imports with no environment variable
(the library path comes from the generated _build_config.py), and `pip wheel
--no-build-isolation --no-index` of the repository (meson-python) gives a platform wheel holding
the library and the tool, which imports in a fresh venv with no environment variable.

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


def _source_copy(dest):
    """The repository's files without build trees or git data (pip builds in the source dir)."""
    shutil.copytree(SOURCE_ROOT, dest, ignore=shutil.ignore_patterns(
        "build*", ".git", "__pycache__", ".mesonpy*", "*.egg-info"))
    return dest


@pytest.fixture(scope="module")
def wheel_venv(tmp_path_factory):
    """A platform wheel built by `pip wheel` from a copy of the repository, installed into a fresh
    venv (system site packages only for Debian's numpy)."""
    tmp = tmp_path_factory.mktemp("wheel")
    src = _source_copy(tmp / "src")
    wheels = tmp / "wheels"
    build = subprocess.run([PYTHON, "-m", "pip", "wheel", "--no-index", "--no-build-isolation", "--no-deps",
                            "-w", str(wheels), str(src)], capture_output=True, text=True)
    assert build.returncode == 0, build.stdout + build.stderr
    (whl,) = glob.glob(str(wheels / "circledist-*.whl"))
    venv = tmp / "venv"
    subprocess.run([PYTHON, "-m", "venv", "--system-site-packages", str(venv)], check=True)
    pip = subprocess.run([str(venv / "bin" / "python"), "-m", "pip", "install", "--no-index", "--no-deps", whl],
                         capture_output=True, text=True)
    assert pip.returncode == 0, pip.stdout + pip.stderr
    return whl, venv


def test_wheel_holds_the_library_and_the_tool(wheel_venv):
    import zipfile
    whl, _ = wheel_venv
    assert not whl.endswith("-none-any.whl"), "a pure wheel cannot hold the C library: " + whl
    names = zipfile.ZipFile(whl).namelist()
    for needed in ("circledist/libcircledist.so.1", "circledist/circledist", "circledist/__init__.py",
                   "circledist/__init__.pyi", "circledist/py.typed", "circledist/__main__.py"):
        assert needed in names, (needed, names)
    assert not [n for n in names if n.endswith((".h", ".pc", ".cmake"))], names


def test_wheel_imports_without_environment(wheel_venv, tmp_path):
    _, venv = wheel_venv
    out = subprocess.run([str(venv / "bin" / "python"), "-c", CHECK], env=_clean_env(), cwd=tmp_path,
                         capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    where = out.stdout.split("\n")
    assert where[0].startswith(str(venv)), where
    assert where[1] == os.path.join(os.path.dirname(where[0]), "libcircledist.so.1"), where


@pytest.mark.skipif(not BUILD_ROOT, reason="needs CIRCLEDIST_BUILD_ROOT (run through meson test)")
def test_python_m_circledist_is_the_tool(wheel_venv, tmp_path):
    _, venv = wheel_venv
    tool = os.path.join(BUILD_ROOT, "circledist")
    queries = os.path.join(SOURCE_ROOT, "examples", "queries.txt")
    for args in (["--help"], ["--version"], [queries], ["--format=json", queries], ["--format=table", queries],
                 ["--bogus-option"]):
        want = subprocess.run([tool] + args, capture_output=True, text=True, env=_clean_env(), cwd=tmp_path)
        got = subprocess.run([str(venv / "bin" / "python"), "-m", "circledist"] + args, capture_output=True,
                             text=True, env=_clean_env(), cwd=tmp_path)
        assert (got.returncode, got.stdout) == (want.returncode, want.stdout), args
        assert got.stderr == want.stderr, args


def test_import_error_lists_what_was_tried(tmp_path):
    missing = str(tmp_path / "nowhere" / "libcircledist.so.1")
    run = subprocess.run([PYTHON, "-c", "import circledist"], cwd=tmp_path, capture_output=True, text=True,
                         env=_clean_env(CIRCLEDIST_LIBRARY=missing,
                                        PYTHONPATH=os.path.join(SOURCE_ROOT, "python")))
    assert run.returncode != 0
    assert "ImportError" in run.stderr and "tried:" in run.stderr and missing in run.stderr
    assert "$CIRCLEDIST_LIBRARY" in run.stderr
