#pragma once

#include <csignal>
#include <functional>
#include <stdexcept>
#include <utility>

namespace punchsweep::model {

/// Thrown by work that gave up on a StopRequest: its result is abandoned, not wrong.
struct Stopped : std::runtime_error {
  Stopped() : std::runtime_error("stopped on request") {}
};

/// A request from outside to give up long work: a stop signal's flag (SIGTERM, SIGINT,
/// SIGUSR1 in a sweep), or a question to ask (the Python module asks the interpreter
/// whether Ctrl-C was pressed). The loops that can run for more than a fraction of a second
/// (a tile's points, the BEM's time steps) check it between their steps, so a stop is
/// honoured within about one step, however long the whole piece of work would be.
class StopRequest {
 public:
  StopRequest() = default;
  explicit StopRequest(const volatile std::sig_atomic_t* flag) : flag_(flag) {}
  explicit StopRequest(std::function<bool()> asked) : asked_(std::move(asked)) {}

  bool requested() const { return (flag_ != nullptr && *flag_ != 0) || (asked_ && asked_()); }
  void throw_if_requested() const {
    if (requested()) throw Stopped();
  }

 private:
  const volatile std::sig_atomic_t* flag_ = nullptr;
  std::function<bool()> asked_;
};

}  // namespace punchsweep::model
