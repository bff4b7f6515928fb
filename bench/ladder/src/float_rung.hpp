// SPDX-License-Identifier: MIT
// The `float` and `double` rungs' setup (BENCH.LADDER.RUNGS), shared by the scalar loop
// (rungs.cpp) and the SIMD one (float_simd_avx2.cpp), so that both decide every centre with
// the same values: the clockwise-oriented vertices in F and the centres of the bounding box.
// Implements: BENCH.LADDER.RUNGS (float, double, float-simd)

#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "rastrules/bench/ladder.hpp"

namespace rastrules::bench {

// Pixels whose centre (p + 1/2) lies in [lo, hi] on one axis, clipped to [0, n): computed in
// the rung's own arithmetic type.
template <class F> std::pair<std::int32_t, std::int32_t> centre_span(F lo, F hi, std::int32_t n) {
  const F a = std::ceil(lo - F(0.5));
  const F b = std::floor(hi - F(0.5));
  const F first = std::max(a, F(0));
  const F last = std::min(b, static_cast<F>(n - 1));
  if (!(first <= last))
    return {0, -1};
  return {static_cast<std::int32_t>(first), static_cast<std::int32_t>(last)};
}

// The vertices in F, clockwise (swapped when the area is negative), and the box of centres
// [px0, px1] x [py0, py1]; empty (px0 > px1 or py0 > py1) for a zero-area triangle.
template <class F> struct FloatSetup {
  F x[3] = {}, y[3] = {};
  std::int32_t px0 = 0, px1 = -1, py0 = 0, py1 = -1;
};

template <class F>
[[nodiscard]] FloatSetup<F> float_setup(const FloatTriangle& tri, std::int32_t w, std::int32_t h) {
  FloatSetup<F> s;
  for (int i = 0; i < 3; ++i) {
    s.x[i] = static_cast<F>(tri[static_cast<std::size_t>(i)][0]);
    s.y[i] = static_cast<F>(tri[static_cast<std::size_t>(i)][1]);
  }
  const F area = (s.x[1] - s.x[0]) * (s.y[2] - s.y[0]) - (s.y[1] - s.y[0]) * (s.x[2] - s.x[0]);
  if (area == F(0))
    return s;
  if (area < F(0)) {
    std::swap(s.x[1], s.x[2]);
    std::swap(s.y[1], s.y[2]);
  }
  std::tie(s.px0, s.px1) =
      centre_span<F>(std::min({s.x[0], s.x[1], s.x[2]}), std::max({s.x[0], s.x[1], s.x[2]}), w);
  std::tie(s.py0, s.py1) =
      centre_span<F>(std::min({s.y[0], s.y[1], s.y[2]}), std::max({s.y[0], s.y[1], s.y[2]}), h);
  return s;
}

// The float-simd rung in AVX2 (float_simd_avx2.cpp, compiled with -mavx2 and without FMA
// contraction; call only when the processor has AVX2): the float rung's edge functions
// evaluated the same way in 8 lanes, so its centres are exactly the float rung's. Returns the
// number of covered centres; with keys, also appends coverage_key(id, x, y) of each, in
// row-major order.
std::uint64_t float_simd_avx2(const FloatTriangle& tri, std::int32_t w, std::int32_t h,
                              std::vector<std::uint64_t>* keys, std::uint32_t id);

} // namespace rastrules::bench
