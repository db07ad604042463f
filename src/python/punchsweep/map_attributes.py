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
