// SPDX-License-Identifier: MIT
// Self-check: the diamond-exit obligations can fail. Runs prove_d3d_diamond_exit and
// prove_d3d_meets_witness against deliberately broken models of the D3D test area, each
// derived from DiamondKernelModel, and passes only if every mutant is REFUTED (with a
// counterexample) by at least one theorem.
// Cites no rule: it is evidence about the proofs, not about the kernel.
// Expected: every mutant REFUTED; exit status 0 iff so.

#include "line/diamond_exit.hpp"
#include "support/mutation.hpp"
#include "support/prover.hpp"

namespace rastrules::proofs {
namespace {

// A test area given by four edge strictness flags (no corner added for y-major lines).
template <bool S0, bool S1, bool S2, bool S3> struct StrictnessModel : DiamondKernelModel {
  template <bool YMajor, class M>
  static auto meets(const M& au, const M& av, const M& du, const M& dv, const M& h) {
    const M zero(0), one(1);
    return formula::t_feasible(formula::segment_in_diamond_constraints<M, M>(
                                   au, av, du, dv, {h, h, h, h}, {S0, S1, S2, S3}, zero, one, one),
                               zero);
  }
  template <bool YMajor, class M> static auto contains(const M& pu, const M& pv, const M& h) {
    const M zero(0);
    return meets<YMajor, M>(pu, pv, zero, zero, h);
  }
  template <bool YMajor, class M>
  static auto exits(const M& au, const M& av, const M& bu, const M& bv, const M& h) {
    return meets<YMajor, M>(au, av, bu - au, bv - av, h) && !contains<YMajor, M>(bu, bv, h);
  }
};

constexpr bool x_major_area(bool) {
  return false;
}
constexpr bool other_area(bool y_major) {
  return !y_major;
}

// The right corner is never included (y-major lines use the x-major area).
struct RightCornerNeverIncluded : DiamondAreaModel<x_major_area> {
  static constexpr const char* kName = "right corner never included (y-major as x-major)";
};

// x-major and y-major exchanged.
struct MajorSwapped : DiamondAreaModel<other_area> {
  static constexpr const char* kName = "x-major and y-major areas swapped";
};

struct UpperEdgesIncluded : StrictnessModel<true, true, false, false> {
  static constexpr const char* kName = "upper edges and top corner included instead of lower";
};
struct OpenDiamond : StrictnessModel<true, true, true, true> {
  static constexpr const char* kName = "open diamond (bottom corner and lower edges excluded)";
};
struct ClosedDiamond : StrictnessModel<false, false, false, false> {
  static constexpr const char* kName = "closed diamond (every edge and corner included)";
};
struct LowerLeftExcluded : StrictnessModel<false, true, true, true> {
  static constexpr const char* kName = "lower-left edge excluded";
};

// Only the touch test is broken: it says "touched" too often (upper edges and the top, left
// and, x-major, right corners count), while the end-point test is the kernel's. The end-point
// and "exits" theorems and the forward direction of "touches" still hold; only the reverse
// direction (prove_d3d_meets_witness) can refute it.
struct MeetsUpperEdgesClosed : DiamondKernelModel {
  static constexpr const char* kName =
      "touch test with closed upper edges (end-point test correct)";
  template <bool YMajor, class M>
  static auto meets(const M& au, const M& av, const M& du, const M& dv, const M& h) {
    const M zero(0), one(1);
    const auto closed = formula::t_feasible(
        formula::segment_in_diamond_constraints<M, M>(au, av, du, dv, {h, h, h, h},
                                                      {false, false, false, false}, zero, one, one),
        zero);
    if constexpr (YMajor) {
      return closed || formula::on_segment(h, zero, au, av, du, dv);
    } else {
      return closed;
    }
  }
  template <bool YMajor, class M>
  static auto exits(const M& au, const M& av, const M& bu, const M& bv, const M& h) {
    return meets<YMajor, M>(au, av, bu - au, bv - av, h) &&
           !DiamondKernelModel::contains<YMajor, M>(bu, bv, h);
  }
};

} // namespace

// Both diamond-exit obligations; their NraProver theorems count too.
MutationSelfcheck mutation_selfcheck() {
  return {"line",
          {refute<RightCornerNeverIncluded, MajorSwapped, UpperEdgesIncluded, OpenDiamond,
                  ClosedDiamond, LowerLeftExcluded, MeetsUpperEdgesClosed>(
              "line/diamond_exit_matches_spec",
              []<class F>(Prover& pr) {
                NraProver nra(pr.ctx());
                prove_d3d_diamond_exit<F>(pr, nra);
                prove_d3d_meets_witness<F>(pr, nra);
                return nra.results();
              })},
          kernel_constants()};
}

} // namespace rastrules::proofs
