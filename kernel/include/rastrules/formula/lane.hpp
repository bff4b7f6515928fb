// SPDX-License-Identifier: MIT
// The 32-bit lane form of the edge test used by the fast traversal (FAST.LANE.I32).
// Generic over Num so that the same source is evaluated with std::int32_t / std::int64_t by the
// kernel and with Z3 terms by proofs/fast/ (branch-free; no division, shift or mask: the one
// floor division the form needs is done by the caller with an arithmetic shift and enters the
// proofs as q with E0 + bias == 256 q + r, 0 <= r < 256).
//
// Inside a tile, the sample point of pixel (tx + i, ty + j) has the edge value
//   E(i, j) = E0 + 256 * (i * A + j * B),  A = ay - by,  B = bx - ax        (FIX.STEP.INCREMENTAL)
// where E0 is the value at the tile's first sample point (tx, ty). With q = floor((E0 + bias) /
// 256):
//   E(i, j) + bias >= 0   <=>   L(i, j) >= -q,   L(i, j) = i * A + j * B.
// |A|, |B| < 2^24 and 0 <= i, j < kFastTileSize keep |L| < 2^30, so L fits an int32 lane and
// -q may be clamped to [-2^30, 2^30] without changing any comparison.
// Implements: FAST.LANE.I32, FAST.TILE.CLASSIFY

#pragma once

namespace rastrules::formula {

// The clamp bound of the lane threshold; every lane offset L satisfies |L| < kLaneBound.
inline constexpr long long kLaneBound = 1LL << 30;

// The same for the 64-bit lanes of a block of 64 x 64 pixels (FAST.TILE.CLASSIFY): |A|, |B| < 2^24
// and 0 <= i, j < 64 keep |L| < 2^31.
// rule: FAST.TILE.CLASSIFY
inline constexpr long long kBlockLaneBound = 1LL << 31;

// Returns L(i, j) = i * A + j * B, the lane offset of pixel (i, j) of a tile in units of
// 256 (1/65536 px^2 per 1/256 px).
// rule: FAST.LANE.I32
template <class Num> constexpr Num lane_offset(Num i, Num j, Num a, Num b) {
  return i * a + j * b;
}

// Returns the lane threshold for q = floor((E0 + bias) / 256): -q clamped to
// [-kLaneBound, kLaneBound]. A lane is inside the edge iff lane_offset >= lane_threshold.
// rule: FAST.LANE.I32
template <class Num, class Select> constexpr Num lane_threshold(Num q, Num bound, Select select) {
  const Num neg = -q;
  const Num lo = select(neg < -bound, -bound, neg);
  return select(lo > bound, bound, lo);
}

// Returns the largest lane offset over a tile's lanes 0 <= i, j <= last (last = kFastTileSize - 1):
// max(A, 0) * last + max(B, 0) * last, attained at the corner chosen by the signs of A and B.
// A tile whose lane_max is below an edge's lane_threshold has no lane inside that edge.
// Branch-free: select(c, t, f) returns c ? t : f.
// rule: FAST.TILE.CLASSIFY
template <class Num, class Select> constexpr Num lane_max(Num a, Num b, Num last, Select select) {
  const Num zero(0);
  return select(a > zero, a, zero) * last + select(b > zero, b, zero) * last;
}

// Returns the smallest lane offset over a tile's lanes 0 <= i, j <= last:
// min(A, 0) * last + min(B, 0) * last. A tile whose lane_min is at least an edge's
// lane_threshold has every lane inside that edge.
// rule: FAST.TILE.CLASSIFY
template <class Num, class Select> constexpr Num lane_min(Num a, Num b, Num last, Select select) {
  const Num zero(0);
  return select(a < zero, a, zero) * last + select(b < zero, b, zero) * last;
}

} // namespace rastrules::formula
