// SPDX-License-Identifier: MIT
// The `limit` rung's setup, scalar loop and run-time dispatch (BENCH.LADDER.RUNGS).
// Implements: BENCH.LADDER.RUNGS (limit)

#include "limit.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "rastrules/isa.hpp"

namespace rastrules::bench {

LimitSetup limit_setup(const FloatTriangle& tri, std::int32_t w, std::int32_t h) {
  std::int64_t x[3], y[3];
  for (std::size_t i = 0; i < 3; ++i) {
    x[i] = static_cast<std::int64_t>(std::lrint(tri[i][0] * 16.0f));
    y[i] = static_cast<std::int64_t>(std::lrint(tri[i][1] * 16.0f));
  }
  LimitSetup s;
  const std::int64_t area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
  if (area == 0)
    return s;
  if (area < 0) {
    std::swap(x[1], x[2]);
    std::swap(y[1], y[2]);
  }
  // Centres (16 p + 8) in [min, max], clipped to the target.
  const auto first = [](std::int64_t lo) { return lo <= 8 ? std::int64_t{0} : (lo - 8 + 15) / 16; };
  const std::int64_t x0 = first(std::min({x[0], x[1], x[2]}));
  const std::int64_t y0 = first(std::min({y[0], y[1], y[2]}));
  const std::int64_t mx = std::max({x[0], x[1], x[2]}), my = std::max({y[0], y[1], y[2]});
  const std::int64_t x1 = std::min<std::int64_t>(mx < 8 ? -1 : (mx - 8) / 16, w - 1);
  const std::int64_t y1 = std::min<std::int64_t>(my < 8 ? -1 : (my - 8) / 16, h - 1);
  if (x1 < x0 || y1 < y0)
    return s;
  s.nx = static_cast<std::int32_t>(x1 - x0 + 1);
  s.ny = static_cast<std::int32_t>(y1 - y0 + 1);
  const std::int64_t sx = x0 * 16 + 8, sy = y0 * 16 + 8;
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t j = (i + 1) % 3;
    s.e[i] = static_cast<std::int32_t>((x[j] - x[i]) * (sy - y[i]) - (y[j] - y[i]) * (sx - x[i]));
    s.dx[i] = static_cast<std::int32_t>(-(y[j] - y[i]) * 16);
    s.dy[i] = static_cast<std::int32_t>((x[j] - x[i]) * 16);
  }
  return s;
}

std::uint64_t limit_loop_scalar(const LimitSetup& s) {
  std::uint64_t n = 0;
  // Wrapping in uint32 (as the SIMD lanes do): never undefined behaviour.
  const auto u = [](std::int32_t v) { return static_cast<std::uint32_t>(v); };
  std::uint32_t r0 = u(s.e[0]), r1 = u(s.e[1]), r2 = u(s.e[2]);
  for (std::int32_t y = 0; y < s.ny; ++y) {
    std::uint32_t e0 = r0, e1 = r1, e2 = r2;
    for (std::int32_t x = 0; x < s.nx; ++x) {
      n += (static_cast<std::int32_t>(e0 | e1 | e2) >= 0) ? 1u : 0u;
      e0 += u(s.dx[0]);
      e1 += u(s.dx[1]);
      e2 += u(s.dx[2]);
    }
    r0 += u(s.dy[0]);
    r1 += u(s.dy[1]);
    r2 += u(s.dy[2]);
  }
  return n;
}

namespace {
using Loop = std::uint64_t (*)(const LimitSetup&);
struct Chosen {
  Loop loop;
  std::string_view name;
  int lanes;
};
// The kernel's choice (best_isa: CPUID and RASTRULES_MAX_ISA), so that the limit steps as many
// lanes as the batch counter's rows on this processor (FAST.BATCH.LANES16).
Chosen choose() {
  switch (best_isa()) {
  case Isa::kAvx512:
    return {&limit_loop_avx512, "avx512", 16};
  case Isa::kAvx2:
    return {&limit_loop_avx2, "avx2", 8};
  case Isa::kScalar:
    break;
  }
  return {&limit_loop_scalar, "scalar", 1};
}
const Chosen& chosen() {
  static const Chosen c = choose();
  return c;
}
} // namespace

std::string_view limit_isa() {
  return chosen().name;
}

int limit_lanes() {
  return chosen().lanes;
}

std::uint64_t limit_count(const FloatTriangle& tri, std::int32_t w, std::int32_t h) {
  const LimitSetup s = limit_setup(tri, w, h);
  if (s.nx == 0)
    return 0;
  return chosen().loop(s);
}

} // namespace rastrules::bench
