#include "app/table_cache.hpp"

#include <fcntl.h>
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
#include <system_error>

#include "io/file_descriptor.hpp"
#include "app/periodic_tables.hpp"
#include "model/localization/shell_sums.hpp"
#include "sweep/reproducible_fft.hpp"

namespace punchsweep::app {
namespace {

constexpr char kMagic[8] = {'P', 'S', 'W', 'T', 'A', 'B', '0', '1'};
/// No table of the engine comes near this (the largest, s = 3, is about 2 MB).
constexpr std::uint64_t kMaxEntries = std::uint64_t{1} << 24;
constexpr std::size_t kFixedBytes = sizeof kMagic + 2 * sizeof(std::uint64_t);

std::uint64_t fnv1a(const std::vector<double>& values) {
  std::uint64_t hash = 14695981039346656037ull;
  const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
  for (std::size_t i = 0; i < values.size() * sizeof(double); ++i) {
    hash ^= bytes[i];
    hash *= 1099511628211ull;
  }
  return hash;
}

bool owned_and_private(const struct stat& st) {
  return (st.st_uid == ::geteuid() || st.st_uid == 0) && (st.st_mode & (S_IWGRP | S_IWOTH)) == 0;
}

std::string octal_mode(mode_t mode) {
  char text[8];
  std::snprintf(text, sizeof text, "%04o", static_cast<unsigned>(mode & 07777));
  return text;
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
  return {};
}

std::vector<double> read_tables(const std::filesystem::path& file) {
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
  std::uint64_t hash = 0;
  char extra = 0;
  if (!io::read_fully(fd.get(), values.data(), n * sizeof(double)) || !io::read_fully(fd.get(), &hash, sizeof hash) ||
      io::read_fully(fd.get(), &extra, 1) || hash != fnv1a(values)) {
    return {};
  }
  return values;
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
  std::random_device random;
  std::filesystem::path temporary = file;
  temporary += ".part." + std::to_string(::getpid()) + "." + std::to_string(random());
  const int raw = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (raw < 0) return;
  bool written = false;
  {
    const io::FileDescriptor fd(raw);
    const std::uint64_t n = tables.size();
    const std::uint64_t hash = fnv1a(tables);
    written = io::write_fully(fd.get(), kMagic, sizeof kMagic) && io::write_fully(fd.get(), &n, sizeof n) &&
              io::write_fully(fd.get(), tables.data(), n * sizeof(double)) && io::write_fully(fd.get(), &hash, sizeof hash);
  }
  if (!written || ::rename(temporary.c_str(), file.c_str()) != 0) ::unlink(temporary.c_str());
}

void use_table_cache() {
  const TableCacheFolder cache = table_cache_folder();
  std::string refusal = cache.not_used;
  if (cache.folder && refusal.empty()) refusal = untrusted_folder(*cache.folder);
  if (!cache.folder || !refusal.empty()) {
    if (!refusal.empty()) std::fprintf(stderr, "punchsweep: %s; tables are built in memory\n", refusal.c_str());
    model::set_shell_sums_store({});
    model::set_periodic_solution_source([](int s) {
      sweep::use_reproducible_fft_plans();
      return periodic_solution_for(s, std::nullopt);
    });
    return;
  }
  const std::filesystem::path root = *cache.folder;
  model::set_periodic_solution_source([root](int s) {
    sweep::use_reproducible_fft_plans();
    return periodic_solution_for(s, root);
  });
  model::set_shell_sums_store({[root](const std::string& name) { return read_tables(root / name); },
                               [root](const std::string& name, const std::vector<double>& tables) {
                                 write_tables(root / name, tables);
                               }});
}

}  // namespace punchsweep::app
