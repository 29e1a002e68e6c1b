"""Figures of a driven path: what the tests, benchmarks and the demo measure."""
import math

import numpy as np


def circle_radius(points):
    """Radius of the least-squares circle through 2-D points (Kasa's algebraic fit)."""
    p = np.asarray(points, dtype=float)
    A = np.column_stack([2 * p[:, 0], 2 * p[:, 1], np.ones(len(p))])
    cx, cy, c = np.linalg.lstsq(A, (p ** 2).sum(axis=1), rcond=None)[0]
    return math.sqrt(c + cx * cx + cy * cy)
