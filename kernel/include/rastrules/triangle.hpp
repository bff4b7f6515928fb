// SPDX-License-Identifier: MIT
// Triangle setup and the per-sample coverage rule (layer 2: typed rules).
// Implements: TRI.ORIENT.AREA, TRI.ORIENT.NORMALISE, TRI.DEGENERATE.ZERO_AREA, TRI.CULL.MODE,
//             TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION, TRI.COVER.SAMPLE, SNAP.CULL.AFTER_SNAP
// Does not implement: clipping, scissor, multisampling, attributes (later rule families).

#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "rastrules/fixed.hpp"
#include "rastrules/formula/edge.hpp"
#include "rastrules/name_table.hpp"

namespace rastrules {

// Which samples exactly on an edge are inside (TRI.FILL.CONVENTION). kTopLeft is D3D's rule
// and the default of every profile in window space with y down.
enum class FillConvention { kTopLeft, kTopRight, kBottomLeft, kBottomRight };
template <> struct Names<FillConvention> {
  static constexpr auto table =
      in_enum_order<FillConvention>({"top-left", "top-right", "bottom-left", "bottom-right"});
};

// rule: TRI.CULL.MODE
enum class CullMode { kNone, kBack, kFront };
template <> struct Names<CullMode> {
  static constexpr auto table = in_enum_order<CullMode>({"none", "back", "front"});
};

// Which on-screen winding is the front face (TRI.CULL.MODE). D3D's default
// (FrontCounterClockwise = FALSE) is kClockwise.
enum class FrontFace { kClockwise, kCounterClockwise };
template <> struct Names<FrontFace> {
  static constexpr auto table = in_enum_order<FrontFace>({"cw", "ccw"});
};

struct RasterState {
  CullMode cull = CullMode::kNone;
  FrontFace front_face = FrontFace::kClockwise;
  FillConvention fill = FillConvention::kTopLeft;
};

// Returns whether the directed edge (a -> b) of a clockwise triangle is inclusive under the
// fill convention f.
// rule: TRI.FILL.CONVENTION, TRI.FILL.TOP_LEFT
[[nodiscard]] constexpr bool is_inclusive(Vec2 a, Vec2 b, FillConvention f) {
  const std::int64_t ax = a.x.raw(), ay = a.y.raw(), bx = b.x.raw(), by = b.y.raw();
  switch (f) {
  case FillConvention::kTopLeft:
    return formula::is_inclusive_edge<true, true>(ax, ay, bx, by);
  case FillConvention::kTopRight:
    return formula::is_inclusive_edge<true, false>(ax, ay, bx, by);
  case FillConvention::kBottomLeft:
    return formula::is_inclusive_edge<false, true>(ax, ay, bx, by);
  case FillConvention::kBottomRight:
    return formula::is_inclusive_edge<false, false>(ax, ay, bx, by);
  }
  return false;
}

// One edge of a clockwise (normalised) triangle, prepared for evaluation at many samples.
struct EdgeSetup {
  Vec2 a;
  Vec2 b;
  bool is_top = false;    // TRI.FILL.TOP_EDGE (diagnostic; independent of the convention)
  bool is_left = false;   // TRI.FILL.LEFT_EDGE (diagnostic; independent of the convention)
  bool inclusive = false; // under the state's fill convention

  // Returns E_ab(s), exact.
  // rule: TRI.EDGE.FUNCTION
  [[nodiscard]] constexpr EdgeValue value_at(Vec2 s) const {
    return EdgeValue::from_raw(formula::edge_value<std::int64_t>(a.x.raw(), a.y.raw(), b.x.raw(),
                                                                 b.y.raw(), s.x.raw(), s.y.raw()));
  }
};

// Returns whether a sample whose edge value is v is inside an edge that is (or is not)
// inclusive: E > 0, or E == 0 and the edge is inclusive. inside() and the decision records
// (rastrules/decision.hpp) both decide with this function.
// rule: TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION
[[nodiscard]] constexpr bool inside_value(EdgeValue v, bool inclusive) {
  return v > EdgeValue{} || (v == EdgeValue{} && inclusive);
}

// Returns whether sample s is inside edge e: E > 0, or E == 0 and the edge is inclusive.
// rule: TRI.FILL.TOP_LEFT
[[nodiscard]] constexpr bool inside(const EdgeSetup& e, Vec2 s) {
  return inside_value(e.value_at(s), e.inclusive);
}

enum class TriangleStatus {
  kRasterized,  // passes culling; coverage follows TRI.COVER.SAMPLE
  kDegenerate,  // zero area after snapping: covers nothing (TRI.DEGENERATE.ZERO_AREA)
  kCulledBack,  // back-facing and cull == kBack
  kCulledFront, // front-facing and cull == kFront
};
template <> struct Names<TriangleStatus> {
  static constexpr auto table =
      in_enum_order<TriangleStatus>({"rasterized", "degenerate (zero area after snapping)",
                                     "culled (back-facing)", "culled (front-facing)"});
};

struct TriangleSetup {
  TriangleStatus status = TriangleStatus::kDegenerate;
  std::array<Vec2, 3> snapped{};    // as given, after snapping
  bool clockwise = false;           // winding on screen of the snapped vertices
  bool front_facing = false;        // per RasterState::front_face; zero area is back-facing
  std::int64_t twice_area = 0;      // signed, 1/65536 px^2; > 0 clockwise
  std::array<EdgeSetup, 3> edges{}; // clockwise order; valid when status == kRasterized
};

// Returns the three edges of the triangle with snapped vertices v (in the order given) in
// clockwise order: (v0, v1, v2) when `clockwise`, else (v0, v2, v1); each with its top, left and
// inclusive flags under `fill`. setup_triangle() and the decision records (which show a culled
// triangle's edges for information) both build edges with this function.
// rule: TRI.ORIENT.NORMALISE, TRI.FILL.TOP_EDGE, TRI.FILL.LEFT_EDGE, TRI.FILL.CONVENTION
[[nodiscard]] constexpr std::array<EdgeSetup, 3> setup_edges(const std::array<Vec2, 3>& v,
                                                             bool clockwise, FillConvention fill) {
  std::array<EdgeSetup, 3> edges{};
  const std::array<Vec2, 3> cw = clockwise ? v : std::array<Vec2, 3>{v[0], v[2], v[1]};
  for (int i = 0; i < 3; ++i) {
    const Vec2 a = cw[static_cast<std::size_t>(i)];
    const Vec2 b = cw[static_cast<std::size_t>((i + 1) % 3)];
    EdgeSetup& e = edges[static_cast<std::size_t>(i)];
    e.a = a;
    e.b = b;
    e.is_top = formula::is_top_edge<std::int64_t>(a.x.raw(), a.y.raw(), b.x.raw(), b.y.raw());
    e.is_left = formula::is_left_edge<std::int64_t>(a.x.raw(), a.y.raw(), b.x.raw(), b.y.raw());
    e.inclusive = is_inclusive(a, b, fill);
  }
  return edges;
}

// Returns the setup of the triangle with snapped vertices v (in the order given).
// Orientation, facing and culling are decided on the snapped positions
// (SNAP.CULL.AFTER_SNAP). Counter-clockwise triangles are normalised by swapping v1 and v2.
// rule: TRI.ORIENT.AREA, TRI.ORIENT.NORMALISE, TRI.DEGENERATE.ZERO_AREA, TRI.CULL.MODE, SNAP.CULL.AFTER_SNAP
[[nodiscard]] constexpr TriangleSetup setup_triangle(const std::array<Vec2, 3>& v,
                                                     const RasterState& state) {
  TriangleSetup t;
  t.snapped = v;
  t.twice_area = formula::twice_signed_area<std::int64_t>(v[0].x.raw(), v[0].y.raw(), v[1].x.raw(),
                                                          v[1].y.raw(), v[2].x.raw(), v[2].y.raw());
  t.clockwise = t.twice_area > 0;
  // rule: TRI.DEGENERATE.ZERO_AREA
  if (t.twice_area == 0) {
    t.front_facing = false; // zero-area geometry is back-facing (D3D11.3 15.11.1)
    t.status = TriangleStatus::kDegenerate;
    return t;
  }
  // rule: TRI.CULL.MODE
  t.front_facing = (state.front_face == FrontFace::kClockwise) == t.clockwise;
  if (state.cull == CullMode::kBack && !t.front_facing) {
    t.status = TriangleStatus::kCulledBack;
    return t;
  }
  if (state.cull == CullMode::kFront && t.front_facing) {
    t.status = TriangleStatus::kCulledFront;
    return t;
  }
  // rule: TRI.ORIENT.NORMALISE
  t.edges = setup_edges(v, t.clockwise, state.fill);
  t.status = TriangleStatus::kRasterized;
  return t;
}

// Returns whether the triangle covers sample s: it is rasterized and s is inside all three
// edges. A sample on two edges is therefore inside only when both are inclusive.
// rule: TRI.COVER.SAMPLE, TRI.FILL.TOP_LEFT
[[nodiscard]] constexpr bool covers(const TriangleSetup& t, Vec2 s) {
  return t.status == TriangleStatus::kRasterized && inside(t.edges[0], s) &&
         inside(t.edges[1], s) && inside(t.edges[2], s);
}

} // namespace rastrules
