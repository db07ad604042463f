// The single-level phase under the family of localizations of docs/model.md, section 11:
// one shell of point loads is the paper's eqs 9.5/9.10 (SingleLevel's closed forms); the
// lattice shells are the lattice's; the distributed model equals the independent Python
// study (studies/localization/localization_shells.py, numpy/scipy quadrature and root
// finding) at two of its points.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <functional>
#include <stdexcept>
#include <tuple>

#include "model/numerics/lattice.hpp"
#include "model/problem/localization.hpp"
#include "model/paper/pressure.hpp"
#include "model/contact/regime.hpp"
#include "model/shells/shell_sums.hpp"
#include "model/paper/single_level.hpp"
#include "model/paper/elastic_two_level.hpp"
#include "model/shells/single_level_shells.hpp"
#include "model/shells/spot_average.hpp"
#include "model/shells/two_level_shells.hpp"

using namespace punchsweep::model;

TEST(LatticeShells, are_the_lattice_distances_and_counts) {
  const auto punch = lattice_shells(0.0, 0.0, 5, 1);
  const double expect[5][2] = {{1.0, 4}, {std::sqrt(2.0), 4}, {2.0, 4}, {std::sqrt(5.0), 8}, {std::sqrt(8.0), 4}};
  ASSERT_EQ(punch.size(), 5u);
  for (int k = 0; k < 5; ++k) {
    EXPECT_DOUBLE_EQ(punch[k].distance, expect[k][0]);
    EXPECT_EQ(punch[k].count, expect[k][1]);
  }
  const auto centre = lattice_shells(0.5, 0.5, 3, 1);
  EXPECT_DOUBLE_EQ(centre[0].distance, std::sqrt(0.5));
  EXPECT_EQ(centre[0].count, 4);
  EXPECT_DOUBLE_EQ(centre[1].distance, std::sqrt(2.5));
  EXPECT_EQ(centre[1].count, 8);
  EXPECT_DOUBLE_EQ(centre[2].distance, std::sqrt(4.5));
  EXPECT_EQ(centre[2].count, 4);
  // 100 shells hold 1 + 828 punches (the study's N at K = 100).
  int kept = 1;
  for (const DistanceShell& s : lattice_shells(0.0, 0.0, 100, 1)) kept += s.count;
  EXPECT_EQ(kept, 829);
}

TEST(LatticeShells, the_papers_neighbourhood_is_two_distances) {
  for (const int level : {1, 2}) {
    const auto kept = kept_neighbours(level, 2);
    ASSERT_EQ(kept.size(), 2u);
    EXPECT_DOUBLE_EQ(kept[0].distance, std::sqrt(0.5));
    EXPECT_EQ(kept[0].count, 4);
    EXPECT_EQ(kept[0].level, 3 - level);  // the other level, at l/sqrt(2)
    EXPECT_DOUBLE_EQ(kept[1].distance, 1.0);
    EXPECT_EQ(kept[1].count, 4);
    EXPECT_EQ(kept[1].level, level);
  }
  // Three distances about a level-1 punch: then 8 level-2 punches at sqrt(5/2)? No: sqrt(2)
  // (4 of level 1) comes first, at 1.414 < 1.581.
  const auto three = kept_neighbours(1, 3);
  EXPECT_DOUBLE_EQ(three[2].distance, std::sqrt(2.0));
  EXPECT_EQ(three[2].level, 1);
}

TEST(SingleLevelShells, the_papers_neighbourhood_of_point_loads_is_the_papers_single_level_phase) {
  for (const int s : {1, 2, 3}) {
    for (const double l : {0.5, 0.75, 1.5}) {
      const Shape shape{s, 0.5};
      const SingleLevel paper(l, shape);
      const SingleLevelShells shells(l, shape, Localization{});
      EXPECT_NEAR(shells.radius_limit() / (SingleLevel::kScaledRadiusLimit * l), 1.0, 1e-12);
      for (const double x : {0.05, 0.2, 0.4, 0.6}) {
        const double a = x * l;
        EXPECT_NEAR(shells.creep_scaled_pressure(a) / paper.creep_scaled_pressure(a), 1.0, 1e-12);
        EXPECT_NEAR(shells.displacement_difference(a) / paper.displacement_difference(a), 1.0, 1e-11)
            << "s = " << s << ", l = " << l << ", x = " << x;
        EXPECT_NEAR(shells.displacement_difference_rate(a) / paper.displacement_difference_rate(a), 1.0, 1e-8);
      }
      const double X = paper.creep_scaled_pressure(0.3 * l);
      EXPECT_NEAR(shells.contact_radius(X) / (0.3 * l), 1.0, 1e-14);
    }
  }
}

TEST(SingleLevelShells, distributed_shells_equal_the_python_study) {
  const Shape sphere{2, 0.5};
  struct Case {
    double l, X;
    int D;
    double a, h;  // localization_shells.single_level_distances(l, X, D, distributed=True)
  };
  for (const Case& c : {Case{0.75, 0.06, 20, 0.2812355347198514, 0.055867711854423796},
                        Case{1.5, 0.005, 60, 0.20325090596959977, 0.036050558649695474}}) {
    const SingleLevelShells model(c.l, sphere, Localization{c.D, true});
    const double a = model.contact_radius(c.X);
    EXPECT_NEAR(a / c.a, 1.0, 1e-12);
    EXPECT_NEAR(model.displacement_difference(a, c.X) / c.h, 1.0, 1e-11);
  }
}

TEST(SingleLevelShells, joins_the_two_level_family_at_touchdown) {
  // The same neighbourhoods in both phases: past the touchdown X* of the single-level model
  // (h = dh) the two-level state starts from it, a2 ~ sqrt(X - X*) -> 0 and a1 -> a1*.
  const Shape sphere{2, 0.5};
  for (const Localization loc : {Localization{}, Localization{20, true}}) {
    const double l = 0.75;
    const double dh = 0.05;
    const SingleLevelShells single(l, sphere, loc);
    // X* where h(a1) = dh along the solution curve (h and X grow with a1 up to the radius
    // limit; past it the phase has no state, so X is not bisected beyond).
    const Touchdown touch = touchdown(single, dh);
    const double X_star = touch.X_star;
    const double a1_star = touch.a1_star;
    ASSERT_NEAR(single.displacement_difference(a1_star), dh, 1e-12);
    double a2[2];
    double a1_gap[2];
    for (int k = 0; k < 2; ++k) {
      const double X = X_star * (1.0 + (k == 0 ? 1e-2 : 1e-4));
      const ContactProblem p{l, dh, X, sphere};
      // From the touchdown state (the single-level loads), as the point evaluation starts.
      const TwoLevelSolve r = TwoLevelShells(p, loc).solve(X, TwoLevelState{a1_star, 0.02 * l, X * l * l, 0.0});
      ASSERT_TRUE(r.converged) << loc.spelling() << ", X/X* - 1 = " << X / X_star - 1;
      a2[k] = r.state.a2;
      a1_gap[k] = std::abs(r.state.a1 / a1_star - 1.0);
    }
    // A hundredth of the excess: a2 ten times smaller (sqrt), a1 a hundred times closer.
    EXPECT_NEAR(a2[0] / a2[1], 10.0, 0.5) << loc.spelling();
    EXPECT_LT(a1_gap[1], 2e-2 * a1_gap[0] + 1e-9) << loc.spelling();
  }
}

TEST(SpotAverage, agrees_with_a_fine_quadrature_up_to_nearly_touching_spots) {
  // The rules against a brute-force midpoint sum (2000 radial x 20000 angular points, its
  // own error about 1e-9) of the load-weighted mean of the depth kernel, for spots whose
  // distance to the punch's circle falls from twice their radius to a hundredth of it.
  const auto brute = [](int s, double rho, double a, double x) {
    double sum = 0.0, total = 0.0;
    const int radial = 2000, angular = 20000;
    for (int i = 0; i < radial; ++i) {
      const double phi = 0.5 * std::numbers::pi * (i + 0.5) / radial;
      const double r = a * std::sin(phi);
      const double w = punch_pressure_shape(s, r / a, 1.0) * r * std::cos(phi);
      double ring = 0.0;
      for (int j = 0; j < angular; ++j) {
        const double d2 = rho * rho + r * r + 2.0 * rho * r * std::cos(std::numbers::pi * (j + 0.5) / angular);
        ring += 1.0 / std::sqrt(d2 - x * x);
      }
      sum += w * ring / angular;
      total += w;
    }
    return sum / total;
  };
  for (const int s : {2, 4}) {
    const SpotAverage spot(s);
    for (const double ratio : {0.5, 0.9, 0.99}) {
      const double rho = 1.0 / std::numbers::sqrt2;
      const double x = 0.3;
      const double a = ratio * (rho - x);
      const double rule = spot([x](double r) { return 1.0 / std::sqrt(r * r - x * x); }, rho, a, x);
      EXPECT_NEAR(rule / brute(s, rho, a, x), 1.0, 1e-8) << "s = " << s << ", a/d = " << ratio;
    }
  }
}

TEST(ShellSums, the_tables_equal_the_direct_sums) {
  // Random radii over the tables. reach (x + y up to the merge margin), both sums, for the
  // refined default's D and a small one, s = 1 and 2.
  std::mt19937_64 random(12);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const auto& [s, D] : {std::pair{2, 200}, std::pair{1, 6}}) {
    const ShellSums sums(s, Localization{D, true});
    for (int k = 0; k < 100; ++k) {
      const double x = 0.49 * unit(random);
      const ShellSums::Sums table = sums.same(x);
      const ShellSums::Sums exact = sums.same_direct(x);
      EXPECT_NEAR(table.carried, exact.carried, ShellSums::kTableTolerance) << "x = " << x;
      EXPECT_NEAR(table.depth, exact.depth, ShellSums::kTableTolerance * (1.0 + exact.depth)) << "x = " << x;
      const double y = 0.5 * unit(random);
      const double x2 = std::min(0.5, unit(random) * (Localization::kMergeMargin / std::numbers::sqrt2 - y));
      const ShellSums::Sums cross = sums.cross(x2, y);
      const ShellSums::Sums cross_exact = sums.cross_direct(x2, y);
      EXPECT_NEAR(cross.carried, cross_exact.carried, ShellSums::kTableTolerance) << "x = " << x2 << ", y = " << y;
      EXPECT_NEAR(cross.depth, cross_exact.depth, ShellSums::kTableTolerance * (1.0 + cross_exact.depth))
          << "x = " << x2 << ", y = " << y;
    }
  }
}

TEST(ShellSums, saved_tables_read_back_bit_for_bit_and_stale_ones_are_refused) {
  // The tables a cache keeps between processes (tables() / from_tables()): read back they
  // give the same bits; another construction's, a damaged or a cut table is refused.
  const Localization six{6, true};
  const ShellSums built(1, six);
  const std::vector<double> saved = built.tables();
  ASSERT_FALSE(saved.empty());
  const std::optional<ShellSums> read = ShellSums::from_tables(1, six, saved);
  ASSERT_TRUE(read.has_value());
  EXPECT_EQ(read->tables(), saved);
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> unit(0.0, 0.34);
  for (int k = 0; k < 50; ++k) {
    const double x = unit(random);
    const double y = unit(random);
    EXPECT_EQ(read->same(x).carried, built.same(x).carried);
    EXPECT_EQ(read->same(x).depth, built.same(x).depth);
    EXPECT_EQ(read->cross(x, y).carried, built.cross(x, y).carried);
    EXPECT_EQ(read->cross(x, y).depth, built.cross(x, y).depth);
  }
  EXPECT_FALSE(ShellSums::from_tables(2, six, saved).has_value());                 // another s
  EXPECT_FALSE(ShellSums::from_tables(1, Localization{7, true}, saved).has_value());  // another D
  EXPECT_FALSE(ShellSums::from_tables(1, Localization{6, false}, saved).has_value()); // point loads
  std::vector<double> cut(saved.begin(), saved.end() - 1);
  EXPECT_FALSE(ShellSums::from_tables(1, six, cut).has_value());
  std::vector<double> longer = saved;
  longer.push_back(0.0);
  EXPECT_FALSE(ShellSums::from_tables(1, six, longer).has_value());
  // The far table's constant term (the last 512 numbers are the cross far table) off by
  // 1e-6: the sums no longer meet the direct ones.
  std::vector<double> damaged = saved;
  damaged[damaged.size() - 512] += 1e-6;
  EXPECT_FALSE(ShellSums::from_tables(1, six, damaged).has_value());
  EXPECT_FALSE(ShellSums::from_tables(1, six, {}).has_value());
  EXPECT_EQ(ShellSums::table_name(2, parse_localization("refined")), "shell_sums-s2-shells_200");
}

namespace {

/// The tables with every near patch's coefficients scaled by `factor`, except the patches
/// that hold the three radii from_tables checks at fixed points (same: x = 0.2; cross:
/// t = x / (0.98/sqrt 2 - y) at (0.2, 0.15) and (0.3, 0.3)): the probe's forgery of issue 22,
/// which a recomputed checksum would let through. Layout as ShellSums::tables() writes it.
std::vector<double> forged(std::vector<double> tables, double factor) {
  std::size_t at = 16;  // the header
  const double edge = Localization::kMergeMargin / std::numbers::sqrt2;
  const double fixed[2][2] = {{0.2, 0.2}, {0.2 / (edge - 0.15), 0.3 / (edge - 0.3)}};
  for (int k = 0; k < 2; ++k) {
    const auto patches = static_cast<std::size_t>(tables[at++]);
    for (std::size_t i = 0; i < patches; ++i) {
      const double lo = tables[at], hi = tables[at + 1];
      const auto size = static_cast<std::size_t>(tables[at + 2]);
      at += 3;
      const bool checked = (fixed[k][0] >= lo && fixed[k][0] <= hi) || (fixed[k][1] >= lo && fixed[k][1] <= hi);
      if (!checked) {
        for (std::size_t j = 0; j < size; ++j) tables[at + j] *= factor;
      }
      at += size;
    }
  }
  return tables;
}

}  // namespace

TEST(ShellSums, a_forged_table_with_a_valid_checksum_is_refused_by_random_direct_evaluation) {
  // Issue 22: coefficients scaled by 1.002 away from the three fixed radii moved the paper
  // point's t* from 0.8301 to 0.7748, believed. from_tables now also compares the tables
  // with the direct sums at points drawn at random in every process, one in every patch.
  const Localization six{6, true};
  const ShellSums built(1, six);
  const std::vector<double> saved = built.tables();
  const std::vector<double> forgery = forged(saved, 1.002);
  ASSERT_NE(forgery, saved);
  for (int run = 0; run < 5; ++run) EXPECT_FALSE(ShellSums::from_tables(1, six, forgery).has_value());
  // Honest tables pass the random checks whatever the draw (here 200 seeds), so a cache is
  // never rebuilt for nothing; a forgery of 1e-6 relative fails every one of them.
  const std::optional<ShellSums> honest = ShellSums::from_tables(1, six, saved);
  ASSERT_TRUE(honest.has_value());
  const std::optional<ShellSums> slight = ShellSums::from_tables(1, six, forged(saved, 1.0 + 1e-12));
  int caught = 0;
  const std::vector<double> small_forgery = forged(saved, 1.0 + 1e-6);
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    EXPECT_TRUE(honest->spot_check(seed)) << "seed " << seed;
    if (slight) {
      EXPECT_TRUE(slight->spot_check(seed)) << "seed " << seed;  // within the tables' own accuracy
    }
  }
  for (int run = 0; run < 20; ++run) caught += ShellSums::from_tables(1, six, small_forgery).has_value() ? 0 : 1;
  EXPECT_EQ(caught, 20);
}

TEST(Localization, parses_its_spellings_and_refuses_others) {
  EXPECT_TRUE(parse_localization("paper").is_paper());
  EXPECT_TRUE(parse_localization("point-shells:2").is_paper());
  const Localization k = parse_localization("shells:30");
  EXPECT_EQ(k.shells, 30);
  EXPECT_TRUE(k.distributed);
  EXPECT_EQ(k.spelling(), "shells:30");
  EXPECT_FALSE(parse_localization("point-shells:3").distributed);
  const Localization refined = parse_localization("refined");
  EXPECT_EQ(refined.spelling(), "shells:" + std::to_string(Localization::kRefinedShells));
  const Localization periodic = parse_localization("periodic");
  EXPECT_TRUE(periodic.periodic);
  EXPECT_FALSE(periodic.is_paper());
  EXPECT_EQ(periodic.spelling(), "periodic");
  EXPECT_TRUE(std::isinf(periodic.merge_margin()));
  for (const char* bad : {"shells:0", "shells:", "shells:3x", "shells:1001", "refine", "periodical", ""}) {
    try {
      parse_localization(bad);
      ADD_FAILURE() << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("= point-shells:2), refined (= shells:200, "), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("valid: periodic"), std::string::npos) << e.what();
    }
  }
}

// The two-level family: D = 2 distances of point loads is the paper's elastic two-level
// state (eqs 9.12-9.15, Table 9.1, solved by ElasticTwoLevel); D = 20 distributed equals the
// Python study (localization_shells.two_level) at two of its points.
TEST(TwoLevelShells, two_distances_of_point_loads_are_the_papers_elastic_state) {
  for (const auto& [l, dh, pbar] : {std::tuple{0.75, 0.05, 0.06}, std::tuple{1.25, 0.05, 0.025},
                                    std::tuple{1.0, 0.02, 0.06}}) {
    const ContactProblem p{l, dh, pbar, Shape{2, 0.5}};
    const ElasticTwoLevel paper = solve_elastic_two_level(p, 1.0);
    ASSERT_TRUE(paper.converged && paper.level2_touches);
    const TwoLevelShells shells(p, Localization{2, false});
    const TwoLevelSolve r = shells.solve(pbar, TwoLevelState{paper.state.a1, paper.state.a2, 0.0, 0.0});
    ASSERT_TRUE(r.converged);
    EXPECT_NEAR(r.state.a1 / paper.state.a1, 1.0, 1e-10);
    EXPECT_NEAR(r.state.a2 / paper.state.a2, 1.0, 1e-9);
    EXPECT_NEAR(r.state.Q1 / paper.state.Q1, 1.0, 1e-10);
    const NominalRadii A = shells.radii(r.state, pbar);
    EXPECT_NEAR(A.A1 / paper.radii.A1, 1.0, 1e-10);
    EXPECT_NEAR(A.A2 / paper.radii.A2, 1.0, 1e-10);
  }
}

TEST(TwoLevelShells, twenty_distances_distributed_equal_the_python_study) {
  struct Case {
    double l, dh, X, a1, a2, Q1;
  };
  for (const Case& c : {Case{0.75, 0.05, 0.06, 0.2795406117475716, 0.06914789241474505, 0.03319329985717882},
                        Case{1.25, 0.05, 0.025, 0.29411650707050113, 0.14175976069728735, 0.03505533767637511}}) {
    const ContactProblem p{c.l, c.dh, c.X, Shape{2, 0.5}};
    const TwoLevelSolve r =
        TwoLevelShells(p, Localization{20, true}).solve(c.X, TwoLevelState{c.a1 * 1.02, c.a2 * 0.9, 0.0, 0.0});
    ASSERT_TRUE(r.converged);
    EXPECT_NEAR(r.state.a1 / c.a1, 1.0, 1e-10);
    EXPECT_NEAR(r.state.a2 / c.a2, 1.0, 1e-9);
    EXPECT_NEAR(r.state.Q1 / c.Q1, 1.0, 1e-10);
  }
}
