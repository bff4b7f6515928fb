// SPDX-License-Identifier: MIT
// Self-check: the pipeline obligations can fail. Runs prove_bary_sum, prove_depth_format and
// prove_guard_band against deliberately broken models, each derived from PipeModel with one
// member replaced, and passes only if every mutant is REFUTED (with a counterexample) by at
// least one theorem. A mutant that survives means the proof cannot see that kind of bug.
// Cites no rule: it is evidence about the proofs, not about the kernel.
// Assumes: SNAP.VERTEX.RANGE, PIPE.DEPTH.CLAMP (as the obligations do)
// Expected: every mutant REFUTED; exit status 0 iff so.

#include <array>
#include <cstdint>

#include "pipe/pipe_proofs.hpp"
#include "support/mutation.hpp"
#include "support/prover.hpp"

namespace rastrules::proofs {
namespace {

// e1 taken along the edge v0 -> v2 instead of v2 -> v0: the sum is no longer A.
struct WrongEdgeOrder : PipeModel {
  static constexpr const char* kName = "e1 = E_v0v2(s) (edge order reversed)";
  template <class S> static std::array<S, 3> bary_edges(const Triangle<S>& v, const Point<S>& s) {
    return {edge_value(v[1], v[2], s), edge_value(v[0], v[2], s), edge_value(v[0], v[1], s)};
  }
};

// The area with the other winding, E_v0v2(v1) = -A.
struct AreaReversed : PipeModel {
  static constexpr const char* kName = "A = E_v0v2(v1) (opposite winding)";
  template <class S> static S twice_signed_area(const Triangle<S>& t) {
    return formula::twice_signed_area<S>(t[0].x, t[0].y, t[2].x, t[2].y, t[1].x, t[1].y);
  }
};

// Barycentrics in 32-bit integers.
using BaryInt32 = AccumulatorOf<PipeModel, std::int32_t, "barycentrics in int32_t">;

// Coordinates of 2^26 raw units (2^18 px) each side: still int64_t, but edge values reach
// 2^55 and are no longer doubles exactly.
using Coordinates2To26 = CoordinateRangeOf<PipeModel, 26, "coordinate range [-2^26, 2^26)">;

// The UNORM scale 2^n instead of 2^n - 1: depth 1.0 overflows the format.
struct UnormScale2n : PipeModel {
  static constexpr const char* kName = "UNORM scale 2^n";
  static double unorm_scale(int bits) { return static_cast<double>(std::int64_t{1} << bits); }
};

// Truncation without the + 0.5: not the nearest integer.
struct UnormTruncate : PipeModel {
  static constexpr const char* kName = "UNORM conversion truncates (no + 0.5)";
  static Real unorm_rounding_argument(const Real& z, const Real& max) { return z * max; }
};

// The conversion in float32: fl32(z * 16777215) is an integer from 2^23 up, and adding 0.5
// ties to even.
struct UnormInFloat : PipeModel {
  static constexpr const char* kName = "UNORM conversion in float32";
  static Real unorm_rounding_argument(const Real& z, const Real& max) {
    const SymFloat<float> zf = convert<float>(z);
    const SymFloat<float> mf = convert<float>(max);
    return convert<double>(formula::unorm_rounding_argument<SymFloat<float>>(zf, mf));
  }
};

// No margin: the guard band as wide as the snap range.
struct GuardBandNoMargin : PipeModel {
  static constexpr const char* kName = "guard band 32768 px (no margin)";
  static constexpr double kGuardBand = 32768.0;
};

} // namespace

MutationSelfcheck mutation_selfcheck() {
  return {"pipe",
          {refute<WrongEdgeOrder, AreaReversed, BaryInt32, Coordinates2To26>(kBarySum),
           refute<UnormScale2n, UnormTruncate, UnormInFloat>(kDepthFormat),
           refute<GuardBandNoMargin>(kGuardBand)},
          PipeModel::constants(),
          {"SNAP.VERTEX.RANGE", "PIPE.DEPTH.CLAMP"}};
}

} // namespace rastrules::proofs
