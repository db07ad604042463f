#include "input/csv_cells.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "model/numerics/number_text.hpp"

namespace punchsweep::input {

std::string trim_cell(std::string_view cell) { return std::string(model::trim(cell, " \t\r\"")); }

std::vector<std::string> split_cells(std::string_view line, char sep) {
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
      cells.push_back(trim_cell(cell));
      cell.clear();
    } else {
      cell += c;
    }
  }
  cells.push_back(trim_cell(cell));
  return cells;
}

char separator_of(std::string_view line) {
  return line.find(';') != std::string_view::npos ? ';' : line.find('\t') != std::string_view::npos ? '\t' : ',';
}

std::optional<double> cell_number(const std::string& written, bool decimal_comma) {
  std::string cell = !written.empty() && written[0] == '+' ? written.substr(1) : written;
  if (decimal_comma) std::replace(cell.begin(), cell.end(), ',', '.');
  double x = 0.0;
  const auto [ptr, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), x);
  if (ec != std::errc() || ptr != cell.data() + cell.size() || !std::isfinite(x)) return std::nullopt;
  return x;
}

}  // namespace punchsweep::input
