// SPDX-License-Identifier: MIT
// Obligations LINE.AA.FRAGMENT (the square-root-free comparison) and LINE.AA.BLEND (the blend
// numerator), as templates over a model. Used by aa_formulas.cpp and mutants.cpp.

#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <z3++.h>

#include "rastrules/fixed.hpp"
#include "rastrules/formula/aa.hpp"
#include "support/prover.hpp"
#include "support/sym.hpp"

namespace rastrules::proofs {

// The kernel as these obligations see it: members forward to rastrules::formula (aa.hpp).
struct AAModel {
  static constexpr const char* kName = "kernel";
  // The kernel evaluates the blend numerator in std::int64_t (kernel/src/line_aa.cpp).
  using Acc = Sym<std::int64_t>;
  static constexpr std::int64_t kCoverageOne = std::int64_t{1} << 16; // kAACoverageBits

  // On real-valued Z3 terms: the comparison is an algebraic fact, proved over the reals
  // (it then holds for the integers the kernel passes, whose squares are budgeted in
  // LINE.AA.PRECISION to fit __int128).
  static z3::expr times_sqrt_less(const z3::expr& v, const z3::expr& w, const z3::expr& D) {
    return formula::times_sqrt_less<z3::expr>(v, w, D);
  }
  template <class S> static S blend_numerator(S src, S sa, S dst, S cov, S den) {
    return formula::aa_blend_numerator<S>(src, sa, dst, cov, den);
  }
};

// For all reals v, w >= 0, D > 0 and r = sqrt(D) (r >= 0, r^2 = D):
//   times_sqrt_less(v, w, D)  <=>  v * r < w.
// rule: LINE.AA.FRAGMENT
template <class F> void prove_times_sqrt_less(Prover& pr) {
  z3::context& ctx = pr.ctx();
  const z3::expr v = ctx.real_const("v");
  const z3::expr w = ctx.real_const("w");
  const z3::expr D = ctx.real_const("D");
  const z3::expr r = ctx.real_const("r");
  const std::vector<z3::expr> hyps = {w >= 0, D > 0, r >= 0, r * r == D};
  pr.prove("times_sqrt_less(v, w, D) <=> v * sqrt(D) < w  (reals, w >= 0, D > 0)", hyps,
           F::times_sqrt_less(v, w, D) == (v * r < w));
}

// For src, src_alpha, dst in [0, 255] and coverage in [0, 65536], den = 255 * 65536, with
// N = aa_blend_numerator(src, src_alpha, dst, coverage, den):
//   every intermediate fits the accumulator;
//   min(src, dst) * den <= N <= max(src, dst) * den (so N / den rounded lies between src and dst,
//   in [0, 255]);
//   coverage == 0 or src_alpha == 0 gives N == dst * den; src_alpha == 255 and full coverage give
//   N == src * den.
// rule: LINE.AA.BLEND
template <class F> void prove_blend(Prover& pr) {
  using S = typename F::Acc;
  using Rep = typename S::rep;
  Domain& dom = pr.domain();
  const S src = dom.var<Rep>("src", Unit::kInteger);
  const S sa = dom.var<Rep>("src_alpha", Unit::kInteger);
  const S dst = dom.var<Rep>("dst", Unit::kInteger);
  const S cov = dom.var<Rep>("coverage_q16", Unit::kInteger);
  z3::context& ctx = pr.ctx();
  auto k = [&](std::int64_t v) { return ctx.int_val(v); };
  auto in = [&](const S& x, std::int64_t lo, std::int64_t hi) {
    return x.expr() >= k(lo) && x.expr() <= k(hi);
  };
  const std::vector<z3::expr> hyps = {in(src, 0, 255), in(sa, 0, 255), in(dst, 0, 255),
                                      in(cov, 0, F::kCoverageOne)};
  const std::int64_t den_value = 255 * F::kCoverageOne;
  const std::size_t mark = dom.mark();
  const S den(den_value);
  const S n = F::blend_numerator(src, sa, dst, cov, den);
  const std::vector<Obligation> obligations = dom.obligations_since(mark);
  pr.watch("N", n.expr(), Unit::kInteger);
  const z3::expr N = n.expr();
  const z3::expr lo = z3::ite(src.expr() < dst.expr(), src.expr(), dst.expr()) * k(den_value);
  const z3::expr hi = z3::ite(src.expr() < dst.expr(), dst.expr(), src.expr()) * k(den_value);
  pr.prove(std::string("blend numerator: every intermediate fits ") + type_name<Rep>(), hyps,
           ctx.bool_val(true), obligations);
  pr.prove("blend numerator: min(src, dst) * den <= N <= max(src, dst) * den", hyps,
           lo <= N && N <= hi);
  pr.prove("blend numerator: coverage 0 or alpha 0 gives dst exactly", hyps,
           z3::implies(cov.expr() == 0 || sa.expr() == 0, N == dst.expr() * k(den_value)));
  pr.prove("blend numerator: alpha 255 and coverage 1 give src exactly", hyps,
           z3::implies(sa.expr() == 255 && cov.expr() == k(F::kCoverageOne),
                       N == src.expr() * k(den_value)));
}

} // namespace rastrules::proofs
