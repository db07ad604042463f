#include "app/surface_command.hpp"

#include <boost/program_options.hpp>

#include <cmath>
#include <ostream>
#include <sstream>

#include "report/surface_output.hpp"
#include "input/usage_error.hpp"
#include "engine/surface_evaluation.hpp"

namespace po = boost::program_options;

namespace punchsweep::app {
namespace {

constexpr const char* kUsage =
    "usage: punchsweep surface --lattice square|hexagonal --l L --dh DH [--dh2 DH2] --T T --pbar P --s S [options]";

}  // namespace

int run_surface_command(const std::vector<std::string>& given, std::ostream& out) {
  // --dry-run is the command's switch, not a texture's key (a map's [texture] takes none).
  std::vector<std::string> args;
  bool dry_run = false;
  for (const std::string& a : given) {
    if (a == "--dry-run") {
      dry_run = true;
    } else {
      args.push_back(a);
    }
  }
  const input::PointMaterial material = input::find_point_material(args);
  const po::options_description opts = engine::surface_options(material);
  const po::variables_map vm = input::parse_command(args, opts, "surface");
  if (vm.count("help")) {
    out << kUsage << "\n\n" << opts << "  --dry-run             what the curve asks (its grids, memory, whether the cache holds it, "
        << "the time to build it estimated for this machine); nothing is built\n\n"
        << "Example: punchsweep surface --lattice hexagonal --l 1.2 --dh 0.05 --T 2.5 --pbar 0.02 --s 2 --format json\n"
        << "Exit codes: 0 success (a flagged snapshot is still a success: see 'valid'), 2 bad input.\n";
    return 0;
  }
  engine::SurfaceRun run = engine::read_surface(vm, material);
  if (dry_run) {
    const engine::CurveCost cost = engine::curve_cost(run);
    write_curve_cost(out, cost);
    if (run.seeds > 1) {
      double each = 0.0;
      for (const engine::CurveCost::Grid& grid : cost.grids) each += grid.built_seconds;
      const std::streamsize precision = out.precision(3);
      out << "  --seeds " << run.seeds << ": as many draws, each its own supercell and curve on the same grid (the "
          << "first's above): about " << each << " s each to build, " << each * (run.seeds - 1) << " s for the other "
          << run.seeds - 1 << (run.target_error > 0.0 ? " at most (--target-error may stop sooner)" : "")
          << "; a draw the cache holds is read\n";
      out.precision(precision);
    }
    return 0;
  }
  const report::OutputFormat format = report::read_output_format(vm);
  if (run.seeds > 1) {
    const engine::SurfaceEnsemble ensemble = engine::evaluate_ensemble(run, vm, material, true);
    report::write_surface(out, format, run, &ensemble);
    return 0;
  }
  engine::evaluate(run, true);
  report::write_surface(out, format, run);
  return 0;
}

void write_curve_cost(std::ostream& out, const engine::CurveCost& cost) {
  const std::streamsize precision = out.precision(3);
  out << "punchsweep surface --dry-run\n";
  out << "  cell: " << cost.caps << " caps, " << cost.levels << " levels\n";
  if (cost.source != "cell") {
    out << "  curve: off the periodic tables (no boundary elements; milliseconds)\n";
    out.precision(precision);
    return;
  }
  double seconds = 0.0;
  for (const engine::CurveCost::Grid& grid : cost.grids) {
    out << "  curve on " << grid.nx << " x " << grid.ny << " nodes";
    if (grid.nodes_per_pitch > 0) out << " (" << grid.nodes_per_pitch << " a pitch)";
    out << ": about " << grid.bytes / 1e6 << " MB; ";
    if (grid.cached) {
      out << "in the cache (read, not built)\n";
    } else if (grid.continued_from > 0.0) {
      out << "in the cache to X = " << grid.continued_from << " E0*, continued from there, at most about " << grid.seconds
          << " s on one core\n";
    } else {
      out << "to build, about " << grid.seconds << " s on one core\n";
    }
    seconds += grid.seconds;
  }
  if (cost.auto_grid) {
    out << "  --grid auto: the curves above at least; where t* still moves by more than " << engine::kAutoTStarAccuracy
        << " of itself between them the nodes double (to " << engine::kAutoMaxNodes << " a pitch)\n";
  }
  if (std::isfinite(cost.X_reach)) {
    out << "  each curve stops at its first sample past X = " << cost.X_reach
        << " E0*, X(inf) of the load (--full-curve: to full contact); the seconds are a whole curve's, at most\n";
  }
  out << "  estimated time: about " << seconds << " s (each estimate within a factor of " << engine::kCurveSecondsSpread
      << " of this machine's measured curves)\n";
  out.precision(precision);
}

}  // namespace punchsweep::app
