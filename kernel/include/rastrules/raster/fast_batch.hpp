// SPDX-License-Identifier: MIT
// Counting the coverage of many triangles at once (layer 3: mechanism): snapping and setup of
// small triangles eight at a time in 32-bit SIMD lanes, then each one's rows in lanes; larger
// triangles go through the tiled traversal (fast.hpp). Its only correctness criterion: for
// every triangle, exactly the pixels walk_triangle emits for the triangle set up from its
// snapped vertices (FAST.BATCH.EQUALS.PLAIN).
// Implements: FAST.BATCH.EQUALS.PLAIN, FAST.BATCH.SMALL_I32, FAST.BATCH.SNAP_SIMD
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "rastrules/isa.hpp"
#include "rastrules/snap.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules::raster {

// Triangles whose snapped vertices span less than kBatchSmallSpan raw units (64 pixels) in x
// and in y are set up and decided in 32-bit lanes (FAST.BATCH.SMALL_I32).
inline constexpr std::int32_t kBatchSmallSpan = 64 * kSubpixelOne;

enum class BatchStatus {
  kOk,
  kBadLength, // xy.size() is not a multiple of 6, an output span has the wrong size, or a
              // RunSink has no run
  kBadTarget, // width or height outside [1, kMaxTargetSide]
  kBadIsa,    // the instruction set is not supported here (isa_supported)
  kBadVertex, // a coordinate does not snap (SNAP.VERTEX.INVALID): see bad_*
};

struct FastBatchResult {
  BatchStatus status = BatchStatus::kOk;
  std::uint64_t covered = 0;    // pixel centres covered, summed over the triangles
  std::uint64_t rasterized = 0; // triangles with status kRasterized (not degenerate, not culled)
  std::uint64_t small = 0;      // of all triangles, those decided in 32-bit lanes
  // kBadVertex: the first triangle (lowest index) with a coordinate that does not snap, its
  // first such vertex (0..2) and axis ('x' or 'y'), and why.
  std::size_t bad_triangle = 0;
  int bad_vertex = 0;
  char bad_axis = 'x';
  SnapStatus bad_snap = SnapStatus::kOk;
};

// Returns a one-line description of r's status that names the problem ("ok" when kOk).
[[nodiscard]] std::string describe(const FastBatchResult& r);

// The per-pixel counts (overdraw) of a width x height target, for fast_count_batch to add to
// over many calls: pixel i's count (row-major) is low[i] + high[i], a byte below 255 and a
// 32-bit count. The batch unit's rows add to the bytes, a quarter of the memory of 32-bit
// counts, so that a million pixels stay in a core's cache where four million bytes do not (the
// per-pixel counts of 10^6 scattered small triangles, FAST.BATCH.PIXEL_COUNTS); a byte that
// reaches 255 moves 255 to high. Both planes come zeroed from the system (calloc), so pages no
// triangle touches cost no memory.
// rule: FAST.BATCH.PIXEL_COUNTS
class PixelCounts {
public:
  // All counts zero; a target of width * height pixels (0 for a side below 1). Throws
  // std::bad_alloc when the memory cannot be had.
  PixelCounts(std::int32_t width, std::int32_t height);
  [[nodiscard]] std::int32_t width() const { return width_; }
  [[nodiscard]] std::int32_t height() const { return height_; }
  [[nodiscard]] std::size_t size() const { return size_; }
  // Pixel i's count, modulo 2^32 (FAST.BATCH.EQUALS.PLAIN's wrap).
  [[nodiscard]] std::uint32_t operator[](std::size_t i) const { return high_[i] + low_[i]; }
  // The same target and the same count at every pixel.
  friend bool operator==(const PixelCounts& a, const PixelCounts& b);
  // One more at pixel i.
  void add(std::size_t i) {
    if (++low_[i] == 255) {
      low_[i] = 0;
      high_[i] += 255;
    }
  }
  // The two planes, for the batch unit: a byte of low is never 255 between calls.
  [[nodiscard]] std::uint8_t* low() { return low_.get(); }
  [[nodiscard]] std::uint32_t* high() { return high_.get(); }

private:
  struct Free {
    void operator()(void* p) const;
  };
  std::int32_t width_ = 0;
  std::int32_t height_ = 0;
  std::size_t size_ = 0;
  std::unique_ptr<std::uint8_t[], Free> low_;
  std::unique_ptr<std::uint32_t[], Free> high_;
};

// Counts the pixel centres of a width x height target covered by each triangle of xy (six
// floats a triangle: x0 y0 x1 y1 x2 y2, window coordinates in pixels): for triangle i, the
// pixels walk_triangle(setup_triangle(snapped vertices, state), width, height) emits.
//   per_triangle: empty, or one entry per triangle, set to that triangle's count;
//   hits: empty, or width * height counters (row-major), each increased by the number of
//         triangles covering its pixel (overdraw; a watertight mesh leaves 0 or 1). They
//         are read and written back in blocks (adding zero to pixels a triangle does not
//         cover), so no other thread may write them while the batch runs.
// isa selects the lanes (scalar: every triangle through setup_triangle and the scalar tiles;
// avx2 and avx512: the small triangles' snapping, setup and rows in AVX2 lanes, the others
// through the tiles of that instruction set). Every isa gives the same result.
// On an error status the counts and the outputs are unspecified (nothing is read or written
// out of bounds); the status names the problem (describe()).
// rule: FAST.BATCH.EQUALS.PLAIN
[[nodiscard]] FastBatchResult fast_count_batch(std::span<const float> xy, std::int32_t width,
                                               std::int32_t height, const RasterState& state,
                                               Isa isa, std::span<std::uint64_t> per_triangle = {},
                                               std::span<std::uint32_t> hits = {});

// The same, the overdraw added to counts (whose width and height must be the target's, else
// kBadLength): the form for many calls on one target (`render --count`'s chunks).
// rule: FAST.BATCH.EQUALS.PLAIN, FAST.BATCH.PIXEL_COUNTS
[[nodiscard]] FastBatchResult fast_count_batch(std::span<const float> xy, std::int32_t width,
                                               std::int32_t height, const RasterState& state,
                                               Isa isa, std::span<std::uint64_t> per_triangle,
                                               PixelCounts& counts);

// A row of covered pixels: x, x + 1, ..., x + n - 1 of row y, covered by triangle tri (n >= 1).
struct BatchRun {
  std::uint32_t tri;
  std::int32_t y;
  std::int32_t x;
  std::int32_t n;
};

// Where fast_runs_batch sends each row of covered pixels: run(context, tri, y, x, n) for pixels
// x, x + 1, ..., x + n - 1 of row y, covered by triangle tri (n >= 1).
struct RunSink {
  void* context = nullptr;
  void (*run)(void* context, std::uint32_t tri, std::int32_t y, std::int32_t x,
              std::int32_t n) = nullptr;
  // Optional: consecutive runs at once, in the order run would receive them one by one. Where
  // it is set, fast_runs_batch sends the small triangles' runs of each chunk this way, the
  // others through run (a call a run was a fifth of writing 10^6 small triangles' runs).
  void (*runs)(void* context, const BatchRun* runs, std::size_t n) = nullptr;
};

// The covered pixels of each triangle of xy, as fast_count_batch finds them, sent to sink as
// runs: triangle by triangle in order, and within a triangle row by row from the top, one run
// a row with a covered pixel (a row meets a triangle's covered set, which is convex, in
// consecutive pixels): for triangle i, exactly the pixels walk_triangle(setup_triangle(snapped
// vertices, state), width, height) emits, in its order. On an error status (as
// fast_count_batch's) the runs sent are unspecified; a caller that must write nothing then
// checks the triangles with fast_count_batch first. covered and rasterized are
// fast_count_batch's.
// rule: FAST.BATCH.EQUALS.PLAIN
[[nodiscard]] FastBatchResult fast_runs_batch(std::span<const float> xy, std::int32_t width,
                                              std::int32_t height, const RasterState& state,
                                              Isa isa, const RunSink& sink);

// The runs fast_runs_batch sends for triangle tri of xy (tri < xy.size() / 6) in rows y_first
// to y_last alone, in the same order: the rows of one large triangle can be drawn in bands, on
// several threads, and joined in band order to that triangle's runs. covered counts the pixels
// sent; rasterized is 1 when the triangle is rasterized (whatever the rows). Errors as
// fast_runs_batch's (kBadLength also for tri out of range), for this triangle alone.
// rule: FAST.BATCH.EQUALS.PLAIN
[[nodiscard]] FastBatchResult fast_runs_rows(std::span<const float> xy, std::size_t tri,
                                             std::int32_t width, std::int32_t height,
                                             const RasterState& state, Isa isa,
                                             std::int32_t y_first, std::int32_t y_last,
                                             const RunSink& sink);

} // namespace rastrules::raster
