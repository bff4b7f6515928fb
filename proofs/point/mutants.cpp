// SPDX-License-Identifier: MIT
// Self-check: the point obligation can fail. Runs prove_point_half_open_square against
// deliberately broken point models, each derived from PointKernelModel with one member
// replaced, and passes only if every mutant is REFUTED (with a counterexample). A mutant that
// survives means the proof cannot see that kind of bug.
// Cites no rule: it is evidence about the proof, not about the kernel.
// Assumes: POINT.RANGE, SNAP.VERTEX.RANGE (as the obligation does)
// Expected: every mutant REFUTED; exit status 0 iff so.

#include <array>
#include <cstdint>

#include "point/half_open_square.hpp"
#include "point/point_model.hpp"
#include "support/kernel_model.hpp"
#include "support/mutation.hpp"
#include "support/prover.hpp"
#include "support/sym.hpp"

namespace rastrules::proofs {
namespace {

// The second triangle's upper-right corner one subpixel lower: a sliver gap along the diagonal.
struct GapOnDiagonal : PointKernelModel {
  static constexpr const char* kName = "one-subpixel gap along the diagonal";
  template <class S> static std::array<Triangle<S>, 2> point_triangles(const Point<S>& c) {
    auto t = PointKernelModel::point_triangles<S>(c);
    t[1][1].y = t[1][1].y + S(1);
    return t;
  }
};

// The other diagonal with the second triangle wound counter-clockwise, in a kernel that does
// not normalise windings: the counter-clockwise triangle covers nothing.
struct FlippedDiagonalWrongWinding : PointKernelModel {
  static constexpr const char* kName = "diagonal flipped, counter-clockwise half, no normalisation";
  template <class S> static std::array<Triangle<S>, 2> point_triangles(const Point<S>& c) {
    const auto t = PointKernelModel::point_triangles<S>(c);
    const Point<S> tl = t[0][0], tr = t[0][1], bl = t[0][2], br = t[1][2];
    return {Triangle<S>{tl, tr, br}, Triangle<S>{tl, bl, br}};
  }
  template <class S> static SymBool is_clockwise(const Triangle<S>&) { return SymBool(true); }
};

// Two triangles that overlap (both contain the top edge) instead of tiling the square.
struct OverlappingHalves : PointKernelModel {
  static constexpr const char* kName = "overlapping halves (TL, TR, BL) and (TL, TR, BR)";
  template <class S> static std::array<Triangle<S>, 2> point_triangles(const Point<S>& c) {
    const auto t = PointKernelModel::point_triangles<S>(c);
    const Point<S> tl = t[0][0], tr = t[0][1], br = t[1][2];
    return {t[0], Triangle<S>{tl, tr, br}};
  }
};

// A square one subpixel too small (half side 127 raw).
struct SquareTooSmall : PointKernelModel {
  static constexpr const char* kName = "half side 127 raw instead of 128";
  template <class S> static std::array<Triangle<S>, 2> point_triangles(const Point<S>& c) {
    const auto t = formula::point_z_triangles<S>(c.x, c.y, S(kSubpixelHalf - 1));
    return {to_triangle<S>(t[0]), to_triangle<S>(t[1])};
  }
};

// Samples on an edge never inside: the square becomes open.
struct TiesNeverInside : PointKernelModel {
  static constexpr const char* kName = "samples on an edge never inside";
  template <class S> static SymBool inside(const S& e, const SymBool&) { return e > S(0); }
};

// The point range as wide as the vertex range: corners leave SNAP.VERTEX.RANGE.
struct PointRangeTooWide : PointKernelModel {
  static constexpr const char* kName = "point centres over the whole vertex range";
  static constexpr std::int64_t kMinPointCentreRaw = kMinVertexRaw;
  static constexpr std::int64_t kMaxPointCentreRaw = kMaxVertexRaw;
};

} // namespace

MutationSelfcheck mutation_selfcheck() {
  return {"point",
          {refute<GapOnDiagonal, FlippedDiagonalWrongWinding, OverlappingHalves, SquareTooSmall,
                  TiesNeverInside, PointRangeTooWide>(kHalfOpenSquare)},
          PointKernelModel::constants(),
          {"POINT.RANGE", "SNAP.VERTEX.RANGE"}};
}

} // namespace rastrules::proofs
