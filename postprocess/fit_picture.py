#!/usr/bin/python3
"""A fitted material against its data: the picture `punchsweep fit` promises.

Reads the MATERIAL.fit.json that `punchsweep fit -o MATERIAL.ini` writes beside the material
file (or `punchsweep.fit_material(..., output=...)`), and draws three panels:

  master curve  E' and E'' (or E(t)) of every reading at its reduced frequency omega a_T
                (reduced time t / a_T), coloured by its isotherm's temperature; the fitted
                Prony series as lines; readings outside the fit's time window hollow grey;
  shifts        log10 a_T measured from the isotherms' overlap (points, on the law's zero as
                `punchsweep fit` writes them) and the shift law (line), against temperature;
  residuals     fit / reading - 1 in percent, against the reduced abscissa.

The title names the material, the reference temperature, the number of terms and the RMS
errors. Units: moduli in MPa, frequency in rad/s, time in s, temperature in degC.

Example:
  punchsweep fit --dma materials/dma/nrel_pyvisco_ems_ca.csv --reference-temperature -5 \\
      --poisson 0.35 -o ems_ca.ini
  postprocess/fit_picture.py ems_ca.fit.json -o ems_ca_fit.png
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import punchsweep_maps as pm  # noqa: E402

FIG_DPI = 150
MPA = 1e6


def parse_args(argv: list[str]) -> argparse.Namespace:
    return pm.picture_args(argv, "fit_picture.py", __doc__, "details", "MATERIAL.fit.json",
                           "`punchsweep fit` beside the material")


def read_details(path: str) -> dict:
    return pm.read_json(path, "a fit's details",
                        lambda d: d.get("kind") in ("dma", "relaxation") and "readings" in d,
                        "the .fit.json of `punchsweep fit` (no 'kind' and 'readings')")


def prony_curves(prony: dict, x: np.ndarray, dma: bool):
    """E', E'' at angular frequencies x, or E(t) at times x, of the fitted series (Pa)."""
    E = np.asarray(prony["E_i"], dtype=float)[:, None]
    tau = np.asarray(prony["tau_i"], dtype=float)[:, None]
    if dma:
        wt = x[None, :] * tau
        return prony["E_inf"] + (E * wt**2 / (1 + wt**2)).sum(0), (E * wt / (1 + wt**2)).sum(0)
    return prony["E_inf"] + (E * np.exp(-x[None, :] / tau)).sum(0), None


def render(d: dict):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib import cm, colors

    dma = d["kind"] == "dma"
    r = {k: np.asarray(v, dtype=float) for k, v in d["readings"].items()}
    used = r["used"] > 0.5
    temps = np.asarray(d["shift"]["temperatures"], dtype=float)
    norm = colors.Normalize(temps.min(), temps.max() if temps.max() > temps.min() else temps.min() + 1)
    cmap = plt.get_cmap("coolwarm")
    fig, (ax, ax_shift, ax_res) = plt.subplots(1, 3, figsize=(14.5, 4.6), gridspec_kw={"width_ratios": [1.5, 1, 1]})
    x = r["x_reduced"]
    first, second = ("storage", "loss") if dma else ("modulus", None)
    for name, marker in ((first, "o"), (second, "s")):
        if name is None:
            continue
        y = r[name] / MPA
        ax.scatter(x[used], y[used], c=r["temperature"][used], cmap=cmap, norm=norm, s=14, marker=marker,
                   edgecolors="none", zorder=3)
        if (~used).any():
            ax.scatter(x[~used], y[~used], s=14, marker=marker, facecolors="none", edgecolors="0.6", zorder=2)
    grid = np.logspace(np.log10(x[used].min()), np.log10(x[used].max()), 400)  # where it was fitted
    f1, f2 = prony_curves(d["prony"], grid, dma)
    ax.plot(grid, f1 / MPA, color="k", lw=1.4, label="E' fit" if dma else "E(t) fit", zorder=4)
    if f2 is not None:
        ax.plot(grid, f2 / MPA, color="k", lw=1.4, ls=(0, (5, 2)), label="E'' fit", zorder=4)
    ax.scatter([], [], marker="o", color="0.3", s=14, label="E' measured" if dma else "E(t) measured")
    if dma:
        ax.scatter([], [], marker="s", color="0.3", s=14, label="E'' measured")
    if (~used).any():
        ax.scatter([], [], marker="o", facecolors="none", edgecolors="0.6", s=14, label="outside the time window")
    ax.set_xscale("log")
    ax.set_yscale("log")
    T_ref = d["shift"].get("T_ref", temps[0])
    what = "frequency $\\omega a_T$ [rad/s]" if dma else "time $t / a_T$ [s]"
    ax.set_xlabel(f"reduced {what} at {T_ref:g} °C")
    ax.set_ylabel("modulus [MPa]")
    ax.legend(fontsize=8, loc="best")
    ax.grid(True, which="major", alpha=0.3)
    fig.colorbar(cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax, label="isotherm temperature [°C]", pad=0.01)

    shift = d["shift"]
    measured = np.asarray(shift["measured_log10_aT"], dtype=float)
    if np.isfinite(measured).any():
        ax_shift.plot(temps, measured, "o", color="k", ms=4, label="measured (overlap, on the law's zero)")
    if shift.get("law"):
        tt = np.linspace(temps.min(), temps.max(), 200)
        if shift["law"] == "wlf":
            law = -shift["C1"] * (tt - T_ref) / (shift["C2"] + tt - T_ref)
            label = f"WLF C1 = {shift['C1']:.4g}, C2 = {shift['C2']:.4g} K"
        else:
            law = shift["E_a"] / (8.314462618 * np.log(10)) * (1 / (tt + 273.15) - 1 / (T_ref + 273.15))
            label = f"Arrhenius E_a = {shift['E_a'] / 1e3:.4g} kJ/mol"
        ax_shift.plot(tt, law, color="C3", lw=1.4, label=label)
    ax_shift.set_xlabel("temperature [°C]")
    ax_shift.set_ylabel("log$_{10}$ $a_T$ [-]")
    ax_shift.set_title(f"shift factors (RMS about the law {shift['rms_log10']:.2g} decades)", fontsize=9)
    ax_shift.legend(fontsize=8)
    ax_shift.grid(True, alpha=0.3)

    for name, fit_name, marker in ((first, first + "_fit", "o"), (second, (second or "") + "_fit", "s")):
        if name is None:
            continue
        res = 100 * (r[fit_name] / r[name] - 1)
        ax_res.scatter(x[used], res[used], c=r["temperature"][used], cmap=cmap, norm=norm, s=12, marker=marker,
                       edgecolors="none")
    ax_res.axhline(0, color="k", lw=0.8)
    ax_res.set_xscale("log")
    ax_res.set_xlabel(f"reduced {'frequency [rad/s]' if dma else 'time [s]'}")
    ax_res.set_ylabel("fit / measured - 1 [%]")
    rms = d["prony"]["rms_relative"]
    ax_res.set_title("residuals of the fitted readings: RMS " +
                     ", ".join(f"{'E′' if k == 'storage' else 'E″' if k == 'loss' else 'E(t)'} {100 * v:.2g}%"
                               for k, v in rms.items()), fontsize=9)
    ax_res.grid(True, alpha=0.3)
    fig.suptitle(f"{d['name']}: Prony series of {len(d['prony']['E_i'])} terms at T_ref = {T_ref:g} °C, "
                 f"fitted to {int(used.sum())} of {len(used)} readings", fontsize=10)
    fig.tight_layout()
    return fig


def main(argv: list[str]) -> int:
    args = parse_args(argv)
    pm.picture_of(args.details, args.output, read_details, render, FIG_DPI)
    return 0


if __name__ == "__main__":
    sys.exit(pm.run_cli(main, "fit_picture.py"))
