// SPDX-License-Identifier: MIT
// Proof: stepping an edge value by one pixel equals direct evaluation.
// For all a, b, p in the vertex range whose stepped sample is also in range:
//   formula::edge_value(a, b, p + (kSubpixelOne, 0))
//       == formula::edge_value(a, b, p) + formula::edge_step_x(ay, by, kSubpixelOne),
// the same in y with edge_step_y, and the traversal's biased accumulator
// (E(p) + edge_bias) + edge_step_x == E(p + 1 px) + edge_bias for both biases, all in int64_t
// without overflow. By induction over the steps of a row (each stepped sample is a pixel
// centre of the target, inside the vertex range), the traversal's accumulated values equal
// direct evaluation at every pixel centre.
// rule: FIX.STEP.INCREMENTAL
// Assumes: SNAP.VERTEX.RANGE, SCENE.TARGET.LIMITS
// Expected: PROVED. Exit status 0 iff every theorem is PROVED; a counterexample is printed
// otherwise.

#include "tri/incremental_step.hpp"
#include "support/kernel_model.hpp"
#include "support/obligation.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_obligation<KernelModel>(kIncrementalStep, "FIX.STEP.INCREMENTAL",
                                     {"SNAP.VERTEX.RANGE", "SCENE.TARGET.LIMITS"});
}
