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

// Calls emit(x, y) for exactly the pixels walk_triangle_rows(t, width, height, y_first, y_last,
// emit) emits, in the same order. Strips of whole tile rows from the first row (all of the
// pixel bounds when they fit 4 KiB of bits) are decided by fast_cover_rect, then their set bits
// emitted row by row.
// Preconditions: width, height in [1, kMaxTargetSide]; isa_supported(isa).
// rule: FAST.EQUALS.PLAIN
template <class Emit>
void walk_triangle_fast_rows(const TriangleSetup& t, std::int32_t width, std::int32_t height,
                             std::int32_t y_first, std::int32_t y_last, Isa isa, Emit&& emit) {
  const PixelRect r = rows_of(walk_bounds(t, width, height), y_first, y_last);
  if (r.empty())
    return;
  const auto wpr = static_cast<std::size_t>(r.x1 - r.x0 + 64) / 64;
  const std::int32_t rows = fast_detail::strip_rows(wpr, 1);
  const std::size_t words = wpr * static_cast<std::size_t>(rows);
  std::uint64_t stack[fast_detail::kStackWords];
  std::vector<std::uint64_t> heap;
  std::uint64_t* buf = stack;
  if (words > fast_detail::kStackWords) {
    heap.resize(words);
    buf = heap.data();
  }
  // Strips of whole tile rows from the first row of the bounds.
  for (std::int32_t sy = r.y0; sy <= r.y1; sy += rows) {
    const PixelRect strip{r.x0, std::max(sy, r.y0), r.x1, std::min(sy + rows - 1, r.y1)};
    fast_cover_rect(t, strip, 0, 0, isa, buf, wpr);
    for (std::int32_t y = strip.y0; y <= strip.y1; ++y) {
      const std::uint64_t* row = buf + static_cast<std::size_t>(y - strip.y0) * wpr;
      for (std::size_t w = 0; w < wpr; ++w) {
        const std::int32_t x_base = r.x0 + static_cast<std::int32_t>(w * 64);
        for (std::uint64_t bits = row[w]; bits != 0; bits &= bits - 1)
          emit(x_base + std::countr_zero(bits), y);
      }
    }
  }
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
    const PixelRect strip{r.x0, std::max(sy, r.y0), r.x1, std::min(sy + rows - 1, r.y1)};
    for (std::size_t k = 0; k < n; ++k) {
      const SampleOffset o = pattern.positions[k];
      fast_cover_rect(t, strip, std::int32_t{o.x} * kSampleGridUnit,
                      std::int32_t{o.y} * kSampleGridUnit, isa, buf + k * plane, wpr);
    }
    for (std::int32_t y = strip.y0; y <= strip.y1; ++y) {
      const std::size_t row = static_cast<std::size_t>(y - strip.y0) * wpr;
      for (std::size_t w = 0; w < wpr; ++w) {
        std::uint64_t any = 0;
        for (std::size_t k = 0; k < n; ++k)
          any |= buf[k * plane + row + w];
        const std::int32_t x_base = r.x0 + static_cast<std::int32_t>(w * 64);
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
