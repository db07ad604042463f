#include "io/tile_encoder.hpp"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "io/map_variables.hpp"
#include "sample_tiles.hpp"

namespace punchsweep::io {
namespace {

using namespace testing;
using testing::sample_tile;

/// A 2 x 3 x 2 x 5 x 2 grid in chunks of 1 x 2 x 1 x 3 x 2: edge tiles on dh and pbar.
MapLayout test_layout(map::Quantities quantities, bool bem = false) {
  MapLayout layout;
  layout.grid = sls_grid();
  layout.grid.axes[kL] = {"l", {0.5, 1.0}, "0.5, 1", false};
  layout.grid.axes[kDh] = {"dh", {0.0, 0.05, 0.1}, "0, 0.05, 0.1", false};
  layout.grid.axes[kT] = {"T", {2.0, 5.0}, "2, 5", false};
  layout.grid.axes[kPbar] = {"pbar", {0.01, 0.02, 0.03, 0.04, 0.05}, "linspace(0.01, 0.05, 5)", false};
  layout.grid.axes[kS] = {"s", {1.0, 2.0}, "1, 2", false};
  layout.times = {0.0, 1.0, 5.0};
  layout.quantities = quantities;
  layout.chunk = {1, 2, 1, 3, 2};
  if (bem) layout.bem = BemSetup{32, 1e-10, 12, 1, "test"};
  return layout;
}

/// Every tile of the layout's chunk grid (edge tiles cut to the grid).
std::vector<map::TileBox> chunk_boxes(const MapLayout& layout) {
  const auto shape = layout.grid.shape();
  std::vector<map::TileBox> boxes;
  map::TileBox box{map::Index(kAxes), map::Index(kAxes)};
  for (box.start[0] = 0; box.start[0] < shape[0]; box.start[0] += layout.chunk[0])
    for (box.start[1] = 0; box.start[1] < shape[1]; box.start[1] += layout.chunk[1])
      for (box.start[2] = 0; box.start[2] < shape[2]; box.start[2] += layout.chunk[2])
        for (box.start[3] = 0; box.start[3] < shape[3]; box.start[3] += layout.chunk[3])
          for (box.start[4] = 0; box.start[4] < shape[4]; box.start[4] += layout.chunk[4]) {
            for (std::size_t a = 0; a < kAxes; ++a)
              box.count[a] = std::min(layout.chunk[a], shape[a] - box.start[a]);
            boxes.push_back(box);
          }
  return boxes;
}

/// Inflates a zlib stream and undoes HDF5's byte shuffle: the chunk as HDF5 reads it.
std::vector<std::byte> decode_chunk(const std::vector<std::byte>& encoded, std::size_t size,
                                    std::size_t element) {
  std::vector<std::byte> shuffled(size);
  uLongf out_size = static_cast<uLongf>(size);
  EXPECT_EQ(uncompress(reinterpret_cast<Bytef*>(shuffled.data()), &out_size,
                       reinterpret_cast<const Bytef*>(encoded.data()), static_cast<uLong>(encoded.size())),
            Z_OK);
  EXPECT_EQ(out_size, size);
  std::vector<std::byte> out(size);
  const std::size_t elements = size / element;
  for (std::size_t i = 0; i < elements; ++i) {
    for (std::size_t b = 0; b < element; ++b) out[i * element + b] = shuffled[b * elements + i];
  }
  return out;
}

/// The whole chunk that `box` (row-major values `values`, `inner` per point) fills: its
/// values where the box lies, `fill` elsewhere.
std::vector<std::byte> expected_chunk(const MapLayout& layout, const map::TileBox& box,
                                      const std::byte* values, std::size_t element, std::size_t inner,
                                      const void* fill) {
  const auto& chunk = layout.chunk;
  std::size_t cells = inner;
  for (const std::size_t c : chunk) cells *= c;
  std::vector<std::byte> out(cells * element);
  map::Index at(kAxes);
  std::size_t cell = 0;
  for (at[0] = 0; at[0] < chunk[0]; ++at[0])
    for (at[1] = 0; at[1] < chunk[1]; ++at[1])
      for (at[2] = 0; at[2] < chunk[2]; ++at[2])
        for (at[3] = 0; at[3] < chunk[3]; ++at[3])
          for (at[4] = 0; at[4] < chunk[4]; ++at[4]) {
            bool inside = true;
            std::size_t point = 0;
            for (std::size_t a = 0; a < kAxes; ++a) {
              inside = inside && at[a] < box.count[a];
              point = point * box.count[a] + at[a];
            }
            for (std::size_t t = 0; t < inner; ++t, ++cell) {
              const void* from = inside ? values + (point * inner + t) * element : fill;
              std::memcpy(out.data() + cell * element, from, element);
            }
          }
  return out;
}

TEST(TileEncoder, encoded_chunks_decode_to_the_tile_padded_with_fill_values) {
  // (quantities, BEM reference, chunks per tile): the model's 8, in full mode also its 3
  // rates of t* and 5 series; the reference's 5 + 5 and the merged answer's 3.
  for (const auto& [quantities, bem, chunks] : {std::tuple{map::Quantities::regime, false, 8U},
                                                std::tuple{map::Quantities::full, false, 16U},
                                                std::tuple{map::Quantities::regime, true, 21U},
                                                std::tuple{map::Quantities::full, true, 29U}}) {
    const MapLayout layout = test_layout(quantities, bem);
    TileEncoder encoder(layout);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<std::size_t> stored = stored_variables(layout);
    std::size_t edges = 0;
    std::uint64_t seed = 0;
    for (const map::TileBox& box : chunk_boxes(layout)) {
      edges += box.count != layout.chunk ? 1 : 0;
      const map::TileData data = sample_tile(++seed, box.points(), layout.times.size(), layout.full(), bem);
      const EncodedTile encoded = encoder.encode(seed, box, data);
      EXPECT_EQ(encoded.tile, seed);
      ASSERT_EQ(encoded.chunks.size(), chunks);
      ASSERT_EQ(stored.size(), chunks);
      for (std::size_t v = 0; v < encoded.chunks.size(); ++v) {
        const map::QuantitySpec& spec = map::kQuantities[stored[v]];
        EXPECT_EQ(spec.source != map::Source::model, v >= (layout.full() ? 16U : 8U)) << spec.name;
        const bool codes = spec.kind == map::Kind::flag;
        const std::size_t element = codes ? 1 : sizeof(double);
        const std::size_t inner = spec.extent == map::Extent::series ? layout.times.size() : 1;
        const auto* values = codes ? reinterpret_cast<const std::byte*>(data.flag(stored[v]).data())
                                   : reinterpret_cast<const std::byte*>(data.real(stored[v]).data());
        const void* fill = codes ? static_cast<const void*>(&kNotComputed) : static_cast<const void*>(&nan);
        const std::vector<std::byte> expected = expected_chunk(layout, box, values, element, inner, fill);
        EXPECT_EQ(decode_chunk(encoded.chunks[v], expected.size(), element), expected)
            << spec.name << " of tile " << seed;
      }
    }
    EXPECT_GT(edges, 0U) << "the layout must have edge tiles for this test to mean anything";
  }
}

TEST(TileEncoder, encoded_tile_summary_counts_points_per_code) {
  const MapLayout layout = test_layout(map::Quantities::regime);
  TileEncoder encoder(layout);
  for (const map::TileBox& box : chunk_boxes(layout)) {
    const map::TileData data = sample_tile(box.start[1] + 7 * box.start[3], box.points(), 0, false);
    const TileSummary summary = encoder.encode(0, box, data).summary;
    EXPECT_EQ(summary.points, box.points());
    TileSummary expected;
    for (const std::int8_t r : flag(data, "regime")) {
      if (r >= 0) ++expected.regimes[static_cast<std::size_t>(r)];
    }
    for (const std::int8_t v : flag(data, "valid")) {
      if (v >= 0) ++expected.validity[static_cast<std::size_t>(v)];
    }
    EXPECT_EQ(summary.regimes, expected.regimes);  // not_computed (-1) counts nowhere
    EXPECT_EQ(summary.validity, expected.validity);
    EXPECT_EQ(summary.bem_regimes, expected.bem_regimes);  // no reference: nothing
    EXPECT_EQ(summary.bem_agreeing, 0U);
  }
}

TEST(TileEncoder, encoded_tile_summary_counts_reference_points_and_their_agreement) {
  const MapLayout layout = test_layout(map::Quantities::regime, /*bem=*/true);
  TileEncoder encoder(layout);
  std::uint64_t agreeing = 0;
  for (const map::TileBox& box : chunk_boxes(layout)) {
    const map::TileData data = sample_tile(box.start[1] + 7 * box.start[3], box.points(), 3, false, true);
    const TileSummary summary = encoder.encode(0, box, data).summary;
    TileSummary expected;
    for (std::size_t i = 0; i < flag(data, "bem_regime").size(); ++i) {
      const std::int8_t r = flag(data, "bem_regime")[i];
      if (r < 0) continue;  // outside the sample
      ++expected.bem_regimes[static_cast<std::size_t>(r)];
      expected.bem_agreeing += r == flag(data, "regime")[i] ? 1 : 0;
    }
    EXPECT_EQ(summary.bem_regimes, expected.bem_regimes);
    EXPECT_EQ(summary.bem_agreeing, expected.bem_agreeing);
    agreeing += summary.bem_agreeing;
  }
  EXPECT_GT(agreeing, 0U);
}

TEST(TileEncoder, encoded_bytes_depend_only_on_the_tile) {
  // Any rank may encode any tile: the bytes must not depend on what the encoder did before.
  const MapLayout layout = test_layout(map::Quantities::full);
  const std::vector<map::TileBox> boxes = chunk_boxes(layout);
  TileEncoder busy(layout);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    busy.encode(i, boxes[i], sample_tile(100 + i, boxes[i].points(), 3, true));
  }
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const map::TileData data = sample_tile(i, boxes[i].points(), 3, true);
    TileEncoder fresh(layout);
    EXPECT_TRUE(fresh.encode(i, boxes[i], data) == busy.encode(i, boxes[i], data)) << "tile " << i;
  }
}

TEST(TileEncoder, encoder_refuses_boxes_that_are_not_one_chunk) {
  const MapLayout layout = test_layout(map::Quantities::regime);
  TileEncoder encoder(layout);
  const auto refused = [&](std::array<std::size_t, 5> start, std::array<std::size_t, 5> count) {
    map::TileBox box{map::Index(kAxes), map::Index(kAxes)};
    box.start.assign(start.begin(), start.end());
    box.count.assign(count.begin(), count.end());
    const map::TileData data = sample_tile(1, box.points(), 0, false);
    EXPECT_THROW(encoder.encode(0, box, data), std::invalid_argument);
  };
  refused({0, 1, 0, 0, 0}, {1, 2, 1, 3, 2});  // not chunk-aligned
  refused({0, 0, 0, 0, 0}, {1, 1, 1, 3, 2});  // part of a chunk, not at the grid's edge
  refused({0, 0, 0, 0, 0}, {1, 2, 1, 3, 1});  // s is whole in the chunk, the box has half of it
  refused({0, 0, 0, 3, 0}, {1, 2, 1, 3, 2});  // runs past the last pbar
  refused({0, 0, 0, 0, 0}, {1, 2, 1, 0, 2});  // empty
  refused({0, 0, 0, 0, 0}, {2, 2, 1, 3, 2});  // two chunks
}

TEST(TileEncoder, encoder_refuses_arrays_of_the_wrong_length_and_bad_layouts) {
  const MapLayout layout = test_layout(map::Quantities::full);
  TileEncoder encoder(layout);
  map::TileBox box{map::Index(kAxes), map::Index(kAxes)};
  box.count = layout.chunk;
  map::TileData data = sample_tile(1, box.points(), 3, true);
  EXPECT_NO_THROW(encoder.encode(0, box, data));
  real(data, "P2").pop_back();
  EXPECT_THROW(encoder.encode(0, box, data), std::invalid_argument);
  data = sample_tile(1, box.points(), 3, false);  // series missing from a full map
  EXPECT_THROW(encoder.encode(0, box, data), std::invalid_argument);
  data = sample_tile(1, box.points() - 1, 3, true);
  EXPECT_THROW(encoder.encode(0, box, data), std::invalid_argument);
  data = sample_tile(1, box.points(), 3, true, true);  // bem_* arrays for a map without them
  EXPECT_THROW(encoder.encode(0, box, data), std::invalid_argument);
  TileEncoder with_reference(test_layout(map::Quantities::full, /*bem=*/true));
  EXPECT_NO_THROW(with_reference.encode(0, box, data));
  data = sample_tile(1, box.points(), 3, true, false);  // bem_* arrays missing
  EXPECT_THROW(with_reference.encode(0, box, data), std::invalid_argument);

  MapLayout bad = layout;
  bad.chunk[kPbar] = 6;
  EXPECT_THROW(TileEncoder{bad}, std::invalid_argument);
  bad = layout;
  bad.times.clear();
  EXPECT_THROW(TileEncoder{bad}, std::invalid_argument);
}

}  // namespace
}  // namespace punchsweep::io
