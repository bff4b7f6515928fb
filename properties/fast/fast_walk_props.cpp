// SPDX-License-Identifier: MIT
// Properties: for every instruction set this processor runs, the fast traversal emits exactly
// the plain walks' pixels (and sample masks) in the same order, and fast_count_covered counts
// them, on random, tie-heavy and extreme triangles (vertices anywhere in SNAP.VERTEX.RANGE, at
// its ends, slivers whose lane steps approach 2^24, where the 32-bit lane form is at its
// limits), at pixel centres and for standard, centre and custom sample patterns.
// Implements (properties for): FAST.EQUALS.PLAIN, FAST.TILE.CLASSIFY, FAST.LANE.I32,
//   FAST.ISA.DISPATCH

#include <cstdint>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "fast_gen.hpp"
#include "rastrules/raster/fast.hpp"
#include "rastrules/raster/walk.hpp"
#include "rastrules/raster/walk_msaa.hpp"

namespace {

namespace fg = rastrules::fast_gen;
namespace mg = rastrules::msaa_gen;
namespace raster = rastrules::raster;
using rastrules::Isa;

using Px = std::pair<std::int32_t, std::int32_t>;                       // y, x
using MaskedPx = std::tuple<std::int32_t, std::int32_t, std::uint32_t>; // y, x, mask

rc::Gen<std::int32_t> side() {
  return mg::full_size(rc::gen::weightedOneOf<std::int32_t>(
      {{3, rc::gen::inRange<std::int32_t>(1, 80)},
       {2, rc::gen::inRange<std::int32_t>(80, 260)},
       {1, rc::gen::element<std::int32_t>(1, 15, 16, 17, 63, 64, 65, 128)}}));
}

// rule: FAST.EQUALS.PLAIN, FAST.TILE.CLASSIFY, FAST.LANE.I32, FAST.ISA.DISPATCH
RC_GTEST_PROP(FastWalk, EveryIsaEmitsThePlainWalksPixelsInOrder, ()) {
  const std::int32_t w = *side(), h = *side();
  const rastrules::RasterState state = *rastrules::gen::raster_state();
  const fg::GenTri g = *fg::triangle(w, h);
  RC_TAG(fg::to_string(g.shape));
  const rastrules::TriangleSetup t = fg::setup(g, state);
  std::vector<Px> plain;
  raster::walk_triangle(t, w, h, [&](std::int32_t x, std::int32_t y) { plain.emplace_back(y, x); });
  RC_CLASSIFY(!plain.empty(), "covers some pixel");
  const raster::FastTileCounts c = raster::fast_tile_counts(t, w, h);
  RC_CLASSIFY(c.accepted > 0, "a tile accepted whole");
  RC_CLASSIFY(c.rejected > 0, "a tile rejected whole");
  for (Isa isa : fg::supported_isas()) {
    std::vector<Px> fast;
    raster::walk_triangle_fast(t, w, h, isa,
                               [&](std::int32_t x, std::int32_t y) { fast.emplace_back(y, x); });
    if (fast != plain) {
      RC_FAIL(std::string(rastrules::to_string(isa)) + ": fast " + std::to_string(fast.size()) +
              " pixels, plain " + std::to_string(plain.size()) + "; " + fg::show(g, w, h));
    }
    RC_ASSERT(raster::fast_count_covered(t, w, h, isa) == plain.size());
    // As runs (walk_triangle_fast_row_runs): maximal in their row, rows and runs in order,
    // the same pixels.
    std::vector<Px> from_runs;
    std::int32_t last_y = -1, last_end = -1;
    raster::walk_triangle_fast_row_runs(
        t, w, h, 0, h - 1, isa, [&](std::int32_t y, std::int32_t x, std::int32_t n) {
          RC_ASSERT(n >= 1);
          RC_ASSERT(y > last_y || (y == last_y && x > last_end + 1)); // in order, maximal
          for (std::int32_t k = 0; k < n; ++k)
            from_runs.emplace_back(y, x + k);
          last_y = y;
          last_end = x + n - 1;
        });
    RC_ASSERT(from_runs == plain);
  }
}

// rule: FAST.EQUALS.PLAIN, FAST.ISA.DISPATCH, MSAA.COVER.SAMPLE
RC_GTEST_PROP(FastWalk, EveryIsaEmitsThePlainSampleWalksMasksInOrder, ()) {
  const std::int32_t w = *side(), h = *side();
  const rastrules::RasterState state = *rastrules::gen::raster_state();
  const mg::Pattern pattern = *mg::any_pattern();
  const fg::GenTri g = *fg::triangle(w, h);
  RC_TAG(pattern.name());
  RC_CLASSIFY(g.shape == fg::Shape::kTies, "tie-heavy");
  const rastrules::TriangleSetup t = fg::setup(g, state);
  std::vector<MaskedPx> plain;
  raster::walk_triangle_samples(
      t, pattern.kernel, w, h,
      [&](std::int32_t x, std::int32_t y, std::uint32_t m) { plain.emplace_back(y, x, m); });
  for (Isa isa : fg::supported_isas()) {
    std::vector<MaskedPx> fast;
    raster::walk_triangle_samples_fast(
        t, pattern.kernel, w, h, isa,
        [&](std::int32_t x, std::int32_t y, std::uint32_t m) { fast.emplace_back(y, x, m); });
    if (fast != plain) {
      RC_FAIL(std::string(rastrules::to_string(isa)) + " " + pattern.name() + ": fast " +
              std::to_string(fast.size()) + " pixels, plain " + std::to_string(plain.size()) +
              "; " + fg::show(g, w, h));
    }
  }
}

} // namespace
