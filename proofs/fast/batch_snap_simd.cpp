// SPDX-License-Identifier: MIT
// Proof: snapping in float lanes is the integer rule. For every float32 bit pattern v and
// every rounding mode of the product (the MXCSR's: any of the five IEEE modes), with
// p = v * 256.0f rounded in that mode, r = roundToIntegral(p), ties to even
// (_mm256_round_ps(.., _MM_FROUND_TO_NEAREST_INT)), and the lane accepted iff
// r >= -8388608.0f && r <= 8388607.0f (ordered comparisons, false for NaN):
// accepted => v is finite, snap_to_subpixel(v) (rastrules/snap.hpp, integer-only, restated on
// bit-vectors and checked against the compiled function first) succeeds and cvtps_epi32(r),
// in any rounding mode, equals its value, which lies in SNAP.VERTEX.RANGE; snap_to_subpixel(v)
// succeeds => accepted; a finite product is exact (the same in every mode); a zero or
// subnormal v snaps to 0 in the kernel and in the lane, also when the processor treats it
// as zero (DAZ) or flushes its product to zero (FTZ). Z3's IEEE-754 theory, bit-blasted; one
// range of biased exponents (0..255) takes about 1 s, so the theorems are not split further.
// rule: FAST.BATCH.SNAP_SIMD
// Assumes: SNAP.VERTEX.ROUND, SNAP.VERTEX.RANGE, SNAP.VERTEX.INVALID (as snap.hpp implements them)
// Expected: PROVED. Exit status 0 iff every theorem is PROVED; a counterexample is printed
// otherwise.

#include "fast/batch_proofs.hpp"
#include "support/obligation.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_obligation<SnapKernelModel>(
      kBatchSnapSimd, "FAST.BATCH.SNAP_SIMD",
      {"SNAP.VERTEX.ROUND", "SNAP.VERTEX.RANGE", "SNAP.VERTEX.INVALID"}, snap_model_matches_kernel);
}
