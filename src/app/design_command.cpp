#include "app/design_command.hpp"

#include <algorithm>
#include <ostream>
#include <string>

#include "engine/design.hpp"
#include "input/command_options.hpp"
#include "input/usage_error.hpp"
#include "report/design_output.hpp"

namespace punchsweep::app {
namespace {

constexpr const char* kUsage =
    "usage: punchsweep design --require \"touch within 1s at 30kPa\" [--require \"never at 5kPa\" ...]\n"
    "         --material FILE --R R --l L --s S [--C C] [--temperature 20..40C]\n"
    "         [--lattice square|hexagonal [--dh2 DH2] [--grid N|auto]] [--find dh|dh2|l|pressure]\n"
    "         [--tolerance \"dh=0.5um, pressure=10%\"] [--format table|json] [point options]";

/// "--name value" and "--name=value" as keywords; --help alone.
input::Keywords keywords_of(const std::vector<std::string>& args) {
  input::Keywords out;
  for (std::size_t k = 0; k < args.size(); ++k) {
    const std::string& a = args[k];
    if (a.rfind("--", 0) != 0 || a.size() == 2) {
      throw input::UsageError("'" + a + "' is no option (options are --NAME VALUE; see punchsweep design --help)");
    }
    const std::size_t eq = a.find('=');
    if (eq != std::string::npos) {
      out.emplace_back(a.substr(2, eq - 2), a.substr(eq + 1));
    } else if (a == "--help" || a == "-h") {
      out.emplace_back("help", "");
    } else if (k + 1 < args.size()) {
      out.emplace_back(a.substr(2), args[++k]);
    } else {
      throw input::UsageError(a + " needs a value");
    }
  }
  return out;
}

}  // namespace

int run_design_command(const std::vector<std::string>& args, std::ostream& out) {
  const input::Keywords keywords = keywords_of(args);
  if (std::any_of(keywords.begin(), keywords.end(), [](const auto& kv) { return kv.first == "help"; })) {
    out << kUsage << "\n\n"
        << "The window of the height difference dh (or, --find dh2, l or pressure, of a third level's drop, the pitch or the pressure) that meets every requirement at every temperature of\n"
           "the range and every corner of the tolerance box (exact: the dh whose t* is the requirement's\n"
           "time, at each), its centre and margin, and which requirement binds each edge.\n\n"
           "  --require TEXT      "
        << engine::kRequirementForms
        << "\n  --temperature A..B  a range (degC, or K), checked at " << engine::kTemperatureSamples
        << " temperatures; or one temperature\n"
           "  --tolerance TEXT    'dh=0.5um, pressure=10%' (also l, C: 5% or a value; temperature: 2K widens the range)\n"
           "  --format FMT        table (default) or json\n"
           "  --find l            the window of the pitch l instead, for --dh DH, searched over --l A..B\n"
           "                      (100um..400um); the tolerance on l then moves its edges inward\n"
           "  --find pressure     the window of the nominal pressure instead, for --dh DH, searched over\n"
           "                      --pressure A..B (1kPa..200kPa; or --pbar); the requirements then name no\n"
           "                      pressure ('touch within 1min'), the pressure's tolerance moves its edges inward\n"
           "  --lattice KIND      a texture: square or hexagonal (surface's lattices), solved by its cell's boundary\n"
           "                      elements: each bound from one contact solve at the requirement's load (docs/design.md)\n"
           "  --dh2 DH2           a third level this far down (fixed; or --find dh2, its window for a given --dh)\n"
           "  --level 1|2         with --find l or pressure on a texture: the level the requirements are on (default 1)\n"
           "  --grid N|auto       a texture's nodes per pitch (auto: from 64, doubled until no edge moves by more\n"
           "                      than 1e-3 of itself, up to 256)\n"
           "  --supercell K --scatter DIST [--seed N]\n"
           "                      a scattered supercell (surface's): a drop's or the pitch's window on the level's\n"
           "                      first cap (its caps moved as one), a share of its caps or of every cap ('90% of\n"
           "                      level 1 within 1min at 20kPa', 'at most 5% of caps at 5kPa'); with --find\n"
           "                      pressure shares of any level or of every cap, read off the load curve of every cap\n"
           "  --cell FILE         a cell file: --find dh [--level L] (the level's tallest cap's drop) or pressure\n"
           "  --height-map FILE   a measured period (surface's options): --find pressure\n"
           "and the point's options but the pressure, and --dh but with --find l or pressure (punchsweep point --help).\n"
           "Example: punchsweep design --material materials/epoxy.ini --R 50um --l 250um --s 2 \\\n"
           "           --temperature 20..40C --require \"touch within 1s at 30kPa\" --require \"never at 5kPa\" \\\n"
           "           --tolerance \"dh=0.5um, pressure=10%\"\n"
           "Exit codes: 0 an answer (a window, or none with the nearest miss), 2 bad input.\n";
    return 0;
  }
  const engine::DesignResult d = engine::design(keywords);  // (it refuses a bad --format)
  std::string format = "table";
  for (const auto& [name, value] : keywords) format = name == "format" ? value : format;
  if (format == "json") {
    out << report::design_json(d);
  } else {
    report::write_design_table(out, d);
  }
  return 0;
}

}  // namespace punchsweep::app
