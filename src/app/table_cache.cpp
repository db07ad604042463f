#include "app/table_cache.hpp"

#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <system_error>

#include "model/shell_sums.hpp"

namespace punchsweep::app {
namespace {

constexpr char kMagic[8] = {'P', 'S', 'W', 'T', 'A', 'B', '0', '1'};

std::uint64_t fnv1a(const std::vector<double>& values) {
  std::uint64_t hash = 14695981039346656037ull;
  const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
  for (std::size_t i = 0; i < values.size() * sizeof(double); ++i) {
    hash ^= bytes[i];
    hash *= 1099511628211ull;
  }
  return hash;
}

}  // namespace

std::optional<std::filesystem::path> table_cache_folder() {
  if (const char* set = std::getenv("PUNCHSWEEP_CACHE")) {
    const std::string folder(set);
    if (folder.empty() || folder == "off") return std::nullopt;
    return std::filesystem::path(folder);
  }
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg != '\0') {
    return std::filesystem::path(xdg) / "punchsweep";
  }
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
    return std::filesystem::path(home) / ".cache" / "punchsweep";
  }
  return std::nullopt;
}

std::vector<double> read_tables(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  char magic[8];
  std::uint64_t n = 0;
  if (!in.read(magic, sizeof magic) || std::memcmp(magic, kMagic, sizeof magic) != 0 ||
      !in.read(reinterpret_cast<char*>(&n), sizeof n) || n > (std::uint64_t{1} << 28)) {
    return {};
  }
  std::vector<double> values(n);
  std::uint64_t hash = 0;
  if (!in.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(n * sizeof(double))) ||
      !in.read(reinterpret_cast<char*>(&hash), sizeof hash) || in.peek() != std::ifstream::traits_type::eof() ||
      hash != fnv1a(values)) {
    return {};
  }
  return values;
}

void write_tables(const std::filesystem::path& file, const std::vector<double>& tables) {
  std::error_code error;
  std::filesystem::create_directories(file.parent_path(), error);
  std::random_device random;
  std::filesystem::path temporary = file;
  temporary += ".part." + std::to_string(::getpid()) + "." + std::to_string(random());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    const std::uint64_t n = tables.size();
    const std::uint64_t hash = fnv1a(tables);
    out.write(kMagic, sizeof kMagic);
    out.write(reinterpret_cast<const char*>(&n), sizeof n);
    out.write(reinterpret_cast<const char*>(tables.data()), static_cast<std::streamsize>(n * sizeof(double)));
    out.write(reinterpret_cast<const char*>(&hash), sizeof hash);
    if (!out.flush()) {
      out.close();
      std::filesystem::remove(temporary, error);
      return;
    }
  }
  std::filesystem::rename(temporary, file, error);
  if (error) std::filesystem::remove(temporary, error);
}

void use_table_cache() {
  const std::optional<std::filesystem::path> folder = table_cache_folder();
  if (!folder) {
    model::set_shell_sums_store({});
    return;
  }
  const std::filesystem::path root = *folder;
  model::set_shell_sums_store({[root](const std::string& name) { return read_tables(root / name); },
                               [root](const std::string& name, const std::vector<double>& tables) {
                                 write_tables(root / name, tables);
                               }});
}

}  // namespace punchsweep::app
