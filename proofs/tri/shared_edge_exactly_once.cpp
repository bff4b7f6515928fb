// SPDX-License-Identifier: MIT
// Proof: shared edges are drawn once, under every fill convention.
// (1) For every directed edge a -> b with a != b in the vertex range, exactly one of a -> b and
//     b -> a is inclusive (formula::is_inclusive_edge).
// (2) For two triangles sharing the edge (a, b) whose third vertices c, d lie strictly on
//     opposite sides of line ab, in either vertex order and normalised to clockwise as the
//     kernel does (swap v1, v2 when not clockwise), every integer point on the open segment
//     (a, b) is covered by exactly one of them under the kernel's per-edge rule
//     (E > 0 || (E == 0 && inclusive)) with E = formula::edge_value, checking all three edges.
// rule: TRI.SHARED_EDGE.EXACTLY_ONCE
// Assumes: SNAP.VERTEX.RANGE, TRI.ORIENT.NORMALISE, TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION
// Expected: PROVED. Exit status 0 iff every theorem is PROVED; a counterexample is printed
// otherwise.

#include "tri/shared_edge_exactly_once.hpp"
#include "support/kernel_model.hpp"
#include "support/obligation.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_obligation<KernelModel>(
      kSharedEdgeExactlyOnce, "TRI.SHARED_EDGE.EXACTLY_ONCE",
      {"SNAP.VERTEX.RANGE", "TRI.ORIENT.NORMALISE", "TRI.FILL.TOP_LEFT", "TRI.FILL.CONVENTION"});
}
