#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace punchsweep::sweep {

/// The five swept axes, in the order of the map's dimensions (slowest first).
inline constexpr std::size_t kAxes = 5;
enum AxisIndex : std::size_t { kAxisL = 0, kAxisDh = 1, kAxisT = 2, kAxisPbar = 3, kAxisS = 4 };
inline constexpr std::array<const char*, kAxes> kAxisNames{"l", "dh", "T", "pbar", "s"};

/// One axis: its values (strictly increasing) and the text they were given as.
struct Axis {
  std::vector<double> values;
  std::string text;          ///< e.g. "linspace(0.5, 1.25, 16)" or "2, 5, 10"
  bool log_spaced = false;   ///< given by logspace(): plots use a log axis
};

/// The 5-D grid over (l, dh, T, pbar, s); s values are integers stored as doubles.
struct Grid {
  std::array<Axis, kAxes> axes;

  std::array<std::size_t, kAxes> shape() const {
    std::array<std::size_t, kAxes> n{};
    for (std::size_t a = 0; a < kAxes; ++a) n[a] = axes[a].values.size();
    return n;
  }
  std::size_t points() const {
    std::size_t n = 1;
    for (const Axis& axis : axes) n *= axis.values.size();
    return n;
  }
};

/// A chunk-aligned box of the grid: [start, start + count) on each axis.
struct TileBox {
  std::array<std::size_t, kAxes> start{};
  std::array<std::size_t, kAxes> count{};

  std::size_t points() const {
    std::size_t n = 1;
    for (const std::size_t c : count) n *= c;
    return n;
  }
};

}  // namespace punchsweep::sweep
