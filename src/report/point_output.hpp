#pragma once

#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include <boost/program_options/variables_map.hpp>

#include "input/command_options.hpp"
#include "model/point/point_evaluation.hpp"

namespace punchsweep::report {

enum class OutputFormat { table, json, csv };

/// --format table|json|csv (input::read_choice's refusal for another).
OutputFormat read_output_format(const boost::program_options::variables_map& vm);

/// Receives a point's output fields, as visit_point hands them out.
struct PointFields {
  virtual ~PointFields() = default;
  virtual void text(std::string_view name, const std::string& value) = 0;
  virtual void boolean(std::string_view name, bool value) = 0;
  virtual void number(std::string_view name, double value) = 0;  ///< NaN: not computed
  virtual void series(std::string_view name, const std::vector<double>& values) = 0;
};

/// A point's output in the JSON contract's order (map::kQuantities' model quantities):
/// regime by name (text), t_star, h_0, h_inf (numbers), valid (boolean) followed by its
/// reason (text), a1_inf, a2_inf, area_fraction_inf; then the series t and each series
/// quantity. The JSON writer and the Python module both read a point through it.
void visit_point(const model::PointResult& r, std::string_view time_unit, PointFields& fields);

/// One output in physical units: a field of the point (or its input) whose scale the
/// inputs know (input::physical_unit), in `units` (a UDUNITS-2 string).
struct PhysicalField {
  std::string name;
  std::vector<double> values;  ///< one value, or the series over t
  bool series = false;
  std::string units;
};

/// The point in physical units where its scales are known: R; the inputs l, dh (with R),
/// E0_star and pressure (with a material); the per-point quantities and series whose scale
/// is known (lengths in R's unit, loads in N, times in the material's unit) and t. Empty
/// without R and a material. JSON's "physical" and "units" objects and Python's point() read it.
std::vector<PhysicalField> physical_fields(const input::PointInputs& inputs, const model::PointResult& r);

/// Writes one evaluated point. The keys are map::kQuantities' model quantities (a
/// contract, in that order): regime, t_star (null for never), h_0, h_inf, valid (with
/// reason after it), a1_inf, a2_inf, area_fraction_inf, and series with arrays t and the
/// series quantities a1, a2, P1, P2, area_fraction. Numbers that could not be computed are
/// null (JSON), nan (CSV, table). Where the inputs know a physical scale, the JSON adds
/// "physical" (physical_fields, series in its own "series") and "units" (each of them to its
/// UDUNITS-2 string).
void write_point(std::ostream& out, OutputFormat format, const input::PointInputs& inputs, const model::PointResult& result);

}  // namespace punchsweep::report
