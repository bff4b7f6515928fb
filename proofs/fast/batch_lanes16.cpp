// SPDX-License-Identifier: MIT
// Proof: the batch counter's AVX-512 unit (kernel/src/fast_batch_avx512.cpp, FAST.BATCH.LANES16)
// decides a small triangle in int32_t lanes without wrapping, as the AVX2 unit does
// (batch_small_i32.cpp): the same set-up (fast_batch_group.hpp, so B1-B5 are the same theorems)
// and the same obligations at sixteen lanes a chunk. Its row loop (cover16: full = (ncols - 1)
// / 16 chunks of sixteen lanes, then a tail of rest = ncols - 16 full lanes masked with
// (1 << rest) - 1) counts exactly the pixels i < ncols, and every lane it computes has its
// sample point at most 15 px right of the box and one row below it (B6); for every edge,
// 16 x 256 A is below 2^26 and every lane value E0 + bias + 256 (i A + j B), i = 16 c + m, fits
// int32_t, is below 2^30 in magnitude and equals formula::edge_value at (sx + 256 i,
// sy + 256 j) plus formula::edge_bias on int64_t (E1, E2). The sign test `_mm512_cmpge_epi32_mask
// (l0 | l1 | l2, 0)` is the AVX2 unit's `> -1` on the same bits (batch_small_i32.cpp's bit-level
// theorem 1). Rows of up to 8 pixels go through the AVX2 unit's cover_one (its low half), which
// batch_small_i32.cpp proves.
// rule: FAST.BATCH.LANES16, FAST.BATCH.SMALL_I32
// Assumes: SNAP.VERTEX.RANGE, FIX.BUDGET.EDGE_VALUE, FIX.BIAS.FORM
// Expected: PROVED. Exit status 0 iff every theorem is PROVED; a counterexample is printed
// otherwise.

#include "fast/batch_proofs.hpp"
#include "support/obligation.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_obligation<BatchLanes16Model>(
      kBatchSmallI32, "FAST.BATCH.LANES16",
      {"SNAP.VERTEX.RANGE", "FIX.BUDGET.EDGE_VALUE", "FIX.BIAS.FORM", "FAST.BATCH.SMALL_I32"});
}
