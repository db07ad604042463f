#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "app/curve_commands.hpp"
#include "app/design_command.hpp"
#include "app/fit_command.hpp"
#include "app/point_command.hpp"
#include "app/reference_command.hpp"
#include "app/surface_command.hpp"
#include "app/texture_map_run.hpp"
#include "app/sweep_command.hpp"
#include "engine/periodic_tables.hpp"
#include "app/tables_command.hpp"
#include "input/usage_error.hpp"
#include "engine/version.hpp"

namespace {

constexpr const char* kTopHelp =
    "punchsweep: when does a two-level textured surface make full contact with a\n"
    "viscoelastic half-space? (Goryacheva & Yakovenko's localization method)\n\n"
    "usage: punchsweep <command> [options]\n\n"
    "commands:\n"
    "  point      evaluate one parameter point: regime, t*, contact state over time\n"
    "  sweep      evaluate a 5-D grid over (l, dh, T, pbar, s) on MPI ranks into an HDF5\n"
    "             regime map (mpirun -np N punchsweep sweep --config F.ini)\n"
    "  single-level  h(a1), a1(t), h(t) of the single-level phase (Figs. 9.2, 9.3)\n"
    "  elastic    the elastic two-level problem with free radii A_i (Table 9.1)\n"
    "  reference  one point by the periodic boundary-element solver (the model's check)\n"
    "  tables     the periodic model's tables: shipped for s = 1, 2, 3, built and cached for others\n"
    "  fit        a material file from DMA isotherms or a relaxation test (Prony series, WLF)\n"
    "  design     the window of dh that meets requirements ('touch within 1s at 30kPa', 'never at\n"
    "             5kPa') at every temperature of a range and corner of a tolerance box\n"
    "  surface    a square or hexagonal texture of two or three levels: each level's touch and\n"
    "             the contact areas in time, from its cell's elastic load curve\n"
    "  surface-map  a texture over geometry and load axes on MPI ranks (a curve per geometry, the\n"
    "             loads read off it) into a netCDF-4 map with a level axis\n\n"
    "options:\n"
    "  --help     this text; 'punchsweep <command> --help' explains a command\n"
    "  --version  print the version and git revision\n\n"
    "Exit codes: 0 success, 2 bad input (one line on stderr per problem, naming the option),\n"
    "3 sweep stopped by a signal (resume it with --resume), 1 failure.\n";

}  // namespace

int main(int argc, char** argv) {
  using punchsweep::input::UsageError;
  const std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
      std::cout << kTopHelp;
      return args.empty() ? punchsweep::input::kUsageExitCode : 0;
    }
    if (args[0] == "--version") {
      std::cout << "punchsweep " << punchsweep::engine::kVersion << " (git "
                << punchsweep::engine::kGitRevision << ")\n";
      return 0;
    }
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    punchsweep::engine::use_table_cache();
    if (args[0] == "point") return punchsweep::app::run_point_command(rest, std::cout);
    if (args[0] == "sweep") return punchsweep::app::run_sweep_command(rest);
    if (args[0] == "single-level") return punchsweep::app::run_single_level_command(rest, std::cout);
    if (args[0] == "elastic") return punchsweep::app::run_elastic_command(rest, std::cout);
    if (args[0] == "reference") return punchsweep::app::run_reference_command(rest, std::cout);
    if (args[0] == "tables") return punchsweep::app::run_tables_command(rest, std::cout);
    if (args[0] == "fit") return punchsweep::app::run_fit_command(rest, std::cout);
    if (args[0] == "design") return punchsweep::app::run_design_command(rest, std::cout);
    if (args[0] == "surface") return punchsweep::app::run_surface_command(rest, std::cout);
    if (args[0] == "surface-map") return punchsweep::app::run_surface_map_command(rest);
    throw punchsweep::input::UsageError("unknown command '" + args[0] +
                     "' (commands: point, sweep, single-level, elastic, reference, tables, fit, design, surface, surface-map; see punchsweep --help)");
  } catch (const punchsweep::input::UsageError& e) {
    std::cerr << "punchsweep: " << e.what() << "\n";
    return punchsweep::input::kUsageExitCode;
  } catch (const std::exception& e) {
    std::cerr << "punchsweep: internal error: " << e.what() << "\n";
    return 1;
  }
}
