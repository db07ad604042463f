#include "run/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <thread>

namespace punchsweep::run {
namespace {

/// What the holder wrote into the lock file (one line), or "" if nothing can be read.
std::string holder_of(int fd) {
  char buffer[1024];
  const ssize_t n = ::pread(fd, buffer, sizeof buffer - 1, 0);
  if (n <= 0) return {};
  std::string text(buffer, static_cast<std::size_t>(n));
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  for (char& c : text) {
    if (static_cast<unsigned char>(c) < 0x20) c = ' ';
  }
  return text;
}

std::string holder_line(const std::string& command) {
  char host[256] = "unknown host";
  ::gethostname(host, sizeof host - 1);
  host[sizeof host - 1] = '\0';
  char when[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(when, sizeof when, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return "pid " + std::to_string(::getpid()) + " on " + host + " since " + when + ": " + command + "\n";
}

}  // namespace

std::optional<OutputLock> OutputLock::take(const OutputPaths& paths, const std::string& command,
                                           std::string* refusal) {
  const std::string& path = paths.lock;
  const std::string name = "output.file = " + paths.final_path + ": ";
  // A lock file removed by its holder between our open and our flock is another file than
  // the one at the path: try again (a few times; each round means another run finished).
  for (int attempt = 0; attempt < 8; ++attempt) {
    const int raw = ::open(path.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK, 0644);
    if (raw < 0) {
      // (A missing or read-only folder is run::output_folder_problem's to say, asked first.)
      *refusal = name + (errno == ELOOP ? path + " is a symbolic link; punchsweep writes no file through a link: "
                                                 "remove it or choose another file name"
                                           : "cannot create the lock file " + path + ": " + std::strerror(errno));
      return std::nullopt;
    }
    io::FileDescriptor fd(raw);
    struct stat held {};
    if (::fstat(fd.get(), &held) != 0 || !S_ISREG(held.st_mode)) {
      *refusal = name + path + " is not a regular file; remove it or choose another file name";
      return std::nullopt;
    }
    if (::flock(fd.get(), LOCK_EX | LOCK_NB) != 0) {
      // The holder writes its line just after it takes the lock: give it a moment.
      std::string holder = holder_of(fd.get());
      for (int wait = 0; wait < 50 && holder.empty(); ++wait) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        holder = holder_of(fd.get());
      }
      *refusal = name + "another sweep is writing this map (" + (holder.empty() ? "its lock file is " + path : holder) +
                 "); wait for it to finish or stop it first";
      return std::nullopt;
    }
    struct stat now {};
    if (::lstat(path.c_str(), &now) != 0 || now.st_dev != held.st_dev || now.st_ino != held.st_ino) continue;
    // The holder's line is for messages only: a failure to write it changes nothing else.
    const std::string line = holder_line(command);
    if (::ftruncate(fd.get(), 0) == 0) {
      [[maybe_unused]] const ssize_t written = ::pwrite(fd.get(), line.data(), line.size(), 0);
    }
    return OutputLock(std::move(fd), path);
  }
  *refusal = name + "the lock file " + path + " keeps being replaced by other runs; try again";
  return std::nullopt;
}

OutputLock::~OutputLock() {
  // Unlinked while still held: a run that opened it meanwhile finds, once it has the lock,
  // that the path names another file (or none), and tries again.
  if (fd_.is_open()) ::unlink(path_.c_str());
}

}  // namespace punchsweep::run
