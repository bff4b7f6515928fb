// SPDX-License-Identifier: MIT
// The fast traversal's lane arithmetic as the proofs see it, and the obligations FAST.LANE.I32
// and FAST.TILE.CLASSIFY as templates over a model, so that the same theorems run against the
// kernel (lane_budget.cpp, lane_equivalence.cpp, tile_classify.cpp) and against deliberately
// broken models (mutants.cpp).
//
// FastKernelModel = KernelModel (support/kernel_model.hpp: the kernel's formula::edge_value,
// edge_bias, edge_step_x/y on Sym<int64_t>) plus:
//   - the lane formulas of rastrules/formula/lane.hpp (lane_offset, lane_threshold, lane_max,
//     lane_min), instantiated on Sym with `select` as a Z3 if-then-else;
//   - the constants kFastTileSize (rastrules/raster/fast.hpp), kLaneBound (formula/lane.hpp),
//     kSubpixelOne and the vertex range (rastrules/fixed.hpp): nothing retyped;
//   - one restated line: the kernel computes q = (E0 + bias) >> kSubpixelBits on int64_t, an
//     arithmetic shift, that is floor((E0 + bias) / kSubpixelOne). The proofs characterise it
//     as E0 + bias == kSubpixelOne * q + r with 0 <= r < kSubpixelOne (floor division by a
//     positive divisor has exactly one such (q, r)), in `shift_characterisation`.

#pragma once

#include <cstdint>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "rastrules/fixed.hpp"
#include "rastrules/formula/edge.hpp"
#include "rastrules/formula/lane.hpp"
#include "rastrules/raster/fast.hpp"
#include "support/kernel_model.hpp"
#include "support/obligation.hpp"
#include "support/prover.hpp"
#include "support/sym.hpp"

namespace rastrules::proofs {

// The `select` argument of the lane templates for symbolic values: c ? t : f as a Z3 ite
// (support/sym.hpp's select; records no obligation).
struct SymSelect {
  template <class S> S operator()(const SymBool& c, const S& t, const S& f) const {
    return select(c, t, f);
  }
};

struct FastKernelModel : KernelModel {
  static constexpr const char* kName = "kernel";
  // The lanes: 32-bit (FAST.LANE.I32). Raw coordinates are int32_t, so A = ay - by and
  // B = bx - ax are computed on the lane type too.
  using Lane = Sym<std::int32_t>;
  // Tile side in pixels (raster/fast.hpp), the lane bound (formula/lane.hpp), and the divisor
  // of the shift: one pixel step of E is kSubpixelOne * A (FIX.STEP.INCREMENTAL).
  static constexpr std::int64_t kTile = raster::kFastTileSize;
  static constexpr std::int64_t kBound = formula::kLaneBound;
  static constexpr std::int64_t kDivisor = kSubpixelOne;
  // The edge-value budget |E| < 2^kEdgeValueMagBits (FIX.BUDGET.EDGE_VALUE, fixed.hpp).
  static constexpr int kEdgeBits = kEdgeValueMagBits;

  static std::vector<Constant> constants() {
    return kernel_constants_and({{"kFastTileSize", raster::kFastTileSize, Unit::kInteger},
                                 {"kLaneBound", formula::kLaneBound, Unit::kInteger},
                                 {"kEdgeValueMagBits", kEdgeValueMagBits, Unit::kInteger}});
  }

  template <class L> static L lane_offset(const L& i, const L& j, const L& a, const L& b) {
    return formula::lane_offset<L>(i, j, a, b);
  }
  template <class S> static S lane_threshold(const S& q, const S& bound) {
    return formula::lane_threshold<S>(q, bound, SymSelect{});
  }
  template <class L> static L lane_max(const L& a, const L& b, const L& last) {
    return formula::lane_max<L>(a, b, last, SymSelect{});
  }
  template <class L> static L lane_min(const L& a, const L& b, const L& last) {
    return formula::lane_min<L>(a, b, last, SymSelect{});
  }

  // Restated (see the file comment): q = (e_biased >> kSubpixelBits) on int64_t, as
  // e_biased == kDivisor * q + r, 0 <= r < kDivisor.
  static z3::expr shift_characterisation(const z3::expr& e_biased, const z3::expr& q,
                                         const z3::expr& r) {
    z3::context& ctx = q.ctx();
    const z3::expr d = ctx.int_val(kDivisor);
    return e_biased == d * q + r && 0 <= r && r < d;
  }
};

// Returns false (after printing where) unless C++'s `e >> kSubpixelBits` on int64_t (the
// kernel's shift; arithmetic since C++20) satisfies the restatement
// e == kSubpixelOne * q + r, 0 <= r < kSubpixelOne, for every e within 2^17 of 0 and within 2^9
// of +-2^kEdgeValueMagBits and of +-2^k for every k below it.
inline bool shift_restatement_matches_cpp() {
  const auto ok = [](std::int64_t e) {
    const std::int64_t q = e >> kSubpixelBits;
    const std::int64_t r = e - std::int64_t{kSubpixelOne} * q;
    if (0 <= r && r < kSubpixelOne)
      return true;
    std::cout << "restatement of >> differs from C++ at e = " << e << "\n";
    return false;
  };
  for (std::int64_t e = -(std::int64_t{1} << 17); e <= (std::int64_t{1} << 17); ++e) {
    if (!ok(e))
      return false;
  }
  for (int k = 17; k <= kEdgeValueMagBits; ++k) {
    for (const std::int64_t c : {std::int64_t{1} << k, -(std::int64_t{1} << k)}) {
      for (std::int64_t d = -512; d <= 512; ++d) {
        if (!ok(c + d))
          return false;
      }
    }
  }
  std::cout << "restatement of the shift checked against C++ >> on int64_t\n";
  return true;
}

// Returns the int64_t value of a lane-typed value (widening is exact: no obligation).
template <class L> Sym<std::int64_t> to_acc(const L& v) {
  return Sym<std::int64_t>(v.domain(), v.expr(), v.text());
}

// The inputs every lane theorem shares: edge endpoints a, b (raw coordinates, lane type) and a
// lane (i, j) of a tile, with A = ay - by and B = bx - ax computed as the kernel does.
template <class F> struct LaneInputs {
  using L = typename F::Lane;
  Point<L> a;
  Point<L> b;
  L i;
  L j;
  std::vector<z3::expr> hyps;

  explicit LaneInputs(Domain& dom)
      : a(point_var<L>(dom, "a")), b(point_var<L>(dom, "b")),
        i(dom.var<typename L::rep>("i", Unit::kInteger)),
        j(dom.var<typename L::rep>("j", Unit::kInteger)) {
    // Assumes: SNAP.VERTEX.RANGE; lanes 0 <= i, j < kFastTileSize
    hyps = {in_vertex_range<F>(a), in_vertex_range<F>(b), in_closed(i.expr(), 0, F::kTile - 1),
            in_closed(j.expr(), 0, F::kTile - 1)};
  }
  // A = ay - by (the x step in units of kSubpixelOne), B = bx - ax (the y step).
  [[nodiscard]] L step_a() const { return a.y - b.y; }
  [[nodiscard]] L step_b() const { return b.x - a.x; }
};

// FAST.LANE.I32, the budget. For all a, b in SNAP.VERTEX.RANGE and lanes 0 <= i, j < kTile,
// with A = ay - by, B = bx - ax and L = lane_offset(i, j, A, B), all on the lane type:
//   1. A, B, every product and sum of lane_offset fit the lane type, and |L| < kLaneBound;
//   2. the next row's offset L + B (the kernel steps rows by adding B) and the next column's
//      L + A fit the lane type and equal lane_offset(i, j + 1, ..) and lane_offset(i + 1, j, ..),
//      also for the one-past-the-end step j = kTile - 1 (i = kTile - 1).
// rule: FAST.LANE.I32
template <class F> void prove_lane_budget(Prover& pr) {
  using L = typename F::Lane;
  Domain& dom = pr.domain();
  const LaneInputs<F> in(dom);
  {
    const std::size_t mark = dom.mark();
    const L l = F::lane_offset(in.i, in.j, in.step_a(), in.step_b());
    pr.watch("L = lane_offset(i, j, A, B)", l.expr(), Unit::kInteger);
    pr.prove("lane_offset fits the lane type and |L| < kLaneBound", in.hyps,
             in_closed(l.expr(), -F::kBound + 1, F::kBound - 1), dom.obligations_since(mark));
  }
  {
    const std::size_t mark = dom.mark();
    const L a = in.step_a();
    const L b = in.step_b();
    const L l = F::lane_offset(in.i, in.j, a, b);
    const L next_row = l + b;
    const L next_col = l + a;
    const std::size_t mark_direct = dom.mark();
    const L row_direct = F::lane_offset(in.i, in.j + L(1), a, b);
    const L col_direct = F::lane_offset(in.i + L(1), in.j, a, b);
    // Only the stepped values are computed by the kernel: the direct forms are the spec side,
    // so their own obligations are not required.
    std::vector<Obligation> obl = dom.obligations_since(mark);
    obl.erase(obl.begin() + static_cast<std::ptrdiff_t>(mark_direct - mark), obl.end());
    pr.watch("L", l.expr(), Unit::kInteger);
    pr.watch("L + B", next_row.expr(), Unit::kInteger);
    pr.prove(
        "row step L + B and column step L + A fit the lane type and equal the next lane's offset",
        in.hyps, next_row.expr() == row_direct.expr() && next_col.expr() == col_direct.expr(), obl);
  }
}

// The obligation as its proof and the self-check run it.
inline const ProofObligation kLaneBudget{"fast/lane_budget",
                                         []<class F>(Prover& pr) { prove_lane_budget<F>(pr); }};

// FAST.LANE.I32, the equivalence. Proved as a chain:
//   E1. for a, b, p in SNAP.VERTEX.RANGE: |edge_value(a, b, p)| < 2^kEdgeBits and
//       E + edge_bias(f) fits int64_t, for both flags (FIX.BUDGET.EDGE_VALUE, re-checked here on
//       the model's range);
//   E2. for a, b, p and p' = p + (kDivisor i, kDivisor j) in range (the sample point of pixel
//       (tx + i, ty + j) when p is the tile's first one):
//       edge_value(a, b, p') == edge_value(a, b, p) + i * edge_step_x + j * edge_step_y
//       == edge_value(a, b, p) + kDivisor * lane_offset(i, j, A, B), no overflow (int64_t;
//       lane_offset on the lane type, widened);
//   T.  for each flag f (bias = edge_bias(f)), every integer E0 with |E0| < 2^kEdgeBits (a
//       superset of the values E1 shows the kernel can reach), every a, b, i, j as above and
//       the q of the kernel's shift (shift_characterisation):
//         E > 0 || (E == 0 && f)  <=>  L >= lane_threshold(q, kBound),  E = E0 + kDivisor * L
//       (the per-edge test of TRI.FILL.TOP_LEFT at the pixel) and equally
//         E0 + bias + kDivisor * L >= 0  <=>  L >= lane_threshold(q, kBound)
//       (the biased form of FIX.BIAS.FORM the plain walk evaluates),
//       with lane_threshold evaluated on int64_t without overflow and its result fitting the
//       lane type (the kernel narrows it to an int32_t lane).
// By E2, E0 + kDivisor * L is the plain walk's edge value at pixel (tx + i, ty + j), so the
// lane test decides exactly what E + bias >= 0 (FIX.BIAS.FORM) decides there. T is skipped
// (UNKNOWN) unless E1 and E2 are PROVED.
//   T'. the end-to-end statement without the superset: E0 = edge_value(a, b, p) itself (p and
//       p' in range) and the plain decision taken on edge_value(a, b, p') directly.
// rule: FAST.LANE.I32
template <class F> void prove_lane_equivalence(Prover& pr) {
  using L = typename F::Lane;
  using S = typename F::Acc;
  Domain& dom = pr.domain();
  z3::context& ctx = pr.ctx();
  const LaneInputs<F> in(dom);
  const Point<S> a = Point<S>{to_acc(in.a.x), to_acc(in.a.y)};
  const Point<S> b = Point<S>{to_acc(in.b.x), to_acc(in.b.y)};
  const Point<S> p = point_var<S>(dom, "p");
  const z3::expr budget = ctx.int_val(std::int64_t{1} << F::kEdgeBits);

  Status e1 = Status::kProved;
  for (const bool inclusive : {true, false}) {
    std::vector<z3::expr> h = {in_vertex_range<F>(in.a), in_vertex_range<F>(in.b),
                               in_vertex_range<F>(p)};
    const std::size_t mark = dom.mark();
    const S e = F::edge_value(a, b, p);
    // Computed for its obligation (E + bias fits int64_t); its value is not needed.
    [[maybe_unused]] const S biased = e + F::template edge_bias<S>(inclusive);
    pr.watch("E0 = edge_value(a, b, p)", e.expr(), Unit::kEdgeRaw);
    const Status s =
        pr.prove(std::string("E1: |edge_value| < 2^kEdgeValueMagBits, E + edge_bias(") +
                     (inclusive ? "true" : "false") + ") fits int64_t",
                 h, -budget < e.expr() && e.expr() < budget, dom.obligations_since(mark));
    if (s != Status::kProved)
      e1 = s;
  }

  Status e2 = Status::kUnknown;
  {
    std::vector<z3::expr> h = in.hyps;
    const S one(F::kDivisor);
    const S ii = to_acc(in.i);
    const S jj = to_acc(in.j);
    const Point<S> q{p.x + one * ii, p.y + one * jj};
    h.push_back(in_vertex_range<F>(p));
    h.push_back(in_vertex_range<F>(q));
    const std::size_t mark = dom.mark();
    const S e0 = F::edge_value(a, b, p);
    const S eq = F::edge_value(a, b, q);
    const S stepped = e0 + ii * F::edge_step_x(a, b, one) + jj * F::edge_step_y(a, b, one);
    const S lane = e0 + one * to_acc(F::lane_offset(in.i, in.j, in.step_a(), in.step_b()));
    pr.watch("E(p + (i, j) px)", eq.expr(), Unit::kEdgeRaw);
    pr.watch("E(p) + i step_x + j step_y", stepped.expr(), Unit::kEdgeRaw);
    pr.watch("E(p) + 256 L", lane.expr(), Unit::kEdgeRaw);
    e2 = pr.prove("E2: E(p + (i, j) px) == E(p) + i step_x + j step_y == E(p) + 256 lane_offset", h,
                  eq.expr() == stepped.expr() && stepped.expr() == lane.expr(),
                  dom.obligations_since(mark));
  }

  const S e0 = dom.var<std::int64_t>("E0", Unit::kEdgeRaw);
  const S q = dom.var<std::int64_t>("q", Unit::kInteger);
  const z3::expr r = ctx.int_const("r");
  for (const bool inclusive : {true, false}) {
    const std::string name =
        std::string("T (inclusive = ") + (inclusive ? "true" : "false") +
        "): inside at E0 + 256 L <=> L >= lane_threshold(q), which fits the lane";
    if (e1 != Status::kProved || e2 != Status::kProved) {
      pr.skip(name, "lemma E1 or E2 not proved");
      continue;
    }
    std::vector<z3::expr> h = in.hyps;
    h.push_back(-budget < e0.expr());
    h.push_back(e0.expr() < budget);
    const std::size_t mark = dom.mark();
    const S biased = e0 + F::template edge_bias<S>(inclusive);
    h.push_back(F::shift_characterisation(biased.expr(), q.expr(), r));
    const L l = F::lane_offset(in.i, in.j, in.step_a(), in.step_b());
    const S thr = F::lane_threshold(q, S(F::kBound));
    dom.require_fits<typename L::rep>(thr.expr(), "lane_threshold narrowed to the lane type");
    // The plain decision at the pixel, from the spec's words (TRI.FILL.TOP_LEFT): E > 0, or
    // E == 0 on an inclusive edge, with E = E0 + kDivisor * L (E2).
    const z3::expr e = e0.expr() + ctx.int_val(F::kDivisor) * l.expr();
    const z3::expr plain = e > 0 || (e == 0 && ctx.bool_val(inclusive));
    pr.watch("L", l.expr(), Unit::kInteger);
    pr.watch("lane_threshold(q)", thr.expr(), Unit::kInteger);
    pr.watch("r", r, Unit::kInteger);
    // ... and, equally, the biased form the plain walk evaluates (FIX.BIAS.FORM).
    const z3::expr biased_form = biased.expr() + ctx.int_val(F::kDivisor) * l.expr() >= 0;
    const z3::expr lane_test = l.expr() >= thr.expr();
    pr.prove(name, h, plain == lane_test && biased_form == lane_test, dom.obligations_since(mark));
  }

  // End to end, without the superset: E0 = edge_value(a, b, p) at the tile's first sample
  // point p in range, the plain decision taken on edge_value at the lane's own sample point
  // p' = p + (kDivisor i, kDivisor j) in range.
  for (const bool inclusive : {true, false}) {
    const std::string name = std::string("T' (inclusive = ") + (inclusive ? "true" : "false") +
                             "): inside at edge_value(a, b, p') <=> L >= lane_threshold(q) with "
                             "E0 = edge_value(a, b, p)";
    const S one(F::kDivisor);
    const Point<S> pq{p.x + one * to_acc(in.i), p.y + one * to_acc(in.j)};
    std::vector<z3::expr> h = in.hyps;
    h.push_back(in_vertex_range<F>(p));
    h.push_back(in_vertex_range<F>(pq));
    const std::size_t mark = dom.mark();
    const S e_p = F::edge_value(a, b, p);
    const S biased = e_p + F::template edge_bias<S>(inclusive);
    const z3::expr r2 = ctx.int_const(inclusive ? "r_incl" : "r_excl");
    const S q2 = dom.var<std::int64_t>(inclusive ? "q_incl" : "q_excl", Unit::kInteger);
    h.push_back(F::shift_characterisation(biased.expr(), q2.expr(), r2));
    const L l = F::lane_offset(in.i, in.j, in.step_a(), in.step_b());
    const S thr = F::lane_threshold(q2, S(F::kBound));
    dom.require_fits<typename L::rep>(thr.expr(), "lane_threshold narrowed to the lane type");
    std::vector<Obligation> obl = dom.obligations_since(mark);
    // The plain side (spec words on the kernel's edge value at p'); its own evaluation is
    // covered by FIX.BUDGET.EDGE_VALUE, so its obligations are not part of this theorem.
    const S e = F::edge_value(a, b, pq);
    const z3::expr plain = e.expr() > 0 || (e.expr() == 0 && ctx.bool_val(inclusive));
    pr.watch("E0 = edge_value(a, b, p)", e_p.expr(), Unit::kEdgeRaw);
    pr.watch("edge_value(a, b, p')", e.expr(), Unit::kEdgeRaw);
    pr.watch("L", l.expr(), Unit::kInteger);
    pr.watch("lane_threshold(q)", thr.expr(), Unit::kInteger);
    pr.prove(name, h, plain == (l.expr() >= thr.expr()), obl);
  }
}

// The obligation as its proof and the self-check run it.
inline const ProofObligation kLaneEquivalence{
    "fast/lane_equivalence", []<class F>(Prover& pr) { prove_lane_equivalence<F>(pr); }};

// FAST.TILE.CLASSIFY. For all a, b in SNAP.VERTEX.RANGE (A = ay - by, B = bx - ax on the lane
// type), Lmax = lane_max(A, B, kTile - 1), Lmin = lane_min(A, B, kTile - 1) on the lane type,
// every lane 0 <= i, j < kTile with L = lane_offset(i, j, A, B) and every integer C (an edge's
// lane threshold):
//   1. Lmax and Lmin fit the lane type (no overflow) and lie in (-kLaneBound, kLaneBound);
//   2. Lmax < C implies L < C (rejecting the tile is sound) and Lmin >= C implies L >= C
//      (accepting it is sound);
//   3. both are attained: L at the corner (A > 0 ? kTile - 1 : 0, B > 0 ? kTile - 1 : 0) is
//      Lmax, at the opposite corner Lmin (so the classification is exact: a tile that is not
//      rejected has a lane with L >= C, one that is not accepted a lane with L < C).
// For a triangle the tile is rejected if some edge rejects it and accepted if all three accept
// it; both follow from 2 per edge.
// rule: FAST.TILE.CLASSIFY
template <class F> void prove_tile_classify(Prover& pr) {
  using L = typename F::Lane;
  Domain& dom = pr.domain();
  z3::context& ctx = pr.ctx();
  const LaneInputs<F> in(dom);
  const z3::expr c = ctx.int_const("C");
  {
    const std::size_t mark = dom.mark();
    const L last(F::kTile - 1);
    const L lmax = F::lane_max(in.step_a(), in.step_b(), last);
    const L lmin = F::lane_min(in.step_a(), in.step_b(), last);
    pr.watch("Lmax", lmax.expr(), Unit::kInteger);
    pr.watch("Lmin", lmin.expr(), Unit::kInteger);
    pr.prove("lane_max and lane_min fit the lane type, |.| < kLaneBound", in.hyps,
             in_closed(lmax.expr(), -F::kBound + 1, F::kBound - 1) &&
                 in_closed(lmin.expr(), -F::kBound + 1, F::kBound - 1),
             dom.obligations_since(mark));
  }
  {
    const L last(F::kTile - 1);
    const L lmax = F::lane_max(in.step_a(), in.step_b(), last);
    const L lmin = F::lane_min(in.step_a(), in.step_b(), last);
    const L l = F::lane_offset(in.i, in.j, in.step_a(), in.step_b());
    pr.watch("L", l.expr(), Unit::kInteger);
    pr.watch("Lmax", lmax.expr(), Unit::kInteger);
    pr.prove("rejection is sound: Lmax < C => L(i, j) < C for every lane", in.hyps,
             z3::implies(lmax.expr() < c, l.expr() < c));
    pr.watch("L", l.expr(), Unit::kInteger);
    pr.watch("Lmin", lmin.expr(), Unit::kInteger);
    pr.prove("acceptance is sound: Lmin >= C => L(i, j) >= C for every lane", in.hyps,
             z3::implies(lmin.expr() >= c, l.expr() >= c));
  }
  {
    const L last(F::kTile - 1);
    const L zero(0);
    const L a = in.step_a();
    const L b = in.step_b();
    const L lmax = F::lane_max(a, b, last);
    const L lmin = F::lane_min(a, b, last);
    const L hi = F::lane_offset(select(a > zero, last, zero), select(b > zero, last, zero), a, b);
    const L lo = F::lane_offset(select(a < zero, last, zero), select(b < zero, last, zero), a, b);
    pr.watch("Lmax", lmax.expr(), Unit::kInteger);
    pr.watch("L at the max corner", hi.expr(), Unit::kInteger);
    pr.prove("the classification is exact: Lmax and Lmin are the offsets of two corner lanes",
             in.hyps, lmax.expr() == hi.expr() && lmin.expr() == lo.expr());
  }
}

// The obligation as its proof and the self-check run it.
inline const ProofObligation kTileClassify{"fast/tile_classify",
                                           []<class F>(Prover& pr) { prove_tile_classify<F>(pr); }};

} // namespace rastrules::proofs
