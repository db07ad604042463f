#include "engine/material_fitting.hpp"

#include <boost/program_options.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string_view>

#include "engine/version.hpp"
#include "input/material_file.hpp"
#include "input/value_parsing.hpp"
#include "input/measurement_file.hpp"
#include "input/usage_error.hpp"
#include "io/output_file.hpp"
#include "model/numerics/number_text.hpp"
#include "model/numerics/units.hpp"

namespace po = boost::program_options;

namespace punchsweep::engine {

po::options_description fit_options() {
  po::options_description opts(
      "punchsweep fit: a material file from measurements (docs/fitting.md). The isotherms are\n"
      "shifted onto a master curve at the reference temperature (shift factors from the\n"
      "overlap of neighbouring isotherms, then WLF or Arrhenius fitted to them, or the law\n"
      "given), and a Prony series is fitted to it by non-negative least squares on relative\n"
      "errors, its number of terms chosen by the Bayesian information criterion and its\n"
      "times refined. Writes MATERIAL.ini and MATERIAL.fit.json (readings, shifts and fit,\n"
      "for postprocess/fit_picture.py), and prints the report.\n\nOptions");
  opts.add_options()
      ("help", "this text")
      ("dma", po::value<std::vector<std::string>>()->composing()->value_name("FILE[@TEMP]"),
       "DMA readings: CSV with a header row naming each column and its unit, e.g.\n"
       "'temperature [C],frequency [Hz],storage [MPa],loss [MPa]' (or tan_delta [-] for\n"
       "loss; frequency in Hz or rad/s; moduli in Pa, kPa, MPa or GPa; temperature in C or\n"
       "K). Repeat for one file per temperature; FILE@40C gives the temperature of a file\n"
       "without that column")
      ("relaxation", po::value<std::vector<std::string>>()->composing()->value_name("FILE[@TEMP]"),
       "a relaxation test instead: 'temperature [C],time [s],modulus [MPa]'")
      ("reference-temperature", po::value<std::string>()->value_name("T"),
       "the master curve's temperature, T_ref (degC, or 296.15K); default: the data's\n"
       "temperature when there is one")
      ("poisson", po::value<std::string>()->value_name("NU"),
       "Poisson's ratio of the material, -1 < NU <= 0.5 (required: DMA in tension gives E)")
      ("shift", po::value<std::string>()->default_value("wlf")->value_name("LAW"),
       "the shift law fitted to the shift factors: wlf or arrhenius")
      ("C1", po::value<std::string>()->value_name("C1"), "WLF's C1 given (with --C2): no shift law is fitted")
      ("C2", po::value<std::string>()->value_name("K"), "WLF's C2 given, in K")
      ("E-a", po::value<std::string>()->value_name("J/mol"), "Arrhenius' activation energy given, in J/mol")
      ("terms-per-decade", po::value<std::string>()->default_value("0.5, 1, 1.5, 2, 3")->value_name("LIST"),
       "relaxation-time densities tried (terms per decade of the data's span); the one\n"
       "with the smallest BIC is kept")
      ("smoothing", po::value<std::string>()->default_value("0")->value_name("LAMBDA"),
       "weight of a penalty on second differences of neighbouring E_i (>= 0; try 1e-3 to\n"
       "1e-2 for noisy data)")
      ("isotherm-gap", po::value<std::string>()->default_value("1")->value_name("K"),
       "readings whose temperatures (sorted) lie within this many K of the previous one\n"
       "form one isotherm (instruments log each reading's measured temperature)")
      ("time-window", po::value<std::string>()->default_value("1e-10s, 1e12s")->value_name("LO,HI"),
       "the times the material is to hold, at T_ref (s, ms, min or h): the series is fitted\n"
       "to every reading, then terms slower than HI join E_inf (frozen) and terms faster\n"
       "than LO are dropped (relaxed); at most 24 decades, which the engine's\n"
       "interconversion resolves")
      ("refine", po::value<std::string>()->default_value("yes")->value_name("yes|no"),
       "refine the relaxation times after the grid (no: keep the grid's)")
      ("accept-poor-fit", po::bool_switch(),
       "write the material even where the fit fails its checks (shifts that rise with\n"
       "temperature, WLF's C2 on its bound, shifts 0.5 decades about the law, E' beyond\n"
       "10% or E'' beyond 20% RMS); the verdict is recorded in the file")
      ("name", po::value<std::string>()->value_name("TEXT"), "the material's name: one line without # or ; (default: the files' sample names, else their names)")
      ("output", po::value<std::string>()->value_name("FILE"), "the material file to write (-o)");
  return opts;
}

namespace {

/// The modulus unit that puts E_0 between 1 and 1000.
const model::Unit& modulus_unit_for(double E0_Pa) {
  const auto units = model::units_of(model::Dimension::pressure);
  const model::Unit* best = &units.front();
  for (const model::Unit& u : units) {
    if (E0_Pa / u.si >= 1.0) best = &u;
  }
  return *best;
}

std::string list_text(const std::vector<double>& v, double divisor) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + model::number_text(v[i] / divisor, 10);
  return s;
}

/// How far outside its isotherms' span the reference temperature may lie, in K (the shift
/// law's range is the isotherms' span, widened to T_ref).
constexpr double kReferenceMargin = 10.0;

/// `text` with every control character (a line break above all) replaced by `with`: what a
/// comment line of a material file may hold.
std::string one_line(std::string text, char with) {
  for (char& c : text) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = with;
  }
  return text;
}

/// Why `name` cannot be a material's name in a material file, or "": one line without # or ;
/// (they start a comment there, so the name would be cut).
std::string name_problem(const std::string& name) {
  if (name.size() > 200) return "is " + std::to_string(name.size()) + " bytes long";
  if (one_line(name, '\n').find_first_of("\n#;") != std::string::npos) {
    return "holds a line break, a control character, # or ; (# and ; start a comment in a material file)";
  }
  return {};
}

/// `word` as one word of a POSIX shell: as it is where it holds only characters no shell
/// reads specially, else in single quotes.
std::string shell_word(const std::string& word) {
  const bool plain = !word.empty() && std::all_of(word.begin(), word.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || std::string_view("/._-+=:,@%").find(c) != std::string_view::npos;
  });
  if (plain) return word;
  std::string quoted = "'";
  for (const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

/// The command that draws the fit's picture, runnable from any folder: the script by its
/// absolute path in the source tree this binary was built from (engine::kSourceDir), and the
/// details by theirs. Where that tree is gone (an installed binary), the script's path in
/// punchsweep's source tree, said as such.
std::string picture_command(const std::string& details) {
  std::error_code ec;
  std::filesystem::path file = std::filesystem::absolute(details, ec);
  if (ec) file = details;
  const std::filesystem::path script = std::filesystem::path(kSourceDir) / "postprocess" / "fit_picture.py";
  if (std::filesystem::is_regular_file(script, ec)) {
    return "/usr/bin/python3 " + shell_word(script.lexically_normal().string()) + " " +
           shell_word(file.lexically_normal().string()) + " -o fit.png";
  }
  return "/usr/bin/python3 postprocess/fit_picture.py " + shell_word(file.lexically_normal().string()) +
         " -o fit.png   (postprocess/ of punchsweep's source tree)";
}

/// How a law fitted with the series came about, for the material file and the report.
std::string joint_law_words(const fit::MasterCurve& m) {
  if (m.polished) {
    return "polished with the series from the law of the overlap shifts of E' (\"measured\", " +
           model::number_text(m.rms_log10, 3) + " decades RMS about it)";
  }
  if (std::isnan(m.rms_log10)) return "fitted together with the series, the overlap of E' having placed no isotherm";
  return "fitted together with the series, since the overlap shifts of E' failed the fit's checks (\"measured\", " +
         model::number_text(m.rms_log10, 3) + " decades RMS about it)";
}

std::string material_text(const FitRun& run, const std::string& name) {
  const fit::MaterialFit& f = run.fit;
  const fit::PronyTerms& t = f.prony.terms;
  const model::Unit& unit = *model::find_unit(model::Dimension::pressure, run.modulus_unit);
  std::ostringstream s;
  s << "# Fitted by `punchsweep fit` to " << f.readings.size() << " readings from:";
  for (const std::string& src : run.sources) s << " " << one_line(src, '?');
  s << "\n# Prony series: " << t.E.size() << " terms, for times " << model::number_text(run.window_lo, 3) << " to "
    << model::number_text(run.window_hi, 3) << " s at T_ref; RMS relative error within them "
    << (f.abscissa == fit::Abscissa::frequency
            ? "E' " + model::number_text(100 * f.prony.rms_first, 3) + "%, E'' " +
                  model::number_text(100 * f.prony.rms_second, 3) + "%"
            : "E(t) " + model::number_text(100 * f.prony.rms_first, 3) + "%")
    << ".\n";
  if (f.master.law) {
    s << "# Shift: " << f.master.law->describe();
    if (f.master.joint) {
      s << ", " << joint_law_words(f.master);
    } else if (!std::isnan(f.master.measured_log10_aT.front())) {
      s << ", RMS of the measured shifts about it " << model::number_text(f.master.rms_log10, 3) << " decades";
    }
    s << ".\n";
  }
  for (const std::string& p : run.problems) s << "# POOR FIT, written with --accept-poor-fit: " << one_line(p, '?') << "\n";
  s << "[material]\n"
    << "name = " << name << "\n"
    << "law = prony\n"
    << "modulus_unit = " << unit.name << "\n"
    << "time_unit = s\n"
    << "poisson = " << model::number_text(run.poisson, 10) << "\n"
    << "E_inf = " << model::number_text(t.E_inf / unit.si, 10) << "\n"
    << "E_i = " << list_text(t.E, unit.si) << "\n"
    << "tau_i = " << list_text(t.tau, 1.0) << "\n";
  if (f.master.law) {
    const model::TemperatureShift& law = *f.master.law;
    s << "[shift]\n";
    if (law.kind == model::TemperatureShift::Kind::wlf) {
      s << "kind = wlf\nC1 = " << model::number_text(law.C1, 10) << "\nC2 = " << model::number_text(law.C2, 10)
        << "                     # K\n";
    } else {
      s << "kind = arrhenius\nE_a = " << model::number_text(law.E_a, 10) << "             # J/mol\n";
    }
    s << "T_ref = " << model::number_text(law.T_ref, 10) << "                    # degC\n";
    if (law.T_min > -model::kZeroCelsius) s << "T_min = " << model::number_text(law.T_min, 10) << "\n";
    if (std::isfinite(law.T_max)) s << "T_max = " << model::number_text(law.T_max, 10) << "\n";
  }
  return s.str();
}

/// The .fit.json beside the material: readings on the master curve with the fit, the
/// shifts, the candidates and the terms, each number with its unit in the key's "units".
std::string details_json(const FitRun& run) {
  const fit::MaterialFit& f = run.fit;
  const bool dma = f.abscissa == fit::Abscissa::frequency;
  std::vector<double> T, x, xr, y1, y2, f1, f2, used;
  for (const fit::ReducedReading& r : f.readings) {
    T.push_back(r.temperature);
    x.push_back(r.x);
    xr.push_back(r.x_reduced);
    y1.push_back(r.first);
    y2.push_back(r.second);
    f1.push_back(r.first_fit);
    f2.push_back(r.second_fit);
    used.push_back(r.used ? 1.0 : 0.0);
  }
  std::ostringstream s;
  s << "{\n  \"kind\": \"" << (dma ? "dma" : "relaxation") << "\",\n";
  s << "  \"sources\": [";
  for (std::size_t i = 0; i < run.sources.size(); ++i) s << (i ? ", " : "") << input::json_string(run.sources[i]);
  s << "],\n  \"material\": " << input::json_string(run.output) << ",\n";
  s << "  \"name\": " << input::json_string(run.material->name()) << ",\n";
  s << "  \"verdict\": {\"poor\": " << (run.problems.empty() ? "false" : "true") << ", \"problems\": [";
  for (std::size_t i = 0; i < run.problems.size(); ++i) s << (i ? ", " : "") << input::json_string(run.problems[i]);
  s << "]},\n";
  s << "  \"units\": {\"temperature\": \"degC\", \"x\": \"" << (dma ? "rad/s" : "s")
    << "\", \"moduli\": \"Pa\", \"tau\": \"s\", \"log10_aT\": \"1\", \"C2\": \"K\", \"E_a\": \"J/mol\"},\n";
  s << "  \"readings\": {\"temperature\": " << input::json_array(T) << ",\n    \"x\": " << input::json_array(x)
    << ",\n    \"x_reduced\": " << input::json_array(xr) << ",\n    \"" << (dma ? "storage" : "modulus") << "\": " << input::json_array(y1);
  if (dma) s << ",\n    \"loss\": " << input::json_array(y2);
  s << ",\n    \"" << (dma ? "storage_fit" : "modulus_fit") << "\": " << input::json_array(f1);
  if (dma) s << ",\n    \"loss_fit\": " << input::json_array(f2);
  s << ",\n    \"used\": " << input::json_array(used);
  s << "},\n  \"shift\": {\"temperatures\": " << input::json_array(f.master.temperatures)
    << ", \"measured_log10_aT\": " << input::json_array(f.master.measured_log10_aT)
    << ", \"law_log10_aT\": " << input::json_array(f.master.law_log10_aT);
  if (f.master.law) {
    const model::TemperatureShift& law = *f.master.law;
    s << ", \"law\": " << input::json_string(law.kind == model::TemperatureShift::Kind::wlf ? "wlf" : "arrhenius")
      << ", \"T_ref\": " << input::json_number(law.T_ref) << ", \"C1\": " << input::json_number(law.C1)
      << ", \"C2\": " << input::json_number(law.C2) << ", \"E_a\": " << input::json_number(law.E_a)
      << ", \"describe\": " << input::json_string(law.describe());
  }
  s << ", \"rms_log10\": " << input::json_number(f.master.rms_log10) << ", \"joint\": " << (f.master.joint ? "true" : "false")
    << ", \"polished\": " << (f.master.polished ? "true" : "false") << "},\n";
  s << "  \"prony\": {\"E_inf\": " << input::json_number(f.prony.terms.E_inf) << ", \"E_i\": " << input::json_array(f.prony.terms.E)
    << ", \"tau_i\": " << input::json_array(f.prony.terms.tau) << ",\n    \"rms_relative\": {\""
    << (dma ? "storage" : "modulus") << "\": " << input::json_number(f.prony.rms_first);
  if (dma) s << ", \"loss\": " << input::json_number(f.prony.rms_second);
  s << "}, \"rms_relative_all\": {\"" << (dma ? "storage" : "modulus") << "\": " << input::json_number(f.rms_all_first);
  if (dma) s << ", \"loss\": " << input::json_number(f.rms_all_second);
  s << "}, \"window\": [" << input::json_number(run.window_lo) << ", " << input::json_number(run.window_hi)
    << "], \"frozen\": " << f.frozen << ", \"dropped\": " << f.dropped;
  s << ", \"bic\": " << input::json_number(f.prony.bic) << ", \"residuals\": " << f.prony.residuals
    << ", \"fitted\": " << f.fitted
    << ",\n    \"candidates\": [";
  for (std::size_t i = 0; i < f.prony.candidates.size(); ++i) {
    const fit::PronyCandidate& c = f.prony.candidates[i];
    s << (i ? ", " : "") << "{\"per_decade\": " << input::json_number(c.per_decade) << ", \"grid_terms\": " << c.grid_terms
      << ", \"terms\": " << c.terms << ", \"rss\": " << input::json_number(c.rss) << ", \"bic\": " << input::json_number(c.bic)
      << "}";
  }
  s << "], \"chosen\": " << f.prony.chosen << "}\n}\n";
  return s.str();
}

std::string report(const FitRun& run) {
  const fit::MaterialFit& f = run.fit;
  const bool dma = f.abscissa == fit::Abscissa::frequency;
  std::ostringstream s;
  s << "punchsweep fit: " << f.readings.size() << (dma ? " DMA readings" : " relaxation readings") << " at "
    << f.master.temperatures.size() << " temperature(s)\n";
  if (f.master.law) {
    s << "shift: " << f.master.law->describe();
    if (f.master.joint) {
      s << " (" << joint_law_words(f.master) << "; the readings are shifted by the law)";
    } else if (!std::isnan(f.master.measured_log10_aT.front())) {
      s << " (fitted; RMS of the measured shifts about it " << model::number_text(f.master.rms_log10, 3) << " decades)";
    } else {
      s << " (given)";
    }
    if (!std::isnan(f.master.measured_log10_aT.front())) {
      s << "\n  (the measured shifts are relative to each other: shown on the law's zero, log10 a_T = 0 at "
        << model::number_text(f.master.law->T_ref, 6) << " degC, by the constant that best matches the law)";
    }
    s << "\n  T [degC]   log10 a_T measured   log10 a_T law\n";
    for (std::size_t i = 0; i < f.master.temperatures.size(); ++i) {
      char line[128];
      std::snprintf(line, sizeof line, "  %8.3g   %18.4f   %13.4f\n", f.master.temperatures[i], f.master.measured_log10_aT[i],
                    f.master.law_log10_aT[i]);
      s << line;
    }
  }
  if (f.fitted < f.readings.size()) {
    s << "the " << f.readings.size() << " readings were binned to " << f.fitted
      << " for the fit (per isotherm, bins of equal width in log10 " << (dma ? "frequency" : "time")
      << ", each at its readings' geometric means and weighted by their number: the fit's time grows with the "
         "readings it is fitted to); the errors below are over every reading\n";
  }
  s << "Prony series: densities tried (terms per decade: grid terms, terms kept, BIC)\n";
  for (std::size_t i = 0; i < f.prony.candidates.size(); ++i) {
    const fit::PronyCandidate& c = f.prony.candidates[i];
    s << "  " << model::number_text(c.per_decade, 3) << ": " << c.grid_terms << ", " << c.terms << ", "
      << model::number_text(c.bic, 6) << (i == f.prony.chosen ? "   <- chosen" : "") << "\n";
  }
  s << "  after refining the times: " << f.prony.terms.E.size() << " terms, BIC " << model::number_text(f.prony.bic, 6)
    << "\n  E_inf = " << model::number_text(f.prony.terms.E_inf, 6) << " Pa, E_0 = "
    << model::number_text(run.material->instantaneous_modulus_Pa(), 6) << " Pa, E0* = E_0/(1 - nu^2) = "
    << model::number_text(run.material->plane_strain_modulus_Pa(), 6) << " Pa (nu = " << model::number_text(run.poisson, 6)
    << ")\n  RMS relative error over all " << f.readings.size() << " readings: "
    << (dma ? "E' " + model::number_text(100 * f.rms_all_first, 3) + "%, E'' " + model::number_text(100 * f.rms_all_second, 3) + "%"
            : "E(t) " + model::number_text(100 * f.rms_all_first, 3) + "%")
    << "\n  time window " << model::number_text(run.window_lo, 3) << " to " << model::number_text(run.window_hi, 3)
    << " s at T_ref: " << f.frozen << " slower term(s) held in E_inf, " << f.dropped
    << " faster term(s) dropped; the series written, over the " << f.used << " readings within it: "
    << (dma ? "E' " + model::number_text(100 * f.prony.rms_first, 3) + "%, E'' " + model::number_text(100 * f.prony.rms_second, 3) + "%"
            : "E(t) " + model::number_text(100 * f.prony.rms_first, 3) + "%")
    << "\n";
  if (!run.problems.empty()) {
    s << "POOR FIT, written with --accept-poor-fit (the verdict is in both files):\n";
    for (const std::string& p : run.problems) s << "  - " << p << "\n";
  }
  if (!run.output.empty()) {
    s << "wrote " << run.output << " and " << run.details << "\n"
      << "picture: " << picture_command(run.details) << "\n";
  }
  return s.str();
}

/// The measurement files read (a source is FILE or FILE@TEMPERATURE): no output may be one.
std::vector<std::string> input_files(const FitRun& run) {
  std::vector<std::string> files;
  for (const std::string& source : run.sources) {
    files.push_back(source);
    if (const auto at = source.rfind('@'); at != std::string::npos) files.push_back(source.substr(0, at));
  }
  return files;
}

void read_window(const po::variables_map& vm, fit::MaterialFitRequest* request) {
  const std::string text = vm["time-window"].as<std::string>();
  const auto comma = text.find(',');
  const auto bad = [&](const std::string& why) {
    return input::UsageError("--time-window = '" + text + "' " + why +
                             " (valid: LO,HI in s, ms, min or h, 0 < LO < HI <= LO x 1e24, e.g. 1e-10s,1e12s)");
  };
  if (comma == std::string::npos) throw bad("is not two times");
  double v[2];
  const std::string parts[2] = {text.substr(0, comma), text.substr(comma + 1)};
  for (int i = 0; i < 2; ++i) {
    try {
      const auto p = model::parse_physical(parts[i], model::Dimension::time);
      v[i] = p ? p->si() : input::parse_real(parts[i], "--time-window");
    } catch (const std::invalid_argument& e) {
      throw bad(std::string("is not two times: ") + e.what());
    }
  }
  if (!(v[0] > 0.0 && v[1] > v[0] && v[1] <= v[0] * 1e24)) throw bad("is outside its range");
  request->window_lo = v[0];
  request->window_hi = v[1];
}

}  // namespace

FitRun run_fit(const po::variables_map& vm) {
  FitRun run;
  for (const char* kind : {"dma", "relaxation"}) {
    if (vm.count(kind)) {
      for (const std::string& s : vm[kind].as<std::vector<std::string>>()) run.sources.push_back(s);
    }
  }
  if (run.sources.empty()) throw input::UsageError("give the measurements: --dma FILE or --relaxation FILE");
  if (vm.count("dma") && vm.count("relaxation")) throw input::UsageError("give --dma or --relaxation, not both");
  if (vm.count("output")) {
    run.output = vm["output"].as<std::string>();
    const std::filesystem::path p(run.output);
    run.details = (p.parent_path() / p.stem()).string() + ".fit.json";
    // Refused before the work, and again as each file is written (io::write_file_whole).
    for (const std::string& file : {run.output, run.details}) {
      if (std::string problem = io::output_file_problem(file, input_files(run)); !problem.empty()) {
        throw input::UsageError("-o " + problem);
      }
    }
  }
  if (!vm.count("poisson")) {
    throw input::UsageError("missing --poisson: Poisson's ratio, -1 < NU <= 0.5 (0.5 for an incompressible rubber)");
  }
  run.poisson = input::read_real(vm, "poisson", "Poisson's ratio", "-1 < NU <= 0.5", [](double v) { return v > -1.0 && v <= 0.5; });
  const fit::Measurements m = input::read_measurement_files(run.sources);
  run.samples = m.samples;
  const bool dma = vm.count("dma") > 0;
  if (dma ? m.dma.empty() : m.relaxation.empty()) {
    throw input::UsageError(std::string("the files given to --") + (dma ? "dma hold a relaxation test (give them to --relaxation)"
                                                                         : "relaxation hold DMA readings (give them to --dma)"));
  }
  fit::MaterialFitRequest request;
  std::vector<double> temperatures;
  for (const auto& r : m.dma) temperatures.push_back(r.temperature);
  for (const auto& r : m.relaxation) temperatures.push_back(r.temperature);
  const auto [tmin, tmax] = std::minmax_element(temperatures.begin(), temperatures.end());
  if (vm.count("reference-temperature")) {
    const std::string text = vm["reference-temperature"].as<std::string>();
    request.shift.T_ref = input::read_temperature(text, "--reference-temperature");
    // The master curve is drawn at a temperature the data reach: far from every isotherm the
    // shifts to it are extrapolated, and the law would be believed there.
    if (request.shift.T_ref < *tmin - kReferenceMargin || request.shift.T_ref > *tmax + kReferenceMargin) {
      throw input::UsageError("--reference-temperature = " + text + " (" + model::number_text(request.shift.T_ref, 6) +
                              " degC) is far outside the data, whose readings span " + model::number_text(*tmin, 3) +
                              " to " + model::number_text(*tmax, 3) + " degC; valid: " +
                              model::number_text(*tmin - kReferenceMargin, 3) + " to " +
                              model::number_text(*tmax + kReferenceMargin, 3) + " degC (within " +
                              model::number_text(kReferenceMargin, 3) + " K of the data)");
    }
  } else if (*tmin == *tmax) {
    request.shift.T_ref = *tmin;
  } else {
    throw input::UsageError("missing --reference-temperature: the data span " + model::number_text(*tmin, 6) + " to " +
                            model::number_text(*tmax, 6) + " degC; name the master curve's temperature");
  }
  const std::string law = input::read_choice(vm, "shift", {"wlf", "arrhenius"});
  request.shift.law = law == "wlf" ? fit::ShiftRequest::Law::wlf : fit::ShiftRequest::Law::arrhenius;
  if ((vm.count("C1") || vm.count("C2")) && vm.count("E-a")) {
    throw input::UsageError("give WLF's --C1 and --C2, or Arrhenius' --E-a, not both");
  }
  if (vm.count("C1") || vm.count("C2")) {
    if (!(vm.count("C1") && vm.count("C2"))) throw input::UsageError("give WLF's --C1 and --C2 together");
    request.shift.law = fit::ShiftRequest::Law::given;
    request.shift.given.kind = model::TemperatureShift::Kind::wlf;
    request.shift.given.C1 = input::read_real(vm, "C1", "WLF's C1", "C1 > 0", [](double v) { return v > 0.0; });
    request.shift.given.C2 = input::read_real(vm, "C2", "WLF's C2", "C2 > 0 (in K)", [](double v) { return v > 0.0; });
  } else if (vm.count("E-a")) {
    request.shift.law = fit::ShiftRequest::Law::given;
    request.shift.given.kind = model::TemperatureShift::Kind::arrhenius;
    request.shift.given.E_a = input::read_real(vm, "E-a", "the activation energy", "E_a > 0 (in J/mol)", [](double v) { return v > 0.0; });
  }
  request.shift.given.T_ref = request.shift.T_ref;
  request.prony.per_decade = input::parse_real_list(vm["terms-per-decade"].as<std::string>(), "--terms-per-decade");
  for (const double d : request.prony.per_decade) {
    if (!(d > 0.0 && d <= 10.0)) {
      throw input::UsageError("--terms-per-decade = " + vm["terms-per-decade"].as<std::string>() +
                              " is outside its range: each 0 < density <= 10");
    }
  }
  request.prony.smoothing = input::read_real(vm, "smoothing", "the smoothing weight", "LAMBDA >= 0", [](double v) { return v >= 0.0; });
  request.prony.refine = input::read_choice(vm, "refine", {"yes", "no"}) == "yes";
  read_window(vm, &request);
  run.window_lo = request.window_lo;
  run.window_hi = request.window_hi;
  request.isotherm_gap = input::read_real(vm, "isotherm-gap", "the isotherm gap", "K > 0", [](double v) { return v > 0.0; });
  try {
    run.fit = fit::fit_material(m, request);
  } catch (const std::invalid_argument& e) {
    throw input::UsageError(std::string("cannot fit: ") + e.what());
  }
  // The fit judges itself before anything is written.
  run.problems = fit::fit_problems(run.fit);
  if (!run.problems.empty() && !vm["accept-poor-fit"].as<bool>()) {
    std::string why = "the fit is poor; nothing written:";
    for (const std::string& p : run.problems) why += "\n  - " + p;
    throw input::UsageError(why + "\n  check the data (isotherm labels, units, temperatures), give the shift law "
                                  "(--C1 --C2 or --E-a), or pass --accept-poor-fit to write it with this verdict "
                                  "recorded in the file");
  }
  const fit::PronyTerms& t = run.fit.prony.terms;
  double E0 = t.E_inf;
  for (const double e : t.E) E0 += e;
  run.modulus_unit = std::string(modulus_unit_for(E0).name);
  std::string name = vm.count("name") ? std::string(model::trim(vm["name"].as<std::string>())) : "";
  if (name.empty()) {
    // Each file's sample name where its preamble gives one, else the file's name.
    name = "fitted to";
    for (std::size_t k = 0; k < run.sources.size(); ++k) {
      const std::string sample = k < run.samples.size() ? run.samples[k] : "";
      name += " " + (sample.empty() ? std::filesystem::path(run.sources[k]).filename().string() : sample);
    }
    for (char& c : name) {
      if (c == '#' || c == ';') c = '_';
    }
    name = one_line(name, '_');
  } else if (const std::string problem = name_problem(name); !problem.empty()) {
    throw input::UsageError("--name = '" + one_line(name, '?') + "' " + problem +
                            "; valid: one line of text without # or ;, at most 200 bytes");
  }
  run.material_text = material_text(run, name);
  // The engine reads what was written, as a user's run will.
  run.material = std::make_shared<const model::Material>(
      input::read_material_text(run.material_text, run.output.empty() ? "fitted material" : run.output));
  run.details_json = details_json(run);
  run.report = report(run);
  return run;
}

void write_fit_files(const FitRun& run) {
  try {
    io::write_file_whole(run.details, run.details_json, input_files(run));
    io::write_file_whole(run.output, run.material_text, input_files(run));
  } catch (const std::runtime_error& e) {
    throw input::UsageError(std::string("-o ") + e.what());
  }
}

FitRun fit_material(const input::Keywords& keywords) {
  const FitRun run = run_fit(input::parse_keywords(keywords, fit_options(), "fit"));
  if (!run.output.empty()) write_fit_files(run);
  return run;
}

}  // namespace punchsweep::engine
