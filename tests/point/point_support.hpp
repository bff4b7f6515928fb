// SPDX-License-Identifier: MIT
// Helpers for the point examples: the pixels a point covers through the kernel's point path
// (setup_point + the triangle traversal), counting how often each pixel is emitted.

#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "rastrules/point.hpp"
#include "rastrules/raster/walk.hpp"
#include "rastrules/triangle.hpp"
#include "support.hpp"

namespace rastrules::test {

// Returns, for every pixel of the width x height target emitted by either triangle of the
// point with snapped centre c, how many times it was emitted.
inline std::map<Pixel, int> point_hits(Vec2 c, std::int32_t width, std::int32_t height,
                                       const RasterState& state = {}) {
  std::map<Pixel, int> hits;
  for (const TriangleSetup& t : setup_point(c, state)) {
    raster::walk_triangle(t, width, height, [&](std::int32_t x, std::int32_t y) {
      ++hits[Pixel{x, y}];
    });
  }
  return hits;
}

// Returns the pixels of point_hits, sorted by (y, x).
inline std::vector<Pixel> point_pixels(Vec2 c, std::int32_t width, std::int32_t height,
                                       const RasterState& state = {}) {
  std::vector<Pixel> out;
  for (const auto& [p, n] : point_hits(c, width, height, state))
    out.push_back(p);
  return out;
}

} // namespace rastrules::test
