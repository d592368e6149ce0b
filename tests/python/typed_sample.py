# SPDX-License-Identifier: MIT
"""A typed use of circledist: mypy --strict accepts it (test_typing.py), and run as a script it
checks that every statically typed return value has that type at runtime too."""
import numpy as np
import numpy.typing as npt

import circledist as cd

F64 = npt.NDArray[np.float64]

ring = cd.Circle((0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 1.0)
other: cd.Circle[cd.One] = cd.Circle((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), 1.0)
rings: cd.Circle[cd.Many] = cd.Circle(np.zeros((5, 3)), (0.0, 0.0, 1.0), np.linspace(1.0, 2.0, 5))

# One object each: a Result whose distance is a float.
r: cd.Result = cd.circle_circle(ring, other)
d: float = r.distance
pts: F64 = r.points
method: cd.Method = r.method
radius: float = ring.radius
# Tuples of numbers are single objects too.
r2: cd.Result = cd.point_disk((0.0, 0.0, 2.0), ((0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 1.0))

# Arrays: a BatchResult of arrays, from the module function and from a Query method.
b: cd.BatchResult = cd.circle_circle(rings, other)
distances: F64 = b.distance
radii: F64 = rings.radius
with cd.Query(threads=1) as q:
    b2: cd.BatchResult = q.circle_disk(other, rings)
# distance_only=True answers in the batch form even for one object each.
only: cd.BatchResult = cd.circle_circle(ring, other, distance_only=True)

# Swept objects and gradients.
torus = cd.Torus(ring, 0.25)
tori: cd.Torus[cd.Many] = cd.Torus(rings, 0.25)
c: cd.Contact = cd.torus_torus(torus, cd.Torus(other, 0.25))
signed: float = c.distance
bc: cd.BatchContact = cd.torus_torus(tori, torus)
res, grad = cd.circle_circle_grad(ring, other)
g: cd.Grad = grad
d_center: F64 = grad.obj[0].d_center
bres, bgrad = cd.circle_circle_grad(rings, other)
bg: cd.BatchGrad = bgrad
cres, cgrad = cd.capsule_sphere_grad(cd.Capsule(((0.0, 0.0, 0.0), (1.0, 0.0, 0.0)), 0.5),
                                     cd.Sphere((0.0, 2.0, 0.0), 0.5))
cc: cd.Contact = cres

# A sub-object of one object is one object.
core: cd.Circle[cd.One] = torus.circle


def check() -> None:
    """The static types above hold at runtime."""
    expected = [(r, cd.Result), (d, float), (radius, float), (r2, cd.Result), (b, cd.BatchResult),
                (b2, cd.BatchResult), (only, cd.BatchResult), (c, cd.Contact), (signed, float),
                (bc, cd.BatchContact), (res, cd.Result), (g, cd.Grad), (bres, cd.BatchResult),
                (bg, cd.BatchGrad), (cc, cd.Contact), (distances, np.ndarray), (radii, np.ndarray)]
    for value, cls in expected:
        assert isinstance(value, cls), (value, cls)
    assert core.shape == () and rings.shape == (5,) and tori.shape == (5,)


if __name__ == "__main__":
    check()
    print("typed_sample: ok")
