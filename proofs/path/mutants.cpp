// SPDX-License-Identifier: MIT
// Self-check: the path obligation can fail. Runs prove_line_crossing against deliberately
// broken path models, each derived from PathKernelModel with one member replaced, and passes
// only if every mutant is REFUTED (with a counterexample).
// Cites no rule: it is evidence about the proof, not about the kernel.
// Assumes: PATH.GEOMETRY, PATH.WINDING (as the obligation does)
// Expected: every mutant REFUTED; exit status 0 iff so.

#include <cstdint>

#include "path/line_crossing.hpp"
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

// 32-bit accumulators: the edge value and the numerator overflow.
using Int32Path = AccumulatorOf<PathKernelModel, std::int32_t, "int32_t path accumulator">;

} // namespace

MutationSelfcheck mutation_selfcheck() {
  return {"path",
          {refute<TieAlwaysCounts, ClosedInY, HalfOpenFlipped, ThresholdOffByOne,
                  NumeratorFromBottom, Int32Path>(kLineCrossing)},
          PathKernelModel::constants(),
          {"PATH.GEOMETRY", "PATH.WINDING"}};
}

} // namespace rastrules::proofs
