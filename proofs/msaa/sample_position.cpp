// SPDX-License-Identifier: MIT
// Proof: sample positions are exact 16.8 values inside the vertex range and inside their
// pixel's half-open square, and the edge value at any sample stays within the int64_t edge
// budget. For every pixel of a target (px, py < kMaxTargetSide), every offset on the
// [kSampleGridMin, kSampleGridMax] grid and every edge with vertices in SNAP.VERTEX.RANGE, over
// the kernel's sample_position arithmetic (int32_t, restated and checked against the compiled
// function) and formula::edge_value (int64_t).
// rule: MSAA.SAMPLE.POSITION, MSAA.PATTERN.GRID
// Assumes: SCENE.TARGET.LIMITS, SNAP.VERTEX.RANGE, FIX.BUDGET.EDGE_VALUE
// Expected: PROVED. Exit status 0 iff every theorem is PROVED; a counterexample is printed
// otherwise.

#include "msaa/msaa_proofs.hpp"
#include "support/obligation.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_obligation<MsaaKernelModel>(
      kSamplePosition, "MSAA.SAMPLE.POSITION, MSAA.PATTERN.GRID",
      {"SCENE.TARGET.LIMITS", "SNAP.VERTEX.RANGE", "FIX.BUDGET.EDGE_VALUE"},
      restatement_matches_kernel<MsaaKernelModel>);
}
