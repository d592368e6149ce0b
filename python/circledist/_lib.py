# SPDX-License-Identifier: MIT
"""Loading libcircledist and declaring the C functions (internal).

The library is searched in this order, and the ImportError lists every place tried:

1. ``$CIRCLEDIST_LIBRARY`` (a file path), if set; nothing else is tried then.
2. The copy inside this package's directory (a wheel built by ``pip install .``).
3. The library installed together with this package by ``meson install``: its install path is
   written into the generated ``_build_config.py`` (first relative to this package, so a
   ``--destdir`` or relocated prefix works, then the absolute configured path).
4. The system loader: ``ctypes.util.find_library("circledist")``, then ``libcircledist.so.1``.
"""
import ctypes
import ctypes.util
import os

import numpy as np

SONAME = "libcircledist.so.1"
PACKAGE_DIR = os.path.dirname(os.path.abspath(__file__))


def _build_config_candidates():
    """Library paths from the meson-generated _build_config module (none for a pip install)."""
    try:
        from . import _build_config as bc  # written by meson (python/meson.build) at install
    except ImportError:
        return []
    libdir = os.path.join(bc.PREFIX, bc.LIBDIR)  # LIBDIR may be absolute: join keeps it
    found = []
    # The package sits in PREFIX/<rel_py>/circledist and the library in PREFIX/<rel_lib>; looking
    # relative to this file first makes a --destdir staging or a moved prefix work too.
    rel_py = os.path.relpath(bc.PYTHON_DIR, bc.PREFIX)
    rel_lib = os.path.relpath(libdir, bc.PREFIX)
    site = os.path.dirname(PACKAGE_DIR)
    if not rel_py.startswith("..") and not rel_lib.startswith("..") and \
            site.endswith(os.sep + rel_py):
        root = site[: -len(rel_py) - 1]
        found.append(("installed with this package", os.path.join(root, rel_lib, bc.LIBRARY)))
    found.append(("configured install path", os.path.join(libdir, bc.LIBRARY)))
    return found


# Candidates that are files this package expects to exist (the others are names for the loader).
_FILE_CANDIDATES = ("inside this package", "installed with this package", "configured install path")


def tool_path():
    """The circledist tool installed with this package (inside a wheel, or meson's bindir), else
    the first on PATH; None when there is none."""
    import shutil
    candidates = [os.path.join(PACKAGE_DIR, "circledist")]
    try:
        from . import _build_config as bc
        candidates.append(os.path.join(bc.PREFIX, bc.BINDIR, "circledist"))
    except (ImportError, AttributeError):
        pass
    for path in candidates:
        if os.path.isfile(path) and os.access(path, os.X_OK):
            return path
    return shutil.which("circledist")


def load():
    """Load the C library; raise ImportError naming every candidate that failed."""
    tried = []
    env = os.environ.get("CIRCLEDIST_LIBRARY")
    if env:
        candidates = [("$CIRCLEDIST_LIBRARY", env)]
    else:
        candidates = [("inside this package", os.path.join(PACKAGE_DIR, SONAME))]
        candidates += _build_config_candidates()
        found = ctypes.util.find_library("circledist")
        if found:
            candidates.append(("ctypes.util.find_library", found))
        candidates.append(("system loader", SONAME))
    for how, path in candidates:
        if how in _FILE_CANDIDATES and not os.path.exists(path):
            tried.append("%s: %s (no such file)" % (how, path))
            continue
        try:
            return ctypes.CDLL(path)
        except OSError as e:
            tried.append("%s: %s (%s)" % (how, path, e))
    raise ImportError("circledist: cannot load libcircledist; tried:\n  " + "\n  ".join(tried) +
                      "\nSet CIRCLEDIST_LIBRARY to the path of libcircledist.so.1, or install the "
                      "library where the system loader finds it.")


lib = load()

_c = ctypes
_P = _c.c_void_p
_ST = _c.c_int


def _decl(name, restype, *argtypes, required=True):
    fn = getattr(lib, name, None)
    if fn is None:
        if required:
            raise ImportError("circledist: the loaded library has no %s" % name)
        return None
    fn.restype = restype
    fn.argtypes = list(argtypes)
    return fn


version_string = _decl("cdist_version_string", _c.c_char_p)
version_major = _decl("cdist_version_major", _c.c_int)
status_name = _decl("cdist_status_name", _c.c_char_p, _c.c_int)
method_name = _decl("cdist_method_name", _c.c_char_p, _c.c_int)
status_string = _decl("cdist_status_string", _c.c_char_p, _c.c_int)
result_size = _decl("cdist_result_size", _c.c_size_t)
query_new = _decl("cdist_query_new", _P)
query_free = _decl("cdist_query_free", None, _P)
query_set_method = _decl("cdist_query_set_method", _ST, _P, _c.c_int)
query_get_method = _decl("cdist_query_get_method", _c.c_int, _P)
query_set_unit_tolerance = _decl("cdist_query_set_unit_tolerance", _ST, _P, _c.c_double)
query_get_unit_tolerance = _decl("cdist_query_get_unit_tolerance", _c.c_double, _P)
query_set_curve_samples = _decl("cdist_query_set_curve_samples", _ST, _P, _c.c_int)
query_get_curve_samples = _decl("cdist_query_get_curve_samples", _c.c_int, _P)
query_set_max_iterations = _decl("cdist_query_set_max_iterations", _ST, _P, _c.c_int)
query_get_max_iterations = _decl("cdist_query_get_max_iterations", _c.c_int, _P)
query_last_error = _decl("cdist_query_last_error", _c.c_char_p, _P)
circle_basis = _decl("cdist_circle_basis", _ST, _P, _P, _P)
circle_point = _decl("cdist_circle_point", _ST, _P, _c.c_double, _P)

# The batch API (may be missing from an older library: the vectorised calls then say so).
batch = _decl("cdist_batch", _ST, _P, _c.c_int, _c.c_size_t, _P, _c.c_ssize_t, _P, _c.c_ssize_t,
              _P, _P, required=False)
batch_distance = _decl("cdist_batch_distance", _ST, _P, _c.c_int, _c.c_size_t, _P, _c.c_ssize_t,
                       _P, _c.c_ssize_t, _P, _P, required=False)
query_set_threads = _decl("cdist_query_set_threads", _ST, _P, _c.c_int, required=False)
query_get_threads = _decl("cdist_query_get_threads", _c.c_int, _P, required=False)
kind_count = _decl("cdist_kind_count", _c.c_int, required=False)
kind_name = _decl("cdist_kind_name", _c.c_char_p, _c.c_int, required=False)
kind_size_a = _decl("cdist_kind_size_a", _c.c_size_t, _c.c_int, required=False)
kind_size_b = _decl("cdist_kind_size_b", _c.c_size_t, _c.c_int, required=False)

CURVE_FN = _c.CFUNCTYPE(_c.c_int, _P, _c.c_double, _c.POINTER(_c.c_double), _c.POINTER(_c.c_double))
curve_circle = _decl("cdist_curve_circle", _ST, _P, CURVE_FN, _P, _c.c_double, _c.c_double, _P, _P)
curve_disk = _decl("cdist_curve_disk", _ST, _P, CURVE_FN, _P, _c.c_double, _c.c_double, _P, _P)


class Curve(_c.Structure):
    """struct cdist_curve: a callback curve as one batch object."""
    _fields_ = [("fn", CURVE_FN), ("user", _P), ("t0", _c.c_double), ("t1", _c.c_double)]


#: numpy mirror of struct cdist_pair / cdist_result (checked against cdist_result_size()).
PAIR_DTYPE = np.dtype([("point", np.float64, (2, 3)), ("param", np.float64, (2,))], align=True)
RESULT_DTYPE = np.dtype([("distance", np.float64), ("sqr_distance", np.float64),
                         ("num_pairs", np.int32), ("equidistant", np.int32),
                         ("pairs", PAIR_DTYPE, (2,)), ("method", np.int32), ("iterations", np.int32),
                         ("reserved", np.float64, (8,))], align=True)
if result_size() != RESULT_DTYPE.itemsize:
    raise ImportError("circledist: the library's cdist_result is %d bytes, this package expects %d"
                      % (result_size(), RESULT_DTYPE.itemsize))
if version_major() != 1:
    raise ImportError("circledist: library version %s is not ABI version 1" % version_string().decode())


# Swept objects (contacts) and gradients (may be missing from an older library: the calls
# then say so). struct cdist_contact / cdist_grad as numpy dtypes, checked below.
contact_size = _decl("cdist_contact_size", _c.c_size_t, required=False)
swept_size = _decl("cdist_swept_size", _c.c_size_t, _c.c_int, required=False)
contact_flag_core_touch = _decl("cdist_contact_flag_core_touch", _c.c_int, required=False)
grad_size = _decl("cdist_grad_size", _c.c_size_t, required=False)
grad_flag_not_differentiable = _decl("cdist_grad_flag_not_differentiable", _c.c_int,
                                     required=False)
CONTACT_PAIR_DTYPE = np.dtype([("point", np.float64, (2, 3)), ("core_point", np.float64, (2, 3)),
                               ("normal", np.float64, (3,)), ("param", np.float64, (2,))],
                              align=True)
CONTACT_DTYPE = np.dtype([("distance", np.float64), ("core_distance", np.float64),
                          ("num_pairs", np.int32), ("equidistant", np.int32),
                          ("flags", np.int32), ("method", np.int32),
                          ("pairs", CONTACT_PAIR_DTYPE, (2,)), ("reserved", np.float64, (8,))],
                         align=True)
GRAD_OBJECT_FIELDS = ("d_center", "d_normal", "d_origin", "d_direction", "d_p0", "d_p1",
                      "d_zero_direction", "d_radius", "d_radius_swept", "d_start", "d_end")
GRAD_OBJECT_DTYPE = np.dtype([(f, np.float64, (3,)) for f in GRAD_OBJECT_FIELDS[:7]] +
                             [(f, np.float64) for f in GRAD_OBJECT_FIELDS[7:]] +
                             [("reserved", np.float64, (8,))], align=True)
GRAD_DTYPE = np.dtype([("obj", GRAD_OBJECT_DTYPE, (2,)), ("flags", np.int32),
                       ("reserved_int", np.int32), ("reserved", np.float64, (8,))], align=True)
for _fn, _dt, _what in ((contact_size, CONTACT_DTYPE, "cdist_contact"),
                        (grad_size, GRAD_DTYPE, "cdist_grad")):
    if _fn is not None and _fn() != _dt.itemsize:
        raise ImportError("circledist: the library's %s is %d bytes, this package expects %d"
                          % (_what, _fn(), _dt.itemsize))
CONTACT_CORE_TOUCH = contact_flag_core_touch() if contact_flag_core_touch is not None else 1
GRAD_NOT_DIFFERENTIABLE = (grad_flag_not_differentiable()
                           if grad_flag_not_differentiable is not None else 1)


# Contact and gradient batches, progress and cancel (ABI 1.1; missing from a 1.0 library: the
# array forms of the swept and gradient queries then say so).
batch_contact = _decl("cdist_batch_contact", _ST, _P, _c.c_int, _c.c_size_t, _P, _c.c_ssize_t, _P,
                      _c.c_ssize_t, _P, _P, required=False)
batch_grad = _decl("cdist_batch_grad", _ST, _P, _c.c_int, _c.c_size_t, _P, _c.c_ssize_t, _P,
                   _c.c_ssize_t, _P, _P, _P, required=False)
kind_result_size = _decl("cdist_kind_result_size", _c.c_size_t, _c.c_int, required=False)
kind_has_grad = _decl("cdist_kind_has_grad", _c.c_int, _c.c_int, required=False)
PROGRESS_FN = _c.CFUNCTYPE(_c.c_int, _P, _c.c_size_t, _c.c_size_t)
query_set_progress = _decl("cdist_query_set_progress", _ST, _P, PROGRESS_FN, _P, _c.c_size_t,
                           required=False)
#: cdist_status values the package names (appended in ABI 1.1).
STATUS_CANCELLED = 17
STATUS_OVERLAP = 18


def single_query(name):
    """The C function cdist_<name>(q, a, b, result) for one query, with pointer arguments."""
    return _decl("cdist_" + name, _ST, _P, _P, _P, _P)


def contact_query(name):
    """cdist_<name>(q, a, b, contact) of a swept query, or None if the library lacks it."""
    return _decl("cdist_" + name, _ST, _P, _P, _P, _P, required=False)


def grad_query(name):
    """cdist_<name>_grad(q, a, b, result_or_contact, grad), or None if the library lacks it."""
    return _decl("cdist_" + name + "_grad", _ST, _P, _P, _P, _P, _P, required=False)
