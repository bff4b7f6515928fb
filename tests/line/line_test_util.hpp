// SPDX-License-Identifier: MIT
// Helpers for the aliased-line example tests: lines written in pixels (values exact on the
// 16.8 grid), collected pixel lists.

#pragma once

#include <cstdint>
#include <vector>

#include "rastrules/line.hpp"
#include "rastrules/line_aliased.hpp"
#include "support.hpp"

namespace rastrules::test {

inline std::vector<Pixel> line_pixels(Px a, Px b, LineMode mode, std::int32_t w = 32,
                                      std::int32_t h = 32) {
  std::vector<Pixel> out;
  rasterize_aliased_line(sample_px(a.x, a.y), sample_px(b.x, b.y), mode, w, h,
                         [&](std::int32_t x, std::int32_t y) {
                           out.push_back({x, y});
                         });
  return out;
}

inline bool covers_px(Px a, Px b, LineMode mode, std::int32_t px, std::int32_t py) {
  return aliased_line_covers(sample_px(a.x, a.y), sample_px(b.x, b.y), mode, px, py);
}

} // namespace rastrules::test
