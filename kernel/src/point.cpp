// SPDX-License-Identifier: MIT
// Points as two triangles in the Z pattern (rastrules/point.hpp).
// Implements: POINT.SHAPE.SQUARE, POINT.SHAPE.TWO_TRIANGLES, POINT.CULL.NONE

#include "rastrules/point.hpp"

#include <array>
#include <cstddef>
#include <cstdint>

#include "rastrules/formula/point.hpp"

namespace rastrules {

// rule: POINT.SHAPE.SQUARE, POINT.SHAPE.TWO_TRIANGLES
std::array<std::array<Vec2, 3>, 2> point_triangles(Vec2 c) {
  const auto tris = formula::point_z_triangles<std::int64_t>(c.x.raw(), c.y.raw(), kSubpixelHalf);
  std::array<std::array<Vec2, 3>, 2> out{};
  for (std::size_t t = 0; t < 2; ++t) {
    for (std::size_t v = 0; v < 3; ++v) {
      // In range by the precondition (POINT.RANGE): |c| + 128 fits the vertex range.
      out[t][v] = Vec2{Subpixel::from_raw(static_cast<std::int32_t>(tris[t][v][0])),
                       Subpixel::from_raw(static_cast<std::int32_t>(tris[t][v][1]))};
    }
  }
  return out;
}

// rule: POINT.CULL.NONE
std::array<TriangleSetup, 2> setup_point(Vec2 c, const RasterState& state) {
  RasterState no_cull = state;
  no_cull.cull = CullMode::kNone;
  const auto tris = point_triangles(c);
  return {setup_triangle(tris[0], no_cull), setup_triangle(tris[1], no_cull)};
}

} // namespace rastrules
