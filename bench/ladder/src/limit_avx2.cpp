// SPDX-License-Identifier: MIT
// The `limit` rung's loop in AVX2 (compiled with -mavx2; called only when the processor has
// AVX2, limit.cpp): 8 lanes of 32-bit edge values stepped incrementally.
// Implements: BENCH.LADDER.RUNGS (limit)

#include <immintrin.h>

#include <bit>

#include "limit.hpp"

namespace rastrules::bench {

std::uint64_t limit_loop_avx2(const LimitSetup& s) {
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  __m256i row[3], step8[3];
  for (int i = 0; i < 3; ++i) {
    row[i] = _mm256_add_epi32(_mm256_set1_epi32(s.e[i]),
                              _mm256_mullo_epi32(lane, _mm256_set1_epi32(s.dx[i])));
    step8[i] =
        _mm256_set1_epi32(static_cast<std::int32_t>(static_cast<std::uint32_t>(s.dx[i]) * 8u));
  }
  const __m256i dy0 = _mm256_set1_epi32(s.dy[0]), dy1 = _mm256_set1_epi32(s.dy[1]),
                dy2 = _mm256_set1_epi32(s.dy[2]);
  const std::int32_t full = s.nx / 8, rest = s.nx % 8;
  const unsigned tail = (1u << rest) - 1u;
  std::uint64_t n = 0;
  for (std::int32_t y = 0; y < s.ny; ++y) {
    __m256i e0 = row[0], e1 = row[1], e2 = row[2];
    for (std::int32_t k = 0; k < full; ++k) {
      const __m256i o = _mm256_or_si256(_mm256_or_si256(e0, e1), e2);
      const auto outside = static_cast<unsigned>(_mm256_movemask_ps(_mm256_castsi256_ps(o)));
      n += static_cast<unsigned>(std::popcount(~outside & 0xffu));
      e0 = _mm256_add_epi32(e0, step8[0]);
      e1 = _mm256_add_epi32(e1, step8[1]);
      e2 = _mm256_add_epi32(e2, step8[2]);
    }
    if (rest != 0) {
      const __m256i o = _mm256_or_si256(_mm256_or_si256(e0, e1), e2);
      const auto outside = static_cast<unsigned>(_mm256_movemask_ps(_mm256_castsi256_ps(o)));
      n += static_cast<unsigned>(std::popcount(~outside & tail));
    }
    row[0] = _mm256_add_epi32(row[0], dy0);
    row[1] = _mm256_add_epi32(row[1], dy1);
    row[2] = _mm256_add_epi32(row[2], dy2);
  }
  return n;
}

} // namespace rastrules::bench
