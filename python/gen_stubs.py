# SPDX-License-Identifier: MIT
"""Generate the repetitive parts of python/circledist/__init__.pyi from the package's own tables.

    python3 python/gen_stubs.py            # rewrite the generated regions in place
    python3 python/gen_stubs.py --check    # exit 1 (with a diff) when the stub differs

The object classes come from their field specs (_objects), the query functions and Query
methods from the query tables (_query._KINDS, _SWEPT_KINDS, _GRAD_CORE). Each generated region
lies between "# BEGIN GENERATED <name>" and "# END GENERATED <name>"; the rest of the stub is
written by hand. Importing the package needs the C library (CIRCLEDIST_LIBRARY or installed).

Typing rule: an object built from Python numbers and tuples is X[One], one built from numpy
arrays (or from_array) is X[Many]. A query whose arguments are all One (with no out= and no
distance_only=True) returns the single answer, one with any Many argument the batch answer;
when the checker cannot tell, the union of both.
"""
import difflib
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
STUB = os.path.join(HERE, "circledist", "__init__.pyi")
sys.path.insert(0, HERE)

from circledist import _objects, _query  # noqa: E402

OBJECTS = [_objects.Point, _objects.Circle, _objects.Disk, _objects.Line, _objects.Ray,
           _objects.Segment, _objects.Arc, _objects.Helix, _objects.Bezier3, _objects.Sphere,
           _objects.Capsule, _objects.Torus, _objects.RoundedDisk]
# Classes with the same C struct are accepted for each other (_objects._SAME_LAYOUT).
ACCEPTS = {cls.__name__: [c.__name__ for c in _objects._SAME_LAYOUT.get(cls, (cls,))] for cls in OBJECTS}
SUB_OBJECTS = sorted({s.__name__ for cls in OBJECTS for _, _, s, _ in cls._SPEC if s is not None})


def objects_region():
    out = []
    for sub in SUB_OBJECTS:
        out += ["class _%sField:" % sub,
                "    @overload",
                "    def __get__(self, obj: GeometricObject[One], owner: Any) -> %s[One]: ..." % sub,
                "    @overload",
                "    def __get__(self, obj: GeometricObject[Many], owner: Any) -> %s[Many]: ..." % sub,
                "    @overload",
                "    def __get__(self, obj: GeometricObject[Any], owner: Any) -> %s[Any]: ..." % sub,
                "", ""]
    for cls in OBJECTS:
        n = cls.__name__
        one_params, many_params, fields = [], [], []
        for field, width, sub, _ in cls._SPEC:
            if sub is not None:
                one_params.append("%s: _%sOne" % (field, sub.__name__))
                many_params.append("%s: _%sArg" % (field, sub.__name__))
                fields.append("    %s: _%sField" % (field, sub.__name__))
            elif width is None:
                one_params.append("%s: _Scalar" % field)
                many_params.append("%s: npt.ArrayLike" % field)
                fields.append("    %s: _ScalarField" % field)
            else:
                one_params.append("%s: _Vec3" % field)
                many_params.append("%s: npt.ArrayLike" % field)
                fields.append("    %s: _VectorField" % field)
        out += ["class %s(GeometricObject[_S]):" % n,
                "    @overload",
                "    def __init__(self: %s[One], %s, /) -> None: ..." % (n, ", ".join(one_params)),
                "    @overload",
                "    def __init__(self: %s[Many], %s, /) -> None: ..." % (n, ", ".join(many_params)),
                "    @classmethod",
                "    def from_array(cls, array: npt.ArrayLike) -> %s[Many]: ..." % n,
                "    def __getitem__(self, index: Any) -> %s[Any]: ..." % n]
        out += fields + ["", ""]
    for cls in OBJECTS:
        n = cls.__name__
        acc = ACCEPTS[n]
        tup = ", ".join("_%sOne" % s.__name__ if s is not None else "_Scalar" if w is None else "_Vec3"
                        for _, w, s, _ in cls._SPEC)
        one = " | ".join("%s[One]" % a for a in acc) + " | tuple[%s]" % tup
        many = " | ".join("%s[Many]" % a for a in acc)
        arg = " | ".join("%s[Any]" % a for a in acc) + " | tuple[Any, ...]"
        if n == "Point":   # a point is given as its coordinates, any (..., 3) sequence or array
            one = "Point[One] | _Vec3"
            many = "Point[Many] | npt.NDArray[Any]"
            arg = "Point[Any] | npt.ArrayLike"
        out += ["_%sOne = %s" % (n, one), "_%sMany = %s" % (n, many), "_%sArg = %s" % (n, arg)]
    return out


def _signature(lead, b, self_, module, extra, curve):
    """The parameter list of one query: lead and b are (name, type) pairs of the leading
    parameters and the second object."""
    params = (["self"] if self_ else []) + ["%s: %s" % p for p in lead + [b]]
    params += ["*", "method: _MethodArg = ...",
               "threads: %s = ..." % ("int" if module else "int | None")] + extra
    if not curve:
        params.append("progress: _Progress = ...")
    if module:
        params.append("query: Query | None = ...")
    return ", ".join(params)


def query_overloads(name, lead, cls_b, single, batch, has_distance_only, self_, module, curve=False):
    """The overloads of one query. lead: (parameter, "_<Class>") for the first object, or the
    curve's (f, t0, t1); cls_b: the second object's class; single, batch: the return types for
    one object each and for arrays."""
    ind = "    " if self_ else ""
    b_name, b = ("other" if curve else "b"), "_" + cls_b.__name__

    def typed(suffix):
        return [(p, t + suffix if t.startswith("_") and not t.startswith("_Curve") else t)
                for p, t in lead]

    def extra(distance_only, out):
        return (["distance_only: " + distance_only] if has_distance_only else []) + ["out: " + out]

    optional_out = batch + " | None = ..."
    variants = [(typed("One"), b + "One", extra("Literal[False] = ...", "None = ..."), single)]
    if has_distance_only:   # distance_only=True: always the batch form (shape () for one each)
        variants.append((typed("Arg"), b + "Arg", extra("Literal[True]", optional_out), batch))
    variants.append((typed("Arg"), b + "Arg", extra("bool = ...", batch), batch))   # out= given
    if not curve:
        variants.append((typed("Many"), b + "Arg", extra("bool = ...", optional_out), batch))
    variants.append((typed("Arg"), b + "Many", extra("bool = ...", optional_out), batch))
    variants.append((typed("Arg"), b + "Arg", extra("bool = ...", optional_out),
                     "%s | %s" % (single, batch)))
    lines = []
    for lead_params, b_type, ex, ret in variants:
        lines += [ind + "@overload", ind + "def %s(%s) -> %s: ..." % (
            name, _signature(lead_params, (b_name, b_type), self_, module, ex, curve), ret)]
    return lines


def queries(self_, module):
    lines = []
    for name, _kind, ca, cb in _query._KINDS:
        lines += query_overloads(name, [("a", "_" + ca.__name__)], cb, "Result", "BatchResult",
                                 True, self_, module)
    for name, kind in (("curve_circle", _query.KIND_CURVE_CIRCLE), ("curve_disk", _query.KIND_CURVE_DISK)):
        cb = _objects.Circle if kind == _query.KIND_CURVE_CIRCLE else _objects.Disk
        lines += query_overloads(name, [("f", "_Curve"), ("t0", "float"), ("t1", "float")], cb,
                                 "Result", "BatchResult", True, self_, module, curve=True)
    for name, ca, cb in _query._SWEPT_KINDS:
        lines += query_overloads(name, [("a", "_" + ca.__name__)], cb, "Contact", "BatchContact",
                                 True, self_, module)
        lines += query_overloads(name + "_grad", [("a", "_" + ca.__name__)], cb,
                                 "tuple[Contact, Grad]", "tuple[BatchContact, BatchGrad]", False,
                                 self_, module)
    kinds = {k[0]: k for k in _query._KINDS}
    for name in _query._GRAD_CORE:
        _, _, ca, cb = kinds[name]
        lines += query_overloads(name + "_grad", [("a", "_" + ca.__name__)], cb,
                                 "tuple[Result, Grad]", "tuple[BatchResult, BatchGrad]", False,
                                 self_, module)
    return lines


REGIONS = {
    "objects": objects_region,
    "query-methods": lambda: queries(True, False),
    "functions": lambda: queries(False, True),
}


def generate(text):
    """text with every generated region replaced by its current content."""
    for name, make in REGIONS.items():
        begin, end = "# BEGIN GENERATED %s" % name, "# END GENERATED %s" % name
        i, j = text.find(begin), text.find(end)
        if i < 0 or j < i:
            raise SystemExit("gen_stubs: %s has no region %r" % (STUB, name))
        indent = text[text.rfind("\n", 0, i) + 1:i]
        head = text[:i] + begin + " (python/gen_stubs.py; do not edit)\n"
        text = head + "\n".join(make()) + "\n" + indent + text[j:]
    return text


def main(argv):
    with open(STUB) as f:
        old = f.read()
    new = generate(old)
    if "--check" in argv:
        if new != old:
            sys.stdout.writelines(difflib.unified_diff(old.splitlines(True), new.splitlines(True),
                                                       STUB, "generated"))
            print("gen_stubs: %s differs from the generated stub; run python3 python/gen_stubs.py"
                  % STUB)
            return 1
        return 0
    if new != old:
        with open(STUB, "w") as f:
            f.write(new)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
