#include "app/fit_command.hpp"

#include <boost/program_options.hpp>

#include <ostream>
#include <string>
#include <vector>

#include "engine/material_fitting.hpp"
#include "input/command_options.hpp"
#include "input/usage_error.hpp"

namespace po = boost::program_options;

namespace punchsweep::app {
namespace {

constexpr const char* kUsage =
    "usage: punchsweep fit --dma FILE[@TEMP]... --poisson NU -o MATERIAL.ini [options]\n"
    "       punchsweep fit --relaxation FILE[@TEMP]... --poisson NU -o MATERIAL.ini [options]";

}  // namespace

int run_fit_command(const std::vector<std::string>& args, std::ostream& out) {
  std::vector<std::string> a = args;
  for (std::string& s : a) {
    if (s == "-o") s = "--output";
  }
  const po::options_description opts = engine::fit_options();
  const po::variables_map vm = input::parse_command(a, opts, "fit");
  if (vm.count("help")) {
    out << kUsage << "\n\n" << opts << "\n"
        << "Example: punchsweep fit --dma data.csv --reference-temperature 23 --poisson 0.5 -o material.ini\n"
        << "Exit codes: 0 success, 2 bad input or data that give no material (nothing written).\n";
    return 0;
  }
  if (!vm.count("output")) throw input::UsageError("missing -o/--output: the material file to write");
  const engine::FitRun run = engine::run_fit(vm);
  engine::write_fit_files(run);
  out << run.report;
  return 0;
}

}  // namespace punchsweep::app
