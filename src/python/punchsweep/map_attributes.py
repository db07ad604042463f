"""The one reader of a regime map: the file checked as the engine writes it (open_map), its
physical scales (its attributes E0_star_Pa, R, R_m, time_unit) and its variables' units,
read, checked and converted one way for the Python module's open_map and the postprocess
scripts' (which load this file by its path: it needs no build)."""
from __future__ import annotations

import math
import os

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
    kPa for the pictures), R^2 in R's unit squared, R^2 E0/(1-nu^2) in N, and the rates of t* (dt_star_ddh, ...: T_eps
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
        scales["R^2"] = (number ** 2, f"{unit}^2")
        if time != "T_eps":
            scales["T_eps/R"] = (1.0 / number, f"{time}/{unit}")
        if E0_star is not None:
            scales["R^2 E0/(1-nu^2)"] = (R_m ** 2 * E0_star, "N")
    return scales


def _decoded_flags(variable, meanings: list[str], codes: list[int]):
    """A flag variable's codes as their meanings, decoded only where it is read (a lazily
    indexed array): decoding a whole map at once took about 260 bytes a point."""
    from xarray.backends import BackendArray
    from xarray.core import indexing

    table = np.array([f"code_{c - 128}" for c in range(256)], dtype=object)
    for code, meaning in zip(codes, meanings):
        table[int(code) + 128] = meaning
    width = max(len(str(t)) for t in table)
    table = table.astype(f"<U{width}")

    class Decoded(BackendArray):
        shape = variable.shape
        dtype = table.dtype

        def __getitem__(self, key):
            return indexing.explicit_indexing_adapter(key, self.shape, indexing.IndexingSupport.OUTER, self._read)

        def _read(self, key):
            raw = np.asarray(variable[key].values, dtype=np.int16)
            return table[raw + 128]

    return indexing.LazilyIndexedArray(Decoded())


def in_units(ds, units: str = "physical", pressure_unit: str = "Pa", decode_flags: bool = True, error=ValueError):
    """A map as both readers give it: every real variable's `units` the scale it is measured
    in (its file's `scaled_by`: R, T_eps, E0/(1-nu^2), ...), and with units="physical" each
    one whose scale the map knows (physical_scales, pressures in `pressure_unit`) converted:
    values in the physical unit, `units` that unit, `scaled_by` the scale, `per_scaled` the
    factor (scaled value = value / per_scaled). With `decode_flags` every flag variable is
    its meanings as text, read lazily, and its codes stay as NAME_code (the module's
    open_map); without, the codes stay under the name (the scripts)."""
    import xarray as xr

    for name in list(ds.variables):
        attrs = ds[name].attrs
        if "flag_values" in attrs and "flag_meanings" in attrs:
            if decode_flags:
                meanings = attrs["flag_meanings"]
                meanings = (meanings.decode() if isinstance(meanings, bytes) else str(meanings)).split()
                codes = [int(v) for v in np.atleast_1d(attrs["flag_values"])]
                ds[name + "_code"] = ds[name].copy()
                ds[name + "_code"].attrs["units"] = "1"
                ds[name] = xr.Variable(ds[name].dims, _decoded_flags(ds[name].variable, meanings, codes),
                                       {**attrs, "units": "1"})
        else:
            unit = attrs.get("scaled_by", attrs.get("units", "1"))
            ds[name].attrs["units"] = unit.decode() if isinstance(unit, bytes) else str(unit)
    scales = physical_scales(ds.attrs, pressure_unit, error) if units == "physical" else {}
    for name in list(ds.variables):
        scale = ds[name].attrs.get("units")
        if scale not in scales:
            continue
        factor, unit = scales[scale]
        attrs = {**ds[name].attrs, "units": unit, "scaled_by": scale, "per_scaled": factor}
        if name in ds.coords:
            ds = ds.assign_coords({name: (ds[name].dims, ds[name].values * factor, attrs)})
        else:
            ds[name] = ds[name] * factor
            ds[name].attrs = attrs
    return ds


def flag_table(attrs, variable: str, error=ValueError) -> tuple[tuple[int, ...], tuple[str, ...]]:
    """A flag variable's codes and meanings (its flag_values/flag_meanings), checked: both
    present and pairing up one to one."""
    values, meanings = attrs.get("flag_values"), attrs.get("flag_meanings")
    if values is None or meanings is None:
        raise error(f"'{variable}' has no flag_values/flag_meanings attributes, so its codes "
                    f"cannot be read")
    if isinstance(meanings, bytes):
        meanings = meanings.decode()
    codes = tuple(int(v) for v in np.atleast_1d(values))
    words = tuple(str(meanings).split())
    if len(codes) != len(words) or len(set(codes)) != len(codes) or len(set(words)) != len(words):
        raise error(f"'{variable}' has flag_values {' '.join(map(str, codes))} and flag_meanings "
                    f"'{meanings}', which do not pair up one to one")
    return codes, words


# The map layouts this reader knows, by kind: the engine's map::kRegimeLayoutVersion and
# map::kTextureLayoutVersion (src/map/layout_version.hpp; tests/python hold them equal). A
# map without the attribute was written before it: a regime map's layout 1, a texture's 1.
LAYOUT_VERSIONS = {"regime": 1, "texture": 2}


def layout_version(ds) -> int:
    """The map's layout (its `layout_version` attribute; 1 where it has none)."""
    return int(ds.attrs.get("layout_version", 1))


def is_texture_map(ds) -> bool:
    """Whether `ds` is a texture's map (`punchsweep surface-map`): regime over its axes and
    `level` last (each level's answer), valid over its axes and the times `t`."""
    return tuple(ds["regime"].dims)[-1:] == ("level",)


def check_layout(ds, error=ValueError) -> None:
    """A map's layout as the engine writes it: regime over its axes (a texture's map: and
    `level` last), each axis a coordinate variable of finite values (or labels), valid over
    the same axes (a texture's map: its axes and `t`; none in a texture's map of regime
    quantities, which reads no snapshot), both flag variables with their codes' meanings,
    and its physical scales what the engine writes."""
    names = tuple(ds["regime"].dims)
    if not names:
        raise error("regime has no dimensions")
    kind = "texture" if is_texture_map(ds) else "regime"
    if layout_version(ds) > LAYOUT_VERSIONS[kind]:
        raise error(f"its layout_version is {layout_version(ds)}, newer than this reader's {kind} maps "
                    f"(up to {LAYOUT_VERSIONS[kind]}): it was written by a newer punchsweep; read it with that one")
    expected_valid = set(names)
    if is_texture_map(ds):
        expected_valid = set(names[:-1]) | {"t"}
        names = names + ("t",)
    for name in names:
        if name not in ds.variables or ds[name].dims != (name,):
            raise error(f"regime's dimension '{name}' has no coordinate variable (dimension "
                        f"scale) with its grid values")
        values = ds[name].values
        if values.dtype.kind in "fiu" and not np.all(np.isfinite(values)):
            raise error(f"the axis {name} holds values that are not finite numbers: "
                        f"{[float(v) for v in values if not np.isfinite(v)][:3]}")
    flag_table(ds["regime"].attrs, "regime", error)
    if "valid" not in ds and is_texture_map(ds):
        scale_attributes(ds.attrs, error)
        return
    if set(ds["valid"].dims) != expected_valid:
        raise error(f"valid has the dimensions {', '.join(ds['valid'].dims)}, regime {', '.join(ds['regime'].dims)}")
    flag_table(ds["valid"].attrs, "valid", error)
    scale_attributes(ds.attrs, error)


def open_map(path, units: str = "physical", pressure_unit: str = "Pa", decode_flags: bool = True,
             error=ValueError):
    """A map file (a regime map of `punchsweep sweep`, or a texture's of `surface-map`: its
    regime and t* over a `level` dimension) as an xarray Dataset (h5netcdf, read lazily), checked (check_layout)
    and converted (in_units); `error` (the caller's exception type) says what is wrong with a
    file that is missing, a folder, damaged or no regime map, naming it. The module's
    open_map and the scripts' both read a map here."""
    import h5py
    import xarray as xr

    text = str(path)
    if os.path.isdir(text):
        raise error(f"'{text}' is a folder, not a map file (a run folder holds map.h5)")
    if not os.path.isfile(text):
        raise error(f"'{text}': no such file (the map file does not exist)")
    if not h5py.is_hdf5(text):
        raise error(f"'{text}' is not an HDF5 file, so not a punchsweep regime map")
    def unreadable(e: Exception):
        why = str(e).strip().splitlines()[0] if str(e).strip() else "unreadable"
        return error(f"'{text}' is not a readable punchsweep regime map ({type(e).__name__}: {why})")

    try:
        with h5py.File(text, "r") as f:
            # (A texture's map of regime quantities, each level's touch alone, has no valid.)
            texture = "X_star" in f and "level" in f
            missing = [n for n in ("regime", "valid") if n not in f and not (n == "valid" and texture)]
    except Exception as e:  # a damaged file
        raise unreadable(e) from None
    if missing:
        raise error(f"'{text}' is not a punchsweep regime map (no {', '.join(missing)}; a map holds the flag "
                    f"variables regime and valid over its axes)")
    try:
        ds = xr.open_dataset(text, engine="h5netcdf")
    except Exception as e:  # h5py's, h5netcdf's and xarray's errors for a file they cannot read
        raise unreadable(e) from None
    try:
        if is_texture_map(ds) and "R" in ds.attrs and "R_m" not in ds.attrs:
            # A texture's map written before its R was stated as a regime map's ("60um", no
            # R_m): it still opens, its lengths in R.
            ds.attrs["R_as_given"] = ds.attrs.pop("R")
        check_layout(ds, error)
        return in_units(ds, units, pressure_unit, decode_flags, error)
    except error as e:
        ds.close()
        raise error(f"'{text}' is not a punchsweep regime map ({e})") from None
