// Measures, for every tile of a sweep, what it costs a rank to compute it (evaluate and
// encode) and what it costs rank 0 to take it in (journal and write): the input of
// benchmarks/scheduler_simulation.py, which plays the manager/worker schedule with these
// costs for any number of ranks.
// Usage: tile_costs [punchsweep sweep options] > costs.csv   (one process; writes a scratch map)
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "input/sweep_options.hpp"
#include "io/encoded_tile.hpp"
#include "io/tile_encoder.hpp"
#include "map/tiling.hpp"
#include "run/map_run.hpp"
#include "sweep/tile_evaluator.hpp"

using namespace punchsweep;
using Clock = std::chrono::steady_clock;

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  std::ostringstream help;
  sweep::SweepConfig config = input::parse_sweep_options(args, help, nullptr);
  const std::string scratch = (std::filesystem::temp_directory_path() / "punchsweep_tile_costs.h5").string();
  std::filesystem::remove(scratch + ".partial");
  std::filesystem::remove(scratch + ".partial.journal");
  config.output = scratch;
  config.quiet = true;
  const map::Tiling tiling(config.grid.shape(), config.tile_points());
  const sweep::TileEvaluator evaluator(config.grid, *config.creep_law, config.C, config.times, config.quantities);
  const io::MapLayout layout = run::map_layout(config, tiling, std::nullopt, 0.0);
  io::TileEncoder encoder(layout);
  std::ostringstream log;
  const io::MapAttributes attributes;
  run::MapRun sink(config, layout, attributes, run::Start::fresh, tiling, log);
  map::TileData data;
  std::printf("tile,points,compute_s,sink_s,bytes\n");
  for (std::size_t t = 0; t < tiling.tiles(); ++t) {
    const auto a = Clock::now();
    const map::TileBox box = tiling.box(t);
    evaluator.evaluate(box, &data);
    const std::vector<std::byte> bytes = io::pack_encoded_tile(encoder.encode(t, box, data));
    const auto b = Clock::now();
    sink.accept(bytes);
    const auto c = Clock::now();
    std::printf("%zu,%zu,%.9g,%.9g,%zu\n", t, box.points(), std::chrono::duration<double>(b - a).count(),
                std::chrono::duration<double>(c - b).count(), bytes.size());
  }
  sink.finish(1);
  std::filesystem::remove(scratch);
  return 0;
}
