#include "run/disk_space.hpp"

#include <sys/statvfs.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "io/encoded_tile.hpp"
#include "io/map_variables.hpp"
#include "io/tile_encoder.hpp"

namespace fs = std::filesystem;

namespace punchsweep::run {

DiskEstimate estimate_disk(const map::Tiling& tiling, const sweep::TileEvaluator& evaluator,
                           const io::MapLayout& layout, double seconds) {
  io::MapLayout model_layout = layout;
  model_layout.bem.reset();
  io::TileEncoder encoder(model_layout);
  map::TileData data;
  constexpr std::uint64_t kMaxTiles = 8;
  const std::uint64_t tiles = std::min<std::uint64_t>(kMaxTiles, tiling.tiles());
  double compressed = 0.0;
  double records = 0.0;
  DiskEstimate estimate;
  const auto start = std::chrono::steady_clock::now();
  for (std::uint64_t k = 0; k < tiles; ++k) {
    const std::uint64_t tile = tiling.tiles() / tiles * k;  // spread over the grid
    const map::TileBox box = tiling.box(tile);
    evaluator.evaluate(box, &data, sweep::TileEvaluator::Reference::skipped);
    const io::EncodedTile encoded = encoder.encode(tile, box, data);
    for (const auto& chunk : encoded.chunks) compressed += static_cast<double>(chunk.size());
    records += static_cast<double>(io::pack_encoded_tile(encoded).size());
    estimate.sampled_points += box.points();
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > seconds) break;
  }
  const double points = static_cast<double>(layout.grid.points());
  const double per_point = compressed / static_cast<double>(estimate.sampled_points);
  const double per_point_record = records / static_cast<double>(estimate.sampled_points);
  estimate.map_bytes = per_point * points;
  estimate.journal_bytes = per_point_record * points;
  if (layout.bem) {
    const double bem_share = static_cast<double>(io::uncompressed_bytes_per_point(layout) -
                                                 io::uncompressed_bytes_per_point(model_layout));
    const double bem = bem_share * static_cast<double>(layout.bem->sample);
    estimate.map_bytes += bem;
    estimate.journal_bytes += bem;
  }
  return estimate;
}

double free_bytes(const std::string& path) {
  const fs::path p(path);
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  struct statvfs info {};
  if (::statvfs(dir.c_str(), &info) != 0) return -1.0;
  return static_cast<double>(info.f_bavail) * static_cast<double>(info.f_frsize);
}

std::string format_bytes(double bytes) {
  char text[32];
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB"};
  int u = 0;
  while (bytes >= 1024.0 && u < 5) {
    bytes /= 1024.0;
    ++u;
  }
  std::snprintf(text, sizeof text, "%.3g %s", bytes, units[u]);
  return text;
}

std::string disk_space_problem(const OutputPaths& paths, const DiskEstimate& need) {
  const double available = free_bytes(paths.final_path);
  if (available < 0.0) return {};  // cannot tell: let the writes say so
  // What this run writes: the .partial (rebuilt whole; an old one is truncated first) and
  // the journal's missing records.
  std::error_code ec;
  const auto size_of = [&](const std::string& path) {
    return fs::exists(path, ec) ? static_cast<double>(fs::file_size(path, ec)) : 0.0;
  };
  const double needed = need.map_bytes - size_of(paths.partial) +
                        std::max(0.0, need.journal_bytes - size_of(paths.journal));
  if (needed <= available) return {};
  return "output.file = " + paths.final_path + ": the map and its journal need about " +
         format_bytes(need.map_bytes + need.journal_bytes) + " (map " + format_bytes(need.map_bytes) +
         ", journal " + format_bytes(need.journal_bytes) + ", measured on " + std::to_string(need.sampled_points) +
         " points), this run about " + format_bytes(needed) + ", but its file system has " +
         format_bytes(available) + " free; free space, write to another folder, or shrink the grid";
}

}  // namespace punchsweep::run
