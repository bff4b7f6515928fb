// SPDX-License-Identifier: MIT
// Proof: zero-area triangles cover nothing, even without the kernel's early return.
// For all a, b, c, p in the vertex range with formula::twice_signed_area(a, b, c) == 0, under
// each of the four fill conventions, p is not inside all three edges (a b), (b c), (c a) by
// the kernel's per-edge rule (E > 0 || (E == 0 && is_inclusive_edge)).
// rule: TRI.DEGENERATE.ZERO_AREA
// Assumes: SNAP.VERTEX.RANGE, TRI.ORIENT.AREA, TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION
// Expected: PROVED. Exit status 0 iff every theorem is PROVED; a counterexample is printed
// otherwise.

#include "tri/degenerate_covers_nothing.hpp"
#include "support/kernel_model.hpp"
#include "support/obligation.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_obligation<KernelModel>(
      kDegenerateCoversNothing, "TRI.DEGENERATE.ZERO_AREA",
      {"SNAP.VERTEX.RANGE", "TRI.ORIENT.AREA", "TRI.FILL.TOP_LEFT", "TRI.FILL.CONVENTION"});
}
