// SPDX-License-Identifier: MIT
// The fast exact traversal (layer 3: mechanism): tiles of kFastTileSize x kFastTileSize pixels
// aligned to the target, whole-tile rejection and acceptance, 32-bit SIMD lanes (FAST.LANE.I32),
// incremental stepping, AVX-512 / AVX2 / scalar chosen at run time. Its only correctness
// criterion: exactly the coverage of the plain walks (walk.hpp, walk_msaa.hpp), in the same
// order (FAST.EQUALS.PLAIN).
// Implements: FAST.TILE.CLASSIFY, FAST.LANE.I32, FAST.EQUALS.PLAIN

#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "rastrules/isa.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/raster/walk.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules::raster {

inline constexpr std::int32_t kFastTileSize = 16;

// Writes the coverage of the sample points at raw offset (dx, dy) from each pixel centre of
// rect r by the rasterized triangle t: bit (x - r.x0) % 64 of word (y - r.y0) * words_per_row +
// (x - r.x0) / 64 is set iff t covers the sample point of pixel (x, y) (TRI.COVER.SAMPLE).
// Every word of the r.y1 - r.y0 + 1 rows is written (bits past r.x1 are zero).
// Preconditions: t.status == kRasterized; r not empty, inside [0, kMaxTargetSide)^2;
// words_per_row >= (r.x1 - r.x0 + 64) / 64; isa_supported(isa); |dx|, |dy| <= 128.
// rule: FAST.TILE.CLASSIFY, FAST.LANE.I32
void fast_cover_rect(const TriangleSetup& t, PixelRect r, std::int32_t dx, std::int32_t dy,
                     Isa isa, std::uint64_t* out, std::size_t words_per_row);

// Returns the number of pixels of the target whose centre t covers (what walk_triangle
// emits, counted). The benchmarks' decision rate of the fast path.
// rule: FAST.EQUALS.PLAIN
[[nodiscard]] std::uint64_t fast_count_covered(const TriangleSetup& t, std::int32_t width,
                                               std::int32_t height, Isa isa);

// Calls emit(x, y) for exactly the pixels walk_triangle(t, width, height, emit) emits, in the
// same order; strips of kFastTileSize rows are decided by fast_cover_rect.
// rule: FAST.EQUALS.PLAIN
template <class Emit>
void walk_triangle_fast(const TriangleSetup& t, std::int32_t width, std::int32_t height, Isa isa,
                        Emit&& emit);

// Calls emit(x, y, mask) for exactly what walk_triangle_samples(t, pattern, width, height, emit)
// emits, in the same order.
// rule: FAST.EQUALS.PLAIN
template <class Emit>
void walk_triangle_samples_fast(const TriangleSetup& t, const SamplePattern& pattern,
                                std::int32_t width, std::int32_t height, Isa isa, Emit&& emit);

}  // namespace rastrules::raster
