// SPDX-License-Identifier: MIT
// The fast traversal's entry points (FAST.ISA.DISPATCH): the exact 64-bit edge values at the
// first tile of a rectangle (the only place the fast path evaluates TRI.EDGE.FUNCTION), then
// the instruction set's lanes. Compiled for the baseline instruction set.
// Implements: FAST.ISA.DISPATCH, FAST.TILE.CLASSIFY, FAST.EQUALS.PLAIN

#include "rastrules/raster/fast.hpp"

#include "fast_tiles.hpp"
#include "rastrules/formula/edge.hpp"

namespace rastrules::raster {

namespace {

static_assert(kFastTileSize == fast_detail::kTile, "one tile size");
static_assert(kFastBlockSize == fast_detail::kBlock, "one block size");

// Returns E + bias of each edge at the sample point of the first pixel of r's first tile,
// shifted by (dx, dy) raw units, and the lane steps A and B. Tiles start at r's first pixel
// (tx0, ty0) = (r.x0, r.y0) (FAST.TILE.CLASSIFY: a triangle smaller than a tile is one tile,
// wherever it lies), which lies in [0, kMaxTargetSide) (r inside the target); |dx|, |dy| <=
// 128: the sample point lies in [0, 2^22], inside SNAP.VERTEX.RANGE, and E is exact in int64
// (FIX.BUDGET.EDGE_VALUE).
// rule: FAST.LANE.I32, FIX.BIAS.FORM
fast_detail::FastEdges prepare_edges(const TriangleSetup& t, PixelRect r, std::int32_t dx,
                                     std::int32_t dy) {
  fast_detail::FastEdges f{};
  f.tx0 = r.x0;
  f.ty0 = r.y0;
  const Vec2 s{Subpixel::from_raw(f.tx0 * kSubpixelOne + kSubpixelHalf + dx),
               Subpixel::from_raw(f.ty0 * kSubpixelOne + kSubpixelHalf + dy)};
  for (std::size_t k = 0; k < 3; ++k) {
    const EdgeSetup& e = t.edges[k];
    f.e_first[k] = e.value_at(s).raw() + formula::edge_bias<std::int64_t>(e.inclusive);
    // |A|, |B| <= 2^24 - 1 for snapped vertices (SNAP.VERTEX.RANGE): int32.
    f.a[k] = e.a.y.raw() - e.b.y.raw();
    f.b[k] = e.b.x.raw() - e.a.x.raw();
  }
  return f;
}

// The lanes of isa (FAST.ISA.DISPATCH).
const fast_detail::Lanes& lanes(Isa isa) {
  switch (isa) {
#if RASTRULES_FAST_X86
  case Isa::kAvx512:
    return fast_detail::kAvx512Lanes;
  case Isa::kAvx2:
    return fast_detail::kAvx2Lanes;
#else
  case Isa::kAvx512:
  case Isa::kAvx2: // never supported in this build (isa_supported): the same lanes, scalar
#endif
  case Isa::kScalar:
    return fast_detail::kScalarLanes;
  }
  return fast_detail::kScalarLanes;
}

} // namespace

// rule: FAST.ISA.DISPATCH, FAST.TILE.CLASSIFY, FAST.LANE.I32
void fast_cover_rect(const TriangleSetup& t, PixelRect r, std::int32_t dx, std::int32_t dy, Isa isa,
                     std::uint64_t* out, std::size_t words_per_row) {
  lanes(isa).cover_rect(prepare_edges(t, r, dx, dy), r, out, words_per_row);
}

// rule: FAST.EQUALS.PLAIN, FAST.ISA.DISPATCH
std::uint64_t fast_count_covered(const TriangleSetup& t, std::int32_t width, std::int32_t height,
                                 Isa isa) {
  const PixelRect r = walk_bounds(t, width, height);
  if (r.empty())
    return 0;
  // The whole rectangle at once, nothing stored: accepted tiles count their clipped area,
  // partial ones the popcount of each row's lane mask.
  return lanes(isa).count_rect(prepare_edges(t, r, 0, 0), r);
}

// rule: FAST.TILE.CLASSIFY
FastTileCounts fast_tile_counts(const TriangleSetup& t, std::int32_t width, std::int32_t height) {
  const PixelRect r = walk_bounds(t, width, height);
  if (r.empty())
    return {};
  const fast_detail::TileCounts c = fast_detail::tile_counts_scalar(prepare_edges(t, r, 0, 0), r);
  return FastTileCounts{c.rejected,        c.accepted,        c.partial,
                        c.blocks_rejected, c.blocks_accepted, c.blocks_partial};
}

} // namespace rastrules::raster
