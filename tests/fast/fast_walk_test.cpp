// SPDX-License-Identifier: MIT
// The fast traversal against the plain walks on hand-made cases: whole tiles accepted and
// rejected, ties on inclusive and exclusive edges inside a partial tile, tile borders, the far
// corner of the largest target, vertices at the ends of the snapped range, slivers whose steps
// are near 2^24, fast_cover_rect's bit layout, and every instruction set and sample pattern.

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "fast_support.hpp"
#include "rastrules/fixed.hpp"
#include "rastrules/formula/lane.hpp"
#include "rastrules/msaa.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

TriangleSetup raw_triangle(std::int32_t ax, std::int32_t ay, std::int32_t bx, std::int32_t by,
                           std::int32_t cx, std::int32_t cy, const RasterState& state = {}) {
  const auto v = [](std::int32_t x, std::int32_t y) {
    return Vec2{Subpixel::from_raw(x), Subpixel::from_raw(y)};
  };
  return setup_triangle({v(ax, ay), v(bx, by), v(cx, cy)}, state);
}

// A classification's counts {accepted, rejected, partial}: of tiles, and of 64 x 64 blocks.
using Counts = std::array<std::uint64_t, 3>;
Counts tiles(const raster::FastTileCounts& c) {
  return {c.accepted, c.rejected, c.partial};
}
Counts blocks(const raster::FastTileCounts& c) {
  return {c.blocks_accepted, c.blocks_rejected, c.blocks_partial};
}

// Every supported instruction set: the fast walk emits the plain walk's pixels in its order,
// and fast_count_covered counts them.
void expect_fast_equals_plain(const TriangleSetup& t, std::int32_t w, std::int32_t h) {
  const std::vector<Pixel> plain = walk_pixels(t, w, h);
  for (Isa isa : supported_isas()) {
    EXPECT_EQ(fast_pixels(t, w, h, isa), plain) << isa_name(isa);
    EXPECT_EQ(raster::fast_count_covered(t, w, h, isa), plain.size()) << isa_name(isa);
  }
}

// rule: FAST.TILE.CLASSIFY, FAST.EQUALS.PLAIN
TEST(FastTileClassify, TilesInsideATriangleAreAcceptedWhole) {
  // Larger than a 64 x 64 target on every side: all 16 tiles accepted, no lane tested.
  const TriangleSetup t = triangle_px({-10, -10}, {200, -10}, {-10, 200});
  const raster::FastTileCounts c = raster::fast_tile_counts(t, 64, 64);
  EXPECT_EQ(tiles(c), (Counts{16, 0, 0}));
  for (Isa isa : supported_isas())
    EXPECT_EQ(raster::fast_count_covered(t, 64, 64, isa), 64u * 64u);
  expect_fast_equals_plain(t, 64, 64);
}

// rule: FAST.TILE.CLASSIFY, FAST.EQUALS.PLAIN
TEST(FastTileClassify, TilesBeyondTheHypotenuseAreRejectedAndCrossedOnesTestedPerLane) {
  // x >= 0, y >= 0, x + y <= 64 on a 64 x 64 target; tile (a, b) spans centre sums
  // 16 (a + b) + 1 .. 16 (a + b) + 31: a + b <= 2 inside (6 tiles), a + b >= 4 outside
  // (6 tiles), a + b == 3 crossed (4 tiles), with centres exactly on the hypotenuse.
  const TriangleSetup t = triangle_px({0, 0}, {64, 0}, {0, 64});
  const raster::FastTileCounts c = raster::fast_tile_counts(t, 64, 64);
  EXPECT_EQ(tiles(c), (Counts{6, 6, 4}));
  expect_fast_equals_plain(t, 64, 64);
  // The bounding box decides which tiles are looked at: a triangle in one tile classifies one.
  const raster::FastTileCounts one =
      raster::fast_tile_counts(triangle_px({17, 17}, {30, 18}, {20, 29}), 64, 64);
  EXPECT_EQ(one.accepted + one.rejected + one.partial, 1u);
}

// rule: FAST.TILE.CLASSIFY, FAST.EQUALS.PLAIN
TEST(FastTileClassify, BlocksOf64PixelsAreDecidedBeforeTheirTiles) {
  // x >= 0, y >= 0, x + y <= 256 on a 256 x 256 target: 16 blocks of 64 x 64. Block (a, b)
  // spans centre sums 64 (a + b) + 1 .. 64 (a + b) + 127: a + b <= 2 inside (6 blocks, 96
  // tiles accepted without a lane), a + b >= 4 outside (6 blocks, 96 tiles rejected), a + b == 3
  // crossed (4 blocks whose 64 tiles are classified one by one: the 6 accepted, 6 rejected and
  // 4 per-lane tiles of each 64 x 64 hypotenuse, as in the test above).
  const TriangleSetup t = triangle_px({0, 0}, {256, 0}, {0, 256});
  const raster::FastTileCounts c = raster::fast_tile_counts(t, 256, 256);
  EXPECT_EQ(blocks(c), (Counts{6, 6, 4}));
  EXPECT_EQ(tiles(c), (Counts{6 * 16 + 4 * 6, 6 * 16 + 4 * 6, 4 * 4}));
  expect_fast_equals_plain(t, 256, 256);
  // Bounds within one block are not classified as a block (never decided whole).
  const raster::FastTileCounts small =
      raster::fast_tile_counts(triangle_px({3, 3}, {60, 5}, {9, 50}), 256, 256);
  EXPECT_EQ(small.blocks_accepted + small.blocks_rejected, 0u);
  EXPECT_EQ(small.blocks_partial, 1u);
}

// rule: FAST.TILE.CLASSIFY, FAST.EQUALS.PLAIN, TRI.FILL.TOP_LEFT
TEST(FastTileClassify, TiesInAPartialTileFollowTheFillRule) {
  // Edges through pixel centres: the top edge y = 2.5 and the left edge x = 2.5 are inclusive,
  // the diagonal x + y = 15 (running down-left) exclusive.
  {
    const TriangleSetup t = triangle_px({2.5, 2.5}, {12.5, 2.5}, {2.5, 12.5});
    std::vector<Pixel> want;
    for (std::int32_t y = 2; y < 16; ++y)
      for (std::int32_t x = 2; x < 16; ++x)
        if (x + y < 14)
          want.push_back(Pixel{x, y});
    for (Isa isa : supported_isas())
      EXPECT_EQ(fast_pixels(t, 16, 16, isa), want) << isa_name(isa);
    EXPECT_EQ(walk_pixels(t, 16, 16), want);
  }
  // The bottom edge y = 12.5 (running -x) and the diagonal y = x (running down) are exclusive.
  {
    const TriangleSetup t = triangle_px({2.5, 2.5}, {12.5, 12.5}, {2.5, 12.5});
    std::vector<Pixel> want;
    for (std::int32_t y = 2; y < 12; ++y)
      for (std::int32_t x = 2; x < y; ++x)
        want.push_back(Pixel{x, y});
    for (Isa isa : supported_isas())
      EXPECT_EQ(fast_pixels(t, 16, 16, isa), want) << isa_name(isa);
    EXPECT_EQ(walk_pixels(t, 16, 16), want);
  }
  // The same shapes under the other fill conventions.
  for (FillConvention f : kAllConventions) {
    RasterState s;
    s.fill = f;
    expect_fast_equals_plain(triangle_px({2.5, 2.5}, {12.5, 2.5}, {2.5, 12.5}, s), 16, 16);
    expect_fast_equals_plain(triangle_px({2.5, 2.5}, {12.5, 12.5}, {2.5, 12.5}, s), 16, 16);
  }
}

// rule: FAST.EQUALS.PLAIN, FAST.TILE.CLASSIFY
TEST(FastEqualsPlain, TrianglesCrossingTileBordersOnUnalignedTargets) {
  expect_fast_equals_plain(triangle_px({5.3125, 7.125}, {40.6875, 13.1875}, {20.0625, 45.875}), 64,
                           64);
  expect_fast_equals_plain(triangle_px({5.3125, 7.125}, {40.6875, 13.1875}, {20.0625, 45.875}), 37,
                           29);
  expect_fast_equals_plain(triangle_px({15.5, 15.5}, {16.5, 15.5}, {15.5, 16.5}), 40, 40);
  expect_fast_equals_plain(triangle_px({-20, 3}, {150, 60.25}, {70, 140}), 100, 70);
  // Wider than 64 pixels: a bit row spans several words, tiles straddle word borders.
  expect_fast_equals_plain(triangle_px({3.6875, 1}, {250.1875, 40.5}, {1, 80}), 300, 90);
  // Wider than 2048 pixels: a strip of one tile row no longer fits the walk's stack buffer.
  const TriangleSetup wide = triangle_px({-5, 2.5}, {3001.25, 20}, {700.5, 70.75});
  expect_fast_equals_plain(wide, 3000, 64);
  for (std::uint32_t n : {4u, 16u}) {
    const SamplePattern p = standard_pattern(n);
    for (Isa isa : supported_isas())
      EXPECT_EQ(fast_samples(wide, p, 3000, 64, isa), plain_samples(wide, p, 3000, 64)) << n;
  }
}

// rule: FAST.EQUALS.PLAIN
TEST(FastEqualsPlain, TheFarCornerOfTheLargestTarget) {
  const std::int32_t s = kMaxTargetSide;
  expect_fast_equals_plain(triangle_px({16370.5, 16371}, {16384, 16384}, {16372, 16390}), s, s);
  expect_fast_equals_plain(triangle_px({16300, 16383.5}, {16400, 16383.5}, {16383.5, 16300}), s, s);
  // The whole target: every tile accepted, 2^28 pixels counted without a lane test.
  const TriangleSetup all = triangle_px({32767, 32767}, {-32768, 32767}, {32767, -32768});
  const raster::FastTileCounts c = raster::fast_tile_counts(all, s, s);
  EXPECT_EQ(c.accepted, std::uint64_t{1024} * 1024);
  EXPECT_EQ(c.rejected + c.partial, 0u);
  for (Isa isa : supported_isas())
    EXPECT_EQ(raster::fast_count_covered(all, s, s, isa), std::uint64_t{1} << 28) << isa_name(isa);
}

// rule: FAST.LANE.I32, FAST.EQUALS.PLAIN
TEST(FastLaneI32, VerticesAtTheEndsOfTheSnappedRange) {
  const std::int32_t lo = kMinVertexRaw, hi = kMaxVertexRaw;
  // Edge values at the target reach 2^47: the lane threshold is clamped to 2^30.
  expect_fast_equals_plain(raw_triangle(lo, lo, hi, lo, lo, hi), 300, 200);
  expect_fast_equals_plain(raw_triangle(hi, hi, lo, hi, hi, lo), 300, 200);
  expect_fast_equals_plain(raw_triangle(lo, lo, hi, hi, lo, hi), 257, 255);
  expect_fast_equals_plain(raw_triangle(lo, lo, hi, hi, hi, lo), 257, 255);
  // An edge through the target from one end of the range to the other.
  expect_fast_equals_plain(raw_triangle(lo, lo, hi, hi - 37, lo, hi), 200, 200);
  expect_fast_equals_plain(raw_triangle(lo, lo + 5, hi, hi, hi, lo), 200, 200);
  // The clamp itself: q far below and above +-2^30 gives the bound, in between -q.
  const auto sel = [](bool c, std::int64_t a, std::int64_t b) { return c ? a : b; };
  const std::int64_t bound = formula::kLaneBound;
  EXPECT_EQ(formula::lane_threshold<std::int64_t>(-(std::int64_t{1} << 40), bound, sel), bound);
  EXPECT_EQ(formula::lane_threshold<std::int64_t>(std::int64_t{1} << 40, bound, sel), -bound);
  EXPECT_EQ(formula::lane_threshold<std::int64_t>(5, bound, sel), -5);
}

// rule: FAST.LANE.I32, FAST.EQUALS.PLAIN
TEST(FastLaneI32, SliversWithStepsNearTwoToTheTwentyFour) {
  const std::int32_t lo = kMinVertexRaw, hi = kMaxVertexRaw;
  // Nearly vertical slivers from the top of the range to the bottom: |A| = 2^24 - 1, B a few
  // units; they cross the target a few pixels wide.
  expect_fast_equals_plain(raw_triangle(100 * 256, lo, 101 * 256 + 7, hi, 100 * 256 + 3, hi), 256,
                           256);
  expect_fast_equals_plain(raw_triangle(40 * 256 + 128, lo, 40 * 256 + 128, hi, 43 * 256 + 1, hi),
                           256, 256);
  // Nearly horizontal: |B| = 2^24 - 1.
  expect_fast_equals_plain(raw_triangle(lo, 60 * 256, hi, 60 * 256 + 300, hi, 61 * 256), 256, 256);
  expect_fast_equals_plain(raw_triangle(hi, 7 * 256 + 128, lo, 7 * 256 + 128, lo, 9 * 256 + 5), 256,
                           256);
  // A long diagonal needle through the whole target.
  expect_fast_equals_plain(raw_triangle(lo, lo, hi, hi, hi, hi - 300), 1024, 1024);
}

// Issue 17 item 2: a long diagonal sliver that covers no pixel centre cost the fast walk
// every word of its bounding box (7.6 ms on the largest target). Each strip of rows is now
// narrowed to the columns the triangle reaches there (narrow_to_rows), so it costs per row;
// the coverage stays the plain walk's, at the centres and at every sample pattern.
// rule: FAST.EQUALS.PLAIN
TEST(FastEqualsPlain, LongSliversAreNarrowedToTheirColumnsPerStrip) {
  const std::int32_t s = kMaxTargetSide;
  // y - x in [0.25, 0.254]: no pixel centre, 16384 x 16384 bounding box.
  const TriangleSetup none = triangle_px({0, 0.25}, {16384, 16384.25}, {16384, 16384.25390625});
  ASSERT_EQ(none.status, TriangleStatus::kRasterized);
  const raster::PixelRect r = raster::walk_bounds(none, s, s);
  EXPECT_EQ(r.x1 - r.x0 + 1, s);
  for (std::int32_t y0 : {0, 16, 8000, s - 16}) {
    const raster::PixelRect n = raster::narrow_to_rows(none, {r.x0, y0, r.x1, y0 + 15}, 0);
    EXPECT_EQ(n.y0, y0);
    EXPECT_EQ(n.y1, y0 + 15);
    EXPECT_LE(n.x1 - n.x0 + 1, 18) << y0; // the 16 rows' columns, not 16384
    const raster::PixelRect m = raster::narrow_to_rows(none, {r.x0, y0, r.x1, y0 + 15}, 128);
    EXPECT_LE(m.x1 - m.x0 + 1, 20) << y0;
  }
  // Rows the triangle does not reach are empty.
  const TriangleSetup small = triangle_px({10, 10}, {20, 10}, {10, 20});
  EXPECT_TRUE(raster::narrow_to_rows(small, {0, 30, 63, 45}, 0).empty());
  expect_fast_equals_plain(none, s, s);
  // Slivers that do cover a few centres, in both diagonal directions and nearly flat.
  expect_fast_equals_plain(triangle_px({0, 0.5}, {3000, 3000.5}, {3000, 3000.625}), 3000, 3000);
  expect_fast_equals_plain(triangle_px({3000, 0.5}, {0, 3000.5}, {0, 3001}), 3000, 3000);
  expect_fast_equals_plain(triangle_px({-7, 3.5}, {5000, 9.5}, {-7, 4}), 4096, 64);
  const TriangleSetup sliver = triangle_px({0, 0.1875}, {700, 700.1875}, {700, 700.875});
  for (std::uint32_t n : {2u, 4u, 16u}) {
    const SamplePattern p = standard_pattern(n);
    for (Isa isa : supported_isas())
      EXPECT_EQ(fast_samples(sliver, p, 700, 700, isa), plain_samples(sliver, p, 700, 700)) << n;
  }
}

// rule: FAST.TILE.CLASSIFY, FAST.LANE.I32
TEST(FastCoverRect, WritesEveryWordOfTheRectangleBitPerSample) {
  const TriangleSetup t = triangle_px({3.1875, 1.875}, {150.625, 20.3125}, {40.125, 33.6875});
  const raster::PixelRect r{5, 3, 141, 29}; // unaligned on every side, three words per row
  const std::size_t wpr = 3;
  const SampleOffset offsets[] = {{0, 0}, {-8, -8}, {7, 7}, {-3, 5}};
  for (Isa isa : supported_isas()) {
    for (const SampleOffset o : offsets) {
      std::vector<std::uint64_t> out(static_cast<std::size_t>(r.y1 - r.y0 + 1) * wpr,
                                     ~std::uint64_t{0});
      raster::fast_cover_rect(t, r, o.x * kSampleGridUnit, o.y * kSampleGridUnit, isa, out.data(),
                              wpr);
      for (std::int32_t y = r.y0; y <= r.y1; ++y) {
        for (std::int32_t bit = 0; bit < static_cast<std::int32_t>(64 * wpr); ++bit) {
          const std::int32_t x = r.x0 + bit;
          const std::uint64_t word =
              out[static_cast<std::size_t>(y - r.y0) * wpr + static_cast<std::size_t>(bit / 64)];
          const bool set = ((word >> (bit % 64)) & 1u) != 0;
          const bool want = x <= r.x1 && covers(t, sample_position(x, y, o));
          ASSERT_EQ(set, want) << isa_name(isa) << " x " << x << " y " << y << " offset "
                               << int{o.x} << "," << int{o.y};
        }
      }
    }
  }
}

// rule: FAST.ISA.DISPATCH, FAST.EQUALS.PLAIN
class FastIsa : public ::testing::TestWithParam<Isa> {};

TEST_P(FastIsa, EqualsThePlainWalkOnACatalog) {
  const Isa isa = GetParam();
  if (!isa_supported(isa))
    GTEST_SKIP() << "this processor (or build) has no " << isa_name(isa) << " (FAST.ISA.DISPATCH)";
  const std::vector<TriangleSetup> catalog = {
      triangle_px({1, 1}, {60, 4}, {8, 50}),
      triangle_px({60, 4}, {1, 1}, {8, 50}), // counter-clockwise
      triangle_px({0.5, 0.5}, {31.5, 0.5}, {0.5, 31.5}),
      triangle_px({16, 0}, {32, 16}, {16, 32}),
      triangle_px({-100, 10}, {300, 11}, {100, 12.5}),
      triangle_px({30.5, -50}, {31, 200}, {30.625, 200}),
      triangle_px({3, 3}, {3.00390625, 3}, {3, 60}),
  };
  for (std::size_t i = 0; i < catalog.size(); ++i) {
    const std::vector<Pixel> plain = walk_pixels(catalog[i], 64, 48);
    EXPECT_EQ(fast_pixels(catalog[i], 64, 48, isa), plain) << i;
    EXPECT_EQ(raster::fast_count_covered(catalog[i], 64, 48, isa), plain.size()) << i;
    // The scalar lanes are the reference the SIMD ones must equal (FAST.ISA.DISPATCH).
    EXPECT_EQ(fast_pixels(catalog[i], 64, 48, isa), fast_pixels(catalog[i], 64, 48, Isa::kScalar))
        << i;
  }
  // Degenerate and culled triangles emit nothing.
  RasterState cull;
  cull.cull = CullMode::kBack;
  EXPECT_TRUE(fast_pixels(triangle_px({1, 1}, {5, 5}, {9, 9}), 16, 16, isa).empty());
  EXPECT_TRUE(fast_pixels(triangle_px({60, 4}, {1, 1}, {8, 50}, cull), 64, 64, isa).empty());
  EXPECT_EQ(raster::fast_count_covered(triangle_px({1, 1}, {5, 5}, {9, 9}), 16, 16, isa), 0u);
  // Entirely outside the target.
  EXPECT_TRUE(fast_pixels(triangle_px({-50, -50}, {-10, -50}, {-50, -10}), 16, 16, isa).empty());
}

TEST_P(FastIsa, EqualsThePlainSampleWalkForEveryPattern) {
  const Isa isa = GetParam();
  if (!isa_supported(isa))
    GTEST_SKIP() << "this processor (or build) has no " << isa_name(isa) << " (FAST.ISA.DISPATCH)";
  std::vector<SamplePattern> patterns;
  for (std::uint32_t n : {1u, 2u, 4u, 8u, 16u}) {
    patterns.push_back(standard_pattern(n));
    patterns.push_back(center_pattern(n));
  }
  patterns.push_back(custom_pattern({{-8, -8}, {7, 7}, {-8, 7}, {7, -8}, {0, 0}}));
  patterns.push_back(custom_pattern({{5, 6}, {7, 7}, {6, 5}})); // hull misses the centre
  const std::vector<TriangleSetup> catalog = {
      triangle_px({1, 1}, {60, 4}, {8, 50}),
      triangle_px({0.5, 0.5}, {31.5, 0.5}, {0.5, 31.5}),
      triangle_px({15.5, 15.5}, {17, 15.5}, {15.5, 17}),
      triangle_px({0, 0}, {64, 0}, {0, 48}),
      triangle_px({-3, 47.875}, {70, 47.875}, {30, 60}), // only samples above the centre of row 47
      triangle_px({63.875, -4}, {70, 50},
                  {63.875, 50}), // only samples left of the centre of column 63
  };
  for (const SamplePattern& p : patterns) {
    for (std::size_t i = 0; i < catalog.size(); ++i) {
      EXPECT_EQ(fast_samples(catalog[i], p, 64, 48, isa), plain_samples(catalog[i], p, 64, 48))
          << to_string(p.kind) << " " << p.count() << " triangle " << i;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllIsas, FastIsa, ::testing::ValuesIn(kAllIsas),
                         [](const ::testing::TestParamInfo<Isa>& param_info) {
                           return isa_name(param_info.param);
                         });

// rule: FAST.ISA.DISPATCH
TEST(FastIsaDispatch, NamesParseAndTheBestIsTheWidestSupported) {
  for (Isa isa : kAllIsas)
    EXPECT_EQ(parse_isa(to_string(isa)), isa);
  EXPECT_EQ(to_string(Isa::kScalar), "scalar");
  EXPECT_EQ(to_string(Isa::kAvx2), "avx2");
  EXPECT_EQ(to_string(Isa::kAvx512), "avx512");
  EXPECT_EQ(parse_isa("avx"), std::nullopt);
  EXPECT_EQ(parse_isa("AVX2"), std::nullopt);
  EXPECT_EQ(parse_isa(""), std::nullopt);
  EXPECT_TRUE(isa_supported(Isa::kScalar));
  const Isa best = best_isa();
  EXPECT_TRUE(isa_supported(best));
  const Isa widest = isa_supported(Isa::kAvx512) ? Isa::kAvx512
                     : isa_supported(Isa::kAvx2) ? Isa::kAvx2
                                                 : Isa::kScalar;
  EXPECT_EQ(best, widest);
  EXPECT_EQ(effective_isa(RenderOptions{}), best);
  RenderOptions o;
  o.isa = Isa::kScalar;
  EXPECT_EQ(effective_isa(o), Isa::kScalar);
  EXPECT_EQ(RenderOptions{}.traversal, Traversal::kFast);
  EXPECT_EQ(parse_traversal("plain"), Traversal::kPlain);
  EXPECT_EQ(parse_traversal("fast"), Traversal::kFast);
  EXPECT_EQ(parse_traversal("tiled"), std::nullopt);
  EXPECT_EQ(to_string(Traversal::kPlain), "plain");
  EXPECT_EQ(to_string(Traversal::kFast), "fast");
}

} // namespace
} // namespace rastrules::test
