// SPDX-License-Identifier: MIT
// Obligations for the aliased-line diamond tests (formula/diamond.hpp), as templates over a
// model policy so that the same theorems run against the kernel (diamond_exit_matches_spec.cpp,
// diamond_no_overflow.cpp) and against broken models (mutants.cpp). The D3D "meets"
// test is proved equal to "some point of the segment lies in T" in both directions:
// prove_d3d_diamond_exit (point in T => meets) and prove_d3d_meets_witness (meets => an
// explicit point in T). Not proved: the same converse for the Vulkan vk_meets (its perturbed
// "for every small e" statement); vk_contains is proved equal to its spec words.
//
// RealNum instantiates the formulas on Z3 real terms: the kernel's formulas use only + - * and
// comparisons, so over the reals they state the same test the kernel computes on integers
// (exactly, when nothing overflows: diamond_no_overflow.cpp). The spec side is written from the
// words of LINE.D3D.TEST_AREA / LINE.VK.TEST_AREA on |u| + |v| and the signs of u and v, and
// "the segment meets T" is literally "some t in [0, 1] has a + t (b - a) in T".

#pragma once

#include <array>
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
class RealNum : public TermComparisons<RealNum> {
public:
  explicit RealNum(std::int64_t v) : e_(Domain::active().ctx().real_val(v)) {}
  explicit RealNum(z3::expr e) : e_(std::move(e)) {}
  [[nodiscard]] const z3::expr& expr() const { return e_; }

  friend RealNum operator+(const RealNum& a, const RealNum& b) { return RealNum(a.e_ + b.e_); }
  friend RealNum operator-(const RealNum& a, const RealNum& b) { return RealNum(a.e_ - b.e_); }
  friend RealNum operator*(const RealNum& a, const RealNum& b) { return RealNum(a.e_ * b.e_); }
  friend RealNum operator-(const RealNum& a) { return RealNum(-a.e_); }

private:
  z3::expr e_;
};

// The kernel's D3D diamond formulas, a line of major axis YMajor tested against the test area
// of major axis AreaOf(YMajor): its own in the kernel (DiamondKernelModel), another one in
// line/mutants.cpp.
template <bool (*AreaOf)(bool)> struct DiamondAreaModel {
  template <bool YMajor, class M>
  static auto meets(const M& au, const M& av, const M& du, const M& dv, const M& h) {
    return formula::d3d_meets<AreaOf(YMajor), M>(au, av, du, dv, h);
  }
  template <bool YMajor, class M> static auto contains(const M& pu, const M& pv, const M& h) {
    return formula::d3d_contains<AreaOf(YMajor), M>(pu, pv, h);
  }
  template <bool YMajor, class M>
  static auto exits(const M& au, const M& av, const M& bu, const M& bv, const M& h) {
    return formula::d3d_exits<AreaOf(YMajor), M>(au, av, bu, bv, h);
  }
  template <class M> static auto vk_contains(const M& pu, const M& pv, const M& h) {
    return formula::vk_contains<M>(pu, pv, h);
  }
};

constexpr bool own_area(bool y_major) {
  return y_major;
}

struct DiamondKernelModel : DiamondAreaModel<own_area> {
  static constexpr const char* kName = "kernel";
};

// |x| as a Z3 term.
inline z3::expr abs_term(const z3::expr& x) {
  return z3::ite(x >= 0, x, -x);
}

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
  if (y_major)
    in = in || right_corner;
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
// which the shared Prover's integer pipeline does not use; the few that contain a real
// division go to Z3's default solver instead (Engine::kDefault). Same report format: one line
// per theorem with PROVED / REFUTED / UNKNOWN and the time; a counterexample on REFUTED.
class NraProver {
public:
  explicit NraProver(z3::context& ctx) : ctx_(ctx) {}

  // kNlsat: the qfnra-nlsat tactic; kDefault: Z3's default solver (for terms with division).
  enum class Engine { kNlsat, kDefault };

  Status prove(const std::string& name, const std::vector<z3::expr>& hyps, const z3::expr& goal,
               const std::vector<std::pair<std::string, z3::expr>>& show,
               Engine engine = Engine::kNlsat) {
    const auto start = std::chrono::steady_clock::now();
    auto make = [&] {
      return engine == Engine::kNlsat ? z3::tactic(ctx_, "qfnra-nlsat").mk_solver()
                                      : z3::solver(ctx_);
    };
    z3::solver s = make();
    z3::params p(ctx_);
    p.set("timeout", 30000u);
    s.set(p);
    z3::solver pre = make();
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
        for (const auto& [n, e] : show)
          note += "\n    " + n + " = " + m.eval(e, true).to_string();
      } else {
        note = " -- solver gave up: " + s.reason_unknown();
      }
    }
    const double secs =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << to_string(status) << " " << name << " (" << std::fixed << std::setprecision(2)
              << secs << (engine == Engine::kNlsat ? " s, qfnra-nlsat)" : " s, z3 default solver)")
              << note << "\n";
    std::cout.flush();
    results_.emplace_back(name, status);
    return status;
  }

  [[nodiscard]] const std::vector<std::pair<std::string, Status>>& results() const {
    return results_;
  }
  [[nodiscard]] bool all_proved() const {
    for (const auto& r : results_)
      if (r.second != Status::kProved)
        return false;
    return !results_.empty();
  }

private:
  z3::context& ctx_;
  std::vector<std::pair<std::string, Status>> results_;
};

// The Boolean skeleton of e: every maximal non-Boolean atom (a comparison of numbers, for
// example) is replaced by a fresh Boolean constant, the same constant for the same atom (Z3
// terms are hash-consed, so an atom built twice by the same code is the same term). If the
// skeleton of (hypotheses => goal) is a tautology, so is the formula itself: the theorem
// step that only chains proved lemmas is checked this way, without arithmetic.
inline z3::expr boolean_skeleton(const z3::expr& e,
                                 std::vector<std::pair<z3::expr, z3::expr>>& atoms) {
  if (e.is_app()) {
    const Z3_decl_kind k = e.decl().decl_kind();
    const bool connective = k == Z3_OP_AND || k == Z3_OP_OR || k == Z3_OP_NOT ||
                            k == Z3_OP_IMPLIES || k == Z3_OP_XOR || k == Z3_OP_IFF ||
                            k == Z3_OP_TRUE || k == Z3_OP_FALSE ||
                            ((k == Z3_OP_EQ || k == Z3_OP_ITE || k == Z3_OP_DISTINCT) &&
                             e.num_args() > 1 && e.arg(1).is_bool());
    if (connective) {
      z3::expr_vector args(e.ctx());
      for (unsigned i = 0; i < e.num_args(); ++i)
        args.push_back(boolean_skeleton(e.arg(i), atoms));
      return e.num_args() == 0 ? e : e.decl()(args);
    }
  }
  for (const auto& [atom, var] : atoms)
    if (z3::eq(atom, e))
      return var;
  const z3::expr var = e.ctx().bool_const(("atom!" + std::to_string(atoms.size())).c_str());
  atoms.emplace_back(e, var);
  return var;
}

// For the x-major and the y-major test area, over all real positions (relative to the pixel
// centre, h = kSubpixelHalf raw):
//   contains(p)        <=> p in T (spec words);                              [Prover, linear]
//   exits(a, b)        <=> meets(a, b - a) and not contains(b);              [Prover]
//   a + t d in T for some t in [0, 1]  =>  meets(a, d);                      [nlsat, t free]
// The converse, meets(a, d) => some a + t d in T, times out as one query (with the quantifier
// and with one explicit witness alike); it is proved in lemmas by prove_d3d_meets_witness below.
// rule: LINE.D3D.TEST_AREA, LINE.D3D.EXIT, LINE.DIAMOND.GEOMETRY
template <class F> void prove_d3d_diamond_exit(Prover& pr, NraProver& nra) {
  Domain& dom = pr.domain();
  z3::context& ctx = dom.ctx();
  const RealNum h(kSubpixelHalf);
  for (const bool y_major : {false, true}) {
    const std::string axis = y_major ? "y-major" : "x-major";
    const std::string sfx = y_major ? "_y" : "_x";
    const z3::expr au = ctx.real_const(("au" + sfx).c_str()),
                   av = ctx.real_const(("av" + sfx).c_str());
    const z3::expr bu = ctx.real_const(("bu" + sfx).c_str()),
                   bv = ctx.real_const(("bv" + sfx).c_str());
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
    const std::vector<std::pair<std::string, z3::expr>> show = {{"a - centre (u)", au},
                                                                {"a - centre (v)", av},
                                                                {"b - centre (u)", bu},
                                                                {"b - centre (v)", bv}};

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

// The converse of the last theorem above, for the D3D test area: meets<axis>(a, d) => some
// a + t d, t in [0, 1], lies in T. Z3 4.8.12 does not prove it in one query (with the
// quantifier or with one explicit witness), so it is split into lemmas, each a small query,
// all stated over free real variables and used, instantiated, as hypotheses of the theorem.
// The spec side is the proof's own: T (x-major, LINE.D3D.TEST_AREA's "equivalently" form) is
// the four half-planes s·p (< or <=) h below; p(t) = a + t d lies in half-plane k iff
// t m_k (<|<=) r_k with m_k = s·d, r_k = h - s·a; constraints 4 and 5 are -t <= 0 and t <= 1.
// q_k stands for the bound r_k / m_k: free reals with the hypothesis m_k != 0 => q_k m_k = r_k
// (and tc with len2 != 0 => tc len2 = dot, len2 = 0 => tc = 0).
//   DEFS  such q_k and tc exist for every a, d: q_k = r_k / m_k (0 if m_k = 0) and
//         tc = dot / len2 (0 if d = 0) satisfy them.              [Z3 default solver, division]
//   FM    meets<axis>(a, d) [and, y-major, not on_segment((h, 0), a, d)]  =>  every constraint
//         with m_k = 0 holds at any t, and every lower bound q_i (m_i < 0) is below every upper
//         bound q_j (m_j > 0), strictly unless both are non-strict.       [nlsat; the kernel]
//   ORDER the witness t_fm = (L + U) / 2, L = max{0, q_i : m_i < 0}, U = min{1, q_j : m_j > 0},
//         is above every lower and below every upper bound, with the strictness of each.
//         [linear; no kernel term]
//   BACKk for any t: t beyond q_k on the side m_k asks (or m_k = 0 and 0 (<|<=) r_k)
//         => t m_k (<|<=) r_k.                                         [nlsat, one per k]
//   SPEC  any t with every t m_k (<|<=) r_k (so 0 <= t <= 1) has a + t d in T (spec words).
//   CORNER (y-major) the kernel's on_segment((h, 0), a, d) => tc = dot / len2 (tc = 0 if
//         d = 0) lies in [0, 1] and a + tc d = (h, 0), the right corner, which is in T.
//   THEOREM meets<axis>(a, d) => t* in [0, 1] and a + t* d in T, with t* = tc if
//         on_segment((h, 0), a, d) (y-major; the kernel's predicate is used only as a case
//         split, sound for any predicate) and t_fm otherwise, for all q_k, tc meeting their
//         definitions: from the lemmas instantiated at these terms. This step is checked on
//         the Boolean skeleton (boolean_skeleton): a propositional tautology, no arithmetic.
// Every lemma is always run; if one is not PROVED the theorem is UNKNOWN (skipped).
// rule: LINE.D3D.TEST_AREA, LINE.DIAMOND.GEOMETRY
template <class F> void prove_d3d_meets_witness(Prover& pr, NraProver& nra) {
  z3::context& ctx = pr.ctx();
  const RealNum h(kSubpixelHalf);
  const z3::expr hv = h.expr();
  const z3::expr zero = ctx.real_val(0), one = ctx.real_val(1);
  // The half-planes of T (x-major), in the spec's words: lower edges included, upper excluded.
  struct HalfPlane {
    int s1, s2;
    bool strict;
  };
  const std::array<HalfPlane, 4> planes = {{
      {+1, +1, false}, // u + v <= h   (lower-right edge included)
      {-1, +1, false}, // -u + v <= h  (lower-left edge included)
      {+1, -1, true},  // u - v < h    (upper-right edge excluded)
      {-1, -1, true},  // -u - v < h   (upper-left edge excluded)
  }};
  for (const bool y_major : {false, true}) {
    const std::string axis = y_major ? "y-major" : "x-major";
    const std::string sfx = "_w" + std::string(y_major ? "y" : "x");
    const z3::expr au = ctx.real_const(("au" + sfx).c_str()),
                   av = ctx.real_const(("av" + sfx).c_str());
    const z3::expr du = ctx.real_const(("du" + sfx).c_str()),
                   dv = ctx.real_const(("dv" + sfx).c_str());
    const z3::expr t = ctx.real_const(("t" + sfx).c_str());
    const z3::expr tc = ctx.real_const(("tc" + sfx).c_str());
    auto sgn = [](int s, const z3::expr& x) { return s > 0 ? x : -x; };
    std::vector<z3::expr> m, r, q;
    std::vector<bool> strict;
    for (std::size_t k = 0; k < 4; ++k) {
      const HalfPlane& pl = planes[k];
      m.push_back(sgn(pl.s1, du) + sgn(pl.s2, dv));
      r.push_back(hv - (sgn(pl.s1, au) + sgn(pl.s2, av)));
      q.push_back(ctx.real_const(("q" + std::to_string(k) + sfx).c_str()));
      strict.push_back(pl.strict);
    }
    m.push_back(-one), r.push_back(zero), q.push_back(zero), strict.push_back(false); // -t <= 0
    m.push_back(one), r.push_back(one), q.push_back(one), strict.push_back(false);    // t <= 1
    const std::size_t n = m.size();

    std::vector<z3::expr> defs; // q_k is r_k / m_k
    for (std::size_t k = 0; k < 4; ++k)
      defs.push_back(z3::implies(m[k] != 0, q[k] * m[k] == r[k]));
    auto rel = [](bool s, const z3::expr& x, const z3::expr& y) { return s ? x < y : x <= y; };
    // Constraint k at t, and its form as a bound on t.
    auto holds_at = [&](std::size_t k, const z3::expr& tt) {
      return rel(strict[k], tt * m[k], r[k]);
    };
    auto bound_ok = [&](std::size_t k, const z3::expr& tt) {
      return z3::implies(m[k] < 0, rel(strict[k], q[k], tt)) &&
             z3::implies(m[k] > 0, rel(strict[k], tt, q[k])) &&
             z3::implies(m[k] == 0, rel(strict[k], zero, r[k]));
    };
    // FM's conclusion.
    z3::expr fm = ctx.bool_val(true);
    for (std::size_t k = 0; k < n; ++k)
      fm = fm && z3::implies(m[k] == 0, rel(strict[k], zero, r[k]));
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        if (i != j)
          fm = fm && z3::implies(m[i] < 0 && m[j] > 0, rel(strict[i] || strict[j], q[i], q[j]));
    // The witness t_fm.
    z3::expr lo = zero, up = one;
    for (std::size_t k = 0; k < 4; ++k) {
      const z3::expr lk = z3::ite(m[k] < 0, q[k], zero), uk = z3::ite(m[k] > 0, q[k], one);
      lo = z3::ite(lk > lo, lk, lo);
      up = z3::ite(uk < up, uk, up);
    }
    const z3::expr t_fm = (lo + up) / ctx.real_val(2);
    // The corner witness tc = dot / len2 for q = (h, 0).
    const z3::expr dot = (hv - au) * du + (zero - av) * dv, len2 = du * du + dv * dv;
    const z3::expr tc_def =
        z3::implies(len2 != 0, tc * len2 == dot) && z3::implies(len2 == 0, tc == 0);
    const RealNum A(au), B(av), Du(du), Dv(dv);
    const z3::expr kmeets = y_major ? F::template meets<true>(A, B, Du, Dv, h).expr()
                                    : F::template meets<false>(A, B, Du, Dv, h).expr();
    const z3::expr on_corner = formula::on_segment(h, RealNum(0), A, B, Du, Dv).expr();
    auto in_t_at = [&](const z3::expr& tt) {
      return (tt >= 0) && (tt <= 1) && spec_in_d3d_area(y_major, au + tt * du, av + tt * dv, hv);
    };
    std::vector<std::pair<std::string, z3::expr>> show = {
        {"a - centre (u)", au}, {"a - centre (v)", av}, {"d (u)", du}, {"d (v)", dv}};
    const std::string pre = "reverse<" + axis + "> ";
    std::vector<z3::expr> lemmas; // proved lemma statements, for the theorem
    bool ok = true;
    auto run_nra = [&](const std::string& name, std::vector<z3::expr> hyps, const z3::expr& goal,
                       const std::vector<std::pair<std::string, z3::expr>>& sh) {
      z3::expr stmt = goal;
      if (!hyps.empty()) {
        z3::expr all = hyps[0];
        for (std::size_t k = 1; k < hyps.size(); ++k)
          all = all && hyps[k];
        stmt = z3::implies(all, goal);
      }
      ok = (nra.prove(pre + name, hyps, goal, sh) == Status::kProved) && ok;
      lemmas.push_back(stmt);
    };

    // FM (the only lemma about the kernel's formula).
    std::vector<z3::expr> fm_hyps = defs;
    fm_hyps.push_back(kmeets);
    if (y_major)
      fm_hyps.push_back(!on_corner);
    run_nra("lemma FM: meets (off the right corner) => bounds compatible", fm_hyps, fm, show);
    // ORDER (linear).
    {
      z3::expr goal = ctx.bool_val(true);
      for (std::size_t k = 0; k < n; ++k)
        goal = goal && bound_ok(k, t_fm);
      run_nra("lemma ORDER: t_fm = (L + U) / 2 within every bound", {fm}, goal, show);
    }
    // BACK_k at a free t, then instantiated at t_fm for the theorem.
    for (std::size_t k = 0; k < n; ++k) {
      std::vector<z3::expr> hyps;
      if (k < 4)
        hyps.push_back(defs[k]);
      hyps.push_back(bound_ok(k, t));
      auto sh = show;
      sh.emplace_back("t", t);
      run_nra("lemma BACK" + std::to_string(k) + ": bound on t => t m_k (<|<=) r_k", hyps,
              holds_at(k, t), sh);
      const z3::expr inst = holds_at(k, t_fm);
      const z3::expr h_inst = bound_ok(k, t_fm);
      lemmas.back() = (k < 4) ? z3::implies(defs[k] && h_inst, inst) : z3::implies(h_inst, inst);
    }
    // SPEC at a free t.
    {
      std::vector<z3::expr> hyps;
      for (std::size_t k = 0; k < n; ++k)
        hyps.push_back(holds_at(k, t));
      auto sh = show;
      sh.emplace_back("t", t);
      run_nra("lemma SPEC: every t m_k (<|<=) r_k => a + t d in T (spec words)", hyps, in_t_at(t),
              sh);
      z3::expr all = holds_at(0, t_fm);
      for (std::size_t k = 1; k < n; ++k)
        all = all && holds_at(k, t_fm);
      lemmas.back() = z3::implies(all, in_t_at(t_fm));
    }
    z3::expr witness = t_fm;
    if (y_major) {
      auto sh = show;
      sh.emplace_back("tc", tc);
      run_nra("lemma CORNER: on_segment((h, 0), a, d) => a + tc d = right corner, tc in [0, 1]",
              {on_corner, tc_def}, in_t_at(tc) && (au + tc * du == hv) && (av + tc * dv == 0), sh);
      witness = z3::ite(on_corner, tc, t_fm);
    }
    const std::string thm =
        "meets<" + axis + ">(a, d) => a + t* d in T, t* in [0, 1] (witness; lemmas chained)";
    if (!ok) {
      pr.skip(thm, "relies on a lemma that was not proved");
      continue;
    }
    // The witnesses exist for every a, d: q_k = r_k / m_k (0 when m_k = 0) and tc = dot / len2
    // (0 when d = 0) satisfy the definitions. One query per definition, on Z3's default solver
    // (real division, with x / 0 unspecified; nlsat does not take division).
    {
      std::vector<z3::expr> inst;
      for (std::size_t k = 0; k < 4; ++k) {
        z3::expr_vector from(ctx), to(ctx);
        from.push_back(q[k]);
        to.push_back(z3::ite(m[k] != 0, r[k] / m[k], zero));
        inst.push_back(defs[k].substitute(from, to));
      }
      z3::expr_vector from(ctx), to(ctx);
      from.push_back(tc);
      to.push_back(z3::ite(len2 != 0, dot / len2, zero));
      z3::expr tc_inst = tc_def;
      inst.push_back(tc_inst.substitute(from, to));
      bool defs_ok = true;
      for (std::size_t k = 0; k < inst.size(); ++k) {
        const std::string what = k < 4 ? "q" + std::to_string(k) + " = r / m" : "tc = dot / len2";
        defs_ok = (nra.prove(pre + "lemma DEFS: " + what + " satisfies its definition", {}, inst[k],
                             show, NraProver::Engine::kDefault) == Status::kProved) &&
                  defs_ok;
      }
      if (!defs_ok) {
        pr.skip(thm, "relies on a lemma that was not proved");
        continue;
      }
    }
    // The theorem's own hypotheses are satisfiable (so it is not vacuous): nlsat.
    std::vector<z3::expr> base = defs;
    base.push_back(tc_def);
    base.push_back(kmeets);
    {
      z3::solver sat = z3::tactic(ctx, "qfnra-nlsat").mk_solver();
      for (const z3::expr& b : base)
        sat.add(b);
      if (sat.check() != z3::sat) {
        pr.skip(thm, "hypotheses not shown satisfiable");
        continue;
      }
    }
    // t* = tc on the right corner (y-major), t_fm otherwise; the goal names the case.
    const z3::expr goal = y_major ? z3::ite(on_corner, in_t_at(tc), in_t_at(t_fm)) : in_t_at(t_fm);
    std::vector<std::pair<z3::expr, z3::expr>> atoms;
    std::vector<z3::expr> skel_hyps;
    for (const z3::expr& b : base)
      skel_hyps.push_back(boolean_skeleton(b, atoms));
    for (const z3::expr& l : lemmas)
      skel_hyps.push_back(boolean_skeleton(l, atoms));
    const z3::expr skel_goal = boolean_skeleton(goal, atoms);
    pr.prove(thm, skel_hyps, skel_goal);
  }
}

// vk_contains(p) <=> p in the Vulkan point test area (spec words), over all real positions.
// rule: LINE.VK.TEST_AREA
template <class F> void prove_vk_point_area(Prover& pr) {
  z3::context& ctx = pr.ctx();
  const RealNum h(kSubpixelHalf);
  const z3::expr pu = ctx.real_const("pu_vk"), pv = ctx.real_const("pv_vk");
  pr.watch("p - centre (u)", pu, Unit::kCoordRaw);
  pr.watch("p - centre (v)", pv, Unit::kCoordRaw);
  pr.prove("vk_contains(p) <=> p - (e, e^2) in the open diamond for small e: interior, right "
           "edges, right corner",
           {},
           F::vk_contains(RealNum(pu), RealNum(pv), h).expr() ==
               spec_in_vk_point_area(pu, pv, h.expr()));
}

// Every intermediate of d3d_exits (x-major and y-major) and vk_exits, evaluated on std::int64_t
// as the kernel does, fits int64_t when the end points relative to the pixel centre lie in
// (-2^24, 2^24) raw: a, b in SNAP.VERTEX.RANGE ([-2^23, 2^23)) and a centre of a pixel of a
// target of at most kMaxTargetSide pixels (in [128, 2^22 + 128)).
// rule: LINE.D3D.EXIT, LINE.VK.EXIT
template <class Acc> void prove_diamond_no_overflow(Prover& pr) {
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

} // namespace rastrules::proofs
