// SPDX-License-Identifier: MIT
// Properties: the batch counter (fast_count_batch) gives, for every instruction set this
// processor runs, each triangle's count and the per-pixel overdraw that the plain walk gives
// the triangle set up from its snapped vertices, on batches mixing small triangles (spans at
// and around the 64-pixel bound of the 32-bit lanes, vertices off the 1/256 grid and on ties
// of the snapping rule, clipped by the target's sides) with every shape of the fast
// traversal's properties; and it reports the same first coordinate that does not snap.
// Implements (properties for): FAST.BATCH.EQUALS.PLAIN, FAST.BATCH.SMALL_I32,
//   FAST.BATCH.SNAP_SIMD

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "fast_gen.hpp"
#include "rastrules/raster/fast_batch.hpp"
#include "rastrules/raster/walk.hpp"

namespace {

namespace fg = rastrules::fast_gen;
namespace mg = rastrules::msaa_gen;
namespace raster = rastrules::raster;
using rastrules::Isa;

// A coordinate from a raw 16.8 value: exactly raw / 256, or moved off the grid by a fraction
// of a unit (ties of round-half-to-even, just below and above them, tiny offsets).
rc::Gen<float> coordinate(std::int64_t raw) {
  return rc::gen::weightedOneOf<float>(
      {{3, rc::gen::just(static_cast<float>(static_cast<double>(raw) / 256.0))},
       {2, rc::gen::map(rc::gen::element(0.5, -0.5, 0.499, 0.501, 0.25, -0.75, 1e-3, -1e-3),
                        [raw](double f) {
                          // at the range's ends, only moves that still snap
                          const auto v = static_cast<float>((static_cast<double>(raw) + f) / 256.0);
                          return rastrules::snap_to_subpixel(v).status == rastrules::SnapStatus::kOk
                                     ? v
                                     : static_cast<float>(static_cast<double>(raw) / 256.0);
                        })}});
}

// A small triangle: vertices within `span` raw units of a point near the w x h target, with
// the spans 16383 and 16384 (the 32-bit lanes' bound, FAST.BATCH.SMALL_I32) and the row
// lengths 8 and 16 px (where the lanes change form) made likely.
rc::Gen<fg::RawTri> small_triangle(std::int32_t w, std::int32_t h) {
  return rc::gen::exec([=] {
    const std::int64_t s =
        *rc::gen::element<std::int64_t>(16383, 16384, 16385, 8000, 4096, 2048, 1024, 600, 64, 3);
    const std::int64_t x = *fg::near_raw(w, 18), y = *fg::near_raw(h, 18);
    fg::RawTri t;
    for (auto& p : t)
      p = {x + *rc::gen::inRange<std::int64_t>(-s, s + 1),
           y + *rc::gen::inRange<std::int64_t>(-s, s + 1)};
    if (*rc::gen::arbitrary<bool>())
      t[1][0] = t[0][0] + s; // the span exactly s
    if (*rc::gen::arbitrary<bool>())
      t[2][1] = t[0][1] - s;
    if (*rc::gen::inRange(0, 4) == 0)
      t[1][1] = t[0][1]; // a horizontal edge
    if (*rc::gen::inRange(0, 4) == 0)
      t[2][0] = t[1][0]; // a vertical edge
    for (auto& p : t)
      p = {fg::clamp_raw(p[0]), fg::clamp_raw(p[1])};
    return t;
  });
}

struct Batch {
  std::int32_t w = 1, h = 1;
  std::vector<float> xy;
};

rc::Gen<Batch> batch() {
  return mg::full_size<Batch>(rc::gen::exec([] {
    Batch b;
    b.w = *rc::gen::weightedOneOf<std::int32_t>(
        {{3, rc::gen::inRange<std::int32_t>(1, 70)}, {1, rc::gen::inRange<std::int32_t>(70, 200)}});
    b.h = *rc::gen::weightedOneOf<std::int32_t>(
        {{3, rc::gen::inRange<std::int32_t>(1, 70)}, {1, rc::gen::inRange<std::int32_t>(70, 200)}});
    const auto n = *rc::gen::inRange<std::size_t>(1, 41);
    for (std::size_t i = 0; i < n; ++i) {
      const fg::RawTri t = *rc::gen::weightedOneOf<fg::RawTri>(
          {{4, small_triangle(b.w, b.h)},
           {1, rc::gen::map(fg::triangle(b.w, b.h), [](const fg::GenTri& g) { return g.v; })}});
      for (const auto& p : t) {
        b.xy.push_back(*coordinate(p[0]));
        b.xy.push_back(*coordinate(p[1]));
      }
    }
    return b;
  }));
}

using Run = std::array<std::int64_t, 4>; // triangle, y, x, n

struct Expected {
  std::vector<std::uint64_t> per_triangle;
  std::vector<std::uint32_t> hits;
  std::uint64_t covered = 0, rasterized = 0;
  // The plain walk's pixels grouped into maximal runs of consecutive x in a row, in its order.
  std::vector<Run> runs;
};

// The plain way, triangle by triangle: snap_to_subpixel, setup_triangle, walk_triangle.
Expected plain(const Batch& b, const rastrules::RasterState& state) {
  Expected e;
  e.hits.assign(static_cast<std::size_t>(b.w) * static_cast<std::size_t>(b.h), 0);
  for (std::size_t i = 0; i < b.xy.size() / 6; ++i) {
    std::array<rastrules::Vec2, 3> v;
    for (std::size_t k = 0; k < 3; ++k) {
      const auto x = rastrules::snap_to_subpixel(b.xy[6 * i + 2 * k]);
      const auto y = rastrules::snap_to_subpixel(b.xy[6 * i + 2 * k + 1]);
      RC_ASSERT(x.status == rastrules::SnapStatus::kOk);
      RC_ASSERT(y.status == rastrules::SnapStatus::kOk);
      v[k] = rastrules::Vec2{x.value, y.value};
    }
    const rastrules::TriangleSetup t = rastrules::setup_triangle(v, state);
    if (t.status == rastrules::TriangleStatus::kRasterized)
      ++e.rasterized;
    std::uint64_t n = 0;
    const auto tri = static_cast<std::int64_t>(i);
    raster::walk_triangle(t, b.w, b.h, [&](std::int32_t x, std::int32_t y) {
      ++e.hits[static_cast<std::size_t>(y) * static_cast<std::size_t>(b.w) +
               static_cast<std::size_t>(x)];
      ++n;
      if (!e.runs.empty() && e.runs.back()[0] == tri && e.runs.back()[1] == y &&
          e.runs.back()[2] + e.runs.back()[3] == x)
        ++e.runs.back()[3];
      else
        e.runs.push_back(Run{tri, y, x, 1});
    });
    e.per_triangle.push_back(n);
    e.covered += n;
  }
  return e;
}

// rule: FAST.BATCH.EQUALS.PLAIN, FAST.BATCH.SMALL_I32, FAST.BATCH.SNAP_SIMD, FAST.ISA.DISPATCH
RC_GTEST_PROP(FastBatch, EveryIsaCountsEachTrianglesPlainPixels, ()) {
  const Batch b = *batch();
  const rastrules::RasterState state = *rastrules::gen::raster_state();
  const Expected e = plain(b, state);
  const std::size_t n = b.xy.size() / 6;
  for (Isa isa : fg::supported_isas()) {
    std::vector<std::uint64_t> per(n, 99);
    std::vector<std::uint32_t> hits(e.hits.size(), 0);
    const raster::FastBatchResult r =
        raster::fast_count_batch(b.xy, b.w, b.h, state, isa, per, hits);
    RC_ASSERT(r.status == raster::BatchStatus::kOk);
    RC_CLASSIFY(r.small > 0 && r.small < n, "small and large triangles");
    for (std::size_t i = 0; i < n; ++i) {
      if (per[i] != e.per_triangle[i]) {
        std::string tri;
        for (int k = 0; k < 6; ++k)
          tri += " " + std::to_string(b.xy[6 * i + static_cast<std::size_t>(k)]);
        RC_FAIL(std::string(rastrules::to_string(isa)) + ": triangle " + std::to_string(i) +
                " counts " + std::to_string(per[i]) + ", plain " +
                std::to_string(e.per_triangle[i]) + " on " + std::to_string(b.w) + " x " +
                std::to_string(b.h) + ":" + tri);
      }
    }
    RC_ASSERT(hits == e.hits);
    RC_ASSERT(r.covered == e.covered);
    RC_ASSERT(r.rasterized == e.rasterized);
    // Without outputs: the same totals.
    const raster::FastBatchResult bare = raster::fast_count_batch(b.xy, b.w, b.h, state, isa);
    RC_ASSERT(bare.covered == e.covered);
    RC_ASSERT(bare.rasterized == e.rasterized);
  }
}

// rule: FAST.BATCH.PIXEL_COUNTS, FAST.BATCH.EQUALS.PLAIN, FAST.ISA.DISPATCH
// The per-pixel counts past a byte: a batch drawn 128 to 600 times over (so that a pixel
// covered once a copy passes 254, and pixels covered by several triangles pass it several
// times), given to fast_count_batch in random chunks that share one PixelCounts (render
// --count's chunks) and, once, with 32-bit counts that start non-zero: every count is the
// copies times the plain count, on every instruction set.
RC_GTEST_PROP(FastBatch, EveryIsaKeepsCountsPastAByteExact, ()) {
  const Batch b = *batch();
  const rastrules::RasterState state = *rastrules::gen::raster_state();
  const Expected e = plain(b, state);
  const auto copies = *rc::gen::element<std::size_t>(128, 254, 255, 256, 300, 509, 510, 600);
  std::vector<float> xy;
  for (std::size_t c = 0; c < copies; ++c)
    xy.insert(xy.end(), b.xy.begin(), b.xy.end());
  const std::size_t n = xy.size() / 6;
  const auto chunk = *rc::gen::inRange<std::size_t>(1, n + 1);
  std::uint32_t most = 0;
  for (const std::uint32_t h : e.hits)
    most = std::max(most, h);
  RC_CLASSIFY(most * copies >= 255, "a count past 254");
  RC_CLASSIFY(most * copies >= 510, "a count past 509");
  for (Isa isa : fg::supported_isas()) {
    raster::PixelCounts counts(b.w, b.h);
    std::uint64_t covered = 0;
    for (std::size_t first = 0; first < n; first += chunk) {
      const std::size_t m = std::min(chunk, n - first);
      std::vector<std::uint64_t> per(m, 99);
      const raster::FastBatchResult r = raster::fast_count_batch(
          std::span(xy).subspan(6 * first, 6 * m), b.w, b.h, state, isa, per, counts);
      RC_ASSERT(r.status == raster::BatchStatus::kOk);
      for (std::size_t i = 0; i < m; ++i)
        RC_ASSERT(per[i] == e.per_triangle[(first + i) % e.per_triangle.size()]);
      covered += r.covered;
    }
    RC_ASSERT(covered == e.covered * copies);
    std::vector<std::uint32_t> wide(e.hits.size());
    for (std::size_t i = 0; i < wide.size(); ++i)
      wide[i] = static_cast<std::uint32_t>(i % 7);
    const raster::FastBatchResult r = raster::fast_count_batch(xy, b.w, b.h, state, isa, {}, wide);
    RC_ASSERT(r.status == raster::BatchStatus::kOk);
    for (std::size_t i = 0; i < e.hits.size(); ++i) {
      const auto want = static_cast<std::uint32_t>(e.hits[i] * copies);
      if (counts[i] != want || wide[i] != want + i % 7)
        RC_FAIL(std::string(rastrules::to_string(isa)) + ": pixel " + std::to_string(i) +
                " counts " + std::to_string(counts[i]) + " and " + std::to_string(wide[i]) + " - " +
                std::to_string(i % 7) + ", plain " + std::to_string(want));
    }
  }
}

// The runs fast_runs_batch sends, in the order it sends them.
std::vector<Run> runs_of(const Batch& b, const rastrules::RasterState& state, Isa isa,
                         raster::FastBatchResult& r) {
  std::vector<Run> got;
  const raster::RunSink sink{
      &got, [](void* c, std::uint32_t tri, std::int32_t y, std::int32_t x, std::int32_t n) {
        static_cast<std::vector<Run>*>(c)->push_back(Run{tri, y, x, n});
      }};
  r = raster::fast_runs_batch(b.xy, b.w, b.h, state, isa, sink);
  // With the batch callback set too: the same runs in the same order, the same result.
  std::vector<Run> both;
  const raster::RunSink batched{
      &both,
      [](void* c, std::uint32_t tri, std::int32_t y, std::int32_t x, std::int32_t n) {
        static_cast<std::vector<Run>*>(c)->push_back(Run{tri, y, x, n});
      },
      [](void* c, const raster::BatchRun* runs, std::size_t n) {
        RC_ASSERT(n > 0);
        for (std::size_t i = 0; i < n; ++i)
          static_cast<std::vector<Run>*>(c)->push_back(
              Run{runs[i].tri, runs[i].y, runs[i].x, runs[i].n});
      }};
  const raster::FastBatchResult rb = raster::fast_runs_batch(b.xy, b.w, b.h, state, isa, batched);
  RC_ASSERT(rb.status == r.status);
  RC_ASSERT(rb.covered == r.covered);
  if (r.status == raster::BatchStatus::kOk)
    RC_ASSERT(both == got);
  return got;
}

// rule: FAST.BATCH.EQUALS.PLAIN, FAST.BATCH.SMALL_I32, FAST.ISA.DISPATCH
// The runs are the plain walk's pixels, triangle by triangle in order, a row's pixels in one
// run (the small triangles' rows come from the lanes' masks: consecutive bits, one run a row).
RC_GTEST_PROP(FastBatch, EveryIsaSendsEachTrianglesPlainPixelsAsRuns, ()) {
  const Batch b = *batch();
  const rastrules::RasterState state = *rastrules::gen::raster_state();
  const Expected e = plain(b, state);
  for (Isa isa : fg::supported_isas()) {
    raster::FastBatchResult r;
    const std::vector<Run> got = runs_of(b, state, isa, r);
    RC_ASSERT(r.status == raster::BatchStatus::kOk);
    RC_CLASSIFY(r.small > 0 && r.small < b.xy.size() / 6, "small and large triangles");
    if (got != e.runs) {
      std::size_t k = 0;
      while (k < got.size() && k < e.runs.size() && got[k] == e.runs[k])
        ++k;
      const auto show = [](const std::vector<Run>& v, std::size_t at) {
        if (at >= v.size())
          return std::string("none");
        return "(" + std::to_string(v[at][0]) + ", y " + std::to_string(v[at][1]) + ", x " +
               std::to_string(v[at][2]) + ", n " + std::to_string(v[at][3]) + ")";
      };
      RC_FAIL(std::string(rastrules::to_string(isa)) + ": run " + std::to_string(k) + " is " +
              show(got, k) + ", plain " + show(e.runs, k));
    }
    RC_ASSERT(r.covered == e.covered);
    RC_ASSERT(r.rasterized == e.rasterized);
  }
}

// rule: FAST.BATCH.EQUALS.PLAIN, FAST.ISA.DISPATCH
// Each triangle's runs drawn in bands of rows (fast_runs_rows, random band heights, bands that
// start above the target and end below it) and joined in band order are its runs from
// fast_runs_batch, with the same counts.
RC_GTEST_PROP(FastBatch, EveryIsaSendsATrianglesRowsInBandsAsItsRuns, ()) {
  const Batch b = *batch();
  const rastrules::RasterState state = *rastrules::gen::raster_state();
  const Expected e = plain(b, state);
  const auto band = *rc::gen::inRange<std::int32_t>(1, 40);
  const auto start = *rc::gen::inRange<std::int32_t>(-5, 1);
  RC_CLASSIFY(band < 16, "bands thinner than a tile");
  for (Isa isa : fg::supported_isas()) {
    std::vector<Run> got;
    const raster::RunSink sink{
        &got, [](void* c, std::uint32_t tri, std::int32_t y, std::int32_t x, std::int32_t n) {
          static_cast<std::vector<Run>*>(c)->push_back(Run{tri, y, x, n});
        }};
    std::uint64_t covered = 0, rasterized = 0;
    for (std::size_t i = 0; i < b.xy.size() / 6; ++i) {
      std::uint64_t tri_rasterized = 0;
      for (std::int32_t y = start; y < b.h + 3; y += band) {
        const raster::FastBatchResult r =
            raster::fast_runs_rows(b.xy, i, b.w, b.h, state, isa, y, y + band - 1, sink);
        RC_ASSERT(r.status == raster::BatchStatus::kOk);
        covered += r.covered;
        tri_rasterized = std::max(tri_rasterized, r.rasterized);
      }
      rasterized += tri_rasterized;
    }
    RC_ASSERT(got == e.runs);
    RC_ASSERT(covered == e.covered);
    RC_ASSERT(rasterized == e.rasterized);
  }
  // A triangle index past the end is a length error.
  const raster::RunSink none{nullptr, [](void*, std::uint32_t, std::int32_t, std::int32_t,
                                         std::int32_t) { RC_FAIL("a run of no triangle"); }};
  RC_ASSERT(
      raster::fast_runs_rows(b.xy, b.xy.size() / 6, b.w, b.h, state, Isa::kScalar, 0, b.h, none)
          .status == raster::BatchStatus::kBadLength);
}

// rule: FAST.BATCH.SNAP_SIMD, SNAP.VERTEX.INVALID, FAST.ISA.DISPATCH
RC_GTEST_PROP(FastBatch, EveryIsaNamesTheFirstCoordinateThatDoesNotSnap, ()) {
  Batch b = *batch();
  const float inf = std::numeric_limits<float>::infinity();
  const auto bad = *rc::gen::inRange<std::size_t>(1, 4);
  for (std::size_t k = 0; k < bad; ++k) {
    const auto at = *rc::gen::inRange<std::size_t>(0, b.xy.size());
    b.xy[at] = *rc::gen::element(std::numeric_limits<float>::quiet_NaN(), inf, -inf, 32768.0f,
                                 -32768.00390625f, -32768.0020f, 32767.998f, 1e30f, -1e38f);
  }
  // The first coordinate that does not snap, in order, and why.
  std::size_t first = b.xy.size();
  rastrules::SnapStatus why = rastrules::SnapStatus::kOk;
  for (std::size_t i = 0; i < b.xy.size(); ++i) {
    const auto s = rastrules::snap_to_subpixel(b.xy[i]);
    if (s.status != rastrules::SnapStatus::kOk) {
      first = i;
      why = s.status;
      break;
    }
  }
  RC_CLASSIFY(first == b.xy.size(), "every coordinate snaps");
  for (Isa isa : fg::supported_isas()) {
    const raster::FastBatchResult r =
        raster::fast_count_batch(b.xy, b.w, b.h, rastrules::RasterState{}, isa);
    if (first == b.xy.size()) {
      RC_ASSERT(r.status == raster::BatchStatus::kOk);
      continue;
    }
    RC_ASSERT(r.status == raster::BatchStatus::kBadVertex);
    RC_ASSERT(r.bad_triangle == first / 6);
    RC_ASSERT(r.bad_vertex == static_cast<int>((first % 6) / 2));
    RC_ASSERT(r.bad_axis == (first % 2 == 0 ? 'x' : 'y'));
    RC_ASSERT(r.bad_snap == why);
    // The runs form reports the same coordinate.
    raster::FastBatchResult rr;
    (void)runs_of(b, rastrules::RasterState{}, isa, rr);
    RC_ASSERT(rr.status == raster::BatchStatus::kBadVertex);
    RC_ASSERT(rr.bad_triangle == r.bad_triangle);
    RC_ASSERT(rr.bad_vertex == r.bad_vertex);
    RC_ASSERT(rr.bad_axis == r.bad_axis);
    RC_ASSERT(rr.bad_snap == r.bad_snap);
  }
}

} // namespace
