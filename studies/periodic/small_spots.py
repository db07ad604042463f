#!/usr/bin/python3
"""Where the periodic model's two tables hold (issue 34, docs/model.md, section 14.7): the
elastic cell (l = 1, C = 1, T = 1, t = 0, so pbar is the scaled load xi and dh the scaled
height difference delta) by direct boundary-element solves at N = 1024 and 2048 (`punchsweep
reference`), against
  - the model (the default, `periodic`),
  - the small-spot table alone: the refined localization with the lattice's exact far field
    (its h plus (Psi - Psi_D) xi, its two levels at dh = eta h_D: what the table holds),
  - the boundary elements' tables alone: the engine before the small-spot table (commit
    732bc55), recorded in the cache with the binary that made them (--old-binary).
Single level: h and a1 at a1/l = 0.04 ... 0.35; two levels: a1, a2 (relative to a1) and
Q2 / xi at a1/l = 0.15 ... 0.40 and eta = delta / h = 0.1 ... 0.97, the worst of the six.

Usage: small_spots.py [--old-binary PATH]   (PYTHONPATH=build/python)
Results are cached in small_spots_cache.json beside this file (the reference's, and the old
engine's with its revision); a run with the cache present solves nothing again.
"""
import argparse
import json
import math
import subprocess
from pathlib import Path

HERE = Path(__file__).resolve().parent
CACHE = HERE / "small_spots_cache.json"
# The small-spot table's far-field correction, Psi - Psi_D (the header of small_spot-s*.inc):
# the lattice's exact constant less the refined localization's own.
FAR_FIELD_CORRECTION = 2.200713690e-4
SINGLE = (0.04, 0.06, 0.08, 0.10, 0.12, 0.15, 0.18, 0.22, 0.26, 0.30, 0.35)
TWO = (0.15, 0.20, 0.25, 0.30, 0.35, 0.40)
ETAS = (0.1, 0.3, 0.5, 0.7, 0.9, 0.97)


def K_P(s):
    return 2 ** (s - 1) * s * s * math.gamma(s / 2) ** 2 / ((s + 1) * math.gamma(s))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--old-binary", default=None, help="punchsweep at 732bc55, for the tables-alone column")
    args = ap.parse_args()
    import punchsweep as ps

    cache = json.loads(CACHE.read_text()) if CACHE.exists() else {}

    def cached(key, compute):
        if key not in cache:
            cache[key] = compute()
            CACHE.write_text(json.dumps(cache, indent=0, sort_keys=True))
        return cache[key]

    def bem(s, xi, delta, grid):
        def solve():
            b = ps.reference(l=1, C=1, T=1, pbar=xi, dh=delta, s=s, times=[0], bem_grid=grid)
            return [float(b.series[q][0]) for q in ("a1", "a2", "P2", "h")]
        return cached(json.dumps(["bem", s, xi, delta, grid]), solve)

    def old(s, xi, delta):
        def run():
            if not args.old_binary:
                return None
            out = subprocess.run([args.old_binary, "point", "--l", "1", "--C", "1", "--T", "1", "--pbar", repr(xi),
                                  "--dh", repr(delta), "--s", str(s), "--times", "0", "--format", "json"],
                                 capture_output=True, text=True, check=True).stdout
            d = json.loads(out)
            return [d["series"]["a1"][0], d["series"]["a2"][0], d["series"]["P2"][0], d["h_0"]]
        value = cached(json.dumps(["732bc55", s, xi, delta]), run)
        if value is None:
            del cache[json.dumps(["732bc55", s, xi, delta])]
        return value

    def model(s, xi, delta, localization="periodic"):
        r = ps.point(l=1, C=1, T=1, pbar=xi, dh=delta, s=s, times=[0], localization=localization)
        return [float(r.series["a1"][0]), float(r.series["a2"][0]), float(r.series["P2"][0]), r.h_0]

    f = lambda x: "-" if x is None else f"{x:+.1e}"
    print("Single level, relative to the boundary elements at N = 2048 (h; a1):\n")
    print("| s | a1/l | xi | model | small-spot table alone | boundary-element tables alone | N = 1024 |")
    print("|---|---|---|---|---|---|---|")
    for s in (1, 2, 3):
        for a in SINGLE:
            xi = K_P(s) * a ** (s + 1)
            ref, coarse = bem(s, xi, 10.0, 2048), bem(s, xi, 10.0, 1024)
            m = model(s, xi, 10.0)
            small = model(s, xi, 10.0, "refined")
            small[3] += FAR_FIELD_CORRECTION * xi  # the refined model's far field made exact
            o = old(s, xi, 10.0)
            cell = lambda v: "-" if v is None else f"{v[3] / ref[3] - 1:+.1e}; {v[0] / ref[0] - 1:+.1e}"
            print(f"| {s} | {a:.2f} | {xi:.2e} | {cell(m)} | {cell(small)} | {cell(o)} | {cell(coarse)} |")

    print("\nTwo levels, the worst of eta = 0.1 ... 0.97, against N = 2048 (a1 relative; a2 of a1; Q2 of xi):\n")
    print("| s | a1/l | model | small-spot table alone | boundary-element tables alone | N = 1024 |")
    print("|---|---|---|---|---|---|")
    for s in (1, 2, 3):
        for a in TWO:
            xi = K_P(s) * a ** (s + 1)
            h_own = model(s, xi, 10.0, "refined")[3]
            h = h_own + FAR_FIELD_CORRECTION * xi
            worst = {k: [0.0, 0.0, 0.0] for k in ("model", "small", "old", "coarse")}
            have_old = True
            for eta in ETAS:
                delta = eta * h
                ref = bem(s, xi, delta, 2048)
                values = dict(model=model(s, xi, delta), small=model(s, xi, eta * h_own, "refined"),
                              old=old(s, xi, delta), coarse=bem(s, xi, delta, 1024))
                for k, v in values.items():
                    if v is None:
                        have_old = False
                        continue
                    e = [abs(v[0] / ref[0] - 1), abs(v[1] - ref[1]) / ref[0], abs(v[2] - ref[2]) / xi]
                    worst[k] = [max(x, y) for x, y in zip(worst[k], e)]
            g = lambda w: f"{w[0]:.1e}; {w[1]:.1e}; {w[2]:.1e}"
            print(f"| {s} | {a:.2f} | {g(worst['model'])} | {g(worst['small'])} | "
                  f"{g(worst['old']) if have_old else '-'} | {g(worst['coarse'])} |")


if __name__ == "__main__":
    main()
