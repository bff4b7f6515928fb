// SPDX-License-Identifier: MIT
// Self-check: every proof obligation can fail. Runs the same obligation templates as the
// proofs (fixed/*.hpp, tri/*.hpp) against deliberately broken kernel models, each derived
// from KernelModel with one member replaced, and passes only if every mutant is REFUTED (with
// a counterexample) by each obligation listed for it. A mutant that survives means a proof
// that cannot see that kind of bug.
// Cites no rule: it is evidence about the proofs, not about the kernel.
// Assumes: SNAP.VERTEX.RANGE (as the obligations do)
// Expected: every mutant REFUTED; exit status 0 iff so.

#include <cstdint>

#include "fixed/edge_value_no_overflow.hpp"
#include "support/kernel_model.hpp"
#include "support/mutation.hpp"
#include "support/prover.hpp"
#include "support/sym.hpp"
#include "tri/bias_form.hpp"
#include "tri/degenerate_covers_nothing.hpp"
#include "tri/incremental_step.hpp"
#include "tri/shared_edge_exactly_once.hpp"
#include "tri/top_left_matches_spec.hpp"

namespace rastrules::proofs {
namespace {

// The top rule read with y up: horizontal edges running in -x (interior above) count as top.
struct TopRuleYUp : KernelModel {
  static constexpr const char* kName = "top rule with y up (horizontal edges running -x are top)";
  template <class S> static auto is_top_edge(const Point<S>& a, const Point<S>& b) {
    return (b.y == a.y) && (b.x < a.x);
  }
  template <bool TopInclusive, bool LeftInclusive, class S>
  static auto is_inclusive_edge(const Point<S>& a, const Point<S>& b) {
    return KernelModel::is_inclusive_edge<!TopInclusive, LeftInclusive>(a, b);
  }
};

// The left rule with the interior on the wrong side: edges running down the screen are left.
struct LeftRuleMirrored : KernelModel {
  static constexpr const char* kName = "left rule mirrored (edges running +y are left)";
  template <class S> static auto is_left_edge(const Point<S>& a, const Point<S>& b) {
    return b.y > a.y;
  }
  template <bool TopInclusive, bool LeftInclusive, class S>
  static auto is_inclusive_edge(const Point<S>& a, const Point<S>& b) {
    return KernelModel::is_inclusive_edge<TopInclusive, !LeftInclusive>(a, b);
  }
};

// Every horizontal edge inclusive, whatever its direction.
struct HorizontalAlwaysInclusive : KernelModel {
  static constexpr const char* kName = "horizontal edges always inclusive";
  template <bool TopInclusive, bool LeftInclusive, class S>
  static auto is_inclusive_edge(const Point<S>& a, const Point<S>& b) {
    const auto horizontal = (b.y == a.y);
    const auto v_ok = LeftInclusive ? (b.y < a.y) : (b.y > a.y);
    return horizontal || (!horizontal && v_ok);
  }
};

// The two biases exchanged.
struct BiasSwapped : KernelModel {
  static constexpr const char* kName = "bias swapped (-1 for inclusive edges, 0 otherwise)";
  template <class S> static S edge_bias(bool inclusive) { return inclusive ? S(-1) : S(0); }
};

// A 32-bit accumulator, as a SIMD lane might use.
using Int32Accumulator = AccumulatorOf<KernelModel, std::int32_t, "int32_t accumulator">;

// A vertex range of 2^31 raw units each side (instead of SNAP.VERTEX.RANGE's 2^23).
using RangeTooWide = CoordinateRangeOf<KernelModel, 31, "vertex range [-2^31, 2^31)">;

// The x step with the wrong sign.
struct StepXSignWrong : KernelModel {
  static constexpr const char* kName = "edge_step_x with the wrong sign";
  template <class S> static S edge_step_x(const Point<S>& a, const Point<S>& b, const S& one) {
    return (b.y - a.y) * one;
  }
};

// The y step without the pixel scale.
struct StepYUnscaled : KernelModel {
  static constexpr const char* kName = "edge_step_y not scaled by one pixel";
  template <class S> static S edge_step_y(const Point<S>& a, const Point<S>& b, const S& one) {
    (void)one;
    return b.x - a.x;
  }
};

// No winding normalisation: counter-clockwise triangles are tested as given.
struct NoNormalisation : KernelModel {
  static constexpr const char* kName = "no winding normalisation";
  template <class S> static SymBool is_clockwise(const Triangle<S>&) { return SymBool(true); }
};

// Samples on an edge never inside (the fill rule ignored).
struct TiesNeverInside : KernelModel {
  static constexpr const char* kName = "samples on an edge never inside";
  template <class S> static SymBool inside(const S& e, const SymBool&) { return e > S(0); }
};

// The runs of broken models Fs against edge_value_no_overflow, which also report each model's
// vertex range.
template <class... Fs> std::vector<MutantRun> refute_edge_value_no_overflow() {
  return {MutantRun(Fs::kName, kEdgeValueNoOverflow.file, prove_edge_value_no_overflow<Fs>,
                    {{"model kMinRaw", Fs::kMinRaw, Unit::kCoordRaw},
                     {"model kMaxRaw", Fs::kMaxRaw, Unit::kCoordRaw}})...};
}

} // namespace

MutationSelfcheck mutation_selfcheck() {
  return {"fixed, tri",
          {refute<TopRuleYUp, LeftRuleMirrored, HorizontalAlwaysInclusive>(kTopLeftMatchesSpec),
           refute<HorizontalAlwaysInclusive>(kSharedEdgeExactlyOnce),
           refute<HorizontalAlwaysInclusive>(kDegenerateCoversNothing),
           refute<BiasSwapped>(kBiasForm), refute_edge_value_no_overflow<Int32Accumulator>(),
           refute<Int32Accumulator>(kIncrementalStep),
           refute_edge_value_no_overflow<RangeTooWide>(),
           refute<StepXSignWrong, StepYUnscaled>(kIncrementalStep),
           refute<NoNormalisation, TiesNeverInside>(kSharedEdgeExactlyOnce)},
          KernelModel::constants(),
          {"SNAP.VERTEX.RANGE"}};
}

} // namespace rastrules::proofs
