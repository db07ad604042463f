#include "io/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "io/file_descriptor.hpp"

namespace punchsweep::io {

namespace {

const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a pipe";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

}  // namespace

std::string output_file_problem(const std::string& path, const std::vector<std::string>& inputs) {
  if (path.empty()) return "the output file name is empty";
  const std::filesystem::path p(path);
  const std::filesystem::path dir = p.has_parent_path() ? p.parent_path() : std::filesystem::path(".");
  struct stat d {};
  if (::stat(dir.c_str(), &d) != 0) return path + ": the folder " + dir.string() + " does not exist";
  if (!S_ISDIR(d.st_mode)) return path + ": " + dir.string() + " is not a folder";
  struct stat s {};
  if (::lstat(path.c_str(), &s) != 0) return {};  // a new file
  if (S_ISLNK(s.st_mode)) {
    return path + " is a symbolic link; punchsweep writes no file through a link: remove it or choose another file name";
  }
  if (!S_ISREG(s.st_mode)) {
    return path + " is " + kind_of(s.st_mode) + ", which a written file would replace; choose another file name";
  }
  for (const std::string& input : inputs) {
    struct stat i {};
    if (!input.empty() && ::stat(input.c_str(), &i) == 0 && i.st_dev == s.st_dev && i.st_ino == s.st_ino) {
      return path + " is the input " + input + ", which writing would destroy; choose another file name";
    }
  }
  return {};
}

void write_file_whole(const std::string& path, const std::string& text, const std::vector<std::string>& inputs) {
  if (std::string problem = output_file_problem(path, inputs); !problem.empty()) throw std::runtime_error(problem);
  const std::string tmp = path + ".tmp-" + std::to_string(::getpid());
  {
    FileDescriptor fd(::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644));
    if (!fd.is_open()) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
    if (!write_fully(fd.get(), text.data(), text.size()) || ::fsync(fd.get()) != 0) {
      const int error = errno;
      ::unlink(tmp.c_str());
      throw std::runtime_error("cannot write " + path + ": " + std::strerror(error));
    }
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(tmp.c_str());
    throw std::runtime_error("cannot write " + path + ": " + std::strerror(error));
  }
}

}  // namespace punchsweep::io
