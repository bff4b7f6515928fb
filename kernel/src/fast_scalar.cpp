// SPDX-License-Identifier: MIT
// The fast traversal's scalar lanes (FAST.ISA.DISPATCH): the lane form of FAST.LANE.I32 in
// plain int32 arithmetic, 16 lanes per tile row stepped by B per row. Compiled for the baseline
// instruction set; the reference the AVX2 and AVX-512 units must equal.
// Implements: FAST.LANE.I32, FAST.TILE.CLASSIFY, FAST.ISA.DISPATCH

#include <cstddef>
#include <cstdint>

#include "fast_tiles.hpp"
#include "rastrules/formula/lane.hpp"

namespace rastrules::raster::fast_detail {

namespace {

struct ScalarKernel {
  std::int32_t a[3];
  std::int32_t b[3];
  std::int32_t base[3][kTile]; // lane_offset(i, 0) = i A

  ScalarKernel(const std::int32_t (&a_)[3], const std::int32_t (&b_)[3]) : a{}, b{}, base{} {
    for (int k = 0; k < 3; ++k) {
      a[k] = a_[k];
      b[k] = b_[k];
      for (std::int32_t i = 0; i < kTile; ++i)
        base[k][i] = formula::lane_offset<std::int32_t>(i, 0, a[k], b[k]);
    }
  }

  // rule: FAST.LANE.I32
  template <class Sink>
  void tile(const std::int32_t c[3], std::int32_t j0, std::int32_t j1, std::uint32_t cols,
            Sink& sink, std::int32_t tx, std::int32_t ty) const {
    // L(i, j) = i A + j B (formula::lane_offset) for the 16 lanes of row j, compared with the
    // threshold as the lane form states it: L >= C. |L| < 2^29 (FAST.LANE.I32); the row offset
    // j B is stepped by B, and j <= 15 where it is used.
    std::int32_t jb[3] = {j0 * b[0], j0 * b[1], j0 * b[2]};
    for (std::int32_t j = j0; j <= j1; ++j) {
      std::uint32_t bits = 0;
      for (std::int32_t i = 0; i < kTile; ++i) {
        const bool in = (base[0][i] + jb[0] >= c[0]) & (base[1][i] + jb[1] >= c[1]) &
                        (base[2][i] + jb[2] >= c[2]);
        bits |= static_cast<std::uint32_t>(in) << i;
      }
      sink.row(tx, ty + j, bits & cols);
      for (int k = 0; k < 3; ++k)
        jb[k] += b[k];
    }
  }
};

} // namespace

const Lanes kScalarLanes = lanes_of<ScalarKernel>();

TileCounts tile_counts_scalar(const FastEdges& f, PixelRect r) {
  ClassSink sink;
  drive<ScalarKernel>(f, r, sink);
  return sink.counts;
}

} // namespace rastrules::raster::fast_detail
