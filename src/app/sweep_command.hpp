#pragma once

#include <string>
#include <vector>

namespace punchsweep::app {

/// Exit code of a sweep stopped by SIGTERM, SIGUSR1 or SIGINT before it finished: the
/// finished tiles are safe and `--resume` completes the map.
inline constexpr int kInterruptedExitCode = 3;

/// `punchsweep sweep ...` (collective over MPI_COMM_WORLD; initializes and finalizes MPI).
/// Returns the process exit code: 0 done, 2 bad input (nothing written), 3 interrupted,
/// 1 failure.
int run_sweep_command(const std::vector<std::string>& args);

}  // namespace punchsweep::app
