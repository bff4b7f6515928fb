// SPDX-License-Identifier: MIT
// The `limit` rung's loop in AVX-512F (compiled with -mavx512f; called only when the processor
// has it, limit.cpp): 16 lanes of 32-bit edge values stepped incrementally.
// Implements: BENCH.LADDER.RUNGS (limit)

#include <immintrin.h>

#include <bit>

#include "limit.hpp"

namespace rastrules::bench {

std::uint64_t limit_loop_avx512(const LimitSetup& s) {
  const __m512i lane = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  __m512i row[3], step16[3], dy[3];
  for (int i = 0; i < 3; ++i) {
    row[i] = _mm512_add_epi32(_mm512_set1_epi32(s.e[i]),
                              _mm512_mullo_epi32(lane, _mm512_set1_epi32(s.dx[i])));
    step16[i] =
        _mm512_set1_epi32(static_cast<std::int32_t>(static_cast<std::uint32_t>(s.dx[i]) * 16u));
    dy[i] = _mm512_set1_epi32(s.dy[i]);
  }
  const __m512i zero = _mm512_setzero_si512();
  const std::int32_t full = s.nx / 16, rest = s.nx % 16;
  const auto tail = static_cast<__mmask16>((1u << rest) - 1u);
  std::uint64_t n = 0;
  for (std::int32_t y = 0; y < s.ny; ++y) {
    __m512i e0 = row[0], e1 = row[1], e2 = row[2];
    for (std::int32_t k = 0; k < full; ++k) {
      const __m512i o = _mm512_or_si512(_mm512_or_si512(e0, e1), e2);
      n += static_cast<unsigned>(
          std::popcount(static_cast<unsigned>(_mm512_cmpge_epi32_mask(o, zero))));
      e0 = _mm512_add_epi32(e0, step16[0]);
      e1 = _mm512_add_epi32(e1, step16[1]);
      e2 = _mm512_add_epi32(e2, step16[2]);
    }
    if (rest != 0) {
      const __m512i o = _mm512_or_si512(_mm512_or_si512(e0, e1), e2);
      n += static_cast<unsigned>(
          std::popcount(static_cast<unsigned>(_mm512_mask_cmpge_epi32_mask(tail, o, zero))));
    }
    for (int i = 0; i < 3; ++i)
      row[i] = _mm512_add_epi32(row[i], dy[i]);
  }
  return n;
}

} // namespace rastrules::bench
