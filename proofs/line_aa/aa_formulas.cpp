// SPDX-License-Identifier: MIT
// Proof: the antialiased-line formulas of kernel/include/rastrules/formula/aa.hpp. The exact
// "v * sqrt(D) < w" comparison used by the fragment decision equals its square-root-free
// form; the 8-bit blend numerator never overflows int64_t and lies between src and dst.
// rule: LINE.AA.FRAGMENT, LINE.AA.BLEND
// Assumes: LINE.AA.PRECISION (the bit budget of the squares)
// Expected: PROVED. Exit status 0 iff every theorem is PROVED; a counterexample is printed
// otherwise.

#include "line_aa/aa_formulas.hpp"
#include "support/prover.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_proof("line_aa/aa_formulas", "LINE.AA.FRAGMENT, LINE.AA.BLEND", {"LINE.AA.PRECISION"},
                   kernel_constants(), [](Prover& pr) {
                     prove_times_sqrt_less<AAModel>(pr);
                     prove_blend<AAModel>(pr);
                   });
}
