// SPDX-License-Identifier: MIT
// Proof: the fast traversal's 32-bit lane test decides exactly what the plain walk decides.
// For every edge with endpoints in SNAP.VERTEX.RANGE, every tile first sample point p in range,
// every lane (i, j) of the tile whose sample point is in range and either inclusiveness:
// the edge value at pixel (tx + i, ty + j) is E0 + 256 L with E0 = E(p) and
// L = lane_offset(i, j, A, B) (through edge_step_x / edge_step_y), and, with
// q = (E0 + edge_bias) >> 8 (restated as E0 + bias == 256 q + r, 0 <= r < 256, and that
// restatement first checked against C++'s >> on int64_t), the sample is
// inside the edge (E > 0, or E == 0 on an inclusive edge) iff L >= lane_threshold(q, kLaneBound),
// whose int64_t evaluation never overflows and whose result fits an int32_t lane.
// E0 ranges over every integer of the edge-value budget |E0| < 2^kEdgeValueMagBits, a superset
// (lemma E1) of the values edge_value takes at points in range.
// rule: FAST.LANE.I32
// Assumes: SNAP.VERTEX.RANGE, FIX.BUDGET.EDGE_VALUE, FIX.BIAS.FORM, FIX.STEP.INCREMENTAL,
// TRI.FILL.TOP_LEFT
// Expected: PROVED. Exit status 0 iff every theorem is PROVED; a counterexample is printed
// otherwise.

#include "fast/fast_proofs.hpp"
#include "support/obligation.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_obligation<FastKernelModel>(kLaneEquivalence, "FAST.LANE.I32",
                                         {"SNAP.VERTEX.RANGE", "FIX.BUDGET.EDGE_VALUE",
                                          "FIX.BIAS.FORM", "FIX.STEP.INCREMENTAL",
                                          "TRI.FILL.TOP_LEFT"},
                                         shift_restatement_matches_cpp);
}
