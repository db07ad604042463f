#!/usr/bin/python3
"""Issue 23: the periodic model (`--localization periodic`, tables of the elastic periodic
solution read at the creep-weighted load X(t)) against the time-stepping periodic BEM
(`punchsweep reference --bem-grid 512`) at points drawn here, half of them where the
refined localization model is invalid (spots that merge).

Points: l in [0.5, 1.25], dh in [0.01, 0.12], pbar log-uniform in [0.005, 0.08], s in
{1, 2, 3}, C = 0.5, snapshot times 0, 0.5, 1, 2, 5; the law cycles through a standard
linear solid (T in [2, 10]), the same under a ramp (t_r = 1), and a Prony series with a WLF
shift (materials/pla_prusament_chapuis2025.ini at 75 C, WLF above T_g; times in s).

Measures, per point: the regime; |t* - t*_BEM| / t*_BEM (delayed points); the loads'
max over snapshots of |P_i - P_i,BEM| / (pbar(t) l^2); the radii's and area fraction's
relative difference max over snapshots (where the BEM value is > 2 grid spacings).

Usage: accuracy.py [--points 40] [--seed 23] [--grid 512] [--out results.json]
The BEM results are cached in bem_cache.json beside this file (keyed by the point).
"""
import argparse
import json
import math
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
CACHE = HERE / "bem_cache.json"
TIMES = [0.0, 0.5, 1.0, 2.0, 5.0]
MATERIAL = str(HERE.parents[1] / "materials" / "pla_prusament_chapuis2025.ini")


def draw(rng, k):
    law = ["sls", "ramp", "prony"][k % 3]
    p = dict(l=float(rng.uniform(0.5, 1.25)), dh=float(rng.uniform(0.01, 0.12)),
             pbar=float(math.exp(rng.uniform(math.log(0.005), math.log(0.08)))), s=int(rng.integers(1, 4)), C=0.5,
             times=TIMES)
    if law == "prony":
        p.update(material=MATERIAL, temperature=75, times=[0.0, 1e-3, 1e-1, 10.0, 1e3])
    else:
        p["T"] = float(rng.uniform(2, 10))
        if law == "ramp":
            p["ramp"] = 1.0
    return law, p


def rel(a, b):
    return abs(a - b) / abs(b) if b != 0 else (0.0 if a == 0 else math.inf)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--points", type=int, default=40)
    ap.add_argument("--seed", type=int, default=23)
    ap.add_argument("--grid", type=int, default=512)
    ap.add_argument("--out", default=None)
    args = ap.parse_args()
    import punchsweep as ps

    cache = json.loads(CACHE.read_text()) if CACHE.exists() else {}
    rng = np.random.default_rng(args.seed)
    want_invalid = args.points // 2
    chosen, invalid_refined, k = [], 0, 0
    while len(chosen) < args.points:
        law, p = draw(rng, k)
        k += 1
        refined = ps.point(localization="refined", **p)
        if not refined.valid and invalid_refined >= want_invalid:
            continue
        if refined.valid and len(chosen) - invalid_refined >= args.points - want_invalid:
            continue
        invalid_refined += not refined.valid
        chosen.append((law, p, refined.valid))

    rows = []
    for i, (law, p, refined_valid) in enumerate(chosen):
        key = json.dumps([args.grid, p], sort_keys=True)
        if key not in cache:
            try:
                b = ps.reference(bem_grid=args.grid, **p)
            except ValueError as e:
                print(f"{i:2d} {law:5s} reference failed: {e}", flush=True)
                continue
            cache[key] = dict(regime=b.regime, t_star=b.t_star,
                              series={q: [float(x) for x in b.series[q]] for q in ("a1", "a2", "P1", "P2", "area_fraction")})
            CACHE.write_text(json.dumps(cache, indent=0))
        b = cache[key]
        m = ps.point(localization="periodic", **p)
        spacing = p["l"] / args.grid
        scale = [p["pbar"] * p["l"] ** 2] * len(p["times"])
        if "ramp" in p:
            scale = [p["pbar"] * p["l"] ** 2 * min(max(t, 1e-300) / p["ramp"], 1.0) for t in p["times"]]
        loads = max(abs(m.series[q][j] - b["series"][q][j]) / scale[j]
                    for q in ("P1", "P2") for j in range(len(scale)) if scale[j] > 0)
        radii = max([rel(m.series[q][j], b["series"][q][j]) for q in ("a1", "a2") for j in range(len(scale))
                     if b["series"][q][j] > 2 * spacing] or [0.0])
        area = max(rel(m.series["area_fraction"][j], b["series"]["area_fraction"][j]) for j in range(len(scale)))
        # t* > 0 for delayed points and for immediate ones touching while a ramp rises.
        tstar = (rel(m.t_star, b["t_star"]) if m.regime == b["regime"] and b["t_star"]
                 else 0.0 if m.regime == b["regime"] else math.inf)
        rows.append(dict(law=law, point=p, refined_valid=refined_valid, regime=m.regime, bem_regime=b["regime"],
                         valid=m.valid, t_star=m.t_star, bem_t_star=b["t_star"], t_star_error=tstar, loads_error=loads,
                         radii_error=radii, area_error=area))
        print(f"{i:2d} {law:5s} l {p['l']:.3f} dh {p['dh']:.3f} pbar {p['pbar']:.4f} s {p['s']} "
              f"refined {'valid  ' if refined_valid else 'INVALID'} | {m.regime:9s} {b['regime']:9s} "
              f"t* {tstar:.1e} loads {loads:.1e} radii {radii:.1e} area {area:.1e} {'' if m.valid else m.reason}",
              flush=True)

    agree = sum(r["regime"] == r["bem_regime"] for r in rows)
    print(f"\nregimes agree: {agree}/{len(rows)}; periodic valid: {sum(r['valid'] for r in rows)}/{len(rows)}")
    for name in ("t_star_error", "loads_error", "radii_error", "area_error"):
        v = np.array([r[name] for r in rows])
        print(f"{name:13s} median {np.median(v):.2e}  worst {v.max():.2e}")
    if args.out:
        Path(args.out).write_text(json.dumps(rows, indent=1))


if __name__ == "__main__":
    main()
