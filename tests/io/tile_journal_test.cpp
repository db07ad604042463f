#include "io/tile_journal.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "io/crc32.hpp"
#include "sample_tiles.hpp"
#include "scratch_dir.hpp"

namespace punchsweep::io {
namespace {

using namespace testing;
using testing::sample_encoded_tile;
using testing::ScratchDir;

/// Tile `i` of the test journals: index 1000 + i, 13 chunks of a few hundred bytes each
/// (as a small full-quantities tile), all of it depending on i.
EncodedTile tile(std::size_t i) { return sample_encoded_tile(1000 + i, 13, 300); }

std::vector<EncodedTile> replay_all(const std::string& path, std::size_t* good_end = nullptr) {
  std::vector<EncodedTile> records;
  const std::size_t end = TileJournal::replay(path, [&](const EncodedTile& t) {
    records.push_back(t);
    return true;
  });
  if (good_end != nullptr) *good_end = end;
  return records;
}

/// Whether `records` are exactly tiles 0 .. n-1, in order, byte for byte.
void expect_first_tiles(const std::vector<EncodedTile>& records, std::size_t n) {
  ASSERT_EQ(records.size(), n);
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(records[i].tile, 1000 + i);
    EXPECT_TRUE(records[i] == tile(i)) << "record " << i;
  }
}

std::vector<char> read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::string& path, const std::vector<char>& bytes, std::size_t n) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(n));
}

using testing::error_of;

/// Writes tiles 0 .. n-1 and returns the offsets where each record starts (and the end).
std::vector<std::size_t> write_journal(const std::string& path, const std::string& header, std::size_t n) {
  TileJournal journal = TileJournal::create(path, header);
  std::vector<std::size_t> offsets{journal.size()};
  for (std::size_t i = 0; i < n; ++i) {
    journal.append(tile(i));
    offsets.push_back(journal.size());
  }
  return offsets;
}

TEST(TileJournal, journal_replay_streams_records_in_order) {
  const ScratchDir dir;
  const std::string path = dir.file("j");
  const std::vector<std::size_t> offsets = write_journal(path, "identity", 6);
  EXPECT_EQ(std::filesystem::file_size(path), offsets.back());
  std::size_t good_end = 0;
  const auto records = replay_all(path, &good_end);
  expect_first_tiles(records, 6);
  EXPECT_EQ(good_end, offsets.back());
}

TEST(TileJournal, journal_keeps_its_header_text) {
  const ScratchDir dir;
  const std::string text = std::string("grid.l = linspace(0.5, 1.25, 16)\n\0binary\xff tail", 47);
  write_journal(dir.file("j"), text, 2);
  EXPECT_EQ(TileJournal::read_header(dir.file("j")), text);
  write_journal(dir.file("empty"), "", 1);
  EXPECT_EQ(TileJournal::read_header(dir.file("empty")), "");
  expect_first_tiles(replay_all(dir.file("empty")), 1);
}

TEST(TileJournal, journal_without_records_replays_nothing) {
  const ScratchDir dir;
  const std::vector<std::size_t> offsets = write_journal(dir.file("j"), "h", 0);
  std::size_t good_end = 0;
  EXPECT_TRUE(replay_all(dir.file("j"), &good_end).empty());
  EXPECT_EQ(good_end, offsets[0]);
}

TEST(TileJournal, journal_ignores_a_torn_last_record) {
  const ScratchDir dir;
  const std::string full = dir.file("full");
  const std::vector<std::size_t> offsets = write_journal(full, "h", 4);
  const std::vector<char> bytes = read_bytes(full);
  const std::string torn = dir.file("torn");
  // Every length from "the last record's first byte" to "all but its last byte".
  for (std::size_t cut = offsets[3]; cut < offsets[4]; ++cut) {
    write_bytes(torn, bytes, cut);
    std::size_t good_end = 0;
    const auto records = replay_all(torn, &good_end);
    expect_first_tiles(records, 3);
    ASSERT_EQ(good_end, offsets[3]) << "cut at " << cut;
    if (cut % 37 == 0 || cut + 1 == offsets[4]) {  // resuming from a sample of the cuts
      TileJournal journal = TileJournal::open_for_append(torn, good_end);
      journal.append(tile(3));
      expect_first_tiles(replay_all(torn), 4);
      ASSERT_EQ(read_bytes(torn), bytes) << "cut at " << cut;
    }
  }
}

TEST(TileJournal, journal_ignores_a_damaged_record_and_everything_after_it) {
  const ScratchDir dir;
  const std::string path = dir.file("j");
  const std::vector<std::size_t> offsets = write_journal(path, "h", 5);
  const std::vector<char> bytes = read_bytes(path);
  const std::size_t record = offsets[3] - offsets[2];
  // A flipped byte anywhere in record 2 (magic, length, payload or CRC) hides it and 3, 4.
  for (std::size_t at = offsets[2]; at < offsets[3]; at += (at - offsets[2] < 64 ? 1 : record / 40)) {
    std::vector<char> damaged = bytes;
    damaged[at] = static_cast<char>(damaged[at] ^ 0x10);
    write_bytes(path, damaged, damaged.size());
    std::size_t good_end = 0;
    expect_first_tiles(replay_all(path, &good_end), 2);
    ASSERT_EQ(good_end, offsets[2]) << "flipped byte " << at;
  }
  TileJournal journal = TileJournal::open_for_append(path, offsets[2]);
  EXPECT_EQ(std::filesystem::file_size(path), offsets[2]);
  for (std::size_t i = 2; i < 5; ++i) journal.append(tile(i));
  expect_first_tiles(replay_all(path), 5);
}

TEST(TileJournal, journal_survives_kill_9_of_the_writer) {
  const ScratchDir dir;
  const std::string path = dir.file("j");
  // Records of about 2.5 MB, so that kills land inside write() calls as well as between them.
  const auto big = [](std::size_t i) { return sample_encoded_tile(i, 8, 256 * 1024); };
  for (int attempt = 0; attempt < 6; ++attempt) {
    const std::size_t header_end = TileJournal::create(path, "h").size();
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      // The child only appends until it is killed; it must never return into the test runner.
      try {
        TileJournal journal = TileJournal::open_for_append(path, header_end);
        for (std::size_t i = 0; i < 100000; ++i) journal.append(big(i));
      } catch (...) {
        ::_exit(1);
      }
      ::_exit(0);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(3 + 7 * attempt));
    ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the writer ended before it was killed";

    std::size_t count = 0;
    const std::size_t good_end = TileJournal::replay(path, [&](const EncodedTile& t) {
      EXPECT_EQ(t.tile, count);
      EXPECT_TRUE(t == big(count)) << "record " << count;
      ++count;
      return true;
    });
    EXPECT_LE(good_end, std::filesystem::file_size(path));
    TileJournal journal = TileJournal::open_for_append(path, good_end);
    journal.append(big(count));
    std::size_t after = 0;
    TileJournal::replay(path, [&](const EncodedTile& t) {
      EXPECT_EQ(t.tile, after++);
      return true;
    });
    EXPECT_EQ(after, count + 1);
  }
}

TEST(TileJournal, journal_rejects_a_file_that_is_not_a_journal) {
  const ScratchDir dir;
  const std::string path = dir.file("garbage");
  write_bytes(path, std::vector<char>(100, 'x'), 100);
  EXPECT_NE(error_of([&] { TileJournal::read_header(path); }).find("is not a punchsweep tile journal"),
            std::string::npos);
  EXPECT_THROW(TileJournal::replay(path, [](const EncodedTile&) { return true; }), std::runtime_error);
  EXPECT_THROW(TileJournal::open_for_append(path, 100), std::runtime_error);
  write_bytes(path, {}, 0);
  EXPECT_NE(error_of([&] { TileJournal::read_header(path); }).find("is empty"), std::string::npos);
  EXPECT_NE(error_of([&] { TileJournal::read_header(dir.file("missing")); }).find("cannot open"),
            std::string::npos);
}

TEST(TileJournal, journal_rejects_a_torn_or_damaged_header) {
  const ScratchDir dir;
  const std::string path = dir.file("j");
  const std::vector<std::size_t> offsets = write_journal(path, "the configuration identity", 1);
  const std::vector<char> bytes = read_bytes(path);
  const std::string cut = dir.file("cut");
  for (std::size_t n = 1; n < offsets[0]; ++n) {
    write_bytes(cut, bytes, n);
    const std::string message = error_of([&] { TileJournal::read_header(cut); });
    EXPECT_NE(message.find("torn"), std::string::npos) << "cut at " << n << ": " << message;
  }
  for (std::size_t at = 8; at < offsets[0]; ++at) {  // past the magic: version, length, text, CRC
    std::vector<char> damaged = bytes;
    damaged[at] = static_cast<char>(damaged[at] ^ 0x04);
    write_bytes(cut, damaged, damaged.size());
    EXPECT_THROW(TileJournal::read_header(cut), std::runtime_error) << "flipped byte " << at;
  }
  std::vector<char> damaged = bytes;
  damaged[20] = static_cast<char>(damaged[20] ^ 0x04);  // inside the text
  write_bytes(cut, damaged, damaged.size());
  EXPECT_NE(error_of([&] { TileJournal::read_header(cut); }).find("damaged header"), std::string::npos);
}

TEST(TileJournal, journal_refuses_to_append_outside_its_records) {
  const ScratchDir dir;
  const std::string path = dir.file("j");
  const std::vector<std::size_t> offsets = write_journal(path, "h", 2);
  EXPECT_THROW(TileJournal::open_for_append(path, offsets[0] - 1), std::runtime_error);
  EXPECT_THROW(TileJournal::open_for_append(path, offsets[2] + 1), std::runtime_error);
  expect_first_tiles(replay_all(path), 2);
}

TEST(TileJournal, journal_create_truncates_an_old_journal) {
  const ScratchDir dir;
  const std::string path = dir.file("j");
  write_journal(path, "old", 3);
  write_journal(path, "new", 1);
  EXPECT_EQ(TileJournal::read_header(path), "new");
  expect_first_tiles(replay_all(path), 1);
}

TEST(TileJournal, journal_of_an_older_format_version_is_refused) {
  // Version 1 records held uncompressed tiles, version 2 tiles without the BEM counts,
  // version 3 chunks in the old variable order, version 4 four validity counts, version 5
  // records not bound to their header; none must be misread as version 6.
  for (const std::uint32_t version : {1U, 2U, 3U, 4U, 5U}) {
    const ScratchDir dir;
    const std::string path = dir.file("j");
    write_journal(path, "h", 1);
    std::vector<char> bytes = read_bytes(path);
    std::memcpy(bytes.data() + 8, &version, sizeof version);
    write_bytes(path, bytes, bytes.size());
    EXPECT_NE(error_of([&] {
                TileJournal::read_header(path);
              }).find("format version " + std::to_string(version) + ", this program reads version 6"),
              std::string::npos);
  }
}

TEST(TileJournal, a_record_that_passes_its_crc_but_does_not_decode_ends_the_replay) {
  // Issue 22: such a record (as another program would write) was trusted as far as its
  // framing went; now it is treated like a damaged one: the replay stops before it, and
  // open_for_append cuts it, so its tile and every later one are computed again.
  const ScratchDir dir;
  const std::string path = dir.file("j");
  const std::vector<std::size_t> offsets = write_journal(path, "h", 2);
  std::vector<char> bytes = read_bytes(path);
  const std::vector<char> payload(100, 'x');
  const auto put = [&](const void* p, std::size_t n) {
    bytes.insert(bytes.end(), static_cast<const char*>(p), static_cast<const char*>(p) + n);
  };
  // The header's CRC, which a record's CRC continues: its last four bytes before offsets[0].
  std::uint32_t seed = 0;
  std::memcpy(&seed, bytes.data() + offsets[0] - 4, sizeof seed);
  const std::uint32_t magic = 0x43525350;  // "PSRC"
  const std::uint64_t length = payload.size();
  put(&magic, sizeof magic);
  const std::size_t framed_from = bytes.size();
  put(&length, sizeof length);
  put(payload.data(), payload.size());
  const std::uint32_t crc = crc32(bytes.data() + framed_from, bytes.size() - framed_from, seed);
  put(&crc, sizeof crc);
  write_bytes(path, bytes, bytes.size());
  std::size_t replayed = 0;
  const std::size_t good_end = TileJournal::replay(path, [&](const EncodedTile&) { return ++replayed, true; });
  EXPECT_EQ(replayed, 2U);
  EXPECT_EQ(good_end, offsets[2]);
  // And a record the caller refuses (its chunks do not decode to its box) ends it too.
  replayed = 0;
  EXPECT_EQ(TileJournal::replay(path, [&](const EncodedTile& t) { return ++replayed, t.tile == 1000; }), offsets[1]);
}

}  // namespace
}  // namespace punchsweep::io
