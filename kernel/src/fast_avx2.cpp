// SPDX-License-Identifier: MIT
// The fast traversal's AVX2 lanes (FAST.ISA.DISPATCH): a tile row of 16 int32 lanes as two
// __m256i halves, L >= C tested as the sign of L - C (it fits: see tile()). Compiled with -mavx2
// on x86-64 (kernel/CMakeLists.txt); elsewhere this unit is empty and isa_supported(kAvx2) is
// false.
// Implements: FAST.LANE.I32, FAST.ISA.DISPATCH

#include <cstddef>
#include <cstdint>

#include "fast_tiles.hpp"

#if RASTRULES_FAST_X86 && defined(__AVX2__)

#include <immintrin.h>

namespace rastrules::raster::fast_detail {

namespace {

struct Avx2Kernel {
  __m256i lo[3], hi[3], step[3]; // lanes i A for i = 0..7 and 8..15; B
  std::int32_t step_b[3];        // B

  Avx2Kernel(const std::int32_t (&a)[3], const std::int32_t (&b)[3]) {
    const __m256i iota = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    for (int k = 0; k < 3; ++k) {
      lo[k] = _mm256_mullo_epi32(iota, _mm256_set1_epi32(a[k]));
      hi[k] = _mm256_add_epi32(lo[k], _mm256_set1_epi32(8 * a[k]));
      step[k] = _mm256_set1_epi32(b[k]);
      step_b[k] = b[k];
    }
  }

  // rule: FAST.LANE.I32
  template <class Sink>
  void tile(const std::int32_t c[3], std::int32_t j0, std::int32_t j1, std::uint32_t cols,
            Sink& sink, std::int32_t tx, std::int32_t ty) const {
    // Lanes hold D = L - C with L = i A + j B (formula::lane_offset) from row j0, stepped by B
    // per row: L >= C iff D >= 0, the sign bit of D clear, so a lane is inside all three edges
    // iff the sign bit of D0 | D1 | D2 is clear. |L| < 2^29 (15 |A| + 16 |B|, FAST.LANE.I32)
    // and |C| <= 2^30 keep |D| < 2^31: no lane wraps. Eight of the sixteen registers hold the
    // lanes and steps (two halves of two edges would not fit as L and C separately).
    // Named registers, not arrays: the row loop then keeps all lanes in registers.
    const __m256i off0 = _mm256_set1_epi32(j0 * step_b[0] - c[0]);
    const __m256i off1 = _mm256_set1_epi32(j0 * step_b[1] - c[1]);
    const __m256i off2 = _mm256_set1_epi32(j0 * step_b[2] - c[2]);
    __m256i d0l = _mm256_add_epi32(lo[0], off0), d0h = _mm256_add_epi32(hi[0], off0);
    __m256i d1l = _mm256_add_epi32(lo[1], off1), d1h = _mm256_add_epi32(hi[1], off1);
    __m256i d2l = _mm256_add_epi32(lo[2], off2), d2h = _mm256_add_epi32(hi[2], off2);
    const __m256i s0 = step[0], s1 = step[1], s2 = step[2];
    for (std::int32_t j = j0; j <= j1; ++j) {
      const __m256i o_lo = _mm256_or_si256(_mm256_or_si256(d0l, d1l), d2l);
      const __m256i o_hi = _mm256_or_si256(_mm256_or_si256(d0h, d1h), d2h);
      const auto m_lo = static_cast<std::uint32_t>(_mm256_movemask_ps(_mm256_castsi256_ps(o_lo)));
      const auto m_hi = static_cast<std::uint32_t>(_mm256_movemask_ps(_mm256_castsi256_ps(o_hi)));
      sink.row(tx, ty + j, ~(m_lo | (m_hi << 8)) & cols);
      d0l = _mm256_add_epi32(d0l, s0);
      d0h = _mm256_add_epi32(d0h, s0);
      d1l = _mm256_add_epi32(d1l, s1);
      d1h = _mm256_add_epi32(d1h, s1);
      d2l = _mm256_add_epi32(d2l, s2);
      d2h = _mm256_add_epi32(d2h, s2);
    }
  }
};

} // namespace

const Lanes kAvx2Lanes = lanes_of<Avx2Kernel>();

} // namespace rastrules::raster::fast_detail

#endif
