#pragma once

#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "app/command_options.hpp"
#include "model/point_evaluation.hpp"

namespace punchsweep::app {

enum class OutputFormat { table, json, csv };

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

/// Writes one evaluated point. The keys are map::kQuantities' model quantities (a
/// contract, in that order): regime, t_star (null for never), h_0, h_inf, valid (with
/// reason after it), a1_inf, a2_inf, area_fraction_inf, and series with arrays t and the
/// series quantities a1, a2, P1, P2, area_fraction. Numbers that could not be computed are
/// null (JSON), nan (CSV, table).
void write_point(std::ostream& out, OutputFormat format, const PointInputs& inputs, const model::PointResult& result);

}  // namespace punchsweep::app
