// SPDX-License-Identifier: MIT
// Generators of the fast traversal's properties: triangles in raw 16.8 units near the target
// (tie-heavy: vertices on the 1/16 sample grid, pixel centres and corners), anywhere in
// SNAP.VERTEX.RANGE, at its ends, and slivers whose lane steps A, B approach 2^24; the
// instruction sets this processor runs; and the comparison of the fast and plain walks.
// Implements (generators for): FAST.EQUALS.PLAIN, FAST.TILE.CLASSIFY, FAST.LANE.I32,
//   FAST.ISA.DISPATCH

#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <rapidcheck.h>

#include "../msaa/msaa_gen.hpp"
#include "rastrules/fixed.hpp"
#include "rastrules/gen/triangles.hpp"
#include "rastrules/isa.hpp"
#include "rastrules/snap.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules::fast_gen {

using RawTri = std::array<std::array<std::int64_t, 2>, 3>;

enum class Shape { kNear, kTies, kCentres, kAnywhere, kRangeEnds, kSliver, kCrossingSliver };

inline const char* to_string(Shape s) {
  switch (s) {
  case Shape::kNear:
    return "near the target";
  case Shape::kTies:
    return "tie-heavy (sample grid, centres, corners)";
  case Shape::kCentres:
    return "vertices on pixel centres (edges through centres)";
  case Shape::kAnywhere:
    return "anywhere in the range";
  case Shape::kRangeEnds:
    return "vertices at the range ends";
  case Shape::kSliver:
    return "sliver between far vertices";
  case Shape::kCrossingSliver:
    return "sliver crossing the whole range";
  }
  return "?";
}

struct GenTri {
  Shape shape = Shape::kNear;
  RawTri v{};
};

inline std::int64_t clamp_raw(std::int64_t c) {
  return std::clamp<std::int64_t>(c, kMinVertexRaw, kMaxVertexRaw);
}

inline rc::Gen<std::int64_t> any_raw() {
  return msaa_gen::full_size(rc::gen::weightedOneOf<std::int64_t>(
      {{4, rc::gen::inRange<std::int64_t>(kMinVertexRaw, std::int64_t{kMaxVertexRaw} + 1)},
       {1, rc::gen::element<std::int64_t>(kMinVertexRaw, kMinVertexRaw + 1, kMaxVertexRaw - 1,
                                          kMaxVertexRaw, 0)}}));
}

// A raw coordinate within `margin` pixels of [0, side] on the 1/256 grid.
inline rc::Gen<std::int64_t> near_raw(std::int32_t side, std::int32_t margin) {
  return msaa_gen::full_size(rc::gen::inRange<std::int64_t>(
      -std::int64_t{margin} * 256, (std::int64_t{side} + margin) * 256 + 1));
}

// A triangle for a w x h target, of any of the shapes.
inline rc::Gen<GenTri> triangle(std::int32_t w, std::int32_t h) {
  return msaa_gen::full_size<GenTri>(rc::gen::exec([=] {
    GenTri t;
    t.shape = *rc::gen::weightedElement<Shape>({{3, Shape::kNear},
                                                {3, Shape::kTies},
                                                {3, Shape::kCentres},
                                                {1, Shape::kAnywhere},
                                                {1, Shape::kRangeEnds},
                                                {2, Shape::kSliver},
                                                {2, Shape::kCrossingSliver}});
    switch (t.shape) {
    case Shape::kNear:
      for (auto& p : t.v)
        p = {*near_raw(w, 40), *near_raw(h, 40)};
      break;
    case Shape::kTies:
      for (auto& p : t.v)
        p = {*msaa_gen::coord(w), *msaa_gen::coord(h)};
      if (*rc::gen::inRange(0, 3) == 0)
        t.v[1][1] = t.v[0][1]; // a horizontal edge
      if (*rc::gen::inRange(0, 3) == 0)
        t.v[2][0] = t.v[1][0]; // a vertical edge
      break;
    case Shape::kCentres: {
      // Every vertex on a pixel centre: each edge passes through the centres at multiples of
      // its reduced direction, so small triangles have several centres exactly on edges.
      const auto centre = [](std::int32_t s) {
        return rc::gen::map(rc::gen::inRange<std::int64_t>(-2, s + 2),
                            [](std::int64_t k) { return 256 * k + 128; });
      };
      const std::int64_t x0 = *centre(w), y0 = *centre(h);
      const std::int64_t r = 256 * *rc::gen::inRange<std::int64_t>(1, 20);
      for (auto& p : t.v)
        p = {x0 + 256 * *rc::gen::inRange<std::int64_t>(-r / 256, r / 256 + 1),
             y0 + 256 * *rc::gen::inRange<std::int64_t>(-r / 256, r / 256 + 1)};
      break;
    }
    case Shape::kAnywhere:
      for (auto& p : t.v)
        p = {*any_raw(), *any_raw()};
      break;
    case Shape::kRangeEnds:
      for (auto& p : t.v) {
        p = {*rc::gen::element<std::int64_t>(kMinVertexRaw, kMaxVertexRaw, *near_raw(w, 2)),
             *rc::gen::element<std::int64_t>(kMinVertexRaw, kMaxVertexRaw, *near_raw(h, 2))};
      }
      break;
    case Shape::kSliver: {
      // a and b far apart, c within a few units of a point of the line through them near
      // the target: a thin triangle with |A| or |B| up to 2^24 - 1 crossing the target.
      const std::array<std::int64_t, 2> m = {*near_raw(w, 1), *near_raw(h, 1)};
      const std::array<std::int64_t, 2> a = {*any_raw(), *any_raw()};
      const std::array<std::int64_t, 2> b = {clamp_raw(2 * m[0] - a[0]),
                                             clamp_raw(2 * m[1] - a[1])};
      const std::int64_t e = *rc::gen::inRange<std::int64_t>(-600, 601);
      const std::int64_t f = *rc::gen::inRange<std::int64_t>(-600, 601);
      t.v = {a, b, {clamp_raw(m[0] + e), clamp_raw(m[1] + f)}};
      break;
    }
    case Shape::kCrossingSliver: {
      // From one end of the range to the other along y (or x), a few pixels wide at most.
      const bool vertical = *rc::gen::arbitrary<bool>();
      const std::int32_t side = vertical ? w : h;
      const std::int64_t x0 = *near_raw(side, 2), x1 = *near_raw(side, 2);
      const std::int64_t d = *rc::gen::inRange<std::int64_t>(-1024, 1025);
      const std::int64_t lo = *rc::gen::element<std::int64_t>(kMinVertexRaw, kMinVertexRaw + 3);
      const std::int64_t hi = *rc::gen::element<std::int64_t>(kMaxVertexRaw, kMaxVertexRaw - 5);
      t.v = {std::array<std::int64_t, 2>{x0, lo}, {x1, hi}, {clamp_raw(x1 + d), hi}};
      if (*rc::gen::arbitrary<bool>())
        t.v[2] = {clamp_raw(x0 + d), lo};
      if (!vertical)
        for (auto& p : t.v)
          std::swap(p[0], p[1]);
      break;
    }
    }
    for (auto& p : t.v)
      p = {clamp_raw(p[0]), clamp_raw(p[1])};
    return t;
  }));
}

inline TriangleSetup setup(const GenTri& t, const RasterState& state) {
  std::array<Vec2, 3> v{};
  for (std::size_t i = 0; i < 3; ++i) {
    v[i] = Vec2{Subpixel::from_raw(static_cast<std::int32_t>(t.v[i][0])),
                Subpixel::from_raw(static_cast<std::int32_t>(t.v[i][1]))};
  }
  return setup_triangle(v, state);
}

inline std::string show(const GenTri& t, std::int32_t w, std::int32_t h) {
  std::ostringstream os;
  os << to_string(t.shape) << " on " << w << " x " << h << ": raw";
  for (const auto& p : t.v)
    os << " (" << p[0] << ", " << p[1] << ")";
  return os.str();
}

// The instruction sets this build and processor run.
inline std::vector<Isa> supported_isas() {
  std::vector<Isa> out;
  for (Isa isa : {Isa::kScalar, Isa::kAvx2, Isa::kAvx512})
    if (isa_supported(isa))
      out.push_back(isa);
  return out;
}

} // namespace rastrules::fast_gen
