// SPDX-License-Identifier: MIT
// Obligation path/area_budget (PATH.AREA.CELLS) as a template over an area model. Used by
// area_budget.cpp and area_mutants.cpp.
//
// AreaKernelModel instantiates the kernel's own integer expressions of the cell method,
// rastrules/formula/path_area.hpp, on Sym<std::int64_t> (I) and Sym<__int128> (W), as
// kernel/src/path_area.cpp (CellRows::collect, cell_area, meet_in_cell, ramp_integral) calls
// them. What the kernel writes on concrete types and this file restates or assumes:
//   - dir = sgn dy, q = |dy| (the numerator's denominator), adx = |dx|, sdx = sgn dx: the
//     theorems take each sign of the run as its own case, with dir or sdx the literal;
//   - the heights y at which collect() takes x (ya = max(ymin, t), yb = min(ymax, t + kW)) lie
//     within the edge's y-range, and the column lines x = k kW at which it takes y within the
//     edge's x-range: the numerator theorems range over every such y (x);
//   - the column of a crossing with the row's top or bottom, col = floor_div(xn, q kW),
//     entering as col q kW <= xn < (col + 1) q kW;
//   - a crossing of a column line lies on the cell's side: the kernel takes k between
//     ceil(xlo / (q kW)) and floor(xhi / (q kW)) for the edge's x-range [xlo, xhi] / q within
//     the row, so y = yn / adx lies in [top, top + kW] (a horizontal edge: yn = y0 strictly
//     inside, q = 1), entering as top adx <= yn <= (top + kW) adx;
//   - rows and column lines of a target of at most kMaxTargetSide px (area_rows refuses larger
//     ones): top = j kW, 0 <= j < kMaxTargetSide; lines lo = c kW, 0 <= c <= kMaxTargetSide;
//   - the orientations o3, o4 that meet_in_cell passes on are edge values of in-range points,
//     |o| <= 2^49 (FIX.BUDGET.EDGE_VALUE, proved by proof.fixed.edge_value_no_overflow).
// Every theorem ranges over a superset of what the kernel computes (independent variables
// within the bounds the earlier theorems prove), so each budget holds whatever path through
// the code reaches it.

#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "path/curve_budget.hpp"
#include "path/line_crossing.hpp"
#include "rastrules/fixed.hpp"
#include "rastrules/formula/path_area.hpp"
#include "support/obligation.hpp"
#include "support/prover.hpp"
#include "support/sym.hpp"

namespace rastrules::proofs {

struct AreaKernelModel : PathKernelModel {
  static constexpr const char* kName = "kernel";
  using I = Sym<std::int64_t>; // the kernel's std::int64_t
  using W = Sym<Int128>;       // the kernel's __int128 (I128)
  static constexpr std::int64_t kSide = formula::kCellSide;
  // Rows' tops 0 .. (kMaxTargetSide - 1) kW; column lines 0 .. kMaxTargetSide kW.
  static constexpr std::int64_t kMaxTop = std::int64_t{kMaxTargetSide - 1} * kSide;
  static constexpr std::int64_t kMaxLine = std::int64_t{kMaxTargetSide} * kSide;

  // The bounds the theorems prove, in raw units (PATH.AREA.CELLS):
  // |xn| <= kNumPerQ q (x within the edge's range: |x| <= 2^23), and so
  static constexpr Int128 kNumPerQ = Int128{1} << 23;
  // |col| <= kCol for a crossing's column,
  static constexpr Int128 kCol = Int128{1} << 15;
  // 0 <= ramp integral <= kRamp (the triangle (2^23 2^24)^2 where an edge crosses the column
  // line 0 from x = 2^23 px), so a cell's part |v| <= kRamp,
  static constexpr Int128 kRamp = Int128{1} << 94;
  // and the meeting point's numerators and denominator.
  static constexpr Int128 kMeetNum = Int128{1} << 74;
  static constexpr Int128 kMeetDen = Int128{1} << 50;

  static std::vector<Constant> constants() {
    return PathKernelModel::constants(); // kMaxTargetSide among them
  }

  template <class S>
  static S x_numerator(const S& x0, const S& y0, const S& dx, const S& dy, const S& dir,
                       const S& y) {
    return formula::cell_x_numerator<S>(x0, y0, dx, dy, dir, y);
  }
  template <class S>
  static S y_numerator(const S& x0, const S& y0, const S& dx, const S& dy, const S& sdx,
                       const S& x) {
    return formula::cell_y_numerator<S>(x0, y0, dx, dy, sdx, x);
  }
  template <class S> static S top_position(const S& xn, const S& col, const S& q) {
    return formula::cell_top_position<S>(xn, col, q);
  }
  template <class S> static S bottom_position(const S& xn, const S& col, const S& q) {
    return formula::cell_bottom_position<S>(xn, col, q);
  }
  template <class S> static S right_position(const S& yn, const S& top, const S& q) {
    return formula::cell_right_position<S>(yn, top, q);
  }
  template <class S> static S left_position(const S& yn, const S& top, const S& q) {
    return formula::cell_left_position<S>(yn, top, q);
  }
  template <class V, class S>
  static SymBool border_before(const S& pa, const S& qa, const S& sa, const S& da, const S& pb,
                               const S& qb, const S& sb, const S& db) {
    return formula::cell_border_before<V, S>(pa, qa, sa, da, pb, qb, sb, db);
  }
  template <class S>
  static SymBool doubles_back(const S& ex, const S& ey, const S& fx, const S& fy) {
    return formula::cell_doubles_back<S>(ex, ey, fx, fy);
  }
  template <class V>
  static formula::CellMeetPoint<V> meet_point(const V& x0, const V& y0, const V& x1, const V& y1,
                                              const V& o3, const V& o4) {
    return formula::cell_meet_point<V>(
        x0, y0, x1, y1, o3, o4,
        [](const SymBool& c, const V& t, const V& f) { return select(c, t, f); });
  }
  template <class V>
  static SymBool meet_inside(const formula::CellMeetPoint<V>& m, const V& left, const V& top) {
    return formula::cell_meet_inside<V>(m, left, top);
  }
  template <class V>
  static V ramp(const V& pa, const V& pb, const V& q, const V& h, const V& adx, const V& lo) {
    return formula::cell_ramp_integral<V>(
        pa, pb, q, h, adx, lo,
        [](const SymBool& c, const V& t, const V& f) { return select(c, t, f); });
  }
};

// For model F:
//   A1. x at a row line (cell_x_numerator) for each sign of dy, and y at a column line
//       (cell_y_numerator) for each sign of dx: every step fits int64_t, |xn| <= 2^23 |dy|
//       (|yn| <= 2^23 |dx|);
//   A2. the crossing's column col = floor(xn / (q kW)) has |col| <= 2^15 + 1, and its positions
//       on the top side (in [0, kW q)) and bottom side (in (2 kW q, 3 kW q]) fit int64_t;
//   A3. a column line's crossing at y = yn / q in [top, top + kW]: its positions on the right
//       side (in [kW q, 2 kW q]) and the left side (in [3 kW q, 4 kW q]) fit int64_t;
//   A4. the border sort: positions in [0, 4 kW q], tie orders |sn| <= 2^24 over sd in
//       [1, 2^24]: the cross products fit __int128;
//   A5. the doubling-back test on runs within 2^24 fits int64_t;
//   A6. meet_in_cell's common point from orientations |o| <= 2^49: fits __int128, |den| <=
//       2^50, |nx|, |ny| <= 2^74, the comparisons with the cell's lines fit;
//   A7. ramp_integral: fits __int128, 0 <= . <= kRamp = 2^94, a cell's part (left ramp less
//       right ramp) within kRamp, its denominator 2 q adx <= 2^49 in int64_t.
// The groups, for the mutation self-check (it runs the group a mutant targets).
enum AreaPart : unsigned {
  kA1 = 1,
  kA2 = 2,
  kA3 = 4,
  kA4 = 8,
  kA5 = 16,
  kA6 = 32,
  kA7 = 64,
  kAllAreaParts = 127
};

template <class F> void prove_area_budget(Prover& pr, unsigned parts = kAllAreaParts) {
  using I = typename F::I;
  using W = typename F::W;
  using IR = typename I::rep;
  using WR = typename W::rep;
  Domain& dom = pr.domain();
  z3::context& ctx = pr.ctx();
  const auto big = [&](Int128 v) { return int128_val(ctx, v); };
  const auto ivar = [&](const std::string& n, Unit u) { return dom.var<IR>(n, u); };
  const auto wvar = [&](const std::string& n, Unit u) { return dom.var<WR>(n, u); };
  const z3::expr lo_raw = ctx.int_val(F::kMinRaw), hi_raw = ctx.int_val(F::kMaxRaw);
  const z3::expr side = ctx.int_val(F::kSide);
  const auto raw = [&](const I& v) { return lo_raw <= v.expr() && v.expr() <= hi_raw; };

  // Lemmas P, M, L, A and D of curve_budget.hpp, proved first; the theorems take instances of
  // A, P and D as hypotheses.
  const bool lemmas = prove_product_lemmas(pr);
  const auto needs_lemmas = [&](const std::string& name) {
    if (!lemmas)
      pr.skip(name, "lemma P, M, L, A or D not proved");
    return lemmas;
  };
  // |x y| <= X y for a constant X and 0 <= y (lemma A with Y = y).
  const auto scaled_by = [&](const z3::expr& x, Int128 bx, const z3::expr& y) {
    return lemma_a(x, bx, y, y);
  };

  // A1: the numerators, one theorem per axis and sign.
  for (const bool x_axis : {true, false}) {
    for (const int sign : {1, -1}) {
      if ((parts & kA1) == 0)
        break;
      const std::string axis = x_axis ? "x at a row line" : "y at a column line";
      const std::string name = "A1: " + axis + (sign > 0 ? ", run > 0" : ", run < 0") +
                               ": fits int64_t, |.| <= " + magnitude(F::kNumPerQ) + " |run|";
      if (!needs_lemmas(name))
        continue;
      const std::string tag = std::string(x_axis ? "n" : "m") + (sign > 0 ? "p" : "n");
      std::vector<z3::expr> h;
      const I x0 = ivar(tag + "x0", Unit::kCoordRaw), y0 = ivar(tag + "y0", Unit::kCoordRaw);
      const I x1 = ivar(tag + "x1", Unit::kCoordRaw), y1 = ivar(tag + "y1", Unit::kCoordRaw);
      const I at = ivar(tag + "at", Unit::kCoordRaw); // the y (x) where the numerator is taken
      for (const I* v : {&x0, &y0, &x1, &y1})
        h.push_back(raw(*v));
      // The run along the axis of `at` and its ends.
      const I& a0 = x_axis ? y0 : x0;
      const I& a1 = x_axis ? y1 : x1;
      const I& b0 = x_axis ? x0 : y0;
      const I& b1 = x_axis ? x1 : y1;
      if (sign > 0)
        h.push_back(a0.expr() < a1.expr() && a0.expr() <= at.expr() && at.expr() <= a1.expr());
      else
        h.push_back(a1.expr() < a0.expr() && a1.expr() <= at.expr() && at.expr() <= a0.expr());
      // n = b0 (a1 - at) + b1 (at - a0) (sign > 0) or b0 (at - a1) + b1 (a0 - at): a weighted
      // sum of the ends' other coordinates with non-negative weights summing to |run|.
      const z3::expr w0 = sign > 0 ? a1.expr() - at.expr() : at.expr() - a1.expr();
      const z3::expr w1 = sign > 0 ? at.expr() - a0.expr() : a0.expr() - at.expr();
      h.push_back(scaled_by(b0.expr(), F::kNumPerQ, w0));
      h.push_back(scaled_by(b1.expr(), F::kNumPerQ, w1));
      const std::size_t mark = dom.mark();
      const I dx = x1 - x0, dy = y1 - y0;
      const I s(std::int64_t{sign});
      const I n =
          x_axis ? F::x_numerator(x0, y0, dx, dy, s, at) : F::y_numerator(x0, y0, dx, dy, s, at);
      const z3::expr run = sign > 0 ? a1.expr() - a0.expr() : a0.expr() - a1.expr();
      const z3::expr b = big(F::kNumPerQ) * run;
      pr.prove(name, h, -b <= n.expr() && n.expr() <= b, dom.obligations_since(mark));
    }
  }

  // A2: the top and bottom sides, at x = xn / q.
  if ((parts & kA2) != 0 && needs_lemmas("A2: top and bottom positions")) {
    std::vector<z3::expr> h;
    const I xn = ivar("txn", Unit::kInteger), q = ivar("tq", Unit::kInteger);
    const I col = ivar("tcol", Unit::kInteger);
    h.push_back(1 <= q.expr() && q.expr() <= big(Int128{1} << 24));
    h.push_back(-(big(F::kNumPerQ) * q.expr()) <= xn.expr() &&
                xn.expr() <= big(F::kNumPerQ) * q.expr()); // A1
    const z3::expr d = q.expr() * side;
    h.push_back(col.expr() * d <= xn.expr() && xn.expr() < (col.expr() + 1) * d); // floor_div
    h.push_back(lemma_d(col.expr(), d, xn.expr(), F::kCol));
    h.push_back(scaled_by(col.expr() * side, (F::kCol + 1) * F::kSide, q.expr()));
    h.push_back(scaled_by(col.expr() * side + 3 * side, (F::kCol + 4) * F::kSide, q.expr()));
    const std::size_t mark = dom.mark();
    const I top = F::top_position(xn, col, q);
    const I bottom = F::bottom_position(xn, col, q);
    const z3::expr kq = side * q.expr();
    pr.prove("A2: the column of a crossing with a row line, |col| <= " + magnitude(F::kCol) +
                 " + 1; its positions on the top side in [0, kW q) and on the bottom side in "
                 "(2 kW q, 3 kW q], int64_t",
             h,
             -big(F::kCol) - 1 <= col.expr() && col.expr() <= big(F::kCol) && 0 <= top.expr() &&
                 top.expr() < kq && 2 * kq < bottom.expr() && bottom.expr() <= 3 * kq,
             dom.obligations_since(mark));
  }

  // A3: the right and left sides, at y = yn / q in [top, top + kW].
  if ((parts & kA3) != 0 && needs_lemmas("A3: right and left positions")) {
    std::vector<z3::expr> h;
    const I yn = ivar("ryn", Unit::kInteger), q = ivar("rq", Unit::kInteger);
    const I top = ivar("rtop", Unit::kCoordRaw);
    h.push_back(1 <= q.expr() && q.expr() <= big(Int128{1} << 24));
    h.push_back(0 <= top.expr() && top.expr() <= ctx.int_val(F::kMaxTop));
    h.push_back(top.expr() * q.expr() <= yn.expr() && yn.expr() <= (top.expr() + side) * q.expr());
    h.push_back(scaled_by(top.expr(), F::kMaxTop, q.expr()));
    h.push_back(scaled_by(side - top.expr(), F::kMaxTop, q.expr()));
    h.push_back(scaled_by(4 * side + top.expr(), F::kMaxTop + 4 * F::kSide, q.expr()));
    const std::size_t mark = dom.mark();
    const I right = F::right_position(yn, top, q);
    const I left = F::left_position(yn, top, q);
    const z3::expr kq = side * q.expr();
    pr.prove("A3: a column line's crossing on the right side in [kW q, 2 kW q] and on the left "
             "side in [3 kW q, 4 kW q], int64_t",
             h,
             kq <= right.expr() && right.expr() <= 2 * kq && 3 * kq <= left.expr() &&
                 left.expr() <= 4 * kq,
             dom.obligations_since(mark));
  }

  // A4: the border sort's cross products.
  if ((parts & kA4) != 0 && needs_lemmas("A4: border order")) {
    std::vector<z3::expr> h;
    const I pa = ivar("spa", Unit::kInteger), qa = ivar("sqa", Unit::kInteger);
    const I pb = ivar("spb", Unit::kInteger), qb = ivar("sqb", Unit::kInteger);
    const I sa = ivar("ssa", Unit::kInteger), da = ivar("sda", Unit::kInteger);
    const I sb = ivar("ssb", Unit::kInteger), db = ivar("sdb", Unit::kInteger);
    const z3::expr q_max = big(Int128{1} << 24);
    for (const auto& [p, q] : {std::pair{&pa, &qa}, std::pair{&pb, &qb}}) {
      h.push_back(1 <= q->expr() && q->expr() <= q_max);
      h.push_back(0 <= p->expr() && p->expr() <= 4 * side * q->expr());
    }
    for (const auto& [s, d] : {std::pair{&sa, &da}, std::pair{&sb, &db}}) {
      h.push_back(1 <= d->expr() && d->expr() <= q_max);
      h.push_back(-q_max <= s->expr() && s->expr() <= q_max);
    }
    h.push_back(product_bound128(pa.expr(), Int128{1} << 34, qb.expr(), Int128{1} << 24));
    h.push_back(product_bound128(pb.expr(), Int128{1} << 34, qa.expr(), Int128{1} << 24));
    h.push_back(product_bound128(sa.expr(), Int128{1} << 24, db.expr(), Int128{1} << 24));
    h.push_back(product_bound128(sb.expr(), Int128{1} << 24, da.expr(), Int128{1} << 24));
    const std::size_t mark = dom.mark();
    (void)F::template border_before<W>(pa, qa, sa, da, pb, qb, sb, db);
    pr.prove("A4: the border order's cross products (positions, tie orders) fit __int128", h,
             ctx.bool_val(true), dom.obligations_since(mark));
  }

  // A5: the doubling-back test.
  if ((parts & kA5) != 0 && needs_lemmas("A5: doubling back")) {
    std::vector<z3::expr> h;
    const I ex = ivar("dex", Unit::kCoordRaw), ey = ivar("dey", Unit::kCoordRaw);
    const I fx = ivar("dfx", Unit::kCoordRaw), fy = ivar("dfy", Unit::kCoordRaw);
    const Int128 run = Int128{1} << 24;
    for (const I* v : {&ex, &ey, &fx, &fy})
      h.push_back(abs_at_most(v->expr(), run));
    h.push_back(product_bound128(ex.expr(), run, fy.expr(), run));
    h.push_back(product_bound128(ey.expr(), run, fx.expr(), run));
    h.push_back(product_bound128(ex.expr(), run, fx.expr(), run));
    h.push_back(product_bound128(ey.expr(), run, fy.expr(), run));
    const std::size_t mark = dom.mark();
    (void)F::doubles_back(ex, ey, fx, fy);
    pr.prove("A5: the doubling-back test on runs within 2^24 fits int64_t", h, ctx.bool_val(true),
             dom.obligations_since(mark));
  }

  // A6: the common point of two segments.
  if ((parts & kA6) != 0 && needs_lemmas("A6: meeting point")) {
    std::vector<z3::expr> h;
    const W x0 = wvar("mx0", Unit::kCoordRaw), y0 = wvar("my0", Unit::kCoordRaw);
    const W x1 = wvar("mx1", Unit::kCoordRaw), y1 = wvar("my1", Unit::kCoordRaw);
    const W o3 = wvar("mo3", Unit::kEdgeRaw), o4 = wvar("mo4", Unit::kEdgeRaw);
    const W left = wvar("mleft", Unit::kCoordRaw), top = wvar("mtop", Unit::kCoordRaw);
    for (const W* v : {&x0, &y0, &x1, &y1})
      h.push_back(lo_raw <= v->expr() && v->expr() <= hi_raw);
    const Int128 ov = Int128{1} << 49;
    h.push_back(abs_at_most(o3.expr(), ov) && abs_at_most(o4.expr(), ov));
    h.push_back(0 <= left.expr() && left.expr() <= ctx.int_val(F::kMaxLine));
    h.push_back(0 <= top.expr() && top.expr() <= ctx.int_val(F::kMaxTop));
    const z3::expr den = o3.expr() - o4.expr();
    const Int128 raw_max = Int128{1} << 23, run_max = Int128{1} << 24;
    h.push_back(product_bound128(x0.expr(), raw_max, den, F::kMeetDen));
    h.push_back(product_bound128(y0.expr(), raw_max, den, F::kMeetDen));
    h.push_back(product_bound128(o3.expr(), ov, x1.expr() - x0.expr(), run_max));
    h.push_back(product_bound128(o3.expr(), ov, y1.expr() - y0.expr(), run_max));
    const std::size_t mark = dom.mark();
    const formula::CellMeetPoint<W> m = F::meet_point(x0, y0, x1, y1, o3, o4);
    for (const z3::expr& line : {left.expr(), left.expr() + side, top.expr(), top.expr() + side})
      h.push_back(product_bound128(line, F::kMaxLine + F::kSide, m.den.expr(), F::kMeetDen));
    (void)F::meet_inside(m, left, top);
    pr.prove("A6: the common point of two segments: |nx|, |ny| <= 2^74, 0 <= den <= 2^50, the "
             "comparisons with the cell's lines fit __int128",
             h,
             abs_at_most(m.nx.expr(), F::kMeetNum) && abs_at_most(m.ny.expr(), F::kMeetNum) &&
                 0 <= m.den.expr() && m.den.expr() <= big(F::kMeetDen),
             dom.obligations_since(mark));
  }

  // A7: the ramp integrals and a cell's part of the integral of w.
  if ((parts & kA7) != 0 && needs_lemmas("A7: ramp integrals")) {
    std::vector<z3::expr> h;
    const W pa = wvar("ipa", Unit::kInteger), pb = wvar("ipb", Unit::kInteger);
    const W q = wvar("iq", Unit::kInteger), adx = wvar("iadx", Unit::kInteger);
    const W hgt = wvar("ih", Unit::kCoordRaw), lo = wvar("ilo", Unit::kCoordRaw);
    const I qi = ivar("iqi", Unit::kInteger), adxi = ivar("iadxi", Unit::kInteger);
    const Int128 run = Int128{1} << 24;
    h.push_back(1 <= q.expr() && q.expr() <= big(run) && 1 <= adx.expr() && adx.expr() <= big(run));
    h.push_back(qi.expr() == q.expr() && adxi.expr() == adx.expr());
    h.push_back(1 <= hgt.expr() && hgt.expr() <= side);
    h.push_back(0 <= lo.expr() && lo.expr() + side <= ctx.int_val(F::kMaxLine));
    for (const W* p : {&pa, &pb})
      h.push_back(-(big(F::kNumPerQ) * q.expr()) <= p->expr() &&
                  p->expr() <= big(F::kNumPerQ) * q.expr()); // A1
    const Int128 u_max = 3 * (Int128{1} << 46);              // |pa - lo q| <= (2^23 + 2^22) 2^24
    for (const z3::expr& line : {lo.expr(), lo.expr() + side}) {
      h.push_back(scaled_by(line, Int128{F::kMaxLine}, q.expr()));
      const z3::expr ua = pa.expr() - line * q.expr(), ub = pb.expr() - line * q.expr();
      const z3::expr up = z3::ite(ua > 0, ua, ub); // the template's select
      h.push_back(product_bound128(up, u_max, up, u_max));
      h.push_back(product_bound128(up, F::kNumPerQ << 24, up, F::kNumPerQ << 24));
      h.push_back(lemma_a(ua + ub, 2 * u_max, hgt.expr(), side));
      h.push_back(product_bound128(hgt.expr() * (ua + ub), 2 * u_max * F::kSide, adx.expr(), run));
    }
    h.push_back(product_bound128(qi.expr(), run, adxi.expr(), run));
    const std::size_t mark = dom.mark();
    const W left = F::ramp(pa, pb, q, hgt, adx, lo);
    const W right = F::ramp(pa, pb, q, hgt, adx, lo + W(F::kSide));
    const W part = left - right;
    const I den = I(2) * qi * adxi;
    pr.prove("A7: ramp integrals fit __int128, 0 <= . <= " + magnitude(F::kRamp) +
                 "; a cell's part |.| <= " + magnitude(F::kRamp) +
                 "; its denominator 2 q |dx| <= 2^49 in int64_t",
             h,
             0 <= left.expr() && left.expr() <= big(F::kRamp) && 0 <= right.expr() &&
                 right.expr() <= big(F::kRamp) && abs_at_most(part.expr(), F::kRamp) &&
                 0 < den.expr() && den.expr() <= big(Int128{1} << 49),
             dom.obligations_since(mark));
  }
}

// The obligation as its proof and the self-check run it.
inline const ProofObligation kAreaBudget{"path/area_budget",
                                         []<class F>(Prover& pr) { prove_area_budget<F>(pr); }};
// Some of its groups (AreaPart), for the mutants that target them.
template <unsigned Parts>
inline const ProofObligation kAreaBudgetPart{
    "path/area_budget", []<class F>(Prover& pr) { prove_area_budget<F>(pr, Parts); }};

} // namespace rastrules::proofs
