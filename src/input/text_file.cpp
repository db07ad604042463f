#include "input/text_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "input/usage_error.hpp"
#include "io/file_descriptor.hpp"

namespace punchsweep::input {

std::string read_text_file(const std::string& path, const std::string& what) {
  const std::string name = what + " " + path;
  if (path.empty()) throw UsageError(what + ": no file name given");
  // O_NONBLOCK: opening a FIFO must not wait for a writer (it is refused below).
  const int raw = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (raw < 0) {
    throw UsageError(name + (errno == ENOENT ? std::string(" does not exist") : ": cannot open the file: " + std::string(std::strerror(errno))));
  }
  const io::FileDescriptor fd(raw);
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0) throw UsageError(name + ": cannot read the file: " + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw UsageError(name + " is a folder, not a file");
  if (!S_ISREG(st.st_mode)) throw UsageError(name + " is not a regular file (a device or a pipe); give a text file");
  if (static_cast<std::size_t>(st.st_size) > kMaxTextFileBytes) {
    throw UsageError(name + " is " + std::to_string(st.st_size) + " bytes; valid: at most " +
                     std::to_string(kMaxTextFileBytes) + " bytes of text");
  }
  std::string text;
  char buffer[65536];
  while (true) {
    const ssize_t n = ::read(fd.get(), buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw UsageError(name + ": cannot read the file: " + std::strerror(errno));
    if (n == 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
    if (text.size() > kMaxTextFileBytes) {
      throw UsageError(name + " grew past " + std::to_string(kMaxTextFileBytes) + " bytes while being read");
    }
  }
  // A UTF-8 byte-order mark (editors on Windows write one) is no part of the first key.
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
  // A binary file would be echoed back line by line: refuse it at its first control byte.
  int line = 1;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') ++line;
    if ((byte < 0x20 && c != '\n' && c != '\r' && c != '\t' && c != '\f' && c != '\v') || byte == 0x7F) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02X", byte);
      throw UsageError(name + ", line " + std::to_string(line) + ": byte " + hex + " is a control character; a " +
                       what + " is INI text");
    }
  }
  return text;
}

}  // namespace punchsweep::input
