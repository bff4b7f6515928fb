// SPDX-License-Identifier: MIT
// Triangle, scene, shared-edge and mesh generators that construct ties on purpose.
// Implements (generators for): TRI.COVER.SAMPLE, TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION,
//   TRI.SHARED_EDGE.EXACTLY_ONCE, TRI.WATERTIGHT.MESH, TRI.INVARIANCE.TRANSLATION,
//   RASTER.WALK.BBOX

#include "rastrules/gen/triangles.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <numeric>
#include <sstream>
#include <utility>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>

#include "rastrules/gen/floats.hpp"

namespace rastrules::gen {
namespace {

constexpr std::int32_t kOne = 256;  // one pixel in raw units
constexpr std::int32_t kHalf = 128; // half a pixel in raw units
constexpr std::int32_t kMargin = 4; // pixels around the target used by "near" generators

std::int32_t clamp_raw(std::int64_t v) {
  return static_cast<std::int32_t>(std::clamp<std::int64_t>(v, kMinVertexRaw, kMaxVertexRaw));
}

RawPoint point(std::int64_t x, std::int64_t y) {
  return RawPoint{clamp_raw(x), clamp_raw(y)};
}

// Returns t with its vertices permuted by the permutation numbered `perm` (0..5).
RawTriangle permuted(const RawTriangle& t, std::int32_t perm) {
  static constexpr std::array<std::array<std::size_t, 3>, 6> kPerms = {
      {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}}};
  const auto& p = kPerms[static_cast<std::size_t>(perm) % 6];
  return RawTriangle{t[p[0]], t[p[1]], t[p[2]]};
}

rc::Gen<std::int32_t> perm_index() {
  return rc::gen::inRange<std::int32_t>(0, 6);
}

rc::Gen<std::int32_t> raw_in(std::int32_t lo, std::int32_t hi) {
  return rc::gen::inRange<std::int32_t>(lo, hi + 1);
}

rc::Gen<RawPoint> pixel_centre_near(std::int32_t w, std::int32_t h, std::int32_t margin) {
  return rc::gen::apply(
      [](std::int32_t i, std::int32_t j) { return point(i * kOne + kHalf, j * kOne + kHalf); },
      rc::gen::inRange<std::int32_t>(-margin, w + margin),
      rc::gen::inRange<std::int32_t>(-margin, h + margin));
}

rc::Gen<RawPoint> raw_point_anywhere() {
  return rc::gen::apply(
      [](std::int32_t x, std::int32_t y) {
        return RawPoint{x, y};
      },
      raw_in(kMinVertexRaw, kMaxVertexRaw), raw_in(kMinVertexRaw, kMaxVertexRaw));
}

// A raw coordinate at or next to a range limit, or near the target.
rc::Gen<std::int32_t> limit_coord(std::int32_t side) {
  return rc::gen::weightedOneOf<std::int32_t>({
      {3, rc::gen::element(kMinVertexRaw, kMinVertexRaw + 1, kMinVertexRaw + kHalf, kMaxVertexRaw,
                           kMaxVertexRaw - 1, kMaxVertexRaw - kHalf + 1)},
      {1, raw_in(-kMargin * kOne, (side + kMargin) * kOne)},
  });
}

std::int64_t cross(const RawPoint& o, const RawPoint& a, const RawPoint& b) {
  return (std::int64_t{a[0]} - o[0]) * (std::int64_t{b[1]} - o[1]) -
         (std::int64_t{a[1]} - o[1]) * (std::int64_t{b[0]} - o[0]);
}

// Moves p by one raw unit along `axis` towards the inside of the range.
RawPoint nudge(RawPoint p, std::size_t axis) {
  p[axis] = p[axis] < kMaxVertexRaw ? p[axis] + 1 : p[axis] - 1;
  return p;
}

GenTriangle tagged(const RawTriangle& t, TriKind kind) {
  return GenTriangle{to_float(t), kind};
}

// ---- one generator per TriKind ----

rc::Gen<GenTriangle> random_tri(std::int32_t w, std::int32_t h) {
  return rc::gen::map(raw_triangle_near(w, h),
                      [](const RawTriangle& t) { return tagged(t, TriKind::kRandom); });
}

rc::Gen<GenTriangle> pixel_centres_tri(std::int32_t w, std::int32_t h) {
  return rc::gen::apply(
      [](RawPoint a, RawPoint b, RawPoint c) {
        return tagged(RawTriangle{a, b, c}, TriKind::kPixelCentres);
      },
      pixel_centre_near(w, h, kMargin), pixel_centre_near(w, h, kMargin),
      pixel_centre_near(w, h, kMargin));
}

// Some coordinates become (2r + 1) / 512: exactly half-way between raw r and r + 1, so
// snapping must break the tie to the even one.
rc::Gen<GenTriangle> snap_ties_tri(std::int32_t w, std::int32_t h) {
  return rc::gen::apply(
      [](const RawTriangle& t, std::array<bool, 6> tie) {
        GenTriangle g{to_float(t), TriKind::kSnapTies};
        for (std::size_t i = 0; i < 3; ++i) {
          for (std::size_t k = 0; k < 2; ++k) {
            if (tie[2 * i + k])
              g.v[i][k] = static_cast<float>(2 * t[i][k] + 1) / 512.0f;
          }
        }
        return g;
      },
      raw_triangle_near(w, h), rc::gen::arbitrary<std::array<bool, 6>>());
}

rc::Gen<GenTriangle> axis_edge_tri(std::int32_t w, std::int32_t h, bool horizontal) {
  return rc::gen::apply(
      [horizontal](RawPoint a, std::int32_t other, RawPoint c, std::int32_t perm) {
        RawPoint b = a;
        b[horizontal ? 0 : 1] = other;
        return tagged(permuted(RawTriangle{a, b, c}, perm),
                      horizontal ? TriKind::kHorizontalEdge : TriKind::kVerticalEdge);
      },
      rc::gen::weightedOneOf<RawPoint>(
          {{1, raw_point_near(w, h, kMargin)}, {1, pixel_centre_near(w, h, kMargin)}}),
      raw_in(-kMargin * kOne, (std::max(w, h) + kMargin) * kOne), raw_point_near(w, h, kMargin),
      perm_index());
}

// An edge through the pixel centre c0: a = c0 + k1 s (p, q), b = c0 - k2 s (p, q). When s (p, q)
// is a multiple of 128 in both coordinates it passes through further centres.
rc::Gen<GenTriangle> through_centres_tri(std::int32_t w, std::int32_t h) {
  return rc::gen::exec([w, h] {
    const RawPoint c0 = *pixel_centre_near(w, h, 0);
    std::int32_t p = *rc::gen::inRange<std::int32_t>(-4, 5);
    const std::int32_t q = *rc::gen::inRange<std::int32_t>(-4, 5);
    if (p == 0 && q == 0)
      p = 1;
    const std::int32_t s = *rc::gen::element(16, 32, 64, 128, 256);
    const std::int32_t k1 = *rc::gen::inRange<std::int32_t>(1, 9);
    const std::int32_t k2 = *rc::gen::inRange<std::int32_t>(1, 9);
    const RawPoint a = point(c0[0] + k1 * s * p, c0[1] + k1 * s * q);
    const RawPoint b = point(c0[0] - k2 * s * p, c0[1] - k2 * s * q);
    const RawPoint c = *rc::gen::weightedOneOf<RawPoint>(
        {{1, raw_point_near(w, h, kMargin)}, {1, pixel_centre_near(w, h, kMargin)}});
    return tagged(permuted(RawTriangle{a, b, c}, *perm_index()), TriKind::kThroughCentres);
  });
}

rc::Gen<GenTriangle> sliver_tri(std::int32_t w, std::int32_t h) {
  return rc::gen::exec([w, h] {
    const RawPoint a = *raw_point_near(w, h, kMargin);
    const RawPoint b = *raw_point_near(w, h, kMargin);
    const std::int32_t den = *rc::gen::inRange<std::int32_t>(1, 9);
    const std::int32_t num = *rc::gen::inRange<std::int32_t>(0, den + 1);
    const std::int32_t ox = *rc::gen::inRange<std::int32_t>(-3, 4);
    const std::int32_t oy = *rc::gen::inRange<std::int32_t>(-3, 4);
    const RawPoint c = point(a[0] + (std::int64_t{b[0]} - a[0]) * num / den + ox,
                             a[1] + (std::int64_t{b[1]} - a[1]) * num / den + oy);
    return tagged(permuted(RawTriangle{a, b, c}, *perm_index()), TriKind::kSliver);
  });
}

rc::Gen<GenTriangle> needle_tri(std::int32_t w, std::int32_t h) {
  return rc::gen::exec([w, h] {
    const RawPoint a = *raw_point_near(w, h, kMargin);
    const std::int32_t dx = *rc::gen::inRange<std::int32_t>(-4, 5);
    const std::int32_t dy = *rc::gen::inRange<std::int32_t>(-4, 5);
    const RawPoint b = point(a[0] + dx, a[1] + dy);
    const RawPoint c = *rc::gen::weightedOneOf<RawPoint>(
        {{2, raw_point_near(w, h, 3 * std::max(w, h))}, {1, raw_point_anywhere()}});
    return tagged(permuted(RawTriangle{a, b, c}, *perm_index()), TriKind::kNeedle);
  });
}

// Vertices far away; usually the triangle crosses or contains the target.
rc::Gen<GenTriangle> huge_tri(std::int32_t w, std::int32_t h) {
  return rc::gen::apply(
      [](RawPoint a, RawPoint b, RawPoint c, std::int32_t perm) {
        return tagged(permuted(RawTriangle{a, b, c}, perm), TriKind::kHuge);
      },
      raw_point_anywhere(), raw_point_anywhere(),
      rc::gen::weightedOneOf<RawPoint>(
          {{2, raw_point_near(w, h, kMargin)}, {1, raw_point_anywhere()}}),
      perm_index());
}

rc::Gen<GenTriangle> range_limits_tri(std::int32_t w, std::int32_t h) {
  const auto coord_x = limit_coord(w);
  const auto coord_y = limit_coord(h);
  const auto pt = rc::gen::apply(
      [](std::int32_t x, std::int32_t y) {
        return RawPoint{x, y};
      },
      coord_x, coord_y);
  return rc::gen::apply(
      [](RawPoint a, RawPoint b, RawPoint c) {
        return tagged(RawTriangle{a, b, c}, TriKind::kRangeLimits);
      },
      pt, pt, pt);
}

rc::Gen<GenTriangle> degenerate_tri(std::int32_t w, std::int32_t h) {
  return rc::gen::exec([w, h] {
    const RawPoint a = *raw_point_near(w, h, kMargin);
    const std::int32_t p = *rc::gen::inRange<std::int32_t>(-8, 9);
    const std::int32_t q = *rc::gen::inRange<std::int32_t>(-8, 9);
    const std::int32_t s = *rc::gen::element(1, 64, 256);
    const std::int32_t k1 = *rc::gen::inRange<std::int32_t>(-4, 5);
    const std::int32_t k2 = *rc::gen::inRange<std::int32_t>(-4, 5);
    const RawTriangle t{a, point(a[0] + k1 * s * p, a[1] + k1 * s * q),
                        point(a[0] + k2 * s * p, a[1] + k2 * s * q)};
    return tagged(permuted(t, *perm_index()), TriKind::kDegenerate);
  });
}

rc::Gen<GenTriangle> floats_tri(std::int32_t w, std::int32_t h) {
  // x / 65536 px: 16 fractional bits, so snapping rounds (and sometimes ties).
  const auto fx =
      rc::gen::map(rc::gen::inRange<std::int32_t>(-kMargin * 65536, (w + kMargin) * 65536),
                   [](std::int32_t x) { return static_cast<float>(x) / 65536.0f; });
  const auto fy =
      rc::gen::map(rc::gen::inRange<std::int32_t>(-kMargin * 65536, (h + kMargin) * 65536),
                   [](std::int32_t y) { return static_cast<float>(y) / 65536.0f; });
  return rc::gen::apply(
      [](float x0, float y0, float x1, float y1, float x2, float y2) {
        return GenTriangle{FloatTriangle{{{x0, y0}, {x1, y1}, {x2, y2}}}, TriKind::kFloats};
      },
      fx, fy, fx, fy, fx, fy);
}

} // namespace

float to_float(std::int32_t raw) {
  return static_cast<float>(raw) / 256.0f;
}

FloatTriangle to_float(const RawTriangle& t) {
  FloatTriangle f{};
  for (std::size_t i = 0; i < 3; ++i)
    f[i] = {to_float(t[i][0]), to_float(t[i][1])};
  return f;
}

Vec2 to_vec2(const RawPoint& p) {
  return Vec2{Subpixel::from_raw(p[0]), Subpixel::from_raw(p[1])};
}

std::array<Vec2, 3> to_vec2(const RawTriangle& t) {
  return {to_vec2(t[0]), to_vec2(t[1]), to_vec2(t[2])};
}

std::int64_t twice_area(const RawTriangle& t) {
  return cross(t[0], t[1], t[2]);
}

RawTriangle make_nondegenerate(RawTriangle t) {
  if (t[0] == t[1])
    t[1] = nudge(t[1], 0);
  if (cross(t[0], t[1], t[2]) == 0) {
    // With t0 != t1, moving t2 across the line by one unit: along y for a horizontal edge
    // (the area changes by +-(x1 - x0) != 0), along x otherwise (changes by -+(y1 - y0) != 0).
    t[2] = nudge(t[2], t[0][1] == t[1][1] ? 1 : 0);
  }
  return t;
}

RawTriangle reversed(const RawTriangle& t) {
  return RawTriangle{t[0], t[2], t[1]};
}

rc::Gen<FillConvention> fill_convention() {
  return rc::gen::element(FillConvention::kTopLeft, FillConvention::kTopRight,
                          FillConvention::kBottomLeft, FillConvention::kBottomRight);
}

rc::Gen<RasterState> raster_state() {
  return rc::gen::apply(
      [](CullMode c, FrontFace f, FillConvention fill) {
        return RasterState{c, f, fill};
      },
      rc::gen::element(CullMode::kNone, CullMode::kBack, CullMode::kFront),
      rc::gen::element(FrontFace::kClockwise, FrontFace::kCounterClockwise), fill_convention());
}

rc::Gen<RawPoint> raw_point_near(std::int32_t width, std::int32_t height, std::int32_t margin) {
  return rc::gen::apply([](std::int32_t x, std::int32_t y) { return point(x, y); },
                        raw_in(-margin * kOne, (width + margin) * kOne),
                        raw_in(-margin * kOne, (height + margin) * kOne));
}

rc::Gen<RawTriangle> raw_triangle_near(std::int32_t width, std::int32_t height) {
  const auto p = raw_point_near(width, height, kMargin);
  return rc::gen::apply(
      [](RawPoint a, RawPoint b, RawPoint c) {
        return RawTriangle{a, b, c};
      },
      p, p, p);
}

rc::Gen<RawTriangle> nondegenerate_raw_triangle_near(std::int32_t width, std::int32_t height) {
  return rc::gen::map(rc::gen::mapcat(rc::gen::inRange<std::int32_t>(0, 12),
                                      [width, height](std::int32_t kind) -> rc::Gen<RawTriangle> {
                                        // Tie-heavy kinds as raw triangles (no float ties here).
                                        rc::Gen<GenTriangle> g = random_tri(width, height);
                                        switch (kind) {
                                        case 1:
                                          g = pixel_centres_tri(width, height);
                                          break;
                                        case 2:
                                          g = axis_edge_tri(width, height, true);
                                          break;
                                        case 3:
                                          g = axis_edge_tri(width, height, false);
                                          break;
                                        case 4:
                                          g = through_centres_tri(width, height);
                                          break;
                                        case 5:
                                          g = sliver_tri(width, height);
                                          break;
                                        case 6:
                                          g = needle_tri(width, height);
                                          break;
                                        case 7:
                                          g = huge_tri(width, height);
                                          break;
                                        case 8:
                                          g = range_limits_tri(width, height);
                                          break;
                                        case 9:
                                          g = degenerate_tri(width, height);
                                          break;
                                        default:
                                          break;
                                        }
                                        return rc::gen::map(std::move(g), [](const GenTriangle& t) {
                                          RawTriangle r{};
                                          for (std::size_t i = 0; i < 3; ++i) {
                                            for (std::size_t k = 0; k < 2; ++k) {
                                              // Exact: these kinds are built on the 1/256 grid.
                                              r[i][k] =
                                                  static_cast<std::int32_t>(t.v[i][k] * 256.0f);
                                            }
                                          }
                                          return r;
                                        });
                                      }),
                      make_nondegenerate);
}

rc::Gen<GenTriangle> triangle_near(std::int32_t width, std::int32_t height) {
  const std::int32_t w = width, h = height;
  return rc::gen::weightedOneOf<GenTriangle>({
      {3, random_tri(w, h)},
      {2, pixel_centres_tri(w, h)},
      {2, snap_ties_tri(w, h)},
      {2, axis_edge_tri(w, h, true)},
      {2, axis_edge_tri(w, h, false)},
      {3, through_centres_tri(w, h)},
      {2, sliver_tri(w, h)},
      {1, needle_tri(w, h)},
      {1, degenerate_tri(w, h)},
      {1, floats_tri(w, h)},
  });
}

rc::Gen<GenTriangle> triangle_anywhere(std::int32_t width, std::int32_t height) {
  return rc::gen::weightedOneOf<GenTriangle>({
      {6, triangle_near(width, height)},
      {2, huge_tri(width, height)},
      {1, range_limits_tri(width, height)},
  });
}

namespace {

// A pair of triangles sharing an edge, placed near a target or anywhere in the range.
rc::Gen<SharedEdgePair> shared_edge_pair_around(rc::Gen<RawPoint> base) {
  return rc::gen::exec([base] {
    // Everything below stays within 2^14 raw of the base, which stays 2^15 inside the range,
    // so nothing is clamped and the reflection a + b - c is in range too.
    constexpr std::int32_t kKeep = 1 << 15;
    RawPoint a = *base;
    a[0] = std::clamp(a[0], kMinVertexRaw + kKeep, kMaxVertexRaw - kKeep);
    a[1] = std::clamp(a[1], kMinVertexRaw + kKeep, kMaxVertexRaw - kKeep);
    // Direction: a small lattice direction times a step (many raw lattice points and pixel
    // centres on the edge, axis-aligned and diagonal edges), or arbitrary.
    const RawPoint d = *rc::gen::weightedOneOf<RawPoint>({
        {3, rc::gen::apply(
                [](std::int32_t p, std::int32_t q, std::int32_t s) {
                  return RawPoint{p * s, q * s};
                },
                rc::gen::inRange<std::int32_t>(-3, 4), rc::gen::inRange<std::int32_t>(-3, 4),
                rc::gen::element(1, 7, 64, 128, 256, 1024))},
        {1, rc::gen::apply(
                [](std::int32_t x, std::int32_t y) {
                  return RawPoint{x, y};
                },
                raw_in(-4096, 4096), raw_in(-4096, 4096))},
    });
    RawPoint b{a[0] + d[0], a[1] + d[1]};
    if (b == a)
      b = nudge(b, 0);
    const auto offset = rc::gen::apply(
        [](std::int32_t x, std::int32_t y) {
          return RawPoint{x, y};
        },
        raw_in(-4096, 4096), raw_in(-4096, 4096));
    const RawPoint o1 = *offset;
    const RawPoint o2 = *offset;
    RawPoint c1{a[0] + o1[0], a[1] + o1[1]};
    RawPoint c2{a[0] + o2[0], a[1] + o2[1]};
    const std::size_t across = (a[1] == b[1]) ? 1 : 0; // axis that leaves the line
    if (cross(a, b, c1) == 0)
      c1 = nudge(c1, across);
    if (cross(a, b, c2) == 0)
      c2 = nudge(c2, across);
    if ((cross(a, b, c1) > 0) == (cross(a, b, c2) > 0)) {
      // Point reflection through the edge's midpoint flips the side.
      c2 = RawPoint{a[0] + b[0] - c2[0], a[1] + b[1] - c2[1]};
    }
    SharedEdgePair pair;
    pair.a = a;
    pair.b = b;
    pair.first = permuted(RawTriangle{a, b, c1}, *perm_index());
    pair.second = permuted(RawTriangle{b, a, c2}, *perm_index());
    return pair;
  });
}

} // namespace

rc::Gen<SharedEdgePair> shared_edge_pair() {
  return shared_edge_pair_around(rc::gen::weightedOneOf<RawPoint>({
      {2, raw_point_near(16, 16, kMargin)},
      {1, pixel_centre_near(16, 16, kMargin)},
      {1, raw_point_anywhere()},
  }));
}

rc::Gen<TriScene> tri_scene(std::int32_t max_side, std::int32_t max_triangles) {
  return rc::gen::exec([max_side, max_triangles] {
    TriScene s;
    s.width = *rc::gen::inRange<std::int32_t>(1, max_side + 1);
    s.height = *rc::gen::inRange<std::int32_t>(1, max_side + 1);
    s.state = *raster_state();
    const std::int32_t n = *rc::gen::inRange<std::int32_t>(1, max_triangles + 1);
    while (static_cast<std::int32_t>(s.triangles.size()) < n) {
      if (*rc::gen::inRange(0, 5) == 0) {
        // Two triangles sharing an edge near the target.
        const SharedEdgePair p = *shared_edge_pair_around(
            rc::gen::weightedOneOf<RawPoint>({{1, raw_point_near(s.width, s.height, 0)},
                                              {1, pixel_centre_near(s.width, s.height, 0)}}));
        s.triangles.push_back(tagged(p.first, TriKind::kThroughCentres));
        s.triangles.push_back(tagged(p.second, TriKind::kThroughCentres));
      } else {
        s.triangles.push_back(*triangle_anywhere(s.width, s.height));
      }
    }
    return s;
  });
}

std::vector<RawPoint> points_on_open_segment(const RawPoint& a, const RawPoint& b,
                                             std::size_t limit) {
  const std::int64_t dx = std::int64_t{b[0]} - a[0];
  const std::int64_t dy = std::int64_t{b[1]} - a[1];
  const std::int64_t g = std::gcd(std::llabs(dx), std::llabs(dy));
  std::vector<RawPoint> out;
  if (g < 2 || limit == 0)
    return out;
  const std::int64_t inner = g - 1; // lattice points strictly inside: j = 1 .. g - 1
  const auto count =
      static_cast<std::int64_t>(std::min<std::size_t>(limit, static_cast<std::size_t>(inner)));
  for (std::int64_t i = 0; i < count; ++i) {
    const std::int64_t j =
        (count == inner) ? i + 1 : 1 + (inner - 1) * i / std::max<std::int64_t>(count - 1, 1);
    out.push_back(point(a[0] + dx / g * j, a[1] + dy / g * j));
  }
  return out;
}

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

rc::Gen<Mesh> jittered_grid(std::int32_t w, std::int32_t h) {
  return rc::gen::exec([w, h] {
    Mesh m;
    m.kind = MeshKind::kJitteredGrid;
    const std::int32_t s =
        *rc::gen::weightedOneOf<std::int32_t>({{2, rc::gen::element(128, 256, 384, 512, 768, 1024)},
                                               {1, rc::gen::inRange<std::int32_t>(64, 1025)}});
    const auto nx = static_cast<std::size_t>(*rc::gen::inRange<std::int32_t>(1, 7));
    const auto ny = static_cast<std::size_t>(*rc::gen::inRange<std::int32_t>(1, 7));
    const RawPoint origin = *rc::gen::weightedOneOf<RawPoint>(
        {{1, raw_point_near(w, h, kMargin)}, {1, pixel_centre_near(w, h, kMargin)}});
    // Jitter strictly below s/8 per coordinate keeps every quad convex: each edge vector is
    // (s, 0) or (0, s) plus at most s/4 per coordinate, so consecutive edge vectors have a
    // cross product of at least (3s/4)^2 - (s/4)^2 > 0. Both diagonals are then valid.
    const std::int32_t j = s / 8 - 1;
    const auto jitter = rc::gen::weightedOneOf<std::int32_t>(
        {{1, rc::gen::just<std::int32_t>(0)}, {2, rc::gen::inRange<std::int32_t>(-j, j + 1)}});
    std::vector<std::vector<RawPoint>> v(nx + 1, std::vector<RawPoint>(ny + 1));
    for (std::size_t i = 0; i <= nx; ++i) {
      for (std::size_t k = 0; k <= ny; ++k) {
        const std::int64_t x = origin[0] + static_cast<std::int64_t>(i) * s + *jitter;
        const std::int64_t y = origin[1] + static_cast<std::int64_t>(k) * s + *jitter;
        v[i][k] = point(x, y);
      }
    }
    for (std::size_t i = 0; i < nx; ++i) {
      for (std::size_t k = 0; k < ny; ++k) {
        const RawPoint p00 = v[i][k], p10 = v[i + 1][k], p01 = v[i][k + 1], p11 = v[i + 1][k + 1];
        if (*rc::gen::arbitrary<bool>()) {
          m.triangles.push_back(permuted(RawTriangle{p00, p10, p11}, *perm_index()));
          m.triangles.push_back(permuted(RawTriangle{p00, p11, p01}, *perm_index()));
        } else {
          m.triangles.push_back(permuted(RawTriangle{p00, p10, p01}, *perm_index()));
          m.triangles.push_back(permuted(RawTriangle{p10, p11, p01}, *perm_index()));
        }
      }
    }
    for (std::size_t i = 0; i < nx; ++i)
      m.outline.push_back(v[i][0]);
    for (std::size_t k = 0; k < ny; ++k)
      m.outline.push_back(v[nx][k]);
    for (std::size_t i = nx; i > 0; --i)
      m.outline.push_back(v[i][ny]);
    for (std::size_t k = ny; k > 0; --k)
      m.outline.push_back(v[0][k]);
    return m;
  });
}

// A closed fan: rim vertex i at angle 2 pi (i + u_i) / k with u_i in [0.1, 0.9] and k >= 4, so
// consecutive angles differ by 2 pi [0.2, 1.8] / k <= 0.9 pi < pi, and radius >= 3 px, so
// rounding to the 1/256 grid cannot reorder them. The rim is a star-shaped simple polygon.
rc::Gen<Mesh> fan(std::int32_t w, std::int32_t h) {
  return rc::gen::exec([w, h] {
    Mesh m;
    m.kind = MeshKind::kFan;
    const RawPoint c = *rc::gen::weightedOneOf<RawPoint>(
        {{1, raw_point_near(w, h, 0)}, {1, pixel_centre_near(w, h, 0)}});
    const std::int32_t k = *rc::gen::inRange<std::int32_t>(4, 13);
    for (std::int32_t i = 0; i < k; ++i) {
      const double u = *rc::gen::inRange<std::int32_t>(10, 91) / 100.0;
      const double r = *rc::gen::inRange<std::int32_t>(3 * kOne, 24 * kOne + 1);
      const double theta = 2.0 * std::numbers::pi * (i + u) / k;
      m.outline.push_back(point(c[0] + std::llround(r * std::cos(theta)),
                                c[1] + std::llround(r * std::sin(theta))));
    }
    for (std::size_t i = 0; i < m.outline.size(); ++i) {
      const RawPoint& a = m.outline[i];
      const RawPoint& b = m.outline[(i + 1) % m.outline.size()];
      m.triangles.push_back(permuted(RawTriangle{c, a, b}, *perm_index()));
    }
    return m;
  });
}

// A fan whose spokes run along the 8 axis and diagonal directions from a pixel centre, with
// lengths in half pixels: spokes and rim edges through many pixel centres, horizontal and
// vertical edges everywhere.
rc::Gen<Mesh> lattice_fan(std::int32_t w, std::int32_t h) {
  return rc::gen::exec([w, h] {
    static constexpr std::array<RawPoint, 8> kDirs = {
        {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}}};
    Mesh m;
    m.kind = MeshKind::kLatticeFan;
    const RawPoint c = *pixel_centre_near(w, h, 0);
    const auto keep = *rc::gen::arbitrary<std::array<bool, 8>>();
    std::vector<std::size_t> chosen;
    for (std::size_t i = 0; i < 8; ++i) {
      // Keep every other direction at least, so that consecutive spokes are < 180 deg apart.
      if (keep[i] || i % 2 == 0)
        chosen.push_back(i);
    }
    for (const std::size_t i : chosen) {
      const std::int32_t len = *rc::gen::inRange<std::int32_t>(1, 17) * kHalf;
      m.outline.push_back(point(c[0] + kDirs[i][0] * len, c[1] + kDirs[i][1] * len));
    }
    for (std::size_t i = 0; i < m.outline.size(); ++i) {
      m.triangles.push_back(permuted(
          RawTriangle{c, m.outline[i], m.outline[(i + 1) % m.outline.size()]}, *perm_index()));
    }
    return m;
  });
}

// The Delaunay triangulation (CGAL) of random points on the 1/256 grid, some on the
// half-pixel lattice (pixel centres, pixel corners); the outline is their convex hull.
rc::Gen<Mesh> delaunay(std::int32_t w, std::int32_t h) {
  return rc::gen::exec([w, h] {
    Mesh m;
    m.kind = MeshKind::kDelaunay;
    const RawTriangle seed = *nondegenerate_raw_triangle_near(w, h);
    const auto lattice = rc::gen::apply(
        [](std::int32_t i, std::int32_t j) {
          return RawPoint{i * kHalf, j * kHalf};
        },
        rc::gen::inRange<std::int32_t>(-2 * kMargin, 2 * (w + kMargin)),
        rc::gen::inRange<std::int32_t>(-2 * kMargin, 2 * (h + kMargin)));
    const auto pts = *rc::gen::container<std::vector<RawPoint>>(
        static_cast<std::size_t>(*rc::gen::inRange<std::int32_t>(0, 25)),
        rc::gen::weightedOneOf<RawPoint>({{1, raw_point_near(w, h, kMargin)}, {1, lattice}}));
    std::vector<K::Point_2> points;
    for (const RawPoint& p : seed)
      points.emplace_back(p[0], p[1]);
    for (const RawPoint& p : pts)
      points.emplace_back(p[0], p[1]);
    const CGAL::Delaunay_triangulation_2<K> dt(points.begin(), points.end());
    const auto raw = [](const K::Point_2& p) {
      // Exact: the coordinates are integers below 2^24 stored in doubles.
      return RawPoint{static_cast<std::int32_t>(p.x()), static_cast<std::int32_t>(p.y())};
    };
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
      m.triangles.push_back(
          permuted(RawTriangle{raw(f->vertex(0)->point()), raw(f->vertex(1)->point()),
                               raw(f->vertex(2)->point())},
                   *perm_index()));
    }
    std::vector<K::Point_2> hull;
    CGAL::convex_hull_2(points.begin(), points.end(), std::back_inserter(hull));
    for (const K::Point_2& p : hull)
      m.outline.push_back(raw(p));
    return m;
  });
}

} // namespace

rc::Gen<Mesh> mesh_near(std::int32_t width, std::int32_t height) {
  return rc::gen::weightedOneOf<Mesh>({
      {2, jittered_grid(width, height)},
      {1, fan(width, height)},
      {1, lattice_fan(width, height)},
      {2, delaunay(width, height)},
  });
}

Scene to_kernel_scene(const TriScene& s) {
  Scene k;
  k.width = s.width;
  k.height = s.height;
  set_raster_state(k, s.state);
  for (const GenTriangle& t : s.triangles) {
    Primitive p;
    p.type = PrimitiveType::kTriangle;
    p.v.assign(t.v.begin(), t.v.end());
    k.primitives.push_back(p);
  }
  return k;
}

std::string to_json(const TriScene& s) {
  std::ostringstream os;
  os << "{\"version\": 1, \"target\": {\"width\": " << s.width << ", \"height\": " << s.height
     << "}, \"cull\": \"" << to_string(s.state.cull) << "\", \"front_face\": \""
     << to_string(s.state.front_face) << "\", \"fill\": \"" << to_string(s.state.fill)
     << "\", \"primitives\": [";
  for (std::size_t i = 0; i < s.triangles.size(); ++i) {
    os << (i ? ", " : "") << "{\"type\": \"triangle\", \"v\": [";
    for (std::size_t v = 0; v < 3; ++v) {
      os << (v ? ", " : "") << "[";
      show_float(s.triangles[i].v[v][0], os);
      os << ", ";
      show_float(s.triangles[i].v[v][1], os);
      os << "]";
    }
    os << "]}";
  }
  os << "]}";
  return os.str();
}

void showValue(const GenTriangle& t, std::ostream& os) {
  os << to_string(t.kind) << " [";
  for (std::size_t v = 0; v < 3; ++v) {
    os << (v ? ", " : "") << "[";
    show_float(t.v[v][0], os);
    os << ", ";
    show_float(t.v[v][1], os);
    os << "]";
  }
  os << "]";
}

void showValue(const TriScene& s, std::ostream& os) {
  os << "scene (kinds:";
  for (const GenTriangle& t : s.triangles)
    os << " " << to_string(t.kind) << ";";
  os << ")\n" << to_json(s);
}

namespace {
void show_raw(const RawPoint& p, std::ostream& os) {
  os << "(" << p[0] << ", " << p[1] << ")";
}
void show_raw(const RawTriangle& t, std::ostream& os) {
  os << "[";
  for (std::size_t i = 0; i < 3; ++i) {
    if (i)
      os << ", ";
    show_raw(t[i], os);
  }
  os << "]";
}
} // namespace

void showValue(const SharedEdgePair& p, std::ostream& os) {
  os << "shared edge (raw 16.8) ";
  show_raw(p.a, os);
  os << " - ";
  show_raw(p.b, os);
  os << "; first ";
  show_raw(p.first, os);
  os << "; second ";
  show_raw(p.second, os);
}

void showValue(const Mesh& m, std::ostream& os) {
  os << to_string(m.kind) << " mesh (raw 16.8), outline [";
  for (std::size_t i = 0; i < m.outline.size(); ++i) {
    if (i)
      os << ", ";
    show_raw(m.outline[i], os);
  }
  os << "], triangles [";
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    if (i)
      os << ", ";
    show_raw(m.triangles[i], os);
  }
  os << "]";
}

} // namespace rastrules::gen
