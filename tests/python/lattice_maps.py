"""Test data shared by the texture tests: the paper's lattice as a measured height map."""
from __future__ import annotations

import numpy as np


def lattice_heights(l: float, n: int, dh: float) -> np.ndarray:
    """The paper's two-level square lattice sampled as a profilometer would: n x n pixels of
    one period, the height -min(f1, f2 + dh) (s = 2, C = 0.5), rows along y."""
    x = np.arange(n) * (l / n)
    X, Y = np.meshgrid(x, x)

    def r(cx, cy):
        return np.hypot((X - cx + l / 2) % l - l / 2, (Y - cy + l / 2) % l - l / 2)

    return -np.minimum(0.5 * r(0, 0) ** 2, 0.5 * r(l / 2, l / 2) ** 2 + dh)
