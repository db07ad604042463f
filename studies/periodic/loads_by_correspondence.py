#!/usr/bin/python3
"""The worst loads of accuracy.py's study (issue 34), computed a third way: at the standard
linear solid point l 0.8697, dh 2.327e-4, pbar 4.850e-6, s 3, T 7.231, just after its
touchdown (t* = 1.7491), the model and the time-stepping reference differ in P2(2) by 8.8e-4 of
pbar l^2, while the reference's two grids agree to 3e-5. Here

    P2(t) = int_{t*}^{t} E(t - tau) dQ2(X(tau)),      X = pbar J(tau)

(the correspondence of docs/model.md, section 14.1) with Q2 from elastic boundary-element
solves (`punchsweep reference --T 1` at pbar = X) at 25 loads graded toward touchdown, summed
as a Stieltjes integral: no time stepping. Prints it beside the model's and the model's
elastic Q2 against the solves.

Usage: loads_by_correspondence.py [N]   (PYTHONPATH=build/python; N = 1024 by default)
"""
import math
import sys

import numpy as np


def main():
    import punchsweep as ps

    n = int(sys.argv[1]) if len(sys.argv) > 1 else 1024
    point = dict(l=0.8697311048382018, dh=0.0002327, s=3, C=0.5)
    pbar, T, t = 4.849556776599304e-06, 7.230910398262821, 2.0
    J = lambda u: T - (T - 1) * math.exp(-u)
    E = lambda u: 1 / T + (1 - 1 / T) * np.exp(-T * u)
    model = ps.point(pbar=pbar, T=T, times=[t], **point)
    t_star = model.t_star
    load = pbar * point["l"] ** 2
    taus = t_star + (t - t_star) * np.linspace(0, 1, 25) ** 2  # Q2 grows as (tau - t*)^(4/3)
    solved, own = [], []
    for tau in taus:
        X = pbar * J(tau)
        solved.append(ps.reference(T=1, pbar=X, times=[0], bem_grid=n, **point).series["P2"][0])
        own.append(ps.point(T=1, pbar=X, times=[0], **point).series["P2"][0])
    solved, own = np.array(solved), np.array(own)
    middle = 0.5 * (taus[1:] + taus[:-1])
    p2 = lambda q: float(np.sum(E(t - middle) * np.diff(q)))
    print(f"t* = {t_star:.6f}; the model's elastic Q2 against the solves at N = {n}: within "
          f"{np.max(np.abs(own - solved)) / load:.1e} of pbar l^2")
    print(f"P2({t}) / (pbar l^2): by correspondence from the solves {p2(solved) / load:.6f}, "
          f"from the model's Q2 {p2(own) / load:.6f}, the model {model.series['P2'][0] / load:.6f}")


if __name__ == "__main__":
    main()
