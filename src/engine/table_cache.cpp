#include "engine/table_cache.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string_view>
#include <system_error>

#include "io/file_descriptor.hpp"
#include "io/sha256.hpp"

namespace punchsweep::engine {
namespace {

constexpr char kMagic[8] = {'P', 'S', 'W', 'T', 'A', 'B', '0', '2'};
/// No table of the engine comes near this (the largest, s = 3, is about 2 MB).
constexpr std::uint64_t kMaxEntries = std::uint64_t{1} << 24;
constexpr std::size_t kKeyBytes = 32;
constexpr std::size_t kFixedBytes = sizeof kMagic + sizeof(std::uint64_t) + sizeof(io::Digest);

/// What a file's signature covers: the magic, the count and the numbers, as written.
io::Digest signature(const std::string& key, std::uint64_t n, const std::vector<double>& values) {
  return io::hmac_sha256(key, {std::string_view(kMagic, sizeof kMagic),
                               std::string_view(reinterpret_cast<const char*>(&n), sizeof n),
                               std::string_view(reinterpret_cast<const char*>(values.data()), n * sizeof(double))});
}

bool owned_and_private(const struct stat& st) {
  return (st.st_uid == ::geteuid() || st.st_uid == 0) && (st.st_mode & (S_IWGRP | S_IWOTH)) == 0;
}

std::string octal_mode(mode_t mode) {
  char text[8];
  std::snprintf(text, sizeof text, "%04o", static_cast<unsigned>(mode & 07777));
  return text;
}

/// The key in `file`, if it is a private regular file of this user (or root) holding exactly
/// kKeyBytes bytes; else empty.
std::string read_key(const std::filesystem::path& file) {
  const int raw = ::open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (raw < 0) return {};
  const io::FileDescriptor fd(raw);
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0 || !S_ISREG(st.st_mode) || !owned_and_private(st) ||
      (st.st_mode & (S_IRWXG | S_IRWXO)) != 0 || st.st_size != static_cast<off_t>(kKeyBytes)) {
    return {};
  }
  std::string key(kKeyBytes, '\0');
  if (!io::read_fully(fd.get(), key.data(), key.size())) return {};
  return key;
}

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

}  // namespace

TableCacheFolder table_cache_folder() {
  if (const char* set = std::getenv("PUNCHSWEEP_CACHE")) {
    const std::string folder(set);
    const std::string word = lowercase(folder);
    if (word.empty() || word == "off" || word == "0" || word == "false" || word == "no" || word == "none") return {};
    if (folder.front() != '/') {
      return {std::nullopt, "PUNCHSWEEP_CACHE = " + folder +
                                " is not an absolute path (the shell does not expand ~ inside quotes); the table "
                                "cache is not used"};
    }
    return {std::filesystem::path(folder), {}};
  }
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && xdg[0] == '/') {
    return {std::filesystem::path(xdg) / "punchsweep", {}};
  }
  if (const char* home = std::getenv("HOME"); home != nullptr && home[0] == '/') {
    return {std::filesystem::path(home) / ".cache" / "punchsweep", {}};
  }
  return {};
}

std::string untrusted_folder(const std::filesystem::path& folder) {
  struct stat st {};
  if (::lstat(folder.c_str(), &st) != 0) return {};  // created by write_tables, private
  if (S_ISLNK(st.st_mode)) return "the table cache folder " + folder.string() + " is a symbolic link";
  if (!S_ISDIR(st.st_mode)) return "the table cache folder " + folder.string() + " is not a folder";
  if (!owned_and_private(st)) {
    return "the table cache folder " + folder.string() + " (mode " + octal_mode(st.st_mode) + ", owner uid " +
           std::to_string(st.st_uid) + ") can be written by other users, who could bias every result; " +
           "make it yours and private (chmod go-w) to use it";
  }
  const std::filesystem::path key = folder / "key";
  if (::lstat(key.c_str(), &st) == 0 && read_key(key).empty()) {
    return "the table cache's key " + key.string() + " (mode " + octal_mode(st.st_mode) + ", owner uid " +
           std::to_string(st.st_uid) + ", " + std::to_string(st.st_size) +
           " bytes) is not a private file of 32 bytes of yours; remove it (a new one is made) to use the cache";
  }
  return {};
}

std::vector<double> read_tables(const std::filesystem::path& file) {
  const std::string key = cache_key(file.parent_path(), false);
  if (key.empty()) return {};
  const int raw = ::open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (raw < 0) return {};
  const io::FileDescriptor fd(raw);
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0 || !S_ISREG(st.st_mode) || !owned_and_private(st)) return {};
  char magic[8];
  std::uint64_t n = 0;
  if (!io::read_fully(fd.get(), magic, sizeof magic) || std::memcmp(magic, kMagic, sizeof magic) != 0 ||
      !io::read_fully(fd.get(), &n, sizeof n) || n > kMaxEntries ||
      static_cast<std::uint64_t>(st.st_size) != kFixedBytes + n * sizeof(double)) {
    return {};
  }
  std::vector<double> values(n);
  io::Digest stored{};
  char extra = 0;
  if (!io::read_fully(fd.get(), values.data(), n * sizeof(double)) ||
      !io::read_fully(fd.get(), stored.data(), stored.size()) || io::read_fully(fd.get(), &extra, 1)) {
    return {};
  }
  const io::Digest expected = signature(key, n, values);
  unsigned char difference = 0;  // compared in full, not up to the first difference
  for (std::size_t i = 0; i < stored.size(); ++i) difference |= static_cast<unsigned char>(stored[i] ^ expected[i]);
  if (difference != 0) return {};
  return values;
}

std::string cache_key(const std::filesystem::path& folder, bool create) {
  const std::filesystem::path file = folder / "key";
  if (std::string key = read_key(file); !key.empty() || !create) return key;
  if (!make_private_folder(folder)) return {};
  // A new key in a file of its own, linked to its name only if none is there: processes that
  // make one at once end with the same key (link() fails for all but one).
  std::random_device random;
  std::string key(kKeyBytes, '\0');
  for (std::size_t i = 0; i < kKeyBytes; i += 4) {
    const std::uint32_t word = random();
    std::memcpy(key.data() + i, &word, 4);
  }
  std::filesystem::path temporary = file;
  temporary += ".part." + std::to_string(::getpid()) + "." + std::to_string(random());
  const int raw = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (raw < 0) return {};
  bool written = false;
  {
    const io::FileDescriptor fd(raw);
    written = io::write_fully(fd.get(), key.data(), key.size()) && ::fsync(fd.get()) == 0;
  }
  if (written) static_cast<void>(::link(temporary.c_str(), file.c_str()));
  ::unlink(temporary.c_str());
  return read_key(file);
}

bool make_private_folder(const std::filesystem::path& folder) {
  if (::mkdir(folder.c_str(), 0700) != 0 && errno == ENOENT) {
    std::error_code error;
    std::filesystem::create_directories(folder.parent_path(), error);
    ::mkdir(folder.c_str(), 0700);
  }
  return untrusted_folder(folder).empty();
}

void write_tables(const std::filesystem::path& file, const std::vector<double>& tables) {
  if (!make_private_folder(file.parent_path())) return;
  const std::string key = cache_key(file.parent_path(), true);
  if (key.empty()) return;
  std::random_device random;
  std::filesystem::path temporary = file;
  temporary += ".part." + std::to_string(::getpid()) + "." + std::to_string(random());
  const int raw = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (raw < 0) return;
  bool written = false;
  {
    const io::FileDescriptor fd(raw);
    const std::uint64_t n = tables.size();
    const io::Digest signed_by = signature(key, n, tables);
    written = io::write_fully(fd.get(), kMagic, sizeof kMagic) && io::write_fully(fd.get(), &n, sizeof n) &&
              io::write_fully(fd.get(), tables.data(), n * sizeof(double)) &&
              io::write_fully(fd.get(), signed_by.data(), signed_by.size());
  }
  if (!written || ::rename(temporary.c_str(), file.c_str()) != 0) ::unlink(temporary.c_str());
}

FileLock::FileLock(const std::filesystem::path& file)
    : fd_(::open(file.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0600)) {
  if (fd_ >= 0 && ::flock(fd_, LOCK_EX) != 0) {
    ::close(fd_);
    fd_ = -1;
  }
}

FileLock::~FileLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock
}

}  // namespace punchsweep::engine
