#include "sweep/scheduler.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <thread>
#include <cstdint>
#include <deque>
#include <stdexcept>
#include <utility>

namespace punchsweep::sweep {
namespace {

enum Tag : int { kTagWork = 1, kTagStop = 2, kTagResult = 3, kTagDone = 4, kTagStopRequest = 5 };
constexpr int kBatchesInFlight = 2;
constexpr std::uint64_t kMaxBatch = 256;  // tiles in one batch at most

void check(int status, const char* what) {
  if (status != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

/// A worker's results in transit to the manager, oldest first. The manager takes results
/// only between tiles of its own, so a worker that waited for each send to finish before
/// the next tile would idle for up to a tile's time per tile; instead every tile gets its
/// own buffer. There are never more than the tiles handed to the worker (two batches).
class Outbox {
 public:
  void send(std::vector<std::byte> bytes, MPI_Comm comm) {
    sends_.push_back({std::move(bytes), MPI_REQUEST_NULL});
    Send& s = sends_.back();
    check(MPI_Isend(s.bytes.data(), static_cast<int>(s.bytes.size()), MPI_BYTE, 0, kTagResult, comm, &s.request),
          "send result");
  }
  /// Frees the buffers of the sends that have finished (and lets MPI progress the others).
  void release_finished() {
    while (!sends_.empty()) {
      int finished = 0;
      check(MPI_Test(&sends_.front().request, &finished, MPI_STATUS_IGNORE), "test send");
      if (!finished) return;
      sends_.pop_front();
    }
  }
  void wait_all() {
    for (Send& s : sends_) check(MPI_Wait(&s.request, MPI_STATUS_IGNORE), "wait send");
    sends_.clear();
  }

 private:
  struct Send {
    std::vector<std::byte> bytes;
    MPI_Request request;
  };
  std::deque<Send> sends_;
};

/// Worker side: computes and encodes the tiles it is sent, one result message per tile,
/// until told to stop. A stop signal to this rank (`*signalled`) is passed on to the
/// manager, which stops the whole sweep; the worker starts no further tile meanwhile.
void work(MPI_Comm comm, const TileWork& compute, const volatile std::sig_atomic_t* signalled) {
  TileRanges pending;
  bool stop = false;
  bool requested = false;
  Outbox outbox;
  while (!stop) {
    if (*signalled && !requested) {
      const int signal = static_cast<int>(*signalled);
      check(MPI_Send(&signal, 1, MPI_INT, 0, kTagStopRequest, comm), "send stop request");
      requested = true;
    }
    // Wait only when there is nothing to compute, polling so that a signal is noticed.
    int flag = 0;
    MPI_Status status;
    check(MPI_Iprobe(0, MPI_ANY_TAG, comm, &flag, &status), "iprobe");
    if (!flag && (pending.empty() || requested)) {
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      continue;
    }
    while (flag) {
      int count = 0;
      MPI_Get_count(&status, MPI_UINT64_T, &count);
      std::vector<std::uint64_t> message(static_cast<std::size_t>(count));
      check(MPI_Recv(message.data(), count, MPI_UINT64_T, 0, status.MPI_TAG, comm, MPI_STATUS_IGNORE), "recv work");
      if (status.MPI_TAG == kTagStop) stop = true;
      else pending.add_flat(message);
      check(MPI_Iprobe(0, MPI_ANY_TAG, comm, &flag, &status), "iprobe");
    }
    if (stop || requested || pending.empty()) continue;
    std::vector<std::byte> result = compute(pending.pop_front());
    if (result.empty()) continue;  // given up on a stop signal: the loop's top reports it
    outbox.send(std::move(result), comm);
    outbox.release_finished();
  }
  outbox.wait_all();
  check(MPI_Send(nullptr, 0, MPI_BYTE, 0, kTagDone, comm), "send done");
}

class Manager {
 public:
  Manager(MPI_Comm comm, int ranks, const TileWork& compute, const TileRanges& pending, const TileSink& sink, Pace pace)
      : comm_(comm), ranks_(ranks),
        in_flight_(pace == Pace::tiles ? kBatchesInFlight : pace == Pace::readings ? 2 : 1), pace_(pace), compute_(compute),
        sink_(sink), queue_(pending),
        outstanding_(static_cast<std::size_t>(ranks), 0), to_do_(pending.size()) {}

  ScheduleResult run(const volatile std::sig_atomic_t* stop) {
    // (Readings: one each at first, the long first units spread over the ranks.)
    for (int w = 1; w < ranks_; ++w) {
      for (int b = 0; b < (pace_ == Pace::readings ? 1 : in_flight_); ++b) send_batch(w);
    }
    while (true) {
      if (*stop && result_.stop_signal == 0) {  // a signal to rank 0 (a worker's is taken in drain_results)
        result_.stop_signal = static_cast<int>(*stop);
        result_.stop_rank = 0;
      }
      if (result_.stop_signal != 0 && !stopping_) begin_stop();
      drain_results(false);
      if (!stopping_ && !queue_.empty()) {
        compute_one();
        continue;
      }
      if (!stopping_ && total_outstanding() == 0) begin_stop();  // every tile is done: release workers
      if (stopping_ && done_ == ranks_ - 1) break;
      drain_results(true);
    }
    result_.interrupted = result_.tiles_done < to_do_;
    return result_;
  }

 private:
  std::size_t total_outstanding() const {
    std::size_t n = 0;
    for (const std::size_t o : outstanding_) n += o;
    return n;
  }

  // Guided size: large batches early (at most kMaxBatch, so no message and no worker's
  // backlog grows with the grid), single tiles at the end.
  std::size_t guided_size() const {
    if (pace_ != Pace::tiles) return 1;
    const std::uint64_t size = queue_.size() / (4 * static_cast<std::uint64_t>(ranks_));
    return static_cast<std::size_t>(std::clamp<std::uint64_t>(size, 1, kMaxBatch));
  }

  void send_batch(int worker) {
    if (queue_.empty() || stopping_) return;
    const TileRanges batch = queue_.take(guided_size());
    const std::vector<std::uint64_t> message = batch.flat();  // [first, last) pairs
    check(MPI_Send(message.data(), static_cast<int>(message.size()), MPI_UINT64_T, worker, kTagWork, comm_),
          "send work");
    outstanding_[static_cast<std::size_t>(worker)] += batch.size();
  }

  void begin_stop() {
    stopping_ = true;
    for (int w = 1; w < ranks_; ++w) {
      check(MPI_Send(nullptr, 0, MPI_UINT64_T, w, kTagStop, comm_), "send stop");
    }
  }

  void compute_one() {
    const std::vector<std::byte> result = compute_(queue_.pop_front());
    if (result.empty()) return;  // given up on a stop signal (run() takes the signal next)
    sink_(result);
    ++result_.tiles_done;
  }

  // Receives results (blocking for one message if `wait`), refilling each worker's batches.
  void drain_results(bool wait) {
    while (true) {
      int flag = 0;
      MPI_Status status;
      if (wait) {
        check(MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, comm_, &status), "probe");
        flag = 1;
        wait = false;
      } else {
        check(MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, comm_, &flag, &status), "iprobe");
      }
      if (!flag) return;
      const int worker = status.MPI_SOURCE;
      int count = 0;
      MPI_Get_count(&status, MPI_BYTE, &count);
      buffer_.resize(static_cast<std::size_t>(count));
      check(MPI_Recv(buffer_.data(), count, MPI_BYTE, worker, status.MPI_TAG, comm_, MPI_STATUS_IGNORE), "recv result");
      if (status.MPI_TAG == kTagDone) {
        ++done_;
        continue;
      }
      if (status.MPI_TAG == kTagStopRequest) {
        if (result_.stop_signal == 0) {
          std::memcpy(&result_.stop_signal, buffer_.data(), sizeof(int));
          result_.stop_rank = worker;
        }
        continue;
      }
      sink_(buffer_);
      ++result_.tiles_done;
      // Keep about two batches of work queued at the worker, so it never waits for us.
      auto& out = outstanding_[static_cast<std::size_t>(worker)];
      --out;
      while (!stopping_ && !queue_.empty() && out < static_cast<std::size_t>(in_flight_) * guided_size()) send_batch(worker);
    }
  }

  MPI_Comm comm_;
  int ranks_;
  int in_flight_;  ///< batches queued at each worker
  Pace pace_;
  const TileWork& compute_;
  const TileSink& sink_;
  TileRanges queue_;
  std::vector<std::size_t> outstanding_;
  std::size_t to_do_;
  bool stopping_ = false;
  int done_ = 0;
  std::vector<std::byte> buffer_;
  ScheduleResult result_;
};

}  // namespace

ScheduleResult run_schedule(MPI_Comm comm, const TileRanges& pending, const TileWork& work_on,
                            const TileSink& sink, const volatile std::sig_atomic_t* stop, Pace pace) {
  int rank = 0;
  int ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  if (rank != 0) {
    work(comm, work_on, stop);
    return {};
  }
  return Manager(comm, ranks, work_on, pending, sink, pace).run(stop);
}

}  // namespace punchsweep::sweep
