#pragma once
/// @file
/// The exit code of a map's run stopped by a signal (SIGTERM, SIGINT, SIGUSR1): its
/// finished tiles or geometries are journalled and --resume continues it. Bad input is
/// input::kUsageExitCode (2), any other failure 1.

namespace punchsweep::run {

inline constexpr int kInterruptedExitCode = 3;

}  // namespace punchsweep::run
