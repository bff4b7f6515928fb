// SPDX-License-Identifier: MIT
// Proof: the batch counter's SIMD unit (kernel/src/fast_batch_avx2.cpp) sets up and decides a
// small triangle in int32_t lanes without wrapping, and its lanes hold the kernel's 64-bit edge
// values. For snapped vertices in SNAP.VERTEX.RANGE and targets of 1..kMaxTargetSide pixels:
// the spans, pixel bounds px0 = max((minx + 127) >> 8, 0), px1 = min((maxx - 128) >> 8, w - 1)
// (and in y), ncols, nrows and the first sample point (sx, sy) = (256 px0 + 128, ..) never
// leave int32_t, and px0..px1 are the target's pixels whose centres lie in [minx, maxx]. For a
// small triangle (spans below raster::kBatchSmallSpan, 64 px) with a non-empty rect:
// 1 <= ncols, nrows <= 64 and (sx, sy) lies in the bounding box; the area's differences
// (< 2^14), mullo products and difference fit, |twice area| < 2^29 and it equals
// formula::twice_signed_area; the lanes' inclusive mask is formula::is_inclusive_edge. Both row
// loops (cover_one for rows up to 16 px, cover_rows in chunks of eight beyond) count exactly
// the pixels i < ncols, and every lane they compute has its sample point at most 15 px right of
// the box and one row below it. For every edge of either winding: A, B, E0 = B (sy - ay) +
// A (sx - ax), E0 + bias (bias 0 or -1), 256 A, 256 B and 8 x 256 A (< 2^25) fit int32_t, and
// every lane value E0 + bias + 256 (i A + j B) either loop computes (one row step past the last
// row included) fits, is below 2^30 in magnitude and equals formula::edge_value at
// (sx + 256 i, sy + 256 j) plus formula::edge_bias on int64_t. On 32-bit bit-vectors:
// (l0 | l1 | l2) > -1 iff all three are >= 0; a dead lane's poison -2^30 stays negative and
// fails that test; inclusive ^ -1 is the bias; srai by 8 is floor division, slli is
// multiplication where it fits.
// rule: FAST.BATCH.SMALL_I32
// Assumes: SNAP.VERTEX.RANGE, FIX.BUDGET.EDGE_VALUE, FIX.BIAS.FORM
// Expected: PROVED. Exit status 0 iff every theorem is PROVED; a counterexample is printed
// otherwise.

#include "fast/batch_proofs.hpp"
#include "support/obligation.hpp"

int main() {
  using namespace rastrules::proofs;
  int status = run_obligation<BatchKernelModel>(
      kBatchSmallI32, "FAST.BATCH.SMALL_I32",
      {"SNAP.VERTEX.RANGE", "FIX.BUDGET.EDGE_VALUE", "FIX.BIAS.FORM"});
  status |= run_obligation<BatchKernelModel>(kLaneBits, "FAST.BATCH.SMALL_I32", {});
  return status;
}
