// SPDX-License-Identifier: MIT
// The kernel as the proofs see it: a "model" policy whose members forward to the kernel's own
// rastrules::formula templates, instantiated on Sym (support/sym.hpp), with the constants of
// rastrules/fixed.hpp. Every obligation in proofs/ is a template over such a policy, so the
// same theorems run against KernelModel (the real proofs) and against deliberately broken
// models (proofs/selftest/mutants.cpp), which shows that each theorem can fail.
//
// Only two pieces are restated rather than instantiated, because the kernel writes them on
// concrete types in rastrules/triangle.hpp: the per-edge test `inside` (TRI.FILL.TOP_LEFT)
// and the winding normalisation of setup_triangle (TRI.ORIENT.NORMALISE). Both are one line
// and mirror the kernel's text.

#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "rastrules/fixed.hpp"
#include "rastrules/formula/edge.hpp"
#include "support/prover.hpp"
#include "support/sym.hpp"

namespace rastrules::proofs {

// A point in raw 16.8 units, with coordinates of symbolic type S.
template <class S> struct Point {
  S x;
  S y;
};

template <class S> using Triangle = std::array<Point<S>, 3>;

// Returns a point with fresh coordinates "<name>x", "<name>y".
template <class S> Point<S> point_var(Domain& dom, const std::string& name) {
  return Point<S>{dom.var<typename S::rep>(name + "x", Unit::kCoordRaw),
                  dom.var<typename S::rep>(name + "y", Unit::kCoordRaw)};
}

// Obligations call the model only as F::member (never a member from inside another member,
// except is_clockwise below), so a mutant that hides one member changes every use of it.
struct KernelModel {
  static constexpr const char* kName = "kernel";

  // The kernel instantiates every formula with std::int64_t (rastrules/triangle.hpp,
  // rastrules/raster/walk.hpp), on raw coordinates widened from int32_t.
  using Acc = Sym<std::int64_t>;

  // Assumes: SNAP.VERTEX.RANGE
  static constexpr std::int64_t kMinRaw = kMinVertexRaw;
  static constexpr std::int64_t kMaxRaw = kMaxVertexRaw;
  // One pixel in raw units: the traversal steps by kSubpixelOne (walk.hpp).
  static constexpr std::int64_t kOne = kSubpixelOne;

  static std::vector<Constant> constants() { return kernel_constants(); }

  template <class S> static S edge_value(const Point<S>& a, const Point<S>& b, const Point<S>& p) {
    return formula::edge_value<S>(a.x, a.y, b.x, b.y, p.x, p.y);
  }
  template <class S> static S twice_signed_area(const Triangle<S>& t) {
    return formula::twice_signed_area<S>(t[0].x, t[0].y, t[1].x, t[1].y, t[2].x, t[2].y);
  }
  template <class S> static auto is_top_edge(const Point<S>& a, const Point<S>& b) {
    return formula::is_top_edge<S>(a.x, a.y, b.x, b.y);
  }
  template <class S> static auto is_left_edge(const Point<S>& a, const Point<S>& b) {
    return formula::is_left_edge<S>(a.x, a.y, b.x, b.y);
  }
  template <bool TopInclusive, bool LeftInclusive, class S>
  static auto is_inclusive_edge(const Point<S>& a, const Point<S>& b) {
    return formula::is_inclusive_edge<TopInclusive, LeftInclusive, S>(a.x, a.y, b.x, b.y);
  }
  template <class S> static S edge_bias(bool inclusive) { return formula::edge_bias<S>(inclusive); }
  template <class S> static S edge_step_x(const Point<S>& a, const Point<S>& b, const S& one) {
    return formula::edge_step_x<S>(a.y, b.y, one);
  }
  template <class S> static S edge_step_y(const Point<S>& a, const Point<S>& b, const S& one) {
    return formula::edge_step_y<S>(a.x, b.x, one);
  }

  // Mirrors rastrules::inside (triangle.hpp): E > 0, or E == 0 and the edge is inclusive.
  // Mirrors (assumed, not proved here): TRI.FILL.TOP_LEFT
  template <class S> static SymBool inside(const S& e, const SymBool& inclusive) {
    const S zero(0);
    return e > zero || (e == zero && inclusive);
  }

  // Mirrors setup_triangle (triangle.hpp): `t.clockwise = t.twice_area > 0`, and a triangle
  // that is not clockwise is normalised to (v0, v2, v1) (see covers_normalised below).
  // Mirrors (assumed, not proved here): TRI.ORIENT.NORMALISE
  template <class S> static SymBool is_clockwise(const Triangle<S>& v) {
    return twice_signed_area(v) > S(0);
  }
};

// Returns whether clockwise (normalised) triangle t covers sample p under the convention
// (TopInclusive, LeftInclusive): inside all three edges (v0 v1), (v1 v2), (v2 v0), as
// rastrules::covers does for a rasterized triangle.
// Mirrors (assumed, not proved here): TRI.COVER.SAMPLE
template <class F, bool TopInclusive, bool LeftInclusive, class S>
SymBool covers(const Triangle<S>& t, const Point<S>& p) {
  SymBool all(true);
  for (std::size_t i = 0; i < 3; ++i) {
    const Point<S>& a = t[i];
    const Point<S>& b = t[(i + 1) % 3];
    all = all && F::inside(F::edge_value(a, b, p),
                           F::template is_inclusive_edge<TopInclusive, LeftInclusive>(a, b));
  }
  return all;
}

// Returns whether the triangle with vertices v (in the order given, A != 0) covers sample p
// under the convention (TopInclusive, LeftInclusive), after the winding normalisation of
// setup_triangle: a triangle that is not clockwise (F::is_clockwise) becomes (v0, v2, v1);
// then p must be inside all three edges (rastrules::covers). The kernel selects the vertex
// order and then evaluates; selecting between the two evaluations is the same function, and
// keeps every edge value a polynomial in the inputs.
// Mirrors (assumed, not proved here): TRI.ORIENT.NORMALISE, TRI.COVER.SAMPLE
template <class F, bool TopInclusive, bool LeftInclusive, class S>
SymBool covers_normalised(const Triangle<S>& v, const Point<S>& p) {
  return select(F::is_clockwise(v), covers<F, TopInclusive, LeftInclusive>(v, p),
                covers<F, TopInclusive, LeftInclusive>(Triangle<S>{v[0], v[2], v[1]}, p));
}

// Calls fn.template operator()<TopInclusive, LeftInclusive>(name) for the four fill
// conventions of TRI.FILL.CONVENTION, in the spec's order.
template <class Fn> void for_each_convention(Fn&& fn) {
  fn.template operator()<true, true>("top-left");
  fn.template operator()<false, true>("bottom-left");
  fn.template operator()<true, false>("top-right");
  fn.template operator()<false, false>("bottom-right");
}

// Returns lo <= v <= hi.
inline z3::expr in_closed(const z3::expr& v, std::int64_t lo, std::int64_t hi) {
  z3::context& ctx = v.ctx();
  return ctx.int_val(lo) <= v && v <= ctx.int_val(hi);
}

// Returns "p lies in the supported vertex range" (SNAP.VERTEX.RANGE) for model F.
template <class F, class S> z3::expr in_vertex_range(const Point<S>& p) {
  z3::context& ctx = p.x.expr().ctx();
  const z3::expr lo = ctx.int_val(F::kMinRaw);
  const z3::expr hi = ctx.int_val(F::kMaxRaw);
  return lo <= p.x.expr() && p.x.expr() <= hi && lo <= p.y.expr() && p.y.expr() <= hi;
}

// Returns one point per name, with fresh coordinates "<name>x", "<name>y" declared in the names'
// order, and appends "it lies in the supported vertex range" (in_vertex_range,
// SNAP.VERTEX.RANGE) to hyps for each, in the same order.
template <class F, std::size_t N>
std::array<Point<typename F::Acc>, N> points_in_range(Domain& dom, const char* const (&names)[N],
                                                      std::vector<z3::expr>& hyps) {
  using S = typename F::Acc;
  // A braced list is evaluated left to right.
  const auto declare = [&]<std::size_t... I>(std::index_sequence<I...>) {
    return std::array<Point<S>, N>{point_var<S>(dom, names[I])...};
  };
  const std::array<Point<S>, N> points = declare(std::make_index_sequence<N>{});
  for (const Point<S>& p : points)
    hyps.push_back(in_vertex_range<F>(p));
  return points;
}

} // namespace rastrules::proofs
