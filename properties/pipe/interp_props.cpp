// SPDX-License-Identifier: MIT
// Properties: the kernel's barycentrics equal the exact oracle's and sum to the area; its
// perspective-correct and linear interpolation lie within PIPE.INTERP.BOUND of the exact value
// (within [min a_i, max a_i] up to the bound inside the triangle, the flat value beyond the
// horizon, saturated rather than infinite, never NaN), on random triangles of every kind
// (ties, slivers, needles, the range's ends), evaluation points on vertices, on edges, inside,
// outside and anywhere in the vertex range, attributes from subnormal to FLT_MAX, and w ratios
// up to 2^100.
// Implements (properties for): PIPE.BARY.EXACT, PIPE.BARY.SUM, PIPE.INTERP.PERSPECTIVE,
//   PIPE.INTERP.LINEAR, PIPE.INTERP.HORIZON, PIPE.INTERP.BOUND

#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "pipe_gen.hpp"

namespace {

namespace pg = rastrules::pipe_gen;
namespace op = rastrules::oracle::pipe;
namespace kp = rastrules::pipe;

// rule: PIPE.BARY.EXACT, PIPE.BARY.SUM
RC_GTEST_PROP(PipeBary, EqualTheExactEdgeValuesAndSumToTheArea, ()) {
  const pg::RawTri t = *pg::full_size(pg::raw_triangle(true));
  const pg::Raw2 s = *pg::full_size(pg::sample_for(t));
  const kp::Barycentrics k = kp::barycentrics(pg::to_vec2(t), pg::to_vec2(s));
  const op::Bary o = op::barycentrics(t, s);
  const std::string where = "triangle " + pg::rs(t) + ", sample " + pg::rs(s);
  RC_ASSERT_FALSE(o.e[0] + o.e[1] + o.e[2] != o.area); // the oracle's own identity
  if (pg::to_oracle(k) != o) {
    RC_FAIL(where + ": kernel e = (" + std::to_string(k.e[0]) + ", " + std::to_string(k.e[1]) +
            ", " + std::to_string(k.e[2]) + ") area " + std::to_string(k.area) + ", oracle e = (" +
            std::to_string(o.e[0]) + ", " + std::to_string(o.e[1]) + ", " + std::to_string(o.e[2]) +
            ") area " + std::to_string(o.area));
  }
  RC_ASSERT(k.e[0] + k.e[1] + k.e[2] == k.area);
  RC_CLASSIFY(o.area == 0, "degenerate");
  RC_CLASSIFY(op::inside_closed(o), "inside");
  RC_CLASSIFY(o.e[0] == 0 || o.e[1] == 0 || o.e[2] == 0, "on an edge line");
}

void classify(const op::InterpCheck& c) {
  RC_CLASSIFY(c.inside, "inside");
  RC_CLASSIFY(c.horizon, "beyond the horizon");
  RC_CLASSIFY(c.near_horizon, "near the horizon");
  RC_CLASSIFY(c.saturated, "saturated");
}

// rule: PIPE.INTERP.PERSPECTIVE, PIPE.INTERP.HORIZON, PIPE.INTERP.BOUND
RC_GTEST_PROP(PipeInterp, PerspectiveWithinTheBoundOfTheExactValue, ()) {
  const pg::RawTri t = *pg::full_size(pg::raw_triangle(false));
  const pg::Raw2 s = *pg::full_size(pg::sample_for(t));
  const std::array<float, 3> a = *pg::full_size(pg::attr_triple());
  const std::array<float, 3> w = *pg::full_size(pg::w_triple());
  const float flat = a[static_cast<std::size_t>(*rc::gen::inRange(0, 3))];
  const kp::Barycentrics b = kp::barycentrics(pg::to_vec2(t), pg::to_vec2(s));
  const float got = kp::interpolate_perspective(b, a, w, flat);
  const op::InterpCheck c = op::check_perspective(op::barycentrics(t, s), a, w, flat, got);
  classify(c);
  if (!c.ok) {
    RC_FAIL("triangle " + pg::rs(t) + ", sample " + pg::rs(s) + ", a " + pg::fs(a) + ", w " +
            pg::fs(w) + ", flat " + pg::fs(flat) + ": " + c.describe());
  }
}

// rule: PIPE.INTERP.LINEAR, PIPE.INTERP.HORIZON, PIPE.INTERP.BOUND
RC_GTEST_PROP(PipeInterp, LinearWithinTheBoundOfTheExactValue, ()) {
  const pg::RawTri t = *pg::full_size(pg::raw_triangle(false));
  const pg::Raw2 s = *pg::full_size(pg::sample_for(t));
  const std::array<float, 3> a = *pg::full_size(pg::attr_triple());
  const kp::Barycentrics b = kp::barycentrics(pg::to_vec2(t), pg::to_vec2(s));
  const float got = kp::interpolate_linear(b, a);
  const op::InterpCheck c = op::check_linear(op::barycentrics(t, s), a, got);
  classify(c);
  if (!c.ok) {
    RC_FAIL("triangle " + pg::rs(t) + ", sample " + pg::rs(s) + ", a " + pg::fs(a) + ": " +
            c.describe());
  }
}

// The same on points inside the triangle only (half of the cases above are outside): the
// value stays within [min a_i, max a_i] up to the bound, and is never beyond the horizon.
// rule: PIPE.INTERP.PERSPECTIVE, PIPE.INTERP.LINEAR, PIPE.INTERP.BOUND
RC_GTEST_PROP(PipeInterp, InsideTheTriangleWithinTheVertexValues, ()) {
  const pg::RawTri t = *pg::full_size(pg::raw_triangle(false));
  pg::Raw2 s = *pg::full_size(pg::sample_for(t));
  // Pull s into the closed triangle: the integer point nearest the centroid on the way.
  op::Bary ob = op::barycentrics(t, s);
  const pg::Raw2 c{(t[0][0] + t[1][0] + t[2][0]) / 3, (t[0][1] + t[1][1] + t[2][1]) / 3};
  for (int k = 0; k < 64 && !op::inside_closed(ob); ++k) {
    s = {(s[0] + c[0]) / 2, (s[1] + c[1]) / 2};
    ob = op::barycentrics(t, s);
  }
  if (!op::inside_closed(ob))
    s = t[0];
  ob = op::barycentrics(t, s);
  RC_ASSERT(op::inside_closed(ob));
  const std::array<float, 3> a = *pg::full_size(pg::attr_triple());
  const std::array<float, 3> w = *pg::full_size(pg::w_triple());
  const kp::Barycentrics b = kp::barycentrics(pg::to_vec2(t), pg::to_vec2(s));
  const op::InterpCheck cp =
      op::check_perspective(ob, a, w, a[0], kp::interpolate_perspective(b, a, w, a[0]));
  const op::InterpCheck cl = op::check_linear(ob, a, kp::interpolate_linear(b, a));
  const std::string where =
      "triangle " + pg::rs(t) + ", sample " + pg::rs(s) + ", a " + pg::fs(a) + ", w " + pg::fs(w);
  if (!cp.ok || cp.horizon)
    RC_FAIL(where + ": perspective: " + cp.describe());
  if (!cl.ok)
    RC_FAIL(where + ": linear: " + cl.describe());
  RC_CLASSIFY(cp.near_horizon, "near the horizon (inside: a sliver)");
}

} // namespace
