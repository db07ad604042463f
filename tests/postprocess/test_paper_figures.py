"""paper_figures.py reproduces the paper's qualitative claims, checked on the data it plots
(the JSON written beside each figure), not on pixels."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "postprocess"))
from punchsweep_point import find_binary  # noqa: E402

BINARY = find_binary(os.environ.get("PUNCHSWEEP"))


@pytest.fixture(scope="module")
def figures(tmp_path_factory):
    out = tmp_path_factory.mktemp("paper")
    done = subprocess.run([sys.executable, str(REPO / "postprocess" / "paper_figures.py"), "--out", str(out),
                           "--binary", BINARY], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    for name in ("fig9_2", "fig9_3", "fig9_4", "fig9_5"):
        assert (out / f"{name}.png").read_bytes()[:4] == b"\x89PNG"
    return {name: json.loads((out / f"{name}.json").read_text())
            for name in ("fig9_2", "fig9_3", "fig9_4", "fig9_5", "table9_1")} | {"md": (out / "table9_1.md").read_text()}


def test_fig9_2_h_of_a1_increases_with_positive_slope(figures):
    for s in (1, 2, 3):
        curve = figures["fig9_2"][f"s={s}"]
        assert np.all(np.diff(curve["h"]) > 0), s
        assert np.all(np.array(curve["dh_da1"][1:]) > 0), s


def test_fig9_3_claims(figures):
    f = figures["fig9_3"]
    # "if dh = 0.04R ... the two-level contact does not occur at T = 2 or at l = 0.5R"
    assert f["regime_at_dh"]["l=0.75,T=2"] == "never" and f["regime_at_dh"]["l=0.5,T=10"] == "never"
    for key in ("l=0.75,T=5", "l=0.75,T=10", "l=1,T=10"):
        assert f["regime_at_dh"][key] == "delayed", key
    # h grows in time, with T (a) and with the pitch (b), towards the long-term elastic value.
    for panel in ("a", "b"):
        curves = f["panels"][panel]
        for c in curves:
            assert np.all(np.diff(c["h"]) > 0) and abs(c["h"][-1] - c["h_inf"]) < 0.01 * c["h_inf"]
        at_t1 = [c["h"][20] for c in curves]  # t = 1
        assert at_t1 == sorted(at_t1), panel


def test_fig9_4_growth_and_delayed_start(figures):
    a, b = figures["fig9_4"]["a"], figures["fig9_4"]["b"]
    t = np.array(figures["fig9_4"]["t"])
    assert a["regime"] == "immediate" and b["regime"] == "delayed"
    # "a1 increases about 1.2 times, while a2 increases 2.7 times to t = 5"
    assert round(a["a1"][-1] / a["a1"][0], 1) == 1.2 and round(a["a2"][-1] / a["a2"][0], 1) == 2.7
    a2 = np.array(b["a2"])
    assert np.all(a2[t < b["t_star"]] == 0) and np.all(a2[t > b["t_star"]] > 0)


def test_fig9_5_claims(figures):
    f = figures["fig9_5"]
    # (a) pbar0 = 0.025: transition to two-level contact only for l = 0.75; immediate for 1.0, 1.25.
    assert [c["regime"] for c in f["a"]] == ["delayed", "immediate", "immediate"]
    # (b) pbar0 = 0.06: dh = 0.05 immediate, 0.075 at t = 1.03 T_eps, 0.1 never.
    assert [c["regime"] for c in f["b"]] == ["immediate", "delayed", "never"]
    assert abs(f["b"][1]["t_star"] - 1.03) < 0.005
    # Smaller pitch and smaller height difference give a larger contact area.
    for group in ("a", "b"):
        final = [c["area_fraction"][-1] for c in f[group]]
        assert final == sorted(final, reverse=True), group


def test_table9_1_matches_the_paper(figures):
    t = figures["table9_1"]
    paper = {"P1": [0.0335, 0.0327, 0.0308, 0.0300], "P2": [0.0003, 0.0011, 0.0029, 0.0038],
             "a1": [0.2815, 0.2976, 0.3302, 0.3447], "a2": [0.0567, 0.0926, 0.1455, 0.1662],
             "A1": [0.9454, 0.9432, 0.9379, 0.9355], "A2": [0.8472, 0.8497, 0.8555, 0.8581]}
    np.testing.assert_allclose(t["E"], [1, 0.8, 0.5, 0.4], rtol=1e-12)
    for key, values in paper.items():
        np.testing.assert_allclose(t[key], values, atol=1e-4, rtol=0, err_msg=key)  # +-1 in the last digit
    assert "| 0.8 | 0.0327 | 0.0011 | 0.2976 | 0.0926 | 0.9432 | 0.8497 |" in figures["md"]
