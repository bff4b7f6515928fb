// SPDX-License-Identifier: MIT
// Internal to the batch counter (kernel/src/fast_batch*.cpp): what the dispatcher
// (fast_batch.cpp, baseline instruction set) hands the SIMD unit (fast_batch_avx2.cpp, compiled
// for AVX2) and what it gets back. The SIMD unit calls no inline function of another header
// (see fast_tiles.hpp): it decides the small triangles and lists the others for the dispatcher.
// Implements: FAST.BATCH.SMALL_I32

#pragma once

#include <cstddef>
#include <cstdint>

#include "rastrules/raster/fast_batch.hpp"

#ifndef RASTRULES_FAST_X86
#define RASTRULES_FAST_X86 0
#endif

namespace rastrules::raster::batch_detail {

// Spans below this many raw units (64 pixels) are small (raster::kBatchSmallSpan).
inline constexpr std::int32_t kSmallSpan = 64 * 256;

// A row's covered pixels of one triangle: x, x + 1, ..., x + n - 1 in row y (a triangle's
// covered pixel centres in a row are consecutive: the row meets a convex set in an interval).
// Left uninitialised where it is allocated (make_unique_for_overwrite): a buffer of runs is
// only read where the unit wrote it.
// The lanes' runs, as fast_runs_batch sends them (BatchRun: tri is the index in the whole
// batch).
using Run = BatchRun;

// The most runs one small triangle gives: one a row, rows below 64 + 1.
inline constexpr std::size_t kMaxRunsPerSmall = 65;

struct Params {
  const float* xy = nullptr; // 6 floats a triangle
  std::size_t n = 0;         // triangles
  std::int32_t width = 0;
  std::int32_t height = 0;
  bool top_inclusive = true; // TRI.FILL.CONVENTION, as formula::is_inclusive_edge's flags
  bool left_inclusive = true;
  bool skip_cw = false;                  // TRI.CULL.MODE: clockwise triangles are culled
  bool skip_ccw = false;                 // counter-clockwise triangles are culled
  std::uint64_t* per_triangle = nullptr; // n entries, zeroed by the caller, or null
  // The overdraw (FAST.BATCH.PIXEL_COUNTS), or both null: pixel i's count is low[i] + hits[i];
  // the rows add to the bytes of low (never 255 between calls) and move 255 to hits when one
  // reaches it.
  std::uint32_t* hits = nullptr; // width * height, or null
  std::uint8_t* low = nullptr;   // width * height, or null
  // With runs (and no hits): each small triangle's rows appended as runs, in triangle order,
  // rows top down; room for kMaxRunsPerSmall a triangle of p. tri_base: the index in the whole
  // batch of p's first triangle.
  Run* runs = nullptr;
  std::size_t tri_base = 0;
};

struct Out {
  std::uint64_t covered = 0;
  std::uint64_t rasterized = 0; // small triangles only
  std::uint64_t small = 0;
  std::size_t bad = static_cast<std::size_t>(-1); // first triangle that does not snap
  std::size_t runs = 0;                           // runs written to Params::runs
};

#if RASTRULES_FAST_X86
// Decides the triangles of p whose snapped spans are below kBatchSmallSpan; writes the indices
// (0-based in p) of the other snapped triangles to large[0..k) and returns k. Stops at the
// first group of eight with a coordinate that does not snap and sets out.bad to its first
// such triangle (the triangles of that group are then not counted).
// rule: FAST.BATCH.SMALL_I32, FAST.BATCH.SNAP_SIMD
std::size_t small_batch_avx2(const Params& p, Out& out, std::uint32_t* large);
// The same, each small triangle's rows in chunks of sixteen lanes (FAST.BATCH.LANES16): the same
// answers, outputs and order. Only where isa_supported(Isa::kAvx512) (fast_batch_avx512.cpp is
// empty without AVX-512 support in the compiler's target).
// rule: FAST.BATCH.LANES16
std::size_t small_batch_avx512(const Params& p, Out& out, std::uint32_t* large);
#endif

} // namespace rastrules::raster::batch_detail
