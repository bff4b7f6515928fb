// SPDX-License-Identifier: MIT
// Proof: the fast traversal's 32-bit lanes never overflow. For every edge with endpoints in
// SNAP.VERTEX.RANGE and every lane (i, j) of a kFastTileSize x kFastTileSize tile, the lane
// offset L = lane_offset(i, j, A, B) (formula/lane.hpp) with A = ay - by, B = bx - ax, evaluated
// in int32_t, never overflows and |L| < kLaneBound; the incremental steps L + B (next row) and
// L + A (next column) fit int32_t too and equal the next lane's offset.
// rule: FAST.LANE.I32
// Assumes: SNAP.VERTEX.RANGE
// Expected: PROVED. Exit status 0 iff every theorem is PROVED; a counterexample is printed
// otherwise.

#include "fast/fast_proofs.hpp"
#include "support/obligation.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_obligation<FastKernelModel>(kLaneBudget, "FAST.LANE.I32", {"SNAP.VERTEX.RANGE"});
}
