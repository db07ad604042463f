#include "reference/transform_threads.hpp"

#include <pthread.h>
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <string>

namespace punchsweep::reference {
namespace {

std::atomic<int>& chosen() {
  static std::atomic<int> threads{0};  // 0: not set, the default
  return threads;
}

}  // namespace

int affinity_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) != 0) return 1;
  return std::max(1, CPU_COUNT(&set));
}

int machine_cpus() { return static_cast<int>(std::max(1L, sysconf(_SC_NPROCESSORS_ONLN))); }

namespace {

/// OMP_NUM_THREADS as a positive whole number (OpenMP's list form: its first entry, this
/// level's), else 0.
int omp_num_threads() {
  const char* text = std::getenv("OMP_NUM_THREADS");
  if (text == nullptr) return 0;
  char* end = nullptr;
  const long n = std::strtol(text, &end, 10);
  return end != text && (*end == '\0' || *end == ',') && n >= 1 && n <= 4096 ? static_cast<int>(n) : 0;
}

}  // namespace

int threads_given(int affinity, int machine) {
  if (const int asked = omp_num_threads(); asked > 0) return asked;
  return affinity < machine ? std::max(1, affinity) : 1;
}

int default_transform_threads() { return threads_given(affinity_cpus(), machine_cpus()); }

int transform_threads() {
  const int set = chosen().load(std::memory_order_relaxed);
  if (set > 0) return set;
  static const int fallback = default_transform_threads();
  return fallback;
}

void set_transform_threads(int threads) { chosen().store(std::max(1, threads), std::memory_order_relaxed); }

void one_thread_after_fork() {
  // GNU OpenMP's threads do not survive a fork: a child that enters a parallel region the
  // parent had run waits for them for ever (Python's multiprocessing, measured: a forked
  // pool's first large curve hung). The child's transforms run on its own thread.
  static const bool registered = pthread_atfork(nullptr, nullptr, [] { chosen().store(1, std::memory_order_relaxed); }) == 0;
  (void)registered;
}

}  // namespace punchsweep::reference
