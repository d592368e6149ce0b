# SPDX-License-Identifier: MIT
"""The documentation of the Python package: every public function and class has numpydoc
sections, and every Examples section runs as a doctest with the output it shows."""
import doctest
import inspect

import pytest

import circledist as cd

PUBLIC = [name for name in cd.__all__ if callable(getattr(cd, name))]
FLAGS = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE


def _doctests(name):
    finder = doctest.DocTestFinder()
    return [t for t in finder.find(getattr(cd, name), name, module=False, globs={}) if t.examples]


@pytest.mark.parametrize("name", PUBLIC)
def test_examples_run(name):
    runner = doctest.DocTestRunner(optionflags=FLAGS)
    for test in _doctests(name):
        runner.run(test)
    result = runner.summarize(verbose=False)
    assert result.failed == 0, "%s: %d of %d examples failed (output above)" % (
        name, result.failed, result.attempted)


@pytest.mark.parametrize("name", PUBLIC)
def test_numpydoc_sections(name):
    """Examples everywhere; Parameters when it takes arguments; Returns for functions."""
    obj = getattr(cd, name)
    doc = inspect.getdoc(obj) or ""
    sections = {line for line, under in zip(doc.splitlines(), doc.splitlines()[1:])
                if under.strip() and set(under.strip()) == {"-"}}
    missing = {"Examples"} - sections
    try:
        takes_arguments = bool(inspect.signature(obj).parameters)
    except (TypeError, ValueError):   # builtins without a signature
        takes_arguments = False
    if takes_arguments and not issubclass(obj if inspect.isclass(obj) else type(None), BaseException):
        missing |= {"Parameters"} - sections
    if inspect.isfunction(obj):
        missing |= {"Returns"} - sections
    assert not missing, "%s: its docstring has no %s section" % (name, ", ".join(sorted(missing)))


def test_every_public_name_has_examples():
    """The doctests above are not vacuous: every public callable shows at least one example."""
    assert [n for n in PUBLIC if not _doctests(n)] == []


def _public_methods():
    for name in PUBLIC:
        cls = getattr(cd, name)
        if not inspect.isclass(cls) or issubclass(cls, (BaseException, int)):
            continue
        for attr, value in vars(cls).items():
            if isinstance(value, (classmethod, staticmethod)):
                value = value.__func__
            if not attr.startswith("_") and inspect.isfunction(value):
                yield "%s.%s" % (name, attr), value


@pytest.mark.parametrize("name, method", list(_public_methods()))
def test_method_parameters_documented(name, method):
    """Every public method documents the parameters it takes, by name."""
    doc = inspect.getdoc(method) or ""
    params = [p for p in inspect.signature(method).parameters if p not in ("self", "cls")]
    assert doc, "%s has no docstring" % name
    if params:
        assert "Parameters\n----------" in doc, "%s: no Parameters section" % name
        section = doc.split("Parameters\n----------", 1)[1]
        documented = " ".join(line.split(" : ")[0] for line in section.splitlines()
                              if " : " in line and not line.startswith(" "))
        missing = [p for p in params if p not in documented]
        assert not missing, "%s: parameters %s not documented" % (name, missing)
