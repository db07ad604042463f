#pragma once
/// @file
/// Measurements as instruments export them (docs/fitting.md, "Data files"): CSV text with a
/// header row naming each column and its unit in brackets or parentheses (or in a units row
/// under it),
///   temperature [C],frequency [Hz],storage [MPa],loss [MPa]
/// one row per reading, isotherms in any order, after any preamble (the header is the first
/// line naming frequency or time). Columns, by name (any case):
///   temperature  C, degC or K (or absent: the file's temperature given as FILE@40C)
///   frequency    Hz or rad/s
///   storage      E', in Pa, kPa, MPa or GPa; with `loss` (same units) or `tan_delta` [-]
///   time         s, ms, min or h; with `modulus` (Pa..GPa): a relaxation test E(t)
/// Commas, semicolons or tabs separate (with semicolons or tabs a decimal comma is a
/// point); `#` starts a comment line. Readings come out in SI (degC, rad/s, s, Pa).

#include <string>
#include <string_view>
#include <vector>

#include "fit/material_fit.hpp"

namespace punchsweep::input {

/// Reads one file's text into `into` (`origin` names it in messages; `temperature` in degC
/// is used when the file has no temperature column, NaN when none was given). Throws
/// UsageError naming the origin, the line, the column and the problem.
void read_measurements(std::string_view text, const std::string& origin, double temperature, fit::Measurements* into);

/// Reads "FILE" or "FILE@TEMP" (TEMP a temperature with its unit: 40C, 313.15K) for each
/// spec, every file of one kind (DMA or relaxation).
fit::Measurements read_measurement_files(const std::vector<std::string>& specs);

/// A temperature in degC from "23", "23C", "23 degC" or "296.15K" (a bare number is degC);
/// UsageError naming `option` otherwise.
double read_temperature(const std::string& text, const std::string& option);

}  // namespace punchsweep::input
