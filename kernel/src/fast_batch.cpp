// SPDX-License-Identifier: MIT
// The batch counter's dispatcher (FAST.BATCH.EQUALS.PLAIN), compiled for the baseline
// instruction set: checks the arguments, hands chunks of triangles to the AVX2 unit, and runs
// every other triangle (all of them under Isa::kScalar) through the kernel's own snapping,
// setup_triangle and tiled traversal.
// Implements: FAST.BATCH.EQUALS.PLAIN, FAST.ISA.DISPATCH

#include "rastrules/raster/fast_batch.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "fast_batch_detail.hpp"
#include "rastrules/raster/fast.hpp"

namespace rastrules::raster {

static_assert(kBatchSmallSpan == batch_detail::kSmallSpan, "one small span");

namespace {

constexpr std::size_t kChunk = 1024; // triangles handed to the SIMD unit at once

struct Bad {
  int vertex = 0;
  char axis = 'x';
  SnapStatus status = SnapStatus::kOk;
};

// Snaps the six coordinates of one triangle; on failure, which one and why (the first, in
// the order x0 y0 x1 y1 x2 y2).
// rule: SNAP.VERTEX.ROUND, SNAP.VERTEX.RANGE, SNAP.VERTEX.INVALID
bool snap_triangle(const float* v, std::array<Vec2, 3>& out, Bad& bad) {
  for (int k = 0; k < 3; ++k) {
    const SnapResult x = snap_to_subpixel(v[2 * k]);
    if (x.status != SnapStatus::kOk) {
      bad = Bad{k, 'x', x.status};
      return false;
    }
    const SnapResult y = snap_to_subpixel(v[2 * k + 1]);
    if (y.status != SnapStatus::kOk) {
      bad = Bad{k, 'y', y.status};
      return false;
    }
    out[static_cast<std::size_t>(k)] = Vec2{x.value, y.value};
  }
  return true;
}

struct Context {
  std::span<const float> xy;
  std::int32_t width;
  std::int32_t height;
  RasterState state;
  Isa isa;
  std::span<std::uint64_t> per_triangle;
  std::uint32_t* hits; // the 32-bit overdraw counts, or null (FAST.BATCH.PIXEL_COUNTS)
};

// Snaps and sets up triangle i into t: false when a coordinate does not snap (r says which
// and why); else true, t counted in r.rasterized when it is rasterized.
// rule: SNAP.VERTEX.INVALID
bool set_up(const Context& c, std::size_t i, TriangleSetup& t, FastBatchResult& r) {
  std::array<Vec2, 3> v;
  Bad bad;
  if (!snap_triangle(c.xy.data() + 6 * i, v, bad)) {
    r.status = BatchStatus::kBadVertex;
    r.bad_triangle = i;
    r.bad_vertex = bad.vertex;
    r.bad_axis = bad.axis;
    r.bad_snap = bad.status;
    return false;
  }
  t = setup_triangle(v, c.state);
  if (t.status == TriangleStatus::kRasterized)
    ++r.rasterized;
  return true;
}

// Triangle i the plain way: the kernel's snapping and setup, then its tiles.
// rule: FAST.BATCH.EQUALS.PLAIN
bool one_triangle(const Context& c, std::size_t i, FastBatchResult& r) {
  TriangleSetup t;
  if (!set_up(c, i, t, r))
    return false;
  if (t.status != TriangleStatus::kRasterized)
    return true;
  std::uint64_t n = 0;
  if (c.hits == nullptr) {
    n = fast_count_covered(t, c.width, c.height, c.isa);
  } else {
    const auto w = static_cast<std::size_t>(c.width);
    std::uint32_t* hits = c.hits;
    walk_triangle_fast(t, c.width, c.height, c.isa, [&](std::int32_t x, std::int32_t y) {
      ++hits[static_cast<std::size_t>(y) * w + static_cast<std::size_t>(x)];
      ++n;
    });
  }
  r.covered += n;
  if (!c.per_triangle.empty())
    c.per_triangle[i] = n;
  return true;
}

// Triangle i the plain way, its pixels in rows y_first to y_last sent to sink as runs.
// Returns false when it does not snap (r says why).
// rule: FAST.BATCH.EQUALS.PLAIN
bool one_triangle_runs(const Context& c, std::size_t i, const RunSink& sink, FastBatchResult& r,
                       std::int32_t y_first = 0, std::int32_t y_last = kMaxTargetSide) {
  TriangleSetup t;
  if (!set_up(c, i, t, r))
    return false;
  if (t.status != TriangleStatus::kRasterized)
    return true;
  const auto tri = static_cast<std::uint32_t>(i);
  // The walk's rows as runs, from its row bits (a pixel a call cost a 4096^2 triangle's binary
  // list 30 times its runs).
  walk_triangle_fast_row_runs(t, c.width, c.height, y_first, y_last, c.isa,
                              [&](std::int32_t y, std::int32_t x, std::int32_t n) {
                                r.covered += static_cast<std::uint64_t>(n);
                                sink.run(sink.context, tri, y, x, n);
                              });
  return true;
}

// The checks fast_count_batch and fast_runs_batch share, in this order (the target, the
// lengths, the instruction set): the status of a call that cannot go on, else kOk. outputs_fit:
// whether the caller's outputs have the lengths it needs.
BatchStatus check_call(std::span<const float> xy, std::int32_t width, std::int32_t height, Isa isa,
                       bool outputs_fit) {
  if (width < 1 || height < 1 || width > kMaxTargetSide || height > kMaxTargetSide)
    return BatchStatus::kBadTarget;
  if (xy.size() % 6 != 0 || !outputs_fit)
    return BatchStatus::kBadLength;
  if (!isa_supported(isa))
    return BatchStatus::kBadIsa;
  return BatchStatus::kOk;
}

#if RASTRULES_FAST_X86
// The SIMD unit's parameters for a state (the tie rule and culling as lane flags).
batch_detail::Params lane_params(std::int32_t width, std::int32_t height,
                                 const RasterState& state) {
  batch_detail::Params p;
  p.width = width;
  p.height = height;
  // rule: TRI.FILL.CONVENTION
  // (formula::is_inclusive_edge's two flags)
  p.top_inclusive =
      state.fill == FillConvention::kTopLeft || state.fill == FillConvention::kTopRight;
  p.left_inclusive =
      state.fill == FillConvention::kTopLeft || state.fill == FillConvention::kBottomLeft;
  // rule: TRI.CULL.MODE
  // A clockwise triangle is front-facing iff front_face is kClockwise.
  const bool cw_front = state.front_face == FrontFace::kClockwise;
  p.skip_cw =
      (state.cull == CullMode::kBack && !cw_front) || (state.cull == CullMode::kFront && cw_front);
  p.skip_ccw =
      (state.cull == CullMode::kBack && cw_front) || (state.cull == CullMode::kFront && !cw_front);
  return p;
}

// rule: FAST.ISA.DISPATCH, FAST.BATCH.LANES16
// The SIMD unit of isa (not kScalar): rows in chunks of sixteen lanes with AVX-512, of eight
// with AVX2; both share the group set-up and give the same answers.
std::size_t small_batch(Isa isa, const batch_detail::Params& p, batch_detail::Out& o,
                        std::uint32_t* large) {
  return isa == Isa::kAvx512 ? batch_detail::small_batch_avx512(p, o, large)
                             : batch_detail::small_batch_avx2(p, o, large);
}
#endif

} // namespace

std::string describe(const FastBatchResult& r) {
  switch (r.status) {
  case BatchStatus::kOk:
    return "ok";
  case BatchStatus::kBadLength:
    return "batch: the coordinates are not 6 floats a triangle, or an output does not have one "
           "entry per triangle (per_triangle) or per pixel (hits)";
  case BatchStatus::kBadTarget:
    return "batch: the target's width and height must lie in [1, " +
           std::to_string(kMaxTargetSide) + "]";
  case BatchStatus::kBadIsa:
    return "batch: the instruction set is not supported on this processor";
  case BatchStatus::kBadVertex:
    return "batch: triangle " + std::to_string(r.bad_triangle) + ", vertex " +
           std::to_string(r.bad_vertex) + ", " + std::string(1, r.bad_axis) + ": " +
           std::string(to_string(r.bad_snap)) + " (SNAP.VERTEX.INVALID)";
  }
  return "batch: unknown status";
}

namespace {

// fast_count_batch after its checks (r: kOk), the overdraw added to hits (32-bit counts: the
// plain way's pixels, and the lanes' bytes that reach 255) and low (bytes: the lanes' pixels),
// both null for none; low may be null only under kScalar or without hits.
// rule: FAST.BATCH.EQUALS.PLAIN, FAST.ISA.DISPATCH, FAST.BATCH.PIXEL_COUNTS
FastBatchResult count_checked(std::span<const float> xy, std::int32_t width, std::int32_t height,
                              const RasterState& state, Isa isa,
                              std::span<std::uint64_t> per_triangle, std::uint32_t* hits,
                              [[maybe_unused]] std::uint8_t* low) {
  FastBatchResult r;
  const std::size_t n = xy.size() / 6;
  std::fill(per_triangle.begin(), per_triangle.end(), std::uint64_t{0});
  const Context c{xy, width, height, state, isa, per_triangle, hits};
#if RASTRULES_FAST_X86
  if (isa != Isa::kScalar) {
    batch_detail::Params p = lane_params(width, height, state);
    p.hits = hits;
    p.low = hits == nullptr ? nullptr : low;
    std::array<std::uint32_t, kChunk> large;
    for (std::size_t base = 0; base < n; base += kChunk) {
      p.xy = xy.data() + 6 * base;
      p.n = std::min(kChunk, n - base);
      p.per_triangle = per_triangle.empty() ? nullptr : per_triangle.data() + base;
      batch_detail::Out o;
      const std::size_t k = small_batch(isa, p, o, large.data());
      r.covered += o.covered;
      r.rasterized += o.rasterized;
      r.small += o.small;
      for (std::size_t j = 0; j < k; ++j)
        if (!one_triangle(c, base + large[j], r))
          return r; // cannot fail: all snapped
      if (o.bad != static_cast<std::size_t>(-1)) {
        // The lanes reject exactly what snap_to_subpixel rejects (FAST.BATCH.SNAP_SIMD): the
        // plain way fails on the same triangle and says which coordinate and why.
        (void)one_triangle(c, base + o.bad, r);
        return r;
      }
    }
    return r;
  }
#endif
  for (std::size_t i = 0; i < n; ++i)
    if (!one_triangle(c, i, r))
      return r;
  return r;
}

std::size_t pixels_of(std::int32_t width, std::int32_t height) {
  return static_cast<std::size_t>(std::max(width, 0)) *
         static_cast<std::size_t>(std::max(height, 0));
}

} // namespace

void PixelCounts::Free::operator()(void* p) const {
  std::free(p);
}

// rule: FAST.BATCH.PIXEL_COUNTS
PixelCounts::PixelCounts(std::int32_t width, std::int32_t height)
    : width_(width), height_(height), size_(pixels_of(width, height)),
      low_(static_cast<std::uint8_t*>(std::calloc(std::max<std::size_t>(size_, 1), 1))),
      high_(static_cast<std::uint32_t*>(
          std::calloc(std::max<std::size_t>(size_, 1), sizeof(std::uint32_t)))) {
  if (!low_ || !high_)
    throw std::bad_alloc();
}

bool operator==(const PixelCounts& a, const PixelCounts& b) {
  if (a.width_ != b.width_ || a.height_ != b.height_)
    return false;
  for (std::size_t i = 0; i < a.size_; ++i)
    if (a[i] != b[i])
      return false;
  return true;
}

// rule: FAST.BATCH.EQUALS.PLAIN, FAST.ISA.DISPATCH
FastBatchResult fast_count_batch(std::span<const float> xy, std::int32_t width, std::int32_t height,
                                 const RasterState& state, Isa isa,
                                 std::span<std::uint64_t> per_triangle,
                                 std::span<std::uint32_t> hits) {
  FastBatchResult r;
  r.status = check_call(xy, width, height, isa,
                        (per_triangle.empty() || per_triangle.size() == xy.size() / 6) &&
                            (hits.empty() || hits.size() == pixels_of(width, height)));
  if (r.status != BatchStatus::kOk)
    return r;
  if (hits.empty() || isa == Isa::kScalar)
    return count_checked(xy, width, height, state, isa, per_triangle,
                         hits.empty() ? nullptr : hits.data(), nullptr);
  // rule: FAST.BATCH.PIXEL_COUNTS
  // The lanes add to bytes beside the caller's counts, added to them at the end.
  PixelCounts counts(width, height);
  r = count_checked(xy, width, height, state, isa, per_triangle, hits.data(), counts.low());
  const std::uint8_t* low = counts.low();
  for (std::size_t i = 0; i < hits.size(); ++i)
    hits[i] += low[i];
  return r;
}

// rule: FAST.BATCH.EQUALS.PLAIN, FAST.ISA.DISPATCH, FAST.BATCH.PIXEL_COUNTS
FastBatchResult fast_count_batch(std::span<const float> xy, std::int32_t width, std::int32_t height,
                                 const RasterState& state, Isa isa,
                                 std::span<std::uint64_t> per_triangle, PixelCounts& counts) {
  FastBatchResult r;
  r.status = check_call(xy, width, height, isa,
                        (per_triangle.empty() || per_triangle.size() == xy.size() / 6) &&
                            counts.width() == width && counts.height() == height);
  if (r.status != BatchStatus::kOk)
    return r;
  return count_checked(xy, width, height, state, isa, per_triangle, counts.high(), counts.low());
}

// rule: FAST.BATCH.EQUALS.PLAIN, FAST.ISA.DISPATCH
FastBatchResult fast_runs_batch(std::span<const float> xy, std::int32_t width, std::int32_t height,
                                const RasterState& state, Isa isa, const RunSink& sink) {
  FastBatchResult r;
  r.status = check_call(xy, width, height, isa, sink.run != nullptr);
  if (r.status != BatchStatus::kOk)
    return r;
  const std::size_t n = xy.size() / 6;
  const Context c{xy, width, height, state, isa, {}, {}};
#if RASTRULES_FAST_X86
  if (isa != Isa::kScalar) {
    batch_detail::Params p = lane_params(width, height, state);
    // Room for the runs of one chunk (a call with few triangles, as a thread's unit of a
    // render, allocates for those alone, and nothing is written before the unit writes it).
    const auto runs = std::make_unique_for_overwrite<batch_detail::Run[]>(
        std::min(n, kChunk) * batch_detail::kMaxRunsPerSmall);
    p.runs = runs.get();
    std::array<std::uint32_t, kChunk> large;
    for (std::size_t base = 0; base < n; base += kChunk) {
      p.xy = xy.data() + 6 * base;
      p.n = std::min(kChunk, n - base);
      p.tri_base = base;
      batch_detail::Out o;
      const std::size_t k = small_batch(isa, p, o, large.data());
      r.covered += o.covered;
      r.rasterized += o.rasterized;
      r.small += o.small;
      // The small triangles' runs (in triangle order) and the large triangles (listed in
      // increasing order), merged by triangle index. A large triangle's index never holds runs.
      std::size_t ri = 0;
      for (std::size_t j = 0; j <= k; ++j) {
        const std::size_t until = j < k ? base + large[j] : base + p.n;
        const std::size_t from = ri;
        while (ri < o.runs && runs[ri].tri < until)
          ++ri;
        if (sink.runs != nullptr && ri > from)
          sink.runs(sink.context, runs.get() + from, ri - from);
        else
          for (std::size_t q = from; q < ri; ++q)
            sink.run(sink.context, runs[q].tri, runs[q].y, runs[q].x, runs[q].n);
        if (j < k && !one_triangle_runs(c, base + large[j], sink, r))
          return r; // cannot fail: all snapped
      }
      if (o.bad != static_cast<std::size_t>(-1)) {
        // The lanes reject exactly what snap_to_subpixel rejects (FAST.BATCH.SNAP_SIMD): the
        // plain way fails on the same triangle and says which coordinate and why.
        (void)one_triangle_runs(c, base + o.bad, sink, r);
        return r;
      }
    }
    return r;
  }
#endif
  for (std::size_t i = 0; i < n; ++i)
    if (!one_triangle_runs(c, i, sink, r))
      return r;
  return r;
}

// rule: FAST.BATCH.EQUALS.PLAIN
FastBatchResult fast_runs_rows(std::span<const float> xy, std::size_t tri, std::int32_t width,
                               std::int32_t height, const RasterState& state, Isa isa,
                               std::int32_t y_first, std::int32_t y_last, const RunSink& sink) {
  FastBatchResult r;
  r.status = check_call(xy, width, height, isa, sink.run != nullptr && tri < xy.size() / 6);
  if (r.status != BatchStatus::kOk)
    return r;
  const Context c{xy, width, height, state, isa, {}, {}};
  (void)one_triangle_runs(c, tri, sink, r, y_first, y_last); // r says why it failed
  return r;
}

} // namespace rastrules::raster
