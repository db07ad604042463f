#pragma once
/// @file
/// The elastic half-space's periodic influence operator through FFTW3. Units: pressures in
/// E0*, lengths in R; the operator is the E* = 1 one (a compliance factor scales it).

#include <complex>
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "reference/periodic_grid.hpp"

namespace punchsweep::reference {

/// A forward (r2c) and backward (c2r) FFTW plan pair for one grid size, made once with
/// FFTW_MEASURE and kept for the life of the process. Executing the plans is thread-safe;
/// they are applied to other arrays through FFTW's new-array interface.
class FftPlans {
 public:
  FftPlans(int nx, int ny);
  ~FftPlans();
  FftPlans(const FftPlans&) = delete;
  FftPlans& operator=(const FftPlans&) = delete;

  /// in (nx x ny reals) -> out (nx x (ny/2 + 1) complex), unnormalised. `in` is preserved.
  void forward(double* in, std::complex<double>* out) const;
  /// in (spectrum, destroyed) -> out (reals), unnormalised.
  void backward(std::complex<double>* in, double* out) const;

 private:
  void* forward_ = nullptr;  // fftw_plan, kept opaque so <fftw3.h> stays out of this header
  void* backward_ = nullptr;
};

/// The plans for an nx x ny grid: planned at the first request for that size, then shared
/// (thread-safe; FFTW's planner is serialised by a mutex).
std::shared_ptr<const FftPlans> fft_plans(int nx, int ny);

/// Memory from fftw_malloc (SIMD-aligned, as FFTW's new-array execution requires).
template <class T>
class FftwBuffer {
 public:
  explicit FftwBuffer(std::size_t n = 0);
  ~FftwBuffer();
  FftwBuffer(const FftwBuffer&) = delete;
  FftwBuffer& operator=(const FftwBuffer&) = delete;
  FftwBuffer(FftwBuffer&& other) noexcept;
  FftwBuffer& operator=(FftwBuffer&& other) noexcept;

  T* data() { return data_; }
  const T* data() const { return data_; }
  std::size_t size() const { return size_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }

 private:
  T* data_ = nullptr;
  std::size_t size_ = 0;
};

/// Surface displacement of an elastic half-space (E* = 1) under a periodic normal pressure,
/// through its Fourier-space influence u^(k) = 2 p^(k) / (E* |k|) (Johnson 1985, eq. 13.63's
/// periodic form; Stanley & Kato 1997, doi:10.1115/1.2833523). The k = 0 mode is dropped:
/// the displacement has zero mean, and the rigid-body part belongs to the approach, which
/// the load-controlled contact solver carries as its Lagrange multiplier.
///
/// One instance owns scratch buffers: not for concurrent use (make one per thread).
class PeriodicInfluence {
 public:
  explicit PeriodicInfluence(const PeriodicGrid& grid);

  /// u = scale K p (zero mean). p and u have grid.size() entries and may alias.
  void apply(std::span<const double> p, std::span<double> u, double scale = 1.0);

  const PeriodicGrid& grid() const { return grid_; }

 private:
  PeriodicGrid grid_;
  std::shared_ptr<const FftPlans> plans_;
  std::vector<double> kernel_;  ///< 2/|k| / (nx ny) on the r2c half spectrum, 0 at k = 0
  FftwBuffer<double> real_;
  FftwBuffer<std::complex<double>> spectrum_;
};

}  // namespace punchsweep::reference
