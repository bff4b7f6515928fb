// SPDX-License-Identifier: MIT
// Proof: paths that share a boundary partition its samples (line edges). For every
// convention: two triangles abc and bad sharing the edge ab in opposite directions have, at
// every sample, windings that add up to the winding of their union contour adbc (the shared
// edge's two directions cancel: the same test decides both, with opposite signs); and when
// both are clockwise, every integer sample on the open shared edge has winding 1 in exactly one
// of them and 0 in the other, so exactly one covers it under nonzero and under even-odd; and a
// cubic or quadratic that ends on the sample row and its reverse get, from the kernel's integer
// end rules, the same crossing there with opposite directions and the same x. The
// windings are sums of the kernel's line contributions (formula::path_edge_spans,
// path_crossing_right, edge_value, combined as kernel/src/path.cpp's line_contribution).
// Method: the templates on Sym<std::int64_t>; the sample on the edge as a + k delta with
// b = a + n delta, 0 < k < n, and lemmas L0, L1 of tri/shared_edge_exactly_once.hpp.
// rule: PATH.TIE.PARTITION
// Assumes: PATH.GEOMETRY, PATH.WINDING, PATH.SAMPLE.TIE
// Expected: PROVED. Exit status 0 iff every theorem is PROVED.

#include "path/tie_partition.hpp"
#include "support/obligation.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_obligation<PathKernelModel>(kTiePartition, "PATH.TIE.PARTITION",
                                         {"PATH.GEOMETRY", "PATH.WINDING", "PATH.SAMPLE.TIE"});
}
