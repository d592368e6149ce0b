# SPDX-License-Identifier: MIT
"""circledist: exact minimum distances and all closest pairs between 3D circles, disks, points,
lines, rays, segments, arcs, helices, cubic Beziers and callback curves (libcircledist).

    import circledist as cd
    r = cd.circle_circle(cd.Circle((0, 0, 0), (0, 0, 1), 1), cd.Circle((1, 0, 0), (0, 1, 0), 1))
    r.distance, r.points, r.params, r.equidistant, r.method

Vectorised: give arrays of objects (fields broadcast with numpy's rules) and get arrays back
from one C call, without a Python loop over the entries:

    rings = cd.Circle(centers, normals, radii)            # (N, 3), (N, 3), (N,)
    b = cd.circle_circle(rings, cd.Circle((0, 0, 0), (0, 0, 1), 1), threads=2)
    b.distance, b.points, b.params, b.num_pairs, b.equidistant, b.status   # (N,), (N, 2, 2, 3), ...

Objects: Point, Circle, Disk, Line, Ray, Segment, Arc, Helix, Bezier3 (each also wraps an
(N, WIDTH) float64 array in the C struct's field order with .from_array, without copying).
Queries (module functions and Query methods): point_circle, point_disk, line_circle,
ray_circle, segment_circle, circle_circle, line_disk, ray_disk, segment_disk, circle_disk,
disk_disk, arc_circle, arc_arc, segment_arc, arc_disk, helix_circle, helix_disk,
bezier3_circle, bezier3_disk, curve_circle, curve_disk; each takes method=, threads= and
distance_only=.

Swept objects (a core swept by a ball): Sphere, Capsule, Torus, RoundedDisk. Their queries
(torus_torus, torus_capsule, torus_sphere, torus_rounded_disk, capsule_capsule,
capsule_sphere, capsule_rounded_disk, sphere_sphere, sphere_rounded_disk,
rounded_disk_rounded_disk, torus_line, torus_ray, torus_segment, capsule_circle, capsule_disk,
sphere_circle, sphere_disk) return a Contact (signed distance, witness points, normals) for one
object each, a BatchContact for arrays. Gradients: <query>_grad(a, b) for every swept query and
for point/line/ray/segment/circle/disk/arc queries with a C _grad variant returns (result, Grad),
Grad.obj[k].d_center etc. as in cdist_grad_object; for arrays (BatchResult or BatchContact,
BatchGrad) from one C call, e.g.

    res, grads = cd.circle_circle_grad(rings, other)      # grads.obj[0].d_center: (N, 3)
    contacts = cd.torus_torus(tori, cd.Torus(circle, 0.1))

Long batches report progress (progress=True: a tqdm bar if tqdm is installed, or
progress=callable(done, total) -> stop) and honour Ctrl-C (KeyboardInterrupt well
within 0.2 s, plus the time to write the error state of every entry not answered: with
fresh output arrays of millions of entries a second or more; with out= the entries
answered before it are kept, the others have status CDIST_ERR_CANCELLED).

Types: objects built from Python numbers and tuples are Circle[One] etc., those built from
numpy arrays Circle[Many]; the stubs (__init__.pyi) overload every query on this, so type
checkers know a Result from a BatchResult. Every public function and class has a numpydoc
docstring with examples: help(circledist.circle_circle).

Errors: CircleDistError (status, name, message) from the library; ValueError or TypeError
naming the argument for malformed Python input.

The C library is found through $CIRCLEDIST_LIBRARY (a path), else the library installed with
this package by meson, else the system loader (libcircledist.so.1).
"""
from ._lib import CONTACT_DTYPE, GRAD_DTYPE, RESULT_DTYPE
from ._objects import (Arc, Bezier3, Capsule, Circle, Disk, GeometricObject, Helix, Line, Many,
                       One, Point, Ray, RoundedDisk, Segment, Sphere, Torus)
from ._query import (FUNCTIONS as _FUNCTIONS, BatchContact, BatchGrad, BatchGradObject,
                     BatchResult, CircleDistError, Contact, ContactPair, Grad, GradObject, Method,
                     Pair, Query, Result, circle_basis, circle_point, default_query, status_name,
                     status_string, version)

from ._scene import Scene, SceneLinks, ScenePairs  # noqa: E402  (scenes: many objects at once)
from ._topology import (LINK_DTYPE, LINK_ERROR, LINK_FLAG_EXTENDED, LINK_FLAG_UNRESOLVED, LINK_OVERLAP,
                        LINK_TOUCHING, MOTION_DTYPE, SHAPE_DTYPE, TOI_DTYPE, TOI_HIT,
                        TOI_ITERATION_LIMIT, TOI_NONE, chain_invariants, link_details, linking,
                        time_of_impact)

globals().update(_FUNCTIONS)

METHOD_AUTO, METHOD_POLYNOMIAL, METHOD_ROBUST, METHOD_ITERATION = (
    Method.AUTO, Method.POLYNOMIAL, Method.ROBUST, Method.ITERATION)

__version__ = "1.0.0"

__all__ = ["Point", "Circle", "Disk", "Line", "Ray", "Segment", "Arc", "Helix", "Bezier3",
           "Sphere", "Capsule", "Torus", "RoundedDisk",
           "GeometricObject", "One", "Many", "Query", "Result", "BatchResult", "Pair", "Contact", "ContactPair",
           "Grad", "GradObject", "BatchContact", "BatchGrad", "BatchGradObject", "Method",
           "CircleDistError", "circle_basis", "circle_point", "default_query", "status_name",
           "status_string", "version", "RESULT_DTYPE", "CONTACT_DTYPE", "GRAD_DTYPE", "METHOD_AUTO", "METHOD_POLYNOMIAL",
           "METHOD_ROBUST", "METHOD_ITERATION", "Scene", "SceneLinks", "ScenePairs", "linking", "link_details", "LINK_DTYPE", "LINK_TOUCHING",
           "LINK_OVERLAP", "LINK_ERROR", "LINK_FLAG_EXTENDED", "LINK_FLAG_UNRESOLVED",
           "time_of_impact", "SHAPE_DTYPE", "MOTION_DTYPE", "TOI_DTYPE", "TOI_NONE", "TOI_HIT",
           "TOI_ITERATION_LIMIT", "chain_invariants"] + sorted(_FUNCTIONS)
