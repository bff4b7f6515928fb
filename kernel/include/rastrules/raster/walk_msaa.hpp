// SPDX-License-Identifier: MIT
// Bounding-box traversal of a set-up triangle at every sample of a pattern (layer 3:
// mechanism). Its only correctness criterion: it yields, in row-major order, exactly the pixels
// of the target with a non-zero sample_coverage() mask, each with that mask.
// Implements: MSAA.COVER.SAMPLE (traversal), RASTER.TARGET.CLIP, FIX.BIAS.FORM,
//             FIX.STEP.INCREMENTAL

#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#include "rastrules/fixed.hpp"
#include "rastrules/formula/edge.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/raster/walk.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules::raster {

// Returns the pixels of the target having at least one sample of the pattern inside the
// bounding box of the snapped vertices. Samples sit up to 8/16 px left/up and 7/16 px
// right/down of the pixel centre, so a triangle can cover samples of pixels whose centres lie
// outside its bounding box: the box is widened by the pattern's actual offsets.
// Preconditions: pattern.count() >= 1.
// rule: MSAA.COVER.SAMPLE, RASTER.TARGET.CLIP
[[nodiscard]] constexpr PixelRect sample_pixel_bounds(const TriangleSetup& t,
                                                      const SamplePattern& pattern,
                                                      std::int32_t width, std::int32_t height) {
  std::int64_t ox0 = pattern.positions[0].x, ox1 = ox0;
  std::int64_t oy0 = pattern.positions[0].y, oy1 = oy0;
  for (const SampleOffset& o : pattern.positions) {
    ox0 = std::min<std::int64_t>(ox0, o.x);
    ox1 = std::max<std::int64_t>(ox1, o.x);
    oy0 = std::min<std::int64_t>(oy0, o.y);
    oy1 = std::max<std::int64_t>(oy1, o.y);
  }
  const std::int64_t g = kSampleGridUnit;
  return pixel_bounds_with_offsets(t, width, height, g * ox0, g * ox1, g * oy0, g * oy1);
}

// The pixels a per-sample walk of t visits: sample_pixel_bounds when t is rasterized, none when
// it is degenerate or culled.
// rule: MSAA.COVER.SAMPLE
[[nodiscard]] constexpr PixelRect sample_walk_bounds(const TriangleSetup& t,
                                                     const SamplePattern& pattern,
                                                     std::int32_t width, std::int32_t height) {
  return t.status == TriangleStatus::kRasterized ? sample_pixel_bounds(t, pattern, width, height)
                                                 : PixelRect{};
}

// Calls emit(x, y, mask) for every pixel of the target where t covers at least one sample of
// the pattern, row by row; bit k of mask is sample k (before any sample mask). Each sample's
// edge values are evaluated directly at the start of a row and stepped by one pixel, in bias
// form, exactly as walk_triangle does at the pixel centre (the step and the bias do not depend
// on the point they start from).
// Preconditions: 1 <= pattern.count() <= kMaxSamples; offsets on the sample grid.
// rule: MSAA.COVER.SAMPLE, FIX.BIAS.FORM, FIX.STEP.INCREMENTAL
template <class Emit>
constexpr void walk_triangle_samples(const TriangleSetup& t, const SamplePattern& pattern,
                                     std::int32_t width, std::int32_t height, Emit&& emit) {
  const PixelRect r = sample_walk_bounds(t, pattern, width, height);
  if (r.empty())
    return;
  const std::size_t n = pattern.count();
  const EdgeSteps st = edge_steps(t);
  const auto& bias = st.bias;
  const auto& step_x = st.step_x;
  std::array<std::array<std::int64_t, 3>, kMaxSamples> e{};
  for (std::int32_t y = r.y0; y <= r.y1; ++y) {
    for (std::size_t k = 0; k < n; ++k) {
      const Vec2 s = sample_position(r.x0, y, pattern.positions[k]);
      for (std::size_t i = 0; i < 3; ++i)
        e[k][i] = t.edges[i].value_at(s).raw() + bias[i];
    }
    for (std::int32_t x = r.x0; x <= r.x1; ++x) {
      std::uint32_t mask = 0;
      for (std::size_t k = 0; k < n; ++k) {
        if ((e[k][0] | e[k][1] | e[k][2]) >= 0)
          mask |= std::uint32_t{1} << k;
        e[k][0] += step_x[0];
        e[k][1] += step_x[1];
        e[k][2] += step_x[2];
      }
      if (mask != 0)
        emit(x, y, mask);
    }
  }
}

} // namespace rastrules::raster
