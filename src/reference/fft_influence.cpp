#include "reference/fft_influence.hpp"

#include <fftw3.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <new>
#include <numbers>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "reference/transform_threads.hpp"

namespace punchsweep::reference {

namespace {

// FFTW's planner (and fftw_malloc'd plan scratch) is not thread-safe; plan execution is.
std::mutex& planner_mutex() {
  static std::mutex mutex;
  return mutex;
}

fftw_plan as_plan(void* p) { return static_cast<fftw_plan>(p); }

}  // namespace

void prepare_fftw() {
  // FFTW asks for its threads' set-up before any other of its calls (a static's
  // initialisation runs once, whichever thread comes first).
  static const bool ready = fftw_init_threads() != 0;
  if (!ready) throw std::runtime_error("FFTW could not start its threads");
  one_thread_after_fork();
}

namespace {

/// The plan of type Plan made from `args`, made at the first request for them and shared
/// until exit (a sweep revisits the same few sizes). Plans are made under the planner's
/// mutex, which is made before the cache so that it outlives it (plans lock it when
/// destroyed).
template <class Plan, class... Args>
std::shared_ptr<const Plan> shared_plan(Args... args) {
  std::mutex& mutex = planner_mutex();
  static std::map<std::tuple<Args...>, std::shared_ptr<const Plan>> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  auto& slot = cache[{args...}];
  if (!slot) slot = std::make_shared<const Plan>(args...);
  return slot;
}

}  // namespace

FftPlans::FftPlans(int nx, int ny, bool rows, int threads) {
  if (nx < 1 || ny < 1) throw std::invalid_argument("FFT grid must be at least 1 x 1");
  if (threads < 1) throw std::invalid_argument("FFT plans need at least one thread");
  prepare_fftw();
  fftw_plan_with_nthreads(threads);
  const int nyc = ny / 2 + 1;
  const std::size_t n_real = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  const std::size_t n_complex = static_cast<std::size_t>(nx) * static_cast<std::size_t>(nyc);
  // FFTW_MEASURE overwrites the arrays it plans on, so it gets its own scratch.
  FftwBuffer<double> real(n_real);
  FftwBuffer<std::complex<double>> spectrum(n_complex);
  auto* spec = reinterpret_cast<fftw_complex*>(spectrum.data());
  if (rows) {
    forward_ = fftw_plan_many_dft_r2c(1, &ny, nx, real.data(), nullptr, 1, ny, spec, nullptr, 1, nyc,
                                      FFTW_MEASURE | FFTW_PRESERVE_INPUT);
    backward_ = fftw_plan_many_dft_c2r(1, &ny, nx, spec, nullptr, 1, nyc, real.data(), nullptr, 1, ny,
                                       FFTW_MEASURE | FFTW_DESTROY_INPUT);
  } else {
    forward_ = fftw_plan_dft_r2c_2d(nx, ny, real.data(), spec, FFTW_MEASURE | FFTW_PRESERVE_INPUT);
    backward_ = fftw_plan_dft_c2r_2d(nx, ny, spec, real.data(), FFTW_MEASURE | FFTW_DESTROY_INPUT);
  }
  fftw_plan_with_nthreads(1);  // (the cosine transform's plans are one thread's)
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

std::shared_ptr<const FftPlans> fft_plans(int nx, int ny, bool rows) {
  return shared_plan<FftPlans>(nx, ny, rows, threads_for(static_cast<long>(nx) * ny));
}


template <class T>
FftwBuffer<T>::FftwBuffer(std::size_t n) : size_(n) {
  if (n == 0) return;
  prepare_fftw();
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

/// The lines of one axis are transformed this many at a time.
constexpr int kCosineBlock = 8;

/// A many-transform r2c plan for `lines` lines of m values (x_0 .. x_K, K = m - 1), and
/// how it makes their cosine sums. For even K, a real transform of length K of
///   y_0 = x_0 + x_K,  y_K/2 = 2 x_K/2,  y_j, y_K-j = (x_j + x_K-j) -+ 2 sin(pi j/K) (x_j - x_K-j)
/// gives the even sums as its real parts, X_2k = Re Y_k, and the odd ones by the running
/// sum X_1 = x_0 - x_K + 2 sum_j cos(pi j/K) (x_j - x_K-j), X_2k+1 = X_2k-1 - Im Y_k
/// (Press et al., Numerical Recipes, 2nd ed., section 12.3, cosft1, for FFTW's sign
/// and REDFT00's factor 2): half the transform of the even extension, which odd K takes.
/// Made under the planner's mutex (shared_plan).
struct CosineTransform::RowPlan {
  RowPlan(int m, int lines)
      : m(m), halved((m - 1) % 2 == 0), length(halved ? m - 1 : 2 * (m - 1)), spectrum(length / 2 + 1) {
    if (halved) {
      const int K = m - 1;
      for (int j = 0; j < K / 2; ++j) {
        sine.push_back(2.0 * std::sin(std::numbers::pi * j / K));
        cosine.push_back(2.0 * std::cos(std::numbers::pi * j / K));
      }
    }
    FftwBuffer<double> pad(static_cast<std::size_t>(lines) * length);
    FftwBuffer<std::complex<double>> spec(static_cast<std::size_t>(lines) * spectrum);
    plan = fftw_plan_many_dft_r2c(1, &length, lines, pad.data(), nullptr, 1, length,
                                  reinterpret_cast<fftw_complex*>(spec.data()), nullptr, 1, spectrum,
                                  FFTW_MEASURE | FFTW_DESTROY_INPUT);
    if (plan == nullptr) throw std::runtime_error("FFTW could not plan the cosine transform");
  }
  ~RowPlan() {
    const std::lock_guard<std::mutex> lock(planner_mutex());
    fftw_destroy_plan(plan);
  }
  RowPlan(const RowPlan&) = delete;
  RowPlan& operator=(const RowPlan&) = delete;

  int m;
  bool halved;   ///< K even: the length-K transform; else the even extension's, 2K
  int length;    ///< of each line's real transform
  int spectrum;  ///< complex values of each line's transform
  std::vector<double> sine, cosine;  ///< 2 sin(pi j/K), 2 cos(pi j/K), j < K/2 (halved)
  fftw_plan plan = nullptr;
};

CosineTransform::CosineTransform(int mx, int my, bool along_y)
    : mx_(mx), my_(my) {
  if (mx < 2 || (along_y && my < 2) || my < 1) throw std::invalid_argument("a cosine transform needs at least 2 x 2 values");
  // Along y there are mx lines, along x my: full blocks, and a plan for the rest.
  const auto rows = [](int m, int lines) { return shared_plan<RowPlan>(m, lines); };
  if (along_y) along_y_ = {rows(my, kCosineBlock), mx % kCosineBlock ? rows(my, mx % kCosineBlock) : nullptr};
  along_x_ = {rows(mx, kCosineBlock), my % kCosineBlock ? rows(mx, my % kCosineBlock) : nullptr};
  length_ = static_cast<std::size_t>(std::max(along_y ? along_y_.block->length : 0, along_x_.block->length));
  if (along_y) middle_ = FftwBuffer<double>(static_cast<std::size_t>(mx) * static_cast<std::size_t>(my));
}

namespace {

/// The halved transform's preparation of one block: line b's values x(b, j), j = 0 .. K,
/// become its row of `pad` (length K) and its odd seed odd[b]. Rows (the y axis, each line
/// contiguous) go line by line, columns (the x axis, lines side by side) value by value, so
/// that the inner loop reads memory in order.
template <bool kColumns, class Value>
void halve_lines(const Value& x, int block, int K, const std::vector<double>& sine,
                 const std::vector<double>& cosine, double* pad, double* odd) {
  const auto prepare = [&](int b, int j) {
    double* e = pad + static_cast<std::ptrdiff_t>(b) * K;
    const double sum = x(b, j) + x(b, K - j), difference = x(b, j) - x(b, K - j);
    e[j] = sum - sine[j] * difference;
    e[K - j] = sum + sine[j] * difference;
    odd[b] += cosine[j] * difference;
  };
  for (int b = 0; b < block; ++b) {
    double* e = pad + static_cast<std::ptrdiff_t>(b) * K;
    odd[b] = x(b, 0) - x(b, K);
    e[0] = x(b, 0) + x(b, K);
    e[K / 2] = 2.0 * x(b, K / 2);
  }
  if constexpr (kColumns) {
    for (int j = 1; j < K / 2; ++j) {
      for (int b = 0; b < block; ++b) prepare(b, j);
    }
  } else {
    for (int b = 0; b < block; ++b) {
      for (int j = 1; j < K / 2; ++j) prepare(b, j);
    }
  }
}

/// The halved transform's cosine sums of one block from the spectra (spectrum values a
/// line) and the odd seeds, into y(b, j) = value.
template <bool kColumns, class Put>
void unhalve_lines(const Put& put, int block, int K, const std::complex<double>* spec,
                   std::ptrdiff_t spectrum, double* odd) {
  const auto finish = [&](int b, int k) {
    const std::complex<double> c = spec[b * spectrum + k];
    put(b, 2 * k, c.real());
    odd[b] -= c.imag();
    put(b, 2 * k + 1, odd[b]);
  };
  for (int b = 0; b < block; ++b) {
    put(b, 0, spec[b * spectrum].real());
    put(b, 1, odd[b]);
    put(b, K, spec[b * spectrum + K / 2].real());
  }
  if constexpr (kColumns) {
    for (int k = 1; k < K / 2; ++k) {
      for (int b = 0; b < block; ++b) finish(b, k);
    }
  } else {
    for (int b = 0; b < block; ++b) {
      for (int k = 1; k < K / 2; ++k) finish(b, k);
    }
  }
}

}  // namespace

template <bool kColumns>
void CosineTransform::lines(const Axis& axis, const double* in, double* out, int count) {
  const RowPlan& shape = *axis.block;
  const int m = shape.m;
  const int K = m - 1;
  // Rows: my values a line, lines my apart; columns: mx values my apart, lines side by side.
  const std::ptrdiff_t line = kColumns ? 1 : my_;
  const std::ptrdiff_t step = kColumns ? my_ : 1;
  const std::ptrdiff_t length = shape.length;
  const std::ptrdiff_t spectrum = shape.spectrum;
  const int blocks = (count + kCosineBlock - 1) / kCosineBlock;
  const int threads = std::min(threads_for(static_cast<long>(count) * m), blocks);
  while (static_cast<int>(scratch_.size()) < threads) {  // (made as threads come)
    scratch_.push_back({FftwBuffer<double>(kCosineBlock * length_), FftwBuffer<std::complex<double>>(kCosineBlock * (length_ / 2 + 1))});
  }
  // Each block alone, on whichever thread: the same bits for any number of them.
  const auto transform_block = [&](int index, Scratch& mine) {
    double* pad = mine.pad.data();
    std::complex<double>* spec = mine.spec.data();
    double odd[kCosineBlock];  // halved: the running odd sums of each line
    const int first = index * kCosineBlock;
    const int block = std::min(kCosineBlock, count - first);
    const double* x = in + first * line;
    double* y = out + first * line;
    const auto at = [&](int b, int j) { return x[b * line + j * step]; };
    const auto put = [&](int b, int j, double v) { y[b * line + j * step] = v; };
    if (shape.halved) {
      halve_lines<kColumns>(at, block, K, shape.sine, shape.cosine, pad, odd);
    } else {  // the even extension x_0 .. x_K, x_K-1 .. x_1
      for (int b = 0; b < block; ++b) {
        double* e = pad + b * length;
        for (int j = 0; j < m; ++j) e[j] = at(b, j);
        for (int j = 1; j < K; ++j) e[length - j] = e[j];
      }
    }
    const RowPlan& plan = block == kCosineBlock ? *axis.block : *axis.rest;
    fftw_execute_dft_r2c(plan.plan, pad, reinterpret_cast<fftw_complex*>(spec));
    if (shape.halved) {
      unhalve_lines<kColumns>(put, block, K, spec, spectrum, odd);
    } else {  // an even line's spectrum is real: its cosine sums
      for (int b = 0; b < block; ++b) {
        for (int j = 0; j < m; ++j) put(b, j, spec[b * spectrum + j].real());
      }
    }
  };
  if (threads > 1) {
#pragma omp parallel for num_threads(threads) schedule(static)
    for (int index = 0; index < blocks; ++index) transform_block(index, scratch_[static_cast<std::size_t>(omp_get_thread_num())]);
  } else {  // (no OpenMP region at all: a process forked after one must not enter another)
    for (int index = 0; index < blocks; ++index) transform_block(index, scratch_.front());
  }
}

void CosineTransform::execute(const double* in, double* out) {
  if (!along_y_.block) {  // along x alone
    lines<true>(along_x_, in, out, my_);
    return;
  }
  // Along y (the rows), then along x (the columns, a column's values my apart).
  lines<false>(along_y_, in, middle_.data(), mx_);
  lines<true>(along_x_, middle_.data(), out, my_);
}

namespace {

/// The half-space kernel 2/|k| times `normalisation` (0 at k = 0) at signed wave numbers.
double kernel_value(int fi, int fj, const PeriodicGrid& grid, double normalisation) {
  const double two_pi = 2.0 * std::numbers::pi;
  const double k = std::hypot(two_pi * fi / grid.Lx, two_pi * fj / grid.Ly);
  return k > 0.0 ? 2.0 / k * normalisation : 0.0;
}

}  // namespace

PeriodicInfluence::PeriodicInfluence(const PeriodicGrid& grid) : grid_(grid) {
  if (const std::string e = grid_error(grid); !e.empty()) throw std::invalid_argument(e);
  const double normalisation = 1.0 / static_cast<double>(grid.nodes());
  if (grid.mirrored()) {
    // The quarter's cosine coefficients sit at wave numbers 0 .. nx/2 and 0 .. ny/2.
    const int mx = grid.stored_nx(), my = grid.stored_ny();
    cosine_ = std::make_unique<CosineTransform>(mx, my);
    kernel_.resize(grid.size());
    for (int i = 0; i < mx; ++i) {
      for (int j = 0; j < my; ++j) kernel_[grid.index(i, j)] = kernel_value(i, j, grid, normalisation);
    }
    cosines_ = FftwBuffer<double>(grid.size());
    return;
  }
  if (grid.mirrored_x()) {
    // The half's cosine coefficients along x (wave numbers 0 .. nx/2), each row's r2c
    // half spectrum along y (0 .. ny/2; the negative ones its conjugates).
    const int mx = grid.stored_nx(), nyc = grid.ny / 2 + 1;
    cosine_ = std::make_unique<CosineTransform>(mx, grid.ny, false);
    rows_ = fft_plans(mx, grid.ny, true);
    kernel_.resize(static_cast<std::size_t>(mx) * static_cast<std::size_t>(nyc));
    for (int i = 0; i < mx; ++i) {
      for (int j = 0; j < nyc; ++j) kernel_[static_cast<std::size_t>(i) * nyc + j] = kernel_value(i, j, grid, normalisation);
    }
    cosines_ = FftwBuffer<double>(grid.size());
    spectrum_ = FftwBuffer<std::complex<double>>(kernel_.size());
    return;
  }
  plans_ = fft_plans(grid.nx, grid.ny);
  const int nyc = grid.ny / 2 + 1;
  kernel_.resize(static_cast<std::size_t>(grid.nx) * static_cast<std::size_t>(nyc));
  for (int i = 0; i < grid.nx; ++i) {
    const int fi = i <= grid.nx / 2 ? i : i - grid.nx;  // signed frequency index
    for (int j = 0; j < nyc; ++j) {
      kernel_[static_cast<std::size_t>(i) * nyc + j] = kernel_value(fi, j, grid, normalisation);
    }
  }
  real_ = FftwBuffer<double>(grid.size());
  spectrum_ = FftwBuffer<std::complex<double>>(kernel_.size());
}

void PeriodicInfluence::apply(std::span<const double> p, std::span<double> u, double scale) {
  convolve(p, u, kernel_, scale);
}

void PeriodicInfluence::apply_stiffness(std::span<const double> p, std::span<double> u, double scale) {
  if (stiffness_.empty()) {
    // |k|/2 / (nx ny) from kernel_ = 2/|k| / (nx ny): the inverse on every mode but k = 0.
    const double nodes = static_cast<double>(grid_.nodes());
    stiffness_.resize(kernel_.size());
    for (std::size_t i = 0; i < kernel_.size(); ++i) {
      stiffness_[i] = kernel_[i] > 0.0 ? 1.0 / (kernel_[i] * nodes * nodes) : 0.0;
    }
  }
  convolve(p, u, stiffness_, scale);
}

void PeriodicInfluence::convolve(std::span<const double> p, std::span<double> u,
                                 const std::vector<double>& kernel, double scale) {
  const std::size_t n = grid_.size();
  if (p.size() != n || u.size() != n) {
    throw std::invalid_argument("PeriodicInfluence: array size differs from the grid");
  }
  if (grid_.mirrored()) {
    double* cosines = cosines_.data();
    cosine_->execute(p.data(), cosines);
    for (std::size_t i = 0; i < n; ++i) cosines[i] *= kernel[i] * scale;
    cosine_->execute(cosines, u.data());
    return;
  }
  if (grid_.mirrored_x()) {
    double* cosines = cosines_.data();
    cosine_->execute(p.data(), cosines);
    rows_->forward(cosines, spectrum_.data());
    std::complex<double>* spectrum = spectrum_.data();
    for (std::size_t i = 0; i < kernel.size(); ++i) spectrum[i] *= kernel[i] * scale;
    rows_->backward(spectrum, cosines);
    cosine_->execute(cosines, u.data());
    return;
  }
  std::copy(p.begin(), p.end(), real_.data());
  plans_->forward(real_.data(), spectrum_.data());
  std::complex<double>* spectrum = spectrum_.data();
  for (std::size_t i = 0; i < kernel.size(); ++i) spectrum[i] *= kernel[i] * scale;
  plans_->backward(spectrum_.data(), real_.data());
  std::copy(real_.data(), real_.data() + n, u.begin());
}

}  // namespace punchsweep::reference
