// SPDX-License-Identifier: MIT
// Points: the kernel's point path (setup_point + traversal), the kernel's triangle path on the
// same two triangles (setup_triangle + covers at every centre) and the oracle's exact square
// agree, for random and tie-heavy centres (on pixel centres, on pixel corners, half-way, one
// subpixel off those), under every fill convention and cull mode; whole-pixel translation;
// the range.
// Implements (properties for): POINT.SHAPE.TWO_TRIANGLES, POINT.COVER.HALF_OPEN,
//   POINT.CULL.NONE, POINT.RANGE, POINT.INVARIANCE.TRANSLATION

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "rastrules/fixed.hpp"
#include "rastrules/formula/point.hpp"
#include "rastrules/gen/triangles.hpp"
#include "rastrules/oracle/point.hpp"
#include "rastrules/point.hpp"
#include "rastrules/raster/walk.hpp"
#include "rastrules/triangle.hpp"

namespace {

namespace gen = rastrules::gen;
namespace oracle = rastrules::oracle;
using rastrules::Vec2;

constexpr std::int32_t kSide = 8; // target side for the window properties

// The fill convention spelled as in spec/scene.md, for the string-typed oracle.
std::string fill_name(rastrules::FillConvention f) {
  return std::string(rastrules::to_string(f));
}

Vec2 raw(std::int64_t x, std::int64_t y) {
  return Vec2{rastrules::Subpixel::from_raw(static_cast<std::int32_t>(x)),
              rastrules::Subpixel::from_raw(static_cast<std::int32_t>(y))};
}

// The tie classes of one coordinate of a point centre, relative to the pixel grid.
enum class Tie { kOnCentre, kOnEdge, kNearCentre, kNearEdge, kAny };
const char* tie_name(Tie t) {
  switch (t) {
  case Tie::kOnCentre:
    return "on a pixel centre";
  case Tie::kOnEdge:
    return "on a pixel edge";
  case Tie::kNearCentre:
    return "1 raw off a centre";
  case Tie::kNearEdge:
    return "1 raw off an edge";
  case Tie::kAny:
    return "anywhere";
  }
  return "?";
}

// The tie class of a centre, for the RapidCheck classification output.
std::string centre_class(Tie x, Tie y) {
  if (x == Tie::kOnCentre && y == Tie::kOnCentre)
    return "centre on a pixel centre";
  if (x == Tie::kOnEdge && y == Tie::kOnEdge)
    return "centre on a pixel corner";
  if ((x == Tie::kOnEdge && y == Tie::kOnCentre) || (x == Tie::kOnCentre && y == Tie::kOnEdge))
    return "centre half-way between two pixel centres";
  if (x == Tie::kOnEdge || y == Tie::kOnEdge)
    return "square side through pixel centres";
  if (x == Tie::kNearCentre || x == Tie::kNearEdge || y == Tie::kNearCentre || y == Tie::kNearEdge)
    return "1 raw off a tie";
  return std::string("x ") + tie_name(x) + ", y " + tie_name(y);
}

struct Coord {
  std::int64_t raw;
  Tie tie;
};

// One coordinate of a centre whose square overlaps [lo_px, hi_px] pixels, tie-heavy.
rc::Gen<Coord> coord(std::int64_t lo_px, std::int64_t hi_px) {
  return rc::gen::mapcat(rc::gen::element<int>(0, 1, 2, 3, 4), [=](int kind) {
    return rc::gen::map(rc::gen::pair(rc::gen::inRange<std::int64_t>(lo_px, hi_px + 1),
                                      rc::gen::inRange<std::int64_t>(0, 256)),
                        [=](const std::pair<std::int64_t, std::int64_t>& p) {
                          const std::int64_t base = p.first * 256;
                          const std::int64_t sign = (p.second % 2 == 0) ? 1 : -1;
                          switch (kind) {
                          case 0:
                            return Coord{base + 128, Tie::kOnCentre};
                          case 1:
                            return Coord{base, Tie::kOnEdge};
                          case 2:
                            return Coord{base + 128 + sign, Tie::kNearCentre};
                          case 3:
                            return Coord{base + sign, Tie::kNearEdge};
                          default:
                            return Coord{base + p.second, Tie::kAny};
                          }
                        });
  });
}

// rule: POINT.SHAPE.TWO_TRIANGLES, POINT.COVER.HALF_OPEN, POINT.CULL.NONE
RC_GTEST_PROP(PointCover, PointPathEqualsTrianglePathEqualsExactSquare, ()) {
  const Coord cx = *coord(-1, kSide);
  const Coord cy = *coord(-1, kSide);
  const rastrules::RasterState state = *gen::raster_state(); // any cull mode: must not matter
  RC_TAG(centre_class(cx.tie, cy.tie));
  const Vec2 c = raw(cx.raw, cy.raw);

  // Kernel point path: traversal of setup_point's triangles, counting emissions.
  std::map<std::pair<int, int>, int> hits;
  for (const rastrules::TriangleSetup& t : rastrules::setup_point(c, state)) {
    RC_ASSERT(t.status == rastrules::TriangleStatus::kRasterized);
    rastrules::raster::walk_triangle(t, kSide, kSide, [&](std::int32_t x, std::int32_t y) {
      ++hits[{x, y}];
    });
  }
  // Kernel triangle path: the two triangles set up as ordinary triangles with culling off.
  rastrules::RasterState no_cull = state;
  no_cull.cull = rastrules::CullMode::kNone;
  const auto tris = rastrules::point_triangles(c);
  const auto t0 = rastrules::setup_triangle(tris[0], no_cull);
  const auto t1 = rastrules::setup_triangle(tris[1], no_cull);
  int covered = 0;
  for (std::int32_t y = 0; y < kSide; ++y) {
    for (std::int32_t x = 0; x < kSide; ++x) {
      const Vec2 s = rastrules::pixel_center(x, y);
      const int by_triangles = int(rastrules::covers(t0, s)) + int(rastrules::covers(t1, s));
      const auto it = hits.find({x, y});
      const int by_point = it == hits.end() ? 0 : it->second;
      const bool exact =
          oracle::point_covers({cx.raw, cy.raw}, {s.x.raw(), s.y.raw()}, fill_name(state.fill));
      RC_ASSERT(by_triangles <= 1);
      RC_ASSERT(by_point == by_triangles);
      RC_ASSERT((by_point == 1) == exact);
      covered += by_point;
    }
  }
  // A point covers at most one pixel (exactly one when that pixel is in the target).
  RC_ASSERT(covered <= 1);
}

// rule: POINT.COVER.HALF_OPEN, POINT.RANGE
RC_GTEST_PROP(PointCover, AnywhereInRangeSamplesNearTheSquareFollowTheExactSquare, ()) {
  const std::int64_t lo = rastrules::kMinPointRaw, hi = rastrules::kMaxPointRaw;
  const auto anywhere = rc::gen::weightedOneOf<std::int64_t>(
      {{6, rc::gen::inRange<std::int64_t>(lo, hi + 1)},
       {1, rc::gen::elementOf(std::vector<std::int64_t>{lo, lo + 1, hi - 1, hi, 0, 128, -128})}});
  const std::int64_t cx = *anywhere;
  const std::int64_t cy = *anywhere;
  const rastrules::FillConvention fill = *gen::fill_convention();
  const auto setups = rastrules::setup_point(
      raw(cx, cy), {rastrules::CullMode::kNone, rastrules::FrontFace::kClockwise, fill});
  // Samples of the 16.8 grid on and around the square's sides and corners (any sample is a
  // valid sample position, not only pixel centres).
  for (const std::int64_t ox : {-129, -128, -127, -1, 0, 1, 127, 128, 129}) {
    for (const std::int64_t oy : {-129, -128, -127, 0, 127, 128, 129}) {
      const std::int64_t sx = cx + ox, sy = cy + oy;
      if (sx < rastrules::kMinVertexRaw || sx > rastrules::kMaxVertexRaw ||
          sy < rastrules::kMinVertexRaw || sy > rastrules::kMaxVertexRaw)
        continue;
      const Vec2 s = raw(sx, sy);
      const int n = int(rastrules::covers(setups[0], s)) + int(rastrules::covers(setups[1], s));
      RC_ASSERT(n <= 1);
      RC_ASSERT((n == 1) == oracle::point_covers({cx, cy}, {sx, sy}, fill_name(fill)));
    }
  }
}

// rule: POINT.INVARIANCE.TRANSLATION
RC_GTEST_PROP(PointInvariance, WholePixelTranslationMovesTheCoveredPixel, ()) {
  const Coord cx = *coord(0, kSide - 1);
  const Coord cy = *coord(0, kSide - 1);
  const std::int64_t dx = *rc::gen::inRange<std::int64_t>(-3, 4);
  const std::int64_t dy = *rc::gen::inRange<std::int64_t>(-3, 4);
  const rastrules::RasterState state = *gen::raster_state();
  const auto a = rastrules::setup_point(raw(cx.raw, cy.raw), state);
  const auto b = rastrules::setup_point(raw(cx.raw + 256 * dx, cy.raw + 256 * dy), state);
  for (std::int32_t y = -2; y < kSide + 2; ++y) {
    for (std::int32_t x = -2; x < kSide + 2; ++x) {
      const Vec2 s = raw(256 * x + 128, 256 * y + 128);
      const Vec2 st = raw(256 * (x + dx) + 128, 256 * (y + dy) + 128);
      RC_ASSERT((rastrules::covers(a[0], s) || rastrules::covers(a[1], s)) ==
                (rastrules::covers(b[0], st) || rastrules::covers(b[1], st)));
    }
  }
}

// rule: POINT.RANGE
RC_GTEST_PROP(PointRange, KernelRangeTestEqualsTheSpecRangeInPixels, ()) {
  const auto near_limit = rc::gen::weightedOneOf<std::int64_t>(
      {{1, rc::gen::inRange<std::int64_t>(rastrules::kMinVertexRaw - 300,
                                          rastrules::kMinVertexRaw + 300)},
       {1, rc::gen::inRange<std::int64_t>(rastrules::kMaxVertexRaw - 300,
                                          rastrules::kMaxVertexRaw + 300)},
       {1, rc::gen::inRange<std::int64_t>(-100000, 100000)}});
  const std::int64_t x = *near_limit;
  const std::int64_t y = *near_limit;
  const bool kernel = rastrules::formula::point_centre_in_range<std::int64_t>(
      x, y, rastrules::kMinPointRaw, rastrules::kMaxPointRaw);
  RC_TAG(kernel ? "in range" : "out of range");
  RC_ASSERT(kernel == oracle::point_in_range({x, y}));
}

} // namespace
