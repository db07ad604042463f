#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "io/encoded_tile.hpp"
#include "io/file_descriptor.hpp"

namespace punchsweep::io {

/// Append-only journal of finished tiles, from which an interrupted sweep resumes. It
/// survives `kill -9` of the writer at any moment: each record goes out in one write()
/// and carries a CRC-32, so a record cut short (or damaged) is detected and ignored,
/// never misread. No fsync: a killed process does not lose the page cache, and a machine
/// crash at worst costs tiles that are then computed again.
///
/// File layout (native endianness), format version 6:
///   header: 8-byte magic "PSJRNL\r\n", u32 format version, u64 text length, the header
///           text (the caller's configuration identity), u32 CRC-32 of all of the above;
///   record: u32 magic "PSRC", u64 payload length, payload (a pack_encoded_tile buffer:
///           the tile as the map stores it, its index included), u32 CRC-32 of the length
///           field and the payload, continued from the header's CRC: a record is bound to
///           the journal (the run identity) it was written into, so one copied from another
///           journal fails its check.
/// (Version 1 records held uncompressed tiles, version 2 tiles without the BEM reference
/// counts, version 3 chunks in the variable order before map::kQuantities, version 4 four
/// validity counts, version 5 records not bound to their header; read_header refuses such
/// journals.)
///
/// Replay stops at the first record that is incomplete, has a wrong magic or a wrong CRC:
/// what follows a damaged record cannot be framed reliably, so it is ignored as well, and
/// open_for_append cuts the file there (those tiles are computed again).
class TileJournal {
 public:
  /// Creates the journal at `path` anew (an existing file or symbolic link there is removed,
  /// never followed) and writes its header.
  /// Throws std::runtime_error naming the path and the system error on failure.
  static TileJournal create(const std::string& path, const std::string& header_text);

  /// The header text of the journal at `path`. Throws std::runtime_error saying whether
  /// the file cannot be read, is not a tile journal, has another format version, or has a
  /// torn or damaged header.
  static std::string read_header(const std::string& path);

  /// Calls `on_tile` for every complete, CRC-valid record in file order, holding one record
  /// in memory at a time, and returns the byte offset just past the last good record.
  /// A record whose CRC is right but whose payload does not unpack, or that `on_tile`
  /// refuses (returns false: its chunks do not decode, its tile is not in the tiling), ends
  /// the replay as a damaged one does: it and what follows are computed again, never
  /// written into a map. Throws like read_header for a bad header.
  static std::size_t replay(const std::string& path, const std::function<bool(const EncodedTile&)>& on_tile);

  /// What lies after the last good record: the bytes that replay could not use and the
  /// records that start among them (the record magics found there, read a block at a time;
  /// at least one, the damaged record itself). open_for_append cuts them; their tiles are computed
  /// again.
  struct Tail {
    std::size_t bytes = 0;
    std::size_t records = 0;
  };
  static Tail inspect_tail(const std::string& path, std::size_t good_end);

  /// Opens an existing journal for appending after `good_end` (what replay returned),
  /// cutting off any torn or damaged tail first. Throws std::runtime_error if the header is
  /// bad or `good_end` lies outside [end of header, end of file].
  static TileJournal open_for_append(const std::string& path, std::size_t good_end);

  /// Appends one record. On a write error the file is cut back to its previous end (so no
  /// half record stays in front of later ones) and std::runtime_error is thrown.
  void append(const EncodedTile& tile);
  /// The same for a tile already packed (pack_encoded_tile's bytes, as they come from the
  /// rank that computed it).
  void append_packed(std::span<const std::byte> payload);

  const std::string& path() const { return path_; }
  /// Bytes in the journal after the last appended record.
  std::size_t size() const { return end_; }

 private:
  TileJournal(FileDescriptor fd, std::string path, std::size_t end, std::uint32_t seed);

  FileDescriptor fd_;
  std::uint32_t seed_ = 0;  ///< the header's CRC, which every record's CRC continues
  std::string path_;
  std::size_t end_ = 0;
  std::vector<std::byte> record_;  ///< reused record buffer
};

}  // namespace punchsweep::io
