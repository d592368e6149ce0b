# SPDX-License-Identifier: MIT
"""Misuses of returned values that mypy must reject (test_typing.py expects these errors)."""
import numpy as np

import circledist as cd

ring = cd.Circle((0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 1.0)
rings = cd.Circle(np.zeros((5, 3)), (0.0, 0.0, 1.0), 1.0)

r: cd.Result = cd.circle_circle(rings, ring)
shape = cd.circle_circle(ring, ring).distance.shape
c: cd.Contact = cd.torus_sphere(cd.Torus(rings, 0.1), cd.Sphere((0.0, 0.0, 0.0), 1.0))
