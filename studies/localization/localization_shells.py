#!/usr/bin/python3
"""Issue 12 study: where the localization model loses against the periodic BEM, and how a
family of localization models converges (docs/model.md, section 11). Both phases at t = 0
(elastic, E* = 1): the single-level h and a1, and the two-level a1, a2.

Single level.
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

Two levels (level-2 punches at the square centres, dh lower). Around a punch of level i
every punch of either level within the D nearest distinct distances is kept (the paper's
model keeps D = 2: four of the other level at l/sqrt(2), four of its own at l), the
nominal pressure X acts beyond A_i with pi A_i^2 X = the loads kept (itself included),
and with Q1 + Q2 = X l^2:

    balance_i  Q_i = K_P a_i^(s+1) + sum_kept Q_j <w(a_i, .)>_j + 2X (A_i^2 asin(a_i/A_i) - a_i sqrt(A_i^2 - a_i^2))
    depth_i    d_i = K_d a_i^s + sum_kept Q_j <1/(pi sqrt(.^2 - a_i^2))>_j - 2X sqrt(A_i^2 - a_i^2),   d_1 - d_2 = dh

(D = 2 with point loads is eqs 9.12-9.15, Table 9.1.) A neighbour of level j is spread over
its own spot of radius a_j.

The BEM values are `punchsweep reference` at N = 512, T = 1 (elastic), cached in
bem_single_level.json (dh large: level 2 never touches) and bem_two_level.json with the
commands that made them; N = 1024 moves the single-level h by under 2e-6 relative at three
points (checked). s = 2, C = 0.5 throughout.

Usage: localization_shells.py [--binary build/src/app/punchsweep] [--K 1,3,10,30,100]
                              [--D 2,6,20,60,200]
  (--binary recomputes the BEM caches; without it they are read.)
"""
import argparse
import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
from numpy.polynomial.legendre import leggauss
from scipy.optimize import brentq, fsolve

HERE = Path(__file__).resolve().parent
CACHE = HERE / "bem_single_level.json"
CACHE_TWO = HERE / "bem_two_level.json"
CACHE_CREEP = HERE / "bem_two_level_creep.json"
# The paper's immediate points under the SLS, T = 2.5: a1, a2 at t = 5 (X = pbar0 J(5)).
T_CREEP, T_AT = 2.5, 5.0
# (l, X): the table (N = 256 there) and two denser states at l = 0.75.
POINTS = [(0.5, 0.005), (0.5, 0.02), (0.75, 0.005), (0.75, 0.06), (1.0, 0.005), (1.0, 0.06),
          (1.5, 0.005), (1.5, 0.06), (0.75, 0.112), (0.75, 0.14)]
# (l, dh, X): the paper's immediate points (docs/model.md, section 13.3) and two with a
# large level-2 spot.
POINTS_TWO = [(0.75, 0.05, 0.06), (1.0, 0.05, 0.025), (1.25, 0.05, 0.025), (0.75, 0.02, 0.06), (1.0, 0.02, 0.06)]
S, C = 2, 0.5


def coefficients(s, c):
    """K_P, K_d of the model notes, section 2."""
    load = math.exp((s - 1) * math.log(2) + 2 * math.log(s) + 2 * math.lgamma(0.5 * s) - math.log(s + 1)
                    - math.lgamma(s))
    depth = math.exp(math.log(s) + 2 * math.lgamma(0.5 * s) - (2 - s) * math.log(2) - math.lgamma(s))
    return c * load, c * depth


def site_distances(centre, l, offset, K):
    """Distances (in l) of the sites ((i + offset) l, (j + offset) l) from centre, enough for K shells."""
    R = int(math.sqrt(K)) * 2 + 6
    i, j = np.meshgrid(np.arange(-R, R + 1), np.arange(-R, R + 1))
    d = np.hypot(i + offset - centre[0] / l, j + offset - centre[1] / l).ravel()
    return np.round(d[d > 1e-12], 12)


def shells(centre, l, K):
    """Distances and multiplicities of the K nearest shells of level-1 sites (i l, j l) about centre."""
    values, counts = np.unique(site_distances(centre, l, 0.0, K), return_counts=True)
    return values[:K] * l, counts[:K]


def two_level_neighbours(level, l, D):
    """(distance, count, level) of the punches of both levels within the D nearest distinct
    distances of a punch of `level` (1 at the origin, 2 at the square centre)."""
    centre = (0.0, 0.0) if level == 1 else (0.5 * l, 0.5 * l)
    found = {}
    for other, offset in ((1, 0.0), (2, 0.5)):
        values, counts = np.unique(site_distances(centre, l, offset, 2 * D), return_counts=True)
        for v, n in zip(values, counts):
            found[(v, other)] = n
    kept = sorted({v for v, _ in found})[:D]
    return [(v * l, n, other) for (v, other), n in sorted(found.items()) if v in kept]


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
    """(a1, h) of the K-shell model: the K nearest shells of level-1 neighbours."""
    rk, nk = shells((0.0, 0.0), l, K)
    rm, nm = shells((0.5 * l, 0.5 * l), l, K)
    return single_level_kept(l, X, list(zip(rk, nk)), list(zip(rm, nm)), distributed)


def single_level_distances(l, X, D=2, distributed=False):
    """(a1, h) with the level-1 punches within the D nearest distances of either level (the
    engine's kept set, shared with the two-level model; D = 2 is the paper's)."""
    about_punch = [(rho, n) for rho, n, level in two_level_neighbours(1, l, D) if level == 1]
    about_centre = [(rho, n) for rho, n, level in two_level_neighbours(2, l, D) if level == 1]
    return single_level_kept(l, X, about_punch, about_centre, distributed)


def single_level_kept(l, X, about_punch, about_centre, distributed):
    """(a1, h) with the (distance, count) level-1 neighbours kept about the punch and the centre."""
    KP, Kd = coefficients(S, C)
    P = X * l * l
    A = l * math.sqrt((1 + sum(n for _, n in about_punch)) / math.pi)
    AM = l * math.sqrt(sum(n for _, n in about_centre) / math.pi)

    def mean(f, rho, a):
        return spot_average(f, rho, a) if distributed else float(f(np.asarray(rho)))

    def balance(a):
        carried = sum(n * mean(lambda d: share(a, d), r, a) for r, n in about_punch)
        return KP * a ** (S + 1) + P * carried + 2 * X * (A * A * math.asin(a / A) - a * math.sqrt(A * A - a * a)) - P

    a = brentq(balance, 1e-9, 0.999999 * min(0.5 * l if distributed else l, A), xtol=1e-15)
    depth = (Kd * a ** S + P * sum(n * mean(lambda x: 1 / (math.pi * np.sqrt(x * x - a * a)), r, a)
                                   for r, n in about_punch) - 2 * X * math.sqrt(A * A - a * a))
    centre = P * sum(n * mean(lambda x: 1 / (math.pi * x), r, a) for r, n in about_centre) - 2 * X * AM
    return a, depth - centre


def two_level(l, dh, X, D=2, distributed=False, guess=(0.25, 0.1), radii=None):
    """(a1, a2, Q1, Q2) of the D-distance two-level model, by Newton (fsolve) from `guess`.
    With radii = (A1, A2) the nominal-pressure radii are held at those values (eq 9.18's
    frozen radii) instead of following the loads kept."""
    KP, Kd = coefficients(S, C)
    kept = {1: two_level_neighbours(1, l, D), 2: two_level_neighbours(2, l, D)}

    def mean(f, rho, a_source):
        return spot_average(f, rho, a_source) if distributed and a_source > 0 else float(f(np.asarray(rho)))

    def residuals(z):
        a = {1: z[0], 2: z[1]}
        Q = {1: z[2], 2: z[3]}
        r, depth = [], {}
        for i in (1, 2):
            A = radii[i - 1] if radii else math.sqrt((Q[i] + sum(n * Q[j] for _, n, j in kept[i])) / (math.pi * X))
            carried = sum(n * Q[j] * mean(lambda x: share(a[i], x), rho, a[j]) for rho, n, j in kept[i])
            r.append(KP * a[i] ** (S + 1) + carried
                     + 2 * X * (A * A * math.asin(a[i] / A) - a[i] * math.sqrt(A * A - a[i] ** 2)) - Q[i])
            depth[i] = (Kd * a[i] ** S - 2 * X * math.sqrt(A * A - a[i] ** 2)
                        + sum(n * Q[j] * mean(lambda x: 1 / (math.pi * np.sqrt(x * x - a[i] ** 2)), rho, a[j])
                              for rho, n, j in kept[i]))
        return r + [z[2] + z[3] - X * l * l, depth[1] - depth[2] - dh]

    z = [guess[0], guess[1], 0.9 * X * l * l, 0.1 * X * l * l]
    for _ in range(4):  # fsolve restarted from where it stopped, if it stalls short of the root
        z, _, ok, message = fsolve(residuals, z, full_output=True, xtol=1e-13)
        worst = max(abs(v) for v in residuals(z))
        if worst <= 1e-12 * X * l * l / C:
            return tuple(z)
    raise RuntimeError(f"two-level model at l = {l}, dh = {dh}, X = {X}, D = {D}: residual {worst:.2g} ({message})")


def nominal_radii(l, X, D, Q1, Q2):
    """(A1, A2) of the D-distance model from the loads kept (pi A_i^2 X = Q_i + sum_kept Q_j)."""
    Q = {1: Q1, 2: Q2}
    return tuple(math.sqrt((Q[i] + sum(n * Q[j] for _, n, j in two_level_neighbours(i, l, D))) / (math.pi * X))
                 for i in (1, 2))


def two_level_creep(l, dh, pbar0, J, D=2, distributed=False, guess=(0.25, 0.1), frozen=True):
    """(a1, a2) at creep-scaled pressure pbar0 J of an immediate point: the radii frozen at
    their t = 0 values (section 5, eq 9.18: the elastic state at pbar0), or following the
    loads (frozen=False)."""
    a1, a2, Q1, Q2 = two_level(l, dh, pbar0, D, distributed, guess)
    radii = nominal_radii(l, pbar0, D, Q1, Q2) if frozen else None
    for X in pbar0 * np.geomspace(1.0, J, 12)[1:]:  # continuation in X from the t = 0 state
        a1, a2, Q1, Q2 = two_level(l, dh, X, D, distributed, (a1, a2), radii)
    return a1, a2


def reference(binary, l, dh, T, X, times, N=512):
    """`punchsweep reference` at one point: its series, and the command without the binary."""
    cmd = [binary, "reference", "--l", str(l), "--dh", str(dh), "--T", str(T), "--pbar", str(X), "--s", str(S),
           "--bem-grid", str(N), "--times", times, "--format", "json"]
    out = json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)
    return out["series"], " ".join(cmd[1:])


def bem(binary, l, X, N=512):
    series, command = reference(binary, l, 5, 1, X, "0", N)
    return {"l": l, "X": X, "N": N, "a1": series["a1"][0], "h": series["h"][0], "command": command}


def bem_creep(binary, l, dh, X, N=512):
    series, command = reference(binary, l, dh, T_CREEP, X, f"0,{T_AT:g}", N)
    return {"l": l, "dh": dh, "X": X, "N": N, "T": T_CREEP, "t": T_AT, "a1": series["a1"][1], "a2": series["a2"][1],
            "command": command}


def bem_two(binary, l, dh, X, N=512):
    series, command = reference(binary, l, dh, 1, X, "0", N)
    return {"l": l, "dh": dh, "X": X, "N": N, "a1": series["a1"][0], "a2": series["a2"][0], "P1": series["P1"][0],
            "P2": series["P2"][0], "command": command}


def print_table(title, header, rows):
    """A Markdown table under `title`; rows are (leading cells, compared cells), printed as made."""
    print(title + "\n")
    print("| " + " | ".join(header) + " |")
    print("|---" * len(header) + "|")
    for lead, cells in rows:
        print("| " + " | ".join(lead + list(cells)) + " |", flush=True)


def error(value, ref, digits):
    return f"{100 * (value / ref - 1):+.{digits}f}%"


def main(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--binary", help="punchsweep binary: recompute the BEM caches with it")
    p.add_argument("--K", default="1,3,10,30,100", help="shell counts of the distributed single-level model")
    p.add_argument("--D", default="2,6,20,60,200", help="distance counts of the distributed two-level model")
    args = p.parse_args(argv)
    if args.binary:
        CACHE.write_text(json.dumps([bem(args.binary, l, X) for l, X in POINTS], indent=1) + "\n")
        CACHE_TWO.write_text(json.dumps([bem_two(args.binary, *point) for point in POINTS_TWO], indent=1) + "\n")
        CACHE_CREEP.write_text(json.dumps([bem_creep(args.binary, *point) for point in POINTS_TWO[:3]], indent=1) + "\n")
    Ks = [int(k) for k in args.K.split(",")]

    def single_rows():
        for ref in json.loads(CACHE.read_text()):
            l, X = ref["l"], ref["X"]
            cells = (f"{error(h, ref['h'], 2)} (a1 {error(a, ref['a1'], 2)})"
                     for a, h in (single_level(l, X, K, dist) for K, dist in [(1, False)] + [(k, True) for k in Ks]))
            yield [str(l), str(X), f"{ref['a1'] / l:.3f}", f"{ref['h']:.6f}"], cells

    print_table("Single level, h (and a1) against the BEM:",
                ["l [R]", "X [E0*]", "a1/l", "h BEM [R]", "paper (K = 1, point loads)"]
                + [f"K = {k}, distributed" for k in Ks], single_rows())
    Ds = [int(d) for d in args.D.split(",")]

    def two_rows():
        for ref in json.loads(CACHE_TWO.read_text()):
            l, dh, X = ref["l"], ref["dh"], ref["X"]
            states = (two_level(l, dh, X, D, dist, guess=(ref["a1"], ref["a2"]))
                      for D, dist in [(2, False)] + [(d, True) for d in Ds])
            cells = (f"{error(a2, ref['a2'], 1)} (a1 {error(a1, ref['a1'], 2)})" for a1, a2, _, _ in states)
            yield [str(l), str(dh), str(X), f"{ref['a1']:.4f}, {ref['a2']:.4f}"], cells

    print()
    print_table("Two levels, a2 (and a1) against the BEM:",
                ["l [R]", "dh [R]", "X [E0*]", "a1, a2 BEM [R]", "paper (D = 2, point loads)"]
                + [f"D = {d}, distributed" for d in Ds], two_rows())
    J = T_CREEP - (T_CREEP - 1) * math.exp(-T_AT)  # the SLS creep function, J(0) = 1
    variants = [(d, frozen) for d in (2, 60, 200) for frozen in (True, False)]

    def creep_rows():
        for ref in json.loads(CACHE_CREEP.read_text()):
            l, dh, X = ref["l"], ref["dh"], ref["X"]
            states = (two_level_creep(l, dh, X, J, D, D > 2, guess=(0.28, 0.06), frozen=frozen) for D, frozen in variants)
            cells = (f"{error(a2, ref['a2'], 1)} (a1 {error(a1, ref['a1'], 2)})" for a1, a2 in states)
            yield [str(l), str(dh), str(X), f"{ref['a1']:.4f}, {ref['a2']:.4f}"], cells

    print()
    print_table(f"Two levels under creep (SLS T = {T_CREEP:g}, t = {T_AT:g}), a2 (and a1) against the BEM, radii "
                "frozen at t = 0 (eq 9.18) or following the loads:",
                ["l [R]", "dh [R]", "pbar0 [E0*]", "a1, a2 BEM [R]"]
                + [f"D = {d}{', distributed' if d > 2 else ', point'}, {'frozen' if frozen else 'free'}"
                   for d, frozen in variants], creep_rows())


if __name__ == "__main__":
    main(sys.argv[1:])
