// The run layer without mpirun: the resume policy, preflight's verdicts on the output
// files, and a map run's journal, replay and finish, driven with tiles encoded as the
// ranks encode them.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "io/encoded_tile.hpp"
#include "io/regime_map_reader.hpp"
#include "io/scratch_dir.hpp"
#include "io/tile_encoder.hpp"
#include "io/tile_journal.hpp"
#include "map/test_grid.hpp"
#include "map/tiling.hpp"
#include "model/laws/creep_laws.hpp"
#include "run/disk_space.hpp"
#include "run/map_run.hpp"
#include "run/preflight.hpp"
#include "run/progress.hpp"
#include "run/resume_policy.hpp"

using namespace punchsweep;
using namespace punchsweep::map::testing;
using io::testing::ScratchDir;

namespace {

sweep::SweepConfig small_config(const std::string& output) {
  sweep::SweepConfig config;
  config.grid = sls_grid();
  config.grid.axes[kL].values = {0.75, 1.0};
  config.grid.axes[kDh].values = {0.02, 0.05, 0.08};
  config.grid.axes[kT].values = {2.5};
  config.grid.axes[kPbar].values = {0.02, 0.06};
  config.grid.axes[kS].values = {2};
  config.quantities = map::Quantities::regime;
  config.output = output;
  config.quiet = true;
  config.identity = {"grid.l = 0.75, 1", "run.chunk = 2"};
  return config;
}

// A tile's bytes as a rank sends them: every point flagged with `code` (regime), valid.
std::vector<std::byte> packed_tile(io::TileEncoder& encoder, const map::Tiling& tiling, std::size_t tile,
                                   std::int8_t code) {
  const map::TileBox box = tiling.box(tile);
  map::TileData data;
  data.resize(box.points(), 0, map::Quantities::regime, false);
  for (auto& r : flag(data, "regime")) r = code;
  for (auto& v : flag(data, "valid")) v = 0;
  for (const char* name : {"t_star", "h_0", "h_inf", "a1_inf", "a2_inf", "area_fraction_inf"}) {
    for (double& x : real(data, name)) x = 0.25 * static_cast<double>(tile);
  }
  return io::pack_encoded_tile(encoder.encode(tile, box, data));
}

// A small map run's parts: its config (in a scratch folder), tiling (tiles of 2 points),
// layout, an encoder as the ranks have, and the map's attributes.
struct SmallRun {
  ScratchDir dir;
  sweep::SweepConfig config = small_config(dir.file("map.h5"));
  map::Tiling tiling{config.grid.shape(), 2};
  io::MapLayout layout = run::map_layout(config, tiling, std::nullopt, 0.0);
  io::TileEncoder encoder{layout};
  io::MapAttributes attributes{"t", "s", "h", "c", "grid.l = 0.75, 1\nrun.chunk = 2", "standard_linear_solid", 0.5, "T_eps", {}};
  run::OutputPaths paths{config.output};
};

}  // namespace

TEST(ResumePolicy, identity_differences_name_each_key_in_the_existing_maps_order) {
  const std::vector<std::string> d = run::identity_differences(
      {"grid.T = 2, 5", "model.C = 0.5", "run.chunk = 4096"}, {"grid.T = 2, 5", "run.chunk = 8", "time.times = 0"});
  ASSERT_EQ(d.size(), 3U);
  EXPECT_EQ(d[0], "model.C: the existing map has 0.5; this run does not set it");
  EXPECT_EQ(d[1], "run.chunk: the existing map has 4096; this run asks for 8");
  EXPECT_EQ(d[2], "time.times: the existing map does not record it; this run asks for 0");
  EXPECT_TRUE(run::identity_differences({"grid.T = 2"}, {"grid.T  =  2"}).empty());
}

TEST(Preflight, decides_fresh_resume_or_refusal_from_the_files_there) {
  const ScratchDir dir;
  sweep::SweepConfig config = small_config(dir.file("map.h5"));
  const run::OutputPaths paths(config.output);
  run::Start start = run::Start::resume;

  EXPECT_EQ(run::preflight(config, paths, &start), "");
  EXPECT_EQ(start, run::Start::fresh);

  std::ofstream(paths.final_path) << "a finished map";
  EXPECT_NE(run::preflight(config, paths, &start).find("exists; pass --overwrite"), std::string::npos);
  config.overwrite = true;
  EXPECT_EQ(run::preflight(config, paths, &start), "");
  EXPECT_EQ(start, run::Start::fresh);
  config.overwrite = false;
  config.resume = true;
  // A file that is no punchsweep map is never taken for a finished one.
  EXPECT_NE(run::preflight(config, paths, &start).find("is not an HDF5 file"), std::string::npos);
  std::filesystem::remove(paths.final_path);

  // A folder (or a device) where the map would go is refused before any work.
  std::filesystem::create_directory(paths.final_path);
  EXPECT_NE(run::preflight(config, paths, &start).find("is a folder"), std::string::npos);
  config.overwrite = true;
  config.resume = false;
  EXPECT_NE(run::preflight(config, paths, &start).find("is a folder"), std::string::npos);
  config.overwrite = false;
  config.resume = true;
  std::filesystem::remove(paths.final_path);
  sweep::SweepConfig to_null = config;
  to_null.output = "/dev/null";
  EXPECT_NE(run::preflight(to_null, run::OutputPaths(to_null.output), &start).find("/dev/null is a character device"),
            std::string::npos);

  io::TileJournal::create(paths.journal, "grid.l = 0.75, 1\nrun.chunk = 2");
  EXPECT_EQ(run::preflight(config, paths, &start), "");
  EXPECT_EQ(start, run::Start::resume);
  config.identity = {"grid.l = 0.75, 1", "run.chunk = 3"};
  const std::string refusal = run::preflight(config, paths, &start);
  EXPECT_NE(refusal.find("--resume refused"), std::string::npos) << refusal;
  EXPECT_NE(refusal.find("run.chunk: the existing map has 2; this run asks for 3"), std::string::npos) << refusal;
  config.resume = false;
  EXPECT_NE(run::preflight(config, paths, &start).find("pass --resume to finish it"), std::string::npos);

  config.output = dir.file("no/such/folder/map.h5");
  EXPECT_NE(run::preflight(config, run::OutputPaths(config.output), &start).find("does not exist"), std::string::npos);
}

TEST(MapRun, journals_every_tile_and_resumes_with_only_the_missing_ones) {
  SmallRun r;
  auto& [dir, config, tiling, layout, encoder, attributes, paths] = r;
  std::ostringstream log;
  ASSERT_GT(tiling.tiles(), 3U);
  {
    run::MapRun first(config, layout, attributes, run::Start::fresh, tiling, log);
    ASSERT_EQ(first.pending().size(), tiling.tiles());
    first.accept(packed_tile(encoder, tiling, 0, 1));
    first.accept(packed_tile(encoder, tiling, 2, 1));
    first.interrupt();  // as after a stop signal: the journal keeps tiles 0 and 2
  }
  EXPECT_TRUE(std::filesystem::exists(paths.journal));
  EXPECT_FALSE(std::filesystem::exists(paths.final_path));

  run::MapRun second(config, layout, attributes, run::Start::resume, tiling, log);
  std::vector<std::size_t> expected;
  for (std::size_t t = 0; t < tiling.tiles(); ++t) {
    if (t != 0 && t != 2) expected.push_back(t);
  }
  EXPECT_EQ(second.pending().tiles(), expected);
  EXPECT_EQ(second.progress().points_done(), tiling.box(0).points() + tiling.box(2).points());
  for (const std::uint64_t t : second.pending().tiles()) second.accept(packed_tile(encoder, tiling, t, 0));
  second.finish(1);
  EXPECT_TRUE(std::filesystem::exists(paths.final_path));
  EXPECT_FALSE(std::filesystem::exists(paths.journal));
  EXPECT_FALSE(std::filesystem::exists(paths.partial));

  // --resume on the finished map: nothing to do with the same configuration, refused with
  // the differences for another one.
  sweep::SweepConfig again = config;
  again.resume = true;
  run::Start start = run::Start::fresh;
  EXPECT_EQ(run::preflight(again, paths, &start), "");
  EXPECT_EQ(start, run::Start::already_complete);
  again.identity = {"grid.l = 0.75, 1.25", "run.chunk = 2"};
  const std::string refusal = run::preflight(again, paths, &start);
  EXPECT_NE(refusal.find("the finished map"), std::string::npos) << refusal;
  EXPECT_NE(refusal.find("grid.l: the existing map has 0.75, 1; this run asks for 0.75, 1.25"), std::string::npos)
      << refusal;
}

TEST(MapRun, resume_says_how_many_records_a_damaged_journal_loses) {
  SmallRun r;
  auto& [dir, config, tiling, layout, encoder, attributes, paths] = r;
  std::ostringstream log;
  std::uintmax_t after_first = 0;
  {
    run::MapRun first(config, layout, attributes, run::Start::fresh, tiling, log);
    first.accept(packed_tile(encoder, tiling, 0, 1));
    after_first = std::filesystem::file_size(paths.journal);
    first.accept(packed_tile(encoder, tiling, 1, 1));
    first.accept(packed_tile(encoder, tiling, 2, 1));
    first.interrupt();
  }
  {  // flip a byte inside the second record, past its magic: records 2 and 3 are lost
    std::fstream f(paths.journal, std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(static_cast<std::streamoff>(after_first + 40));
    char c = 0;
    f.read(&c, 1);
    c = static_cast<char>(c ^ 0x5A);
    f.seekp(static_cast<std::streamoff>(after_first + 40));
    f.write(&c, 1);
  }
  std::ostringstream resume_log;
  run::MapRun second(config, layout, attributes, run::Start::resume, tiling, resume_log);
  EXPECT_NE(resume_log.str().find("about 2 tile records) cannot be read; those tiles are computed again"),
            std::string::npos)
      << resume_log.str();
  EXPECT_EQ(second.pending().front(), 1U) << "tiles 1 and 2 are computed again";
  EXPECT_EQ(second.pending().size(), tiling.tiles() - 1);
}

TEST(DiskSpace, the_measured_estimate_is_close_to_the_chunks_the_map_stores_and_refuses_what_cannot_fit) {
  sweep::SweepConfig config = small_config("unused.h5");
  config.grid.axes[kDh].values = {0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.07, 0.08, 0.09, 0.1};
  config.grid.axes[kPbar].values = {0.005, 0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.07};
  config.grid.axes[kT].values = {2.0, 3.0, 5.0, 8.0};
  config.grid.axes[kS].values = {1, 2, 3};
  config.quantities = map::Quantities::full;
  const map::Tiling tiling(config.grid.shape(), 64);
  const io::MapLayout layout = run::map_layout(config, tiling, std::nullopt, 0.0);
  const sweep::TileEvaluator model(config.grid, model::creep_laws().front(), config.C, config.times, config.quantities);
  const run::DiskEstimate estimate = run::estimate_disk(tiling, model, layout, 10.0);
  // Every tile encoded: the bytes the map's chunks really take.
  io::TileEncoder encoder(layout);
  map::TileData data;
  double exact = 0.0;
  for (std::size_t t = 0; t < tiling.tiles(); ++t) {
    model.evaluate(tiling.box(t), &data);
    for (const auto& chunk : encoder.encode(t, tiling.box(t), data).chunks) exact += static_cast<double>(chunk.size());
  }
  EXPECT_NEAR(estimate.map_bytes / exact, 1.0, 0.25) << estimate.map_bytes << " vs " << exact;
  EXPECT_GT(estimate.journal_bytes, estimate.map_bytes);  // the same chunks plus record headers

  const ScratchDir dir;
  const run::OutputPaths paths(dir.file("map.h5"));
  EXPECT_EQ(run::disk_space_problem(paths, estimate), "");
  run::DiskEstimate huge = estimate;
  huge.map_bytes = 1e20;
  const std::string refusal = run::disk_space_problem(paths, huge);
  EXPECT_NE(refusal.find("need about"), std::string::npos) << refusal;
  EXPECT_NE(refusal.find("free"), std::string::npos) << refusal;
}

TEST(ResolveChunk, auto_sizes_for_the_ranks_and_a_resume_keeps_the_size_its_map_started_with) {
  const ScratchDir dir;
  sweep::SweepConfig config = small_config(dir.file("map.h5"));
  // 2 x 3 x 1 x 2 x 1 = 12 points: auto clamps to its floor of 256 values.
  config.chunk = sweep::kAutoChunk;
  config.identity = {"grid.l = 0.75, 1", "run.chunk = auto"};
  run::resolve_chunk(config, run::OutputPaths(config.output), 4);
  EXPECT_EQ(config.chunk, 256U);
  EXPECT_EQ(config.identity[1], "run.chunk = 256");

  // The default grid in full mode: 104328 points x 5 times / (16 ranks x 16) = 2037 values.
  sweep::SweepConfig big;
  big.grid = sls_grid();
  big.grid.axes[kL].values.assign(7, 1.0);
  big.grid.axes[kDh].values.assign(23, 1.0);
  big.grid.axes[kT].values.assign(9, 1.0);
  big.grid.axes[kPbar].values.assign(24, 1.0);
  big.grid.axes[kS].values.assign(3, 1.0);
  EXPECT_EQ(sweep::auto_chunk(big, 16), 2037U);
  EXPECT_EQ(sweep::auto_chunk(big, 1), 4096U);

  // Resuming: the journal's size wins over the rank count.
  io::TileJournal::create(run::OutputPaths(config.output).journal, "grid.l = 0.75, 1\nrun.chunk = 1234");
  config.chunk = sweep::kAutoChunk;
  config.resume = true;
  run::resolve_chunk(config, run::OutputPaths(config.output), 64);
  EXPECT_EQ(config.chunk, 1234U);
  EXPECT_EQ(config.identity[1], "run.chunk = 1234");
  // An explicit size is never touched.
  config.chunk = 77;
  run::resolve_chunk(config, run::OutputPaths(config.output), 64);
  EXPECT_EQ(config.chunk, 77U);
}

// Issue 22: a record whose CRC is right (written through the journal's own append) but
// whose chunk does not inflate was written into the map, which then could not be read
// while the run reported success; a record copied in from another run's journal was
// believed. Both are now refused at replay: they and what follows are computed again, and
// the map that results reads whole.
TEST(MapRun, resume_refuses_records_that_do_not_decode_or_come_from_another_journal) {
  SmallRun r;
  auto& [dir, config, tiling, layout, encoder, attributes, paths] = r;
  std::ostringstream log;
  {
    run::MapRun first(config, layout, attributes, run::Start::fresh, tiling, log);
    first.accept(packed_tile(encoder, tiling, 0, 1));
    first.interrupt();
  }
  {  // tile 1 with its first chunk's deflate stream cut short, appended with a valid CRC
    io::EncodedTile bad = io::unpack_encoded_tile(packed_tile(encoder, tiling, 1, 1).data(),
                                                  packed_tile(encoder, tiling, 1, 1).size());
    bad.chunks[0].resize(bad.chunks[0].size() / 2);
    EXPECT_FALSE(encoder.decodes(bad, tiling.box(1)));
    io::TileJournal journal = io::TileJournal::open_for_append(paths.journal, std::filesystem::file_size(paths.journal));
    journal.append(bad);
    journal.append(io::unpack_encoded_tile(packed_tile(encoder, tiling, 2, 1).data(),
                                           packed_tile(encoder, tiling, 2, 1).size()));
  }
  {
    run::MapRun second(config, layout, attributes, run::Start::resume, tiling, log);
    EXPECT_EQ(second.progress().points_done(), tiling.box(0).points()) << "only tile 0 is trusted";
    EXPECT_EQ(second.pending().front(), 1U);
    for (const std::uint64_t t : second.pending().tiles()) second.accept(packed_tile(encoder, tiling, t, 0));
    second.finish(1);
  }
  EXPECT_NO_THROW(io::read_map_identity(paths.final_path));

  // A journal of another run (another identity in its header): its records fail their CRC
  // in this one, though the bytes are a valid record of the other.
  const std::string other = dir.file("other.journal");
  {
    io::TileJournal journal = io::TileJournal::create(other, "grid.l = 5");
    journal.append(io::unpack_encoded_tile(packed_tile(encoder, tiling, 3, 2).data(),
                                           packed_tile(encoder, tiling, 3, 2).size()));
  }
  std::vector<char> record;
  {
    std::ifstream in(other, std::ios::binary);
    const std::vector<char> all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t header = all.size() - (4 + 8 + packed_tile(encoder, tiling, 3, 2).size() + 4);
    record.assign(all.begin() + static_cast<std::ptrdiff_t>(header), all.end());
  }
  {
    run::MapRun fresh(config, layout, attributes, run::Start::fresh, tiling, log);
    fresh.interrupt();
  }
  {
    std::ofstream out(paths.journal, std::ios::binary | std::ios::app);
    out.write(record.data(), static_cast<std::streamsize>(record.size()));
  }
  std::size_t replayed = 0;
  io::TileJournal::replay(paths.journal, [&](const io::EncodedTile&) { return ++replayed, true; });
  EXPECT_EQ(replayed, 0U) << "a record of another journal was replayed";
  std::size_t in_other = 0;
  io::TileJournal::replay(other, [&](const io::EncodedTile&) { return ++in_other, true; });
  EXPECT_EQ(in_other, 1U);
}

namespace {
// What a Progress prints over 100 tiles of 10 of 1000 points, one after the other at once.
std::string progress_over_a_run(run::Progress::Pace pace, bool quiet) {
  std::ostringstream log;
  run::Progress progress(log, 1000, 0, quiet, pace);
  io::EncodedTile tile;
  tile.summary.points = 10;
  for (int k = 0; k < 100; ++k) progress.computed(tile);
  return log.str();
}
}  // namespace

// Issue 36: progress into a log (a batch job's) is a line each 5% of the points, not one a
// second; the first tile's line says the run has begun.
TEST(Progress, ALogGetsALineEachFivePercent) {
  const std::string log = progress_over_a_run(run::Progress::Pace::log, false);
  std::vector<std::string> lines;
  std::istringstream in(log);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 21U) << log;  // 1% (the first tile), then 5%, 10%, ..., 100%
  EXPECT_NE(lines.front().find("10 / 1000 points (1.0%)"), std::string::npos) << lines.front();
  for (int step = 1; step <= 20; ++step) {
    const std::string done = std::to_string(50 * step) + " / 1000 points";
    EXPECT_NE(lines[static_cast<std::size_t>(step)].find(done), std::string::npos) << lines[static_cast<std::size_t>(step)];
  }
  EXPECT_NE(lines.back().find("ETA"), std::string::npos);
}

TEST(Progress, ATerminalGetsAtMostALineASecond) {
  EXPECT_EQ(progress_over_a_run(run::Progress::Pace::terminal, false), "");  // well within a second
}

TEST(Progress, QuietPrintsNothing) { EXPECT_EQ(progress_over_a_run(run::Progress::Pace::log, true), ""); }
