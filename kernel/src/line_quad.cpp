// SPDX-License-Identifier: MIT
// Quadrilateral lines: a parallelogram of two triangles around the segment (rastrules/line.hpp).
// Implements: LINE.QUAD.SHAPE, LINE.QUAD.WIDTH, LINE.QUAD.CORNERS, LINE.QUAD.ZERO_LENGTH,
//             LINE.QUAD.NO_CULL

#include <array>
#include <cstdint>
#include <vector>

#include "rastrules/line.hpp"
#include "rastrules/line_quad.hpp"

namespace rastrules {

namespace {

Vec2 offset_by(Vec2 p, QuadOffset o, std::int32_t sign) {
  return Vec2{Subpixel::from_raw(p.x.raw() + sign * o.x),
              Subpixel::from_raw(p.y.raw() + sign * o.y)};
}

} // namespace

// rule: LINE.QUAD.SHAPE, LINE.QUAD.WIDTH, LINE.QUAD.CORNERS, LINE.QUAD.ZERO_LENGTH
std::vector<std::array<Vec2, 3>> quad_line_triangles(Vec2 a, Vec2 b, LineMode mode) {
  // rule: LINE.QUAD.ZERO_LENGTH
  if (a == b)
    return {};
  // rule: LINE.QUAD.WIDTH
  QuadHalfWidth hw = kQuadWideHalfWidth;
  if (mode == LineMode::kQuadNarrow)
    hw = kQuadNarrowHalfWidth;
  const std::int64_t dx = std::int64_t{b.x.raw()} - a.x.raw();
  const std::int64_t dy = std::int64_t{b.y.raw()} - a.y.raw();
  // rule: LINE.QUAD.CORNERS
  const QuadOffset o = quad_line_offset(dx, dy, hw);
  // rule: LINE.QUAD.SHAPE
  // Corners in clockwise order (y down): a - o, b - o, b + o, a + o; the diagonal joins a - o
  // and b + o, which is the same segment for the line drawn b -> a (its offset is -o).
  const Vec2 a_minus = offset_by(a, o, -1);
  const Vec2 b_minus = offset_by(b, o, -1);
  const Vec2 b_plus = offset_by(b, o, 1);
  const Vec2 a_plus = offset_by(a, o, 1);
  return {std::array<Vec2, 3>{a_minus, b_minus, b_plus},
          std::array<Vec2, 3>{a_minus, b_plus, a_plus}};
}

// rule: LINE.QUAD.NO_CULL
std::vector<TriangleSetup> setup_quad_line(Vec2 a, Vec2 b, LineMode mode,
                                           const RasterState& state) {
  RasterState no_cull = state;
  no_cull.cull = CullMode::kNone;
  std::vector<TriangleSetup> out;
  for (const auto& t : quad_line_triangles(a, b, mode))
    out.push_back(setup_triangle(t, no_cull));
  return out;
}

} // namespace rastrules
