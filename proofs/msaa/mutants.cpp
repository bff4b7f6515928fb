// SPDX-License-Identifier: MIT
// Self-check: the multisampling obligations can fail. Runs prove_sample_position and
// prove_centroid_within against deliberately broken models, each derived from MsaaKernelModel
// with one member replaced, and passes only if every mutant is REFUTED (with a
// counterexample). A mutant that survives means the proof cannot see that kind of bug.
// Cites no rule: it is evidence about the proofs, not about the kernel.
// Assumes: SCENE.TARGET.LIMITS, SNAP.VERTEX.RANGE (as the obligations do)
// Expected: every mutant REFUTED; exit status 0 iff so.

#include <cstdint>
#include <vector>

#include "msaa/msaa_proofs.hpp"
#include "support/mutation.hpp"
#include "support/prover.hpp"

namespace rastrules::proofs {
namespace {

// Sample positions computed in int16_t: they overflow for most pixels.
struct PositionsInInt16 : MsaaKernelModel {
  static constexpr const char* kName = "sample positions computed in int16_t";
  using Pos = Sym<std::int16_t>;
};

// Offsets in 1/8 px instead of 1/16: samples leave their pixel.
struct GridUnitTooLarge : MsaaKernelModel {
  static constexpr const char* kName = "sample grid unit 1/8 px";
  static constexpr std::int64_t kUnit = 2 * kSampleGridUnit;
  template <class P>
  static Point<P> sample_position(const P& px, const P& py, const P& ox, const P& oy) {
    return Point<P>{px * P(kSubpixelOne) + P(kSubpixelHalf) + ox * P(kUnit),
                    py * P(kSubpixelOne) + P(kSubpixelHalf) + oy * P(kUnit)};
  }
};

// Offsets measured from the pixel's top-left corner instead of its centre: the grid's
// [-8, 7] offsets reach into the neighbouring pixels.
struct OffsetsFromTheCorner : MsaaKernelModel {
  static constexpr const char* kName = "offsets from the pixel corner";
  template <class P>
  static Point<P> sample_position(const P& px, const P& py, const P& ox, const P& oy) {
    return Point<P>{px * P(kSubpixelOne) + ox * P(kSampleGridUnit),
                    py * P(kSubpixelOne) + oy * P(kSampleGridUnit)};
  }
};

// Targets up to 2^16 pixels wide: samples leave SNAP.VERTEX.RANGE. (2^15 would still fit: the
// vertex range has room for one more doubling than kMaxTargetSide uses.)
struct TargetTooLarge : MsaaKernelModel {
  static constexpr const char* kName = "targets up to 65536 pixels";
  static constexpr std::int64_t kMaxSide = 65536;
};

// A custom pattern whose hull misses the centre (all samples up and to the right).
struct QuadrantPattern : MsaaKernelModel {
  static constexpr const char* kName = "pattern in one quadrant (hull misses the centre)";
  static std::vector<NamedPattern> patterns() {
    return {NamedPattern{"quadrant 3", {{4, -4}, {6, -6}, {4, -6}}}};
  }
};

// The 4x pattern with its last sample moved from (2, 6) to (2, -6): the centre is still on the
// hull's boundary (segment (-6, 2) - (6, -2)), but the other samples have no weight, so an
// edge through the centre can pass every sample without touching it.
struct MovedSample : MsaaKernelModel {
  static constexpr const char* kName = "4x pattern with (2, 6) moved to (2, -6)";
  static std::vector<NamedPattern> patterns() {
    NamedPattern p = named("standard 4 moved", standard_pattern(4));
    p.offsets.back() = {2, -6};
    return {p};
  }
};

} // namespace

MutationSelfcheck mutation_selfcheck() {
  return {"msaa",
          {refute<PositionsInInt16, GridUnitTooLarge, OffsetsFromTheCorner>(kSamplePosition),
           // Theorems 1 and 2 only: theorem 3 (the edge budget) still holds there but takes Z3
           // about 30 s outside the vertex range.
           refute<TargetTooLarge>(kSamplePosition.file,
                                  []<class F>(Prover& pr) { prove_sample_position<F>(pr, false); }),
           refute<QuadrantPattern, MovedSample>(kCentroidWithin)},
          MsaaKernelModel::constants(),
          {"SCENE.TARGET.LIMITS", "SNAP.VERTEX.RANGE"}};
}

} // namespace rastrules::proofs
