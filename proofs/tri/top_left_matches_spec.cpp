// SPDX-License-Identifier: MIT
// Proof: the kernel's top/left edge tests and its four fill conventions equal the spec's
// definitions. For every non-degenerate clockwise triangle (a, b, c) in the vertex range
// (formula::twice_signed_area > 0) and each of its three directed edges p -> q with third
// vertex r:
//   formula::is_top_edge(p, q)  <=> p.y == q.y and r.y > p.y (exactly horizontal and above the
//                                   other edges, y down);
//   formula::is_left_edge(p, q) <=> p.y != q.y and r.x > the x of line pq at height r.y
//                                   (exact rational; no edge-function shortcut);
//   formula::is_inclusive_edge<true, true> == is_top_edge || is_left_edge (every edge a -> b);
//   formula::is_inclusive_edge<T, L>(p, q) <=> (T ? top : bottom) || (L ? left : right), for
//   top-left, bottom-left, top-right and bottom-right.
// rule: TRI.FILL.TOP_EDGE, TRI.FILL.LEFT_EDGE, TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION
// Assumes: SNAP.VERTEX.RANGE, TRI.ORIENT.AREA, TRI.ORIENT.NORMALISE
// Expected: PROVED. Exit status 0 iff every theorem is PROVED; a counterexample is printed
// otherwise.

#include "tri/top_left_matches_spec.hpp"
#include "support/kernel_model.hpp"
#include "support/obligation.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_obligation<KernelModel>(
      kTopLeftMatchesSpec,
      "TRI.FILL.TOP_EDGE, TRI.FILL.LEFT_EDGE, TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION",
      {"SNAP.VERTEX.RANGE", "TRI.ORIENT.AREA", "TRI.ORIENT.NORMALISE"});
}
