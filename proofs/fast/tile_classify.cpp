// SPDX-License-Identifier: MIT
// Proof: whole-tile rejection and acceptance never change a decision. For every edge with
// endpoints in SNAP.VERTEX.RANGE, Lmax = lane_max(A, B, kFastTileSize - 1) and
// Lmin = lane_min(A, B, kFastTileSize - 1) (formula/lane.hpp, int32_t) never overflow; for every
// lane (i, j) of the tile and every threshold C, Lmax < C implies L(i, j) < C and Lmin >= C
// implies L(i, j) >= C; and both are the offsets of corner lanes (the classification is exact).
// rule: FAST.TILE.CLASSIFY
// Assumes: SNAP.VERTEX.RANGE, FAST.LANE.I32
// Expected: PROVED. Exit status 0 iff every theorem is PROVED; a counterexample is printed
// otherwise.

#include "fast/fast_proofs.hpp"
#include "support/obligation.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_obligation<FastKernelModel>(kTileClassify, "FAST.TILE.CLASSIFY",
                                         {"SNAP.VERTEX.RANGE", "FAST.LANE.I32"});
}
