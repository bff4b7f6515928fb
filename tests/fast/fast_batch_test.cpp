// SPDX-License-Identifier: MIT
// Examples of the batch counter (FAST.BATCH.*): counts of known triangles under two fill
// conventions, a watertight mesh of small triangles (overdraw exactly one), small and large
// triangles mixed, culling, clipping at the target's sides, a triangle at the 64-pixel bound of
// the small lanes, and every error it names, for every instruction set this processor runs.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fast_support.hpp"
#include "rastrules/isa.hpp"
#include "rastrules/raster/fast_batch.hpp"

namespace {

namespace raster = rastrules::raster;
using raster::BatchStatus;
using raster::fast_count_batch;
using rastrules::FillConvention;
using rastrules::Isa;
using rastrules::RasterState;

// rule: FAST.BATCH.EQUALS.PLAIN, TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION
TEST(FastBatch, CountsTheCentresOfARightTriangleUnderTwoConventions) {
  // (0,0) (4,0) (0,4): centres with i + j <= 2 are inside (6); the 4 on the hypotenuse
  // (i + j == 3) are on an edge that runs down-left: exclusive under top-left, inclusive under
  // bottom-right.
  const std::vector<float> xy = {0, 0, 4, 0, 0, 4};
  for (Isa isa : rastrules::test::supported_isas()) {
    EXPECT_EQ(fast_count_batch(xy, 8, 8, RasterState{}, isa).covered, 6u) << to_string(isa);
    RasterState br;
    br.fill = FillConvention::kBottomRight;
    EXPECT_EQ(fast_count_batch(xy, 8, 8, br, isa).covered, 10u) << to_string(isa);
  }
}

// rule: FAST.BATCH.EQUALS.PLAIN, FAST.BATCH.SMALL_I32, FAST.THREADS.DETERMINISTIC
TEST(FastBatch, AWatertightMeshOfSmallTrianglesDrawsEachCentreOnce) {
  // A 20 x 13 grid of 3.25 px cells from (1.5, 2.25), both diagonals, with vertices on the 1/4
  // grid: every centre inside the rectangle is covered exactly once, none outside.
  std::vector<float> xy;
  const float x0 = 1.5f, y0 = 2.25f, c = 3.25f;
  for (int j = 0; j < 13; ++j)
    for (int i = 0; i < 20; ++i) {
      const float ax = x0 + c * static_cast<float>(i), ay = y0 + c * static_cast<float>(j);
      const float bx = ax + c, by = ay + c;
      if ((i + j) % 2 == 0)
        xy.insert(xy.end(), {ax, ay, bx, ay, bx, by, ax, ay, bx, by, ax, by});
      else
        xy.insert(xy.end(), {ax, ay, bx, ay, ax, by, bx, ay, bx, by, ax, by});
    }
  const std::int32_t w = 72, h = 48;
  for (Isa isa : rastrules::test::supported_isas()) {
    std::vector<std::uint32_t> hits(static_cast<std::size_t>(w * h), 0);
    std::vector<std::uint64_t> per(xy.size() / 6, 0);
    const raster::FastBatchResult r = fast_count_batch(xy, w, h, RasterState{}, isa, per, hits);
    ASSERT_EQ(r.status, BatchStatus::kOk) << describe(r);
    std::uint64_t inside = 0;
    for (std::int32_t y = 0; y < h; ++y)
      for (std::int32_t x = 0; x < w; ++x) {
        const float cx = static_cast<float>(x) + 0.5f, cy = static_cast<float>(y) + 0.5f;
        // Top-left: the rectangle's left and top sides are inclusive, right and bottom not.
        const bool in = cx >= x0 && cx < x0 + 20 * c && cy >= y0 && cy < y0 + 13 * c;
        inside += in ? 1 : 0;
        EXPECT_EQ(hits[static_cast<std::size_t>(y * w + x)], in ? 1u : 0u)
            << to_string(isa) << " at " << x << ", " << y;
      }
    EXPECT_EQ(r.covered, inside);
    EXPECT_EQ(r.rasterized, xy.size() / 6);
    if (isa != Isa::kScalar) {
      EXPECT_EQ(r.small, xy.size() / 6);
    }
    std::uint64_t sum = 0;
    for (std::uint64_t n : per)
      sum += n;
    EXPECT_EQ(sum, inside);
  }
}

// The plain setup of one triangle: the kernel's snapping and setup_triangle.
rastrules::TriangleSetup plain_setup(const float* v, const RasterState& s) {
  std::array<rastrules::Vec2, 3> p;
  for (std::size_t k = 0; k < 3; ++k)
    p[k] = rastrules::Vec2{rastrules::snap_to_subpixel(v[2 * k]).value,
                           rastrules::snap_to_subpixel(v[2 * k + 1]).value};
  return rastrules::setup_triangle(p, s);
}

// Its bounding-box walk, counted.
std::uint64_t plain_count(const float* v, std::int32_t w, std::int32_t h, const RasterState& s) {
  std::uint64_t n = 0;
  raster::walk_triangle(plain_setup(v, s), w, h, [&](std::int32_t, std::int32_t) { ++n; });
  return n;
}

// rule: FAST.BATCH.EQUALS.PLAIN, FAST.BATCH.SMALL_I32, RASTER.TARGET.CLIP, TRI.CULL.MODE
TEST(FastBatch, MixedSizesClippingAndCullingEqualThePlainWalk) {
  const std::vector<float> xy = {
      -3.2f,  -2.7f, 5.9f,    1.1f,  0.3f,   6.6f,   // small, clipped at the left and top
      40.5f,  5.5f,  104.49f, 5.5f,  40.5f,  69.49f, // spans just under 64 px: small
      40.5f,  5.5f,  104.5f,  5.5f,  40.5f,  69.5f,  // spans of exactly 64 px: not small
      10.0f,  10.0f, 10.0f,   90.0f, 99.0f,  40.0f,  // large, counter-clockwise
      10.0f,  10.0f, 90.0f,   40.0f, 10.0f,  90.0f,  // large, clockwise
      120.1f, 70.3f, 125.7f,  79.9f, 119.0f, 78.2f,  // small, past the right and bottom sides
      3.0f,   3.0f,  4.0f,    4.0f,  5.0f,   5.0f,   // degenerate
      40.25f, 3.5f,  33.0f,   9.75f, 47.0f,  9.75f,  // small, counter-clockwise
  };
  const std::int32_t w = 123, h = 77;
  for (const rastrules::CullMode cull :
       {rastrules::CullMode::kNone, rastrules::CullMode::kBack, rastrules::CullMode::kFront}) {
    RasterState s;
    s.cull = cull;
    std::vector<std::uint64_t> expected;
    std::uint64_t rasterized = 0;
    for (std::size_t i = 0; i < xy.size() / 6; ++i) {
      expected.push_back(plain_count(&xy[6 * i], w, h, s));
      rasterized +=
          plain_setup(&xy[6 * i], s).status == rastrules::TriangleStatus::kRasterized ? 1u : 0u;
    }
    // Five run clockwise (front-facing by default), two counter-clockwise, one is degenerate.
    EXPECT_EQ(rasterized, cull == rastrules::CullMode::kNone   ? 7u
                          : cull == rastrules::CullMode::kBack ? 5u
                                                               : 2u);
    for (Isa isa : rastrules::test::supported_isas()) {
      std::vector<std::uint64_t> per(expected.size(), 0);
      const raster::FastBatchResult r = fast_count_batch(xy, w, h, s, isa, per);
      ASSERT_EQ(r.status, BatchStatus::kOk) << describe(r);
      EXPECT_EQ(per, expected) << to_string(isa) << ", cull " << to_string(cull);
      EXPECT_EQ(r.rasterized, rasterized) << to_string(isa);
      if (isa != Isa::kScalar) {
        EXPECT_EQ(r.small, 5u) << to_string(isa);
      }
    }
  }
}

// rule: FAST.BATCH.EQUALS.PLAIN, SNAP.VERTEX.INVALID, FAST.ISA.DISPATCH
TEST(FastBatch, NamesEveryBadArgument) {
  std::vector<float> xy(6 * 20, 1.0f);
  for (std::size_t i = 0; i < 20; ++i)
    xy[6 * i + 2] = 5.0f, xy[6 * i + 5] = 7.0f;
  xy[6 * 13 + 5] = std::numeric_limits<float>::quiet_NaN();
  xy[6 * 17 + 0] = 40000.0f;
  for (Isa isa : rastrules::test::supported_isas()) {
    const raster::FastBatchResult r = fast_count_batch(xy, 10, 10, RasterState{}, isa);
    EXPECT_EQ(r.status, BatchStatus::kBadVertex);
    EXPECT_EQ(r.bad_triangle, 13u);
    EXPECT_EQ(r.bad_vertex, 2);
    EXPECT_EQ(r.bad_axis, 'y');
    EXPECT_EQ(describe(r), "batch: triangle 13, vertex 2, y: " +
                               std::string(rastrules::to_string(rastrules::SnapStatus::kNaN)) +
                               " (SNAP.VERTEX.INVALID)");
  }
  xy[6 * 13 + 5] = 7.0f;
  const raster::FastBatchResult range = fast_count_batch(xy, 10, 10, RasterState{}, Isa::kScalar);
  EXPECT_EQ(range.bad_triangle, 17u);
  EXPECT_EQ(range.bad_snap, rastrules::SnapStatus::kOutOfRange);
  xy[6 * 17 + 0] = 1.0f;
  EXPECT_EQ(fast_count_batch(xy, 10, 10, RasterState{}, Isa::kScalar).status, BatchStatus::kOk);

  const std::vector<float> seven(7, 1.0f);
  EXPECT_EQ(fast_count_batch(seven, 10, 10, RasterState{}, Isa::kScalar).status,
            BatchStatus::kBadLength);
  std::vector<std::uint64_t> per(19);
  EXPECT_EQ(fast_count_batch(xy, 10, 10, RasterState{}, Isa::kScalar, per).status,
            BatchStatus::kBadLength);
  std::vector<std::uint32_t> hits(99);
  EXPECT_EQ(fast_count_batch(xy, 10, 10, RasterState{}, Isa::kScalar, {}, hits).status,
            BatchStatus::kBadLength);
  for (auto [w, h] : {std::pair{0, 10}, {10, -1}, {16385, 10}, {10, 16385}}) {
    const raster::FastBatchResult t = fast_count_batch(xy, w, h, RasterState{}, Isa::kScalar);
    EXPECT_EQ(t.status, BatchStatus::kBadTarget);
    EXPECT_NE(describe(t).find("16384"), std::string::npos);
  }
  // An instruction set the processor lacks, or made to look as if it did.
  ASSERT_EQ(setenv(rastrules::kMaxIsaVariable, "scalar", 1), 0);
  EXPECT_EQ(fast_count_batch(xy, 10, 10, RasterState{}, Isa::kAvx2).status, BatchStatus::kBadIsa);
  EXPECT_EQ(fast_count_batch(xy, 10, 10, RasterState{}, Isa::kAvx512).status, BatchStatus::kBadIsa);
  ASSERT_EQ(unsetenv(rastrules::kMaxIsaVariable), 0);
  // Nothing at all: zero triangles.
  EXPECT_EQ(fast_count_batch({}, 10, 10, RasterState{}, Isa::kScalar).covered, 0u);
}

// Runs as (tri, y, x, n), collected from fast_runs_batch.
struct RunLog {
  std::vector<std::array<std::int32_t, 4>> runs;
  static void add(void* self, std::uint32_t tri, std::int32_t y, std::int32_t x, std::int32_t n) {
    static_cast<RunLog*>(self)->runs.push_back({static_cast<std::int32_t>(tri), y, x, n});
  }
};

// The per-pixel counts are bytes until they reach 255 (FAST.BATCH.PIXEL_COUNTS): 600 copies of
// three small triangles (rows of 3, 12 and 20 pixels: the eight-lane chunk that fits in its
// row, the wide rows, the rows in chunks with a tail), one against the target's right side (the
// pixel-by-pixel path), and 600 of a large one, cover their pixels 600 times, 1200 where two
// overlap; in one call, in chunks of 7 triangles into one PixelCounts, and into 32-bit counts.
// rule: FAST.BATCH.PIXEL_COUNTS, FAST.BATCH.EQUALS.PLAIN
TEST(FastBatch, CountsPastAByteMoveToTheirWideCounts) {
  const std::int32_t w = 100, h = 90;
  const std::vector<float> one = {
      1.0f,  1.0f,  4.0f,  1.0f,  1.0f,  4.0f,  // rows of up to 3 px
      2.0f,  6.0f,  14.0f, 6.0f,  2.0f,  10.0f, // up to 12 px
      80.0f, 2.0f,  99.8f, 2.0f,  80.0f, 8.0f,  // up to 20 px, at the right side
      97.0f, 20.0f, 99.9f, 20.0f, 97.0f, 23.0f, // 3 px against the right side
      0.0f,  0.0f,  90.0f, 0.0f,  0.0f,  89.0f, // large: over every other one
  };
  std::vector<float> xy;
  for (int c = 0; c < 600; ++c)
    xy.insert(xy.end(), one.begin(), one.end());
  // One copy, the plain way.
  std::vector<std::uint32_t> plain(static_cast<std::size_t>(w * h), 0);
  ASSERT_EQ(fast_count_batch(one, w, h, RasterState{}, Isa::kScalar, {}, plain).status,
            BatchStatus::kOk);
  std::uint32_t most = 0;
  for (const std::uint32_t p : plain)
    most = std::max(most, p);
  EXPECT_EQ(most, 2u); // the large triangle over the small ones
  for (Isa isa : rastrules::test::supported_isas()) {
    std::vector<std::uint32_t> wide(plain.size(), 0);
    ASSERT_EQ(fast_count_batch(xy, w, h, RasterState{}, isa, {}, wide).status, BatchStatus::kOk);
    raster::PixelCounts whole(w, h), chunks(w, h);
    ASSERT_EQ(fast_count_batch(xy, w, h, RasterState{}, isa, {}, whole).status, BatchStatus::kOk);
    for (std::size_t first = 0; first < xy.size(); first += 6 * 7) {
      const std::size_t m = std::min<std::size_t>(6 * 7, xy.size() - first);
      ASSERT_EQ(
          fast_count_batch(std::span(xy).subspan(first, m), w, h, RasterState{}, isa, {}, chunks)
              .status,
          BatchStatus::kOk);
    }
    for (std::size_t i = 0; i < plain.size(); ++i) {
      ASSERT_EQ(wide[i], 600 * plain[i]) << to_string(isa) << " pixel " << i;
      ASSERT_EQ(whole[i], 600 * plain[i]) << to_string(isa) << " pixel " << i;
      ASSERT_EQ(chunks[i], 600 * plain[i]) << to_string(isa) << " pixel " << i;
    }
  }
  raster::PixelCounts other(w, h + 1);
  EXPECT_EQ(fast_count_batch(one, w, h, RasterState{}, Isa::kScalar, {}, other).status,
            BatchStatus::kBadLength);
}

// The AVX-512 unit's rows in sixteen lanes give the AVX2 unit's counts, per-triangle counts,
// per-pixel counts and runs on triangles whose rows are 1..64 pixels wide (every tail length of
// both units, full chunks of sixteen), placed against the target's right and bottom sides, where
// the last chunk's lanes run past the end of the hits buffer (masked loads and stores must not
// touch it: ASan and the buffer's last row check that). Needs AVX-512: skipped elsewhere (this
// unit cannot be tested on a machine without it).
// rule: FAST.BATCH.LANES16, FAST.BATCH.EQUALS.PLAIN
TEST(FastBatch, SixteenLanesGiveTheEightLanesAnswersOnEveryRowWidth) {
  if (!rastrules::isa_supported(Isa::kAvx512))
    GTEST_SKIP() << "this processor has no AVX-512 (or RASTRULES_MAX_ISA hides it)";
  const std::int32_t w = 70, h = 66;
  std::vector<float> xy;
  for (int width = 1; width <= 64; ++width) {
    const auto fw = static_cast<float>(width);
    // A right triangle and a thin one, their boxes at the right side, then at the bottom; spans
    // below 64 px (small), rows of up to `width` pixels.
    const float right = static_cast<float>(w) - 0.25f, x0 = right - fw + 0.5f;
    xy.insert(xy.end(), {x0, 1.0f, right, 1.0f, right, 0.5f + fw});
    xy.insert(xy.end(), {x0, 3.0f, right, 5.5f, x0, 6.0f});
    // Clipped by the right side in the last rows (the lanes past the target's last column are
    // inside the triangle: only the tail mask leaves them out).
    if (width <= 40) {
      const float xl = static_cast<float>(w) - fw + 0.5f, xr = static_cast<float>(w) + 20.0f;
      const float yt = static_cast<float>(h) - 3.0f;
      xy.insert(xy.end(), {xl, yt, xr, yt, xr, yt + 5.0f});
    }
    const float bottom = static_cast<float>(h) - 0.125f;
    xy.insert(xy.end(), {0.5f, bottom - 1.5f, fw, bottom, 0.75f, bottom});
  }
  for (const FillConvention fill : {FillConvention::kTopLeft, FillConvention::kBottomRight}) {
    RasterState state;
    state.fill = fill;
    std::vector<std::uint32_t> hits8(static_cast<std::size_t>(w * h), 0), hits16 = hits8;
    std::vector<std::uint64_t> per8(xy.size() / 6, 0), per16 = per8;
    const raster::FastBatchResult r8 = fast_count_batch(xy, w, h, state, Isa::kAvx2, per8, hits8);
    const raster::FastBatchResult r16 =
        fast_count_batch(xy, w, h, state, Isa::kAvx512, per16, hits16);
    ASSERT_EQ(r8.status, BatchStatus::kOk);
    ASSERT_EQ(r16.status, BatchStatus::kOk);
    EXPECT_EQ(r16.covered, r8.covered);
    EXPECT_EQ(r16.small, r8.small);
    EXPECT_EQ(r16.small, xy.size() / 6); // every triangle went through the small lanes
    EXPECT_EQ(per16, per8);
    EXPECT_EQ(hits16, hits8);
    EXPECT_GT(r8.covered, 3000u);
    RunLog runs8, runs16;
    (void)raster::fast_runs_batch(xy, w, h, state, Isa::kAvx2, {&runs8, &RunLog::add});
    (void)raster::fast_runs_batch(xy, w, h, state, Isa::kAvx512, {&runs16, &RunLog::add});
    EXPECT_EQ(runs16.runs, runs8.runs);
    EXPECT_FALSE(runs8.runs.empty());
  }
}

} // namespace
