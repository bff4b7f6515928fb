// SPDX-License-Identifier: MIT
// Self-check of the line_aa obligations: each runs against models with one member broken
// and must REFUTE every one (with a counterexample). A mutant that survives means the
// obligation cannot tell the broken formula from the kernel's.
// rule: LINE.AA.FRAGMENT, LINE.AA.BLEND
// Expected: every mutant REFUTED; exit status 0 iff so.

#include <cstdint>

#include "line_aa/aa_formulas.hpp"
#include "support/mutation.hpp"
#include "support/prover.hpp"

namespace rastrules::proofs {
namespace {

// v = 0 counted as "less": wrong when w = 0.
struct SqrtZeroLess : AAModel {
  static constexpr const char* kName = "times_sqrt_less with v <= 0";
  static z3::expr times_sqrt_less(const z3::expr& v, const z3::expr& w, const z3::expr& D) {
    return (v <= 0) || (v * v * D < w * w);
  }
};
// Squares compared non-strictly: equality counted as "less".
struct SqrtNonStrict : AAModel {
  static constexpr const char* kName = "times_sqrt_less with <= on the squares";
  static z3::expr times_sqrt_less(const z3::expr& v, const z3::expr& w, const z3::expr& D) {
    return (v < 0) || (v * v * D <= w * w);
  }
};
// The sign test forgotten: squaring a negative v.
struct SqrtNoSign : AAModel {
  static constexpr const char* kName = "times_sqrt_less without the sign test";
  static z3::expr times_sqrt_less(const z3::expr& v, const z3::expr& w, const z3::expr& D) {
    return v * v * D < w * w;
  }
};
// Blend towards the destination.
struct BlendSwapped : AAModel {
  static constexpr const char* kName = "blend (dst - src)";
  template <class S> static S blend_numerator(S src, S sa, S dst, S cov, S den) {
    return dst * den + (dst - src) * sa * cov;
  }
};
// A 32-bit accumulator.
using BlendInt32 = AccumulatorOf<AAModel, std::int32_t, "blend in int32_t">;

} // namespace

// Both halves of the one proof line_aa/aa_formulas.cpp runs, one at a time.
MutationSelfcheck mutation_selfcheck() {
  return {"line_aa",
          {refute<SqrtZeroLess, SqrtNonStrict, SqrtNoSign>(
               "line_aa/aa_formulas", []<class F>(Prover& pr) { prove_times_sqrt_less<F>(pr); }),
           refute<BlendSwapped, BlendInt32>("line_aa/aa_formulas",
                                            []<class F>(Prover& pr) { prove_blend<F>(pr); })},
          kernel_constants()};
}

} // namespace rastrules::proofs
