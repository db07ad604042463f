#include "engine/curve_cache.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "engine/table_cache.hpp"
#include "io/sha256.hpp"

namespace punchsweep::engine {

namespace {

/// The digest of a cell's fields: its profile, the levels' shares, the tips.
io::Digest cell_digest(const reference::Cell& cell) {
  io::Sha256 fields;
  fields.update(cell.profile.data(), cell.profile.size() * sizeof(double));
  for (const std::vector<double>& weight : cell.level_weight) fields.update(weight.data(), weight.size() * sizeof(double));
  fields.update(cell.tips.data(), cell.tips.size() * sizeof(std::size_t));
  fields.update(cell.tip_exposed.data(), cell.tip_exposed.size());
  return fields.digest();
}

/// cell_digest as text: each byte as a decimal number after a space.
std::string cell_digest_text(const reference::Cell& cell) {
  std::ostringstream text;
  for (unsigned char byte : cell_digest(cell)) text << ' ' << static_cast<int>(byte);
  return text.str();
}

/// The fingerprint of reference::make_cell: the digest of the cell it makes of a probe (a
/// hexagonal lattice of three levels on a small grid), once per process. A curve's key holds
/// it instead of the cell's own fields, so that a cached curve is found from its geometry
/// and grid without making its cell (seconds for a scattered supercell), and a change to how
/// cells are made, which changes the probe's, gives every curve another key.
const std::string& cell_maker_fingerprint() {
  static const std::string fingerprint = [] {
    model::Shape shape;
    shape.s = 2.0;
    shape.C = 0.5;
    const model::CellGeometry probe = model::lattice_cell(model::LatticeKind::hexagonal, 1.2, shape, {0.05, 0.08});
    return cell_digest_text(reference::make_cell(probe, reference::lattice_grid(probe, model::LatticeKind::hexagonal, 12, 1)));
  }();
  return fingerprint;
}

/// Everything the curve depends on, as text: the geometry, the grid, the options (but the
/// reach: saved_curve cuts a longer curve to it), and the
/// cell: a measured map's own fields (its heights are no sites' punches), hashed; else how
/// cells are made from a geometry and a grid (cell_maker_fingerprint). A change of any
/// gives another file.
std::string curve_key(const model::CellGeometry& g, const reference::PeriodicGrid& grid, const reference::LoadCurveOptions& o,
                      const reference::Cell* measured) {
  std::ostringstream key;
  key.precision(17);
  key << "punchsweep load curve, format " << model::LoadCurve::kFormat << "; cell " << g.Lx << " x " << g.Ly << "; sites";
  for (const model::Site& s : g.sites) key << " (" << s.x << ' ' << s.y << ' ' << s.shape.s << ' ' << s.shape.C << ' ' << s.drop << ' ' << s.level << ')';
  key << "; grid " << grid.nx << " x " << grid.ny << (grid.mirrored() ? " quarter" : grid.mirrored_x() ? " half" : " whole") << "; top " << o.X_top
      << "; spot " << o.min_spot_nodes << "; decade " << o.samples_per_decade << "; area " << o.area_tolerance << "; load "
      << o.load_tolerance << "; refinements " << o.max_refinements << "; touchdown " << o.touchdown_tolerance << "; solver "
      << o.solver.tolerance << ' ' << o.solver.max_iterations << ' ' << o.solver.precondition;
  if (measured) {
    key << "; fields" << cell_digest_text(*measured);
  } else {
    key << "; cells made as" << cell_maker_fingerprint();
  }
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

/// Where the curve of `key` is saved in the cache (the file's name from the key's digest),
/// and the digest the file must start with.
struct CacheEntry {
  std::filesystem::path file;
  std::string name;
  std::vector<double> digest;
};
CacheEntry cache_entry(const std::filesystem::path& folder, const std::string& key) {
  io::Sha256 hash;
  hash.update(key.data(), key.size());
  CacheEntry entry;
  entry.digest = digest_numbers(hash.digest());
  char name[64];
  std::snprintf(name, sizeof name, "load-curve-%08llx%08llx%08llx%08llx.tables", static_cast<unsigned long long>(entry.digest[0]),
                static_cast<unsigned long long>(entry.digest[1]), static_cast<unsigned long long>(entry.digest[2]),
                static_cast<unsigned long long>(entry.digest[3]));
  entry.name = name;
  entry.file = folder / name;
  return entry;
}

/// The numbers saved in `file` after `digest`, where the file starts with it (a file of
/// another key under this name is not believed); else empty.
std::vector<double> saved_numbers(const std::filesystem::path& file, const std::vector<double>& digest) {
  std::vector<double> numbers = read_tables(file);
  if (numbers.size() <= digest.size() || !std::equal(digest.begin(), digest.end(), numbers.begin())) return {};
  numbers.erase(numbers.begin(), numbers.begin() + static_cast<std::ptrdiff_t>(digest.size()));
  return numbers;
}

/// The curve saved in `entry`'s file, whole (as far as it was built), where there is one.
std::optional<model::LoadCurve> saved_curve(const CacheEntry& entry) {
  const std::vector<double> numbers = saved_numbers(entry.file, entry.digest);
  return numbers.empty() ? std::nullopt : model::LoadCurve::from_tables(numbers);
}

/// Whether `curve` reaches the end of the march for `options`.
bool reaches(const model::LoadCurve& curve, const reference::LoadCurveOptions& options) {
  return std::isfinite(curve.X_full) || curve.X_last() >= reference::march_end(curve.X_first(), options);
}

/// The front saved beside a curve that stops at X_last short of full contact
/// (reference::CurveFront), in the file beside the curve's: the digest, X_last, the sizes,
/// the pressure, the h's; none where it is not that curve's.
std::filesystem::path front_file(const CacheEntry& entry) {
  std::filesystem::path file = entry.file;
  return file.replace_extension(".front");
}
std::optional<reference::CurveFront> saved_front(const CacheEntry& entry, const model::LoadCurve& curve) {
  const std::vector<double> n = saved_numbers(front_file(entry), entry.digest);
  if (n.size() < 3 || n[0] != curve.X_last() || n.size() != 3 + static_cast<std::size_t>(n[1]) + static_cast<std::size_t>(n[2])) {
    return std::nullopt;
  }
  const auto p = n.begin() + 3, h = p + static_cast<std::ptrdiff_t>(n[1]);
  return reference::CurveFront{std::vector<double>(p, h), std::vector<double>(h, n.end())};
}

/// Saves `curve` (and where it stops short of full contact, its front) under `entry`.
void save_curve(const CacheEntry& entry, const model::LoadCurve& curve, const reference::CurveFront& front) {
  std::vector<double> saved = entry.digest;
  const std::vector<double> tables = curve.tables();
  saved.insert(saved.end(), tables.begin(), tables.end());
  write_tables(entry.file, saved);
  if (front.p.empty()) return;
  std::vector<double> numbers = entry.digest;
  numbers.insert(numbers.end(), {curve.X_last(), static_cast<double>(front.p.size()), static_cast<double>(front.h.size())});
  numbers.insert(numbers.end(), front.p.begin(), front.p.end());
  numbers.insert(numbers.end(), front.h.begin(), front.h.end());
  write_tables(front_file(entry), numbers);
}

/// The cache's folder where it may be used, else none.
std::optional<std::filesystem::path> usable_cache() {
  const TableCacheFolder cache = table_cache_folder();
  if (!cache.folder || !cache.not_used.empty() || !untrusted_folder(*cache.folder).empty() || !make_private_folder(*cache.folder)) {
    return std::nullopt;
  }
  return *cache.folder;
}

}  // namespace

model::LoadCurve load_curve_for(const model::CellGeometry& geometry, const reference::PeriodicGrid& grid,
                                const reference::LoadCurveOptions& options, const reference::Cell* measured,
                                const std::function<const reference::Cell&()>& cell, CurveOrigin* origin) {
  CurveOrigin ignored;
  if (origin == nullptr) origin = &ignored;
  *origin = CurveOrigin::built;
  const std::optional<std::filesystem::path> folder = usable_cache();
  if (!folder) return reference::build_load_curve(geometry, cell(), options);
  const CacheEntry entry = cache_entry(*folder, curve_key(geometry, grid, options, measured));
  const FileLock lock(*folder / (entry.name + ".lock"));
  // Under the lock a builder before us has saved its curve by now: read and cut where it
  // reaches as far, else continued from where it stopped (its front), else built.
  std::optional<model::LoadCurve> saved = saved_curve(entry);
  if (saved && reaches(*saved, options)) {
    *origin = CurveOrigin::cache;
    return saved->up_to(reference::march_end(saved->X_first(), options));
  }
  reference::CurveFront front;
  std::optional<reference::CurveFront> from;
  if (saved && !std::isfinite(saved->X_full)) from = saved_front(entry, *saved);
  model::LoadCurve curve = from ? reference::extend_load_curve(geometry, cell(), std::move(*saved), *from, options, &front)
                                : reference::build_load_curve(geometry, cell(), options, &front);
  if (from) *origin = CurveOrigin::extended;
  save_curve(entry, curve, front);
  return curve;
}

CachedCurve cached_curve(const model::CellGeometry& geometry, const reference::PeriodicGrid& grid,
                         const reference::LoadCurveOptions& options, const reference::Cell* measured) {
  CachedCurve out;
  const std::optional<std::filesystem::path> folder = usable_cache();
  if (!folder) return out;
  const CacheEntry entry = cache_entry(*folder, curve_key(geometry, grid, options, measured));
  const std::optional<model::LoadCurve> saved = saved_curve(entry);
  if (!saved) return out;
  out.X_first = saved->X_first();
  out.X_last = saved->X_last();
  if (reaches(*saved, options)) {
    out.holds = CachedCurve::Holds::whole;
  } else if (!std::isfinite(saved->X_full) && saved_front(entry, *saved)) {
    out.holds = CachedCurve::Holds::beginning;
  }
  return out;
}

}  // namespace punchsweep::engine
