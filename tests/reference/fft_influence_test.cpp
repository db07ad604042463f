// The periodic influence operator: exact on a harmonic, symmetric and positive, planned once,
// the same on any number of threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <utility>
#include <numbers>
#include <random>
#include <vector>

#include "reference/fft_influence.hpp"
#include "reference/periodic_grid.hpp"
#include "reference/transform_threads.hpp"

using namespace punchsweep::reference;

namespace {
constexpr double pi = std::numbers::pi;

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}
}  // namespace

TEST(PeriodicInfluence, harmonic_pressure_gives_westergaard_displacement) {
  // p = cos(k.x) gives u = 2 cos(k.x) / (E* |k|) (Johnson 1985, section 13.2) exactly on the
  // grid, for any wave vector the grid resolves, and any scale (compliance).
  const PeriodicGrid g{48, 32, 2.0, 1.5};
  PeriodicInfluence K(g);
  for (const auto& [mx, my] : {std::pair{1, 0}, std::pair{3, 2}, std::pair{-5, 7}}) {
    const double kx = 2 * pi * mx / g.Lx, ky = 2 * pi * my / g.Ly;
    std::vector<double> p(g.size()), u(g.size());
    for (int i = 0; i < g.nx; ++i) {
      for (int j = 0; j < g.ny; ++j) p[g.index(i, j)] = std::cos(kx * g.x(i) + ky * g.y(j));
    }
    K.apply(p, u, 2.5);
    const double amplitude = 2.5 * 2.0 / std::hypot(kx, ky);
    for (std::size_t i = 0; i < g.size(); ++i) EXPECT_NEAR(u[i], amplitude * p[i], 1e-13);
  }
}

TEST(PeriodicInfluence, mean_pressure_gives_no_displacement_and_operator_is_symmetric_positive) {
  const PeriodicGrid g = PeriodicGrid::square(32, 1.0);
  PeriodicInfluence K(g);
  std::vector<double> uniform(g.size(), 3.0), u(g.size());
  K.apply(uniform, u);
  for (const double v : u) EXPECT_NEAR(v, 0.0, 1e-15);

  std::mt19937 rng(7);
  std::uniform_real_distribution<double> dist(-1.0, 1.0);
  std::vector<double> a(g.size()), b(g.size()), Ka(g.size()), Kb(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) {
    a[i] = dist(rng);
    b[i] = dist(rng);
  }
  K.apply(a, Ka);
  K.apply(b, Kb);
  EXPECT_NEAR(dot(a, Kb), dot(Ka, b), 1e-12 * std::abs(dot(a, Kb)));
  EXPECT_GT(dot(a, Ka), 0.0);
  double mean = 0.0;
  for (const double v : Ka) mean += v;
  EXPECT_NEAR(mean / g.size(), 0.0, 1e-15);
}

TEST(PeriodicInfluence, plans_are_made_once_per_grid_size) {
  const auto first = fft_plans(24, 24);
  EXPECT_EQ(fft_plans(24, 24).get(), first.get());
  EXPECT_NE(fft_plans(24, 12).get(), first.get());
}

TEST(PeriodicInfluence, self_influence_matches_love_uniform_square_patch) {
  // The spectral kernel's node response equals, to leading order in h, the centre
  // displacement of a uniform pressure on one h x h square: 4 ln(1 + sqrt 2) p h / (pi E*)
  // (Love 1929). The missing tail of the spectral sum makes it O(h^2/L) different.
  const int n = 128;
  const PeriodicGrid g = PeriodicGrid::square(n, 1.0);
  PeriodicInfluence K(g);
  std::vector<double> p(g.size(), 0.0), u(g.size());
  p[g.index(n / 2, n / 2)] = 1.0;
  K.apply(p, u);
  // Remove the periodic/zero-mean part with a far node: the point-load field there is
  // h^2 / (pi r) plus the same images (it cancels to O(h^2) in the difference).
  const int far = n / 4;
  const double r = far * g.hx();
  const double self =
      u[g.index(n / 2, n / 2)] - u[g.index(n / 2 + far, n / 2)] + g.cell_area() / (pi * r);
  const double love = 4.0 * std::log(1.0 + std::sqrt(2.0)) * g.hx() / pi;
  EXPECT_NEAR(self / love, 1.0, 0.02);
}

TEST(PeriodicInfluence, mirrored_quarter_gives_the_whole_grids_displacement) {
  // An even field (here a two-punch profile-like field plus even harmonics) stored as its
  // quarter: the cosine-transform operator must give the quarter of the whole grid's K p.
  // Quarter sizes K + 1 with K even (the halved transform) and odd (the even extension).
  for (const auto& [nx, ny] : {std::pair{32, 32}, std::pair{48, 20}, std::pair{34, 30}, std::pair{36, 6}}) {
    const PeriodicGrid whole{nx, ny, 1.5, 1.0};
    const PeriodicGrid quarter{nx, ny, 1.5, 1.0, Symmetry::mirror};
    ASSERT_EQ(quarter.size(), static_cast<std::size_t>((nx / 2 + 1) * (ny / 2 + 1)));
    std::vector<double> p(whole.size()), u(whole.size());
    for (int i = 0; i < nx; ++i) {
      for (int j = 0; j < ny; ++j) {
        const double cx = std::cos(2 * pi * i / nx), cy = std::cos(2 * pi * 2 * j / ny);
        const double r1 = std::hypot(std::min(i, nx - i) / double(nx), std::min(j, ny - j) / double(ny));
        p[whole.index(i, j)] = 1.0 + 0.5 * cx * cy + std::exp(-20 * r1 * r1);
      }
    }
    PeriodicInfluence K(whole);
    K.apply(p, u, 1.7);
    std::vector<double> pq(quarter.size()), uq(quarter.size());
    for (int i = 0; i < quarter.stored_nx(); ++i) {
      for (int j = 0; j < quarter.stored_ny(); ++j) pq[quarter.index(i, j)] = p[whole.index(i, j)];
    }
    PeriodicInfluence Kq(quarter);
    Kq.apply(pq, uq, 1.7);
    double range = 0.0;
    for (const double v : u) range = std::max(range, std::abs(v));
    for (int i = 0; i < quarter.stored_nx(); ++i) {
      for (int j = 0; j < quarter.stored_ny(); ++j) {
        EXPECT_NEAR(uq[quarter.index(i, j)], u[whole.index(i, j)], 1e-13 * range) << i << ", " << j;
      }
    }
    // Multiplicities count every node of the whole cell once.
    double count = 0.0;
    for (std::size_t k = 0; k < quarter.size(); ++k) count += quarter.multiplicity(k);
    EXPECT_EQ(count, static_cast<double>(whole.nodes()));
  }
}

TEST(PeriodicInfluence, half_mirrored_in_x_gives_the_whole_grids_displacement) {
  // A field even in x but not in y, stored as its half 0 <= i <= nx/2: the cosine transform
  // along x and real transforms along y must give the half of the whole grid's K p (and
  // the stiffness its S p). Half sizes K + 1 with K even and odd; ny even and odd.
  for (const auto& [nx, ny] : {std::pair{32, 32}, std::pair{48, 21}, std::pair{34, 30}, std::pair{36, 7}}) {
    const PeriodicGrid whole{nx, ny, 1.5, 1.0};
    const PeriodicGrid half{nx, ny, 1.5, 1.0, Symmetry::mirror_x};
    ASSERT_EQ(half.size(), static_cast<std::size_t>((nx / 2 + 1) * ny));
    std::vector<double> p(whole.size()), u(whole.size()), s(whole.size());
    for (int i = 0; i < nx; ++i) {
      for (int j = 0; j < ny; ++j) {
        const double cx = std::cos(2 * pi * i / nx), sy = std::sin(2 * pi * 2 * j / ny);
        const double r1 = std::hypot(std::min(i, nx - i) / double(nx), (j - 0.3 * ny) / double(ny));
        p[whole.index(i, j)] = 1.0 + 0.5 * cx * sy + std::exp(-20 * r1 * r1);
      }
    }
    PeriodicInfluence K(whole);
    K.apply(p, u, 1.7);
    K.apply_stiffness(p, s, 0.3);
    std::vector<double> ph(half.size()), uh(half.size()), sh(half.size());
    for (int i = 0; i < half.stored_nx(); ++i) {
      for (int j = 0; j < half.stored_ny(); ++j) ph[half.index(i, j)] = p[whole.index(i, j)];
    }
    PeriodicInfluence Kh(half);
    Kh.apply(ph, uh, 1.7);
    Kh.apply_stiffness(ph, sh, 0.3);
    double range = 0.0, s_range = 0.0;
    for (const double v : u) range = std::max(range, std::abs(v));
    for (const double v : s) s_range = std::max(s_range, std::abs(v));
    for (int i = 0; i < half.stored_nx(); ++i) {
      for (int j = 0; j < half.stored_ny(); ++j) {
        EXPECT_NEAR(uh[half.index(i, j)], u[whole.index(i, j)], 1e-13 * range) << nx << " x " << ny << ": " << i << ", " << j;
        EXPECT_NEAR(sh[half.index(i, j)], s[whole.index(i, j)], 1e-12 * s_range) << nx << " x " << ny << ": " << i << ", " << j;
      }
    }
    double count = 0.0;
    for (std::size_t k = 0; k < half.size(); ++k) count += half.multiplicity(k);
    EXPECT_EQ(count, static_cast<double>(whole.nodes()));
  }
  EXPECT_NE(grid_error(PeriodicGrid{31, 32, 1.0, 1.0, Symmetry::mirror_x}), "");
  EXPECT_EQ(grid_error(PeriodicGrid{32, 31, 1.0, 1.0, Symmetry::mirror_x}), "");
}

TEST(PeriodicInfluence, mirrored_grid_needs_even_sizes_and_mirror_point_centres) {
  EXPECT_NE(grid_error(PeriodicGrid{31, 32, 1.0, 1.0, Symmetry::mirror}), "");
  EXPECT_EQ(grid_error(PeriodicGrid{31, 32, 1.0, 1.0}), "");
  const PeriodicGrid g = PeriodicGrid::square(16, 1.0, Symmetry::mirror);
  EXPECT_NO_THROW(punch_profile(g, {2, 0.5}, 0.5, 0.0));
  EXPECT_THROW(punch_profile(g, {2, 0.5}, 0.25, 0.0), std::invalid_argument);
}

// A large cosine transform's blocks of lines are split over the threads, each block computed
// alone: the bits do not depend on how many threads there are (reference/transform_threads.hpp).
// Quarter sizes above kThreadedValues, K even and odd; the same instance on 1, 2 and 3 threads.
TEST(CosineTransform, gives_the_same_bits_on_any_number_of_threads) {
  const int before = transform_threads();
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  for (const auto& [mx, my] : {std::pair{129, 161}, std::pair{150, 131}}) {
    ASSERT_GE(static_cast<long>(mx) * my, kThreadedValues);
    std::vector<double> in(static_cast<std::size_t>(mx) * my);
    for (double& v : in) v = value(random);
    CosineTransform transform(mx, my);
    std::vector<std::vector<double>> out;
    for (const int threads : {1, 2, 3}) {
      set_transform_threads(threads);
      out.emplace_back(in.size());
      transform.execute(in.data(), out.back().data());
    }
    EXPECT_EQ(out[0], out[1]) << mx << " x " << my;
    EXPECT_EQ(out[0], out[2]) << mx << " x " << my;
    // And it is the transform: REDFT00's value at (1, 2) summed directly.
    double direct = 0.0;
    for (int i = 0; i < mx; ++i) {
      for (int j = 0; j < my; ++j) {
        const double wx = (i == 0 || i == mx - 1) ? 1.0 : 2.0, wy = (j == 0 || j == my - 1) ? 1.0 : 2.0;
        direct += wx * wy * in[static_cast<std::size_t>(i) * my + j] * std::cos(pi * i * 1 / (mx - 1)) * std::cos(pi * j * 2 / (my - 1));
      }
    }
    EXPECT_NEAR(out[0][1 * static_cast<std::size_t>(my) + 2], direct, 1e-12 * static_cast<double>(mx) * my);
  }
  set_transform_threads(before);
}

// The whole grid's 2-D transforms and the half's rows go through FFTW's own threads, whose
// plans FFTW chooses per thread count: the same operator to round-off (seen equal to the
// bit on this machine; FFTW does not promise it).
TEST(PeriodicInfluence, threads_give_the_same_operator) {
  const int before = transform_threads();
  for (const Symmetry symmetry : {Symmetry::none, Symmetry::mirror_x}) {
    const PeriodicGrid grid{256, 150, 1.0, 0.6, symmetry};
    std::vector<double> p(grid.size());
    for (std::size_t k = 0; k < p.size(); ++k) p[k] = 1.0 + std::sin(0.37 * static_cast<double>(k)) * std::cos(0.011 * static_cast<double>(k));
    std::vector<std::vector<double>> u;
    for (const int threads : {1, 2}) {
      set_transform_threads(threads);
      PeriodicInfluence K(grid);
      u.emplace_back(grid.size());
      K.apply(p, u.back(), 1.0);
    }
    double range = 0.0;
    for (const double v : u[0]) range = std::max(range, std::abs(v));
    for (std::size_t k = 0; k < p.size(); ++k) ASSERT_NEAR(u[1][k], u[0][k], 1e-14 * range) << k;
  }
  set_transform_threads(before);
}

// Threads a process takes: the user's word, else the cores a launcher gave it, else one
// (GNU OpenMP's threads spin while they wait: processes sharing cores must not take them all).
TEST(TransformThreads, a_process_takes_the_cores_it_is_given) {
  const char* asked = std::getenv("OMP_NUM_THREADS");
  const std::string kept = asked != nullptr ? asked : "";
  unsetenv("OMP_NUM_THREADS");
  EXPECT_EQ(threads_given(2, 2), 1);    // a plain process: one, whatever the machine
  EXPECT_EQ(threads_given(16, 16), 1);
  EXPECT_EQ(threads_given(1, 2), 1);    // mpirun's binding to a core each
  EXPECT_EQ(threads_given(4, 16), 4);   // Slurm's --cpus-per-task=4, taskset -c 0-3
  EXPECT_EQ(default_transform_threads(), threads_given(affinity_cpus(), machine_cpus()));
  setenv("OMP_NUM_THREADS", "3", 1);
  EXPECT_EQ(threads_given(16, 16), 3);  // the user's word
  EXPECT_EQ(threads_given(1, 16), 3);
  EXPECT_EQ(default_transform_threads(), 3);
  setenv("OMP_NUM_THREADS", "3,1", 1);  // OpenMP's list: this level's first
  EXPECT_EQ(default_transform_threads(), 3);
  setenv("OMP_NUM_THREADS", "none", 1);  // not a number: as unset
  EXPECT_EQ(default_transform_threads(), threads_given(affinity_cpus(), machine_cpus()));
  if (asked != nullptr) {
    setenv("OMP_NUM_THREADS", kept.c_str(), 1);
  } else {
    unsetenv("OMP_NUM_THREADS");
  }
  EXPECT_GE(affinity_cpus(), 1);
  EXPECT_LE(affinity_cpus(), machine_cpus());
}
