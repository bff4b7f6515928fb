// SPDX-License-Identifier: MIT
// The batch counter's AVX-512 unit (FAST.BATCH.SMALL_I32, FAST.BATCH.LANES16): the group set-up
// of fast_batch_group.hpp (eight triangles at a time, the AVX2 unit's code compiled for AVX2),
// then each group's small triangles in one call compiled for AVX-512: rows of up to 8 pixels in
// cover_one's half of eight lanes (as the AVX2 unit), longer ones in chunks of sixteen 32-bit
// lanes (one __m512i an edge), the last chunk's lanes at or past the row's end masked off with a
// __mmask16. Where the AVX2 unit needs six chunks for a row of 45 pixels, this needs three.
// Compiled with -mavx2 on x86-64 (kernel/CMakeLists.txt), the row loops for AVX-512F/BW/VL by
// a function attribute; elsewhere empty, and the dispatcher calls it only where
// isa_supported(kAvx512). Everything here is in an unnamed namespace or calls only intrinsics
// (fast_tiles.hpp says why). Implements: FAST.BATCH.LANES16, FAST.BATCH.SMALL_I32,
// FAST.BATCH.EQUALS.PLAIN

#include <cstddef>
#include <cstdint>

#include "fast_batch_group.hpp"

#if RASTRULES_FAST_X86 && defined(__AVX2__)

#include <immintrin.h>

// The row loops' instruction set. The set-up is compiled for AVX2, as in the AVX2 unit, and calls
// the row loops once a group (Rows16::group, not inlined): with the whole unit compiled for
// AVX-512 and a call a triangle, the tie-heavy mesh of slivers (rows of a few pixels, where the
// set-up is most of the time) ran 13-22 % slower than with the AVX2 unit; this way it runs as
// fast (bench/ BM_Ladder/reference-fast, medians of three, four alternations).
#define RASTRULES_ROWS16 __attribute__((target("avx512f,avx512bw,avx512vl")))

namespace rastrules::raster::batch_detail {

namespace {

// Adds one to the count of pixel i for each lane i that m sets: the sixteen bytes
// (FAST.BATCH.PIXEL_COUNTS) in one masked load, add and store. Masked loads and stores of
// AVX-512 never touch the memory of lanes the mask leaves out, so a chunk that ends past the
// row's last pixel (and the target's last column) reads and writes only the row's pixels. A
// byte that reaches 255 moves to its 32-bit count.
RASTRULES_ROWS16 inline void add_hits16(HitRow h, __mmask16 m) {
  const __m128i v = _mm_add_epi8(_mm_maskz_loadu_epi8(m, h.low), _mm_set1_epi8(1));
  _mm_mask_storeu_epi8(h.low, m, v);
  if (const __mmask16 full = _mm_mask_cmpeq_epi8_mask(m, v, _mm_set1_epi8(-1)); full != 0)
      [[unlikely]]
    spill_full(h, full);
}

// What a row chunk c with covered lanes `in` does besides counting: the per-pixel counts (kHits,
// h the row's first pixel), or the row's run so far (kRuns: its first pixel and length).
template <Mode kMode>
RASTRULES_ROWS16 inline void chunk_extra(__mmask16 in, std::int32_t c, HitRow h,
                                         std::int32_t& first, std::int32_t& count) {
  if constexpr (kMode == kHits) {
    if (in != 0)
      add_hits16(h + 16 * c, in);
  }
  if constexpr (kMode == kRuns) {
    const auto m = static_cast<unsigned>(in);
    if (m != 0) {
      if (first < 0)
        first = 16 * c + __builtin_ctz(m);
      count += __builtin_popcount(m);
    }
  }
  (void)in, (void)c, (void)h, (void)first, (void)count;
}

// rule: FAST.BATCH.LANES16, FAST.BATCH.SMALL_I32, FIX.BIAS.FORM, FIX.STEP.INCREMENTAL
// The rows of triangle t of the group in chunks of sixteen lanes: lane i of chunk c of row j
// holds E + bias at pixel (x0 + 16 c + i, y0 + j), stepped by 16 x 256 A along the row and by
// 256 B down (|E| < 2^30 up to 15 lanes past the row's last pixel, FAST.BATCH.SMALL_I32); the
// pixel is covered iff the OR of the three is >= 0. The last chunk's lanes at or past `cols`
// are masked off. Covered lanes are counted in a vector (one masked add a chunk, summed once at
// the end), not by a population count a chunk (a scalar count a row was 23 % slower on small
// triangles).
template <Mode kMode>
RASTRULES_ROWS16 inline std::uint32_t cover16(const Lanes& g, int t, HitRow hit, std::size_t stride,
                                              RunWriter& rw) {
  const __m512i iota = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  const std::int32_t cols = g.cols[t], full = (cols - 1) / 16, rest = cols - 16 * full;
  const auto tail = static_cast<__mmask16>((1u << rest) - 1u); // rest in 1..16
  __m512i row[3], step16[3], down[3];
  for (int k = 0; k < 3; ++k) {
    const __m512i a = _mm512_set1_epi32(g.a[k][t]);
    row[k] = _mm512_add_epi32(_mm512_set1_epi32(g.e[k][t]), _mm512_mullo_epi32(iota, a));
    // 16 x 256 A below 2^26 (FAST.BATCH.LANES16): the product fits int32_t. (Not
    // _mm512_slli_epi32: GCC 12 warns that its undefined source may be used uninitialized.)
    step16[k] = _mm512_set1_epi32(16 * g.a[k][t]);
    down[k] = _mm512_set1_epi32(g.b[k][t]);
  }
  const __m512i zero = _mm512_setzero_si512();
  const __m512i one = _mm512_set1_epi32(1);
  __m512i acc = zero;
  const std::int32_t rows = g.rows[t];
  for (std::int32_t j = 0; j < rows; ++j) {
    __m512i l0 = row[0], l1 = row[1], l2 = row[2];
    // Only a walk with hits passes hit != nullptr: no row pointer is formed otherwise.
    HitRow h = kMode == kHits ? hit + static_cast<std::size_t>(j) * stride : HitRow{};
    std::int32_t first = -1, count = 0; // the row's run (kRuns)
    for (std::int32_t c = 0; c < full; ++c) {
      const __mmask16 in =
          _mm512_cmpge_epi32_mask(_mm512_or_si512(_mm512_or_si512(l0, l1), l2), zero);
      acc = _mm512_mask_add_epi32(acc, in, acc, one);
      chunk_extra<kMode>(in, c, h, first, count);
      l0 = _mm512_add_epi32(l0, step16[0]);
      l1 = _mm512_add_epi32(l1, step16[1]);
      l2 = _mm512_add_epi32(l2, step16[2]);
    }
    const __mmask16 in =
        _mm512_mask_cmpge_epi32_mask(tail, _mm512_or_si512(_mm512_or_si512(l0, l1), l2), zero);
    acc = _mm512_mask_add_epi32(acc, in, acc, one);
    chunk_extra<kMode>(in, full, h, first, count);
    if constexpr (kMode == kRuns) {
      if (count != 0)
        rw.row(j, first, count);
    }
    for (int k = 0; k < 3; ++k)
      row[k] = _mm512_add_epi32(row[k], down[k]);
  }
  // Summed through memory, once a triangle (GCC 12 warns on _mm512_reduce_add_epi32's
  // extraction that its undefined source may be used uninitialized).
  alignas(64) std::uint32_t lanes[16];
  _mm512_store_si512(lanes, acc);
  std::uint32_t covered = 0;
  for (const std::uint32_t v : lanes)
    covered += v;
  return covered;
}

// The rows of a triangle in lanes of sixteen.
struct Rows16 {
  template <Mode kMode>
  RASTRULES_ROWS16 static std::uint32_t cover(const Lanes& g, int t, HitRow hit, std::size_t stride,
                                              RunWriter& rw) {
    // Rows of up to 8 pixels in one half of eight lanes (fast_batch_group.hpp; proved with the
    // AVX2 unit, proofs/fast/batch_small_i32.cpp): sixteen lanes would do twice the work.
    if (g.cols[t] <= 8)
      return cover_one<kMode, false>(g, t, hit, stride, rw);
    return cover16<kMode>(g, t, hit, stride, rw);
  }
  // A group's live triangles in one call that is not inlined into the set-up (which is compiled
  // for AVX2 and keeps its constants in registers).
  template <Mode kMode>
  RASTRULES_ROWS16 __attribute__((noinline)) static std::uint64_t
  group(const Lanes& g, unsigned live, std::size_t base, const Params& p, RunWriter& rw) {
    return cover_live<kMode, Rows16>(g, live, base, p, rw);
  }
};

} // namespace

std::size_t small_batch_avx512(const Params& p, Out& out, std::uint32_t* large) {
  return run_unit<Rows16>(p, out, large);
}

} // namespace rastrules::raster::batch_detail

#endif
