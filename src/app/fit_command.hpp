#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace punchsweep::app {

/// `punchsweep fit`: reads the measurement files, fits, writes the material file and its
/// .fit.json beside it (each written whole, then renamed into place), prints the report.
int run_fit_command(const std::vector<std::string>& args, std::ostream& out);

}  // namespace punchsweep::app
