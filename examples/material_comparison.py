#!/usr/bin/env python3
"""Three real polymers under the same textured surface: when do the level-2 punches touch?

punchsweep.point with a material file (a Prony series from DMA tests, materials/*.ini) at
the same nominal pressure relative to each material's stiffness (pbar = p / E0*), over a
range of dh: t* in seconds from each material's own creep spectrum. The picture is t*
against dh, one curve per material, from h(0) (the same for all: at t = 0 every material
has modulus E0*, so below it level 2 touches at once) up to --dh-max; a curve ends where its
material never brings level 2 down (h(inf)).

    PYTHONPATH=build/python /usr/bin/python3 examples/material_comparison.py \\
        --pbar 0.01 --output material_comparison.png

Units: lengths in R, pressure in E0* of each material, time in the files' unit (s).
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

import punchsweep

REPO = Path(__file__).resolve().parent.parent
MATERIALS = {
    "NBR rubber (Linder 2011)": ("nbr_linder2011.ini", {}),
    "silicone (Elite Double 32)": ("silicone_elite_double32.ini", {}),
    "PLA at 60 C (Chapuis 2025)": ("pla_prusament_chapuis2025.ini", {"temperature": 60.0}),
}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--l", type=float, default=0.75, help="lattice pitch, in R (default 0.75)")
    parser.add_argument("--pbar", type=float, default=0.01, help="nominal pressure, in E0* (default 0.01)")
    parser.add_argument("--s", type=int, default=2, help="shape exponent (default 2)")
    parser.add_argument("--dh-max", type=float, default=0.08, help="largest dh, in R (default 0.08)")
    parser.add_argument("--points", type=int, default=40, help="dh values a curve (default 40)")
    parser.add_argument("--output", default="material_comparison.png", help="picture (PNG or PDF)")
    args = parser.parse_args(argv)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.2), constrained_layout=True)
    for i, (label, (file, extra)) in enumerate(MATERIALS.items()):
        material = str(REPO / "materials" / file)
        common = dict(l=args.l, pbar=args.pbar, s=args.s, material=material, times=[0.0], **extra)
        try:
            ends = punchsweep.point(dh=0.0, **common)
        except ValueError as e:
            print(f"material_comparison: {e}", file=sys.stderr)
            return 2
        h_0, h_inf = ends.h_0, ends.h_inf
        dh = np.linspace(h_0, args.dh_max, args.points + 1)[1:]
        results = [punchsweep.point(dh=float(d), **common) for d in dh]
        t = np.array([np.nan if r.t_star is None else r.t_star for r in results])
        valid = np.array([r.valid for r in results])
        ax.semilogy(dh, t, "-", color=f"C{i}", label=f"{label}: h(inf) = {h_inf:.3g} R")
        if (~valid).any():
            ax.semilogy(dh[~valid], t[~valid], "x", color=f"C{i}", ms=4)
        first = results[0]
        print(f"{label}: h(0) = {h_0:.5f} R, h(inf) = {h_inf:.5f} R; at dh = {dh[0]:.5f} R t* = "
              f"{first.t_star:.4g} {first.time_unit}; {int((~valid).sum())} of {len(dh)} points flagged invalid")
    ax.set_xlabel("height difference dh [R]")
    ax.set_ylabel("touchdown time t* [s]")
    ax.axvline(h_0, color="0.5", ls=":", lw=1)
    ax.text(h_0, 0.03, " h(0)", transform=ax.get_xaxis_transform(), fontsize=8, color="0.3", rotation=90,
            va="bottom", ha="right")
    ax.set_title(f"Level 2 touches after t*: pbar = {args.pbar} E0*, l = {args.l} R, s = {args.s} "
                 f"(x: model flagged invalid)", fontsize=9)
    ax.legend(fontsize=7, loc="lower right")
    fig.savefig(args.output, dpi=150)
    print(f"picture: {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
