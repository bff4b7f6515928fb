// SPDX-License-Identifier: MIT
// The batch counter's SIMD unit (kernel/src/fast_batch_avx2.cpp) as the proofs see it, and the
// obligations FAST.BATCH.SMALL_I32 and FAST.BATCH.SNAP_SIMD as templates over a model, so that
// the same theorems run against the kernel (batch_small_i32.cpp, batch_snap_simd.cpp) and
// against deliberately broken models (mutants.cpp).
//
// The SIMD unit is written in intrinsics on __m256i / __m256, so it cannot be instantiated on
// a symbolic type: its lines are restated here, each next to the intrinsic it mirrors, in the
// kernel's order. What is restated and how:
//   - int32 lane arithmetic (_mm256_add/sub/mullo_epi32, and _mm256_slli_epi32 by 8 and 3,
//     which is multiplication by 256 and 8 modulo 2^32) on Sym<int32_t>: an exact integer plus
//     the obligation "fits int32_t" for every result (support/sym.hpp). With every obligation
//     met, the lanes' wrapping arithmetic equals the exact integer arithmetic. That the shifts
//     are these multiplications, and _mm256_srai_epi32 by 8 a floor division by 256 (entered
//     as x == 256 q + r, 0 <= r < 256), is proved on 32-bit bit-vectors (`prove_lane_bits`);
//   - _mm256_min/max_epi32 and _mm256_cmpgt_epi32 are the signed min, max and > (Z3 ite and
//     comparisons: no obligation), blendv on all-ones/all-zero masks is a select;
//   - the inclusive mask of an edge (B5, against formula::is_inclusive_edge);
//   - the sign test `(l0 | l1 | l2) > -1`, the dead lanes' poison, the bias `inclusive ^ -1`
//     and the shifts, on 32-bit bit-vectors (`prove_lane_bits`);
//   - FAST.BATCH.SNAP_SIMD: _mm256_mul_ps(f, 256.0f) (rounded in the MXCSR's mode, any of the
//     five IEEE modes), _mm256_round_ps(.., _MM_FROUND_TO_NEAREST_INT) (roundToIntegral, ties
//     to even, whatever the MXCSR says), _CMP_GE_OQ / _CMP_LE_OQ (IEEE comparisons, false on
//     NaN) and _mm256_cvtps_epi32 (fp.to_sbv, in any rounding mode) in Z3's IEEE-754 theory on
//     float32; detail::scaled_magnitude_rne and snap_to_subpixel (rastrules/snap.hpp) line by
//     line on bit-vectors (uint32_t / uint64_t / int64_t arithmetic is bit-vector arithmetic),
//     that restatement first checked against the compiled functions
//     (`snap_model_matches_kernel`).
// Constants from the kernel's headers: kSubpixelOne, kSubpixelBits, kMinVertexRaw,
// kMaxVertexRaw, kMaxTargetSide (rastrules/fixed.hpp), the small span raster::kBatchSmallSpan
// (rastrules/raster/fast_batch.hpp). From the rule's text (FAST.BATCH.SMALL_I32): the
// magnitudes it states (2^14, 2^29, 2^30, 2^25; 64 x 64 pixels, 15 lanes past the last
// column): change the span and the proofs re-run against it, and fail where the stated
// magnitudes no longer hold. From the SIMD unit's text: 8 lanes a vector, cover_one for rows of
// up to 16 pixels (a low and a high half), cover_rows (chunks of 8) beyond, the poison -2^30.

#pragma once

#include <z3++.h>

#include <array>
#include <bit>
#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

#include "rastrules/fixed.hpp"
#include "rastrules/formula/edge.hpp"
#include "rastrules/raster/fast_batch.hpp"
#include "rastrules/snap.hpp"
#include "support/kernel_model.hpp"
#include "support/obligation.hpp"
#include "support/prover.hpp"
#include "support/sym.hpp"

namespace rastrules::proofs {

// ---------------------------------------------------------------------------------------------
// FAST.BATCH.SMALL_I32

struct BatchKernelModel : KernelModel {
  static constexpr const char* kName = "kernel";
  // The SIMD unit's lanes: int32_t.
  using Lane = Sym<std::int32_t>;
  // A triangle is small when its snapped spans (max - min over the three vertices) are below
  // this in x and in y (raster::kBatchSmallSpan, which fast_batch.cpp asserts is the SIMD
  // unit's kSmallSpan).
  static constexpr std::int64_t kSpan = raster::kBatchSmallSpan;
  // _mm256_srai_epi32(x, kShift) in the pixel bounds: a floor division by 2^kShift.
  static constexpr int kShift = kSubpixelBits;
  // Lanes a vector (__m256i of int32_t); cover() takes cover_one (a low and a high half of
  // eight lanes, pixels 0..15 of a row) for rows of up to kOneMaxCols pixels, cover_rows
  // (chunks of eight) beyond.
  static constexpr std::int64_t kHalfLanes = 8;
  static constexpr std::int64_t kOneMaxCols = 2 * kHalfLanes;
  // The value of edge 0 in cover_one's lanes at or past the row's last pixel (`poison`).
  static constexpr std::int64_t kPoison = -(std::int64_t{1} << 30);
  // Target sides 1..kMaxTargetSide (the batch counter rejects others: FAST.BATCH.EQUALS.PLAIN).
  static constexpr std::int64_t kMaxSide = kMaxTargetSide;
  // The magnitudes FAST.BATCH.SMALL_I32 states for a small triangle: vertex differences below
  // 2^14, twice the area below 2^29, E + bias in every lane below 2^30, 256 A, 256 B and
  // 8 x 256 A below 2^25; at most 64 x 64 pixels, and lanes reaching at most 15 pixels past
  // the last column.
  static constexpr int kDiffBits = 14;
  static constexpr int kAreaBits = 29;
  static constexpr int kLaneBits = 30;
  static constexpr int kStepBits = 25;
  static constexpr std::int64_t kMaxPixels = 64;
  static constexpr std::int64_t kPastColumns = 15;

  // The row loops' structure: false for the AVX2 unit's cover_one and cover_rows; true for
  // the AVX-512 unit's single loop (chunks of kHalfLanes lanes, the last one's lanes at or past
  // ncols masked off).
  static constexpr bool kChunkedRows = false;

  static std::vector<Constant> constants() {
    return kernel_constants_and({{"raster::kBatchSmallSpan", kSpan, Unit::kCoordRaw},
                                 {"cover_one's pixels a row", kOneMaxCols, Unit::kInteger},
                                 {"cover_one's poison", kPoison, Unit::kInteger}});
  }

  // The AVX-512 unit's count of lane m of chunk c (full = (ncols - 1) / 16 full chunks, then a
  // tail of rest = ncols - 16 full lanes in 1..16): every lane of a full chunk, and lanes
  // m < rest of the tail (the mask (1 << rest) - 1 of cover16).
  static z3::expr chunk_counted(const z3::expr& c, const z3::expr& full, const z3::expr& m,
                                const z3::expr& rest) {
    return c < full || (c == full && m < rest);
  }
};

// The AVX-512 unit (kernel/src/fast_batch_avx512.cpp, FAST.BATCH.LANES16): the same set-up
// (fast_batch_group.hpp), rows in chunks of sixteen lanes stepped by 16 x 256 A (below 2^26,
// computed as 16 * (256 A) in int32_t), the tail masked (no poison).
struct BatchLanes16Model : BatchKernelModel {
  static constexpr const char* kName = "kernel, rows in sixteen lanes";
  static constexpr std::int64_t kHalfLanes = 16;
  static constexpr int kStepBits = 26;
  static constexpr bool kChunkedRows = true;

  static std::vector<Constant> constants() {
    return kernel_constants_and({{"raster::kBatchSmallSpan", kSpan, Unit::kCoordRaw},
                                 {"cover16's lanes a chunk", kHalfLanes, Unit::kInteger}});
  }
};

// Returns |v| < 2^bits.
inline z3::expr below_pow2(const z3::expr& v, int bits) {
  const std::int64_t m = std::int64_t{1} << bits;
  return in_closed(v, -m + 1, m - 1);
}

// The signed min and max of two lanes (_mm256_min_epi32 / _mm256_max_epi32).
template <class L> L lane_min2(const L& a, const L& b) {
  return select(a < b, a, b);
}
template <class L> L lane_max2(const L& a, const L& b) {
  return select(a > b, a, b);
}

// The SIMD unit's setup of one lane (one triangle) up to the first sample point, in the
// kernel's order (run(), fast_batch_avx2.cpp), for model F: snapped vertices v (raw, in
// SNAP.VERTEX.RANGE), target width w and height h, then
//   minx, maxx, miny, maxy                  _mm256_min/max_epi32
//   spanx = maxx - minx, spany              _mm256_sub_epi32 (the small test's operands)
//   px0 = max((minx + 127) >> 8, 0)         add, srai (as qx0: 256 qx0 + r == minx + 127), max
//   px1 = min((maxx - 128) >> 8, w - 1)     sub, srai, min
//   ncols = px1 + 1 - px0, nrows            add, sub
//   sx = (px0 << 8) + 128, sy               slli (as * 256), add
// Every + - * is on Sym<int32_t>, so `obligations` lists "fits int32_t" for each.
template <class F> struct BatchSetup {
  using L = typename F::Lane;
  std::array<Point<L>, 3> v;
  L w;
  L h;
  L minx, maxx, miny, maxy;
  L spanx, spany;
  L px0, px1, py0, py1;
  L ncols, nrows;
  L sx, sy;
  std::vector<z3::expr> ranges; // SNAP.VERTEX.RANGE for the vertices, 1 <= w, h <= kMaxSide
  std::vector<z3::expr> shifts; // the four srai results, characterised
  z3::expr small;               // spanx < kSpan && spany < kSpan (_mm256_cmpgt_epi32)
  z3::expr nonempty;            // ncols > 0 && nrows > 0 (the lane is live)
  std::vector<Obligation> obligations;

  explicit BatchSetup(Domain& dom)
      : v{point_var<L>(dom, "v0"), point_var<L>(dom, "v1"), point_var<L>(dom, "v2")},
        w(dom.var<std::int32_t>("width", Unit::kInteger)),
        h(dom.var<std::int32_t>("height", Unit::kInteger)), minx(L(0)), maxx(L(0)), miny(L(0)),
        maxy(L(0)), spanx(L(0)), spany(L(0)), px0(L(0)), px1(L(0)), py0(L(0)), py1(L(0)),
        ncols(L(0)), nrows(L(0)), sx(L(0)), sy(L(0)), small(dom.ctx().bool_val(true)),
        nonempty(dom.ctx().bool_val(true)) {
    z3::context& ctx = dom.ctx();
    // Assumes: SNAP.VERTEX.RANGE; target sides in [1, kMaxTargetSide]
    for (const Point<L>& p : v)
      ranges.push_back(in_vertex_range<F>(p));
    ranges.push_back(in_closed(w.expr(), 1, F::kMaxSide));
    ranges.push_back(in_closed(h.expr(), 1, F::kMaxSide));
    const std::size_t mark = dom.mark();
    minx = lane_min2(lane_min2(v[0].x, v[1].x), v[2].x);
    maxx = lane_max2(lane_max2(v[0].x, v[1].x), v[2].x);
    miny = lane_min2(lane_min2(v[0].y, v[1].y), v[2].y);
    maxy = lane_max2(lane_max2(v[0].y, v[1].y), v[2].y);
    spanx = maxx - minx;
    spany = maxy - miny;
    const L span(F::kSpan);
    small = (spanx < span && spany < span).expr();
    const L zero(0);
    const auto srai = [&](const L& x, const std::string& name) {
      const L q = dom.var<std::int32_t>(name, Unit::kInteger);
      const z3::expr r = ctx.int_const((name + "_rem").c_str());
      const z3::expr d = ctx.int_val(std::int64_t{1} << F::kShift);
      shifts.push_back(x.expr() == d * q.expr() + r && 0 <= r && r < d);
      return q;
    };
    const L half_minus_1(kSubpixelHalf - 1);
    const L half(kSubpixelHalf);
    const L one(1);
    px0 = lane_max2(srai(minx + half_minus_1, "qx0"), zero);
    py0 = lane_max2(srai(miny + half_minus_1, "qy0"), zero);
    px1 = lane_min2(srai(maxx - half, "qx1"), w - one);
    py1 = lane_min2(srai(maxy - half, "qy1"), h - one);
    ncols = px1 + one - px0;
    nrows = py1 + one - py0;
    nonempty = (ncols > zero && nrows > zero).expr();
    const L pixel(std::int64_t{1} << F::kShift);
    sx = px0 * pixel + half;
    sy = py0 * pixel + half;
    obligations = dom.obligations_since(mark);
  }

  [[nodiscard]] std::vector<z3::expr> hyps() const {
    std::vector<z3::expr> all = ranges;
    all.insert(all.end(), shifts.begin(), shifts.end());
    return all;
  }
};

// How far a lane's sample point may lie from an edge's start a, per axis, for a small
// triangle (lemmas B3, B6): x in [-(kSpan - 1), kSpan - 1 + 256 kPastColumns], y in
// [-(kSpan - 1), kSpan - 1 + 256] (the row loops step once past the last row).
template <class F> std::int64_t reach_x() {
  return F::kSpan - 1 + F::kPastColumns * (std::int64_t{1} << F::kShift);
}
template <class F> std::int64_t reach_y() {
  return F::kSpan - 1 + (std::int64_t{1} << F::kShift);
}

// The inputs of one edge's theorems: endpoints a, b and the first sample point p (raw, lane
// type), with what lemma B3 shows for every edge of a small triangle, in either winding, and a
// point of its bounding box: |bx - ax|, |by - ay|, |px - ax|, |py - ay| < kSpan, all in
// SNAP.VERTEX.RANGE.
template <class F> struct EdgeInputs {
  using L = typename F::Lane;
  Point<L> a;
  Point<L> b;
  Point<L> p;
  std::vector<z3::expr> hyps;

  explicit EdgeInputs(Domain& dom)
      : a(point_var<L>(dom, "a")), b(point_var<L>(dom, "b")), p(point_var<L>(dom, "s")) {
    const std::int64_t s = F::kSpan - 1;
    hyps = {in_vertex_range<F>(a),
            in_vertex_range<F>(b),
            in_vertex_range<F>(p),
            in_closed(b.x.expr() - a.x.expr(), -s, s),
            in_closed(b.y.expr() - a.y.expr(), -s, s),
            in_closed(p.x.expr() - a.x.expr(), -s, s),
            in_closed(p.y.expr() - a.y.expr(), -s, s)};
  }
};

// The SIMD unit's setup of one edge (a, b) at the first sample point p (run():
// A = ay - by, B = bx - ax, e = B (sy - ay) + A (sx - ax) by mullo and add, g.e = e + bias,
// g.a = A << 8, g.b = B << 8) and the rows' chunk step a << 3 (cover_one's hi, cover_rows'
// step8), on the lane type, in the kernel's order.
template <class F> struct EdgeSetup {
  using L = typename F::Lane;
  L a_step; // A
  L b_step; // B
  L dy;     // sy - ay
  L dx;     // sx - ax
  L eb;     // E0 + bias
  L sa;     // 256 A: _mm256_slli_epi32(A, 8)
  L sb;     // 256 B: _mm256_slli_epi32(B, 8)
  L sa8;    // 8 x 256 A: _mm256_slli_epi32(a, 3)

  EdgeSetup(const EdgeInputs<F>& in, bool inclusive)
      : a_step(in.a.y - in.b.y), b_step(in.b.x - in.a.x), dy(in.p.y - in.a.y), dx(in.p.x - in.a.x),
        eb(b_step * dy + a_step * dx + F::template edge_bias<L>(inclusive)),
        sa(a_step * L(std::int64_t{1} << F::kShift)), sb(b_step * L(std::int64_t{1} << F::kShift)),
        sa8(sa * L(F::kHalfLanes)) {}
};

// Returns the int64_t value of a lane (widening is exact: no obligation).
template <class L> Sym<std::int64_t> widen(const L& v) {
  return Sym<std::int64_t>(v.domain(), v.expr(), v.text());
}

// Lemma P (proved first by prove_batch_small_i32): for all integers x, y, X, Y with
// |x| <= X and |y| <= Y, |x y| <= X Y. Returns its instance for the terms x, y and the
// constants X, Y, as an implication, to be added to a theorem's hypotheses: with it the
// solver needs only linear reasoning over the monomials of the edge values, where the products
// themselves make it time out.
inline z3::expr product_bound(const z3::expr& x, std::int64_t bx, const z3::expr& y,
                              std::int64_t by) {
  z3::context& ctx = x.ctx();
  const z3::expr xy = ctx.int_val(bx * by);
  return z3::implies(in_closed(x, -bx, bx) && in_closed(y, -by, by), -xy <= x * y && x * y <= xy);
}

// FAST.BATCH.SMALL_I32, in lemmas (each skipped, UNKNOWN, unless the lemmas it uses are PROVED):
//   P.  |x| <= X, |y| <= Y => |x y| <= X Y for all integers (B4, E1, E2 take instances of it
//       for their products as hypotheses);
//   B1. for every triangle in SNAP.VERTEX.RANGE and target sides in [1, kMaxTargetSide] (small
//       or not: the unit computes them for every lane): the spans, the pixel bounds, ncols,
//       nrows, sx and sy never leave int32_t (so the small test compares the true spans), and
//       px0 <= p <= px1 iff pixel p lies in [0, w - 1] with its centre 256 p + 128 in
//       [minx, maxx] (RASTER.WALK.BBOX, RASTER.TARGET.CLIP), the same in y;
//   B2. for a small triangle with a non-empty rect (ncols > 0, nrows > 0: the live lanes):
//       1 <= ncols, nrows <= 64; B2'. the first sample point (sx, sy) lies in the bounding box;
//   B3. for a small triangle, either winding (the unit swaps v1 and v2 when the area is
//       negative: a free Boolean here), every point p of its bounding box and every point q of
//       the box extended by kPastColumns pixels to the right and one row down: each of the
//       three edges (a, b) has |b - a| < kSpan and |p - a| < kSpan per axis, and q - a within
//       [-(kSpan - 1), reach_x] x [-(kSpan - 1), reach_y];
//   B4. for a small triangle: the vertex differences of the area fit int32_t and are below
//       2^kDiffBits, the two mullo products and their difference fit int32_t, |twice area| <
//       2^kAreaBits, and the lane's area equals formula::twice_signed_area on int64_t (so its
//       sign, which orients and culls, is the kernel's);
//   B5. the lane's inclusive mask (horizontal = ay == by; h_ok, v_ok by the two flags; blendv)
//       is formula::is_inclusive_edge under each of the four fill conventions;
//   B6. the row loops of a small live triangle: cover_one (ncols <= 16) computes lanes
//       i = 0..15, cover_rows (ncols > 16; full = ncols / 8, rest = ncols % 8) lanes
//       i = 8 c + m, 0 <= c <= full, 0 <= m < 8, both for rows j = 0..nrows (the last a step
//       past the last row); every such lane's sample point (sx + 256 i, sy + 256 j) lies in
//       B3's extended box, and a lane is counted (cover_one: not poisoned, the high half only
//       when ncols > 8; cover_rows: a full chunk, or the tail with m < rest) iff i < ncols, and
//       every pixel i < ncols is among the lanes;
//   E1. for every edge (a, b) and point p as B3 gives (EdgeInputs), each bias 0 / -1: A, B,
//       sy - ay, sx - ax fit int32_t below 2^kDiffBits; B (sy - ay) and A (sx - ax), their sum
//       E0 and E0 + bias fit int32_t, |E0 + bias| < 2^kLaneBits; 256 A, 256 B and 8 x 256 A
//       fit, below 2^kStepBits; and E0 + bias == formula::edge_value(a, b, p) +
//       formula::edge_bias on int64_t;
//   E2. the same edge, every lane i = 8 c + m (c >= 0, 0 <= m < 8) and row j >= 0 whose sample
//       point q = p + 256 (i, j) lies in B3's reach of a: the loops' value
//       E0 + bias + m (256 A) [mullo(iota, a), add] + c (8 x 256 A) [c additions of slli(a, 3):
//       cover_one's high half is c = 1, cover_rows' chunks c = 0..full] + j (256 B) [j row
//       additions] fits int32_t, |value| < 2^kLaneBits, and equals edge_value(a, b, q) +
//       edge_bias on int64_t. Every partial sum of either loop is the value of a lane with a
//       smaller c or j, also in reach, so every addition of the loops fits.
// By B2', B3 and B6, (sx, sy), every edge of a live lane and every lane the loops compute
// satisfy E1's and E2's hypotheses.
// rule: FAST.BATCH.SMALL_I32
template <class F> void prove_batch_small_i32(Prover& pr) {
  using L = typename F::Lane;
  using S = typename F::Acc;
  Domain& dom = pr.domain();
  z3::context& ctx = pr.ctx();
  const BatchSetup<F> st(dom);
  const std::int64_t d = F::kSpan - 1; // the largest |difference| of a small triangle
  const std::int64_t one_px = std::int64_t{1} << F::kShift;

  // P.
  Status lemma_p = Status::kUnknown;
  {
    const z3::expr x = ctx.int_const("P_x");
    const z3::expr y = ctx.int_const("P_y");
    const z3::expr bx = ctx.int_const("P_X");
    const z3::expr by = ctx.int_const("P_Y");
    pr.watch("x y", x * y, Unit::kInteger);
    lemma_p =
        pr.prove("P: |x| <= X, |y| <= Y => |x y| <= X Y (integers)",
                 {-bx <= x, x <= bx, -by <= y, y <= by}, -(bx * by) <= x * y && x * y <= bx * by);
  }

  // B1.
  Status b1 = Status::kUnknown;
  {
    const z3::expr px = ctx.int_const("pixel_x");
    const z3::expr py = ctx.int_const("pixel_y");
    const z3::expr one = ctx.int_val(one_px);
    const z3::expr half = ctx.int_val(kSubpixelHalf);
    const z3::expr in_x = 0 <= px && px <= st.w.expr() - 1 && st.minx.expr() <= one * px + half &&
                          one * px + half <= st.maxx.expr();
    const z3::expr in_y = 0 <= py && py <= st.h.expr() - 1 && st.miny.expr() <= one * py + half &&
                          one * py + half <= st.maxy.expr();
    const z3::expr goal = in_x == (st.px0.expr() <= px && px <= st.px1.expr()) &&
                          in_y == (st.py0.expr() <= py && py <= st.py1.expr());
    pr.watch("px0", st.px0.expr(), Unit::kInteger);
    pr.watch("px1", st.px1.expr(), Unit::kInteger);
    pr.watch("py0", st.py0.expr(), Unit::kInteger);
    pr.watch("py1", st.py1.expr(), Unit::kInteger);
    b1 = pr.prove("B1: spans, pixel bounds, ncols, nrows, (sx, sy) fit int32_t for every "
                  "triangle; px0..px1 x py0..py1 are the target's pixels with centres in the box",
                  st.hyps(), goal, st.obligations);
  }

  // B2, B2'.
  Status b2 = Status::kUnknown;
  {
    std::vector<z3::expr> h = st.hyps();
    h.push_back(st.small);
    h.push_back(st.nonempty);
    pr.watch("ncols", st.ncols.expr(), Unit::kInteger);
    pr.watch("nrows", st.nrows.expr(), Unit::kInteger);
    pr.prove("B2: small and live: 1 <= ncols, nrows <= 64", h,
             in_closed(st.ncols.expr(), 1, F::kMaxPixels) &&
                 in_closed(st.nrows.expr(), 1, F::kMaxPixels));
    pr.watch("sx", st.sx.expr(), Unit::kCoordRaw);
    pr.watch("sy", st.sy.expr(), Unit::kCoordRaw);
    b2 = pr.prove("B2': small and live: minx <= sx <= maxx, miny <= sy <= maxy", h,
                  st.minx.expr() <= st.sx.expr() && st.sx.expr() <= st.maxx.expr() &&
                      st.miny.expr() <= st.sy.expr() && st.sy.expr() <= st.maxy.expr());
  }

  // B3.
  Status b3 = Status::kUnknown;
  {
    std::vector<z3::expr> h = st.ranges;
    h.push_back(st.small);
    const z3::expr ccw = dom.bool_var("ccw");
    const Point<L> p = point_var<L>(dom, "p");
    const Point<L> q = point_var<L>(dom, "q");
    h.push_back(st.minx.expr() <= p.x.expr() && p.x.expr() <= st.maxx.expr());
    h.push_back(st.miny.expr() <= p.y.expr() && p.y.expr() <= st.maxy.expr());
    h.push_back(st.minx.expr() <= q.x.expr() &&
                q.x.expr() <= st.maxx.expr() + ctx.int_val(F::kPastColumns * one_px));
    h.push_back(st.miny.expr() <= q.y.expr() && q.y.expr() <= st.maxy.expr() + ctx.int_val(one_px));
    // The winding swap (_mm256_blendv_epi8 on ccw): (v0, v2, v1) when ccw.
    const SymBool swap(ccw);
    const std::array<Point<L>, 3> t = {
        st.v[0], Point<L>{select(swap, st.v[2].x, st.v[1].x), select(swap, st.v[2].y, st.v[1].y)},
        Point<L>{select(swap, st.v[1].x, st.v[2].x), select(swap, st.v[1].y, st.v[2].y)}};
    z3::expr goal = ctx.bool_val(true);
    for (std::size_t k = 0; k < 3; ++k) {
      const Point<L>& a = t[k];
      const Point<L>& b = t[(k + 1) % 3];
      goal = goal && in_closed(b.x.expr() - a.x.expr(), -d, d) &&
             in_closed(b.y.expr() - a.y.expr(), -d, d) &&
             in_closed(p.x.expr() - a.x.expr(), -d, d) &&
             in_closed(p.y.expr() - a.y.expr(), -d, d) &&
             in_closed(q.x.expr() - a.x.expr(), -d, reach_x<F>()) &&
             in_closed(q.y.expr() - a.y.expr(), -d, reach_y<F>());
    }
    b3 = pr.prove("B3: small, either winding: every edge (a, b), box point p and extended-box "
                  "point q: |b - a|, |p - a| < span per axis, q - a within the lanes' reach",
                  h, goal);
  }

  // B4.
  if (lemma_p != Status::kProved) {
    pr.skip("B4: small: the area", "lemma P not proved");
  } else {
    std::vector<z3::expr> h = st.ranges;
    h.push_back(st.small);
    const std::size_t mark = dom.mark();
    const L d10x = st.v[1].x - st.v[0].x;
    const L d20y = st.v[2].y - st.v[0].y;
    const L d10y = st.v[1].y - st.v[0].y;
    const L d20x = st.v[2].x - st.v[0].x;
    const L area = d10x * d20y - d10y * d20x;
    std::vector<Obligation> obl = dom.obligations_since(mark);
    h.push_back(product_bound(d10x.expr(), d, d20y.expr(), d));
    h.push_back(product_bound(d10y.expr(), d, d20x.expr(), d));
    const Triangle<S> wide = {Point<S>{widen(st.v[0].x), widen(st.v[0].y)},
                              Point<S>{widen(st.v[1].x), widen(st.v[1].y)},
                              Point<S>{widen(st.v[2].x), widen(st.v[2].y)}};
    const S exact = F::twice_signed_area(wide);
    pr.watch("area (lanes)", area.expr(), Unit::kEdgeRaw);
    pr.prove("B4: small: the area's differences (< 2^" + std::to_string(F::kDiffBits) +
                 "), mullo products and difference fit int32_t, |area| < 2^" +
                 std::to_string(F::kAreaBits) + ", area == twice_signed_area (int64_t)",
             h,
             below_pow2(d10x.expr(), F::kDiffBits) && below_pow2(d20y.expr(), F::kDiffBits) &&
                 below_pow2(d10y.expr(), F::kDiffBits) && below_pow2(d20x.expr(), F::kDiffBits) &&
                 below_pow2(area.expr(), F::kAreaBits) && area.expr() == exact.expr(),
             obl);
  }

  // B5.
  {
    const Point<L> ea = point_var<L>(dom, "c");
    const Point<L> eb = point_var<L>(dom, "d");
    z3::expr goal = ctx.bool_val(true);
    for_each_convention([&]<bool Top, bool Left>(const char*) {
      // fast_batch_avx2.cpp: horizontal = cmpeq(ay, by); h_ok = top ? cmpgt(bx, ax) :
      // cmpgt(ax, bx); v_ok = left ? cmpgt(ay, by) : cmpgt(by, ay); blendv(v_ok, h_ok, horizontal)
      const z3::expr horizontal = ea.y.expr() == eb.y.expr();
      const z3::expr h_ok = Top ? eb.x.expr() > ea.x.expr() : ea.x.expr() > eb.x.expr();
      const z3::expr v_ok = Left ? ea.y.expr() > eb.y.expr() : eb.y.expr() > ea.y.expr();
      const z3::expr lane = z3::ite(horizontal, h_ok, v_ok);
      goal = goal && lane == F::template is_inclusive_edge<Top, Left>(ea, eb).expr();
    });
    pr.prove("B5: the lanes' inclusive mask is is_inclusive_edge under each fill convention",
             {in_vertex_range<F>(ea), in_vertex_range<F>(eb)}, goal);
  }

  // B6.
  Status b6 = Status::kProved;
  {
    const z3::expr j = ctx.int_const("row_j");
    const z3::expr c = ctx.int_const("chunk_c");
    const z3::expr m = ctx.int_const("lane_m");
    const z3::expr full = ctx.int_const("full");
    const z3::expr rest = ctx.int_const("rest");
    const z3::expr cols = st.ncols.expr();
    const z3::expr one = ctx.int_val(one_px);
    const auto reach = [&](const z3::expr& lane) {
      const z3::expr qx = st.sx.expr() + one * lane;
      const z3::expr qy = st.sy.expr() + one * j;
      return st.minx.expr() <= qx && qx <= st.maxx.expr() + ctx.int_val(F::kPastColumns * one_px) &&
             st.miny.expr() <= qy && qy <= st.maxy.expr() + one;
    };
    std::vector<z3::expr> base = st.hyps();
    base.push_back(st.small);
    base.push_back(st.nonempty);
    base.push_back(0 <= j && j <= st.nrows.expr());
    if constexpr (F::kChunkedRows) {
      // cover16: full = (cols - 1) / 16, rest = cols - 16 full in 1..16; lane i = 16 c + m for
      // chunks c = 0..full (the last the tail), counted iff F::chunk_counted.
      std::vector<z3::expr> h = base;
      const z3::expr lanes = ctx.int_val(F::kHalfLanes);
      h.push_back(cols == lanes * full + rest && 1 <= rest && rest <= lanes);
      h.push_back(0 <= c && c <= full);
      h.push_back(0 <= m && m < lanes);
      const z3::expr lane = lanes * c + m;
      const z3::expr counted = F::chunk_counted(c, full, m, rest);
      // The lanes are 0..16 full + 15: every pixel 0..cols - 1 is one of them.
      const z3::expr every_pixel = cols - 1 <= lanes * full + lanes - 1;
      pr.watch("ncols", cols, Unit::kInteger);
      pr.watch("lane", lane, Unit::kInteger);
      const Status s = pr.prove(
          "B6 (cover16): lanes 16 c + m, c = 0..(ncols - 1) / 16, of rows 0..nrows reach at most "
          "15 px past the box's right and 1 row below it; a lane is counted iff it is < ncols",
          h, reach(lane) && counted == (lane < cols) && every_pixel);
      if (s != Status::kProved)
        b6 = s;
    } else {
      {
        // cover_one: lanes lo = m (counted iff cols > m: live_lo, else poisoned) and
        // hi = 8 + m (counted iff kWide, cols > 8, and cols > m + 8: live_hi).
        std::vector<z3::expr> h = base;
        h.push_back(cols <= ctx.int_val(F::kOneMaxCols));
        h.push_back(0 <= m && m < ctx.int_val(F::kHalfLanes));
        const z3::expr eight = ctx.int_val(F::kHalfLanes);
        const z3::expr lo_counted = cols > m;
        const z3::expr hi_counted = cols > eight && cols > m + eight;
        // The lanes are 0..2 * 8 - 1: every pixel 0..cols - 1 is one of them.
        const z3::expr every_pixel = cols - 1 <= ctx.int_val(2 * F::kHalfLanes - 1);
        pr.watch("ncols", cols, Unit::kInteger);
        pr.watch("nrows", st.nrows.expr(), Unit::kInteger);
        const Status s = pr.prove(
            "B6 (cover_one): lanes 0..15 of rows 0..nrows reach at most 15 px past the box's right "
            "and 1 row below it; lane i is counted iff i < ncols; every pixel is a lane",
            h,
            reach(m) && reach(m + eight) && lo_counted == (m < cols) &&
                hi_counted == (m + eight < cols) && every_pixel);
        if (s != Status::kProved)
          b6 = s;
      }
      {
        // cover_rows: full = cols / 8, rest = cols % 8 (C++ division of a positive int);
        // lane i = 8 c + m for chunks c = 0..full (the last only stepped to, or the tail), counted
        // iff c < full, or c == full and m < rest (the tail mask).
        std::vector<z3::expr> h = base;
        h.push_back(cols > ctx.int_val(F::kOneMaxCols));
        h.push_back(cols == ctx.int_val(F::kHalfLanes) * full + rest && 0 <= rest &&
                    rest < ctx.int_val(F::kHalfLanes));
        h.push_back(0 <= c && c <= full);
        h.push_back(0 <= m && m < ctx.int_val(F::kHalfLanes));
        const z3::expr lane = ctx.int_val(F::kHalfLanes) * c + m;
        const z3::expr counted = c < full || (c == full && m < rest);
        // The lanes are 0..8 full + 7: every pixel 0..cols - 1 is one of them.
        const z3::expr every_pixel = cols - 1 <= ctx.int_val(F::kHalfLanes) * full + 7;
        pr.watch("ncols", cols, Unit::kInteger);
        pr.watch("lane", lane, Unit::kInteger);
        const Status s =
            pr.prove("B6 (cover_rows): lanes 8 c + m, c = 0..ncols / 8, of rows 0..nrows reach at "
                     "most 15 px past the box's right and 1 row below it; a lane is counted iff "
                     "it is < ncols",
                     h, reach(lane) && counted == (lane < cols) && every_pixel);
        if (s != Status::kProved)
          b6 = s;
      }
    }
  }

  const bool edges_ok = lemma_p == Status::kProved && b1 == Status::kProved &&
                        b2 == Status::kProved && b3 == Status::kProved && b6 == Status::kProved;
  const EdgeInputs<F> in(dom);
  const Point<S> wa{widen(in.a.x), widen(in.a.y)};
  const Point<S> wb{widen(in.b.x), widen(in.b.y)};

  // E1.
  for (const bool inclusive : {true, false}) {
    const std::string name =
        std::string("E1 (bias ") + (inclusive ? "0" : "-1") + "): A, B, s - a fit (< 2^" +
        std::to_string(F::kDiffBits) + "); E0 + bias fits (< 2^" + std::to_string(F::kLaneBits) +
        "); 256 A, 256 B, " + std::to_string(F::kHalfLanes) + " x 256 A fit (< 2^" +
        std::to_string(F::kStepBits) + "); E0 + bias == edge_value(a, b, s) + edge_bias (int64_t)";
    if (!edges_ok) {
      pr.skip(name, "lemma P, B1, B2', B3 or B6 not proved");
      continue;
    }
    const std::size_t mark = dom.mark();
    const EdgeSetup<F> es(in, inclusive);
    const std::vector<Obligation> obl = dom.obligations_since(mark);
    const S exact = F::edge_value(wa, wb, Point<S>{widen(in.p.x), widen(in.p.y)}) +
                    F::template edge_bias<S>(inclusive);
    std::vector<z3::expr> h = in.hyps;
    h.push_back(product_bound(es.b_step.expr(), d, es.dy.expr(), d));
    h.push_back(product_bound(es.a_step.expr(), d, es.dx.expr(), d));
    pr.watch("E0 + bias (lanes)", es.eb.expr(), Unit::kEdgeRaw);
    pr.watch("edge_value + bias (int64_t)", exact.expr(), Unit::kEdgeRaw);
    pr.prove(name, h,
             below_pow2(es.a_step.expr(), F::kDiffBits) &&
                 below_pow2(es.b_step.expr(), F::kDiffBits) &&
                 below_pow2(es.dx.expr(), F::kDiffBits) && below_pow2(es.dy.expr(), F::kDiffBits) &&
                 below_pow2(es.eb.expr(), F::kLaneBits) && below_pow2(es.sa.expr(), F::kStepBits) &&
                 below_pow2(es.sb.expr(), F::kStepBits) &&
                 below_pow2(es.sa8.expr(), F::kStepBits) && es.eb.expr() == exact.expr(),
             obl);
  }

  // E2.
  const L m = dom.var<std::int32_t>("m", Unit::kInteger);
  const L c = dom.var<std::int32_t>("c", Unit::kInteger);
  const L j = dom.var<std::int32_t>("j", Unit::kInteger);
  for (const bool inclusive : {true, false}) {
    const std::string name = std::string("E2 (bias ") + (inclusive ? "0" : "-1") +
                             "): every lane the row loops compute fits int32_t, |E + bias| < 2^" +
                             std::to_string(F::kLaneBits) +
                             ", == edge_value at (sx + 256 i, sy + 256 j) + edge_bias (int64_t)";
    if (!edges_ok) {
      pr.skip(name, "lemma P, B1, B2', B3 or B6 not proved");
      continue;
    }
    const z3::expr i = ctx.int_val(F::kHalfLanes) * c.expr() + m.expr();
    const z3::expr one = ctx.int_val(one_px);
    const z3::expr qdx = in.p.x.expr() + one * i - in.a.x.expr(); // qx - ax
    const z3::expr qdy = in.p.y.expr() + one * j.expr() - in.a.y.expr();
    std::vector<z3::expr> h = in.hyps;
    h.push_back(in_closed(m.expr(), 0, F::kHalfLanes - 1));
    h.push_back(0 <= c.expr());
    h.push_back(0 <= j.expr());
    h.push_back(in_closed(qdx, -d, reach_x<F>()));
    h.push_back(in_closed(qdy, -d, reach_y<F>()));
    const std::size_t mark = dom.mark();
    const EdgeSetup<F> es(in, inclusive);
    const L lo = es.eb + m * es.sa; // _mm256_add_epi32(e, _mm256_mullo_epi32(iota, a))
    // c additions of 8 x 256 A (cover_one's hi = lo + step, cover_rows' chunks), j additions
    // of 256 B (the rows): the value after them, which must fit.
    const z3::expr lane = lo.expr() + c.expr() * es.sa8.expr() + j.expr() * es.sb.expr();
    dom.require_fits<std::int32_t>(lane, "lane after c chunk and j row steps");
    const std::vector<Obligation> obl = dom.obligations_since(mark);
    const S px(one_px);
    const Point<S> q{widen(in.p.x) + px * S(dom, i, "i"), widen(in.p.y) + px * widen(j)};
    const S exact = F::edge_value(wa, wb, q) + F::template edge_bias<S>(inclusive);
    h.push_back(product_bound(es.b_step.expr(), d, es.dy.expr(), d));
    h.push_back(product_bound(es.a_step.expr(), d, es.dx.expr(), d));
    h.push_back(product_bound(es.a_step.expr(), d, qdx, reach_x<F>()));
    h.push_back(product_bound(es.b_step.expr(), d, qdy, reach_y<F>()));
    h.push_back(product_bound(m.expr(), F::kHalfLanes - 1, es.a_step.expr(), d));
    pr.watch("lane", lane, Unit::kEdgeRaw);
    pr.watch("edge_value + bias (int64_t)", exact.expr(), Unit::kEdgeRaw);
    pr.prove(name, h, below_pow2(lane, F::kLaneBits) && lane == exact.expr(), obl);
  }
}

// The obligation as its proof and the self-check run it.
inline const ProofObligation kBatchSmallI32{
    "fast/batch_small_i32", []<class F>(Prover& pr) { prove_batch_small_i32<F>(pr); }};

// The bit-level facts of the SIMD unit's lanes, on 32-bit bit-vectors (two's complement, as
// the intrinsics compute; z3's < and > on bit-vectors are signed):
//   1. the sign test: (l0 | l1 | l2) > -1 (_mm256_cmpgt_epi32 of the OR with minus1) iff
//      l0 >= 0 && l1 >= 0 && l2 >= 0;
//   2. a dead lane: edge 0 holds kPoison and steps by s & 0 (slo[0] & live_lo): after any
//      step it is still kPoison, and (kPoison | l1 | l2) > -1 is false for every l1, l2; a
//      live lane steps by s & -1 == s;
//   3. the bias: inclusive is a mask, 0 or -1 (_mm256_cmpgt_epi32 / blendv), and
//      inclusive ^ -1 is edge_bias(inclusive): 0 for -1, -1 for 0;
//   4. the shifts the integer model uses: _mm256_srai_epi32(x, 8) is floor(x / 256) for every
//      x (on 40 bits: x == 256 (x >> 8) + (x & 255)), and _mm256_slli_epi32(x, k) is x * 2^k
//      for every x with |x * 2^k| < 2^31 (k = 8: 256 A, 256 B, 256 px0 + ..; k = 3: 8 * 256 A).
// rule: FAST.BATCH.SMALL_I32
template <class F> void prove_lane_bits(Prover& pr) {
  z3::context& ctx = pr.ctx();
  const z3::expr l0 = ctx.bv_const("l0", 32);
  const z3::expr l1 = ctx.bv_const("l1", 32);
  const z3::expr l2 = ctx.bv_const("l2", 32);
  const z3::expr s = ctx.bv_const("step", 32);
  const z3::expr zero = ctx.bv_val(0, 32);
  const z3::expr minus1 = ctx.bv_val(-1, 32);
  pr.watch("l0", z3::bv2int(l0, true), Unit::kInteger);
  pr.watch("l1", z3::bv2int(l1, true), Unit::kInteger);
  pr.watch("l2", z3::bv2int(l2, true), Unit::kInteger);
  pr.prove("sign test: (l0 | l1 | l2) > -1 <=> l0 >= 0 && l1 >= 0 && l2 >= 0 (int32_t)", {},
           ((l0 | l1 | l2) > minus1) == (l0 >= zero && l1 >= zero && l2 >= zero));

  const z3::expr poison = ctx.bv_val(F::kPoison, 32);
  const z3::expr stepped = poison + (s & zero);
  pr.watch("poison after a step", z3::bv2int(stepped, true), Unit::kInteger);
  pr.watch("l1", z3::bv2int(l1, true), Unit::kInteger);
  pr.watch("l2", z3::bv2int(l2, true), Unit::kInteger);
  pr.prove("dead lane: poison + (s & 0) == poison, (poison | l1 | l2) > -1 is false; "
           "live lane: s & -1 == s",
           {}, stepped == poison && !((stepped | l1 | l2) > minus1) && (s & minus1) == s);

  const z3::expr mask = ctx.bv_const("inclusive_mask", 32);
  pr.watch("inclusive", z3::bv2int(mask, true), Unit::kInteger);
  const z3::expr bias_true = ctx.bv_val(formula::edge_bias<std::int64_t>(true), 32);
  const z3::expr bias_false = ctx.bv_val(formula::edge_bias<std::int64_t>(false), 32);
  pr.prove("bias: for a mask inclusive in {0, -1}, inclusive ^ -1 == edge_bias(inclusive == -1)",
           {mask == zero || mask == minus1},
           (mask ^ minus1) == z3::ite(mask == minus1, bias_true, bias_false));

  const z3::expr x = ctx.bv_const("x", 32);
  const z3::expr x40 = z3::sext(x, 8);
  const unsigned shift = static_cast<unsigned>(F::kShift);
  const z3::expr q40 = z3::sext(z3::ashr(x, ctx.bv_val(shift, 32)), 8);
  const z3::expr r40 = z3::zext(x & ctx.bv_val((1 << shift) - 1, 32), 8);
  pr.watch("x", z3::bv2int(x, true), Unit::kInteger);
  pr.prove("srai(x, 8) is floor(x / 256): x == 256 (x >> 8) + (x & 255), 0 <= x & 255 < 256 "
           "(40-bit, no wrap)",
           {}, x40 == q40 * ctx.bv_val(1 << shift, 40) + r40);
  for (const unsigned k : {shift, 3u}) {
    const z3::expr lim = ctx.bv_val(std::int64_t{1} << (31 - k), 40);
    pr.watch("x", z3::bv2int(x, true), Unit::kInteger);
    pr.prove("slli(x, " + std::to_string(k) + ") == x * 2^" + std::to_string(k) + " for |x| < 2^" +
                 std::to_string(31 - k) + " (40-bit, no wrap)",
             {-lim < x40, x40 < lim},
             z3::sext(z3::shl(x, ctx.bv_val(k, 32)), 8) ==
                 x40 * ctx.bv_val(std::int64_t{1} << k, 40));
  }
}

// The obligation as its proof and the self-check run it.
inline const ProofObligation kLaneBits{"fast/batch_small_i32 (lane bits)",
                                       []<class F>(Prover& pr) { prove_lane_bits<F>(pr); }};

// ---------------------------------------------------------------------------------------------
// FAST.BATCH.SNAP_SIMD

// The float32 snapping of the SIMD unit, and the kernel's integer snap restated on
// bit-vectors.
struct SnapKernelModel {
  static constexpr const char* kName = "kernel";
  // _mm256_round_ps(.., _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC): roundToIntegral, ties
  // to even, independent of the MXCSR.
  static z3::expr round_mode(z3::context& ctx) { return z3::expr(ctx, Z3_mk_fpa_rne(ctx)); }
  // The scale (a float literal 256.0f) and the accepted interval [lowest, highest] of the
  // rounded value (float literals of SNAP.VERTEX.RANGE's ends, exact in float).
  static constexpr float kScale = static_cast<float>(kSubpixelOne);
  static constexpr float kLowest = static_cast<float>(kMinVertexRaw);
  static constexpr float kHighest = static_cast<float>(kMaxVertexRaw);
  // The integer rule's range (SNAP.VERTEX.RANGE).
  static constexpr std::int64_t kMinRaw = kMinVertexRaw;
  static constexpr std::int64_t kMaxRaw = kMaxVertexRaw;

  static std::vector<Constant> constants() { return kernel_constants(); }

  // detail::scaled_magnitude_rne (rastrules/snap.hpp), line by line: bits a 32-bit bit-vector,
  // the uint64_t result a 64-bit one (C++ unsigned arithmetic is bit-vector arithmetic; the
  // shift counts are those of the C++, all below the width where they are used).
  static z3::expr scaled_magnitude_rne(const z3::expr& bits) {
    z3::context& ctx = bits.ctx();
    const auto u32 = [&](std::uint64_t v) { return ctx.bv_val(v, 32); };
    const auto u64 = [&](std::uint64_t v) { return ctx.bv_val(v, 64); };
    const z3::expr biased = z3::lshr(bits, u32(23)) & u32(0xFFu);
    const z3::expr mantissa = bits & u32(0x7FFFFFu);
    const z3::expr sig =
        z3::zext(z3::ite(biased != u32(0), mantissa | u32(0x800000u), mantissa), 32);
    // std::int32_t right = biased != 0 ? 142 - biased : 141 (two's complement, < and > signed)
    const z3::expr right = z3::ite(biased != u32(0), u32(142) - biased, u32(141));
    const z3::expr r64 = z3::zext(right, 32);
    const z3::expr lsb = z3::lshr(sig, r64) & u64(1);
    const z3::expr rounded = z3::lshr(sig + z3::shl(u64(1), r64 - u64(1)) - u64(1) + lsb, r64);
    return z3::ite(right < u32(0), z3::shl(u64(1), u64(24)),
                   z3::ite(right == u32(0), sig, z3::ite(right > u32(25), u64(0), rounded)));
  }

  // snap_to_subpixel (rastrules/snap.hpp): ok iff the biased exponent is not 255 and the signed
  // magnitude lies in [kMinRaw, kMaxRaw]; raw (int64_t, a 64-bit bit-vector) is the value.
  struct Snap {
    z3::expr ok;
    z3::expr raw;
  };
  template <class F> static Snap snap(const z3::expr& bits) {
    z3::context& ctx = bits.ctx();
    const z3::expr special =
        (z3::lshr(bits, ctx.bv_val(23, 32)) & ctx.bv_val(0xFFu, 32)) == ctx.bv_val(0xFFu, 32);
    const z3::expr mag = F::scaled_magnitude_rne(bits);
    const z3::expr raw =
        z3::ite(z3::lshr(bits, ctx.bv_val(31, 32)) != ctx.bv_val(0, 32), -mag, mag);
    const z3::expr ok =
        !special && ctx.bv_val(F::kMinRaw, 64) <= raw && raw <= ctx.bv_val(F::kMaxRaw, 64);
    return Snap{ok, raw};
  }
};

// The lane's computation on one float32 v (a bit pattern reinterpreted) for model F and
// product rounding mode rm: p = v * 256 (rounded in rm), r = roundToIntegral(F::round_mode, p),
// accept = r >= lowest && r <= highest (false for NaN), value = cvtps_epi32(r) (fp.to_sbv; the
// mode is irrelevant for an integral r, which theorem S3 shows).
struct LaneSnap {
  z3::expr v;
  z3::expr product;
  z3::expr rounded;
  z3::expr accept;
  z3::expr value; // 32-bit
};

inline z3::expr float32_of_bits(const z3::expr& bits) {
  z3::context& ctx = bits.ctx();
  const z3::sort f32 = ctx.fpa_sort(8, 24);
  return z3::expr(ctx, Z3_mk_fpa_to_fp_bv(ctx, bits, f32));
}

template <class F> LaneSnap lane_snap(const z3::expr& v, const z3::expr& rm) {
  z3::context& ctx = v.ctx();
  const z3::expr p(ctx, Z3_mk_fpa_mul(ctx, rm, v, ctx.fpa_val(F::kScale)));
  const z3::expr r(ctx, Z3_mk_fpa_round_to_integral(ctx, F::round_mode(ctx), p));
  const z3::expr ge(ctx, Z3_mk_fpa_geq(ctx, r, ctx.fpa_val(F::kLowest)));
  const z3::expr le(ctx, Z3_mk_fpa_leq(ctx, r, ctx.fpa_val(F::kHighest)));
  const z3::expr rtz(ctx, Z3_mk_fpa_rtz(ctx));
  const z3::expr value(ctx, Z3_mk_fpa_to_sbv(ctx, rtz, r, 32));
  return LaneSnap{v, p, r, ge && le, value};
}

// Returns false (after printing where) unless the bit-vector restatement of
// scaled_magnitude_rne and snap_to_subpixel agrees with the compiled functions: every biased
// exponent, both signs, and mantissas at and around the rounding boundaries (0, 1, the halves
// and their neighbours at every shift, all ones).
inline bool snap_model_matches_kernel() {
  z3::context ctx;
  const z3::expr probe = ctx.bv_const("bits", 32);
  z3::expr mag = SnapKernelModel::scaled_magnitude_rne(probe);
  const SnapKernelModel::Snap sn = SnapKernelModel::snap<SnapKernelModel>(probe);
  z3::expr ok_term = sn.ok;
  z3::expr raw_term = sn.raw;
  std::vector<std::uint32_t> mantissas = {0u, 1u, 2u, 3u, 0x7FFFFFu, 0x7FFFFEu, 0x400000u};
  for (unsigned k = 0; k < 23; ++k) {
    const std::uint32_t half = 1u << k;
    for (const std::uint32_t m : {half, half - 1u, half + 1u, 3u * half, (half << 1) - 1u})
      mantissas.push_back(m & 0x7FFFFFu);
  }
  std::size_t checked = 0;
  for (std::uint32_t sign = 0; sign < 2; ++sign) {
    for (std::uint32_t biased = 0; biased < 256; ++biased) {
      for (const std::uint32_t m : mantissas) {
        const std::uint32_t bits = (sign << 31) | (biased << 23) | m;
        z3::expr_vector from(ctx);
        z3::expr_vector to(ctx);
        from.push_back(probe);
        to.push_back(ctx.bv_val(bits, 32));
        const z3::expr ok = ok_term.substitute(from, to).simplify();
        const rastrules::SnapResult want = rastrules::snap_to_subpixel(std::bit_cast<float>(bits));
        bool same = ok.is_true() == (want.status == rastrules::SnapStatus::kOk);
        if (biased != 255) {
          std::uint64_t got = 0;
          same = same && mag.substitute(from, to).simplify().is_numeral_u64(got) &&
                 got == rastrules::detail::scaled_magnitude_rne(bits);
        }
        if (same && want.status == rastrules::SnapStatus::kOk) {
          std::uint64_t raw = 0;
          same = raw_term.substitute(from, to).simplify().is_numeral_u64(raw) &&
                 static_cast<std::int64_t>(raw) == std::int64_t{want.value.raw()};
        }
        if (!same) {
          std::cout << "restatement of scaled_magnitude_rne / snap_to_subpixel differs from the "
                       "kernel at bits 0x"
                    << std::hex << bits << std::dec << "\n";
          return false;
        }
        ++checked;
      }
    }
  }
  std::cout << "restatement of snap_to_subpixel checked against the compiled kernel on " << checked
            << " bit patterns\n";
  return true;
}

// FAST.BATCH.SNAP_SIMD. For every float32 bit pattern `bits` (v its value) and every rounding
// mode rm of the product (the MXCSR's: RNE, RNA, RTP, RTN, RTZ, a free variable of Z3's
// RoundingMode sort), with the lane's p, r, accept, value (lane_snap) and the kernel's snap
// (ok, raw) restated from snap.hpp, over the biased exponents [lo, hi] of a range:
//   S1. accept => v is finite, ok, and value == raw (so raw lies in SNAP.VERTEX.RANGE);
//   S2. ok => accept;
//   S3. accept => cvtps_epi32(r) == value in every rounding mode (a second free mode);
//   S4. the product is exact: if v * 256 rounded to nearest is finite, the product is the same
//       in every mode (so it is v * 2^8 exactly; an inexact product would differ between
//       towards +inf and towards -inf);
//   S5. DAZ / FTZ: a subnormal v (biased exponent 0) snaps to 0 in the kernel (ok, raw == 0),
//       and the lane accepts it with value 0 whether it takes v itself, or v replaced by the
//       zero of its sign (DAZ), or its product flushed to that zero (FTZ).
// S1..S3 run once per range of the biased exponent given (hypothesis lo <= biased <= hi); the
// ranges must together cover 0..255. One range 0..255 takes about a second (batch_snap_simd.cpp),
// the parameter is there in case a solver version needs the split.
// rule: FAST.BATCH.SNAP_SIMD
struct ExponentRange {
  unsigned lo;
  unsigned hi;
};

template <class F>
void prove_batch_snap_simd(Prover& pr, const std::vector<ExponentRange>& ranges) {
  z3::context& ctx = pr.ctx();
  pr.use_solver(Solver::kFloatingPoint);
  const z3::expr bits = ctx.bv_const("bits", 32);
  const z3::sort rm_sort(ctx, Z3_mk_fpa_rounding_mode_sort(ctx));
  const z3::expr rm = ctx.constant("rm", rm_sort);
  const z3::expr rm2 = ctx.constant("rm_cvt", rm_sort);
  const z3::expr v = float32_of_bits(bits);
  const LaneSnap lane = lane_snap<F>(v, rm);
  const SnapKernelModel::Snap kernel = SnapKernelModel::snap<F>(bits);
  const z3::expr biased = z3::lshr(bits, ctx.bv_val(23, 32)) & ctx.bv_val(0xFFu, 32);
  const z3::expr nan(ctx, Z3_mk_fpa_is_nan(ctx, v));
  const z3::expr inf(ctx, Z3_mk_fpa_is_infinite(ctx, v));
  const auto show = [&] {
    pr.watch("bits", bits, Unit::kInteger);
    pr.watch("v", v, Unit::kFloat);
    pr.watch("rm", rm, Unit::kInteger);
    pr.watch("v * 256 (rm)", lane.product, Unit::kFloat);
    pr.watch("r", lane.rounded, Unit::kFloat);
    pr.watch("accept", lane.accept, Unit::kBool);
    pr.watch("cvt(r)", z3::bv2int(lane.value, true), Unit::kCoordRaw);
    pr.watch("kernel ok", kernel.ok, Unit::kBool);
    pr.watch("kernel raw", z3::bv2int(kernel.raw, true), Unit::kCoordRaw);
  };
  for (const ExponentRange& er : ranges) {
    const std::string tag =
        " [biased exponent " + std::to_string(er.lo) + ".." + std::to_string(er.hi) + "]";
    const std::vector<z3::expr> h = {z3::uge(biased, ctx.bv_val(er.lo, 32)),
                                     z3::ule(biased, ctx.bv_val(er.hi, 32))};
    show();
    pr.prove("S1: accept => v finite, kernel ok, cvt(r) == kernel raw" + tag, h,
             z3::implies(lane.accept,
                         !nan && !inf && kernel.ok && z3::sext(lane.value, 32) == kernel.raw));
    show();
    pr.prove("S2: kernel ok => accept" + tag, h, z3::implies(kernel.ok, lane.accept));
    show();
    pr.watch("rm_cvt", rm2, Unit::kInteger);
    pr.watch("cvt(r) in rm_cvt",
             z3::bv2int(z3::expr(ctx, Z3_mk_fpa_to_sbv(ctx, rm2, lane.rounded, 32)), true),
             Unit::kCoordRaw);
    pr.prove("S3: accept => cvtps_epi32(r) is the same in every rounding mode" + tag, h,
             z3::implies(lane.accept, z3::expr(ctx, Z3_mk_fpa_to_sbv(ctx, rm2, lane.rounded, 32)) ==
                                          lane.value));
  }
  {
    const z3::expr rne(ctx, Z3_mk_fpa_rne(ctx));
    const z3::expr scale = ctx.fpa_val(F::kScale);
    const z3::expr p_rne(ctx, Z3_mk_fpa_mul(ctx, rne, v, scale));
    const z3::expr p_inf(ctx, Z3_mk_fpa_is_infinite(ctx, p_rne));
    const z3::expr p_nan(ctx, Z3_mk_fpa_is_nan(ctx, p_rne));
    show();
    pr.watch("v * 256 (RNE)", p_rne, Unit::kFloat);
    // Structural equality (the same float, signed zeros distinguished).
    pr.prove("S4: v * 256 finite (RNE) => the product is the same in every rounding mode (exact)",
             {!p_inf, !p_nan}, lane.product == p_rne);
  }
  {
    // The zero of v's sign: what DAZ makes of a subnormal input, and (the product of a
    // subnormal v has v's sign) what FTZ makes of a subnormal product.
    const z3::expr negative = z3::lshr(bits, ctx.bv_val(31, 32)) == ctx.bv_val(1, 32);
    const z3::expr signed_zero = z3::ite(negative, ctx.fpa_val(-0.0f), ctx.fpa_val(0.0f));
    const LaneSnap daz = lane_snap<F>(signed_zero, rm);
    const z3::expr r_ftz(ctx, Z3_mk_fpa_round_to_integral(ctx, F::round_mode(ctx), signed_zero));
    const z3::expr ftz_accept = z3::expr(ctx, Z3_mk_fpa_geq(ctx, r_ftz, ctx.fpa_val(F::kLowest))) &&
                                z3::expr(ctx, Z3_mk_fpa_leq(ctx, r_ftz, ctx.fpa_val(F::kHighest)));
    const z3::expr rtz(ctx, Z3_mk_fpa_rtz(ctx));
    const z3::expr ftz_value(ctx, Z3_mk_fpa_to_sbv(ctx, rtz, r_ftz, 32));
    const z3::expr zero32 = ctx.bv_val(0, 32);
    show();
    pr.watch("DAZ: r", daz.rounded, Unit::kFloat);
    pr.watch("FTZ: r", r_ftz, Unit::kFloat);
    pr.prove("S5: biased exponent 0 (zero, subnormal): kernel ok with raw 0; the lane accepts "
             "with value 0 on v, on v as zero (DAZ), with v * 256 flushed to zero (FTZ)",
             {biased == ctx.bv_val(0, 32)},
             kernel.ok && kernel.raw == ctx.bv_val(0, 64) && lane.accept && lane.value == zero32 &&
                 daz.accept && daz.value == zero32 && ftz_accept && ftz_value == zero32);
  }
}

// The obligation as its proof and the self-check run it: every biased exponent in one range.
inline const ProofObligation kBatchSnapSimd{"fast/batch_snap_simd", []<class F>(Prover& pr) {
                                              prove_batch_snap_simd<F>(pr, {{0, 255}});
                                            }};

} // namespace rastrules::proofs
