# SPDX-License-Identifier: MIT
"""Docstrings of the generated query functions: numpydoc templates filled per kind (internal).

The examples place the first object's core in the plane z = 2 through the point (1, 0, 2) and
the second object's core in the plane z = 0 through (1, 0, 0), so the cores are exactly 2 apart;
every swept radius is 0.25, so a signed distance is 2 minus the swept radii."""

# One object of each class for the examples: first argument (core in z = 2), second (z = 0).
FIRST = {
    "Point": "(1.0, 0.0, 2.0)",
    "Line": "cd.Line((1, 0, 2), (1, 0, 0))",
    "Ray": "cd.Ray((1, 0, 2), (1, 0, 0))",
    "Segment": "cd.Segment((0, 0, 2), (2, 0, 2))",
    "Circle": "cd.Circle((0, 0, 2), (0, 0, 1), 1.0)",
    "Disk": "cd.Disk((0, 0, 2), (0, 0, 1), 1.0)",
    "Arc": "cd.Arc(((0, 0, 2), (0, 0, 1), 1.0), (1, 0, 0), -1.0, 1.0)",
    "Helix": "cd.Helix((0, 0, 2), (0, 0, 1), (1, 0, 0), 1.0, 0.0, -1.0, 1.0)",
    "Bezier3": "cd.Bezier3((0, 0, 2), (0.5, 0, 2), (1.5, 0, 2), (2, 0, 2))",
    "Sphere": "cd.Sphere((1, 0, 2), 0.25)",
    "Capsule": "cd.Capsule(((0, 0, 2), (2, 0, 2)), 0.25)",
    "Torus": "cd.Torus(((0, 0, 2), (0, 0, 1), 1.0), 0.25)",
    "RoundedDisk": "cd.RoundedDisk(((0, 0, 2), (0, 0, 1), 1.0), 0.25)",
}
SECOND = {
    "Line": "cd.Line((1, 0, 0), (0, 1, 0))",
    "Ray": "cd.Ray((1, 0, 0), (0, 1, 0))",
    "Segment": "cd.Segment((1, -1, 0), (1, 1, 0))",
    "Circle": "cd.Circle((0, 0, 0), (0, 0, 1), 1.0)",
    "Disk": "cd.Disk((0, 0, 0), (0, 0, 1), 1.0)",
    "Arc": "cd.Arc(((0, 0, 0), (0, 0, 1), 1.0), (1, 0, 0), -1.0, 1.0)",
    "Sphere": "cd.Sphere((1, 0, 0), 0.25)",
    "Capsule": "cd.Capsule(((1, -1, 0), (1, 1, 0)), 0.25)",
    "Torus": "cd.Torus(((0, 0, 0), (0, 0, 1), 1.0), 0.25)",
    "RoundedDisk": "cd.RoundedDisk(((0, 0, 0), (0, 0, 1), 1.0), 0.25)",
}
SWEPT = ("Sphere", "Capsule", "Torus", "RoundedDisk")

_COMMON = """method : Method, str or int, optional
    The algorithm for this call only (default: the handle's, see Query.set_method).
threads : int, optional
    Worker threads of a vectorised call; kept on the handle (results are identical for every
    count).%(module_threads)s"""
_DISTANCE_ONLY = """
distance_only : bool, optional
    Compute only the distances and statuses (cdist_batch_distance, the screening path); the
    answer is then always the batch form, even for one object each."""
_OUT = """
out : %(out)s, optional
    The answer of an earlier call of the same shape%(out_extra)s to write into instead of new
    buffers."""
_PROGRESS = """
progress : bool or callable, optional
    True for a progress bar (tqdm if installed, else a line on stderr), or a callable
    progress(done, total) returning True to stop: the entries not answered get status
    CDIST_ERR_CANCELLED. Long batches honour Ctrl-C (KeyboardInterrupt well within 0.2 s,
    plus the time to write the error state of the entries not answered)."""
_QUERY = """
query : Query, optional
    The handle to use (default: this thread's default_query())."""

_RAISES = """Raises
------
CircleDistError
    For one object each: bad input (NaN or infinite values, a normal or direction that is not
    unit length, a negative radius, ...), with the library's message. For arrays only errors
    of the whole call; a bad entry gets its status and NaN and the others are answered.
TypeError, ValueError
    Arguments of the wrong type or shape (the message names the argument)."""


def _objects_params(name_a, cls_a, name_b, cls_b):
    return """%(a)s : %(A)s or array of %(A)s
    The first object: a %(A)s (or a tuple of its fields), or an array of them.
%(b)s : %(B)s or array of %(B)s
    The second object; the batch shapes of both broadcast with numpy's rules.
""" % {"a": name_a, "A": cls_a, "b": name_b, "B": cls_b}


def _example(call, cls_a, cls_b, grad, contact, module):
    """Examples: one query, then the same with the first object twice in an array."""
    a_radius = 0.25 if cls_a in SWEPT else 0.0
    b_radius = 0.25 if cls_b in SWEPT else 0.0
    expected = 2.0 - a_radius - b_radius
    prefix = "cd." if module else "q."
    lines = [">>> import circledist as cd"]
    if not module:
        lines.append(">>> q = cd.Query()")
    lines += [">>> a = " + FIRST[cls_a], ">>> b = " + SECOND[cls_b]]
    target = "r, g" if grad else "r"
    a_many = "cd.%s.from_array([a.data, a.data])" % cls_a if cls_a != "Point" else "[a, a]"
    lines += [">>> %s = %s%s(a, b)" % (target, prefix, call),
              ">>> round(r.distance, 9)%s" % ("   # 2 minus the swept radii" if contact else ""),
              repr(expected)]
    if grad:
        lines += [">>> type(g).__name__", "'Grad'"]
    lines += [">>> batch = %s%s(%s, b)%s" % (prefix, call, a_many, "[0]" if grad else ""),
              ">>> batch.distance.round(9)",
              "array([%s, %s])" % (_short(expected), _short(expected))]
    return "\n".join(lines)


def _short(x):
    """x as numpy prints it in an array (1.75 -> '1.75', 2.0 -> '2.  ')."""
    return "%g." % x if x == int(x) else "%g" % x


def query_doc(call, cls_a, cls_b, kind, module):
    """The numpydoc docstring of one pair query.

    kind: "result" (Result), "contact" (Contact), "grad" (Result, Grad) or "contact_grad"."""
    contact = kind.startswith("contact")
    grad = kind.endswith("grad")
    c_name = "cdist_" + call
    one = "Contact" if contact else "Result"
    many = "BatchContact" if contact else "BatchResult"
    if grad:
        summary = "%s distance from a %s to a %s with its gradient (%s)." % (
            "Signed" if contact else "Minimum", cls_a, cls_b, c_name)
        returns = """(%(one)s, Grad) or (%(many)s, BatchGrad)
    For one object each the answer and the derivatives of the distance with respect to every
    parameter of both objects (Grad.obj[0] for a, obj[1] for b%(swept)s); for arrays both as
    arrays of the broadcast batch shape (one C call, cdist_batch_grad).""" % {
            "one": one, "many": many,
            "swept": "; d_radius_swept is -1 for each swept object" if contact else ""}
        out_type, out_extra = "tuple", " (the (%s, BatchGrad) pair)" % many
    else:
        summary = "%s distance from a %s to a %s (%s)." % (
            "Signed" if contact else "Minimum", cls_a, cls_b, c_name)
        returns = """%(one)s or %(many)s
    For one object each a %(one)s%(what)s; for arrays (or with out= or distance_only=True) a
    %(many)s of the broadcast batch shape from one C call (%(batch)s).""" % {
            "one": one, "many": many, "batch": "cdist_batch_contact" if contact else "cdist_batch",
            "what": " (signed distance core_distance - (r0 + r1), negative when the solids "
                    "overlap; witness points, core points and normals)" if contact else
                    " (distance, closest pairs, equidistant flag, method)"}
        out_type, out_extra = many, ""
    params = _objects_params("a", cls_a, "b", cls_b) + _COMMON % {
        "module_threads": " Default 1 for the module function." if module else ""}
    if not grad:
        params += _DISTANCE_ONLY
    params += _OUT % {"out": out_type, "out_extra": out_extra} + _PROGRESS
    if module:
        params += _QUERY
    return """%s

Parameters
----------
%s

Returns
-------
%s

%s

See Also
--------
Query : the handle (options, workspaces); the module function uses default_query().

Examples
--------
%s
""" % (summary, params, returns, _RAISES, _example(call, cls_a, cls_b, grad, contact, module))


def curve_doc(call, cls_b, module):
    """The numpydoc docstring of curve_circle / curve_disk."""
    prefix = "cd." if module else "q."
    params = """f : callable
    f(t) -> (position, derivative): two length-3 sequences, the point of the curve at t and
    its exact derivative (the curve must be continuously differentiable).
t0, t1 : float
    The parameter interval [t0, t1].
other : %(B)s or array of %(B)s
    The second object; an array gives one vectorised call with the same curve for every entry.
""" % {"B": cls_b} + _COMMON % {"module_threads": " Default 1 for the module function." if module
                                 else ""} + _DISTANCE_ONLY + _OUT % {"out": "BatchResult", "out_extra": ""}
    if module:
        params += _QUERY
    return """Minimum distance from the curve f(t), t in [t0, t1], to a %(B)s (cdist_%(call)s).

The library samples the curve (Query curve_samples intervals, default 512) and refines each
bracketed minimum, so one query calls f hundreds of times; each call from C into Python costs
microseconds, which dominates: use Helix, Bezier3, Arc or Segment when the curve is one of
them. With threads > 1 the callbacks still run one at a time (the GIL).

Parameters
----------
%(params)s

Returns
-------
Result or BatchResult
    A Result for one object (curve parameters in params[:, 0]); a BatchResult for an array of
    objects, or with out= or distance_only=True.

Raises
------
CircleDistError
    Bad input, or CDIST_ERR_CALLBACK_FAILED when f raised (the exception of f is re-raised,
    chained to it; in the vectorised form after the call, the other answers discarded).
TypeError, ValueError
    f not callable, or arguments of the wrong type or shape.

Examples
--------
>>> import circledist as cd
%(query)s>>> def line(t):
...     return (t, 0.0, 2.0), (1.0, 0.0, 0.0)
>>> r = %(prefix)s%(call)s(line, 0.0, 2.0, %(b)s)
>>> round(r.distance, 9)
2.0
""" % {"B": cls_b, "call": call, "params": params, "prefix": prefix, "b": SECOND[cls_b],
       "query": "" if module else ">>> q = cd.Query()\n"}
