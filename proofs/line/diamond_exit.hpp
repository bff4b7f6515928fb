// SPDX-License-Identifier: MIT
// Obligations for the aliased-line diamond tests (formula/diamond.hpp), as templates over a
// model policy so that the same theorems run against the kernel (diamond_exit_matches_spec.cpp,
// diamond_no_overflow.cpp) and against broken models (selftest_mutants.cpp).
//
// RealNum instantiates the formulas on Z3 real terms: the kernel's formulas use only + - * and
// comparisons, so over the reals they state the same test the kernel computes on integers
// (exactly, when nothing overflows: diamond_no_overflow.cpp). The spec side is written from the
// words of LINE.D3D.TEST_AREA / LINE.VK.TEST_AREA on |u| + |v| and the signs of u and v, and
// "the segment meets T" is literally "some t in [0, 1] has a + t (b - a) in T".

#pragma once

#include <chrono>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "rastrules/fixed.hpp"
#include "rastrules/formula/diamond.hpp"
#include "support/prover.hpp"
#include "support/sym.hpp"

namespace rastrules::proofs {

// A real number term in the active Domain's context (see sym.hpp for the pattern).
class RealNum {
 public:
  explicit RealNum(std::int64_t v) : e_(Domain::active().ctx().real_val(v)) {}
  explicit RealNum(z3::expr e) : e_(std::move(e)) {}
  [[nodiscard]] const z3::expr& expr() const { return e_; }

  friend RealNum operator+(const RealNum& a, const RealNum& b) { return RealNum(a.e_ + b.e_); }
  friend RealNum operator-(const RealNum& a, const RealNum& b) { return RealNum(a.e_ - b.e_); }
  friend RealNum operator*(const RealNum& a, const RealNum& b) { return RealNum(a.e_ * b.e_); }
  friend RealNum operator-(const RealNum& a) { return RealNum(-a.e_); }
  friend SymBool operator==(const RealNum& a, const RealNum& b) { return SymBool(a.e_ == b.e_); }
  friend SymBool operator!=(const RealNum& a, const RealNum& b) { return SymBool(a.e_ != b.e_); }
  friend SymBool operator<(const RealNum& a, const RealNum& b) { return SymBool(a.e_ < b.e_); }
  friend SymBool operator<=(const RealNum& a, const RealNum& b) { return SymBool(a.e_ <= b.e_); }
  friend SymBool operator>(const RealNum& a, const RealNum& b) { return SymBool(a.e_ > b.e_); }
  friend SymBool operator>=(const RealNum& a, const RealNum& b) { return SymBool(a.e_ >= b.e_); }

 private:
  z3::expr e_;
};

// The kernel's D3D diamond formulas.
struct DiamondKernelModel {
  static constexpr const char* kName = "kernel";
  template <bool YMajor, class M>
  static auto meets(const M& au, const M& av, const M& du, const M& dv, const M& h) {
    return formula::d3d_meets<YMajor, M>(au, av, du, dv, h);
  }
  template <bool YMajor, class M>
  static auto contains(const M& pu, const M& pv, const M& h) {
    return formula::d3d_contains<YMajor, M>(pu, pv, h);
  }
  template <bool YMajor, class M>
  static auto exits(const M& au, const M& av, const M& bu, const M& bv, const M& h) {
    return formula::d3d_exits<YMajor, M>(au, av, bu, bv, h);
  }
  template <class M>
  static auto vk_contains(const M& pu, const M& pv, const M& h) {
    return formula::vk_contains<M>(pu, pv, h);
  }
};

// |x| as a Z3 term.
inline z3::expr abs_term(const z3::expr& x) { return z3::ite(x >= 0, x, -x); }

// LINE.D3D.TEST_AREA in the spec's words, for a point (u, v) relative to the centre:
// inside the open diamond; or on the boundary (|u| + |v| = h) at a lower edge or the bottom
// corner (exactly the boundary points with v > 0: lower-left edge u < 0 < v, lower-right edge
// u, v > 0, bottom corner u = 0, v = h); or, y-major only, the right corner (h, 0).
// rule: LINE.D3D.TEST_AREA, LINE.DIAMOND.GEOMETRY
inline z3::expr spec_in_d3d_area(bool y_major, const z3::expr& u, const z3::expr& v,
                                 const z3::expr& h) {
  const z3::expr l1 = abs_term(u) + abs_term(v);
  const z3::expr lower_left_edge = (l1 == h) && (u < 0) && (v > 0);
  const z3::expr lower_right_edge = (l1 == h) && (u > 0) && (v > 0);
  const z3::expr bottom_corner = (u == 0) && (v == h);
  const z3::expr right_corner = (u == h) && (v == 0);
  z3::expr in = (l1 < h) || lower_left_edge || lower_right_edge || bottom_corner;
  if (y_major) in = in || right_corner;
  return in;
}

// LINE.VK.TEST_AREA for a point, in words: the open diamond, the open upper-right and
// lower-right edges and the right corner.
// rule: LINE.VK.TEST_AREA
inline z3::expr spec_in_vk_point_area(const z3::expr& u, const z3::expr& v, const z3::expr& h) {
  const z3::expr l1 = abs_term(u) + abs_term(v);
  const z3::expr upper_right_edge = (l1 == h) && (u > 0) && (v < 0);
  const z3::expr lower_right_edge = (l1 == h) && (u > 0) && (v > 0);
  const z3::expr right_corner = (u == h) && (v == 0);
  return (l1 < h) || upper_right_edge || lower_right_edge || right_corner;
}

// Nonlinear real theorems (products of the segment parameter with the direction) go to Z3's
// complete procedure for quantifier-free nonlinear real arithmetic (the qfnra-nlsat tactic),
// which the shared Prover's integer pipeline does not use. Same report format: one line per
// theorem with PROVED / REFUTED / UNKNOWN and the time; a counterexample on REFUTED.
class NraProver {
 public:
  explicit NraProver(z3::context& ctx) : ctx_(ctx) {}

  Status prove(const std::string& name, const std::vector<z3::expr>& hyps, const z3::expr& goal,
               const std::vector<std::pair<std::string, z3::expr>>& show) {
    const auto start = std::chrono::steady_clock::now();
    z3::solver s = z3::tactic(ctx_, "qfnra-nlsat").mk_solver();
    z3::params p(ctx_);
    p.set("timeout", 30000u);
    s.set(p);
    z3::solver pre = z3::tactic(ctx_, "qfnra-nlsat").mk_solver();
    pre.set(p);
    for (const z3::expr& h : hyps) {
      s.add(h);
      pre.add(h);
    }
    Status status = Status::kUnknown;
    std::string note;
    if (!hyps.empty() && pre.check() != z3::sat) {
      note = " -- hypotheses not shown satisfiable";
    } else {
      s.add(!goal);
      const z3::check_result r = s.check();
      if (r == z3::unsat) {
        status = Status::kProved;
      } else if (r == z3::sat) {
        status = Status::kRefuted;
        const z3::model m = s.get_model();
        note = "\n  counterexample (raw units):";
        for (const auto& [n, e] : show) note += "\n    " + n + " = " + m.eval(e, true).to_string();
      } else {
        note = " -- solver gave up: " + s.reason_unknown();
      }
    }
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << to_string(status) << " " << name << " (" << std::fixed << std::setprecision(2)
              << secs << " s, qfnra-nlsat)" << note << "\n";
    std::cout.flush();
    results_.emplace_back(name, status);
    return status;
  }

  [[nodiscard]] const std::vector<std::pair<std::string, Status>>& results() const {
    return results_;
  }
  [[nodiscard]] bool all_proved() const {
    for (const auto& r : results_)
      if (r.second != Status::kProved) return false;
    return !results_.empty();
  }

 private:
  z3::context& ctx_;
  std::vector<std::pair<std::string, Status>> results_;
};

// For the x-major and the y-major test area, over all real positions (relative to the pixel
// centre, h = kSubpixelHalf raw):
//   contains(p)        <=> p in T (spec words);                              [Prover, linear]
//   exits(a, b)        <=> meets(a, b - a) and not contains(b);              [Prover]
//   a + t d in T for some t in [0, 1]  =>  meets(a, d);                      [nlsat, t free]
// Not proved here: the converse, meets(a, d) => some a + t d in T (the solver times out on it,
// with the quantifier and with an explicit witness alike). It is checked against the exact
// oracle by properties/line/line_props.cpp instead.
// rule: LINE.D3D.TEST_AREA, LINE.D3D.EXIT, LINE.DIAMOND.GEOMETRY
template <class F>
void prove_d3d_diamond_exit(Prover& pr, NraProver& nra) {
  Domain& dom = pr.domain();
  z3::context& ctx = dom.ctx();
  const RealNum h(kSubpixelHalf);
  for (const bool y_major : {false, true}) {
    const std::string axis = y_major ? "y-major" : "x-major";
    const std::string sfx = y_major ? "_y" : "_x";
    const z3::expr au = ctx.real_const(("au" + sfx).c_str()), av = ctx.real_const(("av" + sfx).c_str());
    const z3::expr bu = ctx.real_const(("bu" + sfx).c_str()), bv = ctx.real_const(("bv" + sfx).c_str());
    const z3::expr t = ctx.real_const(("t" + sfx).c_str());
    const z3::expr du = bu - au, dv = bv - av;
    const RealNum A(au), B(av), Bu(bu), Bv(bv), Du(du), Dv(dv);
    const z3::expr kmeets = y_major ? F::template meets<true>(A, B, Du, Dv, h).expr()
                                    : F::template meets<false>(A, B, Du, Dv, h).expr();
    auto kcontains = [&](const RealNum& pu, const RealNum& pv) {
      return y_major ? F::template contains<true>(pu, pv, h).expr()
                     : F::template contains<false>(pu, pv, h).expr();
    };
    const z3::expr kexits = y_major ? F::template exits<true>(A, B, Bu, Bv, h).expr()
                                    : F::template exits<false>(A, B, Bu, Bv, h).expr();
    const z3::expr hv = h.expr();
    auto on_segment_in_t = [&](const z3::expr& tt) {
      return (tt >= 0) && (tt <= 1) && spec_in_d3d_area(y_major, au + tt * du, av + tt * dv, hv);
    };
    const std::vector<std::pair<std::string, z3::expr>> show = {
        {"a - centre (u)", au}, {"a - centre (v)", av}, {"b - centre (u)", bu}, {"b - centre (v)", bv}};

    pr.watch("b - centre (u)", bu, Unit::kCoordRaw);
    pr.watch("b - centre (v)", bv, Unit::kCoordRaw);
    pr.prove("contains<" + axis + ">(b) <=> b in the D3D test area (spec words)", {},
             kcontains(Bu, Bv) == spec_in_d3d_area(y_major, bu, bv, hv));
    pr.prove("exits<" + axis + ">(a, b) <=> meets(a, b - a) and not contains(b)", {},
             kexits == (kmeets && !kcontains(Bu, Bv)));

    auto with_t = show;
    with_t.emplace_back("t", t);
    nra.prove("a + t (b - a) in T for some t in [0, 1]  =>  meets<" + axis + ">(a, b - a)",
              {on_segment_in_t(t)}, kmeets, with_t);

  }
}

// vk_contains(p) <=> p in the Vulkan point test area (spec words), over all real positions.
// rule: LINE.VK.TEST_AREA
template <class F>
void prove_vk_point_area(Prover& pr) {
  z3::context& ctx = pr.ctx();
  const RealNum h(kSubpixelHalf);
  const z3::expr pu = ctx.real_const("pu_vk"), pv = ctx.real_const("pv_vk");
  pr.watch("p - centre (u)", pu, Unit::kCoordRaw);
  pr.watch("p - centre (v)", pv, Unit::kCoordRaw);
  pr.prove("vk_contains(p) <=> p - (e, e^2) in the open diamond for small e: interior, right edges, right corner",
           {}, F::vk_contains(RealNum(pu), RealNum(pv), h).expr() ==
                   spec_in_vk_point_area(pu, pv, h.expr()));
}

// Every intermediate of d3d_exits (x-major and y-major) and vk_exits, evaluated on std::int64_t
// as the kernel does, fits int64_t when the end points relative to the pixel centre lie in
// (-2^24, 2^24) raw: a, b in SNAP.VERTEX.RANGE ([-2^23, 2^23)) and a centre of a pixel of a
// target of at most kMaxTargetSide pixels (in [128, 2^22 + 128)).
// rule: LINE.D3D.EXIT, LINE.VK.EXIT
template <class Acc>
void prove_diamond_no_overflow(Prover& pr) {
  Domain& dom = pr.domain();
  const Acc au = dom.var<typename Acc::rep>("au", Unit::kCoordRaw);
  const Acc av = dom.var<typename Acc::rep>("av", Unit::kCoordRaw);
  const Acc bu = dom.var<typename Acc::rep>("bu", Unit::kCoordRaw);
  const Acc bv = dom.var<typename Acc::rep>("bv", Unit::kCoordRaw);
  const z3::expr lim = dom.ctx().int_val(std::int64_t{1} << 24);
  // Assumes: SNAP.VERTEX.RANGE, SCENE.TARGET.LIMITS
  std::vector<z3::expr> hyps;
  for (const Acc* v : {&au, &av, &bu, &bv}) {
    hyps.push_back(v->expr() > -lim && v->expr() < lim);
  }
  const std::string type = type_name<typename Acc::rep>();
  {
    const std::size_t mark = dom.mark();
    const Acc h(kSubpixelHalf);
    (void)formula::d3d_exits<false, Acc>(au, av, bu, bv, h);
    pr.prove("d3d_exits<x-major>: every intermediate fits " + type, hyps, dom.ctx().bool_val(true),
             dom.obligations_since(mark));
  }
  {
    const std::size_t mark = dom.mark();
    const Acc h(kSubpixelHalf);
    (void)formula::d3d_exits<true, Acc>(au, av, bu, bv, h);
    pr.prove("d3d_exits<y-major>: every intermediate fits " + type, hyps, dom.ctx().bool_val(true),
             dom.obligations_since(mark));
  }
  {
    const std::size_t mark = dom.mark();
    const Acc h(kSubpixelHalf);
    (void)formula::vk_exits<Acc>(au, av, bu, bv, h);
    pr.prove("vk_exits: every intermediate fits " + type, hyps, dom.ctx().bool_val(true),
             dom.obligations_since(mark));
  }
}

}  // namespace rastrules::proofs
