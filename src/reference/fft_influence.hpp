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

/// Readies FFTW's threads, once a process (FFTW asks for it before any of its other calls;
/// every FFTW use here goes through this file, which calls it first).
void prepare_fftw();

/// A forward (r2c) and backward (c2r) FFTW plan pair for one grid size, made once with
/// FFTW_MEASURE and kept for the life of the process: the 2-D transform, or with `rows`
/// the 1-D transforms along y of each of the nx rows alone (the same layouts), each
/// transform split over `threads` (FFTW's threads). Executing the plans is thread-safe;
/// they are applied to other arrays through FFTW's new-array interface.
class FftPlans {
 public:
  FftPlans(int nx, int ny, bool rows = false, int threads = 1);
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

/// The plans for an nx x ny grid: planned at the first request for that size (and thread
/// count: transform_threads() from kThreadedValues values, else one), then shared
/// (thread-safe; FFTW's planner is serialised by a mutex).
std::shared_ptr<const FftPlans> fft_plans(int nx, int ny, bool rows = false);


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

/// The two-dimensional type-I discrete cosine transform (REDFT00 along both axes) of an
/// mx x my array, unnormalised: the discrete Fourier transform of the even 2(mx - 1) x
/// 2(my - 1) periodic field whose quarter it is; its own inverse up to the factor
/// 4 (mx - 1)(my - 1). Each axis is done as real-to-complex transforms of its lines' even
/// extensions, eight lines a time (FFTW's many-transform plans, shared between instances
/// and made once per length; FFTW's own 2-D REDFT00 allocates and copies on every call and
/// measured 1.3-1.6 times slower). The blocks of a large transform are split over
/// transform_threads() (each block alone, so the bits do not depend on how many). One
/// instance owns its scratch: not for concurrent use.
class CosineTransform {
 public:
  /// `along_y` false: along x alone (each column's REDFT00; each row is left as it is).
  CosineTransform(int mx, int my, bool along_y = true);
  /// in (mx x my, row-major) -> out (mx x my); in and out must not alias.
  void execute(const double* in, double* out);

  struct RowPlan;  ///< an FFTW plan for a block of lines (defined with the code)

 private:
  /// The plans of one axis: for a full block of lines, and for the last, shorter one.
  struct Axis {
    std::shared_ptr<const RowPlan> block, rest;
  };
  /// Transforms the `count` lines of one axis of in (the rows, along y, or the columns,
  /// along x) into the same places of out.
  template <bool kColumns>
  void lines(const Axis& axis, const double* in, double* out, int count);

  /// One thread's scratch: a block of even extensions and their spectra.
  struct Scratch {
    FftwBuffer<double> pad;
    FftwBuffer<std::complex<double>> spec;
  };

  int mx_, my_;
  std::size_t length_ = 0;                  ///< the longest line's real transform
  Axis along_x_, along_y_;
  std::vector<Scratch> scratch_;            ///< a thread's each, made as threads come
  FftwBuffer<double> middle_;               ///< after the first axis
};

/// Surface displacement of an elastic half-space (E* = 1) under a periodic normal pressure,
/// through its Fourier-space influence u^(k) = 2 p^(k) / (E* |k|) (Johnson 1985, eq. 13.63's
/// periodic form; Stanley & Kato 1997, doi:10.1115/1.2833523). The k = 0 mode is dropped:
/// the displacement has zero mean, and the rigid-body part belongs to the approach, which
/// the load-controlled contact solver carries as its Lagrange multiplier.
///
/// On a mirrored grid (Symmetry::mirror) the fields are the stored quarters of even ones,
/// and the operator is the same one through the cosine transform of the quarter: every
/// wave vector's cosine pairs with its mirror images, so the spectrum is real and a quarter
/// of the size, at about a third of the full transform's cost. Mirrored in x alone
/// (Symmetry::mirror_x), the half's cosine transform along x and real-to-complex transforms
/// along y: the spectrum of the even field at wave numbers kx >= 0, half the whole's.
///
/// One instance owns scratch buffers: not for concurrent use (make one per thread).
class PeriodicInfluence {
 public:
  explicit PeriodicInfluence(const PeriodicGrid& grid);

  /// u = scale K p (zero mean). p and u have grid.size() entries and may alias.
  void apply(std::span<const double> p, std::span<double> u, double scale = 1.0);
  /// u = scale S p with S the inverse of K on every mode but the mean, E* |k| / 2 in
  /// Fourier space (the half-space's stiffness; the contact solver's preconditioner). The
  /// table is made at the first call.
  void apply_stiffness(std::span<const double> p, std::span<double> u, double scale = 1.0);

  const PeriodicGrid& grid() const { return grid_; }

 private:
  PeriodicGrid grid_;
  std::shared_ptr<const FftPlans> plans_;    ///< whole grid: r2c and c2r
  std::unique_ptr<CosineTransform> cosine_;  ///< mirrored grid: the quarter's REDFT00 (mirror_x: along x)
  std::shared_ptr<const FftPlans> rows_;     ///< mirror_x: r2c and c2r along y
  /// 2/|k| / (nx ny), 0 at k = 0: on the r2c half spectrum, on the quarter's
  /// non-negative wave numbers under mirror, or on kx >= 0 by the r2c half along y under
  /// mirror_x
  std::vector<double> kernel_;
  std::vector<double> stiffness_;  ///< |k|/2 / (nx ny) on the kernel's modes, 0 at k = 0
  void convolve(std::span<const double> p, std::span<double> u, const std::vector<double>& kernel, double scale);
  FftwBuffer<double> real_;
  FftwBuffer<std::complex<double>> spectrum_;  ///< whole grid
  FftwBuffer<double> cosines_;                 ///< mirrored grid: the cosine spectrum
};

}  // namespace punchsweep::reference
