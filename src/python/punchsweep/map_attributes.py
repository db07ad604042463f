"""The attributes of a regime map that carry its physical scales (E0_star_Pa, R, R_m),
read and checked one way for the Python module's open_map and the postprocess scripts
(which load this file by its path: it needs no build)."""
from __future__ import annotations

import math

import numpy as np

LENGTH_UNITS = {"m": 1.0, "mm": 1e-3, "um": 1e-6, "nm": 1e-9}  # the engine's (model/numerics/units)


def scale_attributes(attrs, error=ValueError):
    """The map's physical scales as its attributes hold them, checked: E0_star_Pa (a finite
    number > 0, Pa), R ('50 um': a finite number > 0 and a length unit the engine writes) and
    R_m (R in m, agreeing with R); each None where absent. `error` (the caller's exception
    type) names the attribute and its value where one is not what the engine writes."""
    def text(v):
        return v.decode() if isinstance(v, bytes) else str(v)

    def positive(name):
        if name not in attrs:
            return None
        try:
            value = float(np.asarray(attrs[name]).item())
        except (TypeError, ValueError):
            value = math.nan
        if not (math.isfinite(value) and value > 0):
            raise error(f"the map's attribute {name} = {text(attrs[name])!r} is not a finite number > 0")
        return value

    E0_star, R_m, R = positive("E0_star_Pa"), positive("R_m"), None
    if "R" in attrs:
        parts = text(attrs["R"]).split()
        try:
            number = float(parts[0]) if len(parts) == 2 else math.nan
        except ValueError:
            number = math.nan
        if not (math.isfinite(number) and number > 0 and parts[1] in LENGTH_UNITS):
            raise error(f"the map's attribute R = {text(attrs['R'])!r} is not a length the engine writes "
                        f"(a number > 0 and one of {', '.join(LENGTH_UNITS)})")
        if R_m is None or abs(number * LENGTH_UNITS[parts[1]] - R_m) > 1e-9 * R_m:
            raise error(f"the map's attributes R = {text(attrs['R'])!r} and R_m = "
                        f"{text(attrs.get('R_m', 'missing'))!r} disagree")
        R = (number, parts[1])
    return E0_star, R, R_m


def physical_scales(attrs, pressure_unit: str = "Pa", error=ValueError) -> dict:
    """One unit of each scale the map knows, in physical units, as (factor, unit): R (attribute
    R, '50 um') in its unit, E0/(1-nu^2) (E0_star_Pa) in `pressure_unit` (Pa for the module,
    kPa for the pictures), R^2 E0/(1-nu^2) in N, and the rates of t* (dt_star_ddh, ...: T_eps
    per R or per E0*) in the material's time unit per R's unit and per that pressure unit.
    Times themselves already are in the material's unit. The one table the module's
    open_map and the postprocess scripts convert a map by."""
    per_pascal = {"Pa": 1.0, "kPa": 1e-3, "MPa": 1e-6}[pressure_unit]
    time = attrs.get("time_unit", "T_eps")
    time = time.decode() if isinstance(time, bytes) else str(time)
    scales = {}
    E0_star, R, R_m = scale_attributes(attrs, error)
    if E0_star is not None:
        scales["E0/(1-nu^2)"] = (E0_star * per_pascal, pressure_unit)
        if time != "T_eps":
            scales["T_eps/(E0/(1-nu^2))"] = (1.0 / (E0_star * per_pascal), f"{time}/{pressure_unit}")
    if R is not None:
        number, unit = R
        scales["R"] = R
        if time != "T_eps":
            scales["T_eps/R"] = (1.0 / number, f"{time}/{unit}")
        if E0_star is not None:
            scales["R^2 E0/(1-nu^2)"] = (R_m ** 2 * E0_star, "N")
    return scales
