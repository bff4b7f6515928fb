// SPDX-License-Identifier: MIT
// Bounding-box traversal of a set-up triangle (layer 3: mechanism). Its only correctness
// criterion: it yields exactly the pixel centres inside the target for which covers() is
// true, in row-major order (y, then x). Checked by properties/tri/walk_props.cpp.
// Implements: RASTER.WALK.BBOX, RASTER.TARGET.CLIP, FIX.BIAS.FORM, FIX.STEP.INCREMENTAL

#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

#include "rastrules/fixed.hpp"
#include "rastrules/formula/edge.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules::raster {

struct PixelRect {
  std::int32_t x0 = 0, y0 = 0, x1 = -1, y1 = -1; // inclusive; empty when x1 < x0 or y1 < y0
  [[nodiscard]] constexpr bool empty() const { return x1 < x0 || y1 < y0; }
};

// Returns the pixels of the target [0, width) x [0, height) that have a sample point in the
// bounding box of the snapped vertices, for sample points at raw offsets [dx0, dx1] x [dy0, dy1]
// from the pixel centre (all zero: the pixel centre itself).
// rule: RASTER.WALK.BBOX, RASTER.TARGET.CLIP
[[nodiscard]] constexpr PixelRect pixel_bounds_with_offsets(const TriangleSetup& t,
                                                            std::int32_t width, std::int32_t height,
                                                            std::int64_t dx0, std::int64_t dx1,
                                                            std::int64_t dy0, std::int64_t dy1) {
  std::int64_t minx = t.snapped[0].x.raw(), maxx = minx;
  std::int64_t miny = t.snapped[0].y.raw(), maxy = miny;
  for (const Vec2& v : t.snapped) {
    minx = std::min<std::int64_t>(minx, v.x.raw());
    maxx = std::max<std::int64_t>(maxx, v.x.raw());
    miny = std::min<std::int64_t>(miny, v.y.raw());
    maxy = std::max<std::int64_t>(maxy, v.y.raw());
  }
  // A sample of pixel p is at p*256 + 128 + d: pixel p has one in [min, max] only if
  // p*256 + 128 + d1 >= min and p*256 + 128 + d0 <= max.
  const std::int64_t px0 = -floor_div(-(minx - kSubpixelHalf - dx1), kSubpixelOne);
  const std::int64_t px1 = floor_div(maxx - kSubpixelHalf - dx0, kSubpixelOne);
  const std::int64_t py0 = -floor_div(-(miny - kSubpixelHalf - dy1), kSubpixelOne);
  const std::int64_t py1 = floor_div(maxy - kSubpixelHalf - dy0, kSubpixelOne);
  PixelRect r;
  r.x0 = static_cast<std::int32_t>(std::max<std::int64_t>(px0, 0));
  r.y0 = static_cast<std::int32_t>(std::max<std::int64_t>(py0, 0));
  r.x1 = static_cast<std::int32_t>(std::min<std::int64_t>(px1, std::int64_t{width} - 1));
  r.y1 = static_cast<std::int32_t>(std::min<std::int64_t>(py1, std::int64_t{height} - 1));
  return r;
}

// Returns the pixels whose centres lie in the bounding box of the snapped vertices, clipped
// to the target [0, width) x [0, height).
// rule: RASTER.WALK.BBOX, RASTER.TARGET.CLIP
[[nodiscard]] constexpr PixelRect pixel_bounds(const TriangleSetup& t, std::int32_t width,
                                               std::int32_t height) {
  return pixel_bounds_with_offsets(t, width, height, 0, 0, 0, 0);
}

// The pixels a walk of t visits: pixel_bounds when t is rasterized, none when it is degenerate
// or culled (it covers nothing).
// rule: RASTER.WALK.BBOX
[[nodiscard]] constexpr PixelRect walk_bounds(const TriangleSetup& t, std::int32_t width,
                                              std::int32_t height) {
  return t.status == TriangleStatus::kRasterized ? pixel_bounds(t, width, height) : PixelRect{};
}

// Each edge's bias (E + bias >= 0 is the rule with its tie-break, FIX.BIAS.FORM) and its change
// over one pixel along x (FIX.STEP.INCREMENTAL), for the walks that step edge values.
struct EdgeSteps {
  std::array<std::int64_t, 3> bias{};
  std::array<std::int64_t, 3> step_x{};
};
// rule: FIX.BIAS.FORM, FIX.STEP.INCREMENTAL
[[nodiscard]] constexpr EdgeSteps edge_steps(const TriangleSetup& t) {
  EdgeSteps st;
  for (std::size_t i = 0; i < 3; ++i) {
    const EdgeSetup& e = t.edges[i];
    st.bias[i] = formula::edge_bias<std::int64_t>(e.inclusive);
    st.step_x[i] = formula::edge_step_x<std::int64_t>(e.a.y.raw(), e.b.y.raw(), kSubpixelOne);
  }
  return st;
}

// Returns the rows [y_first, y_last] of r (empty when none of them is in r).
[[nodiscard]] constexpr PixelRect rows_of(PixelRect r, std::int32_t y_first, std::int32_t y_last) {
  r.y0 = std::max(r.y0, y_first);
  r.y1 = std::min(r.y1, y_last);
  return r;
}

// Calls emit(x, y) for every covered pixel centre of t inside the target in the rows
// [y_first, y_last], row by row: what walk_triangle emits in those rows, in the same order, so
// the walks of consecutive row ranges, concatenated, are walk_triangle's.
// Each edge is evaluated directly at the start of a row and stepped by one pixel along it,
// and tested in bias form (E + bias >= 0); both are proved equal to the direct rule
// (proofs/tri/bias_form.cpp, proofs/tri/incremental_step.cpp).
// rule: RASTER.WALK.BBOX, FIX.BIAS.FORM, FIX.STEP.INCREMENTAL
template <class Emit>
constexpr void walk_triangle_rows(const TriangleSetup& t, std::int32_t width, std::int32_t height,
                                  std::int32_t y_first, std::int32_t y_last, Emit&& emit) {
  const PixelRect r = rows_of(walk_bounds(t, width, height), y_first, y_last);
  if (r.empty())
    return;
  const EdgeSteps st = edge_steps(t);
  const auto& bias = st.bias;
  const auto& step_x = st.step_x;
  for (std::int32_t y = r.y0; y <= r.y1; ++y) {
    const Vec2 start = pixel_center(r.x0, y);
    std::int64_t e0 = t.edges[0].value_at(start).raw() + bias[0];
    std::int64_t e1 = t.edges[1].value_at(start).raw() + bias[1];
    std::int64_t e2 = t.edges[2].value_at(start).raw() + bias[2];
    for (std::int32_t x = r.x0; x <= r.x1; ++x) {
      if ((e0 | e1 | e2) >= 0)
        emit(x, y);
      e0 += step_x[0];
      e1 += step_x[1];
      e2 += step_x[2];
    }
  }
}

// Calls emit(x, y) for every covered pixel centre of t inside the target, row by row.
// rule: RASTER.WALK.BBOX
template <class Emit>
constexpr void walk_triangle(const TriangleSetup& t, std::int32_t width, std::int32_t height,
                             Emit&& emit) {
  walk_triangle_rows(t, width, height, 0, height - 1, emit);
}

} // namespace rastrules::raster
