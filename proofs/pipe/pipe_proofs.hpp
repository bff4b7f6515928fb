// SPDX-License-Identifier: MIT
// Obligations of the pipeline around the rules (spec/rules/pipe.md), as templates over a
// model: the barycentric sum (PIPE.BARY.SUM, PIPE.BARY.DOUBLE_EXACT), the UNORM depth
// conversion (PIPE.DEPTH.FORMAT, PIPE.DEPTH.UNORM_ROUND) and the guard band's snap margin
// (PIPE.CLIP.GUARD_BAND_SNAP). Used by bary_sum.cpp, depth_format.cpp, guard_band.cpp (the
// kernel) and mutants.cpp (broken models).

#pragma once

#include <z3++.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "rastrules/fixed.hpp"
#include "rastrules/formula/depth.hpp"
#include "rastrules/formula/edge.hpp"
#include "rastrules/pipeline.hpp"
#include "support/kernel_model.hpp"
#include "support/obligation.hpp"
#include "support/prover.hpp"
#include "support/sym.hpp"
#include "support/sym_float.hpp"

namespace rastrules::proofs {

// A UNORM depth format: its name, its bits n (it stores 0 .. 2^n - 1).
struct UnormFormat {
  const char* name;
  int bits;
};

// The pipeline as these obligations see it. Edge values are the kernel's formula templates
// (KernelModel); the depth conversion is formula::unorm_rounding_argument on double; the
// constants come from fixed.hpp, formula/depth.hpp and pipeline.hpp.
struct PipeModel : KernelModel {
  static constexpr const char* kName = "kernel";

  // Integers of magnitude at most 2^53 are doubles exactly (the significand's bits).
  static constexpr int kDoubleExactBits = std::numeric_limits<double>::digits;

  // The barycentric edge values of PIPE.BARY.EXACT: e0 = E_{v1 v2}(s), e1 = E_{v2 v0}(s),
  // e2 = E_{v0 v1}(s). Mirrors rastrules::pipe::barycentrics (kernel/src/pipeline.cpp), which
  // calls formula::edge_value<std::int64_t> in this order.
  template <class S> static std::array<S, 3> bary_edges(const Triangle<S>& v, const Point<S>& s) {
    return {edge_value(v[1], v[2], s), edge_value(v[2], v[0], s), edge_value(v[0], v[1], s)};
  }

  // The UNORM formats and the scale the kernel multiplies by (formula/depth.hpp).
  static std::vector<UnormFormat> unorm_formats() {
    return {UnormFormat{"d16", formula::kDepthD16Bits}, UnormFormat{"d24", formula::kDepthD24Bits}};
  }
  static double unorm_scale(int bits) { return static_cast<double>(formula::unorm_max(bits)); }

  // z * max + 0.5 in double: the kernel's to_depth_format computes std::floor(z * max + 0.5)
  // (checked by depth_format_matches_kernel below), PIPE.DEPTH.FORMAT.
  using Real = SymFloat<double>;
  static Real unorm_rounding_argument(const Real& z, const Real& max) {
    return formula::unorm_rounding_argument<Real>(z, max);
  }

  // PIPE.CLIP.VOLUME's guard band (px) and the snap scale (raw units per px).
  static constexpr double kGuardBand = pipe::kGuardBand;
  static constexpr std::int64_t kSnapOne = kSubpixelOne;
  static constexpr std::int64_t kTargetSide = kMaxTargetSide;

  static std::vector<Constant> constants() {
    static_assert(static_cast<double>(static_cast<std::int64_t>(pipe::kGuardBand * kSubpixelOne)) ==
                      pipe::kGuardBand * kSubpixelOne,
                  "the report shows kGuardBand in raw 16.8 units");
    return kernel_constants_and(
        {{"pipe::kGuardBand", static_cast<std::int64_t>(pipe::kGuardBand * kSubpixelOne),
          Unit::kCoordRaw},
         {"formula::unorm_max(kDepthD16Bits)", formula::unorm_max(formula::kDepthD16Bits),
          Unit::kInteger},
         {"formula::unorm_max(kDepthD24Bits)", formula::unorm_max(formula::kDepthD24Bits),
          Unit::kInteger},
         {"digits of double", kDoubleExactBits, Unit::kInteger}});
  }
};

// Returns false (after printing what differs) when the compiled rastrules::pipe::barycentrics
// disagrees with the model's bary_edges and twice_signed_area on int64_t: every triangle and
// point whose 8 coordinates are each one of kMinVertexRaw, kMaxVertexRaw, 0, -1 (65536), then
// 100000 seeded random ones in SNAP.VERTEX.RANGE. Ties the restated order of e0, e1, e2 to the
// kernel's code.
inline bool barycentrics_match_kernel() {
  std::mt19937_64 rng(20261122);
  std::uniform_int_distribution<std::int32_t> coord(kMinVertexRaw, kMaxVertexRaw);
  const std::array<std::int32_t, 4> corners = {kMinVertexRaw, kMaxVertexRaw, 0, -1};
  constexpr unsigned kCornerCases = 1u << 16;
  for (unsigned i = 0; i < kCornerCases + 100000; ++i) {
    std::array<std::int32_t, 8> c{};
    for (std::size_t j = 0; j < c.size(); ++j)
      c[j] = i < kCornerCases ? corners[(i >> (2 * j)) & 3u] : coord(rng);
    const auto vec = [&](std::size_t j) {
      return Vec2{Subpixel::from_raw(c[2 * j]), Subpixel::from_raw(c[2 * j + 1])};
    };
    const pipe::Barycentrics b = pipe::barycentrics({vec(0), vec(1), vec(2)}, vec(3));
    std::array<std::int64_t, 8> w{};
    for (std::size_t j = 0; j < w.size(); ++j)
      w[j] = c[j];
    const std::array<std::int64_t, 3> e = {
        formula::edge_value<std::int64_t>(w[2], w[3], w[4], w[5], w[6], w[7]),
        formula::edge_value<std::int64_t>(w[4], w[5], w[0], w[1], w[6], w[7]),
        formula::edge_value<std::int64_t>(w[0], w[1], w[2], w[3], w[6], w[7])};
    const std::int64_t area =
        formula::twice_signed_area<std::int64_t>(w[0], w[1], w[2], w[3], w[4], w[5]);
    if (b.e != e || b.area != area) {
      std::cout << "rastrules::pipe::barycentrics differs from the model at v = (" << c[0] << ", "
                << c[1] << "), (" << c[2] << ", " << c[3] << "), (" << c[4] << ", " << c[5]
                << "), s = (" << c[6] << ", " << c[7] << ")\n";
      return false;
    }
  }
  std::cout << "rastrules::pipe::barycentrics checked against the model on 165536 inputs\n";
  return true;
}

// Returns false (after printing what differs) when the compiled rastrules::pipe::to_depth_format
// (depth range [0, 1]) disagrees with floor(formula::unorm_rounding_argument(z, unorm_max(n)))
// in double, for d16 and d24: every z = (k + 1/2) / max and its 8 neighbouring doubles either
// side for 4096 seeded k (where rounding to nearest is decided), 0, 1, the smallest subnormal,
// and 100000 seeded random z in [0, 1]. Ties the formula the proof reasons about to the
// kernel's code.
inline bool depth_format_matches_kernel() {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const auto& [fmt, bits] : {std::pair{pipe::DepthFormat::kD16, formula::kDepthD16Bits},
                                  std::pair{pipe::DepthFormat::kD24, formula::kDepthD24Bits}}) {
    const double max = static_cast<double>(formula::unorm_max(bits));
    std::vector<double> zs = {0.0, 1.0, std::numeric_limits<double>::denorm_min()};
    std::uniform_int_distribution<std::uint32_t> kdist(0, formula::unorm_max(bits) - 1);
    for (int i = 0; i < 4096; ++i) {
      const std::uint32_t k = i < 4 ? static_cast<std::uint32_t>(i) : kdist(rng);
      double z = (static_cast<double>(k) + 0.5) / max;
      for (int j = 0; j < 8; ++j)
        z = std::nextafter(z, 0.0);
      for (int j = 0; j < 17; ++j, z = std::nextafter(z, 1.0))
        zs.push_back(z);
    }
    for (int i = 0; i < 100000; ++i)
      zs.push_back(unit(rng));
    for (const double z : zs) {
      const pipe::DepthValue v = pipe::to_depth_format(z, 0.0f, 1.0f, fmt);
      const double model = std::floor(formula::unorm_rounding_argument(z, max));
      if (static_cast<double>(v.unorm) != model) {
        std::printf("rastrules::pipe::to_depth_format differs from the formula at z = %a "
                    "(%u bits): kernel %u, formula %.17g\n",
                    z, static_cast<unsigned>(bits), static_cast<unsigned>(v.unorm), model);
        return false;
      }
    }
  }
  std::cout << "rastrules::pipe::to_depth_format checked against the formula (d16, d24) near "
               "4096 rounding boundaries and on 100000 random depths each\n";
  return true;
}

// PIPE.BARY.SUM and PIPE.BARY.DOUBLE_EXACT. For all snapped vertices v0, v1, v2 and every
// evaluation point s with raw coordinates in SNAP.VERTEX.RANGE, with e0 = E_{v1 v2}(s),
// e1 = E_{v2 v0}(s), e2 = E_{v0 v1}(s) and A = twice_signed_area(v0, v1, v2), all evaluated
// by the kernel's formula templates on the model's accumulator:
//   1. (e0 + e1) + e2 == A, and every intermediate (each difference and product of the three
//      edge values and of A, and both sums) fits the accumulator;
//   2. |e0|, |e1|, |e2|, |A| < 2^53, and so do the partial sum e0 + e1: each converts to double
//      exactly, which the double formulas of PIPE.INTERP.* and PIPE.DEPTH.INTERP rely on.
// rule: PIPE.BARY.SUM, PIPE.BARY.DOUBLE_EXACT
template <class F> void prove_bary_sum(Prover& pr) {
  using S = typename F::Acc;
  Domain& dom = pr.domain();
  z3::context& ctx = pr.ctx();
  // Assumes: SNAP.VERTEX.RANGE (vertices and the evaluation point)
  std::vector<z3::expr> hyps;
  const auto [v0, v1, v2, s] = points_in_range<F>(dom, {"v0", "v1", "v2", "s"}, hyps);
  const Triangle<S> t{v0, v1, v2};
  const std::string type = type_name<typename S::rep>();
  const auto watch_all = [&](const std::array<S, 3>& e, const S& area) {
    pr.watch("e0 = E_v1v2(s)", e[0].expr(), Unit::kEdgeRaw);
    pr.watch("e1 = E_v2v0(s)", e[1].expr(), Unit::kEdgeRaw);
    pr.watch("e2 = E_v0v1(s)", e[2].expr(), Unit::kEdgeRaw);
    pr.watch("A", area.expr(), Unit::kEdgeRaw);
  };
  {
    const std::size_t mark = dom.mark();
    const std::array<S, 3> e = F::bary_edges(t, s);
    const S area = F::twice_signed_area(t);
    const S sum = (e[0] + e[1]) + e[2];
    watch_all(e, area);
    pr.watch("e0 + e1 + e2", sum.expr(), Unit::kEdgeRaw);
    pr.prove("e0 + e1 + e2 == A; every intermediate fits " + type, hyps, (sum == area).expr(),
             dom.obligations_since(mark));
  }
  {
    const std::size_t mark = dom.mark();
    const std::array<S, 3> e = F::bary_edges(t, s);
    const S area = F::twice_signed_area(t);
    const z3::expr bound = ctx.int_val(std::int64_t{1} << F::kDoubleExactBits);
    const auto small = [&](const z3::expr& x) { return -bound < x && x < bound; };
    watch_all(e, area);
    pr.prove("|e0|, |e1|, |e2|, |A|, |e0 + e1| < 2^53: each is a double exactly", hyps,
             small(e[0].expr()) && small(e[1].expr()) && small(e[2].expr()) && small(area.expr()) &&
                 small(e[0].expr() + e[1].expr()),
             dom.obligations_since(mark));
  }
}

// The obligation as its proof and the self-check run it.
inline const ProofObligation kBarySum{"pipe/bary_sum",
                                      []<class F>(Prover& pr) { prove_bary_sum<F>(pr); }};

// PIPE.DEPTH.FORMAT and PIPE.DEPTH.UNORM_ROUND, on IEEE-754 double (Z3's floating-point theory,
// bit-exact). For every double z with 0 <= z <= 1 (a depth after PIPE.DEPTH.CLAMP, or a depth
// clear value) and each UNORM format of n bits, with max = the model's scale (2^n - 1), y =
// fl64(z * max) and k = floor(unorm_rounding_argument(z, max)) = floor(fl64(y + 0.5)) as the
// kernel computes it:
//   1. 0 <= k <= 2^n - 1: the conversion to uint32_t is exact and the value fits the format;
//   2. k - 0.5 <= y < k + 0.5 (with 1: k is an integer in [0, 2^24], so k -/+ 0.5 are
//      doubles and both comparisons are exact): k is the nearest integer to y, ties up, that is
//      k == floor(y + 0.5) with the exact + 0.5 of the spec, although the kernel rounds y + 0.5
//      to double first;
// and for d32f: static_cast<float>(z) lies in [0, 1].
// rule: PIPE.DEPTH.FORMAT, PIPE.DEPTH.UNORM_ROUND
template <class F> void prove_depth_format(Prover& pr) {
  using Real = SymFloat<double>;
  Domain& dom = pr.domain();
  pr.use_solver(Solver::kFloatingPoint);
  const Real z = Real::var(dom, "z");
  const Real zero(0.0);
  const Real one(1.0);
  const Real half(0.5);
  // Assumes: PIPE.DEPTH.CLAMP, PIPE.VIEWPORT.RANGE (0 <= MinDepth <= z <= MaxDepth <= 1; no NaN)
  const std::vector<z3::expr> hyps = {(zero <= z).expr(), (z <= one).expr()};
  for (const UnormFormat& fmt : F::unorm_formats()) {
    const std::string name = fmt.name;
    // The format's largest value, 2^n - 1, from the spec (not from the model).
    const Real top(static_cast<double>((std::int64_t{1} << fmt.bits) - 1));
    const Real max(F::unorm_scale(fmt.bits));
    const Real k = floor(F::unorm_rounding_argument(z, max));
    const Real y = z * max;
    pr.watch("y = fl64(z * max)", y.expr(), Unit::kFloat);
    pr.watch("k", k.expr(), Unit::kFloat);
    pr.prove(name + ": 0 <= floor(z * max + 0.5) <= 2^" + std::to_string(fmt.bits) +
                 " - 1 (fits the format, exact as uint32_t)",
             hyps, ((zero <= k) && (k <= top)).expr());
    pr.watch("y = fl64(z * max)", y.expr(), Unit::kFloat);
    pr.watch("k", k.expr(), Unit::kFloat);
    pr.prove(name + ": k - 0.5 <= fl64(z * max) < k + 0.5: k == floor(fl64(z * max) + 0.5) exactly",
             hyps, ((zero <= k) && (k <= top) && (k - half <= y) && (y < k + half)).expr());
  }
  {
    const SymFloat<float> f = convert<float>(z);
    pr.watch("float(z)", f.expr(), Unit::kFloat);
    pr.prove("d32f: 0 <= static_cast<float>(z) <= 1", hyps,
             ((SymFloat<float>(0.0) <= f) && (f <= SymFloat<float>(1.0))).expr());
  }
  pr.use_solver(Solver::kArithmetic);
}

// The obligation as its proof and the self-check run it.
inline const ProofObligation kDepthFormat{"pipe/depth_format",
                                          []<class F>(Prover& pr) { prove_depth_format<F>(pr); }};

// PIPE.CLIP.GUARD_BAND_SNAP. With G = the model's guard band (px, its exact value):
//   1. every window coordinate X with |X| <= G + 1 (a point of the guard band, moved by a
//      rounding error of at most 1 px) snaps inside SNAP.VERTEX.RANGE: every integer r within
//      1/2 of X * 256 (any round-to-nearest, SNAP.VERTEX.ROUND's ties to even among them) lies
//      in [kMinVertexRaw, kMaxVertexRaw];
//   2. the margin is wider: the same holds for |X| <= G + 1023;
//   3. every point of every pixel of the largest target (0 <= X <= kMaxTargetSide) lies at
//      least 15360 px inside the band (PIPE.CLIP.VOLUME's choice).
// rule: PIPE.CLIP.GUARD_BAND_SNAP
template <class F> void prove_guard_band(Prover& pr) {
  z3::context& ctx = pr.ctx();
  // The guard band's exact value: the double converted to a rational by Z3 (exact).
  const z3::expr g =
      z3::expr(ctx, Z3_mk_fpa_to_real(ctx, ctx.fpa_val(static_cast<double>(F::kGuardBand))))
          .simplify();
  if (!g.is_numeral()) {
    pr.skip("guard band theorems", "kGuardBand did not convert to a rational: " + g.to_string());
    return;
  }
  const z3::expr x = ctx.real_const("X");
  const z3::expr r = ctx.int_const("r");
  const z3::expr scale = ctx.real_val(F::kSnapOne);
  const z3::expr half = ctx.real_val(1, 2);
  const z3::expr rr = z3::to_real(r);
  // Assumes: SNAP.VERTEX.ROUND (r is a nearest integer to X * 256)
  const z3::expr nearest = scale * x - half <= rr && rr <= scale * x + half;
  const z3::expr lo = ctx.int_val(F::kMinRaw);
  const z3::expr hi = ctx.int_val(F::kMaxRaw);
  for (const std::int64_t err : {std::int64_t{1}, std::int64_t{1023}}) {
    const z3::expr reach = g + ctx.real_val(err);
    pr.watch("X (px)", x, Unit::kInteger);
    pr.watch("r", r, Unit::kCoordRaw);
    pr.prove("|X| <= kGuardBand + " + std::to_string(err) + " px snaps inside SNAP.VERTEX.RANGE",
             {-reach <= x, x <= reach, nearest}, lo <= r && r <= hi);
  }
  {
    const z3::expr inset = ctx.real_val(15360);
    pr.watch("X (px)", x, Unit::kInteger);
    pr.prove("every point of the largest target lies >= 15360 px inside the guard band",
             {ctx.real_val(0) <= x, x <= ctx.real_val(F::kTargetSide)},
             -g + inset <= x && x <= g - inset);
  }
}

// The obligation as its proof and the self-check run it.
inline const ProofObligation kGuardBand{"pipe/guard_band",
                                        []<class F>(Prover& pr) { prove_guard_band<F>(pr); }};

} // namespace rastrules::proofs
