// SPDX-License-Identifier: MIT
// Quadrilateral lines: the kernel (quad_line_triangles / setup_quad_line + traversal) against
// the exact oracle (GMP: corner offsets by integer square roots, coverage of the parallelogram
// by the spec's side classification), on random and tie-heavy lines (axis-aligned, 45 degrees,
// endpoints on pixel centres and corners, very short, zero length), both widths, every fill
// convention and cull mode; offsets anywhere in the vertex range; a -> b equals b -> a;
// whole-pixel translation.
// Implements (properties for): LINE.QUAD.SHAPE, LINE.QUAD.WIDTH, LINE.QUAD.CORNERS,
//   LINE.QUAD.ZERO_LENGTH, LINE.QUAD.NO_CULL, LINE.QUAD.SYMMETRIC

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "rastrules/fixed.hpp"
#include "rastrules/gen/triangles.hpp"
#include "rastrules/line.hpp"
#include "rastrules/line_quad.hpp"
#include "rastrules/oracle/point.hpp"
#include "rastrules/raster/walk.hpp"
#include "rastrules/triangle.hpp"

namespace {

namespace gen = rastrules::gen;
namespace oracle = rastrules::oracle;
using rastrules::LineMode;
using rastrules::Vec2;
using Raw2 = oracle::Raw2;

constexpr std::int32_t kSide = 10; // target side for the window properties

// The fill convention spelled as in spec/scene.md, for the string-typed oracle.
std::string fill_name(rastrules::FillConvention f) {
  return std::string(rastrules::to_string(f));
}

std::string mode_name(LineMode m) {
  return m == LineMode::kQuadWide ? "quad-wide" : "quad-narrow";
}

Vec2 vec(const Raw2& r) {
  return Vec2{rastrules::Subpixel::from_raw(static_cast<std::int32_t>(r[0])),
              rastrules::Subpixel::from_raw(static_cast<std::int32_t>(r[1]))};
}

struct Line {
  Raw2 a;
  Raw2 b;
  std::string kind; // tie class, for the classification output
};

// A line near a kSide x kSide target, from one of the tie classes.
rc::Gen<Line> line_near() {
  const auto px = rc::gen::inRange<std::int64_t>(-1, kSide + 1);
  const auto sub = rc::gen::inRange<std::int64_t>(0, 256);
  return rc::gen::mapcat(rc::gen::element<int>(0, 1, 2, 3, 4, 5, 6, 7), [=](int kind) {
    return rc::gen::map(
        rc::gen::tuple(px, px, px, px, sub, sub, sub, sub,
                       rc::gen::inRange<std::int64_t>(-2 * 256, 2 * 256 + 1)),
        [=](const std::tuple<std::int64_t, std::int64_t, std::int64_t, std::int64_t, std::int64_t,
                             std::int64_t, std::int64_t, std::int64_t, std::int64_t>& t) {
          const auto [ax, ay, bx, by, fx, fy, gx, gy, len] = t;
          const Raw2 a{ax * 256 + fx, ay * 256 + fy};
          switch (kind) {
          case 0:
            return Line{a, Raw2{bx * 256 + gx, a[1]}, "horizontal"};
          case 1:
            return Line{a, Raw2{a[0], by * 256 + gy}, "vertical"};
          case 2:
            return Line{a, Raw2{a[0] + len * 3, a[1] + (gx % 2 ? len : -len) * 3}, "45 degrees"};
          case 3:
            return Line{Raw2{ax * 256 + 128, ay * 256 + 128}, Raw2{bx * 256 + 128, by * 256 + 128},
                        "endpoints on pixel centres"};
          case 4:
            return Line{Raw2{ax * 256, ay * 256}, Raw2{bx * 256, by * 256},
                        "endpoints on pixel corners"};
          case 5:
            return Line{a, Raw2{a[0] + gx % 5 - 2, a[1] + gy % 5 - 2},
                        "at most 2 raw long (or zero)"};
          case 6:
            return Line{a, a, "zero length"};
          default:
            return Line{a, Raw2{bx * 256 + gx, by * 256 + gy}, "anywhere"};
          }
        });
  });
}

// Returns the kernel's coverage of the quadrilateral line a -> b on the kSide target: pixel ->
// number of emissions (the traversal over setup_quad_line's triangles).
std::map<std::pair<int, int>, int> kernel_hits(const Raw2& a, const Raw2& b, LineMode mode,
                                               const rastrules::RasterState& state) {
  std::map<std::pair<int, int>, int> hits;
  for (const rastrules::TriangleSetup& t :
       rastrules::setup_quad_line(vec(a), vec(b), mode, state)) {
    RC_ASSERT(t.status == rastrules::TriangleStatus::kRasterized);
    rastrules::raster::walk_triangle(t, kSide, kSide, [&](std::int32_t x, std::int32_t y) {
      ++hits[{x, y}];
    });
  }
  return hits;
}

// rule: LINE.QUAD.SHAPE, LINE.QUAD.WIDTH, LINE.QUAD.CORNERS, LINE.QUAD.ZERO_LENGTH, LINE.QUAD.NO_CULL
RC_GTEST_PROP(LineQuad, KernelEqualsExactOracleOnRandomAndTieHeavyLines, ()) {
  const Line line = *line_near();
  const LineMode mode = *rc::gen::element(LineMode::kQuadWide, LineMode::kQuadNarrow);
  const rastrules::RasterState state = *gen::raster_state(); // cull must not matter
  RC_TAG(line.kind);

  // Corners: the kernel's triangles are (a-o, b-o, b+o), (a-o, b+o, a+o).
  const auto tris = rastrules::quad_line_triangles(vec(line.a), vec(line.b), mode);
  const std::vector<Raw2> corners = oracle::quad_line_corners(line.a, line.b, mode_name(mode));
  if (corners.empty()) {
    RC_ASSERT(tris.empty());
  } else {
    RC_ASSERT(tris.size() == 2u);
    const std::array<Vec2, 3> t0{vec(corners[0]), vec(corners[1]), vec(corners[2])};
    const std::array<Vec2, 3> t1{vec(corners[0]), vec(corners[2]), vec(corners[3])};
    RC_ASSERT(tris[0] == t0);
    RC_ASSERT(tris[1] == t1);
  }

  const auto hits = kernel_hits(line.a, line.b, mode, state);
  int covered = 0;
  for (std::int32_t y = 0; y < kSide; ++y) {
    for (std::int32_t x = 0; x < kSide; ++x) {
      const auto it = hits.find({x, y});
      const int n = it == hits.end() ? 0 : it->second;
      RC_ASSERT(n <= 1);
      const bool exact = oracle::quad_line_covers(
          line.a, line.b, mode_name(mode), {256 * x + 128, 256 * y + 128}, fill_name(state.fill));
      if ((n == 1) != exact) {
        RC_FAIL("pixel (" + std::to_string(x) + ", " + std::to_string(y) + "): kernel " +
                std::to_string(n) + ", oracle " + (exact ? "covered" : "not covered"));
      }
      covered += n;
    }
  }
  RC_CLASSIFY(covered == 0, "covers no pixel");
}

// rule: LINE.QUAD.CORNERS, LINE.QUAD.WIDTH
RC_GTEST_PROP(LineQuad, CornerOffsetsEqualTheOracleAnywhereInRange, ()) {
  const std::int64_t lo = rastrules::kMinVertexRaw, hi = rastrules::kMaxVertexRaw;
  const auto coord = rc::gen::weightedOneOf<std::int64_t>(
      {{4, rc::gen::inRange<std::int64_t>(lo, hi + 1)},
       {1, rc::gen::elementOf(std::vector<std::int64_t>{lo, lo + 1, hi - 1, hi, 0})}});
  const Raw2 a{*coord, *coord};
  const auto delta = rc::gen::weightedOneOf<std::int64_t>(
      {{2, rc::gen::inRange<std::int64_t>(-3, 4)},
       {2, rc::gen::inRange<std::int64_t>(-2000, 2001)},
       {1, rc::gen::inRange<std::int64_t>(-(std::int64_t{1} << 24), std::int64_t{1} << 24)}});
  Raw2 b{a[0] + *delta, a[1] + *delta};
  b[0] = std::clamp(b[0], lo, hi);
  b[1] = std::clamp(b[1], lo, hi);
  RC_PRE(a != b);
  const LineMode mode = *rc::gen::element(LineMode::kQuadWide, LineMode::kQuadNarrow);
  const rastrules::QuadOffset o =
      rastrules::quad_line_offset(b[0] - a[0], b[1] - a[1],
                                  mode == LineMode::kQuadWide ? rastrules::kQuadWideHalfWidth
                                                              : rastrules::kQuadNarrowHalfWidth);
  const Raw2 expected = oracle::quad_line_offset(a, b, mode_name(mode));
  RC_ASSERT(std::int64_t{o.x} == expected[0]);
  RC_ASSERT(std::int64_t{o.y} == expected[1]);
  const std::int64_t len = std::max(std::llabs(b[0] - a[0]), std::llabs(b[1] - a[1]));
  RC_CLASSIFY(len <= 3, "length <= 3 raw");
  RC_CLASSIFY(len > (std::int64_t{1} << 20), "length > 4096 px");
}

// rule: LINE.QUAD.SYMMETRIC
RC_GTEST_PROP(LineQuad, DrawingBToAEqualsDrawingAToB, ()) {
  const Line line = *line_near();
  const LineMode mode = *rc::gen::element(LineMode::kQuadWide, LineMode::kQuadNarrow);
  const rastrules::RasterState state = *gen::raster_state();
  RC_TAG(line.kind);
  RC_ASSERT(kernel_hits(line.a, line.b, mode, state) == kernel_hits(line.b, line.a, mode, state));
  // The same four corners, and the same diagonal.
  const auto f = rastrules::quad_line_triangles(vec(line.a), vec(line.b), mode);
  const auto r = rastrules::quad_line_triangles(vec(line.b), vec(line.a), mode);
  RC_ASSERT(f.size() == r.size());
  if (!f.empty()) {
    const auto key = [](const Vec2& v) { return std::make_pair(v.x.raw(), v.y.raw()); };
    std::set<std::pair<std::int32_t, std::int32_t>> fc, rc_;
    for (const auto& t : f)
      for (const Vec2& v : t)
        fc.insert(key(v));
    for (const auto& t : r)
      for (const Vec2& v : t)
        rc_.insert(key(v));
    RC_ASSERT(fc == rc_);
    RC_ASSERT(std::make_pair(key(f[0][0]), key(f[0][2])) ==
              std::make_pair(key(r[0][2]), key(r[0][0])));
  }
}

// rule: LINE.QUAD.SYMMETRIC
RC_GTEST_PROP(LineQuad, WholePixelTranslationMovesCoverageExactly, ()) {
  const Line line = *line_near();
  const LineMode mode = *rc::gen::element(LineMode::kQuadWide, LineMode::kQuadNarrow);
  const rastrules::RasterState state = *gen::raster_state();
  const std::int64_t dx = *rc::gen::inRange<std::int64_t>(-3, 4);
  const std::int64_t dy = *rc::gen::inRange<std::int64_t>(-3, 4);
  RC_TAG(line.kind);
  const auto moved = [&](const Raw2& p) { return Raw2{p[0] + 256 * dx, p[1] + 256 * dy}; };
  const auto before = kernel_hits(line.a, line.b, mode, state);
  const auto after = kernel_hits(moved(line.a), moved(line.b), mode, state);
  // Compare on the pixels that stay inside the target both ways.
  for (std::int32_t y = 0; y < kSide; ++y) {
    for (std::int32_t x = 0; x < kSide; ++x) {
      const std::int64_t tx = x + dx, ty = y + dy;
      if (tx < 0 || ty < 0 || tx >= kSide || ty >= kSide)
        continue;
      RC_ASSERT(before.count({x, y}) == after.count({static_cast<int>(tx), static_cast<int>(ty)}));
    }
  }
}

} // namespace
