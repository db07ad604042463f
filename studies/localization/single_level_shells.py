#!/usr/bin/python3
"""Issue 12 study: where the single-level h of the localization model loses against the
periodic BEM, and how a family of localization models converges (docs/model.md, section 11).

The single-level phase (only level-1 punches touch) at creep-scaled pressure X (= pbar0 at
t = 0), E* = 1, the punch load P = X l^2. Around a punch at O, the level-1 punches of the K
nearest distance shells rho_k (n_k each) are kept, the nominal pressure X acts beyond A_K
with pi A_K^2 = (1 + sum n_k) l^2; around the square centre M the K nearest shells r_m
likewise, with pi A_M^2 = (sum n_m) l^2:

    balance  P = K_P a^(s+1) + P sum_k n_k <w(a, .)>_k + 2X (A_K^2 asin(a/A_K) - a sqrt(A_K^2 - a^2))
    depth    d = K_d a^s + P sum_k n_k <1/(pi sqrt(.^2 - a^2))>_k - 2X sqrt(A_K^2 - a^2)
    centre   u_M = P sum_m n_m <1/(pi .)>_m - 2X A_M,          h = d - u_M

<f>_k is f at the neighbour (point loads: f(rho_k), the paper's choice) or f averaged over
the neighbour's own pressure, p = 3P/(2 pi a^2) sqrt(1 - r'^2/a^2) for s = 2 ("distributed":
the m = 0 ring average about O of every point of the neighbour's spot, by a 24 x 48 Gauss
rule over the spot). K = 1 with point loads is eqs 9.5/9.10 of the paper.

The BEM values are `punchsweep reference` at N = 512, T = 1 (elastic), dh large (level 2
never touches), cached in bem_single_level.json with the command that made them; N = 1024
moves h by under 2e-6 relative at three of them (checked). s = 2, C = 0.5 throughout.

Usage: single_level_shells.py [--binary build/src/app/punchsweep] [--K 1,3,10,30,100]
  (--binary recomputes the BEM cache; without it the cache is read.)
"""
import argparse
import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
from numpy.polynomial.legendre import leggauss
from scipy.optimize import brentq

HERE = Path(__file__).resolve().parent
CACHE = HERE / "bem_single_level.json"
# (l, X): the table (N = 256 there) and two denser states at l = 0.75.
POINTS = [(0.5, 0.005), (0.5, 0.02), (0.75, 0.005), (0.75, 0.06), (1.0, 0.005), (1.0, 0.06),
          (1.5, 0.005), (1.5, 0.06), (0.75, 0.112), (0.75, 0.14)]
S, C = 2, 0.5


def coefficients(s, c):
    """K_P, K_d of the model notes, section 2."""
    load = math.exp((s - 1) * math.log(2) + 2 * math.log(s) + 2 * math.lgamma(0.5 * s) - math.log(s + 1)
                    - math.lgamma(s))
    depth = math.exp(math.log(s) + 2 * math.lgamma(0.5 * s) - (2 - s) * math.log(2) - math.lgamma(s))
    return c * load, c * depth


def shells(centre, l, K):
    """Distances and multiplicities of the K nearest shells of level-1 sites (i l, j l) about centre."""
    R = int(math.sqrt(K)) * 2 + 6
    i, j = np.meshgrid(np.arange(-R, R + 1), np.arange(-R, R + 1))
    d = np.hypot(i - centre[0] / l, j - centre[1] / l).ravel()
    d = np.round(d[d > 1e-12], 12)
    values, counts = np.unique(d, return_counts=True)
    return values[:K] * l, counts[:K]


_phi, _wphi = leggauss(24)
_phi, _wphi = 0.25 * math.pi * (_phi + 1), 0.25 * math.pi * _wphi
_th, _wth = leggauss(48)
_th, _wth = 0.5 * math.pi * (_th + 1), 0.5 * math.pi * _wth


def spot_average(f, rho, a):
    """(1/P) int f(|x'|) p(x' - rho e) dA' over a neighbour's s = 2 spot of radius a (r' = a sin phi)."""
    r = a * np.sin(_phi)[:, None]
    weight = (3 / math.pi) * np.sin(_phi)[:, None] * np.cos(_phi)[:, None] ** 2 * _wphi[:, None] * _wth[None, :]
    return float(np.sum(weight * f(np.sqrt(rho ** 2 + r ** 2 + 2 * rho * r * np.cos(_th)[None, :]))))


def share(a, r):
    """w(a, r): the share of a ring load at r that a punch of contact radius a carries."""
    return (2 / math.pi) * (a / np.sqrt(r ** 2 - a ** 2) - np.arcsin(a / r))


def single_level(l, X, K=1, distributed=False):
    """(a1, h) of the K-shell model."""
    KP, Kd = coefficients(S, C)
    P = X * l * l
    rk, nk = shells((0.0, 0.0), l, K)
    rm, nm = shells((0.5 * l, 0.5 * l), l, K)
    A = l * math.sqrt((1 + nk.sum()) / math.pi)
    AM = l * math.sqrt(nm.sum() / math.pi)

    def mean(f, rho, a):
        return spot_average(f, rho, a) if distributed else float(f(np.asarray(rho)))

    def balance(a):
        carried = sum(n * mean(lambda d: share(a, d), r, a) for r, n in zip(rk, nk))
        return KP * a ** (S + 1) + P * carried + 2 * X * (A * A * math.asin(a / A) - a * math.sqrt(A * A - a * a)) - P

    a = brentq(balance, 1e-9, 0.999999 * min(0.5 * l, A), xtol=1e-15)
    depth = (Kd * a ** S + P * sum(n * mean(lambda x: 1 / (math.pi * np.sqrt(x * x - a * a)), r, a)
                                   for r, n in zip(rk, nk)) - 2 * X * math.sqrt(A * A - a * a))
    centre = P * sum(n * mean(lambda x: 1 / (math.pi * x), r, a) for r, n in zip(rm, nm)) - 2 * X * AM
    return a, depth - centre


def bem(binary, l, X, N=512):
    cmd = [binary, "reference", "--l", str(l), "--dh", "5", "--T", "1", "--pbar", str(X), "--s", str(S),
           "--bem-grid", str(N), "--times", "0", "--format", "json"]
    out = json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)
    return {"l": l, "X": X, "N": N, "a1": out["series"]["a1"][0], "h": out["series"]["h"][0],
            "command": " ".join(cmd[1:])}


def main(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--binary", help="punchsweep binary: recompute the BEM cache with it")
    p.add_argument("--K", default="1,3,10,30,100", help="shell counts of the distributed model")
    args = p.parse_args(argv)
    if args.binary:
        CACHE.write_text(json.dumps([bem(args.binary, l, X) for l, X in POINTS], indent=1) + "\n")
    reference = json.loads(CACHE.read_text())
    Ks = [int(k) for k in args.K.split(",")]
    print("| l [R] | X [E0*] | a1/l | h BEM [R] | paper (K = 1, point loads) | "
          + " | ".join(f"K = {k}, distributed" for k in Ks) + " |")
    print("|---" * (5 + len(Ks)) + "|")
    for ref in reference:
        l, X = ref["l"], ref["X"]
        cells = []
        for K, dist in [(1, False)] + [(k, True) for k in Ks]:
            a, h = single_level(l, X, K, dist)
            cells.append(f"{100 * (h / ref['h'] - 1):+.2f}% (a1 {100 * (a / ref['a1'] - 1):+.2f}%)")
        print(f"| {l} | {X} | {ref['a1'] / l:.3f} | {ref['h']:.6f} | " + " | ".join(cells) + " |", flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
