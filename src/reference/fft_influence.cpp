#include "reference/fft_influence.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <new>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace punchsweep::reference {

namespace {

// FFTW's planner (and fftw_malloc'd plan scratch) is not thread-safe; plan execution is.
std::mutex& planner_mutex() {
  static std::mutex mutex;
  return mutex;
}

fftw_plan as_plan(void* p) { return static_cast<fftw_plan>(p); }

}  // namespace

FftPlans::FftPlans(int nx, int ny) {
  if (nx < 1 || ny < 1) throw std::invalid_argument("FFT grid must be at least 1 x 1");
  const std::size_t n_real = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  const std::size_t n_complex = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny / 2 + 1);
  // FFTW_MEASURE overwrites the arrays it plans on, so it gets its own scratch.
  FftwBuffer<double> real(n_real);
  FftwBuffer<std::complex<double>> spectrum(n_complex);
  auto* spec = reinterpret_cast<fftw_complex*>(spectrum.data());
  forward_ = fftw_plan_dft_r2c_2d(nx, ny, real.data(), spec, FFTW_MEASURE | FFTW_PRESERVE_INPUT);
  backward_ = fftw_plan_dft_c2r_2d(nx, ny, spec, real.data(), FFTW_MEASURE | FFTW_DESTROY_INPUT);
  if (forward_ == nullptr || backward_ == nullptr) {
    if (forward_ != nullptr) fftw_destroy_plan(as_plan(forward_));
    if (backward_ != nullptr) fftw_destroy_plan(as_plan(backward_));
    throw std::runtime_error("FFTW could not plan the periodic influence transform");
  }
}

FftPlans::~FftPlans() {
  const std::lock_guard<std::mutex> lock(planner_mutex());
  fftw_destroy_plan(as_plan(forward_));
  fftw_destroy_plan(as_plan(backward_));
}

void FftPlans::forward(double* in, std::complex<double>* out) const {
  fftw_execute_dft_r2c(as_plan(forward_), in, reinterpret_cast<fftw_complex*>(out));
}

void FftPlans::backward(std::complex<double>* in, double* out) const {
  fftw_execute_dft_c2r(as_plan(backward_), reinterpret_cast<fftw_complex*>(in), out);
}

std::shared_ptr<const FftPlans> fft_plans(int nx, int ny) {
  // Plans live until exit: a sweep revisits the same few grid sizes.
  // The mutex is made first so that it outlives the cache (plans lock it when destroyed).
  std::mutex& mutex = planner_mutex();
  static std::map<std::pair<int, int>, std::shared_ptr<const FftPlans>> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  auto& slot = cache[{nx, ny}];
  if (!slot) slot = std::make_shared<const FftPlans>(nx, ny);
  return slot;
}

template <class T>
FftwBuffer<T>::FftwBuffer(std::size_t n) : size_(n) {
  if (n == 0) return;
  data_ = static_cast<T*>(fftw_malloc(n * sizeof(T)));
  if (data_ == nullptr) throw std::bad_alloc();
  for (std::size_t i = 0; i < n; ++i) new (data_ + i) T{};
}

template <class T>
FftwBuffer<T>::~FftwBuffer() {
  if (data_ != nullptr) fftw_free(data_);
}

template <class T>
FftwBuffer<T>::FftwBuffer(FftwBuffer&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)) {}

template <class T>
FftwBuffer<T>& FftwBuffer<T>::operator=(FftwBuffer&& other) noexcept {
  if (this != &other) {
    if (data_ != nullptr) fftw_free(data_);
    data_ = std::exchange(other.data_, nullptr);
    size_ = std::exchange(other.size_, 0);
  }
  return *this;
}

template class FftwBuffer<double>;
template class FftwBuffer<std::complex<double>>;

PeriodicInfluence::PeriodicInfluence(const PeriodicGrid& grid)
    : grid_(grid),
      plans_(fft_plans(grid.nx, grid.ny)),
      kernel_(static_cast<std::size_t>(grid.nx) * static_cast<std::size_t>(grid.ny / 2 + 1)),
      real_(grid.size()),
      spectrum_(kernel_.size()) {
  if (const std::string e = grid_error(grid); !e.empty()) throw std::invalid_argument(e);
  const int nyc = grid.ny / 2 + 1;
  const double two_pi = 2.0 * std::numbers::pi;
  const double normalisation = 1.0 / static_cast<double>(grid.size());
  for (int i = 0; i < grid.nx; ++i) {
    const int fi = i <= grid.nx / 2 ? i : i - grid.nx;  // signed frequency index
    const double kx = two_pi * fi / grid.Lx;
    for (int j = 0; j < nyc; ++j) {
      const double ky = two_pi * j / grid.Ly;
      const double k = std::hypot(kx, ky);
      kernel_[static_cast<std::size_t>(i) * nyc + j] = k > 0.0 ? 2.0 / k * normalisation : 0.0;
    }
  }
}

void PeriodicInfluence::apply(std::span<const double> p, std::span<double> u, double scale) {
  const std::size_t n = grid_.size();
  if (p.size() != n || u.size() != n) {
    throw std::invalid_argument("PeriodicInfluence::apply: array size differs from the grid");
  }
  std::copy(p.begin(), p.end(), real_.data());
  plans_->forward(real_.data(), spectrum_.data());
  std::complex<double>* spectrum = spectrum_.data();
  for (std::size_t i = 0; i < kernel_.size(); ++i) spectrum[i] *= kernel_[i] * scale;
  plans_->backward(spectrum_.data(), real_.data());
  std::copy(real_.data(), real_.data() + n, u.begin());
}

}  // namespace punchsweep::reference
