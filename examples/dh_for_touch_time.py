#!/usr/bin/env python3
"""Which height difference dh makes the level-2 punches touch at a chosen time?

A design loop around punchsweep.classify: under a held nominal pressure the level-2
punches touch at t* (T_eps), and t* grows with dh from 0 at h(0) (below it they touch at
once) to infinity at h(inf) (above it they never touch). So for any target time between,
one dh gives t* = target, and scipy's brentq finds it between h(0) and h(inf), which
classify reports too. The picture is t* against dh from one vectorised call.

    PYTHONPATH=build/python /usr/bin/python3 examples/dh_for_touch_time.py \\
        --l 0.75 --T 2.5 --pbar 0.06 --s 2 --touch-at 2 --output dh_for_touch_time.png

Units: lengths in R, pressure in E0* = E0/(1-nu^2), time in T_eps (standard linear solid,
T = T_eps/T_sigma).
"""
from __future__ import annotations

import argparse
import sys

import numpy as np
from scipy.optimize import brentq

import punchsweep


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--l", type=float, default=0.75, help="lattice pitch, in R (default 0.75)")
    parser.add_argument("--T", type=float, default=2.5, help="creep ratio T_eps/T_sigma (default 2.5)")
    parser.add_argument("--pbar", type=float, default=0.06, help="nominal pressure, in E0* (default 0.06)")
    parser.add_argument("--s", type=int, default=2, help="shape exponent (default 2, paraboloid)")
    parser.add_argument("--touch-at", type=float, default=2.0, help="target t*, in T_eps (default 2)")
    parser.add_argument("--output", default="dh_for_touch_time.png", help="picture (PNG or PDF)")
    args = parser.parse_args(argv)

    def classify(dh):
        return punchsweep.classify(args.l, dh, args.T, args.pbar, args.s)

    try:
        ends = classify(0.0)
    except ValueError as e:  # the engine's message: the parameter and its valid range
        print(f"dh_for_touch_time: {e}", file=sys.stderr)
        return 2
    h_0, h_inf = float(ends["h_0"]), float(ends["h_inf"])
    # t* - target changes sign between h(0) (t* = 0) and just below h(inf) (t* -> inf).
    lo, hi = h_0, h_0 + (h_inf - h_0) * (1.0 - 1e-9)

    def excess(dh: float) -> float:
        return float(classify(dh)["t_star"]) - args.touch_at

    if not (excess(lo) < 0.0 < excess(hi)):
        print(f"dh_for_touch_time: t* = {args.touch_at} T_eps is not reached between h(0) = {h_0:.6g} R and "
              f"h(inf) = {h_inf:.6g} R", file=sys.stderr)
        return 2
    dh = brentq(excess, lo, hi, xtol=1e-12, rtol=1e-12)
    at = classify(dh)
    print(f"l = {args.l} R, T = {args.T}, pbar = {args.pbar} E0*, s = {args.s}: h(0) = {h_0:.6f} R, "
          f"h(inf) = {h_inf:.6f} R")
    print(f"dh = {dh:.6f} R makes level 2 touch at t* = {float(at['t_star']):.6f} T_eps "
          f"(target {args.touch_at}); the model is {'valid' if bool(at['valid']) else 'NOT valid'} there")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    grid = np.linspace(0.0, 1.3 * h_inf, 600)
    curve = classify(grid)
    fig, ax = plt.subplots(figsize=(6.4, 4.2), constrained_layout=True)
    touching = curve["t_star"] > 0
    ax.semilogy(grid[touching], curve["t_star"][touching], color="C0", label="t* (model)")
    invalid = touching & ~curve["valid"]
    if invalid.any():
        ax.semilogy(grid[invalid], curve["t_star"][invalid], ".", color="C3", ms=3, label="model flagged invalid")
    ax.axvline(h_0, color="0.5", ls=":", lw=1)
    ax.axvline(h_inf, color="0.5", ls=":", lw=1)
    ax.text(h_0, 0.03, " h(0): immediate below", transform=ax.get_xaxis_transform(), fontsize=8, color="0.3",
            rotation=90, va="bottom", ha="right")
    ax.text(h_inf, 0.03, " h(inf): never above", transform=ax.get_xaxis_transform(), fontsize=8, color="0.3",
            rotation=90, va="bottom", ha="right")
    ax.axhline(args.touch_at, color="C1", lw=1)
    ax.plot([dh], [args.touch_at], "o", color="C1", label=f"dh = {dh:.4f} R: t* = {args.touch_at:g} T_eps")
    ax.set_xlabel("height difference dh [R]")
    ax.set_ylabel("touchdown time t* [T_eps]")
    ax.set_title(f"Which dh touches at t* = {args.touch_at:g}? (l = {args.l} R, T = {args.T}, "
                 f"pbar = {args.pbar} E0*, s = {args.s})", fontsize=9)
    ax.legend(fontsize=8, loc="upper center")
    fig.savefig(args.output, dpi=150)
    print(f"picture: {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
