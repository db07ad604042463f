#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace punchsweep::app {

/// `punchsweep tables --s 1,2,3`: makes sure the periodic model's tables of each s are at
/// hand (shipped, or in the table cache with a valid signature, or built with progress and kept
/// there), or with --write-source builds them afresh as the source text the engine ships.
/// Prints one line per s (where the tables come from, their ranges, the time). Returns the
/// exit code; throws UsageError for bad input.
int run_tables_command(const std::vector<std::string>& args, std::ostream& out);

}  // namespace punchsweep::app
