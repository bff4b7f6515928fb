// SPDX-License-Identifier: MIT
// The fast traversal's AVX-512 lanes (FAST.ISA.DISPATCH): a tile row is one __m512i of 16
// int32 lanes, tested with _mm512_cmpge_epi32_mask chained through the three edges. Compiled
// with -mavx512f -mavx512bw -mavx512vl on x86-64 (kernel/CMakeLists.txt); elsewhere this unit
// is empty and isa_supported(kAvx512) is false.
// Implements: FAST.LANE.I32, FAST.ISA.DISPATCH

#include <cstddef>
#include <cstdint>

#include "fast_tiles.hpp"

#if RASTRULES_FAST_X86 && defined(__AVX512F__) && defined(__AVX512BW__) && defined(__AVX512VL__)

#include <immintrin.h>

namespace rastrules::raster::fast_detail {

namespace {

struct Avx512Kernel {
  __m512i base[3], step[3]; // lanes i A for i = 0..15; B

  Avx512Kernel(const std::int32_t (&a)[3], const std::int32_t (&b)[3]) {
    const __m512i iota = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
    for (int k = 0; k < 3; ++k) {
      base[k] = _mm512_mullo_epi32(iota, _mm512_set1_epi32(a[k]));
      step[k] = _mm512_set1_epi32(b[k]);
    }
  }

  // rule: FAST.LANE.I32
  template <class Sink>
  void tile(const std::int32_t c[3], std::int32_t j0, std::int32_t j1, std::uint32_t cols,
            Sink& sink, std::int32_t tx, std::int32_t ty) const {
    // Lanes L = i A + j B (formula::lane_offset) from row j0, stepped by B per row; |L| < 2^30
    // throughout (FAST.LANE.I32).
    // Named registers, not arrays: the row loop then keeps all lanes in registers.
    __m512i l0 = _mm512_add_epi32(base[0], _mm512_mullo_epi32(_mm512_set1_epi32(j0), step[0]));
    __m512i l1 = _mm512_add_epi32(base[1], _mm512_mullo_epi32(_mm512_set1_epi32(j0), step[1]));
    __m512i l2 = _mm512_add_epi32(base[2], _mm512_mullo_epi32(_mm512_set1_epi32(j0), step[2]));
    const __m512i c0 = _mm512_set1_epi32(c[0]), c1 = _mm512_set1_epi32(c[1]),
                  c2 = _mm512_set1_epi32(c[2]);
    const __m512i s0 = step[0], s1 = step[1], s2 = step[2];
    const auto colmask = static_cast<__mmask16>(cols);
    for (std::int32_t j = j0; j <= j1; ++j) {
      __mmask16 m = _mm512_mask_cmpge_epi32_mask(colmask, l0, c0);
      m = _mm512_mask_cmpge_epi32_mask(m, l1, c1);
      m = _mm512_mask_cmpge_epi32_mask(m, l2, c2);
      sink.row(tx, ty + j, static_cast<std::uint32_t>(m));
      l0 = _mm512_add_epi32(l0, s0);
      l1 = _mm512_add_epi32(l1, s1);
      l2 = _mm512_add_epi32(l2, s2);
    }
  }
};

} // namespace

const Lanes kAvx512Lanes = lanes_of<Avx512Kernel>();

} // namespace rastrules::raster::fast_detail

#endif
