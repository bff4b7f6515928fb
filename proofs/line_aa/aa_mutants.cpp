// SPDX-License-Identifier: MIT
// Self-check of the line_aa obligations: each runs against models with one member broken
// and must REFUTE every one (with a counterexample). A mutant that survives means the
// obligation cannot tell the broken formula from the kernel's.
// rule: LINE.AA.FRAGMENT, LINE.AA.BLEND
// Expected: every mutant REFUTED; exit status 0 iff so.

#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "line_aa/aa_formulas.hpp"
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
struct BlendInt32 : AAModel {
  static constexpr const char* kName = "blend in int32_t";
  using Acc = Sym<std::int32_t>;
};

struct Run {
  std::string name;
  std::function<void(Prover&)> prove;
};

} // namespace
} // namespace rastrules::proofs

int main() {
  using namespace rastrules::proofs;
  const std::vector<Run> runs = {
      {SqrtZeroLess::kName, prove_times_sqrt_less<SqrtZeroLess>},
      {SqrtNonStrict::kName, prove_times_sqrt_less<SqrtNonStrict>},
      {SqrtNoSign::kName, prove_times_sqrt_less<SqrtNoSign>},
      {BlendSwapped::kName, prove_blend<BlendSwapped>},
      {BlendInt32::kName, prove_blend<BlendInt32>},
  };
  int survived = 0;
  std::vector<std::string> summary;
  for (const Run& r : runs) {
    std::cout << "\n=== mutant: " << r.name << "\n";
    Domain dom;
    Prover pr(dom, "line_aa/aa_formulas [mutant: " + r.name + "]", "(self-check)", {},
              kernel_constants());
    r.prove(pr);
    int refuted = 0;
    for (const auto& [theorem, status] : pr.results())
      refuted += status == Status::kRefuted;
    survived += refuted > 0 ? 0 : 1;
    summary.push_back(std::string(refuted > 0 ? "REFUTED  " : "SURVIVED ") + r.name + " (" +
                      std::to_string(refuted) + " of " + std::to_string(pr.results().size()) +
                      " theorems refuted)");
  }
  std::cout << "\nmutation self-check (line_aa):\n";
  for (const std::string& line : summary)
    std::cout << "  " << line << "\n";
  std::cout << (summary.size() - static_cast<std::size_t>(survived)) << " mutant runs refuted, "
            << survived << " survived\n";
  return survived == 0 ? 0 : 1;
}
