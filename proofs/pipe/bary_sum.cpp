// SPDX-License-Identifier: MIT
// Proof: the barycentric edge values sum to the doubled area, exactly and without overflow,
// and each is a double exactly. For all snapped vertices v0, v1, v2 and every evaluation point
// s with raw coordinates in SNAP.VERTEX.RANGE, with e0 = E_{v1 v2}(s), e1 = E_{v2 v0}(s),
// e2 = E_{v0 v1}(s) and A = twice_signed_area(v0, v1, v2) (the kernel's formula::edge_value and
// formula::twice_signed_area on int64_t): e0 + e1 + e2 == A with every intermediate in
// int64_t, so lambda0 + lambda1 + lambda2 == 1 exactly; |e_i|, |A| and |e0 + e1| < 2^53, so
// the conversions to double in PIPE.INTERP.* and PIPE.DEPTH.INTERP are exact.
// rule: PIPE.BARY.SUM, PIPE.BARY.DOUBLE_EXACT
// Assumes: SNAP.VERTEX.RANGE, PIPE.BARY.EXACT (the order of e0, e1, e2), TRI.EDGE.FUNCTION,
// TRI.ORIENT.AREA Expected: PROVED. Exit status 0 iff every theorem is PROVED; a counterexample is
// printed otherwise.

#include "pipe/pipe_proofs.hpp"
#include "support/obligation.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_obligation<PipeModel>(
      kBarySum, "PIPE.BARY.SUM, PIPE.BARY.DOUBLE_EXACT",
      {"SNAP.VERTEX.RANGE", "PIPE.BARY.EXACT", "TRI.EDGE.FUNCTION", "TRI.ORIENT.AREA"},
      barycentrics_match_kernel);
}
