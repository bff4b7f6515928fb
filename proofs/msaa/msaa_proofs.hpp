// SPDX-License-Identifier: MIT
// The kernel's multisampling arithmetic as the proofs see it, and the obligations
// MSAA.SAMPLE.POSITION and MSAA.CENTROID.WITHIN as templates over a model, so that the same
// theorems run against the kernel (sample_position.cpp, centroid_within.cpp) and against
// deliberately broken models (mutants.cpp).
//
// MsaaKernelModel = KernelModel (support/kernel_model.hpp: the kernel's formula::edge_value on
// Sym<int64_t>, the per-edge test `inside`) plus:
//   - sample_position: restated from rastrules::sample_position (msaa.hpp), which the kernel
//     writes on concrete int32_t values: pixel_center (fixed.hpp) is
//     px * kSubpixelOne + kSubpixelHalf, then + o * kSampleGridUnit, all in int32_t. The
//     executables check the restatement against the compiled constexpr function at every
//     offset of the grid and the extreme pixels before proving anything;
//   - the patterns: the kernel's own tables, read at run time from rastrules::standard_pattern
//     and rastrules::center_pattern (nothing retyped);
//   - the constants kMaxTargetSide, kSampleGridMin/Max, kSampleGridUnit of fixed.hpp/msaa.hpp.

#pragma once

#include <array>
#include <cstdint>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "rastrules/fixed.hpp"
#include "rastrules/msaa.hpp"
#include "support/kernel_model.hpp"
#include "support/obligation.hpp"
#include "support/prover.hpp"
#include "support/sym.hpp"

namespace rastrules::proofs {

// A pattern by name: offsets in 1/16 px, in sample-index order.
struct NamedPattern {
  std::string name;
  std::vector<std::pair<std::int64_t, std::int64_t>> offsets;
};

inline NamedPattern named(const std::string& name, const SamplePattern& p) {
  NamedPattern n{name, {}};
  for (const SampleOffset& o : p.positions)
    n.offsets.emplace_back(o.x, o.y);
  return n;
}

struct MsaaKernelModel : KernelModel {
  static constexpr const char* kName = "kernel";
  // sample_position and pixel_center compute in int32_t (msaa.hpp, fixed.hpp).
  using Pos = Sym<std::int32_t>;
  // Assumes: SCENE.TARGET.LIMITS (pixels 0 <= px, py < kMaxTargetSide), MSAA.PATTERN.GRID
  static constexpr std::int64_t kMaxSide = kMaxTargetSide;
  static constexpr std::int64_t kGridMin = kSampleGridMin;
  static constexpr std::int64_t kGridMax = kSampleGridMax;
  static constexpr std::int64_t kUnit = kSampleGridUnit;
  static constexpr std::int64_t kPixel = kSubpixelOne;
  static constexpr std::int64_t kHalf = kSubpixelHalf;

  static std::vector<Constant> constants() {
    return kernel_constants_and({{"kSampleGridMin", kSampleGridMin, Unit::kInteger},
                                 {"kSampleGridMax", kSampleGridMax, Unit::kInteger},
                                 {"kSampleGridUnit", kSampleGridUnit, Unit::kCoordRaw}});
  }

  // Mirrors rastrules::sample_position: pixel_center(px, py) + o * kSampleGridUnit in int32_t.
  template <class P>
  static Point<P> sample_position(const P& px, const P& py, const P& ox, const P& oy) {
    return Point<P>{px * P(kSubpixelOne) + P(kSubpixelHalf) + ox * P(kSampleGridUnit),
                    py * P(kSubpixelOne) + P(kSubpixelHalf) + oy * P(kSampleGridUnit)};
  }

  // The patterns MSAA.CENTROID.WITHIN speaks of: every standard and centre pattern, from the
  // kernel's own tables.
  static std::vector<NamedPattern> patterns() {
    std::vector<NamedPattern> v;
    for (const std::uint32_t n : {1u, 2u, 4u, 8u, 16u}) {
      v.push_back(named("standard " + std::to_string(n), standard_pattern(n)));
    }
    for (const std::uint32_t n : {1u, 2u, 4u, 8u, 16u}) {
      v.push_back(named("center " + std::to_string(n), center_pattern(n)));
    }
    return v;
  }
};

// Returns the int64_t value of an int32_t one (the kernel widens raw coordinates before every
// edge formula; widening is exact, so no obligation).
template <class P> Sym<std::int64_t> widen(const P& v) {
  return Sym<std::int64_t>(v.domain(), v.expr(), v.text());
}
template <class P> Point<Sym<std::int64_t>> widen(const Point<P>& p) {
  return Point<Sym<std::int64_t>>{widen(p.x), widen(p.y)};
}

// Returns false (after printing what differs) when the model's sample_position disagrees with
// the compiled rastrules::sample_position at every grid offset of the corner pixels.
template <class F> bool restatement_matches_kernel() {
  if constexpr (!std::is_same_v<F, MsaaKernelModel>) {
    return true; // mutants differ on purpose
  } else {
    const std::int32_t last = kMaxTargetSide - 1;
    for (const std::int32_t px : {0, 1, last}) {
      for (const std::int32_t py : {0, 7, last}) {
        for (std::int32_t ox = kSampleGridMin; ox <= kSampleGridMax; ++ox) {
          for (std::int32_t oy = kSampleGridMin; oy <= kSampleGridMax; ++oy) {
            const Vec2 k = sample_position(
                px, py, SampleOffset{static_cast<std::int8_t>(ox), static_cast<std::int8_t>(oy)});
            const std::int64_t mx = std::int64_t{px} * F::kPixel + F::kHalf + ox * F::kUnit;
            const std::int64_t my = std::int64_t{py} * F::kPixel + F::kHalf + oy * F::kUnit;
            if (k.x.raw() != mx || k.y.raw() != my) {
              std::cout << "restatement differs from rastrules::sample_position at pixel (" << px
                        << ", " << py << ") offset (" << ox << ", " << oy << ")\n";
              return false;
            }
          }
        }
      }
    }
    std::cout << "restatement of sample_position checked against the kernel at 9 pixels x 256 "
                 "offsets\n";
    return true;
  }
}

// MSAA.SAMPLE.POSITION. For every pixel 0 <= px, py < kMaxTargetSide and every offset on the
// grid [kSampleGridMin, kSampleGridMax]^2:
//   1. the sample position computed as the kernel does (int32_t) never overflows and lies in
//      SNAP.VERTEX.RANGE;
//   2. it lies in the pixel's half-open square [256 px, 256 px + 256) (MSAA.PATTERN.GRID);
//   3. for every edge a -> b with vertices in SNAP.VERTEX.RANGE, the edge value at the sample
//      (formula::edge_value on int64_t) and E + edge_bias never overflow, and
//      |E| < 2^kEdgeValueMagBits (FIX.BUDGET.EDGE_VALUE).
// with_edge_budget = false runs theorems 1 and 2 alone (for the mutation self-check).
// rule: MSAA.SAMPLE.POSITION, MSAA.PATTERN.GRID
template <class F> void prove_sample_position(Prover& pr, bool with_edge_budget = true) {
  using P = typename F::Pos;
  using S = typename F::Acc;
  Domain& dom = pr.domain();
  z3::context& ctx = pr.ctx();
  const P px = dom.var<typename P::rep>("px", Unit::kInteger);
  const P py = dom.var<typename P::rep>("py", Unit::kInteger);
  const P ox = dom.var<typename P::rep>("ox", Unit::kInteger);
  const P oy = dom.var<typename P::rep>("oy", Unit::kInteger);
  // Assumes: SCENE.TARGET.LIMITS, MSAA.PATTERN.GRID
  const std::vector<z3::expr> hyps = {in_closed(px.expr(), 0, F::kMaxSide - 1),
                                      in_closed(py.expr(), 0, F::kMaxSide - 1),
                                      in_closed(ox.expr(), F::kGridMin, F::kGridMax),
                                      in_closed(oy.expr(), F::kGridMin, F::kGridMax)};
  {
    const std::size_t mark = dom.mark();
    const Point<P> s = F::sample_position(px, py, ox, oy);
    pr.watch("sample x", s.x.expr(), Unit::kCoordRaw);
    pr.watch("sample y", s.y.expr(), Unit::kCoordRaw);
    pr.prove("sample positions fit int32_t and lie in SNAP.VERTEX.RANGE", hyps,
             in_vertex_range<F>(s), dom.obligations_since(mark));
  }
  {
    const std::size_t mark = dom.mark();
    const Point<P> s = F::sample_position(px, py, ox, oy);
    const z3::expr one = ctx.int_val(F::kPixel);
    const z3::expr goal = px.expr() * one <= s.x.expr() && s.x.expr() < px.expr() * one + one &&
                          py.expr() * one <= s.y.expr() && s.y.expr() < py.expr() * one + one;
    pr.watch("sample x", s.x.expr(), Unit::kCoordRaw);
    pr.watch("sample y", s.y.expr(), Unit::kCoordRaw);
    pr.prove("every sample lies in its pixel's half-open square", hyps, goal,
             dom.obligations_since(mark));
  }
  if (with_edge_budget) {
    const Point<S> a = point_var<S>(dom, "a");
    const Point<S> b = point_var<S>(dom, "b");
    std::vector<z3::expr> h = hyps;
    h.push_back(in_vertex_range<F>(a));
    h.push_back(in_vertex_range<F>(b));
    const std::size_t mark = dom.mark();
    const Point<S> s = widen(F::sample_position(px, py, ox, oy));
    const S e = F::edge_value(a, b, s);
    const S lo = e + F::template edge_bias<S>(false);
    const z3::expr bound = ctx.int_val(std::int64_t{1} << kEdgeValueMagBits);
    pr.watch("E_ab(sample)", e.expr(), Unit::kEdgeRaw);
    pr.prove("edge value and E + bias at a sample fit int64_t, |E| < 2^kEdgeValueMagBits", h,
             -bound < e.expr() && e.expr() < bound && lo.expr() < bound,
             dom.obligations_since(mark));
  }
}

// The obligation as its proof and the self-check run it.
inline const ProofObligation kSamplePosition{
    "msaa/sample_position", []<class F>(Prover& pr) { prove_sample_position<F>(pr); }};

// MSAA.CENTROID.WITHIN, the arithmetic core. For each pattern of the model, every edge a -> b
// with vertices in SNAP.VERTEX.RANGE, every pixel 0 <= px, py < kMaxTargetSide and either
// inclusiveness of the edge:
//   1. inside(E(s_k), incl) at every sample s_k implies inside(E(centre), incl): the pixel
//      centre passes every edge test that all samples pass, so a triangle that covers all
//      samples (branch 1 of both centroid rules) covers the centre, ties included;
//   2. E(s_k) >= 0 at every sample implies E(centre) >= 0, and E(centre) == 0 then implies
//      E(s_k) == 0 at every sample (every sample of a standard pattern has positive weight in
//      a convex combination giving the centre).
// Each E is the kernel's formula::edge_value on int64_t at the kernel's sample position. The
// proof goes through a lemma per pattern (L: E(s_k) == E(c) + kSampleGridUnit (o_y u - o_x v)
// with u = bx - ax, v = by - ay, for every sample, without overflow), then proves 1 and 2 for
// ALL integers E(c), u, v in that linear form (a superset of the values the kernel can reach),
// which keeps Z3 in linear arithmetic; 1 and 2 are skipped (UNKNOWN) unless L is PROVED.
// rule: MSAA.CENTROID.WITHIN
template <class F> void prove_centroid_within(Prover& pr) {
  using P = typename F::Pos;
  using S = typename F::Acc;
  Domain& dom = pr.domain();
  z3::context& ctx = pr.ctx();
  const P px = dom.var<typename P::rep>("px", Unit::kInteger);
  const P py = dom.var<typename P::rep>("py", Unit::kInteger);
  const Point<S> a = point_var<S>(dom, "a");
  const Point<S> b = point_var<S>(dom, "b");
  const z3::expr incl = dom.bool_var("inclusive");
  // The linear form's free variables.
  const S ecv = dom.var<std::int64_t>("Ec", Unit::kEdgeRaw);
  const S u = dom.var<std::int64_t>("u", Unit::kCoordRaw);
  const S v = dom.var<std::int64_t>("v", Unit::kCoordRaw);
  // Assumes: SCENE.TARGET.LIMITS, SNAP.VERTEX.RANGE, TRI.FILL.TOP_LEFT
  const std::vector<z3::expr> hyps = {in_closed(px.expr(), 0, F::kMaxSide - 1),
                                      in_closed(py.expr(), 0, F::kMaxSide - 1),
                                      in_vertex_range<F>(a), in_vertex_range<F>(b)};
  const auto linear = [&](std::int64_t ox, std::int64_t oy) {
    return ecv.expr() +
           ctx.int_val(F::kUnit) * (ctx.int_val(oy) * u.expr() - ctx.int_val(ox) * v.expr());
  };
  for (const NamedPattern& pat : F::patterns()) {
    // Lemma L on the kernel's formula.
    Status lemma = Status::kUnknown;
    {
      const std::size_t mark = dom.mark();
      const Point<S> c = widen(F::sample_position(px, py, P(0), P(0)));
      const S ec = F::edge_value(a, b, c);
      z3::expr all = ctx.bool_val(true);
      for (const auto& [ox, oy] : pat.offsets) {
        const Point<S> s = widen(F::sample_position(px, py, P(ox), P(oy)));
        const S e = F::edge_value(a, b, s);
        all = all && e.expr() == ec.expr() + ctx.int_val(F::kUnit) *
                                                 (ctx.int_val(oy) * (b.x.expr() - a.x.expr()) -
                                                  ctx.int_val(ox) * (b.y.expr() - a.y.expr()));
      }
      lemma = pr.prove(pat.name + ": L: E(sample) = E(centre) + unit (oy u - ox v), no overflow",
                       hyps, all, dom.obligations_since(mark));
    }
    const std::string t1 = pat.name + ": an edge test every sample passes, the centre passes";
    const std::string t2 =
        pat.name + ": E >= 0 at all samples => E >= 0 at the centre, 0 there only if 0 at all";
    if (lemma != Status::kProved) {
      pr.skip(t1, "lemma L not proved");
      pr.skip(t2, "lemma L not proved");
      continue;
    }
    z3::expr all_inside = ctx.bool_val(true), all_nonneg = ctx.bool_val(true),
             all_zero = ctx.bool_val(true);
    for (const auto& [ox, oy] : pat.offsets) {
      const S e(dom, linear(ox, oy), "E(s)");
      all_inside = all_inside && F::inside(e, SymBool(incl)).expr();
      all_nonneg = all_nonneg && e.expr() >= 0;
      all_zero = all_zero && e.expr() == 0;
    }
    const z3::expr ec = ecv.expr();
    pr.prove(t1, {}, z3::implies(all_inside, F::inside(ecv, SymBool(incl)).expr()));
    pr.prove(t2, {}, z3::implies(all_nonneg, ec >= 0 && z3::implies(ec == 0, all_zero)));
  }
}

// The obligation as its proof and the self-check run it.
inline const ProofObligation kCentroidWithin{
    "msaa/centroid_within", []<class F>(Prover& pr) { prove_centroid_within<F>(pr); }};

} // namespace rastrules::proofs
