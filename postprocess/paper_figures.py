#!/usr/bin/python3
"""Redraw the paper's Figs. 9.2-9.5 and Table 9.1 from punchsweep's own output.

Runs `punchsweep sweep` on every config in sweeps/paper/, `punchsweep single-level` for the
h curves (Figs. 9.2, 9.3) and `punchsweep elastic` for Table 9.1, then draws the figures
into --out, each beside a JSON file with exactly the data it plots (what the tests check
against the paper's claims) and table9_1.md.

Units: lengths in R, pressures in E0/(1-nu^2), time in T_eps.
Example:  postprocess/paper_figures.py --out paper-figures
"""
from __future__ import annotations

import argparse
import json
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import punchsweep_maps as pm  # noqa: E402
from punchsweep_point import REPO, find_binary  # noqa: E402

PAPER = REPO / "sweeps" / "paper"
TIMES = ",".join(f"{0.05 * i:g}" for i in range(101))  # 0 to 5 T_eps, as the paper's time axes


def engine(binary: str, *args: str) -> str:
    done = subprocess.run([binary, *args], capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"punchsweep {' '.join(args)} failed: {done.stderr.strip()}")
    return done.stdout


def sweep(binary: str, config: str, out: Path) -> Path:
    path = out / (Path(config).stem + ".h5")
    engine(binary, "sweep", "--config", str(PAPER / config), "--output", str(path), "--overwrite", "--quiet")
    return path


def open_sweep(binary: str, config: str, out: Path, axes: tuple[str, ...]):
    """Sweeps `config` and opens the map; MapError unless it has the axes the figure selects on."""
    ds = pm.open_map(sweep(binary, config, out))
    try:
        pm.require_axes(ds, axes, f"the figure from {config}")
    except pm.MapError:
        ds.close()
        raise
    return ds


def save(out: Path, name: str, fig, data: dict) -> None:
    pm.save_figure(fig, out / f"{name}.png", dpi=120)
    pm.write_whole(out / f"{name}.json", lambda tmp: Path(tmp).write_text(json.dumps(data, indent=1)))


def fig9_2(binary, out, plt):
    """h(a1) and dh/da1 for s = 1, 2, 3, C = 1, l = 0.5."""
    sweep(binary, "fig9_2.ini", out)  # the same points as a map (regime, h(0), h(inf))
    data = {}
    fig, ax = plt.subplots(1, 2, figsize=(10, 3.8), constrained_layout=True)
    for s, colour in zip((1, 2, 3), ("tab:red", "tab:blue", "tab:green")):
        c = json.loads(engine(binary, "single-level", "--l", "0.5", "--s", str(s), "--C", "1", "--a1-points", "101"))
        curve = c["h_of_a1"]
        data[f"s={s}"] = curve
        ax[0].plot(curve["a1"], curve["h"], color=colour, label=f"s = {s}")
        ax[1].plot(curve["a1"], curve["dh_da1"], color=colour, label=f"s = {s}")
    ax[0].set_ylabel("h [R]")
    ax[1].set_ylabel("dh/da$_1$ [-]")
    for a, title in zip(ax, ("(a)", "(b)")):
        a.set_xlabel("a$_1$ [R]")
        a.set_title(title, loc="left")
        a.legend()
        a.grid(alpha=0.3)
    fig.suptitle("Fig. 9.2: h(a$_1$), C = 1, l = 0.5 R")
    save(out, "fig9_2", fig, data)


def fig9_3(binary, out, plt):
    """h(t) for pbar0 = 0.01: (a) l = 0.75, T = 2, 5, 10; (b) T = 10, l = 0.5, 0.75, 1."""
    with open_sweep(binary, "fig9_3.ini", out, ("l", "T")) as ds:
        codes = pm.flags(ds, "regime")
        regimes = {f"l={float(l):g},T={float(T):g}": codes.meaning(ds.regime.sel(l=l, T=T).item())
                   for l in ds.l.values for T in ds.T.values}
    data = {"dh": 0.04, "regime_at_dh": regimes, "panels": {}}
    fig, ax = plt.subplots(1, 2, figsize=(10, 3.8), constrained_layout=True, sharey=True)
    panels = {"a": [(0.75, T) for T in (2, 5, 10)], "b": [(l, 10) for l in (0.5, 0.75, 1.0)]}
    for a, (key, cases) in zip(ax, panels.items()):
        data["panels"][key] = []
        for (l, T), colour in zip(cases, ("tab:red", "tab:blue", "tab:green")):
            c = json.loads(engine(binary, "single-level", "--l", repr(l), "--s", "2", "--pbar", "0.01", "--T", repr(T),
                                  "--times", TIMES, "--a1-points", "2"))
            label = f"T = {T:g}" if key == "a" else f"l = {l:g} R"
            a.plot(c["series"]["t"], c["series"]["h"], color=colour, label=label)
            a.axhline(c["h_inf"], color=colour, ls=":", lw=1)
            data["panels"][key].append({"l": l, "T": T, "t": c["series"]["t"], "h": c["series"]["h"], "h_inf": c["h_inf"]})
        a.axhline(0.04, color="k", ls="--", lw=0.8, label="dh = 0.04 R")
        a.set_xlabel("t [T$_\\varepsilon$]")
        a.set_title(f"({key})", loc="left")
        a.legend(fontsize=8)
        a.grid(alpha=0.3)
    ax[0].set_ylabel("h [R]")
    fig.suptitle("Fig. 9.3: h(t), pbar$_0$ = 0.01 E$_0$/(1-$\\nu^2$); dotted: long-term elastic")
    save(out, "fig9_3", fig, data)


MAP_AXES = ("l", "dh", "T", "pbar", "s")  # the axes map_reader selects on


def map_reader(ds):
    """Series and regime of the map at (l, dh, pbar), T = 2.5, s = 2."""
    codes = pm.flags(ds, "regime")

    def series(l, dh, pbar, name):
        return [float(v) for v in ds[name].sel(l=l, dh=dh, T=2.5, pbar=pbar, s=2).values]

    def t_star(l, dh, pbar):
        regime = codes.meaning(ds.regime.sel(l=l, dh=dh, T=2.5, pbar=pbar, s=2).item())
        value = float(ds.t_star.sel(l=l, dh=dh, T=2.5, pbar=pbar, s=2).item())
        return regime, (None if regime == "never" else value)

    return series, t_star


def fig9_4(binary, out, plt):
    """Radii for pbar0 = 0.06 (a) and 0.025 (b), l = 0.75, dh = 0.05, T = 2.5."""
    with open_sweep(binary, "fig9_4.ini", out, MAP_AXES) as ds:
        series, t_star = map_reader(ds)
        t = [float(v) for v in ds.time.values]
        data = {"t": t}
        fig, ax = plt.subplots(1, 2, figsize=(10, 3.8), constrained_layout=True)
        for a, (key, pbar) in zip(ax, (("a", 0.06), ("b", 0.025))):
            a1, a2 = series(0.75, 0.05, pbar, "a1"), series(0.75, 0.05, pbar, "a2")
            regime, ts = t_star(0.75, 0.05, pbar)
            data[key] = {"pbar": pbar, "a1": a1, "a2": a2, "regime": regime, "t_star": ts}
            a.plot(t, a1, color="tab:blue", label="a$_1$")
            a.plot(t, a2, color="tab:red", label="a$_2$")
            a.set_title(f"({key}) pbar$_0$ = {pbar} E$_0$/(1-$\\nu^2$): {regime}", loc="left", fontsize=10)
            a.set_xlabel("t [T$_\\varepsilon$]")
            a.set_ylabel("contact radius [R]")
            a.legend()
            a.grid(alpha=0.3)
        fig.suptitle("Fig. 9.4: l = 0.75 R, T = 2.5, dh = 0.05 R")
        save(out, "fig9_4", fig, data)


def fig9_5(binary, out, plt):
    """Area fraction; (a) dh = 0.05, pbar0 = 0.025, l varies; (b) l = 0.75, pbar0 = 0.06, dh varies."""
    with open_sweep(binary, "fig9_5.ini", out, MAP_AXES) as ds:
        series, t_star = map_reader(ds)
        t = [float(v) for v in ds.time.values]
        data = {"t": t, "a": [], "b": []}
        fig, ax = plt.subplots(1, 2, figsize=(10, 3.8), constrained_layout=True)
        colours = ("tab:red", "tab:blue", "tab:green")
        for l, colour in zip((0.75, 1.0, 1.25), colours):
            lam = series(l, 0.05, 0.025, "area_fraction")
            regime, ts = t_star(l, 0.05, 0.025)
            data["a"].append({"l": l, "area_fraction": lam, "regime": regime, "t_star": ts})
            ax[0].plot(t, lam, color=colour, label=f"l = {l:g} R ({regime})")
        for dh, colour in zip((0.05, 0.075, 0.1), colours):
            lam = series(0.75, dh, 0.06, "area_fraction")
            regime, ts = t_star(0.75, dh, 0.06)
            data["b"].append({"dh": dh, "area_fraction": lam, "regime": regime, "t_star": ts})
            label = f"dh = {dh:g} R ({regime}" + (f", t* = {ts:.3g}" if regime == "delayed" else "") + ")"
            ax[1].plot(t, lam, color=colour, label=label)
        ax[0].set_title("(a) dh = 0.05 R, pbar$_0$ = 0.025", loc="left", fontsize=10)
        ax[1].set_title("(b) l = 0.75 R, pbar$_0$ = 0.06", loc="left", fontsize=10)
        for a in ax:
            a.set_xlabel("t [T$_\\varepsilon$]")
            a.set_ylabel("relative contact area $\\lambda$ [-]")
            a.legend(fontsize=8)
            a.grid(alpha=0.3)
        fig.suptitle("Fig. 9.5: T = 2.5")
        save(out, "fig9_5", fig, data)


def table9_1(binary, out):
    with open_sweep(binary, "table9_1.ini", out, ("T",)) as ds:
        creep_ratios = [float(T) for T in ds.T.values]
    moduli = ",".join(repr(1.0 / T) for T in creep_ratios)
    args = ["elastic", "--l", "0.75", "--dh", "0.05", "--pbar", "0.06", "--s", "2", "--E", moduli]
    table = engine(binary, *args, "--format", "markdown")
    text = engine(binary, *args, "--format", "json")
    pm.write_whole(out / "table9_1.md", lambda tmp: Path(tmp).write_text("# Table 9.1 (punchsweep elastic)\n\n" + table))
    pm.write_whole(out / "table9_1.json", lambda tmp: Path(tmp).write_text(text))


def main(argv: list[str]) -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--out", required=True, help="folder for the figures (PNG), their data (JSON) and table9_1.md")
    p.add_argument("--binary", help="punchsweep executable (default: PATH or build/)")
    args = p.parse_args(argv)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out = Path(args.out)
    try:
        binary = find_binary(args.binary)
        out.mkdir(parents=True, exist_ok=True)
        fig9_2(binary, out, plt)
        fig9_3(binary, out, plt)
        fig9_4(binary, out, plt)
        fig9_5(binary, out, plt)
        table9_1(binary, out)
    except (FileNotFoundError, RuntimeError, OSError, pm.MapError) as e:
        print(f"paper_figures.py: {e}", file=sys.stderr)
        return 2
    print(f"paper_figures.py: wrote Figs. 9.2-9.5 (PNG + JSON) and table9_1.md to {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
