// SPDX-License-Identifier: MIT
// Obligation path/tie_partition (PATH.TIE.PARTITION) as a template over a path kernel model.
// Used by tie_partition.cpp and mutants.cpp.
//
// The winding number of a closed contour of line edges at a sample is the sum of the kernel's
// line contributions (line_contribution of path/line_crossing.hpp, which path/line_crossing
// proves equal to the spec's at s + (hx eps, hy delta)); PATH.WINDING sums contours.
// Two triangles sharing the edge ab in opposite directions, A = a -> b -> c and
// B = b -> a -> d, and their union contour U = a -> d -> b -> c (the shared edge left out):
//   W  (windings add): w_A(s) + w_B(s) = w_U(s) at every sample s, under every convention:
//      the shared edge's two directions cancel exactly (the same test decides both, with
//      opposite signs); any two contours sharing an edge in opposite directions work the same
//      way edge by edge, triangles are the case stated here;
//   X  (exactly once): for A and B clockwise (c and d on opposite sides of ab, each area > 0)
//      every integer sample on the open segment ab has w_A, w_B in {0, 1} and w_A + w_B = 1:
//      exactly one of the two paths covers it, under nonzero and under even-odd.
// X uses the encoding and lemmas of tri/shared_edge_exactly_once.hpp: b = a + n delta,
// s = a + k delta, 0 < k < n (every integer point strictly between a and b), lemma L0 on signs
// and lemma L1 (the kernel's edge values at s: E_ab = E_ba = 0, E_bc and E_ca with the sign of
// A(a, b, c), E_cb and E_ac opposite), proved here again and instantiated at c and d.

#pragma once

#include <string>
#include <vector>

#include "path/line_crossing.hpp"
#include "support/kernel_model.hpp"
#include "support/obligation.hpp"
#include "support/prover.hpp"
#include "tri/shared_edge_exactly_once.hpp"

namespace rastrules::proofs {

// The winding number at s of the closed contour through the points v (in order), as the sum
// of model F's line contributions of its edges.
template <class F, bool XRight, bool YDown, class S, std::size_t N>
z3::expr contour_winding(const std::array<Point<S>, N>& v, const Point<S>& s) {
  z3::expr w = s.x.expr().ctx().int_val(0);
  for (std::size_t i = 0; i < N; ++i)
    w = w + line_contribution<F, XRight, YDown>(v[i], v[(i + 1) % N], s).expr();
  return w;
}

// W, for every convention: any a, b, c, d, s in range.
template <class F> void prove_windings_add(Prover& pr) {
  std::vector<z3::expr> hyps;
  const auto [a, b, c, d, s] = points_in_range<F>(pr.domain(), {"a", "b", "c", "d", "s"}, hyps);
  for_each_convention([&]<bool TopInclusive, bool LeftInclusive>(const char* name) {
    constexpr bool kXRight = LeftInclusive;
    constexpr bool kYDown = TopInclusive;
    const std::size_t mark = pr.domain().mark();
    const z3::expr wa = contour_winding<F, kXRight, kYDown>(std::array{a, b, c}, s);
    const z3::expr wb = contour_winding<F, kXRight, kYDown>(std::array{b, a, d}, s);
    const z3::expr wu = contour_winding<F, kXRight, kYDown>(std::array{a, d, b, c}, s);
    pr.watch("w_A", wa, Unit::kInteger);
    pr.watch("w_B", wb, Unit::kInteger);
    pr.watch("w_U", wu, Unit::kInteger);
    pr.prove(std::string("W: abc and bad sharing ab: w_A + w_B = w_U of adbc, no overflow (") +
                 name + ")",
             hyps, wa + wb == wu, pr.domain().obligations_since(mark));
  });
}

// rule: PATH.TIE.PARTITION
template <class F> void prove_tie_partition(Prover& pr) {
  using S = typename F::Acc;
  prove_windings_add<F>(pr);
  // X: the shared edge a -> b = a + n delta, the sample p = a + k delta.
  const SharedSegment<S> seg = shared_segment<S>(pr.domain(), point_var<S>(pr.domain(), "xa"), "x");
  const Point<S>&a = seg.a, &b = seg.b, &p = seg.p, &c = seg.c, &d = seg.d;
  const Status l1 = prove_segment_lemmas<F>(pr, seg);
  // Assumes: PATH.GEOMETRY (every point in range); A = abc and B = bad clockwise.
  const std::vector<z3::expr> hyps = {
      in_vertex_range<F>(a),
      in_vertex_range<F>(b),
      in_vertex_range<F>(c),
      in_vertex_range<F>(d),
      seg.on_segment,
      F::twice_signed_area(Triangle<S>{a, b, c}).expr() > 0,
      F::twice_signed_area(Triangle<S>{b, a, d}).expr() > 0,
      segment_edge_values<F>(a, b, c, p), // L1 at c
      segment_edge_values<F>(a, b, d, p), // L1 at d
  };
  for_each_convention([&]<bool TopInclusive, bool LeftInclusive>(const char* name) {
    constexpr bool kXRight = LeftInclusive;
    constexpr bool kYDown = TopInclusive;
    const std::string theorem =
        std::string("X: clockwise abc and bad: a sample on the open edge ab has w_A, w_B in "
                    "{0, 1} and w_A + w_B = 1 (") +
        name + ")";
    if (l1 != Status::kProved) {
      pr.skip(theorem, "relies on lemma L1, which was not proved");
      return;
    }
    const z3::expr wa = contour_winding<F, kXRight, kYDown>(std::array{a, b, c}, p);
    const z3::expr wb = contour_winding<F, kXRight, kYDown>(std::array{b, a, d}, p);
    pr.watch("px", p.x.expr(), Unit::kCoordRaw);
    pr.watch("py", p.y.expr(), Unit::kCoordRaw);
    pr.watch("w_A", wa, Unit::kInteger);
    pr.watch("w_B", wb, Unit::kInteger);
    pr.prove(theorem, hyps, 0 <= wa && wa <= 1 && 0 <= wb && wb <= 1 && wa + wb == 1);
  });
}

// The obligation as its proof and the self-check run it.
inline const ProofObligation kTiePartition{"path/tie_partition",
                                           []<class F>(Prover& pr) { prove_tie_partition<F>(pr); }};

} // namespace rastrules::proofs
