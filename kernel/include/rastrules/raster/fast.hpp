// SPDX-License-Identifier: MIT
// The fast exact traversal (layer 3: mechanism): tiles of kFastTileSize x kFastTileSize pixels
// from the first pixel of the triangle's bounds, whole-tile rejection and acceptance, 32-bit SIMD
// lanes (FAST.LANE.I32), incremental stepping, AVX-512 / AVX2 / scalar chosen at run time. Its only
// correctness criterion: exactly the coverage of the plain walks (walk.hpp, walk_msaa.hpp), in the
// same order (FAST.EQUALS.PLAIN). Implements: FAST.TILE.CLASSIFY, FAST.LANE.I32, FAST.EQUALS.PLAIN

#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "rastrules/isa.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/raster/walk.hpp"
#include "rastrules/raster/walk_msaa.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules::raster {

inline constexpr std::int32_t kFastTileSize = 16;
// Blocks of kFastBlockSize x kFastBlockSize pixels (4 x 4 tiles) are classified first, in 64-bit
// lanes of the same form (FAST.TILE.CLASSIFY): a rejected or accepted block decides its 16
// tiles without looking at them.
inline constexpr std::int32_t kFastBlockSize = 4 * kFastTileSize;

// Writes the coverage of the sample points at raw offset (dx, dy) from each pixel centre of
// rect r by the rasterized triangle t: bit (x - r.x0) % 64 of word (y - r.y0) * words_per_row +
// (x - r.x0) / 64 is set iff t covers the sample point of pixel (x, y) (TRI.COVER.SAMPLE).
// Every word of the r.y1 - r.y0 + 1 rows is written (bits past r.x1 are zero).
// Preconditions: t.status == kRasterized; r not empty, inside [0, kMaxTargetSide)^2;
// words_per_row >= (r.x1 - r.x0 + 64) / 64; isa_supported(isa); |dx|, |dy| <= 128.
// rule: FAST.TILE.CLASSIFY, FAST.LANE.I32
void fast_cover_rect(const TriangleSetup& t, PixelRect r, std::int32_t dx, std::int32_t dy, Isa isa,
                     std::uint64_t* out, std::size_t words_per_row);

// Returns the number of pixels of the target whose centre t covers (what walk_triangle
// emits, counted). The benchmarks' decision rate of the fast path.
// rule: FAST.EQUALS.PLAIN
[[nodiscard]] std::uint64_t fast_count_covered(const TriangleSetup& t, std::int32_t width,
                                               std::int32_t height, Isa isa);

// How FAST.TILE.CLASSIFY decided the tiles a rectangle overlaps: rejected, accepted, or decided
// per sample point. Each tile is classified whole, also where only part of it lies in the
// rectangle.
struct FastTileCounts {
  std::uint64_t rejected = 0; // tiles (also those of rejected blocks)
  std::uint64_t accepted = 0; // tiles (also those of accepted blocks)
  std::uint64_t partial = 0;  // tiles decided per sample point
  std::uint64_t blocks_rejected = 0;
  std::uint64_t blocks_accepted = 0;
  std::uint64_t blocks_partial = 0; // blocks whose tiles were classified one by one
};

// Returns the classification of the tiles of the triangle's pixel bounds (pixel_bounds) at the
// pixel centres, as fast_cover_rect and fast_count_covered decide them. Diagnostics and tests.
// rule: FAST.TILE.CLASSIFY
[[nodiscard]] FastTileCounts fast_tile_counts(const TriangleSetup& t, std::int32_t width,
                                              std::int32_t height);

namespace fast_detail {
// Words of the caller's stack a fast walk uses before it allocates (4 KiB).
inline constexpr std::size_t kStackWords = 512;

// Returns the rows of a strip: as many whole tile rows as `planes` buffers of words_per_row
// words a row fit in kStackWords, at least one tile row (then the buffer is allocated).
constexpr std::int32_t strip_rows(std::size_t words_per_row, std::size_t planes) {
  const std::size_t tile_rows =
      kStackWords / (words_per_row * planes * static_cast<std::size_t>(kFastTileSize));
  return static_cast<std::int32_t>(tile_rows == 0 ? 1 : tile_rows) * kFastTileSize;
}
} // namespace fast_detail

// Returns r narrowed to the columns where t can cover a sample point in the rows of r: the
// pixels whose sample points, at most `reach` raw units from the pixel centre on each axis,
// can lie in the closed triangle within those rows (empty when it meets none of them). A
// covered sample point lies in the closed triangle, so the coverage of the narrowed rectangle
// is that of r: a long thin triangle costs per row, not per pixel of its bounding box.
// Preconditions: t.status == kRasterized; reach >= 0.
// rule: FAST.EQUALS.PLAIN
[[nodiscard]] constexpr PixelRect narrow_to_rows(const TriangleSetup& t, PixelRect r,
                                                 std::int64_t reach) {
  const std::int64_t ya = std::int64_t{r.y0} * kSubpixelOne + kSubpixelHalf - reach;
  const std::int64_t yb = std::int64_t{r.y1} * kSubpixelOne + kSubpixelHalf + reach;
  std::int64_t lo = 0, hi = -1;
  bool any = false;
  const auto take = [&](std::int64_t x0, std::int64_t x1) {
    lo = any ? std::min(lo, x0) : x0;
    hi = any ? std::max(hi, x1) : x1;
    any = true;
  };
  // The triangle's part in the band ya <= y <= yb is convex: its vertices are the triangle's
  // vertices in the band and the edges' crossings of y = ya and y = yb (x rounded outwards).
  for (std::size_t i = 0; i < 3; ++i) {
    const std::int64_t px = t.snapped[i].x.raw(), py = t.snapped[i].y.raw();
    const std::int64_t qx = t.snapped[(i + 1) % 3].x.raw(), qy = t.snapped[(i + 1) % 3].y.raw();
    if (py >= ya && py <= yb)
      take(px, px);
    if (py == qy)
      continue;
    for (const std::int64_t y : {ya, yb}) {
      if (y < std::min(py, qy) || y > std::max(py, qy))
        continue;
      // x = px + (y - py) (qx - px) / (qy - py), |numerator| < 2^50 (SNAP.VERTEX.RANGE).
      std::int64_t num = (y - py) * (qx - px), den = qy - py;
      if (den < 0) {
        num = -num;
        den = -den;
      }
      take(px + floor_div(num, den), px + ceil_div(num, den));
    }
  }
  if (!any)
    return PixelRect{};
  // Pixel x has a sample point within reach of [lo, hi] when 256 x + 128 + reach >= lo and
  // 256 x + 128 - reach <= hi.
  const std::int64_t x0 = ceil_div(lo - kSubpixelHalf - reach, kSubpixelOne);
  const std::int64_t x1 = floor_div(hi - kSubpixelHalf + reach, kSubpixelOne);
  PixelRect n = r;
  n.x0 = static_cast<std::int32_t>(std::max<std::int64_t>(r.x0, x0));
  n.x1 = static_cast<std::int32_t>(std::min<std::int64_t>(r.x1, x1));
  return n.x1 < n.x0 ? PixelRect{} : n;
}

namespace fast_detail {
// The covered bits of the rows y_first to y_last of walk_triangle_rows's bounds: row(y, x0, bits,
// words) for each row, bit i of bits[i / 64] set when pixel x0 + i is covered, rows in order.
// Strips of whole tile rows from the first row (all of the pixel bounds when they fit 4 KiB of
// bits), each narrowed to the columns the triangle reaches in its rows (at most wpr words a
// row), are decided by fast_cover_rect.
template <class Row>
void for_each_covered_row(const TriangleSetup& t, std::int32_t width, std::int32_t height,
                          std::int32_t y_first, std::int32_t y_last, Isa isa, Row&& row) {
  const PixelRect r = rows_of(walk_bounds(t, width, height), y_first, y_last);
  if (r.empty())
    return;
  const auto wpr = static_cast<std::size_t>(r.x1 - r.x0 + 64) / 64;
  const std::int32_t rows = strip_rows(wpr, 1);
  const std::size_t words = wpr * static_cast<std::size_t>(rows);
  std::uint64_t stack[kStackWords];
  std::vector<std::uint64_t> heap;
  std::uint64_t* buf = stack;
  if (words > kStackWords) {
    heap.resize(words);
    buf = heap.data();
  }
  for (std::int32_t sy = r.y0; sy <= r.y1; sy += rows) {
    const PixelRect strip =
        narrow_to_rows(t, PixelRect{r.x0, sy, r.x1, std::min(sy + rows - 1, r.y1)}, 0);
    if (strip.empty())
      continue;
    const auto spr = static_cast<std::size_t>(strip.x1 - strip.x0 + 64) / 64;
    fast_cover_rect(t, strip, 0, 0, isa, buf, spr);
    for (std::int32_t y = strip.y0; y <= strip.y1; ++y)
      row(y, strip.x0, buf + static_cast<std::size_t>(y - strip.y0) * spr, spr);
  }
}
} // namespace fast_detail

// Calls emit(x, y) for exactly the pixels walk_triangle_rows(t, width, height, y_first, y_last,
// emit) emits, in the same order: the set bits of fast_detail::for_each_covered_row, row by row.
// Preconditions: width, height in [1, kMaxTargetSide]; isa_supported(isa).
// rule: FAST.EQUALS.PLAIN
template <class Emit>
void walk_triangle_fast_rows(const TriangleSetup& t, std::int32_t width, std::int32_t height,
                             std::int32_t y_first, std::int32_t y_last, Isa isa, Emit&& emit) {
  fast_detail::for_each_covered_row(
      t, width, height, y_first, y_last, isa,
      [&](std::int32_t y, std::int32_t x0, const std::uint64_t* row, std::size_t words) {
        for (std::size_t w = 0; w < words; ++w) {
          const std::int32_t x_base = x0 + static_cast<std::int32_t>(w * 64);
          for (std::uint64_t bits = row[w]; bits != 0; bits &= bits - 1)
            emit(x_base + std::countr_zero(bits), y);
        }
      });
}

// Calls run(y, x, n) for each maximal run of consecutive pixels x, x + 1, ..., x + n - 1 of a
// row among those walk_triangle_fast_rows emits, rows and runs in its order: its pixels as
// runs, taken from the row bits a word at a time (a large triangle's rows cost per run, not
// per pixel: fast_runs_batch, the binary list of SCENE.OUTPUT.BINARY).
// rule: FAST.EQUALS.PLAIN
template <class Run>
void walk_triangle_fast_row_runs(const TriangleSetup& t, std::int32_t width, std::int32_t height,
                                 std::int32_t y_first, std::int32_t y_last, Isa isa, Run&& run) {
  fast_detail::for_each_covered_row(
      t, width, height, y_first, y_last, isa,
      [&](std::int32_t y, std::int32_t x0, const std::uint64_t* row, std::size_t words) {
        std::int32_t rx = 0, rn = 0; // the open run of the row
        for (std::size_t w = 0; w < words; ++w) {
          std::uint64_t bits = row[w];
          std::int32_t at = x0 + static_cast<std::int32_t>(w * 64);
          while (bits != 0) {
            const int zeros = std::countr_zero(bits);
            bits >>= zeros; // zeros < 64: bits is not 0
            at += zeros;
            const int ones = std::countr_one(bits);
            if (rn > 0 && rx + rn == at) {
              rn += ones;
            } else {
              if (rn > 0)
                run(y, rx, rn);
              rx = at;
              rn = ones;
            }
            at += ones;
            bits = ones == 64 ? 0 : bits >> ones;
          }
        }
        if (rn > 0)
          run(y, rx, rn);
      });
}

// Calls emit(x, y) for exactly the pixels walk_triangle(t, width, height, emit) emits, in the
// same order.
// rule: FAST.EQUALS.PLAIN
template <class Emit>
void walk_triangle_fast(const TriangleSetup& t, std::int32_t width, std::int32_t height, Isa isa,
                        Emit&& emit) {
  walk_triangle_fast_rows(t, width, height, 0, height - 1, isa, emit);
}

// Calls emit(x, y, mask) for exactly what walk_triangle_samples(t, pattern, width, height, emit)
// emits, in the same order.
// Preconditions: as walk_triangle_samples; width, height in [1, kMaxTargetSide];
// isa_supported(isa).
// rule: FAST.EQUALS.PLAIN
template <class Emit>
void walk_triangle_samples_fast(const TriangleSetup& t, const SamplePattern& pattern,
                                std::int32_t width, std::int32_t height, Isa isa, Emit&& emit) {
  const PixelRect r = sample_walk_bounds(t, pattern, width, height);
  if (r.empty())
    return;
  const std::size_t n = pattern.count();
  const auto wpr = static_cast<std::size_t>(r.x1 - r.x0 + 64) / 64;
  const std::int32_t rows = fast_detail::strip_rows(wpr, n);
  const std::size_t plane = wpr * static_cast<std::size_t>(rows); // one sample's strip
  std::uint64_t stack[fast_detail::kStackWords];
  std::vector<std::uint64_t> heap;
  std::uint64_t* buf = stack;
  if (plane * n > fast_detail::kStackWords) {
    heap.resize(plane * n);
    buf = heap.data();
  }
  for (std::int32_t sy = r.y0; sy <= r.y1; sy += rows) {
    // Narrowed for sample points up to half a pixel from the centre (the sample grid's reach).
    const PixelRect strip =
        narrow_to_rows(t, PixelRect{r.x0, sy, r.x1, std::min(sy + rows - 1, r.y1)}, kSubpixelHalf);
    if (strip.empty())
      continue;
    const auto spr = static_cast<std::size_t>(strip.x1 - strip.x0 + 64) / 64;
    for (std::size_t k = 0; k < n; ++k) {
      const SampleOffset o = pattern.positions[k];
      fast_cover_rect(t, strip, std::int32_t{o.x} * kSampleGridUnit,
                      std::int32_t{o.y} * kSampleGridUnit, isa, buf + k * plane, spr);
    }
    for (std::int32_t y = strip.y0; y <= strip.y1; ++y) {
      const std::size_t row = static_cast<std::size_t>(y - strip.y0) * spr;
      for (std::size_t w = 0; w < spr; ++w) {
        std::uint64_t any = 0;
        for (std::size_t k = 0; k < n; ++k)
          any |= buf[k * plane + row + w];
        const std::int32_t x_base = strip.x0 + static_cast<std::int32_t>(w * 64);
        for (; any != 0; any &= any - 1) {
          const int bit = std::countr_zero(any);
          std::uint32_t mask = 0;
          for (std::size_t k = 0; k < n; ++k)
            mask |= static_cast<std::uint32_t>((buf[k * plane + row + w] >> bit) & 1u) << k;
          emit(x_base + bit, y, mask);
        }
      }
    }
  }
}

} // namespace rastrules::raster
