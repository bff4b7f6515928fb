// SPDX-License-Identifier: MIT
// Internal to the fast traversal (kernel/src/fast*.cpp): the tile driver shared by the scalar,
// AVX2 and AVX-512 translation units, and the entry points each of them defines.
//
// Every translation unit that includes this header is compiled for its own instruction set
// (kernel/CMakeLists.txt). So that no code compiled for AVX2 or AVX-512 can be picked by the
// linker for a caller in another unit (inline functions are merged across units), everything
// the ISA units run lives here in an unnamed namespace or is a template instantiated with a
// unit-local kernel type, and calls no external inline function: only arithmetic, builtins and
// the unit's own intrinsics.
// Implements: FAST.TILE.CLASSIFY, FAST.LANE.I32

#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "rastrules/formula/lane.hpp"
#include "rastrules/raster/walk.hpp"

// Set by kernel/CMakeLists.txt when fast_avx2.cpp and fast_avx512.cpp are compiled for their
// instruction sets (x86-64 with GCC or Clang); elsewhere they compile to nothing.
#ifndef RASTRULES_FAST_X86
#define RASTRULES_FAST_X86 0
#endif

namespace rastrules::raster::fast_detail {

// What the dispatcher (fast.cpp) computes once per rectangle from the exact 64-bit setup.
struct FastEdges {
  // E + bias (FIX.BIAS.FORM) of each edge at the sample point of the first pixel (tx0, ty0)
  // of the rectangle's first tile, evaluated directly (TRI.EDGE.FUNCTION, 64-bit).
  std::int64_t e_first[3];
  std::int32_t a[3]; // A = ay - by: the lane step along x (FAST.LANE.I32)
  std::int32_t b[3]; // B = bx - ax: the lane step along y
  std::int32_t tx0;  // first pixel of the first tile: the rectangle's first pixel
  std::int32_t ty0;
};

// How many tiles of a rectangle each classification decided (FAST.TILE.CLASSIFY).
struct TileCounts {
  std::uint64_t rejected = 0;
  std::uint64_t accepted = 0;
  std::uint64_t partial = 0;
  std::uint64_t blocks_rejected = 0;
  std::uint64_t blocks_accepted = 0;
  std::uint64_t blocks_partial = 0;
};

// The entry points of one instruction set's lanes (lanes_of<Kernel>() below). cover_rect writes
// fast_cover_rect's output; count_rect returns the number of covered sample points of r.
struct Lanes {
  void (*cover_rect)(const FastEdges& f, PixelRect r, std::uint64_t* out,
                     std::size_t words_per_row);
  std::uint64_t (*count_rect)(const FastEdges& f, PixelRect r);
};

// Each unit's lanes, and the classification (scalar only: it does not depend on the lanes).
extern const Lanes kScalarLanes;
TileCounts tile_counts_scalar(const FastEdges& f, PixelRect r);
#if RASTRULES_FAST_X86
extern const Lanes kAvx2Lanes;
extern const Lanes kAvx512Lanes;
#endif

namespace {

constexpr std::int32_t kTile = 16;
constexpr std::int32_t kLast = kTile - 1;
constexpr std::int32_t kBlock = 4 * kTile;

constexpr std::int32_t min32(std::int32_t x, std::int32_t y) {
  return x < y ? x : y;
}
constexpr std::int32_t max32(std::int32_t x, std::int32_t y) {
  return x > y ? x : y;
}

// Bits i0..i1 of a 16-bit row (0 <= i0 <= i1 <= 15).
constexpr std::uint32_t column_mask(std::int32_t i0, std::int32_t i1) {
  return ((std::uint32_t{2} << i1) - 1u) & ~((std::uint32_t{1} << i0) - 1u);
}

constexpr std::uint64_t popcount32(std::uint32_t m) {
#if defined(__GNUC__) || defined(__clang__)
  return static_cast<std::uint64_t>(__builtin_popcount(m));
#else
  std::uint64_t n = 0;
  for (; m != 0; m &= m - 1)
    ++n;
  return n;
#endif
}

// The tile walk of FAST.TILE.CLASSIFY over rectangle r: for each tile, the lane thresholds of
// FAST.LANE.I32, then rejection, acceptance or the per-row lane test of Kernel, reported to sink:
//   sink.reject();
//   sink.accept(tx, ty, j0, j1, cols): rows ty+j0..ty+j1, columns tx+i for the bits i of cols;
//   sink.partial(): a tile decided per sample; true when the sink wants its rows;
//   sink.row(tx, y, bits): the covered columns tx+i of row y (already clipped to r).
// Kernel(a, b) prepares the lanes i A of a row (the same in every tile: only the threshold
// depends on the tile); kernel.tile(c, j0, j1, cols, sink, tx, ty) runs a partial tile's rows.
template <class Kernel, class Sink> inline void drive(const FastEdges& f, PixelRect r, Sink& sink) {
  // One tile step along x (y) adds 16 pixels' worth of E: 16 * 256 * A (B), a block step 64
  // pixels' worth; exact in int64 (|A| < 2^24: |step| < 2^38; FIX.STEP.INCREMENTAL).
  const auto select = [](bool cond, std::int64_t x, std::int64_t y) { return cond ? x : y; };
  const auto select32 = [](bool cond, std::int32_t x, std::int32_t y) { return cond ? x : y; };
  std::int64_t step_x[3], step_y[3], block_x[3], block_y[3], block_row_e[3];
  std::int64_t bmax[3], bmin[3];
  std::int32_t lmax[3], lmin[3];
  for (int k = 0; k < 3; ++k) {
    step_x[k] = std::int64_t{kTile} * 256 * f.a[k];
    step_y[k] = std::int64_t{kTile} * 256 * f.b[k];
    block_x[k] = std::int64_t{kBlock} * 256 * f.a[k];
    block_y[k] = std::int64_t{kBlock} * 256 * f.b[k];
    block_row_e[k] = f.e_first[k];
    // rule: FAST.TILE.CLASSIFY
    // L = i A + j B is linear in (i, j): over a tile's lanes 0 <= i, j <= 15 its extremes lie
    // at corners chosen by the signs of A and B (formula::lane_max, lane_min), the same for
    // every tile; over a block's lanes 0 <= i, j <= 63 likewise, in 64-bit (|L| < 2^31). The
    // whole tile or block is classified, also when only part of it lies in r: rejecting or
    // accepting more lanes than r holds decides r's lanes all the same.
    // |A|, |B| < 2^24: |L| < 2^29 over a tile.
    lmax[k] = formula::lane_max<std::int32_t>(f.a[k], f.b[k], kLast, select32);
    lmin[k] = formula::lane_min<std::int32_t>(f.a[k], f.b[k], kLast, select32);
    bmax[k] = formula::lane_max<std::int64_t>(f.a[k], f.b[k], kBlock - 1, select);
    bmin[k] = formula::lane_min<std::int64_t>(f.a[k], f.b[k], kBlock - 1, select);
  }
  const Kernel kernel(f.a, f.b);
  // A rectangle within one block is never rejected or accepted whole (it is a triangle's
  // bounds): its tiles are classified directly.
  const bool blocks = r.x1 - r.x0 >= kBlock || r.y1 - r.y0 >= kBlock;
  for (std::int32_t by = f.ty0; by <= r.y1; by += kBlock) {
    const std::int32_t by1 = min32(by + kBlock - 1, r.y1);
    std::int64_t be[3] = {block_row_e[0], block_row_e[1], block_row_e[2]};
    for (std::int32_t bx = f.tx0; bx <= r.x1; bx += kBlock) {
      const std::int32_t bx1 = min32(bx + kBlock - 1, r.x1);
      // rule: FAST.TILE.CLASSIFY, FAST.LANE.I32
      // The block's lanes in 64-bit: inside iff L >= -q with q = (E0 + bias) >> 8; the clamp
      // to [-2^31, 2^31] (formula::kBlockLaneBound) changes no comparison since |L| < 2^31.
      bool block_reject = false, block_accept = blocks;
      for (int k = 0; blocks && k < 3; ++k) {
        const std::int64_t c = formula::lane_threshold<std::int64_t>(
            be[k] >> 8, std::int64_t{formula::kBlockLaneBound}, select);
        block_reject |= bmax[k] < c;
        block_accept &= bmin[k] >= c;
      }
      sink.block(block_reject ? 0 : block_accept ? 1 : 2);
      std::int64_t row_e[3] = {be[0], be[1], be[2]};
      for (std::int32_t ty = by; ty <= by1; ty += kTile) {
        const std::int32_t j0 = max32(r.y0 - ty, 0), j1 = min32(r.y1 - ty, kLast);
        std::int64_t e[3] = {row_e[0], row_e[1], row_e[2]};
        for (std::int32_t tx = bx; tx <= bx1; tx += kTile) {
          const std::int32_t i0 = max32(r.x0 - tx, 0), i1 = min32(r.x1 - tx, kLast);
          const std::uint32_t cols = column_mask(i0, i1);
          if (block_reject) {
            sink.reject();
            continue;
          }
          if (block_accept) {
            sink.accept(tx, ty, j0, j1, cols);
            continue;
          }
          std::int32_t c[3];
          bool reject = false, accept = true;
          for (int k = 0; k < 3; ++k) {
            // rule: FAST.LANE.I32
            // q = floor((E0 + bias) / 256) by an arithmetic shift; C = -q clamped to
            // [-2^30, 2^30]: lane (i, j) is inside iff i A + j B >= C.
            const std::int64_t q = e[k] >> 8;
            c[k] = static_cast<std::int32_t>(formula::lane_threshold<std::int64_t>(
                q, std::int64_t{formula::kLaneBound}, select));
            // rule: FAST.TILE.CLASSIFY
            reject |= lmax[k] < c[k];  // no lane of the tile inside this edge
            accept &= lmin[k] >= c[k]; // every lane of the tile inside this edge
            e[k] += step_x[k];
          }
          if (reject) {
            sink.reject();
          } else if (accept) {
            sink.accept(tx, ty, j0, j1, cols);
          } else if (sink.partial()) {
            kernel.tile(c, j0, j1, cols, sink, tx, ty);
          }
        }
        for (int k = 0; k < 3; ++k)
          row_e[k] += step_y[k];
      }
      for (int k = 0; k < 3; ++k)
        be[k] += block_x[k];
    }
    for (int k = 0; k < 3; ++k)
      block_row_e[k] += block_y[k];
  }
}

// Writes fast_cover_rect's bit rows: bit (x - r.x0) of row y - r.y0.
struct BitSink {
  std::uint64_t* out;
  std::size_t words_per_row;
  PixelRect r;

  void put(std::int32_t tx, std::int32_t y, std::uint32_t bits) const {
    if (bits == 0)
      return;
    std::int32_t off = tx - r.x0; // >= -15: the tile may start left of r (those bits are 0)
    if (off < 0) {
      bits >>= -off;
      off = 0;
    }
    const auto u = static_cast<std::size_t>(off);
    std::uint64_t* row = out + static_cast<std::size_t>(y - r.y0) * words_per_row;
    const std::size_t w = u >> 6, s = u & 63u;
    row[w] |= std::uint64_t{bits} << s;
    if (s > 48) {
      const std::uint64_t hi = std::uint64_t{bits} >> (64 - s);
      if (hi != 0)
        row[w + 1] |= hi;
    }
  }
  void block(int) const {}
  void reject() const {}
  bool partial() const { return true; }
  void accept(std::int32_t tx, std::int32_t ty, std::int32_t j0, std::int32_t j1,
              std::uint32_t cols) const {
    for (std::int32_t j = j0; j <= j1; ++j)
      put(tx, ty + j, cols);
  }
  void row(std::int32_t tx, std::int32_t y, std::uint32_t bits) const { put(tx, y, bits); }
};

struct CountSink {
  std::uint64_t n = 0;
  void block(int) const {}
  void reject() const {}
  bool partial() const { return true; }
  void accept(std::int32_t, std::int32_t, std::int32_t j0, std::int32_t j1, std::uint32_t cols) {
    n += static_cast<std::uint64_t>(j1 - j0 + 1) * popcount32(cols);
  }
  void row(std::int32_t, std::int32_t, std::uint32_t bits) { n += popcount32(bits); }
};

struct ClassSink {
  TileCounts counts;
  void block(int kind) {
    if (kind == 0)
      ++counts.blocks_rejected;
    else if (kind == 1)
      ++counts.blocks_accepted;
    else
      ++counts.blocks_partial;
  }
  void reject() { ++counts.rejected; }
  bool partial() {
    ++counts.partial;
    return false;
  }
  void accept(std::int32_t, std::int32_t, std::int32_t, std::int32_t, std::uint32_t) {
    ++counts.accepted;
  }
  void row(std::int32_t, std::int32_t, std::uint32_t) {}
};

template <class Kernel>
inline void cover_rect_with(const FastEdges& f, PixelRect r, std::uint64_t* out,
                            std::size_t words_per_row) {
  const auto rows = static_cast<std::size_t>(r.y1 - r.y0 + 1);
  std::memset(out, 0, rows * words_per_row * sizeof(std::uint64_t));
  BitSink sink{out, words_per_row, r};
  drive<Kernel>(f, r, sink);
}

template <class Kernel> inline std::uint64_t count_rect_with(const FastEdges& f, PixelRect r) {
  CountSink sink;
  drive<Kernel>(f, r, sink);
  return sink.n;
}

// The entry points of the unit whose lanes are Kernel, compiled for that unit's instruction set.
template <class Kernel> constexpr Lanes lanes_of() {
  return Lanes{&cover_rect_with<Kernel>, &count_rect_with<Kernel>};
}

} // namespace

} // namespace rastrules::raster::fast_detail
