#include "app/curve_cache.hpp"

#include <cstdint>
#include <cstdio>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/table_cache.hpp"
#include "io/sha256.hpp"

namespace punchsweep::app {

namespace {

/// Everything the curve depends on, as text: the geometry, the grid, the cell's fields and
/// the options (a change of any gives another file).
std::string curve_key(const model::CellGeometry& g, const reference::Cell& cell, const reference::LoadCurveOptions& o) {
  const reference::PeriodicGrid& grid = cell.grid;
  // The cell's own numbers too (a measured map's heights are no sites' punches): the
  // profile and the levels' shares, hashed.
  io::Sha256 fields;
  fields.update(cell.profile.data(), cell.profile.size() * sizeof(double));
  for (const std::vector<double>& weight : cell.level_weight) fields.update(weight.data(), weight.size() * sizeof(double));
  fields.update(cell.tips.data(), cell.tips.size() * sizeof(std::size_t));
  fields.update(cell.tip_exposed.data(), cell.tip_exposed.size());
  const io::Digest field_digest = fields.digest();
  std::ostringstream key;
  key.precision(17);
  key << "punchsweep load curve, format " << model::LoadCurve::kFormat << "; cell " << g.Lx << " x " << g.Ly << "; sites";
  for (const model::Site& s : g.sites) key << " (" << s.x << ' ' << s.y << ' ' << s.shape.s << ' ' << s.shape.C << ' ' << s.drop << ' ' << s.level << ')';
  key << "; grid " << grid.nx << " x " << grid.ny << (grid.mirrored() ? " quarter" : " whole") << "; top " << o.X_top
      << "; spot " << o.min_spot_nodes << "; decade " << o.samples_per_decade << "; area " << o.area_tolerance << "; load "
      << o.load_tolerance << "; refinements " << o.max_refinements << "; touchdown " << o.touchdown_tolerance << "; solver "
      << o.solver.tolerance << ' ' << o.solver.max_iterations << ' ' << o.solver.precondition << "; fields";
  for (unsigned char byte : field_digest) key << ' ' << static_cast<int>(byte);
  return key.str();
}

/// The digest as 8 doubles (each 4 of its bytes as an integer, exact in a double).
std::vector<double> digest_numbers(const io::Digest& d) {
  std::vector<double> out;
  for (std::size_t k = 0; k < d.size(); k += 4) {
    out.push_back(static_cast<double>((std::uint32_t{d[k]} << 24) | (std::uint32_t{d[k + 1]} << 16) |
                                      (std::uint32_t{d[k + 2]} << 8) | std::uint32_t{d[k + 3]}));
  }
  return out;
}

}  // namespace

model::LoadCurve load_curve_for(const model::CellGeometry& geometry, const reference::Cell& cell,
                                const reference::LoadCurveOptions& options, CurveOrigin* origin) {
  CurveOrigin ignored;
  if (origin == nullptr) origin = &ignored;
  *origin = CurveOrigin::built;
  const TableCacheFolder cache = table_cache_folder();
  if (!cache.folder || !cache.not_used.empty() || !untrusted_folder(*cache.folder).empty() ||
      !make_private_folder(*cache.folder)) {
    return reference::build_load_curve(geometry, cell, options);
  }
  const std::string key = curve_key(geometry, cell, options);
  io::Sha256 hash;
  hash.update(key.data(), key.size());
  const std::vector<double> digest = digest_numbers(hash.digest());
  char name[64];
  std::snprintf(name, sizeof name, "load-curve-%08llx%08llx%08llx%08llx.tables", static_cast<unsigned long long>(digest[0]),
                static_cast<unsigned long long>(digest[1]), static_cast<unsigned long long>(digest[2]),
                static_cast<unsigned long long>(digest[3]));
  const std::filesystem::path file = *cache.folder / name;
  const FileLock lock(*cache.folder / (std::string(name) + ".lock"));
  // Under the lock a builder before us has saved its curve by now. The file's first numbers
  // are the key's digest: a file of another key under this name is not believed.
  const std::vector<double> numbers = read_tables(file);
  if (numbers.size() > digest.size() && std::equal(digest.begin(), digest.end(), numbers.begin())) {
    if (std::optional<model::LoadCurve> curve =
            model::LoadCurve::from_tables(std::vector<double>(numbers.begin() + static_cast<std::ptrdiff_t>(digest.size()), numbers.end()))) {
      *origin = CurveOrigin::cache;
      return std::move(*curve);
    }
  }
  model::LoadCurve curve = reference::build_load_curve(geometry, cell, options);
  std::vector<double> saved = digest;
  const std::vector<double> tables = curve.tables();
  saved.insert(saved.end(), tables.begin(), tables.end());
  write_tables(file, saved);
  return curve;
}

}  // namespace punchsweep::app
