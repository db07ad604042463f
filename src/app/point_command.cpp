#include "app/point_command.hpp"

#include <boost/program_options.hpp>

#include <ostream>
#include <utility>

#include "report/point_output.hpp"
#include "engine/point_evaluation.hpp"
#include "input/command_options.hpp"

namespace po = boost::program_options;

namespace punchsweep::app {
namespace {

constexpr const char* kUsage = "usage: punchsweep point --l L --dh DH --T T --pbar P --s S [options]";

}  // namespace

int run_point_command(const std::vector<std::string>& args, std::ostream& out) {
  const input::PointMaterial material = input::find_point_material(args);
  const po::options_description opts = input::point_options(material);
  const po::variables_map vm = input::parse_command(args, opts, "point");
  if (vm.count("help")) {
    out << kUsage << "\n\n" << opts << "\n"
        << "Example: punchsweep point --l 0.75 --dh 0.075 --T 2.5 --pbar 0.06 --s 2 --format json\n"
        << "Exit codes: 0 success (a flagged point is still a success: see 'valid'), 2 bad input.\n";
    return 0;
  }
  engine::PointRequest request = engine::read_point(vm, material);
  const report::OutputFormat format = report::read_output_format(vm);
  const engine::PointRun run = engine::evaluate_point(std::move(request));
  report::write_point(out, format, run.inputs, run.result);
  return 0;
}

}  // namespace punchsweep::app
