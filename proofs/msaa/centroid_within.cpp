// SPDX-License-Identifier: MIT
// Proof: the arithmetic core of MSAA.CENTROID.WITHIN. For every standard and centre pattern
// (the kernel's own tables), every edge with vertices in SNAP.VERTEX.RANGE, every pixel of a
// target and either inclusiveness: an edge test (E > 0, or E == 0 on an inclusive edge) that
// every sample passes is passed by the pixel centre; and E >= 0 at every sample implies
// E >= 0 at the centre, with E == 0 there only when E == 0 at every sample. So a triangle that
// covers all samples (branch 1 of both centroid rules) covers the pixel centre under the
// tie rule, and the centroid lies in the primitive. (Branches 2 and 3 choose a covered
// sample, which needs no proof.)
// rule: MSAA.CENTROID.WITHIN
// Assumes: SCENE.TARGET.LIMITS, SNAP.VERTEX.RANGE, TRI.FILL.TOP_LEFT, MSAA.SAMPLE.POSITION
// Expected: PROVED. Exit status 0 iff every theorem is PROVED; a counterexample is printed
// otherwise.

#include "msaa/msaa_proofs.hpp"
#include "support/obligation.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_obligation<MsaaKernelModel>(
      kCentroidWithin, "MSAA.CENTROID.WITHIN",
      {"SCENE.TARGET.LIMITS", "SNAP.VERTEX.RANGE", "TRI.FILL.TOP_LEFT", "MSAA.SAMPLE.POSITION"},
      restatement_matches_kernel<MsaaKernelModel>);
}
