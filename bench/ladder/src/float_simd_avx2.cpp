// SPDX-License-Identifier: MIT
// The float-simd rung (BENCH.LADDER.RUNGS): the float rung's edge functions in 8 AVX2 lanes
// (compiled with -mavx2 -ffp-contract=off: no fused multiply-add, so every lane rounds as the
// scalar float rung does and covers exactly its centres). What exactness costs against a
// vectorised float rasterizer, not against a scalar one.
// Implements: BENCH.LADDER.RUNGS (float-simd)

#include <immintrin.h>

#include <bit>

#include "float_rung.hpp"

namespace rastrules::bench {

// rule: BENCH.LADDER.RUNGS
std::uint64_t float_simd_avx2(const FloatTriangle& tri, std::int32_t w, std::int32_t h,
                              std::vector<std::uint64_t>* keys, std::uint32_t id) {
  const FloatSetup<float> s = float_setup<float>(tri, w, h);
  if (s.px0 > s.px1 || s.py0 > s.py1)
    return 0;
  // E_i = (x[j] - x[i]) * (sy - y[i]) - (y[j] - y[i]) * (sx - x[i]), j = i + 1 mod 3, in the
  // scalar rung's order of operations.
  __m256 ax[3], ay[3], x0[3], y0[3];
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    ax[i] = _mm256_set1_ps(s.x[j] - s.x[i]);
    ay[i] = _mm256_set1_ps(s.y[j] - s.y[i]);
    x0[i] = _mm256_set1_ps(s.x[i]);
    y0[i] = _mm256_set1_ps(s.y[i]);
  }
  const __m256 lane = _mm256_setr_ps(0.5f, 1.5f, 2.5f, 3.5f, 4.5f, 5.5f, 6.5f, 7.5f);
  const __m256 zero = _mm256_setzero_ps();
  std::uint64_t n = 0;
  for (std::int32_t py = s.py0; py <= s.py1; ++py) {
    const __m256 sy = _mm256_set1_ps(static_cast<float>(py) + 0.5f);
    __m256 ty[3];
    for (int i = 0; i < 3; ++i)
      ty[i] = _mm256_mul_ps(ax[i], _mm256_sub_ps(sy, y0[i]));
    for (std::int32_t px = s.px0; px <= s.px1; px += 8) {
      // px + k + 0.5 is exact in float for the coordinates of the ladder (below 2^23).
      const __m256 sx = _mm256_add_ps(_mm256_set1_ps(static_cast<float>(px)), lane);
      __m256 inside = _mm256_castsi256_ps(_mm256_set1_epi32(-1));
      for (int i = 0; i < 3; ++i) {
        const __m256 e = _mm256_sub_ps(ty[i], _mm256_mul_ps(ay[i], _mm256_sub_ps(sx, x0[i])));
        inside = _mm256_and_ps(inside, _mm256_cmp_ps(e, zero, _CMP_GE_OQ));
      }
      auto bits = static_cast<unsigned>(_mm256_movemask_ps(inside));
      const std::int32_t left = s.px1 - px + 1;
      if (left < 8)
        bits &= (1u << left) - 1u;
      n += static_cast<unsigned>(std::popcount(bits));
      if (keys != nullptr)
        for (; bits != 0; bits &= bits - 1)
          keys->push_back(coverage_key(id, px + std::countr_zero(bits), py));
    }
  }
  return n;
}

} // namespace rastrules::bench
