#!/usr/bin/python3
"""Small spots in any cell: a level's touchdown from the isolated punch and the periodic far
field, held to the periodic tables (issue 50: "never let a tiny spot drive the grid").

A level whose touchdown X* lies below a load curve's resolution (its tallest caps' spots span
too few nodes) drives `--grid auto` to ever finer grids: the study's first run (hexagonal,
three levels, TPE-A, 10 kPa) went 88 -> 176 -> 352 nodes a pitch (127 s) and level 1 (X* of
about 9.3e-4 E0*) stayed unresolved. In the small-spot limit (docs/model.md, section 14.7,
(P3) for the square lattice) the gap a site k below the tallest closes is

    h_k(X) = delta_iso(P) + P Phi_k + O(P a^2 / l^3),

P = X A / N the load each of the N tallest caps carries (A the cell's area), delta_iso the
isolated punch's indentation (Hertz for s = 2: P = 4/3 a^3, delta = a^2 with R = 1, E* = 1),
and Phi_k = G_reg(0) + sum_{j tallest, j != ref} G(x_ref - x_j) - sum_{j tallest} G(x_k - x_j),
G the displacement of zero mean of unit point loads on the cell's lattice (E* = 1), G_reg(0)
its regular part at the load. X*_k solves h_k(X*) = drop_k: one scalar equation, no grid.

G by Ewald's sums: 1/(pi r) = erfc(alpha r)/(pi r) + erf(alpha r)/(pi r); the second's 2-D
Fourier transform is (2/k) erfc(k / (2 alpha)); the first's mean 2/(sqrt(pi) alpha A) is taken
off; the regular part at 0 takes the limit (erfc(alpha r) - 1)/(pi r) -> -2 alpha / pi^1.5.

Measured (this script, 2026-11-29):
- the square lattice's Psi = G_reg(0) - G(centre) = -0.7272496931384, (P3)'s value, to 1e-13
  for two splittings alpha;
- the square two-level lattice (R = 1, C = 0.5, s = 2) against the periodic model's touchdown
  (its tables and small-spot table, through punchsweep.surface_classify): X* off by about
  0.6 (a/l)^3 of itself (a the tallest spot's radius at touchdown; the O(P a^2/l^3) term):
  1.8e-8 at a/l = 0.003, 4.8e-6 at 0.021, 1.1e-4 at 0.059, 1.8e-3 at 0.144, 1.6e-2 at 0.269;
- the first-run example's level 1 (hexagonal, l = 200/60 R, drop 2/60 R): Phi = -0.2551,
  X* = 9.31508e-4 E0* against the 352-node curve's 9.31402e-4 (itself unresolved).
So the leading order holds X* to 5e-5 up to a/l of about 0.045. The engine's limit
(model/surface/small_spot_touchdown.hpp, docs/model.md 17.6) adds the next order (each spot's
second moment in the far field, the field's curvature under each cap, the tilt at the closing
site) and the sites that touch in turn: against the same tables 9.7e-6 at spot ratio 0.18.

Usage: PYTHONPATH=build/python /usr/bin/python3 studies/periodic/small_spot_cells.py
"""
from __future__ import annotations

import numpy as np
from scipy.optimize import brentq
from scipy.special import erfc


def periodic_green(Lx: float, Ly: float, alpha: float | None = None, images: int = 6, waves: int = 40):
    """G(x, regular=False): the zero-mean displacement at x of unit point loads at the nodes of
    the Lx x Ly lattice (E* = 1); regular=True at x = 0 gives lim G(x) - 1/(pi |x|)."""
    A = Lx * Ly
    alpha = alpha or 2.0 / np.sqrt(A)
    R = np.array([(i * Lx, j * Ly) for i in range(-images, images + 1) for j in range(-images, images + 1)])
    k = np.array([(2 * np.pi * i / Lx, 2 * np.pi * j / Ly) for i in range(-waves, waves + 1)
                  for j in range(-waves, waves + 1) if (i, j) != (0, 0)])
    kn = np.hypot(k[:, 0], k[:, 1])
    weight = (2 / kn) * erfc(kn / (2 * alpha)) / A
    background = 2 / (np.sqrt(np.pi) * alpha * A)

    def G(x, regular: bool = False) -> float:
        d = np.hypot(x[0] - R[:, 0], x[1] - R[:, 1])
        if regular:
            near = d > 1e-12
            real = np.sum(erfc(alpha * d[near]) / d[near]) / np.pi - 2 * alpha / np.pi ** 1.5
        else:
            real = np.sum(erfc(alpha * d) / d) / np.pi
        return real - background + np.sum(weight * np.cos(k[:, 0] * x[0] + k[:, 1] * x[1]))
    return G


def touchdown(Lx: float, Ly: float, tallest: list, site: tuple, drop: float) -> tuple[float, float, float]:
    """The site's touchdown X* (E0*) in the small-spot limit for Hertz caps (s = 2, C = 0.5,
    R = 1), its Phi, and the tallest spot's radius there over the pitch Lx."""
    G = periodic_green(Lx, Ly)
    ref = tallest[0]
    phi = G((0.0, 0.0), True) + sum(G((ref[0] - t[0], ref[1] - t[1])) for t in tallest[1:]) \
        - sum(G((site[0] - t[0], site[1] - t[1])) for t in tallest)
    A, N = Lx * Ly, len(tallest)

    def h(X):
        P = X * A / N
        a = (0.75 * P) ** (1 / 3)
        return a * a + P * phi
    X_hi = (0.3 * Lx) ** 3 / 0.75 * N / A  # a spot of 0.3 l: far past where the limit holds
    if h(X_hi) < drop:
        return float("nan"), phi, float("nan")
    X = brentq(lambda x: h(x) - drop, 1e-16, X_hi, xtol=1e-300, rtol=1e-14)
    return X, phi, (0.75 * X * A / N) ** (1 / 3) / Lx


def main() -> None:
    for alpha in (None, 3.0):
        G = periodic_green(1.0, 1.0, alpha)
        print(f"square lattice's Psi (alpha {alpha or 'default'}): {G((0, 0), True) - G((0.5, 0.5)):.13f}"
              f" (docs/model.md (P3): -0.7272496931384)")
    l = 200 / 60
    H = l * np.sqrt(3)
    X, phi, a_l = touchdown(l, H, [(0, 0), (l / 2, H / 2)], (l / 2, H / 6), 2 / 60)
    print(f"hexagonal first-run example, level 1: Phi {phi:.4f}, X* {X:.6e} E0*, a/l {a_l:.3f}"
          f" (the 352-node curve: 9.31402e-4, unresolved)")
    try:
        import punchsweep
    except ImportError:
        print("(the punchsweep module is not on PYTHONPATH: the square lattice's tables are not compared)")
        return
    for l in (0.75, 1.5, 3.0):
        for dh in (1e-4, 1e-3, 1e-2, 3e-2):
            tables = float(punchsweep.surface_classify(pbar=1e-3, T=2.0, l=l, dh=dh, s=2).X_star[1])
            X, _, a_l = touchdown(l, l, [(0, 0)], (l / 2, l / 2), dh)
            print(f"square l {l} dh {dh}: X* {X:.6e} small-spot limit, {tables:.6e} periodic tables,"
                  f" {X / tables - 1:+.2e} of it, a/l {a_l:.3f}")


if __name__ == "__main__":
    main()
