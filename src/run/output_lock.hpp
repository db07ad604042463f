#pragma once

#include <optional>
#include <string>

#include "io/file_descriptor.hpp"
#include "run/preflight.hpp"

namespace punchsweep::run {

/// A run's exclusive claim on a map's name: an advisory lock (flock) on OutputPaths::lock,
/// a file of its own that holds the holder's pid, host, start time and command. It is
/// taken before any of the map's files is looked at or touched, and held until the run
/// ends; the kernel releases it when the holder dies, however it dies (kill -9 included),
/// so a stale lock file never blocks a later run.
class OutputLock {
 public:
  /// Takes the lock for `paths`, or returns nothing and sets *refusal to one line naming
  /// the running holder (or why the lock file cannot be used: a symbolic link, not a
  /// regular file, a folder that cannot be written). `command`, with this process's pid,
  /// host and the time, goes into the lock file for another run's refusal to name.
  static std::optional<OutputLock> take(const OutputPaths& paths, const std::string& command, std::string* refusal);

  /// Removes the lock file (a stale one that a killed run left included) and releases the
  /// lock.
  ~OutputLock();
  OutputLock(OutputLock&& other) noexcept = default;
  OutputLock& operator=(OutputLock&&) = delete;
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

 private:
  OutputLock(io::FileDescriptor fd, std::string path) : fd_(std::move(fd)), path_(std::move(path)) {}
  io::FileDescriptor fd_;
  std::string path_;
};

}  // namespace punchsweep::run
