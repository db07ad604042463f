#!/usr/bin/python3
"""Writes the same DMA readings in the shapes instrument software exports them, and in the
documented form (docs/fitting.md, "Data files"), for `punchsweep fit` (issue 37 item 2):

  documented.csv             temperature [C],frequency [Hz],storage [MPa],loss [MPa]
  trios_lims.txt             TA Instruments TRIOS "Export to LIMS" style: tab separated, a
                             preamble (file, instrument, geometry, procedure) and a step
                             marker, names without units and a units row under them
                             (Hz, MPa, degree sign C), a tan(delta) column, trailing tabs
  semicolon_decimal_comma.csv  a European-locale export (Netzsch Proteus / Anton Paar
                             RheoCompass style): semicolons, decimal commas, units in
                             parentheses, E' and E'', a preamble and a blank line
  tpe_a_truth.ini            the material the readings were made from
  parentheses_crlf.csv       a Windows export (Mettler-Toledo STARe / PerkinElmer Pyris
                             style): commas, CR LF line ends, "Storage Modulus (MPa)",
                             "Tan Delta", a preamble and a blank line before the header

The readings: a rubber of five Prony terms (tau 1e-5 .. 100 s), WLF C1 9, C2 120 K at 23 C,
isotherms 0 .. 80 C at 0.1 .. 100 Hz (10 each), each reading's logged temperature wandering
by 0.1 K, E' and E'' with 1% noise (seed 37). Every number is written with the same digits
in every file, so each file must give the same material as documented.csv
(tests/python/test_fit.py). The layouts are made here from the vendors' public descriptions
of their text exports, not copied from a vendor's file.

    /usr/bin/python3 examples/dma_exports/make_exports.py
"""
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
E_INF, E_I = 1.0e6, np.array([4e6, 3e6, 2e6, 1.5e6, 1e6])
TAU = np.array([1e-5, 1e-3, 1e-1, 3.0, 100.0])
C1, C2, T_REF = 9.0, 120.0, 23.0


def readings():
    rng = np.random.default_rng(37)
    rows = []
    for T in (0, 10, 23, 35, 50, 65, 80):
        f = np.logspace(-1, 2, 10)
        wt = 2 * np.pi * f[:, None] * 10 ** (-C1 * (T - T_REF) / (C2 + T - T_REF)) * TAU
        storage = E_INF + (E_I * wt**2 / (1 + wt**2)).sum(1)
        loss = (E_I * wt / (1 + wt**2)).sum(1)
        for k in range(len(f)):
            rows.append(tuple(f"{v:.6g}" for v in (T + rng.normal(0, 0.1), f[k],
                                                   storage[k] * (1 + 0.01 * rng.normal()) / 1e6,
                                                   loss[k] * (1 + 0.01 * rng.normal()) / 1e6)))
    return rows


def main():
    rows = readings()
    tan = [f"{float(l) / float(s):.5g}" for _, _, s, l in rows]
    (HERE / "documented.csv").write_text(
        "temperature [C],frequency [Hz],storage [MPa],loss [MPa]\n" + "".join(",".join(r) + "\n" for r in rows))
    trios = ["Filename\tTPE-A_freq_sweep.tri", "Instrument serial number\t4020-0123", "Instrument name\tRSA-G2",
             "Operator\tlab", "rundate\t11/27/2026", "Sample name\tTPE-A", "Geometry name\tFilm tension 10 x 5 x 0.5 mm",
             "Procedure name\tFrequency sweep 0-80 C", "", "[step]", "Frequency sweep - 1",
             "Frequency\tStorage modulus\tLoss modulus\ttan(delta)\tTemperature\tOscillation strain\t",
             "Hz\tMPa\tMPa\t\t\u00b0C\t%\t"]
    trios += [f"{f}\t{s}\t{l}\t{t}\t{T}\t0.1\t" for (T, f, s, l), t in zip(rows, tan)]
    (HERE / "trios_lims.txt").write_text("\n".join(trios) + "\n", encoding="utf-8")
    comma = lambda v: v.replace(".", ",")
    euro = ["Sample:;TPE-A", "Operator:;lab", "Date:;27.11.2026", "Mode:;tension, frequency sweep", "",
            "Temperature (\u00b0C);Frequency (Hz);E' (MPa);E'' (MPa);tan \u03b4"]
    euro += [";".join(map(comma, (T, f, s, l, t))) for (T, f, s, l), t in zip(rows, tan)]
    (HERE / "semicolon_decimal_comma.csv").write_text("\n".join(euro) + "\n", encoding="utf-8")
    windows = ["Sample name,TPE-A", "Geometry,tension film 10 x 5 x 0.5 mm", "Method,DMA frequency sweep 0-80 C", "",
               "Temperature (\u00b0C),Frequency (Hz),Storage Modulus (MPa),Loss Modulus (MPa),Tan Delta"]
    windows += [",".join((T, f, s, l, t)) for (T, f, s, l), t in zip(rows, tan)]
    (HERE / "parentheses_crlf.csv").write_bytes(("\r\n".join(windows) + "\r\n").encode("utf-8"))
    (HERE / "tpe_a_truth.ini").write_text(
        "# The material the readings were made from (make_exports.py): what a fit of them should\n"
        "# give back, and what docs/design.md's window is checked against.\n"
        "[material]\nname = TPE-A (the truth)\nlaw = prony\nmodulus_unit = MPa\ntime_unit = s\npoisson = 0.5\n"
        f"E_inf = {E_INF / 1e6:g}\nE_i = {', '.join(f'{v / 1e6:g}' for v in E_I)}\n"
        f"tau_i = {', '.join(f'{v:g}' for v in TAU)}\n"
        f"[shift]\nkind = wlf\nC1 = {C1:g}\nC2 = {C2:g}\nT_ref = {T_REF:g}\n")


if __name__ == "__main__":
    main()
