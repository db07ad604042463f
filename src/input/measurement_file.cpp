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
  std::vector<std::string_view> names;
  std::string_view units;  ///< for messages
};

const std::array<ColumnSpec, 7>& column_specs() {
  static const std::array<ColumnSpec, 7> specs{{
      {Column::temperature, {"temperature", "temp"}, "C, degC or K"},
      {Column::frequency, {"frequency", "freq"}, "Hz or rad/s"},
      {Column::storage, {"storage", "storagemodulus", "e'"}, "Pa, kPa, MPa or GPa"},
      {Column::loss, {"loss", "lossmodulus", "e''"}, "Pa, kPa, MPa or GPa"},
      {Column::tan_delta, {"tandelta", "tan(delta)", "tand"}, "- or 1"},
      {Column::time, {"time"}, "s, min or h"},
      {Column::modulus, {"modulus", "relaxationmodulus", "e(t)"}, "Pa, kPa, MPa or GPa"},
  }};
  return specs;
}

/// How far loss / storage and a tan_delta column of the same reading may differ.
constexpr double kTanDeltaAgreement = 0.02;

/// A cell or header without blanks and the quotes spreadsheets put around it.
std::string trim(std::string_view s) { return std::string(model::trim(s, " \t\r\"")); }

std::string normalized(std::string_view s) {
  std::string out;
  for (const char c : s) {
    if (c == ' ' || c == '_' || c == '-' || c == '\t') continue;
    out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

/// The cells of a line: split at `sep` outside double quotes (a spreadsheet quotes a cell
/// that holds the separator, and doubles a quote inside one: "a ""b"", c").
std::vector<std::string> split(std::string_view line, char sep) {
  std::vector<std::string> cells;
  std::string cell;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '"') {
      if (quoted && i + 1 < line.size() && line[i + 1] == '"') {
        cell += '"';
        ++i;
      } else {
        quoted = !quoted;
      }
    } else if (c == sep && !quoted) {
      cells.push_back(trim(cell));
      cell.clear();
    } else {
      cell += c;
    }
  }
  cells.push_back(trim(cell));
  return cells;
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
      if (u == "c" || u == "degc" || u == "\xc2\xb0" "c" || u == "celsius") return ToSi{1.0, 0.0};
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
  const std::string_view text = unified;
  std::size_t line_no = 0, start = 0;
  std::map<Column, std::pair<std::size_t, ToSi>> columns;
  std::size_t width = 0;
  char sep = ',';
  bool header = false;
  std::size_t readings = 0;
  while (start <= text.size()) {
    auto end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++line_no;
    const std::string t(model::trim(line, " \t\r"));  // (a quote at either end belongs to a cell)
    if (t.empty() || t[0] == '#') {
      if (end == text.size()) break;
      continue;
    }
    if (!header) {
      sep = t.find(';') != std::string::npos ? ';' : t.find('\t') != std::string::npos ? '\t' : ',';
      const std::vector<std::string> cells = split(t, sep);
      width = cells.size();
      for (std::size_t c = 0; c < cells.size(); ++c) {
        if (cells[c].empty()) {
          fail(origin, line_no, "column " + std::to_string(c + 1) + " of the header is empty (a stray separator?); "
                                "name every column, e.g. 'temperature [C]'");
        }
        const auto open = cells[c].find('[');
        const auto close = cells[c].rfind(']');
        const std::string name = normalized(cells[c].substr(0, open));
        const std::string unit =
            open == std::string::npos || close == std::string::npos || close < open ? "" : trim(cells[c].substr(open + 1, close - open - 1));
        const ColumnSpec* spec = nullptr;
        for (const ColumnSpec& s : column_specs()) {
          if (std::find(s.names.begin(), s.names.end(), name) != s.names.end()) spec = &s;
        }
        if (spec == nullptr) continue;  // a column the fit does not use (e.g. strain amplitude)
        if (columns.count(spec->column)) fail(origin, line_no, "two columns are '" + std::string(spec->names[0]) + "'");
        if (open == std::string::npos && spec->column != Column::tan_delta) {
          fail(origin, line_no, "column '" + cells[c] + "' names no unit; write it as '" + std::string(spec->names[0]) +
                                    " [unit]' with the unit one of " + std::string(spec->units));
        }
        const std::optional<ToSi> si = unit_of(spec->column, unit);
        if (!si) {
          fail(origin, line_no, "column '" + cells[c] + "': '" + unit + "' is not a unit it takes (valid: " +
                                    std::string(spec->units) + ")");
        }
        columns[spec->column] = {c, *si};
      }
      header = true;
      const bool dma = columns.count(Column::frequency) > 0;
      const bool relaxation = columns.count(Column::time) > 0;
      if (dma == relaxation) {
        fail(origin, line_no, "the header names " + std::string(dma ? "both frequency and time" : "neither frequency nor time") +
                                  ": a DMA file has 'frequency [Hz]', 'storage [MPa]' and 'loss [MPa]' (or "
                                  "'tan_delta'), a relaxation test 'time [s]' and 'modulus [MPa]'");
      }
      if (dma && (!columns.count(Column::storage) || !(columns.count(Column::loss) || columns.count(Column::tan_delta)))) {
        fail(origin, line_no, "a DMA file needs 'storage [unit]' and 'loss [unit]' (or 'tan_delta') columns");
      }
      if (relaxation && !columns.count(Column::modulus)) fail(origin, line_no, "a relaxation test needs a 'modulus [unit]' column");
      if (!columns.count(Column::temperature) && std::isnan(temperature)) {
        fail(origin, line_no, "no 'temperature [C]' column: give the file's temperature as " + origin + "@23C");
      }
      if (columns.count(Column::temperature) && !std::isnan(temperature)) {
        fail(origin, line_no, "the file has a 'temperature' column and a temperature was given after '@': give one "
                              "or the other");
      }
      if (end == text.size()) break;
      continue;
    }
    const std::vector<std::string> cells = split(t, sep);
    if (cells.size() != width) {
      fail(origin, line_no, std::to_string(cells.size()) + " values where the header has " + std::to_string(width) + " columns");
    }
    std::map<Column, double> v;
    for (const auto& [column, where] : columns) {
      const std::string& written = cells[where.first];
      const std::string cell = !written.empty() && written[0] == '+' ? written.substr(1) : written;  // "+1" is 1
      double x = 0.0;
      const auto [ptr, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), x);
      if (ec != std::errc() || ptr != cell.data() + cell.size() || !std::isfinite(x)) {
        fail(origin, line_no, "column " + std::to_string(where.first + 1) + ": '" + written + "' is not a number");
      }
      v[column] = x * where.second.factor + where.second.offset;
      if (column != Column::temperature && !(v[column] > 0.0)) {
        fail(origin, line_no, "column " + std::to_string(where.first + 1) + ": '" + cell + "' is not > 0");
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
    if (end == text.size()) break;
  }
  if (!header) throw UsageError(origin + ": no header row (e.g. 'temperature [C],frequency [Hz],storage [MPa],loss [MPa]')");
  if (readings == 0) throw UsageError(origin + ": a header but no readings");
}

double read_temperature(const std::string& text, const std::string& option) {
  const std::string t = trim(text);
  double x = 0.0;
  const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), x);
  if (ec != std::errc() || !std::isfinite(x)) {
    throw UsageError(option + " = '" + text + "' is not a temperature (a number in degC, or with its unit: 23C, 296.15K)");
  }
  const std::string unit = trim(std::string_view(ptr, static_cast<std::size_t>(t.data() + t.size() - ptr)));
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
