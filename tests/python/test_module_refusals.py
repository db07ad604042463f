"""What the Python module refuses, and how (issue 48, part A): every wrapper refuses what it
cannot take as a ValueError or TypeError naming the argument, never with a numpy warning and a
silent answer: complex numbers (their imaginary part was dropped with a ComplexWarning), a
switch given as text (check='false' is truthy and stepped the cell), an array of more
dimensions where a 1-D list is meant (it was flattened), a list that mixes values with and
without a unit (the bare number read in the scale). An empty input is no error: it gives an
empty answer of the inputs' shape, in surface_classify as in classify."""
from __future__ import annotations

import re
import warnings
from pathlib import Path

import numpy as np
import pytest

import punchsweep

REPO = Path(__file__).resolve().parents[2]
SILICONE = REPO / "materials" / "silicone_elite_double32.ini"
TEXTURE = dict(l=0.75, dh=0.05, s=2)  # the square lattice of two levels: its curve from the tables


@pytest.fixture(autouse=True)
def warnings_are_errors():
    """A refusal is an exception, never a warning beside an answer."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        yield


@pytest.mark.parametrize("call, message", [
    (lambda: punchsweep.surface_classify(pbar=np.array([0.02 + 1j, 0.04]), T=2.5, **TEXTURE),
     "surface_classify: pbar = array([0.02+1.j, 0.04+0.j]): a complex number"),
    (lambda: punchsweep.surface_classify(pbar=[0.02, 0.04j], T=2.5, **TEXTURE), "surface_classify: pbar = "),
    (lambda: punchsweep.surface_classify(pbar=0.02, T=2.5 + 0j, **TEXTURE), "surface_classify: T = (2.5+0j): a complex"),
    (lambda: punchsweep.surface_classify(pbar=0.02, T=2.5, ramp_time=np.array([1 + 1j]), **TEXTURE),
     "surface_classify: ramp_time = array([1.+1.j]): a complex number"),
    (lambda: punchsweep.surface_classify(pressure="2kPa", material=SILICONE, temperature=[20 + 1j], R="50um",
                                         l="150um", dh="2um", s=2),
     "surface_classify: temperature = [(20+1j)]: a complex number"),
    (lambda: punchsweep.surface_classify(pbar=0.02, T=2.5, l=0.75 + 0j, dh=0.05, s=2), "l = (0.75+0j): a complex number"),
    (lambda: punchsweep.classify(l=0.75, dh=0.05, T=2.5, pbar=np.array([0.02 + 1j]), s=2),
     "classify: pbar = array([0.02+1.j]): a complex number"),
    (lambda: punchsweep.classify(l=0.75, dh=0.05, T=2.5, pbar=0.02, s=2, ramp_time=np.array([1 + 1j])),
     "classify: ramp_time = array([1.+1.j]): a complex number"),
    (lambda: punchsweep.classify(l=3.0, dh=0.04, s=2, material=SILICONE, pressure="2kPa", temperature=[20 + 1j]),
     "classify: temperature = [(20+1j)]: a complex number"),
    (lambda: punchsweep.classify(l=0.75, dh=0.05, T=2.5, pbar=0.02, s=2, C=np.complex64(0.5)), "classify: C = "),
    (lambda: punchsweep.point(l=0.75, dh=0.05 + 0j, T=2.5, pbar=0.02, s=2), "dh = (0.05+0j): a complex number"),
])
def test_complex_input_is_refused_naming_the_argument(call, message):
    """surface_classify took a complex pbar with a ComplexWarning and its real part; classify
    refused a complex pbar but took a complex temperature or ramp_time alike. Both now refuse
    any argument that holds a complex number, named, before the engine sees it."""
    with pytest.raises(ValueError, match=re.escape(message)):
        call()


@pytest.mark.parametrize("call, message", [
    (lambda: punchsweep.surface(T=2.5, pbar=0.02, check="false", **TEXTURE), "check = 'false': valid: True or False"),
    (lambda: punchsweep.surface(T=2.5, pbar=0.02, check=1, **TEXTURE), "check = 1: valid: True or False"),
    (lambda: punchsweep.surface_map(pbar=[0.02, 0.04], T=2.5, overwrite="no", **TEXTURE),
     "overwrite = 'no': valid: True or False"),
    (lambda: punchsweep.fit_material(REPO / "materials" / "dma" / "nrel_pyvisco_ems_ca.csv", reference_temperature=25,
                                     poisson=0.35, refine="no"), "refine = 'no': valid: True or False"),
    (lambda: punchsweep.fit_material(REPO / "materials" / "dma" / "nrel_pyvisco_ems_ca.csv", reference_temperature=25,
                                     poisson=0.35, accept_poor_fit="false"),
     "accept_poor_fit = 'false': valid: True or False"),
    (lambda: punchsweep.surface(T=2.5, pbar=0.02, supercell=True, **TEXTURE), "supercell = True: a punchsweep option"),
])
def test_a_switch_takes_a_bool_only(call, message):
    """A switch keyword's text was taken by its truth: check='false' stepped the cell,
    refine='no' refined, overwrite='no' overwrote. Each takes True or False (numpy's bools
    too) and refuses anything else as a TypeError naming it; a bool given to an option that
    takes a number is named too."""
    with pytest.raises(TypeError, match=re.escape(message)):
        call()


def test_numpy_bools_are_switches():
    plain = punchsweep.surface(T=2.5, pbar=0.02, times=[0, 1], check=np.bool_(False), **TEXTURE)
    assert "check" not in plain and plain["levels"][1]["regime"] == "delayed"


@pytest.mark.parametrize("call, message", [
    (lambda: punchsweep.surface(T=2.5, pbar=0.02, times=[[0, 1], [2, 5]], **TEXTURE),
     "times = [[0, 1], [2, 5]]: an array of shape (2, 2); valid: one value or a 1-D list"),
    (lambda: punchsweep.surface(T=2.5, pbar=0.02, times=np.array([[0.0, 1.0], [2.0, 5.0]]), **TEXTURE),
     "times = array([[0., 1.], [2., 5.]]): an array of shape (2, 2)"),
    (lambda: punchsweep.surface(T=2.5, pbar=np.array([[0.02]]), **TEXTURE), "pbar = array([[0.02]]): an array of shape (1, 1)"),
    (lambda: punchsweep.surface_classify(pbar=[0.02, 0.04], T=2.5, times=[[0], [1]], **TEXTURE),
     "times = [[0], [1]]: an array of shape (2, 1)"),
    (lambda: punchsweep.surface_map(pbar=0.02, T=2.5, l=[[0.75]], dh=0.05, s=2), "l = [[0.75]]: an array of shape (1, 1)"),
    (lambda: punchsweep.point(l=0.75, dh=0.05, T=2.5, pbar=0.02, s=2, times=[[0, 1], [2]]), "times = [[0, 1], [2]]: an array of lists"),
    (lambda: punchsweep.surface_map(pbar=[[0.02, 0.04]], T=2.5, **TEXTURE), "pbar = [[0.02, 0.04]]: an array of shape (1, 2)"),
])
def test_an_array_of_more_dimensions_is_refused_where_a_list_is_meant(call, message):
    """An option's list (times, a surface's pbar, a texture's l) is 1-D: a 2-D array was
    flattened into it, its shape lost. Refused, naming the argument and its shape."""
    with pytest.raises(ValueError, match=re.escape(message)):
        call()


def test_the_vectorized_calls_still_broadcast_arrays_of_any_dimension():
    """Where the contract is numpy's broadcasting (classify's every coordinate, surface_classify's
    load and law), arrays of any dimension stay welcome."""
    c = punchsweep.classify(l=0.75, dh=np.linspace(0.02, 0.08, 3)[:, None, None], T=np.array([[2.0, 2.5]]),
                            pbar=np.array([0.02, 0.04])[:, None], s=2)
    assert c["t_star"].shape == (3, 2, 2)
    r = punchsweep.surface_classify(pbar=np.full((2, 3), 0.02), T=[[2.0], [2.5]], **TEXTURE)
    assert r["t_star"].shape == (2, 3, 2)
    one = punchsweep.surface_classify(pbar=[0.02], T=[2.5], **TEXTURE)
    assert np.array_equal(r["t_star"][1, 2], one["t_star"][0])


def test_an_empty_input_gives_an_empty_answer_of_its_shape():
    """classify takes an empty array and answers with empty arrays; surface_classify refused it
    ('the arrays must have the same size > 0'). It now answers with empty arrays of the inputs'
    shape plus the axis of levels, and the texture's X_star as any call gives them."""
    c = punchsweep.classify(l=0.75, dh=np.array([]), T=2.5, pbar=0.02, s=2)
    assert c["t_star"].shape == (0,) and c["regime"].dtype == np.int8
    full = punchsweep.surface_classify(pbar=[0.02, 0.04], T=2.5, **TEXTURE)
    empty = punchsweep.surface_classify(pbar=np.array([]), T=2.5, **TEXTURE)
    assert empty["t_star"].shape == (0, 2) and empty["regime"].shape == (0, 2)
    assert empty["t_star"].dtype == np.float64 and empty["regime"].dtype == np.int8
    assert np.array_equal(empty["X_star"], full["X_star"]) and empty["caps"] == full["caps"]
    wide = punchsweep.surface_classify(pbar=np.zeros((3, 0)), T=np.array([2.0, 2.5, 3.0])[:, None], **TEXTURE)
    assert wide["t_star"].shape == (3, 0, 2)
    material = punchsweep.surface_classify(pressure=[], material=SILICONE, R="50um", l="150um", dh="2um", s=2)
    assert material["t_star"].shape == (0, 2) and material["time_unit"] == "s"


@pytest.mark.parametrize("call, message", [
    (lambda: punchsweep.classify(l=3.0, dh=0.04, s=2, material=SILICONE, pressure=["2kPa", 0.01]),
     "classify: pressure = ['2kPa', 0.01]: it mixes values with and without a unit"),
    (lambda: punchsweep.classify(l=3.0, dh=0.04, s=2, material=SILICONE, pbar=["2kPa", 0.01]),
     "classify: pbar = ['2kPa', 0.01]: it mixes values with and without a unit"),
    (lambda: punchsweep.classify(l=3.0, dh=["2um", "0.04"], s=2, material=SILICONE, pressure="2kPa", R="50um"),
     "classify: dh = ['2um', '0.04']: it mixes values with and without a unit"),
    (lambda: punchsweep.surface_classify(pressure=["2kPa", 0.01], material=SILICONE, R="50um", l="150um", dh="2um", s=2),
     "surface_classify: pressure = ['2kPa', 0.01]: it mixes values with and without a unit"),
    (lambda: punchsweep.surface_classify(pbar=[0.001, "2kPa"], material=SILICONE, R="50um", l="150um", dh="2um", s=2),
     "surface_classify: pbar = [0.001, '2kPa']: it mixes values with and without a unit"),
])
def test_a_list_that_mixes_values_with_and_without_a_unit_is_refused(call, message):
    """A bare number is in the model's scale, one with a unit physical (docs/cli.md, Units):
    a list of both (pbar=['2kPa', 0.01]: 2 kPa and 0.01 E0*, a hundred times apart in a
    silicone) was taken element by element. Refused, as the command line refuses such an
    axis, naming the argument."""
    with pytest.raises(ValueError, match=re.escape(message)):
        call()


def test_zero_needs_no_unit_beside_values_with_one():
    """0 is 0 in every unit, as on the command line: dh=['2um', 0] is taken."""
    both = punchsweep.classify(l="150um", dh=["2um", 0], s=2, material=SILICONE, pressure="2kPa", R="50um")
    alone = punchsweep.classify(l="150um", dh="2um", s=2, material=SILICONE, pressure="2kPa", R="50um")
    assert both["t_star"][0] == alone["t_star"]
