// SPDX-License-Identifier: MIT
// The `limit` rung (BENCH.LADDER.RUNGS): a bare loop that steps three 32-bit edge functions
// incrementally over each bounding box and counts the centres where all three are >= 0. No tie
// rule, no output, no setup beyond the three edge equations. Not a rasterizer: what the
// hardware can do at best.
// Implements: BENCH.LADDER.RUNGS (limit)

#pragma once

#include <cstdint>
#include <string_view>

#include "rastrules/bench/ladder.hpp"

namespace rastrules::bench {

// The three edge equations of a triangle over its bounding box: vertices at 4 subpixel bits
// (so that the values of triangles up to about 2896 px across fit in 32 bits), values relative
// to the first centre of the box.
struct LimitSetup {
  std::int32_t nx = 0, ny = 0;    // box size in pixels (0: nothing to do)
  std::int32_t e[3] = {0, 0, 0};  // at the first centre
  std::int32_t dx[3] = {0, 0, 0}; // per pixel to the right
  std::int32_t dy[3] = {0, 0, 0}; // per row down
};
[[nodiscard]] LimitSetup limit_setup(const FloatTriangle& tri, std::int32_t w, std::int32_t h);

std::uint64_t limit_loop_scalar(const LimitSetup& s);
std::uint64_t limit_loop_avx2(const LimitSetup& s);   // limit_avx2.cpp (-mavx2)
std::uint64_t limit_loop_avx512(const LimitSetup& s); // limit_avx512.cpp (-mavx512f)

// The instruction set the limit rung runs, chosen once at run time: best_isa() (so that
// RASTRULES_MAX_ISA limits it as it limits the kernel): "avx512", "avx2" or "scalar"; and the
// pixels its loop steps at once (16, 8 or 1), the batch counter's row width on the same ISA.
[[nodiscard]] std::string_view limit_isa();
[[nodiscard]] int limit_lanes();
// limit_setup then the chosen loop.
[[nodiscard]] std::uint64_t limit_count(const FloatTriangle& tri, std::int32_t w, std::int32_t h);

} // namespace rastrules::bench
