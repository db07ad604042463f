#pragma once

#include <string>
#include <vector>

namespace punchsweep::app {

/// `punchsweep sweep ...` (collective over MPI_COMM_WORLD; initializes and finalizes MPI).
/// Returns the process exit code: 0 done, 2 bad input (nothing written), 3 interrupted,
/// 1 failure.
int run_sweep_command(const std::vector<std::string>& args);

}  // namespace punchsweep::app
