#include "app/surface_map_command.hpp"

#include <boost/program_options.hpp>

#include <sstream>
#include <utility>

#include "engine/texture_map.hpp"
#include "input/command_options.hpp"
#include "input/usage_error.hpp"

namespace po = boost::program_options;

namespace punchsweep::app {
namespace {

/// The command line's options as keywords: each as given (a switch as "true").
input::Keywords keywords_of(const std::vector<std::string>& args, const po::options_description& opts) {
  input::Keywords out;
  for (const po::option& o : po::command_line_parser(args).options(opts).run().options) {
    out.emplace_back(o.string_key, o.value.empty() ? "true" : o.value.front());
  }
  return out;
}

constexpr const char* kMapUsage =
    "usage: mpirun -n N punchsweep surface-map --lattice square|hexagonal --l AXIS --dh AXIS [--dh2 AXIS]\n"
    "           --pbar AXIS (or --pressure AXIS with --material) [--T AXIS | --temperature AXIS]\n"
    "           [--ramp AXIS] [--tolerance LIST] [--times LIST] [surface's texture options]\n"
    "           --output FILE\n\n"
    "An AXIS is one value, a list 'a, b, c', linspace(a, b, n) or logspace(a, b, n); --scatter\n"
    "normal:AXIS (or uniform:AXIS) makes the scatter's width an axis, --seed AXIS its seed (one\n"
    "supercell drawn per seed). Each geometry value is one\n"
    "load curve, built by one rank; the pressures, the law's values and the ramp times (the\n"
    "map's ramp_time axis) are read off it. --tolerance 'pressure=10%, T=0.2' adds each level's\n"
    "least and greatest t* over that box about every load point.";

}  // namespace

SurfaceMapArgs read_surface_map_args(const std::vector<std::string>& args) {
  SurfaceMapArgs out;
  const input::PointMaterial material = input::find_point_material(args);
  const po::options_description opts = engine::texture_map_options(material);
  const po::variables_map vm = input::parse_command(args, opts, "surface-map");
  if (vm.count("help")) {
    std::ostringstream help;
    help << kMapUsage << "\n\n" << opts
         << "\nExit codes: 0 success, 2 bad input, 3 stopped by a signal (resume it with --resume), 1 failure.\n";
    out.help = help.str();
    return out;
  }
  if (!vm.count("output")) throw input::UsageError("--output FILE is required: the map to write");
  out.output = vm["output"].as<std::string>();
  out.overwrite = vm["overwrite"].as<bool>();
  out.resume = vm["resume"].as<bool>();
  out.quiet = vm["quiet"].as<bool>();
  if (out.overwrite && out.resume) {
    throw input::UsageError("--resume and --overwrite: give only one (--resume finishes or checks the existing map, --overwrite replaces it)");
  }
  for (auto& [key, value] : keywords_of(args, opts)) {
    if (!engine::is_map_run_keyword(key)) out.keywords.emplace_back(std::move(key), std::move(value));
  }
  return out;
}

}  // namespace punchsweep::app
