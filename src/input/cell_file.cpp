#include "input/cell_file.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "input/text_file.hpp"
#include "input/usage_error.hpp"
#include "input/value_parsing.hpp"
#include "model/numerics/number_text.hpp"

namespace punchsweep::input {

model::CellGeometry parse_cell(const std::string& text, const std::string& origin, const PhysicalScales& scales,
                               std::vector<std::string>* notes) {
  int line_number = 0;
  // Lengths given with a unit, and the first nonzero one given bare (read in R).
  bool any_unit = false;
  std::string first_bare;
  int bare_count = 0;
  const auto fail = [&](const std::string& what) -> void {
    throw UsageError(origin + (line_number > 0 ? ":" + std::to_string(line_number) : std::string()) + ": " + what);
  };
  const auto length = [&](const std::string& key, const std::string& value) {
    const std::string text(model::trim(value));
    const double v = read_length(text, scales, origin + ":" + std::to_string(line_number) + ": " + key);
    const bool has_unit = text.find_first_not_of("0123456789.+-eE") != std::string::npos;  // (read_length took it)
    if (has_unit) {
      any_unit = true;
    } else if (v != 0.0) {
      if (bare_count++ == 0) first_bare = "line " + std::to_string(line_number) + ", " + key + " = " + text;
    }
    return v;
  };
  std::map<std::string, std::pair<std::string, int>> keys;  // key -> value, line
  std::vector<std::pair<std::string, int>> sites;           // text, line
  bool in_cell = false;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    ++line_number;
    if (const auto hash = line.find_first_of("#;"); hash != std::string::npos) line.erase(hash);
    line = std::string(model::trim(line));
    if (line.empty()) continue;
    if (line.front() == '[') {
      if (line != "[cell]") fail("'" + line + "' is no section of a cell file; valid: [cell]");
      if (in_cell) fail("section [cell] appears twice");
      in_cell = true;
      continue;
    }
    const auto eq = line.find('=');
    if (eq == std::string::npos) fail("'" + line + "' is not 'key = value'");
    if (!in_cell) fail("'" + line + "' comes before [cell]");
    const std::string key(model::trim(std::string_view(line).substr(0, eq)));
    const std::string value(model::trim(std::string_view(line).substr(eq + 1)));
    if (key == "site") {
      sites.emplace_back(value, line_number);
    } else if (key == "Lx" || key == "Ly" || key == "s" || key == "C") {
      if (!keys.emplace(key, std::make_pair(value, line_number)).second) fail("key " + key + " is given twice");
    } else {
      fail("unknown key '" + key + "'; valid: Lx, Ly, s, C, site");
    }
  }
  model::CellGeometry g;
  model::Shape shape{};
  for (const char* key : {"Lx", "Ly"}) {
    const auto it = keys.find(key);
    if (it == keys.end()) {
      line_number = 0;
      fail(std::string("missing key ") + key + " (the cell's length, in R or with a unit)");
    }
    line_number = it->second.second;
    (std::string(key) == "Lx" ? g.Lx : g.Ly) = length(key, it->second.first);
  }
  if (const auto it = keys.find("s"); it != keys.end()) {
    line_number = it->second.second;
    shape.s = parse_integer(it->second.first, origin + ":" + std::to_string(line_number) + ": s");
  }
  if (const auto it = keys.find("C"); it != keys.end()) {
    line_number = it->second.second;
    shape.C = parse_real(it->second.first, origin + ":" + std::to_string(line_number) + ": C");
  }
  for (const auto& [value, line] : sites) {
    line_number = line;
    std::vector<std::string> fields;
    std::istringstream items(value);
    for (std::string item; std::getline(items, item, ',');) fields.emplace_back(model::trim(item));
    if (fields.size() != 4 && fields.size() != 6) {
      fail("site = " + value + ": give x, y, drop, level (and optionally s, C)");
    }
    model::Site site;
    site.x = length("site x", fields[0]);
    site.y = length("site y", fields[1]);
    site.drop = length("site drop", fields[2]);
    site.level = parse_integer(fields[3], origin + ":" + std::to_string(line) + ": site level");
    site.shape = shape;
    if (fields.size() == 6) {
      site.shape.s = parse_integer(fields[4], origin + ":" + std::to_string(line) + ": site s");
      site.shape.C = parse_real(fields[5], origin + ":" + std::to_string(line) + ": site C");
    }
    // A tip on the far edge is the near edge's: the cell is periodic.
    if (site.x == g.Lx) site.x = 0.0;
    if (site.y == g.Ly) site.y = 0.0;
    g.sites.push_back(site);
  }
  line_number = 0;
  if (const std::string e = model::geometry_error(g); !e.empty()) throw UsageError(origin + ": " + e);
  double least = std::numeric_limits<double>::infinity();
  for (const model::Site& site : g.sites) least = std::min(least, site.drop);
  if (least != 0.0) {
    std::ostringstream out;
    out.precision(17);
    out << origin << ": the least drop is " << least << " R: the tallest site's drop is 0 (drops are taken from it)";
    throw UsageError(out.str());
  }
  if (notes != nullptr) {
    if (any_unit && bare_count > 0) {
      notes->push_back(origin + ": " + std::to_string(bare_count) + " length" + (bare_count == 1 ? "" : "s") +
                       " without a unit beside lengths with units (the first: " + first_bare +
                       ") read in R, the punch's radius of curvature; give a unit to mean a physical length");
    }
    // Level 0 is the tallest: its caps touch at once.
    double level0 = std::numeric_limits<double>::infinity();
    for (const model::Site& site : g.sites) {
      if (site.level == 0) level0 = std::min(level0, site.drop);
    }
    if (level0 > 0.0) {
      for (std::size_t k = 0; k < g.sites.size(); ++k) {
        if (g.sites[k].drop != 0.0) continue;
        notes->push_back(origin + ":" + std::to_string(sites[k].second) + ": the tallest site is of level " +
                         std::to_string(g.sites[k].level) + ", not 0: levels are read as numbered, level 0 first, " +
                         "though level 0's caps are not the first to touch");
        break;
      }
    }
  }
  // Every tip on the texture's surface: a site under a taller cap (or on another's tip)
  // would never touch as a punch of its own.
  std::size_t by = 0;
  if (const std::size_t k = model::covered_site(g, model::SurfaceLocator(g), &by); k < g.sites.size()) {
    std::ostringstream out;
    out.precision(6);
    const model::Site& site = g.sites[k];
    const model::Site& other = g.sites[by];
    out << origin << ":" << sites[k].second << ": site = " << sites[k].first << ": its tip ";
    if (other.x == site.x && other.y == site.y) {
      out << "is the tip of the site on line " << sites[by].second << ": give each cap once";
    } else {
      out << "lies under the surface of the site on line " << sites[by].second << " (" << sites[by].first
          << "): it would never touch as a cap of its own; every tip must be on the texture's surface (raise it, or move it "
             "away from the taller cap)";
    }
    throw UsageError(out.str());
  }
  return g;
}

model::CellGeometry read_cell_file(const std::string& path, const PhysicalScales& scales, std::vector<std::string>* notes) {
  return parse_cell(read_text_file(path, "cell file"), path, scales, notes);
}

}  // namespace punchsweep::input
