#pragma once
/// @file
/// The creep laws the engine knows, by name: the one place that builds a law from its name
/// and parameter values. Nothing outside src/model names a concrete law; adding a law is a
/// class, one entry in creep_laws.cpp, and its row in the conformance test
/// (tests/model/creep_law_conformance_test.cpp).

#include <functional>
#include <memory>
#include <span>
#include <string_view>

#include "model/laws/creep_law.hpp"
#include "model/problem/parameter.hpp"

namespace punchsweep::model {

/// A creep law as the command line, configs and maps name it.
struct CreepLawSpec {
  std::string_view name;         ///< "standard_linear_solid"; also the map's creep_law attribute
  std::string_view alias;        ///< a short spelling accepted on input ("sls"); may be empty
  std::string_view description;  ///< one line with J(t), for help texts
  std::span<const Parameter> parameters;  ///< its parameters, in the order of a map's axes
  /// Builds the law from values in `parameters` order, each admitted by its Parameter.
  std::function<std::unique_ptr<CreepLaw>(std::span<const double> values)> make;
};

/// Every known creep law; the first is the default.
std::span<const CreepLawSpec> creep_laws();

/// The law called `name` (its name or alias); nullptr if none.
const CreepLawSpec* find_creep_law(std::string_view name);

/// The names of every law, "a, b (alias c)", for messages.
std::string creep_law_names();

/// Builds `law` from `values` (in law.parameters order). Throws std::invalid_argument with
/// Parameter::error's sentence for a value out of range or a wrong count.
std::unique_ptr<CreepLaw> make_creep_law(const CreepLawSpec& law, std::span<const double> values);

}  // namespace punchsweep::model
