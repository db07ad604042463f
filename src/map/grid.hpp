#pragma once
/// @file
/// The grid a sweep covers: an ordered list of named axes (slowest first), each taken from
/// a model parameter that the chosen contact problem and creep law declare sweepable
/// (model::sweep_axes; for the standard linear solid l, dh, T, pbar, s). Points and tiles
/// are addressed row-major over the axes in that order.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace punchsweep::map {

/// A position on the grid, or a shape: one entry per axis, in the grid's axis order.
using Index = std::vector<std::size_t>;

/// One axis: its name (a model parameter's), its values (strictly increasing) and the text
/// they were given as.
struct Axis {
  std::string name;          ///< "l", "dh", "T", "pbar", "s", ...
  std::vector<double> values;
  std::string text;          ///< e.g. "linspace(0.5, 1.25, 16)" or "2, 5, 10"
  bool log_spaced = false;   ///< given by logspace(): plots use a log axis
  /// A categorical axis (the materials of a sweep): one label per value, the values being
  /// 0, 1, ...; empty for a numeric axis.
  std::vector<std::string> labels = {};
};

/// The grid: the product of its axes.
struct Grid {
  std::vector<Axis> axes;

  std::size_t rank() const { return axes.size(); }
  Index shape() const {
    Index n(axes.size());
    for (std::size_t a = 0; a < axes.size(); ++a) n[a] = axes[a].values.size();
    return n;
  }
  /// The number of points; 0 for a grid without axes.
  std::size_t points() const {
    std::size_t n = axes.empty() ? 0 : 1;
    for (const Axis& axis : axes) n *= axis.values.size();
    return n;
  }
  /// The position of the axis called `name`, or rank() when there is none.
  std::size_t find(std::string_view name) const {
    std::size_t a = 0;
    while (a < axes.size() && axes[a].name != name) ++a;
    return a;
  }
  /// Row-major flat index of the point at `at`.
  std::uint64_t flat_index(const Index& at) const {
    std::uint64_t g = 0;
    for (std::size_t a = 0; a < axes.size(); ++a) g = g * axes[a].values.size() + at[a];
    return g;
  }
  /// The position of the point with row-major flat index `flat`.
  Index position(std::uint64_t flat) const {
    Index at(axes.size());
    for (std::size_t a = axes.size(); a-- > 0; flat /= axes[a].values.size()) at[a] = flat % axes[a].values.size();
    return at;
  }
};

/// A chunk-aligned box of the grid: [start, start + count) on each axis.
struct TileBox {
  Index start;
  Index count;

  std::size_t points() const {
    std::size_t n = 1;
    for (const std::size_t c : count) n *= c;
    return n;
  }
  /// The grid position of the box's i-th point (row-major over the box).
  Index position(std::size_t i) const {
    Index at(count.size());
    for (std::size_t a = count.size(); a-- > 0; i /= count[a]) at[a] = start[a] + i % count[a];
    return at;
  }
  /// The one-point box at `at`.
  static TileBox point(const Index& at) { return TileBox{at, Index(at.size(), 1)}; }
};

}  // namespace punchsweep::map
