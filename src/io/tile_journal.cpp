#include "io/tile_journal.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <utility>

#include "io/crc32.hpp"

namespace punchsweep::io {

namespace {

constexpr std::array<char, 8> kFileMagic{'P', 'S', 'J', 'R', 'N', 'L', '\r', '\n'};
// 2: records hold encoded tiles; 3: their summaries carry the BEM reference counts
constexpr std::uint32_t kFormatVersion = 6;
constexpr std::uint32_t kRecordMagic = 0x43525350;  // "PSRC" read as little-endian bytes
constexpr std::size_t kHeaderFixed = kFileMagic.size() + sizeof(std::uint32_t) + sizeof(std::uint64_t);
constexpr std::size_t kRecordHead = sizeof(std::uint32_t) + sizeof(std::uint64_t);
constexpr std::size_t kCrcSize = sizeof(std::uint32_t);
// Payloads above this are CRC-checked in pieces before any buffer is sized for them, so a
// damaged length field cannot make replay allocate the rest of a many-GB file.
constexpr std::size_t kVerifyInPiecesAbove = std::size_t{64} << 20;
constexpr std::size_t kPiece = std::size_t{1} << 20;

std::runtime_error system_error(const std::string& what, const std::string& path) {
  return std::runtime_error("tile journal " + path + ": " + what + ": " + std::strerror(errno));
}

/// Reads exactly `size` bytes at `offset`; false if the file ends first.
bool read_at(int fd, void* out, std::size_t size, std::uint64_t offset, const std::string& path) {
  auto* p = static_cast<char*>(out);
  while (size > 0) {
    const ssize_t n = ::pread(fd, p, size, static_cast<off_t>(offset));
    if (n < 0) {
      if (errno == EINTR) continue;
      throw system_error("read failed", path);
    }
    if (n == 0) return false;
    p += n;
    size -= static_cast<std::size_t>(n);
    offset += static_cast<std::uint64_t>(n);
  }
  return true;
}

void write_all(int fd, const std::byte* bytes, std::size_t size, const std::string& path) {
  if (!write_fully(fd, bytes, size)) throw system_error("write failed", path);
}

/// Never through a symbolic link (O_NOFOLLOW): a link planted at the journal's name would
/// have the run write, or cut, the file it points to.
FileDescriptor open_file(const std::string& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC | O_NOFOLLOW, 0666);
  if (fd < 0) {
    if (errno == ELOOP) throw std::runtime_error("tile journal " + path + " is a symbolic link, which punchsweep does not follow");
    throw system_error("cannot open", path);
  }
  return FileDescriptor(fd);
}

std::uint64_t file_size(int fd, const std::string& path) {
  struct stat st {};
  if (::fstat(fd, &st) != 0) throw system_error("cannot stat", path);
  return static_cast<std::uint64_t>(st.st_size);
}

template <typename T>
void append_bytes(std::vector<std::byte>* out, const T& value) {
  const auto* p = reinterpret_cast<const std::byte*>(&value);
  out->insert(out->end(), p, p + sizeof(T));
}

template <typename T>
T load(const std::byte* p) {
  T value;
  std::memcpy(&value, p, sizeof(T));
  return value;
}

struct Header {
  std::string text;
  std::uint64_t end = 0;  ///< offset of the first record
  std::uint32_t crc = 0;  ///< the header's CRC, which every record's CRC continues
};

Header parse_header(int fd, const std::string& path) {
  const std::uint64_t size = file_size(fd, path);
  std::array<std::byte, kHeaderFixed> fixed{};
  const auto have = static_cast<std::size_t>(std::min<std::uint64_t>(size, fixed.size()));
  if (!read_at(fd, fixed.data(), have, 0, path)) {
    throw std::runtime_error("tile journal " + path + " changed size while being read");
  }
  if (size == 0) {
    throw std::runtime_error("tile journal " + path +
                             " is empty (not a tile journal, or its creation was cut short)");
  }
  // A create() killed early leaves a prefix of the magic: torn, rather than a foreign file.
  if (std::memcmp(fixed.data(), kFileMagic.data(), std::min(have, kFileMagic.size())) != 0) {
    throw std::runtime_error(path +
                             " is not a punchsweep tile journal (its first bytes are not the journal magic)");
  }
  if (have < kHeaderFixed)
    throw std::runtime_error("tile journal " + path + " has a torn header (the file ends inside it)");
  const auto version = load<std::uint32_t>(fixed.data() + kFileMagic.size());
  if (version != kFormatVersion) {
    throw std::runtime_error("tile journal " + path + " has format version " + std::to_string(version) +
                             ", this program reads version " + std::to_string(kFormatVersion));
  }
  const auto length = load<std::uint64_t>(fixed.data() + kFileMagic.size() + sizeof(std::uint32_t));
  if (length > size - kHeaderFixed || size - kHeaderFixed - length < kCrcSize) {
    throw std::runtime_error("tile journal " + path + " has a torn or damaged header (its text length " +
                             std::to_string(length) + " runs past the end of the file)");
  }
  Header header;
  header.text.resize(static_cast<std::size_t>(length));
  std::uint32_t stored_crc = 0;
  if (!read_at(fd, header.text.data(), header.text.size(), kHeaderFixed, path) ||
      !read_at(fd, &stored_crc, kCrcSize, kHeaderFixed + length, path)) {
    throw std::runtime_error("tile journal " + path + " changed size while being read");
  }
  const std::uint32_t crc = crc32(header.text.data(), header.text.size(), crc32(fixed.data(), fixed.size()));
  if (crc != stored_crc)
    throw std::runtime_error("tile journal " + path + " has a damaged header (CRC mismatch)");
  header.end = kHeaderFixed + length + kCrcSize;
  header.crc = crc;
  return header;
}

/// Whether a record's length field and payload match `stored`, read piecewise from the file.
bool crc_matches_in_pieces(int fd, std::uint64_t length_field_at, std::uint64_t length, std::uint32_t stored,
                           std::uint32_t seed, const std::string& path) {
  std::vector<std::byte> piece(kPiece);
  std::uint64_t at = length_field_at;
  std::uint64_t left = sizeof(std::uint64_t) + length;
  std::uint32_t crc = seed;
  while (left > 0) {
    const auto n = static_cast<std::size_t>(std::min<std::uint64_t>(left, piece.size()));
    if (!read_at(fd, piece.data(), n, at, path)) return false;
    crc = crc32(piece.data(), n, crc);
    at += n;
    left -= n;
  }
  return crc == stored;
}

}  // namespace

TileJournal::TileJournal(FileDescriptor fd, std::string path, std::size_t end, std::uint32_t seed)
    : fd_(std::move(fd)), seed_(seed), path_(std::move(path)), end_(end) {}

TileJournal TileJournal::create(const std::string& path, const std::string& header_text) {
  // A new file: whatever was at the path is removed (not followed, not truncated under a
  // reader), and O_EXCL refuses anything planted there meanwhile.
  if (::unlink(path.c_str()) != 0 && errno != ENOENT) throw system_error("cannot replace", path);
  FileDescriptor fd = open_file(path, O_WRONLY | O_CREAT | O_EXCL);
  std::vector<std::byte> header;
  header.reserve(kHeaderFixed + header_text.size() + kCrcSize);
  for (const char c : kFileMagic) header.push_back(static_cast<std::byte>(c));
  append_bytes(&header, kFormatVersion);
  append_bytes(&header, static_cast<std::uint64_t>(header_text.size()));
  const auto* text = reinterpret_cast<const std::byte*>(header_text.data());
  header.insert(header.end(), text, text + header_text.size());
  const std::uint32_t crc = crc32(header.data(), header.size());
  append_bytes(&header, crc);
  write_all(fd.get(), header.data(), header.size(), path);
  return TileJournal(std::move(fd), path, header.size(), crc);
}

std::string TileJournal::read_header(const std::string& path) {
  const FileDescriptor fd = open_file(path, O_RDONLY);
  return parse_header(fd.get(), path).text;
}

std::size_t TileJournal::replay(const std::string& path,
                                const std::function<bool(const EncodedTile&)>& on_tile) {
  const FileDescriptor fd = open_file(path, O_RDONLY);
  const Header header = parse_header(fd.get(), path);
  std::uint64_t at = header.end;
  const std::uint64_t size = file_size(fd.get(), path);
  std::vector<std::byte> buffer;  // length field + payload + CRC of the current record
  while (size - at >= kRecordHead + kCrcSize) {
    std::array<std::byte, kRecordHead> head{};
    if (!read_at(fd.get(), head.data(), head.size(), at, path)) break;
    if (load<std::uint32_t>(head.data()) != kRecordMagic) break;
    const auto length = load<std::uint64_t>(head.data() + sizeof(std::uint32_t));
    if (length > size - at - kRecordHead - kCrcSize) break;  // torn: the file ends inside it
    const std::uint64_t length_at = at + sizeof(std::uint32_t);
    if (length > kVerifyInPiecesAbove) {
      std::uint32_t stored = 0;
      if (!read_at(fd.get(), &stored, kCrcSize, at + kRecordHead + length, path)) break;
      if (!crc_matches_in_pieces(fd.get(), length_at, length, stored, header.crc, path)) break;
    }
    buffer.resize(sizeof(std::uint64_t) + static_cast<std::size_t>(length) + kCrcSize);
    if (!read_at(fd.get(), buffer.data(), buffer.size(), length_at, path)) break;
    const std::size_t checked = buffer.size() - kCrcSize;
    if (crc32(buffer.data(), checked, header.crc) != load<std::uint32_t>(buffer.data() + checked)) break;
    EncodedTile tile;
    try {
      tile = unpack_encoded_tile(buffer.data() + sizeof(std::uint64_t), static_cast<std::size_t>(length));
    } catch (const std::runtime_error&) {
      break;  // passes its CRC but does not unpack: not to be trusted, like a damaged record
    }
    if (!on_tile(tile)) break;
    at += kRecordHead + length + kCrcSize;
  }
  return static_cast<std::size_t>(at);
}

TileJournal TileJournal::open_for_append(const std::string& path, std::size_t good_end) {
  FileDescriptor fd = open_file(path, O_RDWR | O_APPEND);
  const Header header = parse_header(fd.get(), path);
  const std::uint64_t header_end = header.end;
  const std::uint64_t size = file_size(fd.get(), path);
  if (good_end < header_end || good_end > size) {
    throw std::runtime_error("tile journal " + path + ": resume offset " + std::to_string(good_end) +
                             " lies outside [" + std::to_string(header_end) + ", " + std::to_string(size) +
                             "]");
  }
  if (::ftruncate(fd.get(), static_cast<off_t>(good_end)) != 0)
    throw system_error("cannot cut the torn tail", path);
  return TileJournal(std::move(fd), path, good_end, header.crc);
}

void TileJournal::append(const EncodedTile& tile) { append_packed(pack_encoded_tile(tile)); }

void TileJournal::append_packed(std::span<const std::byte> payload) {
  if (!fd_.is_open()) throw std::logic_error("tile journal " + path_ + " is not open");
  record_.clear();
  record_.reserve(kRecordHead + payload.size() + kCrcSize);
  append_bytes(&record_, kRecordMagic);
  append_bytes(&record_, static_cast<std::uint64_t>(payload.size()));
  record_.insert(record_.end(), payload.begin(), payload.end());
  append_bytes(&record_,
               crc32(record_.data() + sizeof(std::uint32_t), record_.size() - sizeof(std::uint32_t), seed_));
  try {
    write_all(fd_.get(), record_.data(), record_.size(), path_);
  } catch (const std::runtime_error&) {
    // A half-written record would hide every later one from replay, so take it back.
    // If even this fails, replay still stops safely at the torn record.
    [[maybe_unused]] const int cut = ::ftruncate(fd_.get(), static_cast<off_t>(end_));
    throw;
  }
  end_ += record_.size();
}

TileJournal::Tail TileJournal::inspect_tail(const std::string& path, std::size_t good_end) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("tile journal " + path + " cannot be read");
  in.seekg(0, std::ios::end);
  const auto size = static_cast<std::size_t>(in.tellg());
  Tail tail;
  if (good_end >= size) return tail;
  tail.bytes = size - good_end;
  // Read in blocks (a tail can be most of a large journal), each overlapping the last by
  // three bytes so that a magic across a block boundary is seen once.
  constexpr std::size_t kBlock = std::size_t{1} << 20;
  constexpr std::size_t kOverlap = sizeof(std::uint32_t) - 1;
  std::vector<std::byte> block(kBlock + kOverlap);
  std::size_t carried = 0;
  in.seekg(static_cast<std::streamoff>(good_end));
  for (std::size_t left = tail.bytes; left > 0;) {
    const std::size_t n = std::min(kBlock, left);
    in.read(reinterpret_cast<char*>(block.data() + carried), static_cast<std::streamsize>(n));
    left -= n;
    const std::size_t have = carried + n;
    for (std::size_t at = 0; at + sizeof(std::uint32_t) <= have; ++at) {
      if (load<std::uint32_t>(block.data() + at) == kRecordMagic) ++tail.records;
    }
    carried = std::min(kOverlap, have);
    std::memmove(block.data(), block.data() + have - carried, carried);
  }
  if (tail.records == 0) tail.records = 1;  // the damaged record itself
  return tail;
}

}  // namespace punchsweep::io
