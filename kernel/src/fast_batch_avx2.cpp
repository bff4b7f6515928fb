// SPDX-License-Identifier: MIT
// The batch counter's AVX2 unit (FAST.BATCH.SMALL_I32, FAST.BATCH.SNAP_SIMD): the group set-up
// of fast_batch_group.hpp (eight triangles at a time), then each small one's rows (up to 16
// pixels: two __m256i halves; up to 64: chunks of eight) are tested and stepped. Compiled with
// -mavx2 on x86-64 (kernel/CMakeLists.txt); elsewhere empty. Everything here is in an unnamed
// namespace or calls only intrinsics (fast_tiles.hpp says why). Implements:
// FAST.BATCH.SMALL_I32, FAST.BATCH.SNAP_SIMD, FAST.BATCH.EQUALS.PLAIN

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "fast_batch_group.hpp"

#if RASTRULES_FAST_X86 && defined(__AVX2__)

#include <immintrin.h>

namespace rastrules::raster::batch_detail {

namespace {

// rule: FAST.BATCH.SMALL_I32, FIX.BIAS.FORM, FIX.STEP.INCREMENTAL
// More than 16 pixels a row: each row in chunks of eight lanes, stepped by 8 * 256 A; the last
// chunk's lanes at or past `cols` masked off (|E| < 2^30 there, FAST.BATCH.SMALL_I32).
template <Mode kMode>
inline std::uint32_t cover_rows(const Lanes& g, int t, HitRow hit, std::size_t stride,
                                RunWriter& rw) {
  const __m256i iota = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const std::int32_t cols = g.cols[t], full = cols / 8, rest = cols % 8;
  const __m256i tail = _mm256_cmpgt_epi32(_mm256_set1_epi32(rest), iota);
  __m256i row[3], step8[3], down[3];
  for (int k = 0; k < 3; ++k) {
    const __m256i a = _mm256_set1_epi32(g.a[k][t]);
    row[k] = _mm256_add_epi32(_mm256_set1_epi32(g.e[k][t]), _mm256_mullo_epi32(iota, a));
    step8[k] = _mm256_slli_epi32(a, 3);
    down[k] = _mm256_set1_epi32(g.b[k][t]);
  }
  const __m256i minus1 = _mm256_set1_epi32(-1);
  __m256i acc = _mm256_setzero_si256();
  const std::int32_t rows = g.rows[t];
  // The last chunk's eight counters lie inside the target's row (stride: its width).
  [[maybe_unused]] const bool tail_fits =
      static_cast<std::size_t>(g.x0[t]) + 8 * static_cast<std::size_t>(full) + 8 <= stride;
  for (std::int32_t j = 0; j < rows; ++j) {
    __m256i l0 = row[0], l1 = row[1], l2 = row[2];
    // Only a walk with hits passes hit != nullptr: no row pointer is formed otherwise (an
    // offset on a null pointer is undefined behaviour, which clang's UBSan reports).
    HitRow h = kMode == kHits ? hit + static_cast<std::size_t>(j) * stride : HitRow{};
    std::int32_t first = -1, count = 0; // the row's run (kRuns)
    const auto add_run = [&](std::int32_t at, __m256i in) {
      if constexpr (kMode == kRuns) {
        const auto m = static_cast<unsigned>(mask_of(in));
        if (m != 0) {
          if (first < 0)
            first = at + __builtin_ctz(m);
          count += __builtin_popcount(m);
        }
      }
    };
    for (std::int32_t c = 0; c < full; ++c) {
      const __m256i in = _mm256_cmpgt_epi32(_mm256_or_si256(_mm256_or_si256(l0, l1), l2), minus1);
      acc = _mm256_sub_epi32(acc, in);
      if constexpr (kMode == kHits) {
        add_hits(h + 8 * c, in, true);
      }
      add_run(8 * c, in);
      l0 = _mm256_add_epi32(l0, step8[0]);
      l1 = _mm256_add_epi32(l1, step8[1]);
      l2 = _mm256_add_epi32(l2, step8[2]);
    }
    if (rest != 0) {
      const __m256i in = _mm256_and_si256(
          tail, _mm256_cmpgt_epi32(_mm256_or_si256(_mm256_or_si256(l0, l1), l2), minus1));
      acc = _mm256_sub_epi32(acc, in);
      if constexpr (kMode == kHits) {
        // pixel x0 + 8 full lies inside the row: x0 + cols - 1 < width
        add_hits(h + 8 * full, in, tail_fits);
      }
      add_run(8 * full, in);
    }
    if constexpr (kMode == kRuns) {
      if (count != 0)
        rw.row(j, first, count);
    }
    for (int k = 0; k < 3; ++k)
      row[k] = _mm256_add_epi32(row[k], down[k]);
  }
  return hsum(acc);
}

// The rows of a triangle in lanes of eight.
struct Rows8 {
  template <Mode kMode>
  static std::uint32_t cover(const Lanes& g, int t, HitRow hit, std::size_t stride, RunWriter& rw) {
    if (g.cols[t] > 16)
      return cover_rows<kMode>(g, t, hit, stride, rw);
    return g.cols[t] > 8 ? cover_one<kMode, true>(g, t, hit, stride, rw)
                         : cover_one<kMode, false>(g, t, hit, stride, rw);
  }
  template <Mode kMode>
  static std::uint64_t group(const Lanes& g, unsigned live, std::size_t base, const Params& p,
                             RunWriter& rw) {
    return cover_live<kMode, Rows8>(g, live, base, p, rw);
  }
};

} // namespace

std::size_t small_batch_avx2(const Params& p, Out& out, std::uint32_t* large) {
  return run_unit<Rows8>(p, out, large);
}

} // namespace rastrules::raster::batch_detail

#endif
