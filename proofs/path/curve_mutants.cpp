// SPDX-License-Identifier: MIT
// Self-check: the curve budget and tie partition obligations can fail. Runs prove_curve_budget
// (all of it, or the group of theorems a mutant targets) and prove_tie_partition against
// deliberately broken models, each derived from CurveKernelModel or PathKernelModel with one
// member replaced, and passes only if every mutant is REFUTED (with a counterexample). The bound
// mutants state each proved magnitude one bit smaller (one four bits): each is refuted, so every
// budget theorem can fail and its bound is tight. Cites no rule: it is evidence about the proof,
// not about the kernel. Assumes: PATH.GEOMETRY, SNAP.VERTEX.RANGE, PATH.WINDING, PATH.SAMPLE.TIE
// (as the obligations do) Expected: every mutant REFUTED; exit status 0 iff so.

#include <array>
#include <cstdint>

#include "path/curve_budget.hpp"
#include "path/tie_partition.hpp"
#include "support/kernel_model.hpp"
#include "support/mutation.hpp"
#include "support/prover.hpp"
#include "support/sym.hpp"

namespace rastrules::proofs {
namespace {

// The curve test's wide integers as int64_t (one size smaller than the kernel's __int128).
struct CurveWide64 : CurveKernelModel {
  static constexpr const char* kName = "curve wide integers in int64_t, not __int128";
  using W = Sym<std::int64_t>;
};

// Raw coordinates one bit wider than PATH.GEOMETRY's 2^23.
using CurveRange24 = CoordinateRangeOf<CurveKernelModel, 24, "curve coordinates up to 2^24">;

// The Lipschitz bound without absolute values (|e1| + 2 |e2| + 3 |e3| read as e1 + 2 e2 + 3 e3).
struct LipschitzSigned : CurveKernelModel {
  static constexpr const char* kName = "Lipschitz bound without absolute values";
  template <class S, class T> static T lipschitz(const std::array<S, 4>& e) {
    return formula::curve_lipschitz_scaled<S, T>(
        e, [](const SymBool&, const S& t, const S& f) { return select(SymBool(true), f, t); });
  }
};

// Each proved magnitude Bits bits smaller (the theorem that proves it must be refuted): bound
// Which of CurveKernelModel divided by 2^Bits, the others kept. One bit for every bound but the
// cubic end path's numerator: its counterexamples near 2^114 (p, q near 2^29) take Z3 longer
// than the test's time limit, so that mutant claims 2^111, which the linear case already
// exceeds (up to 14^4 2^96 > 1.17 2^111).
enum Bound {
  kCoefB,
  kBernB,
  kScaledB,
  kScaledHB,
  kLipB,
  kIntervalB,
  kScanB,
  kDiscQuadB,
  kNum2B,
  kHB,
  kDiscHB,
  kNum3B,
  kDiscDerivB,
  kRowScaledB
};
template <Bound Which, int Bits, MutantName Name> struct Smaller : CurveKernelModel {
  using Base = CurveKernelModel;
  static constexpr const char* kName = Name.text;
  static constexpr Int128 half(Bound b, Int128 v) { return b == Which ? v >> Bits : v; }
  static constexpr std::array<Int128, 4> kCoef{
      half(kCoefB, Base::kCoef[0]), half(kCoefB, Base::kCoef[1]), half(kCoefB, Base::kCoef[2]),
      half(kCoefB, Base::kCoef[3])};
  static constexpr Int128 kBern = half(kBernB, Base::kBern);
  static constexpr Int128 kScaled = half(kScaledB, Base::kScaled);
  static constexpr Int128 kScaledH = half(kScaledHB, Base::kScaledH);
  static constexpr Int128 kLip = half(kLipB, Base::kLip);
  static constexpr Int128 kInterval = half(kIntervalB, Base::kInterval);
  static constexpr Int128 kScan = half(kScanB, Base::kScan);
  static constexpr Int128 kDiscQuad = half(kDiscQuadB, Base::kDiscQuad);
  static constexpr Int128 kNum2 = half(kNum2B, Base::kNum2);
  static constexpr Int128 kH = half(kHB, Base::kH);
  static constexpr Int128 kDiscH = half(kDiscHB, Base::kDiscH);
  static constexpr Int128 kNum3 = half(kNum3B, Base::kNum3);
  static constexpr Int128 kDiscDeriv = half(kDiscDerivB, Base::kDiscDeriv);
  static constexpr Int128 kRowScaled = half(kRowScaledB, Base::kRowScaled);
};
using CoefHalved = Smaller<kCoefB, 1, "power coefficients claimed within kCoef / 2 (C1)">;
using BernHalved = Smaller<kBernB, 1, "3 b(g) claimed within 3 2^23 (C1)">;
using ScaledHalved = Smaller<kScaledB, 1, "P(k / 2^30) 2^90 claimed below 2^117 (C2)">;
using ScaledHHalved = Smaller<kScaledHB, 1, "h's P(k / 2^30) 2^90 claimed below 2^119 (C2)">;
using LipHalved = Smaller<kLipB, 1, "L 2^60 claimed below 2^88 (C3)">;
using IntervalHalved =
    Smaller<kIntervalB, 1, "interval Bernstein coefficients claimed below 2^119 (C4)">;
using ScanHalved = Smaller<kScanB, 1, "the scan's Bernstein coefficients claimed below 2^47 (C4)">;
using DiscQuadHalved = Smaller<kDiscQuadB, 1, "quadratic discriminant claimed below 2^51 (C5)">;
using Num2Halved = Smaller<kNum2B, 1, "quadratic x numerator claimed below 2^78 (C5)">;
using HHalved = Smaller<kHB, 1, "h's coefficients claimed within 7 2^24 (C6)">;
using DiscHHalved = Smaller<kDiscHB, 1, "h's discriminant claimed below 2^57 (C6)">;
using Num3Short = Smaller<kNum3B, 4, "cubic x numerator claimed below 2^111 (C6)">;
using DiscDerivHalved = Smaller<kDiscDerivB, 1, "c2^2 - 3 c1 c3 claimed below 2^54 (C7)">;
using RowScaledHalved = Smaller<kRowScaledB, 1, "s.y 2^90 claimed below 2^112 (C7)">;

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

} // namespace

MutationSelfcheck mutation_selfcheck() {
  return {"path curves and partition",
          {refute<CurveWide64>(kCurveBudget),
           refute<CurveRange24, CoefHalved, BernHalved>(kCurveBudgetPart<kC1>),
           refute<ScaledHalved, ScaledHHalved>(kCurveBudgetPart<kC2>),
           refute<LipschitzSigned, LipHalved>(kCurveBudgetPart<kC3>),
           refute<IntervalHalved, ScanHalved>(kCurveBudgetPart<kC4>),
           refute<DiscQuadHalved, Num2Halved>(kCurveBudgetPart<kC5>),
           refute<HHalved, DiscHHalved, Num3Short>(kCurveBudgetPart<kC6>),
           refute<DiscDerivHalved, RowScaledHalved>(kCurveBudgetPart<kC7>),
           refute<TieByDirection, EndParityFlipped, QuadraticEndParityFlipped>(kTiePartition)},
          CurveKernelModel::constants(),
          {"PATH.GEOMETRY", "SNAP.VERTEX.RANGE", "PATH.WINDING", "PATH.SAMPLE.TIE"}};
}

} // namespace rastrules::proofs
