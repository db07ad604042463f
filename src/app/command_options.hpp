#pragma once

#include <boost/program_options.hpp>

#include <functional>
#include <string>
#include <vector>

#include "model/contact_problem.hpp"
#include "model/shape.hpp"

namespace punchsweep::app {

/// Parses a one-shot command's arguments (long options only, so "--l -0.5" reads -0.5 as
/// a value; no positional arguments). Throws UsageError naming `command` for help.
boost::program_options::variables_map parse_command(const std::vector<std::string>& args,
                                                    const boost::program_options::options_description& opts,
                                                    const std::string& command);

/// A required (or defaulted) real option, range-checked. Throws UsageError naming the
/// option, its value and its valid range `range`.
double read_real(const boost::program_options::variables_map& vm, const char* name, const char* meaning,
                 const char* range, const std::function<bool(double)>& in_range);

/// --s (an integer in [1, 32], required) and --C (> 0) as a Shape.
model::Shape read_shape(const boost::program_options::variables_map& vm);

/// Declares the options of one parameter point: --help, --l, --dh, --T, --pbar, --s, --C
/// and --times, each with its unit and range.
void add_point_options(boost::program_options::options_description& opts);

/// --l, --dh, --pbar, --s and --C as a ContactProblem, each range-checked.
model::ContactProblem read_problem(const boost::program_options::variables_map& vm);

/// --T, the creep ratio of the standard linear solid (>= 1).
double read_creep_ratio(const boost::program_options::variables_map& vm);

/// A list option whose values must each satisfy `in_range` (described by `range`).
std::vector<double> read_real_list(const boost::program_options::variables_map& vm, const char* name,
                                   const char* range, const std::function<bool(double)>& in_range);

/// --format, one of `allowed`.
std::string read_choice(const boost::program_options::variables_map& vm, const char* name,
                        const std::vector<std::string>& allowed);

/// Shortest text that reads back to the same double; "null" for NaN or infinity (JSON).
std::string json_number(double value);

}  // namespace punchsweep::app
