// SPDX-License-Identifier: MIT
// Self-check: the area budget obligation can fail. Runs prove_area_budget (all of it, or the
// group of theorems a mutant targets) against deliberately broken models, each derived from
// AreaKernelModel with one member replaced, and passes only if every mutant is REFUTED (with a
// counterexample): the wide integers one size smaller, positions measured on the wrong side or
// from the wrong column, and each proved magnitude one bit smaller (so that every budget
// theorem can fail and its bound is tight).
// Cites no rule: it is evidence about the proof, not about the kernel.
// Assumes: PATH.GEOMETRY, SNAP.VERTEX.RANGE, FIX.BUDGET.EDGE_VALUE (as the obligation does)
// Expected: every mutant REFUTED; exit status 0 iff so.

#include <cstdint>

#include "path/area_budget.hpp"
#include "support/mutation.hpp"
#include "support/prover.hpp"
#include "support/sym.hpp"

namespace rastrules::proofs {
namespace {

// The cell method's wide integers as int64_t (one size smaller than the kernel's __int128).
struct AreaWide64 : AreaKernelModel {
  static constexpr const char* kName = "cell method wide integers in int64_t, not __int128";
  using W = Sym<std::int64_t>;
};

// The top side's position measured from the next column's line.
struct TopFromNextColumn : AreaKernelModel {
  static constexpr const char* kName = "top position measured from the next column";
  template <class S> static S top_position(const S& xn, const S& col, const S& q) {
    return formula::cell_top_position<S>(xn, col + S(1), q);
  }
};

// The left side's position without its kW (walked from the bottom-left corner as if it were
// the bottom side's end): positions overlap the bottom side's.
struct LeftShort : AreaKernelModel {
  static constexpr const char* kName = "left position without its kW";
  template <class S> static S left_position(const S& yn, const S& top, const S& q) {
    return formula::cell_left_position<S>(yn, top, q) - S(formula::kCellSide) * q;
  }
};

// Each proved magnitude one bit smaller.
template <int Which, MutantName Name> struct Smaller : AreaKernelModel {
  static constexpr const char* kName = Name.text;
  static constexpr Int128 kNumPerQ = AreaKernelModel::kNumPerQ >> (Which == 0 ? 1 : 0);
  static constexpr Int128 kCol = AreaKernelModel::kCol >> (Which == 1 ? 1 : 0);
  static constexpr Int128 kRamp = AreaKernelModel::kRamp >> (Which == 2 ? 1 : 0);
  static constexpr Int128 kMeetDen = AreaKernelModel::kMeetDen >> (Which == 3 ? 1 : 0);
};
using NumHalved = Smaller<0, "x and y numerators claimed within 2^22 |run| (A1)">;
using ColHalved = Smaller<1, "a crossing's column claimed within 2^14 + 1 (A2)">;
using RampHalved = Smaller<2, "ramp integrals claimed within 2^93 (A7)">;
using MeetDenHalved = Smaller<3, "meeting point denominator claimed within 2^49 (A6)">;

} // namespace

MutationSelfcheck mutation_selfcheck() {
  return {"path areas",
          {refute<AreaWide64>(kAreaBudgetPart<kA7>), refute<NumHalved>(kAreaBudgetPart<kA1>),
           refute<TopFromNextColumn, ColHalved>(kAreaBudgetPart<kA2>),
           refute<LeftShort>(kAreaBudgetPart<kA3>), refute<MeetDenHalved>(kAreaBudgetPart<kA6>),
           refute<RampHalved>(kAreaBudgetPart<kA7>)},
          AreaKernelModel::constants(),
          {"PATH.GEOMETRY", "SNAP.VERTEX.RANGE", "FIX.BUDGET.EDGE_VALUE"}};
}

} // namespace rastrules::proofs
