// SPDX-License-Identifier: MIT
// Generators of triangles, scenes, shared-edge pairs and meshes that build ties on purpose:
// vertices on pixel centres and half-way between subpixel steps, edges through pixel centres,
// horizontal and vertical edges, slivers and needles, coordinates at the range limits, and
// triangles larger than and partly outside the target.
// Implements (generators for): TRI.COVER.SAMPLE, TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION,
//   TRI.SHARED_EDGE.EXACTLY_ONCE, TRI.WATERTIGHT.MESH, TRI.INVARIANCE.TRANSLATION,
//   RASTER.WALK.BBOX

#pragma once

#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include <rapidcheck.h>

#include "rastrules/fixed.hpp"
#include "rastrules/name_table.hpp"
#include "rastrules/scene.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules::gen {

// A point in raw 16.8 units (r / 256 px), inside SNAP.VERTEX.RANGE.
using RawPoint = std::array<std::int32_t, 2>;
using RawTriangle = std::array<RawPoint, 3>;
using FloatTriangle = std::array<std::array<float, 2>, 3>;

// How a triangle was built; RC_TAG uses it to show that every tie class occurred.
enum class TriKind {
  kRandom,         // vertices on the 1/256 grid near the target
  kPixelCentres,   // vertices on pixel centres
  kSnapTies,       // some coordinates exactly half-way between two 16.8 values
  kHorizontalEdge, // two vertices with equal snapped y
  kVerticalEdge,   // two vertices with equal snapped x
  kThroughCentres, // an edge passing exactly through one or more pixel centres
  kSliver,         // third vertex within a few 1/256 of the other two's line
  kNeedle,         // two vertices a few 1/256 apart, the third far away
  kHuge,           // vertices far outside the target, the triangle crossing it
  kRangeLimits,    // coordinates at or next to -2^23 and 2^23 - 1 raw
  kDegenerate,     // collinear or coincident snapped vertices
  kFloats,         // floats with bits below 1/256 (snapping rounds)
};
} // namespace rastrules::gen

namespace rastrules {
template <> struct Names<gen::TriKind> {
  static constexpr auto table = in_enum_order<gen::TriKind>(
      {"random", "pixel centres", "snap ties", "horizontal edge", "vertical edge",
       "edge through centres", "sliver", "needle", "huge", "range limits", "degenerate", "floats"});
};
} // namespace rastrules

namespace rastrules::gen {
using rastrules::to_string; // the spellings of TriKind, MeshKind and FloatClass

struct GenTriangle {
  FloatTriangle v{};
  TriKind kind = TriKind::kRandom;
};

// A kernel scene together with the way each triangle was built.
struct TriScene {
  std::int32_t width = 1;
  std::int32_t height = 1;
  RasterState state;
  std::vector<GenTriangle> triangles;
};

// Returns raw / 256 as a float; exact because |raw| <= 2^23.
[[nodiscard]] float to_float(std::int32_t raw);
[[nodiscard]] FloatTriangle to_float(const RawTriangle& t);
[[nodiscard]] std::array<Vec2, 3> to_vec2(const RawTriangle& t);
[[nodiscard]] Vec2 to_vec2(const RawPoint& p);

// Returns twice the signed area of t (> 0: clockwise on screen), in int64, exact.
[[nodiscard]] std::int64_t twice_area(const RawTriangle& t);

// Returns t with at most two vertices moved by one raw unit so that it is not degenerate.
[[nodiscard]] RawTriangle make_nondegenerate(RawTriangle t);

// Returns t with its vertex order reversed (v0, v2, v1).
[[nodiscard]] RawTriangle reversed(const RawTriangle& t);

// Generators. "near" means within `margin` pixels of a width x height target.
[[nodiscard]] rc::Gen<RasterState> raster_state();
[[nodiscard]] rc::Gen<FillConvention> fill_convention();
[[nodiscard]] rc::Gen<RawPoint> raw_point_near(std::int32_t width, std::int32_t height,
                                               std::int32_t margin);
[[nodiscard]] rc::Gen<RawTriangle> raw_triangle_near(std::int32_t width, std::int32_t height);
[[nodiscard]] rc::Gen<RawTriangle> nondegenerate_raw_triangle_near(std::int32_t width,
                                                                   std::int32_t height);
// Any triangle kind, as floats (kSnapTies and kFloats are not multiples of 1/256).
[[nodiscard]] rc::Gen<GenTriangle> triangle_near(std::int32_t width, std::int32_t height);
// Triangles whose vertices may lie anywhere in SNAP.VERTEX.RANGE (kHuge, kRangeLimits), plus
// the ones near the target.
[[nodiscard]] rc::Gen<GenTriangle> triangle_anywhere(std::int32_t width, std::int32_t height);
// Scenes of up to max_triangles triangles (some sharing edges) on targets up to max_side.
[[nodiscard]] rc::Gen<TriScene> tri_scene(std::int32_t max_side, std::int32_t max_triangles);

// Two triangles sharing the edge (a, b), third vertices strictly on opposite sides, each in a
// random vertex order (so any winding).
struct SharedEdgePair {
  RawPoint a{};
  RawPoint b{};
  RawTriangle first{};
  RawTriangle second{};
};
[[nodiscard]] rc::Gen<SharedEdgePair> shared_edge_pair();

// Returns the raw lattice points strictly inside the segment (a, b), at most `limit` of them
// spread along it (all of them when there are fewer).
[[nodiscard]] std::vector<RawPoint> points_on_open_segment(const RawPoint& a, const RawPoint& b,
                                                           std::size_t limit);

enum class MeshKind { kJitteredGrid, kFan, kLatticeFan, kDelaunay };
} // namespace rastrules::gen

namespace rastrules {
template <> struct Names<gen::MeshKind> {
  static constexpr auto table =
      in_enum_order<gen::MeshKind>({"jittered grid", "fan", "lattice fan", "delaunay"});
};
} // namespace rastrules

namespace rastrules::gen {

// A triangulation of a simple polygon: triangles meet only along full shared edges or at
// vertices, all vertices exactly on the 1/256 grid (so snapping keeps it a triangulation).
struct Mesh {
  MeshKind kind = MeshKind::kJitteredGrid;
  std::vector<RawPoint> outline; // the polygon, in order (either orientation)
  std::vector<RawTriangle> triangles;
};
[[nodiscard]] rc::Gen<Mesh> mesh_near(std::int32_t width, std::int32_t height);

// Conversions for the two renderers.
[[nodiscard]] Scene to_kernel_scene(const TriScene& s);
[[nodiscard]] std::string to_json(const TriScene& s); // spec/scene.md, floats round-trip

void showValue(const GenTriangle& t, std::ostream& os);
void showValue(const TriScene& s, std::ostream& os);
void showValue(const SharedEdgePair& p, std::ostream& os);
void showValue(const Mesh& m, std::ostream& os);

} // namespace rastrules::gen

template <> struct rc::Arbitrary<rastrules::gen::SharedEdgePair> {
  static rc::Gen<rastrules::gen::SharedEdgePair> arbitrary() {
    return rastrules::gen::shared_edge_pair();
  }
};
