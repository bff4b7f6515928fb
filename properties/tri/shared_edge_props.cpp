// SPDX-License-Identifier: MIT
// Properties: two triangles sharing an edge, on opposite sides of it, cover every sample of
// the open shared segment exactly once and never overlap, whatever windings and convention.
// Implements (properties for): TRI.SHARED_EDGE.EXACTLY_ONCE

#include <array>
#include <cstdint>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "rastrules/gen/triangles.hpp"
#include "rastrules/triangle.hpp"

namespace {

namespace gen = rastrules::gen;

// rule: TRI.SHARED_EDGE.EXACTLY_ONCE, TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION
RC_GTEST_PROP(TriSharedEdge, SamplesOnASharedEdgeAreCoveredExactlyOnce,
              (const gen::SharedEdgePair& pair)) {
  const rastrules::RasterState state{
      rastrules::CullMode::kNone,
      *rc::gen::element(rastrules::FrontFace::kClockwise, rastrules::FrontFace::kCounterClockwise),
      *gen::fill_convention()};
  const rastrules::TriangleSetup t1 = rastrules::setup_triangle(gen::to_vec2(pair.first), state);
  const rastrules::TriangleSetup t2 = rastrules::setup_triangle(gen::to_vec2(pair.second), state);
  RC_ASSERT(t1.status == rastrules::TriangleStatus::kRasterized);
  RC_ASSERT(t2.status == rastrules::TriangleStatus::kRasterized);
  RC_CLASSIFY(pair.a[1] == pair.b[1], "horizontal shared edge");
  RC_CLASSIFY(pair.a[0] == pair.b[0], "vertical shared edge");
  RC_CLASSIFY(t1.clockwise == t2.clockwise, "same winding");
  const auto hits = [&](const gen::RawPoint& s) {
    return int{rastrules::covers(t1, gen::to_vec2(s))} +
           int{rastrules::covers(t2, gen::to_vec2(s))};
  };
  const auto fail = [](const char* what, const gen::RawPoint& s, int h) {
    std::ostringstream msg;
    msg << what << ": sample (" << s[0] << ", " << s[1] << ") raw covered " << h << " times";
    RC_FAIL(msg.str());
  };
  const auto on_edge = gen::points_on_open_segment(pair.a, pair.b, 64);
  RC_CLASSIFY(!on_edge.empty(), "lattice points on the shared edge");
  for (const gen::RawPoint& s : on_edge) {
    if (hits(s) != 1)
      fail("on the open shared segment", s, hits(s));
    // Off the line, a point is strictly on one side: at most one triangle can contain it.
    for (const auto& d : {std::array<std::int32_t, 2>{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
      const gen::RawPoint n{s[0] + d[0], s[1] + d[1]};
      if (hits(n) > 1)
        fail("next to the shared segment", n, hits(n));
    }
  }
  // The shared vertices: their wedges are part of some full fan, so at most one covers them.
  if (hits(pair.a) > 1)
    fail("shared vertex a", pair.a, hits(pair.a));
  if (hits(pair.b) > 1)
    fail("shared vertex b", pair.b, hits(pair.b));
}

} // namespace
