// SPDX-License-Identifier: MIT
// Self-check: the path obligations can fail. Runs prove_line_crossing and prove_tie_partition
// against deliberately
// broken path models, each derived from PathKernelModel with one member replaced, and passes
// only if every mutant is REFUTED (with a counterexample).
// Cites no rule: it is evidence about the proof, not about the kernel.
// Assumes: PATH.GEOMETRY, PATH.WINDING (as the obligation does)
// Expected: every mutant REFUTED; exit status 0 iff so.

#include <cstdint>

#include "path/line_crossing.hpp"
#include "path/tie_partition.hpp"
#include "support/kernel_model.hpp"
#include "support/mutation.hpp"
#include "support/prover.hpp"
#include "support/sym.hpp"

namespace rastrules::proofs {
namespace {

// A crossing exactly at the sample always counts, whatever hx says.
struct TieAlwaysCounts : PathKernelModel {
  static constexpr const char* kName = "crossing at the sample always counts";
  template <bool XRight, class S>
  static SymBool crossing_right(const S& e, const S& y0, const S& y1) {
    return formula::path_crossing_right<false>(e, y0, y1);
  }
};

// Closed in y at both ends: a vertex on the sample's row counts for both of its edges.
struct ClosedInY : PathKernelModel {
  static constexpr const char* kName = "edges span [min, max], closed at both ends";
  template <bool YDown, class S> static SymBool spans(const S& y0, const S& y1, const S& sy) {
    return ((y0 <= sy) && (sy <= y1)) || ((y1 <= sy) && (sy <= y0));
  }
};

// The half-open interval on the wrong side for the convention (hy read the other way).
struct HalfOpenFlipped : PathKernelModel {
  static constexpr const char* kName = "half-open in y on the wrong side";
  template <bool YDown, class S> static SymBool spans(const S& y0, const S& y1, const S& sy) {
    return formula::path_edge_spans<!YDown>(y0, y1, sy);
  }
};

// The row threshold one too far right for hx = +1 (ceil(N / D) instead of ceil(N / D) - 1).
struct ThresholdOffByOne : PathKernelModel {
  static constexpr const char* kName = "row threshold ceil(N / D), not ceil(N / D) - 1";
  template <bool XRight, class S> static S threshold(const S& q, const S& r) {
    return select(r > S(0), q + S(1), q);
  }
};

// The crossing numerator measured from the bottom end.
struct NumeratorFromBottom : PathKernelModel {
  static constexpr const char* kName = "crossing numerator measured from the lower end";
  template <class S>
  static S crossing_numerator(const S& xa, const S& ya, const S& xb, const S& yb, const S& sy) {
    return xb * (yb - ya) + (sy - ya) * (xb - xa);
  }
};

// A crossing at the sample counts for edges running down and never for edges running up
// (whatever hx says): an edge and its reverse no longer cancel there.
struct TieByDirection : PathKernelModel {
  static constexpr const char* kName = "a crossing at the sample counts for down edges only";
  template <bool XRight, class S>
  static SymBool crossing_right(const S& e, const S& y0, const S& y1) {
    const S zero(0);
    return ((y1 > y0) && (e >= zero)) || ((y1 < y0) && (e < zero));
  }
};

// The t = 1 end rule of cubic_end_crossings with the parity of the order read the other way
// (an odd order m + 1 taken as even): a curve and its reverse no longer agree at their ends.
struct EndParityFlipped : PathKernelModel {
  static constexpr const char* kName = "curve end rule at t = 1 with the order's parity flipped";
  template <class W>
  static EndCrossing end_at_one(const std::array<W, 4>& c, const std::array<W, 4>& e, int hy) {
    // crossed iff -before == hy, that is before == -hy; the direction stays -hy.
    EndCrossing r = PathKernelModel::end_at_one(c, e, -hy);
    r.dir = c[0].expr().ctx().int_val(-hy);
    return r;
  }
};

// The same for a quadratic's end root at t = 1 (rational_quadratic_crossings).
struct QuadraticEndParityFlipped : PathKernelModel {
  static constexpr const char* kName =
      "quadratic end rule at t = 1 with the order's parity flipped";
  template <class W>
  static EndCrossing quadratic_end(const std::array<W, 4>& c, const std::array<W, 4>& e, const W& p,
                                   const W& q, bool at_one, int hy) {
    if (!at_one)
      return PathKernelModel::quadratic_end(c, e, p, q, at_one, hy);
    EndCrossing r = PathKernelModel::quadratic_end(c, e, p, q, at_one, -hy);
    r.dir = c[0].expr().ctx().int_val(-hy);
    return r;
  }
};

// 32-bit accumulators: the edge value and the numerator overflow.
using Int32Path = AccumulatorOf<PathKernelModel, std::int32_t, "int32_t path accumulator">;

} // namespace

MutationSelfcheck mutation_selfcheck() {
  return {"path",
          {refute<TieAlwaysCounts, ClosedInY, HalfOpenFlipped, ThresholdOffByOne,
                  NumeratorFromBottom, Int32Path>(kLineCrossing),
           refute<TieByDirection, ClosedInY, EndParityFlipped, QuadraticEndParityFlipped>(
               kTiePartition)},
          PathKernelModel::constants(),
          {"PATH.GEOMETRY", "PATH.WINDING"}};
}

} // namespace rastrules::proofs
