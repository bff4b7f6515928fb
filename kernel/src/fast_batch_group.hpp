// SPDX-License-Identifier: MIT
// The batch counter's group set-up (FAST.BATCH.SMALL_I32, FAST.BATCH.SNAP_SIMD), shared by its
// SIMD units: eight triangles at a time are gathered, snapped, classified small or large,
// oriented, culled, bounded and set up in 32-bit AVX2 lanes; a unit's row loops then decide
// each small one's pixels (fast_batch_avx2.cpp in lanes of eight, fast_batch_avx512.cpp in
// lanes of sixteen), both taking rows of up to 8 pixels (and the AVX2 unit up to 16) in
// cover_one's halves of eight lanes, here. Included only by those units, each compiled for its
// instruction set: everything here is in an unnamed namespace, so that each unit has its own copy
// compiled with its own flags (fast_tiles.hpp says why). Implements: FAST.BATCH.SMALL_I32,
// FAST.BATCH.SNAP_SIMD, FAST.BATCH.EQUALS.PLAIN

#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "fast_batch_detail.hpp"

#if RASTRULES_FAST_X86 && defined(__AVX2__)

#include <immintrin.h>

namespace rastrules::raster::batch_detail {

namespace {

// One group's set-up lanes, stored for the per-triangle row loops.
struct Lanes {
  alignas(32) std::int32_t e[3][8]; // E + bias at the sample point of the first pixel
  alignas(32) std::int32_t a[3][8]; // 256 A: E's step per pixel along x
  alignas(32) std::int32_t b[3][8]; // 256 B: E's step per row
  alignas(32) std::int32_t x0[8];   // first pixel
  alignas(32) std::int32_t y0[8];
  alignas(32) std::int32_t cols[8]; // pixels per row, 1..64
  alignas(32) std::int32_t rows[8]; // rows, 1..64
};

inline int mask_of(__m256i m) {
  return _mm256_movemask_ps(_mm256_castsi256_ps(m));
}

// What the row loops do besides counting: nothing, per-pixel counts (hits), or runs.
enum Mode { kCount, kHits, kRuns };

// Appends triangle tri's runs, one a row with a covered pixel (the row's mask m has consecutive
// bits: a row meets a convex set in an interval).
struct RunWriter {
  Run* out = nullptr;
  std::size_t n = 0;
  std::uint32_t tri = 0;
  std::int32_t x0 = 0, y0 = 0;
  void row(std::int32_t j, std::int32_t first, std::int32_t count) {
    out[n++] = Run{tri, y0 + j, x0 + first, count};
  }
};

inline unsigned ctz(unsigned m) {
  return static_cast<unsigned>(__builtin_ctz(m));
}
inline unsigned popcount(unsigned m) {
  return static_cast<unsigned>(__builtin_popcount(m));
}

inline std::uint32_t hsum(__m256i v) {
  __m128i s = _mm_add_epi32(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1));
  s = _mm_add_epi32(s, _mm_shuffle_epi32(s, 0x4E));
  s = _mm_add_epi32(s, _mm_shuffle_epi32(s, 0xB1));
  return static_cast<std::uint32_t>(_mm_cvtsi128_si32(s));
}

// A row's per-pixel counts from one pixel on (FAST.BATCH.PIXEL_COUNTS): pixel k's count is
// low[k] + high[k]. Offsets move both.
struct HitRow {
  std::uint8_t* low = nullptr;
  std::uint32_t* high = nullptr;
  template <class I> HitRow operator+(I k) const {
    const auto d = static_cast<std::ptrdiff_t>(k);
    return HitRow{low + d, high + d};
  }
};

// Moves 255 from each byte of the lanes m sets (bit k: h.low[k]) that reached 255 to its 32-bit
// count.
// rule: FAST.BATCH.PIXEL_COUNTS
[[gnu::noinline, gnu::cold]] inline void spill_full(HitRow h, unsigned m) {
  for (; m != 0; m &= m - 1) {
    const int k = __builtin_ctz(m);
    if (h.low[k] == 255) {
      h.low[k] = 0;
      h.high[k] += 255;
    }
  }
}

// kSpread[m]: a byte of 1 for each bit of m (bit i: byte i, the lowest byte first).
inline constexpr auto kSpread = [] {
  std::array<std::uint64_t, 256> t{};
  for (unsigned m = 0; m < 256; ++m)
    for (unsigned i = 0; i < 8; ++i)
      if ((m >> i) & 1u)
        t[m] |= std::uint64_t{1} << (8 * i);
  return t;
}();

// Whether a byte of v is 255 (exact: the classic zero-byte test on ~v).
inline bool has_full_byte(std::uint64_t v) {
  const std::uint64_t t = ~v;
  return ((t - 0x0101010101010101u) & ~t & 0x8080808080808080u) != 0;
}

// Adds one to the count of pixel i for each lane i that `in` sets (all ones). The counts are
// bytes (FAST.BATCH.PIXEL_COUNTS): the eight lanes' ones spread into a 64-bit word
// (kSpread) and added to the eight bytes in one load and store where they lie inside the
// target's row (fits; a lane outside `in` adds zero, and the counts are not shared with
// another thread while the batch runs, fast_count_batch's contract), pixel by pixel otherwise.
// No byte carries into the next: every byte is below 255 before the add, and one that reaches
// 255 moves to its 32-bit count at once. (Scattered small triangles' 32-bit counts of a
// 1000 x 1000 target are 4 MB, a cache miss a row: 43 ms for 10^6 of them against 17 ms for
// the count alone; bytes of the same target fit the core's 1 MB second-level cache.)
inline void add_hits(HitRow h, __m256i in, bool fits) {
  auto m = static_cast<unsigned>(_mm256_movemask_ps(_mm256_castsi256_ps(in)));
  if (fits) {
    std::uint64_t v;
    std::memcpy(&v, h.low, sizeof v);
    v += kSpread[m];
    std::memcpy(h.low, &v, sizeof v);
    if (has_full_byte(v)) [[unlikely]]
      spill_full(h, 0xffu);
    return;
  }
  for (; m != 0; m &= m - 1) {
    const unsigned k = ctz(m);
    if (++h.low[k] == 255) [[unlikely]] {
      h.low[k] = 0;
      h.high[k] += 255;
    }
  }
}

// rule: FAST.BATCH.SMALL_I32, FIX.BIAS.FORM, FIX.STEP.INCREMENTAL
// The rows of triangle t of the group: lane i of row j holds E + bias at pixel (x0 + i, y0 + j)
// (|E| < 2^30, FAST.BATCH.SMALL_I32); the pixel is covered iff all three are >= 0, that is iff
// their OR is >= 0. Lanes at or past `cols` hold -2^30 in edge 0 and never step: never inside.
// Wide: a second half for pixels 8..15.
template <Mode kMode, bool kWide>
inline std::uint32_t cover_one(const Lanes& g, int t, HitRow hit, std::size_t stride,
                               RunWriter& rw) {
  const __m256i iota = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const __m256i cols = _mm256_set1_epi32(g.cols[t]);
  const __m256i poison = _mm256_set1_epi32(-(std::int32_t{1} << 30));
  const __m256i live_lo = _mm256_cmpgt_epi32(cols, iota);
  const __m256i live_hi = _mm256_cmpgt_epi32(cols, _mm256_add_epi32(iota, _mm256_set1_epi32(8)));
  __m256i lo[3], hi[3], slo[3], shi[3];
  for (int k = 0; k < 3; ++k) {
    const __m256i a = _mm256_set1_epi32(g.a[k][t]);
    const __m256i s = _mm256_set1_epi32(g.b[k][t]);
    lo[k] = _mm256_add_epi32(_mm256_set1_epi32(g.e[k][t]), _mm256_mullo_epi32(iota, a));
    hi[k] = _mm256_add_epi32(lo[k], _mm256_slli_epi32(a, 3));
    slo[k] = s;
    shi[k] = s;
  }
  lo[0] = _mm256_blendv_epi8(poison, lo[0], live_lo);
  slo[0] = _mm256_and_si256(slo[0], live_lo);
  hi[0] = _mm256_blendv_epi8(poison, hi[0], live_hi);
  shi[0] = _mm256_and_si256(shi[0], live_hi);
  const __m256i minus1 = _mm256_set1_epi32(-1);
  __m256i acc = _mm256_setzero_si256();
  const std::int32_t rows = g.rows[t];
  [[maybe_unused]] const bool lo_fits =
      static_cast<std::size_t>(g.x0[t]) + 8 <= stride; // stride: the target's width
  [[maybe_unused]] const bool hi_fits = static_cast<std::size_t>(g.x0[t]) + 16 <= stride;
  for (std::int32_t j = 0; j < rows; ++j) {
    const __m256i in_lo =
        _mm256_cmpgt_epi32(_mm256_or_si256(_mm256_or_si256(lo[0], lo[1]), lo[2]), minus1);
    acc = _mm256_sub_epi32(acc, in_lo);
    if constexpr (kMode == kHits) {
      add_hits(hit + static_cast<std::size_t>(j) * stride, in_lo, lo_fits);
    }
    unsigned m = 0;
    if constexpr (kMode == kRuns)
      m = static_cast<unsigned>(mask_of(in_lo));
    if constexpr (kWide) {
      const __m256i in_hi =
          _mm256_cmpgt_epi32(_mm256_or_si256(_mm256_or_si256(hi[0], hi[1]), hi[2]), minus1);
      acc = _mm256_sub_epi32(acc, in_hi);
      if constexpr (kMode == kHits) {
        // cols > 8: pixel x0 + 8 lies inside the row (x0 + cols - 1 < width).
        add_hits(hit + static_cast<std::size_t>(j) * stride + 8, in_hi, hi_fits);
      }
      if constexpr (kMode == kRuns)
        m |= static_cast<unsigned>(mask_of(in_hi)) << 8;
      for (int k = 0; k < 3; ++k)
        hi[k] = _mm256_add_epi32(hi[k], shi[k]);
    }
    if constexpr (kMode == kRuns) {
      if (m != 0)
        rw.row(j, __builtin_ctz(m), __builtin_popcount(m));
    }
    for (int k = 0; k < 3; ++k)
      lo[k] = _mm256_add_epi32(lo[k], slo[k]);
  }
  return hsum(acc);
}

// Decides the live triangles (bits of live) of group g, whose first triangle is base in p, with
// Rows::cover<kMode>(g, t, hit, stride, rw) (hit: the triangle's first pixel in the per-pixel
// counts, rows stride apart; rw placed at its first pixel); returns their covered pixels.
template <Mode kMode, class Rows>
inline std::uint64_t cover_live(const Lanes& g, unsigned live, std::size_t base, const Params& p,
                                RunWriter& rw) {
  std::uint64_t covered = 0;
  const auto stride = static_cast<std::size_t>(p.width);
  for (unsigned bits = live; bits != 0; bits &= bits - 1) {
    const int t = static_cast<int>(ctz(bits));
    HitRow hit; // the triangle's first pixel (kHits)
    if constexpr (kMode == kHits) {
      const std::size_t at =
          static_cast<std::size_t>(g.y0[t]) * stride + static_cast<std::size_t>(g.x0[t]);
      hit = HitRow{p.low + at, p.hits + at};
    }
    if constexpr (kMode == kRuns) {
      rw.tri = static_cast<std::uint32_t>(p.tri_base + base + static_cast<std::size_t>(t));
      rw.x0 = g.x0[t];
      rw.y0 = g.y0[t];
    }
    const std::uint32_t n = Rows::template cover<kMode>(g, t, hit, stride, rw);
    covered += n;
    if (p.per_triangle != nullptr)
      p.per_triangle[base + static_cast<std::size_t>(t)] = n;
  }
  return covered;
}

// Sets up the triangles of p eight at a time (snapped, tested small, oriented, culled, bounded,
// given their edges' values, steps and biases in 32-bit lanes) and has Rows::group<kMode> decide
// each group's live ones (cover_live); lists the others in large (small_batch_avx2's contract).
template <Mode kMode, class Rows>
std::size_t run_groups(const Params& p, Out& out, std::uint32_t* large) {
  std::size_t nlarge = 0;
  const __m256i iota = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const __m256i idx6 = _mm256_setr_epi32(0, 6, 12, 18, 24, 30, 36, 42);
  const __m256i zero = _mm256_setzero_si256();
  const __m256i ones = _mm256_set1_epi32(-1);
  const __m256 scale = _mm256_set1_ps(256.0f);
  // SNAP.VERTEX.RANGE: raw values in [-2^23, 2^23 - 1], both exact in float.
  const __m256 lowest = _mm256_set1_ps(-8388608.0f);
  const __m256 highest = _mm256_set1_ps(8388607.0f);
  const __m256i small_span = _mm256_set1_epi32(kSmallSpan);
  const __m256i keep_cw = p.skip_cw ? zero : ones;
  const __m256i keep_ccw = p.skip_ccw ? zero : ones;
  const __m256i last_x = _mm256_set1_epi32(p.width - 1);
  const __m256i last_y = _mm256_set1_epi32(p.height - 1);
  Lanes g;
  RunWriter rw{p.runs};
  for (std::size_t base = 0; base < p.n; base += 8) {
    const std::size_t left = p.n - base;
    const auto m = static_cast<std::int32_t>(left < 8 ? left : 8);
    const __m256i active = _mm256_cmpgt_epi32(_mm256_set1_epi32(m), iota);
    const float* src = p.xy + 6 * base;
    // rule: FAST.BATCH.SNAP_SIMD, SNAP.VERTEX.ROUND, SNAP.VERTEX.RANGE
    // v * 256 is exact in float (a power-of-two scale; an overflow to infinity or FLT_MAX is
    // out of range either way); rounding to the nearest integer, ties to even, is the
    // instruction's own mode (not MXCSR's); NaN fails both comparisons.
    __m256i c[6];
    int bad = 0;
    for (int k = 0; k < 6; ++k) {
      const __m256 f = _mm256_mask_i32gather_ps(_mm256_setzero_ps(), src + k, idx6,
                                                _mm256_castsi256_ps(active), 4);
      const __m256 r =
          _mm256_round_ps(_mm256_mul_ps(f, scale), _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
      const __m256 ok = _mm256_and_ps(_mm256_cmp_ps(r, lowest, _CMP_GE_OQ),
                                      _mm256_cmp_ps(r, highest, _CMP_LE_OQ));
      bad |= ~_mm256_movemask_ps(ok) & 0xFF;
      c[k] = _mm256_cvtps_epi32(r); // r is an integer in range: exact in any rounding mode
    }
    if (bad != 0) {
      out.bad = base + ctz(static_cast<unsigned>(bad));
      out.runs = rw.n;
      return nlarge;
    }
    __m256i x[3] = {c[0], c[2], c[4]}, y[3] = {c[1], c[3], c[5]};
    const __m256i minx = _mm256_min_epi32(_mm256_min_epi32(x[0], x[1]), x[2]);
    const __m256i maxx = _mm256_max_epi32(_mm256_max_epi32(x[0], x[1]), x[2]);
    const __m256i miny = _mm256_min_epi32(_mm256_min_epi32(y[0], y[1]), y[2]);
    const __m256i maxy = _mm256_max_epi32(_mm256_max_epi32(y[0], y[1]), y[2]);
    // rule: FAST.BATCH.SMALL_I32
    // Spans below 2^14 raw units (64 px): every product below is under 2^28 in magnitude.
    const __m256i small = _mm256_and_si256(
        active, _mm256_and_si256(_mm256_cmpgt_epi32(small_span, _mm256_sub_epi32(maxx, minx)),
                                 _mm256_cmpgt_epi32(small_span, _mm256_sub_epi32(maxy, miny))));
    const unsigned small_bits = static_cast<unsigned>(mask_of(small));
    out.small += popcount(small_bits);
    for (unsigned rest = static_cast<unsigned>(mask_of(active)) & ~small_bits; rest != 0;
         rest &= rest - 1)
      large[nlarge++] = static_cast<std::uint32_t>(base + ctz(rest));
    // rule: TRI.ORIENT.AREA, TRI.DEGENERATE.ZERO_AREA, TRI.CULL.MODE, TRI.ORIENT.NORMALISE
    const __m256i area = _mm256_sub_epi32(
        _mm256_mullo_epi32(_mm256_sub_epi32(x[1], x[0]), _mm256_sub_epi32(y[2], y[0])),
        _mm256_mullo_epi32(_mm256_sub_epi32(y[1], y[0]), _mm256_sub_epi32(x[2], x[0])));
    const __m256i cw = _mm256_cmpgt_epi32(area, zero);
    const __m256i ccw = _mm256_cmpgt_epi32(zero, area);
    const __m256i keep = _mm256_and_si256(
        small, _mm256_or_si256(_mm256_and_si256(cw, keep_cw), _mm256_and_si256(ccw, keep_ccw)));
    out.rasterized += popcount(static_cast<unsigned>(mask_of(keep)));
    {
      const __m256i x1 = _mm256_blendv_epi8(x[1], x[2], ccw),
                    x2 = _mm256_blendv_epi8(x[2], x[1], ccw);
      const __m256i y1 = _mm256_blendv_epi8(y[1], y[2], ccw),
                    y2 = _mm256_blendv_epi8(y[2], y[1], ccw);
      x[1] = x1;
      x[2] = x2;
      y[1] = y1;
      y[2] = y2;
    }
    // rule: RASTER.WALK.BBOX, RASTER.TARGET.CLIP
    // Pixel p's centre p * 256 + 128 lies in [min, max] iff ceil((min - 128) / 256) <= p <=
    // floor((max - 128) / 256); arithmetic shifts are floors.
    const __m256i px0 = _mm256_max_epi32(
        _mm256_srai_epi32(_mm256_add_epi32(minx, _mm256_set1_epi32(127)), 8), zero);
    const __m256i py0 = _mm256_max_epi32(
        _mm256_srai_epi32(_mm256_add_epi32(miny, _mm256_set1_epi32(127)), 8), zero);
    const __m256i px1 = _mm256_min_epi32(
        _mm256_srai_epi32(_mm256_sub_epi32(maxx, _mm256_set1_epi32(128)), 8), last_x);
    const __m256i py1 = _mm256_min_epi32(
        _mm256_srai_epi32(_mm256_sub_epi32(maxy, _mm256_set1_epi32(128)), 8), last_y);
    const __m256i ncols = _mm256_sub_epi32(_mm256_add_epi32(px1, _mm256_set1_epi32(1)), px0);
    const __m256i nrows = _mm256_sub_epi32(_mm256_add_epi32(py1, _mm256_set1_epi32(1)), py0);
    const __m256i live = _mm256_and_si256(
        keep, _mm256_and_si256(_mm256_cmpgt_epi32(ncols, zero), _mm256_cmpgt_epi32(nrows, zero)));
    const unsigned live_bits = static_cast<unsigned>(mask_of(live));
    if (live_bits == 0)
      continue;
    const __m256i sx = _mm256_add_epi32(_mm256_slli_epi32(px0, 8), _mm256_set1_epi32(128));
    const __m256i sy = _mm256_add_epi32(_mm256_slli_epi32(py0, 8), _mm256_set1_epi32(128));
    for (int k = 0; k < 3; ++k) {
      const __m256i ax = x[k], ay = y[k], bx = x[(k + 1) % 3], by = y[(k + 1) % 3];
      const __m256i A = _mm256_sub_epi32(ay, by), B = _mm256_sub_epi32(bx, ax);
      // rule: TRI.EDGE.FUNCTION, FIX.BIAS.FORM, TRI.FILL.CONVENTION
      const __m256i e = _mm256_add_epi32(_mm256_mullo_epi32(B, _mm256_sub_epi32(sy, ay)),
                                         _mm256_mullo_epi32(A, _mm256_sub_epi32(sx, ax)));
      const __m256i horizontal = _mm256_cmpeq_epi32(ay, by);
      const __m256i h_ok =
          p.top_inclusive ? _mm256_cmpgt_epi32(bx, ax) : _mm256_cmpgt_epi32(ax, bx);
      const __m256i v_ok =
          p.left_inclusive ? _mm256_cmpgt_epi32(ay, by) : _mm256_cmpgt_epi32(by, ay);
      const __m256i inclusive = _mm256_blendv_epi8(v_ok, h_ok, horizontal);
      // bias: 0 for an inclusive edge, -1 otherwise
      _mm256_store_si256(reinterpret_cast<__m256i*>(g.e[k]),
                         _mm256_add_epi32(e, _mm256_xor_si256(inclusive, ones)));
      _mm256_store_si256(reinterpret_cast<__m256i*>(g.a[k]), _mm256_slli_epi32(A, 8));
      _mm256_store_si256(reinterpret_cast<__m256i*>(g.b[k]), _mm256_slli_epi32(B, 8));
    }
    _mm256_store_si256(reinterpret_cast<__m256i*>(g.x0), px0);
    _mm256_store_si256(reinterpret_cast<__m256i*>(g.y0), py0);
    _mm256_store_si256(reinterpret_cast<__m256i*>(g.cols), ncols);
    _mm256_store_si256(reinterpret_cast<__m256i*>(g.rows), nrows);
    if constexpr (kMode == kHits) {
      // The per-pixel counts of scattered small triangles are a cache miss a row: asked for
      // all at once (the first rows of the eight triangles), they overlap instead of queueing.
      for (unsigned bits = live_bits; bits != 0; bits &= bits - 1) {
        const int t = static_cast<int>(ctz(bits));
        const std::uint8_t* h =
            p.low + static_cast<std::size_t>(g.y0[t]) * static_cast<std::size_t>(p.width) +
            static_cast<std::size_t>(g.x0[t]);
        const std::int32_t rows = std::min(g.rows[t], 4);
        for (std::int32_t j = 0; j < rows; ++j)
          _mm_prefetch(reinterpret_cast<const char*>(h + static_cast<std::size_t>(j) *
                                                             static_cast<std::size_t>(p.width)),
                       _MM_HINT_T0);
      }
    }
    out.covered += Rows::template group<kMode>(g, live_bits, base, p, rw);
  }
  out.runs = rw.n;
  return nlarge;
}

// A unit's entry (small_batch_avx2's contract) with Rows for its row loops: runs, per-pixel
// counts or counts alone, as p asks.
template <class Rows> std::size_t run_unit(const Params& p, Out& out, std::uint32_t* large) {
  if (p.runs != nullptr)
    return run_groups<kRuns, Rows>(p, out, large);
  return p.hits != nullptr ? run_groups<kHits, Rows>(p, out, large)
                           : run_groups<kCount, Rows>(p, out, large);
}

} // namespace

} // namespace rastrules::raster::batch_detail

#endif
