#include "input/measurement_file.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <filesystem>
#include <map>
#include <optional>

#include "input/csv_cells.hpp"
#include "input/text_file.hpp"
#include "input/usage_error.hpp"
#include "model/laws/time_shift.hpp"
#include "model/numerics/number_text.hpp"
#include "model/numerics/units.hpp"

namespace punchsweep::input {
namespace {

/// The columns a file may have: their names (normalized: lower case, no spaces, '_' or
/// '-'), and the units each accepts.
enum class Column { temperature, frequency, storage, loss, tan_delta, time, modulus };

struct ColumnSpec {
  Column column;
  std::vector<std::string_view> names;  ///< normalized (normalized())
  std::string_view units;  ///< for messages
  std::string_view label;  ///< the column in messages, as docs/fitting.md names it
};

const std::array<ColumnSpec, 7>& column_specs() {
  static const std::array<ColumnSpec, 7> specs{{
      {Column::temperature, {"temperature", "temp", "temp."}, "C, degC or K", "temperature"},
      {Column::frequency, {"frequency", "freq", "angularfrequency", "freq."}, "Hz or rad/s", "frequency"},
      {Column::storage, {"storage", "storagemodulus", "e'"}, "Pa, kPa, MPa or GPa", "storage"},
      {Column::loss, {"loss", "lossmodulus", "e''"}, "Pa, kPa, MPa or GPa", "loss"},
      {Column::tan_delta, {"tandelta", "tan(delta)", "tand", "tan\xce\xb4", "tan(\xce\xb4)", "lossfactor"}, "- or 1", "tan_delta"},
      {Column::time, {"time"}, "s, ms, min or h", "time"},
      {Column::modulus, {"modulus", "relaxationmodulus", "e(t)"}, "Pa, kPa, MPa or GPa", "modulus"},
  }};
  return specs;
}

/// How far loss / storage and a tan_delta column of the same reading may differ.
constexpr double kTanDeltaAgreement = 0.02;

/// A header cell as its names are matched: without blanks, '_' and '-', in lower case, the
/// Greek capitals (UTF-8 U+0391..U+03A9) too, so that "TAN \xce\x94" (capital delta, as
/// some instruments write tan delta in upper case) is "tan\xce\xb4".
std::string normalized(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == ' ' || c == '_' || c == '-' || c == '\t') continue;
    const auto next = i + 1 < s.size() ? static_cast<unsigned char>(s[i + 1]) : 0u;
    if (static_cast<unsigned char>(c) == 0xce && next >= 0x91 && next <= 0xa9 && next != 0xa2) {
      // U+0391..U+039F (0xce 0x91..0x9f) lower to U+03B1..U+03BF (0xce 0xb1..0xbf),
      // U+03A0..U+03A9 (0xce 0xa0..0xa9) to U+03C0..U+03C9 (0xcf 0x80..0x89); U+03A2 is unassigned.
      out += next <= 0x9f ? "\xce" : "\xcf";
      out += static_cast<char>(next <= 0x9f ? next + 0x20 : next - 0x20);
      ++i;
      continue;
    }
    out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

/// How a column's numbers become SI: v -> v * factor + offset.
struct ToSi {
  double factor = 1.0;
  double offset = 0.0;
};

[[noreturn]] void fail(const std::string& origin, std::size_t line, const std::string& what) {
  throw UsageError(origin + ", line " + std::to_string(line) + ": " + what);
}

std::optional<ToSi> unit_of(Column column, const std::string& unit) {
  const std::string u = normalized(unit);
  switch (column) {
    case Column::temperature:
      // The degree sign in UTF-8 or Latin-1 (Windows exports), or the ordinal sign that
      // stands in for it on some keyboards.
      if (u == "c" || u == "degc" || u == "\xc2\xb0" "c" || u == "\xb0" "c" || u == "\xc2\xba" "c" || u == "celsius") {
        return ToSi{1.0, 0.0};
      }
      if (u == "k" || u == "kelvin") return ToSi{1.0, -model::kZeroCelsius};
      return std::nullopt;
    case Column::frequency:
      if (u == "hz") return ToSi{2.0 * M_PI, 0.0};
      if (u == "rad/s" || u == "1/s" || u == "s-1") return ToSi{1.0, 0.0};
      return std::nullopt;
    case Column::tan_delta:
      if (u.empty() || u == "1" || u == "-") return ToSi{1.0, 0.0};
      return std::nullopt;
    case Column::time:
      if (const model::Unit* t = model::find_unit(model::Dimension::time, unit)) return ToSi{t->si, 0.0};
      return std::nullopt;
    default:
      if (const model::Unit* p = model::find_unit(model::Dimension::pressure, unit)) return ToSi{p->si, 0.0};
      return std::nullopt;
  }
}

/// A header cell: the column it names (nullptr: one the fit does not use) and its unit,
/// written "storage [MPa]" or "Storage Modulus (MPa)", or none ("E'", and a units row
/// below the header may give it). A name that holds parentheses is a name: "Tan(delta)".
struct HeaderCell {
  const ColumnSpec* spec = nullptr;
  std::string unit;
  bool has_unit = false;
};
HeaderCell header_cell(const std::string& cell) {
  const auto named = [](const std::string& name) -> const ColumnSpec* {
    for (const ColumnSpec& s : column_specs()) {
      if (std::find(s.names.begin(), s.names.end(), name) != s.names.end()) return &s;
    }
    return nullptr;
  };
  HeaderCell out;
  if ((out.spec = named(normalized(cell))) != nullptr) return out;
  std::size_t open = cell.find('['), close = cell.rfind(']');
  if (open == std::string::npos || close == std::string::npos || close < open) {
    close = !cell.empty() && cell.back() == ')' ? cell.size() - 1 : std::string::npos;
    open = close == std::string::npos ? std::string::npos : cell.rfind('(');
  }
  if (open == std::string::npos || close == std::string::npos || close < open) return out;
  out.spec = named(normalized(cell.substr(0, open)));
  out.unit = trim_cell(cell.substr(open + 1, close - open - 1));
  out.has_unit = true;
  return out;
}

/// What a header holds and what it might: each of its columns as written with the column it
/// was taken for ("not used": a column the fit ignores, or a name it does not know), and the
/// names each column the fit uses goes by. For the refusals of a header that lacks a column,
/// so that a name the reader does not know is seen.
std::string header_words(const std::vector<std::string>& cells) {
  std::string seen, taken;
  for (const std::string& cell : cells) {
    const ColumnSpec* spec = header_cell(cell).spec;
    seen += (seen.empty() ? "\"" : ", \"") + cell + "\" (" + (spec ? std::string(spec->label) : "not used") + ")";
  }
  for (const ColumnSpec& spec : column_specs()) {
    taken += (taken.empty() ? "" : "; ") + std::string(spec.label) + " =";
    for (std::size_t k = 0; k < spec.names.size(); ++k) taken += (k ? ", " : " ") + std::string(spec.names[k]);
  }
  return "the header's columns: " + seen + "; the names taken (any case; blanks, _ and - ignored; the unit after "
         "the name in [] or ()): " + taken;
}

/// Whether a line is the header: it names the readings' abscissa, frequency or time. Lines
/// above it are the instrument's preamble (sample, geometry, procedure, date).
bool names_the_abscissa(const std::string& line) {
  for (const std::string& cell : split_cells(line, separator_of(line))) {
    const ColumnSpec* spec = header_cell(cell).spec;
    if (spec != nullptr && (spec->column == Column::frequency || spec->column == Column::time)) return true;
  }
  return false;
}

}  // namespace

void read_measurements(std::string_view raw, const std::string& origin, double temperature, fit::Measurements* into) {
  // Line ends as any system writes them: LF, CR LF, or CR alone (classic Mac OS, some
  // instruments' exports).
  std::string unified;
  unified.reserve(raw.size());
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] == '\r') {
      unified += '\n';
      if (i + 1 < raw.size() && raw[i + 1] == '\n') ++i;
    } else {
      unified += raw[i];
    }
  }
  // The lines that hold anything but a comment, with their numbers (from 1).
  std::vector<std::pair<std::size_t, std::string>> lines;
  {
    const std::string_view text = unified;
    std::size_t line_no = 0, start = 0;
    while (start <= text.size()) {
      auto end = text.find('\n', start);
      if (end == std::string_view::npos) end = text.size();
      ++line_no;
      std::string t(model::trim(text.substr(start, end - start), " \t\r"));  // (a quote at either end belongs to a cell)
      if (!t.empty() && t[0] != '#') lines.emplace_back(line_no, std::move(t));
      start = end + 1;
    }
  }
  if (lines.empty()) throw UsageError(origin + ": no header row (e.g. 'temperature [C],frequency [Hz],storage [MPa],loss [MPa]')");
  // The header: the first line that names frequency or time (the lines above it are the
  // instrument's preamble); where none does, the first line, whose checks say what it lacks.
  std::size_t h = 0;
  while (h < lines.size() && !names_the_abscissa(lines[h].second)) ++h;
  if (h == lines.size()) h = 0;
  // The sample's name, where the preamble gives it: "Sample name<sep>TPE-A", "Sample:;TPE-A".
  std::string sample;
  for (std::size_t k = 0; k < h && sample.empty(); ++k) {
    const std::vector<std::string> cells = split_cells(lines[k].second, separator_of(lines[k].second));
    std::string key = normalized(cells[0]);
    if (!key.empty() && key.back() == ':') key.pop_back();
    if ((key == "sample" || key == "samplename") && cells.size() > 1) sample = cells[1];
  }
  into->samples.push_back(sample);
  const std::size_t header_no = lines[h].first;
  const char sep = separator_of(lines[h].second);
  const bool decimal_comma = decimal_comma_with(sep);
  // A row's cells, less the empty ones past `width` (exports often end a line with a separator).
  const auto cells_of = [&](const std::string& line, std::size_t width) {
    std::vector<std::string> cells = split_cells(line, sep);
    while (cells.size() > std::max<std::size_t>(width, 1) && cells.back().empty()) cells.pop_back();
    return cells;
  };
  const std::vector<std::string> names = cells_of(lines[h].second, 0);
  const std::size_t width = names.size();
  // The columns the fit uses, in the file's order.
  struct Found {
    std::size_t at;
    HeaderCell cell;
    std::size_t unit_line;
  };
  std::vector<Found> found;
  for (std::size_t c = 0; c < width; ++c) {
    if (names[c].empty()) {
      fail(origin, header_no, "column " + std::to_string(c + 1) + " of the header is empty (a stray separator?); "
                              "name every column, e.g. 'temperature [C]'");
    }
    const HeaderCell cell = header_cell(names[c]);
    if (cell.spec == nullptr) continue;  // a column the fit does not use (e.g. strain amplitude)
    if (std::any_of(found.begin(), found.end(), [&](const Found& f) { return f.cell.spec == cell.spec; })) {
      fail(origin, header_no, "two columns are '" + std::string(cell.spec->label) + "'");
    }
    found.push_back({c, cell, header_no});
  }
  // A units row under the header ("C, Hz, MPa, MPa": some instruments write the units
  // there), where a column the fit uses has none in the header and the row holds no number.
  std::size_t first = h + 1;
  const auto needs_unit = [](const Found& f) { return !f.cell.has_unit && f.cell.spec->column != Column::tan_delta; };
  if (first < lines.size() && std::any_of(found.begin(), found.end(), needs_unit)) {
    const std::vector<std::string> units = cells_of(lines[first].second, width);
    const bool numbers = std::any_of(found.begin(), found.end(), [&](const Found& f) {
      return f.at < units.size() && cell_number(units[f.at], decimal_comma).has_value();
    });
    if (!numbers && units.size() == width) {
      for (Found& f : found) {
        if (f.cell.has_unit || units[f.at].empty()) continue;
        f.cell.unit = units[f.at];
        f.cell.has_unit = true;
        f.unit_line = lines[first].first;
      }
      ++first;
    }
  }
  std::map<Column, std::pair<std::size_t, ToSi>> columns;
  for (const Found& f : found) {
    const Column column = f.cell.spec->column;
    if (needs_unit(f)) {
      fail(origin, header_no, "column '" + names[f.at] + "' names no unit; write it as '" + std::string(f.cell.spec->names[0]) +
                                  " [unit]' (or a units row under the header) with the unit one of " + std::string(f.cell.spec->units));
    }
    const std::optional<ToSi> si = unit_of(column, f.cell.unit);
    if (!si) {
      fail(origin, f.unit_line, "column '" + names[f.at] + "': '" + f.cell.unit + "' is not a unit it takes (valid: " +
                                    std::string(f.cell.spec->units) + ")");
    }
    columns[column] = {f.at, *si};
  }
  const bool dma = columns.count(Column::frequency) > 0;
  const bool relaxation = columns.count(Column::time) > 0;
  if (dma == relaxation) {
    fail(origin, header_no, "the header names " + std::string(dma ? "both frequency and time" : "neither frequency nor time") +
                                ": a DMA file has 'frequency [Hz]', 'storage [MPa]' and 'loss [MPa]' (or "
                                "'tan_delta'), a relaxation test 'time [s]' and 'modulus [MPa]'; " + header_words(names));
  }
  if (dma && (!columns.count(Column::storage) || !(columns.count(Column::loss) || columns.count(Column::tan_delta)))) {
    fail(origin, header_no, "a DMA file needs 'storage [unit]' and 'loss [unit]' (or 'tan_delta') columns; " +
                                header_words(names));
  }
  if (relaxation && !columns.count(Column::modulus)) {
    fail(origin, header_no, "a relaxation test needs a 'modulus [unit]' column; " + header_words(names));
  }
  if (!columns.count(Column::temperature) && std::isnan(temperature)) {
    fail(origin, header_no, "no 'temperature [C]' column: give the file's temperature as " + origin + "@23C; " +
                                header_words(names));
  }
  if (columns.count(Column::temperature) && !std::isnan(temperature)) {
    fail(origin, header_no, "the file has a 'temperature' column and a temperature was given after '@': give one "
                            "or the other");
  }

  std::size_t readings = 0;
  for (std::size_t k = first; k < lines.size(); ++k) {
    const std::size_t line_no = lines[k].first;
    const std::vector<std::string> cells = cells_of(lines[k].second, width);
    if (cells.size() != width) {
      fail(origin, line_no, std::to_string(cells.size()) + " values where the header has " + std::to_string(width) + " columns");
    }
    std::map<Column, double> v;
    for (const auto& [column, where] : columns) {
      const std::string& written = cells[where.first];
      const std::optional<double> x = cell_number(written, decimal_comma);
      if (!x) fail(origin, line_no, "column " + std::to_string(where.first + 1) + ": '" + written + "' is not a number");
      v[column] = *x * where.second.factor + where.second.offset;
      if (column != Column::temperature && !(v[column] > 0.0)) {
        fail(origin, line_no, "column " + std::to_string(where.first + 1) + ": '" + written + "' is not > 0");
      }
    }
    const double th = columns.count(Column::temperature) ? v[Column::temperature] : temperature;
    if (!(th > -model::kZeroCelsius)) fail(origin, line_no, "the temperature is not above absolute zero");
    if (columns.count(Column::frequency)) {
      const double loss = columns.count(Column::loss) ? v[Column::loss] : v[Column::storage] * v[Column::tan_delta];
      // Both loss and tan delta: they must say the same (to 2%, their rounding in exports).
      if (columns.count(Column::loss) && columns.count(Column::tan_delta) &&
          std::abs(v[Column::loss] / (v[Column::storage] * v[Column::tan_delta]) - 1.0) > kTanDeltaAgreement) {
        fail(origin, line_no, "loss / storage = " + model::number_text(v[Column::loss] / v[Column::storage], 4) +
                                  " but tan_delta = " + model::number_text(v[Column::tan_delta], 4) +
                                  ": the columns contradict each other (valid: within 2%)");
      }
      into->dma.push_back({th, v[Column::frequency], v[Column::storage], loss});
    } else {
      into->relaxation.push_back({th, v[Column::time], v[Column::modulus]});
    }
    ++readings;
  }
  if (readings == 0) throw UsageError(origin + ": a header but no readings");
}

double read_temperature(const std::string& text, const std::string& option) {
  const std::string t = trim_cell(text);
  double x = 0.0;
  const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), x);
  if (ec != std::errc() || !std::isfinite(x)) {
    throw UsageError(option + " = '" + text + "' is not a temperature (a number in degC, or with its unit: 23C, 296.15K)");
  }
  const std::string unit = trim_cell(std::string_view(ptr, static_cast<std::size_t>(t.data() + t.size() - ptr)));
  if (!unit.empty()) {
    const std::optional<ToSi> si = unit_of(Column::temperature, unit);
    if (!si) throw UsageError(option + " = '" + text + "': '" + unit + "' is not a temperature unit (valid: C, degC or K)");
    x = x * si->factor + si->offset;
  }
  if (!(x > -model::kZeroCelsius)) throw UsageError(option + " = '" + text + "' is not above absolute zero (-273.15 C)");
  return x;
}

fit::Measurements read_measurement_files(const std::vector<std::string>& specs) {
  fit::Measurements m;
  for (const std::string& spec : specs) {
    std::string path = spec;
    double temperature = std::numeric_limits<double>::quiet_NaN();
    std::error_code ec;
    // FILE@TEMPERATURE, unless the whole text names a file (a name may hold an '@').
    if (const auto at = spec.rfind('@'); at != std::string::npos && !std::filesystem::is_regular_file(spec, ec)) {
      path = spec.substr(0, at);
      temperature = read_temperature(spec.substr(at + 1), "--dma " + spec);
    }
    read_measurements(read_text_file(path, "measurement file"), path, temperature, &m);
  }
  if (!m.dma.empty() && !m.relaxation.empty()) {
    throw UsageError("the files mix DMA readings and relaxation tests; fit one kind at a time");
  }
  return m;
}

}  // namespace punchsweep::input
