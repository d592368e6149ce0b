# SPDX-License-Identifier: MIT
"""The type stubs: generated from the package's tables (no drift), accepted by mypy on a typed
sample whose types hold at runtime, and precise enough that mypy rejects misused results."""
import importlib.util
import inspect
import os
import subprocess
import sys

import pytest

import circledist as cd

from conftest import SOURCE_ROOT

HERE = os.path.dirname(os.path.abspath(__file__))
PYTHON_DIR = os.path.join(SOURCE_ROOT, "python")
# Strict for the samples; the stub's hand-written scene part uses bare np.ndarray.
MYPY_CONFIG = """[mypy]
strict = True
[mypy-circledist]
disallow_any_generics = False
"""


def test_stub_matches_generator():
    """The committed __init__.pyi is what python/gen_stubs.py generates from the query tables."""
    run = subprocess.run([sys.executable, os.path.join(PYTHON_DIR, "gen_stubs.py"), "--check"],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stdout + run.stderr


def test_typed_sample_types_hold_at_runtime():
    spec = importlib.util.spec_from_file_location("typed_sample", os.path.join(HERE, "typed_sample.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    module.check()


def test_shape_markers_and_signatures():
    assert cd.Circle[cd.One] is not cd.Circle and cd.Circle[cd.One].__origin__ is cd.Circle
    c = cd.Circle[cd.One]((0, 0, 0), (0, 0, 1), 1.0)
    assert type(c) is cd.Circle and c.shape == ()
    assert str(inspect.signature(cd.Circle)) == "(center, normal, radius, /)"
    assert str(inspect.signature(cd.Arc)) == "(circle, zero_direction, start, end, /)"
    assert str(inspect.signature(cd.Point)) == "(position, /)"


def _mypy(tmp_path, sample):
    if importlib.util.find_spec("mypy") is None:
        pytest.skip("mypy is not installed (Debian package mypy): the stubs are not type-checked")
    config = tmp_path / "mypy.ini"
    config.write_text(MYPY_CONFIG)
    env = dict(os.environ, MYPYPATH=PYTHON_DIR)
    run = subprocess.run([sys.executable, "-m", "mypy", "--config-file", str(config),
                          "--cache-dir", str(tmp_path / "cache"), "--no-error-summary",
                          "--show-error-codes", os.path.join(HERE, sample)],
                         capture_output=True, text=True, env=env, cwd=str(tmp_path))
    return run.returncode, [line.split(os.sep)[-1] for line in run.stdout.splitlines()]


def test_mypy_accepts_typed_sample(tmp_path):
    code, lines = _mypy(tmp_path, "typed_sample.py")
    print("\n".join(lines))
    assert (code, lines) == (0, [])


def test_mypy_rejects_misused_results(tmp_path):
    code, lines = _mypy(tmp_path, "typed_misuse.py")
    print("\n".join(lines))
    assert code == 1
    assert lines == [
        'typed_misuse.py:10: error: Incompatible types in assignment (expression has type '
        '"BatchResult", variable has type "Result")  [assignment]',
        'typed_misuse.py:11: error: "float" has no attribute "shape"  [attr-defined]',
        'typed_misuse.py:12: error: Incompatible types in assignment (expression has type '
        '"BatchContact", variable has type "Contact")  [assignment]',
    ]
