#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace punchsweep::app {

/// `punchsweep single-level ...`: the single-level phase on its own (level 2 ignored):
/// h(a1) and dh/da1 along the solution curve (Fig. 9.2) and, given --pbar and --T, a1(t)
/// and h(t) (Fig. 9.3). Returns the exit code; throws UsageError for bad input.
int run_single_level_command(const std::vector<std::string>& args, std::ostream& out);

/// `punchsweep elastic ...`: the elastic two-level problem with free radii A_i, eqs
/// (9.12)-(9.15), for one or several moduli (Table 9.1).
int run_elastic_command(const std::vector<std::string>& args, std::ostream& out);

}  // namespace punchsweep::app
