// SPDX-License-Identifier: MIT
// Decision records: why a primitive covers, or does not cover, one pixel, as the kernel decides
// it. Each record is filled by the functions that decide coverage (setup_edges, inside_value,
// sample_coverage, fragment_mask, fragment_centroid, explain_aliased_line_pixel,
// aa_line_coverage), with the rule that decided named from the one table of rule IDs
// (rastrules/rules.hpp). Tools only format records; they do not decide again.
// Recording costs nothing when it is not asked for: the traversal never builds a record, and
// the functions shared with it are constexpr or inline.
// Implements: TRI.COVER.SAMPLE, TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION, MSAA.COVER.SAMPLE,
//             MSAA.MASK.AND, MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10, MSAA.QUAD.HELPER

#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "rastrules/fixed.hpp"
#include "rastrules/line_aliased.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/path.hpp"
#include "rastrules/rules.hpp"
#include "rastrules/scene.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules {

// The rule that breaks a tie (E == 0) under fill convention f.
// rule: TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION
[[nodiscard]] constexpr RuleId fill_rule(FillConvention f) {
  return f == FillConvention::kTopLeft ? rules::kTriFillTopLeft : rules::kTriFillConvention;
}

// One edge of a normalised (clockwise) triangle at one sample.
// rule: TRI.EDGE.FUNCTION, TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION
struct EdgeDecision {
  std::uint32_t from = 0; // vertex indices as given (TRI.ORIENT.NORMALISE)
  std::uint32_t to = 0;
  Vec2 a; // the directed edge, snapped
  Vec2 b;
  EdgeValue e;             // E_ab at the sample, exact
  bool top = false;        // TRI.FILL.TOP_EDGE
  bool left = false;       // TRI.FILL.LEFT_EDGE
  bool horizontal = false; // a.y == b.y
  bool inclusive = false;  // under the fill convention
  bool inside = false;     // E > 0, or E == 0 and inclusive
  RuleId rule;             // TRI.EDGE.FUNCTION when E != 0, else fill_rule(fill)
};

// Returns the decision of edge e (vertices from -> to as given) at sample s under `fill`, the
// fill convention e was set up with.
// rule: TRI.EDGE.FUNCTION, TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION
[[nodiscard]] constexpr EdgeDecision decide_edge(const EdgeSetup& e, Vec2 s, FillConvention fill) {
  EdgeDecision d;
  d.a = e.a;
  d.b = e.b;
  d.e = e.value_at(s);
  d.top = e.is_top;
  d.left = e.is_left;
  d.horizontal = e.a.y == e.b.y;
  d.inclusive = e.inclusive;
  d.inside = inside_value(d.e, e.inclusive);
  d.rule = d.e == EdgeValue{} ? fill_rule(fill) : rules::kTriEdgeFunction;
  return d;
}

// One triangle (a triangle primitive, half of a point, half of a quadrilateral line segment) at
// one sample.
// rule: TRI.COVER.SAMPLE, TRI.DEGENERATE.ZERO_AREA, TRI.CULL.MODE, SNAP.CULL.AFTER_SNAP
struct TriangleDecision {
  TriangleSetup setup;    // snapped vertices, twice signed area, winding, facing, status
  bool has_edges = false; // false when degenerate
  bool culled = false;    // the edges are then for information only
  std::array<EdgeDecision, 3> edges{}; // clockwise order
  bool inside_all_edges = false;
  std::uint32_t on_edges = 0; // edges with E == 0 (2: the sample is a vertex)
  bool covered = false;       // equals covers(setup, sample)
  RuleId rule;                // TRI.DEGENERATE.ZERO_AREA, TRI.CULL.MODE or TRI.COVER.SAMPLE
};

// Returns the decision of the set-up triangle t (set up under `state`) at sample s. The edges
// of a culled triangle are those setup_triangle() would give it without culling.
// rule: TRI.COVER.SAMPLE, TRI.DEGENERATE.ZERO_AREA, TRI.CULL.MODE, TRI.ORIENT.NORMALISE
[[nodiscard]] constexpr TriangleDecision decide_triangle(const TriangleSetup& t,
                                                         const RasterState& state, Vec2 s) {
  TriangleDecision d;
  d.setup = t;
  if (t.status == TriangleStatus::kDegenerate) {
    d.rule = rules::kTriDegenerateZeroArea;
    return d;
  }
  d.has_edges = true;
  d.culled = t.status != TriangleStatus::kRasterized;
  const std::array<EdgeSetup, 3> edges =
      d.culled ? setup_edges(t.snapped, t.clockwise, state.fill) : t.edges;
  const std::array<std::uint32_t, 3> order =
      t.clockwise ? std::array<std::uint32_t, 3>{0, 1, 2} : std::array<std::uint32_t, 3>{0, 2, 1};
  d.inside_all_edges = true;
  for (std::size_t i = 0; i < 3; ++i) {
    EdgeDecision& e = d.edges[i];
    e = decide_edge(edges[i], s, state.fill);
    e.from = order[i];
    e.to = order[(i + 1) % 3];
    d.inside_all_edges = d.inside_all_edges && e.inside;
    d.on_edges += e.e == EdgeValue{} ? 1u : 0u;
  }
  d.covered = !d.culled && d.inside_all_edges;
  d.rule = d.culled ? rules::kTriCullMode : rules::kTriCoverSample;
  return d;
}

// One segment of an aliased or antialiased line drawn without triangles, at one pixel.
// rule: LINE.D3D.EXIT, LINE.VK.EXIT, LINE.AA.FRAGMENT, SCENE.OUTPUT.COVERAGE
struct LineSegmentDecision {
  std::uint32_t seg = 0;
  Vec2 a; // snapped endpoints
  Vec2 b;
  bool x_major = false;           // LINE.MAJOR.AXIS
  bool covered = false;           // the segment produces the pixel
  std::uint32_t coverage_q16 = 0; // antialiased lines: aa_line_coverage
  LineDiamondDecision diamond;    // aliased lines: explain_aliased_line_pixel
  RuleId rule; // LINE.AA.FRAGMENT, or the aliased line's deciding rule (diamond.rule)
};

// Returns the decision of the segment a -> b (antialiased or aliased under `mode`) at pixel
// (x, y).
// rule: LINE.D3D.EXIT, LINE.VK.EXIT, LINE.AA.FRAGMENT
[[nodiscard]] LineSegmentDecision decide_line_segment(Vec2 a, Vec2 b, bool aa, LineMode mode,
                                                      std::int32_t x, std::int32_t y);

// The rule of a sample pattern kind and of a centroid rule.
// rule: MSAA.PATTERN.STANDARD, MSAA.PATTERN.CENTER, MSAA.PATTERN.CUSTOM
[[nodiscard]] RuleId pattern_rule(PatternKind k);
// rule: MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10
[[nodiscard]] RuleId centroid_rule(CentroidRule r);

// One sample of a multisampled pixel: each triangle of the primitive decided there.
// rule: MSAA.SAMPLE.POSITION, MSAA.COVER.SAMPLE
struct SampleDecision {
  std::uint32_t index = 0;
  SampleOffset offset;
  Vec2 position; // sample_position(x, y, offset)
  std::vector<TriangleDecision> triangles;
};

// One segment (0 for triangles and points) of a multisampled primitive at the pixel: what the
// multisampled path of rasterize_primitive decides for it.
// rule: MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10
// rule: MSAA.QUAD.HELPER
struct SegmentMaskDecision {
  std::uint32_t seg = 0;
  std::uint32_t coverage = 0;       // before the sample mask: sample_coverage, or every sample
  std::uint32_t explained = 0;      // the samples the per-sample decisions find covered
  std::uint32_t mask = 0;           // fragment_mask(coverage): the fragment's mask; 0: no fragment
  std::optional<Centroid> centroid; // fragment_centroid(coverage), when the scene asks
  bool helper = false;              // pixel shading: a helper lane of this segment
  std::uint32_t helper_samples = 0; // sample shading: bit k, a helper lane of sample k
};

// A multisampled primitive at one pixel.
// rule: MSAA.COVER.SAMPLE, MSAA.LINE.MODE
struct MsaaDecision {
  RuleId pattern_rule;                 // MSAA.PATTERN.*
  std::vector<SampleDecision> samples; // empty for lines drawn without triangles
  bool whole_pixel = false;            // MSAA.LINE.MODE: every sample of a produced pixel
  // In the order the samples first find them covered, then in triangle (or segment) order.
  std::vector<SegmentMaskDecision> segments;
};

// One sample of a path primitive: the crossings of its ray (PATH.WINDING, displaced by
// PATH.SAMPLE.TIE) from path::crossings(), the code winding_number() sums, and the fill rule's
// verdict.
// rule: PATH.WINDING, PATH.SAMPLE.TIE, PATH.FILL.RULE
struct PathSampleDecision {
  std::uint32_t index = 0; // the sample of the pattern
  SampleOffset offset;     // in 1/16 px from the pixel centre
  Vec2 position;           // raw 16.8
  std::vector<path::SampleCrossing> crossings;
  std::int64_t winding = 0;
  bool fills = false;
};

// A path primitive at one pixel (SCENE.PRIM.PATH): with "samples" coverage every sample of
// the pattern and the fragment mask (covered samples ANDed with the sample mask); with "area"
// the pixel's parts by winding number (path::winding_areas) and its area, the sum of the parts
// that fill (equal to path::cover_area's, which fuzz_path checks), and the windings at the
// samples for information.
// rule: SCENE.PRIM.PATH, PATH.COVER.SAMPLE, PATH.AREA.EXACT
struct PathDecision {
  path::Coverage coverage = path::Coverage::kSamples;
  path::FillRule fill_rule = path::FillRule::kNonZero;
  std::vector<PathSampleDecision> samples;
  std::uint32_t mask = 0; // the fragment's mask (0: no fragment)
  ExactArea area;         // "area" coverage: empty when the area is 0
  // "area" coverage: the pixel's parts by winding number (path::winding_areas), the faces of
  // the boundary's arrangement that gave the area.
  path::PixelWindings windings;
};

// One primitive at one pixel.
// rule: SCENE.PRIM.POINT, SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP, SCENE.LINE_MODE
struct PixelDecision {
  std::size_t prim = 0;
  std::int32_t x = 0;
  std::int32_t y = 0;
  // The prepared primitive's triangles decided at the pixel centre (a triangle: one; a point:
  // two; a quadrilateral line: two per segment, of segment triangle_seg[i]).
  std::vector<TriangleDecision> triangles;
  std::vector<std::uint32_t> triangle_seg;
  // The segments of a line drawn without triangles, at the pixel.
  std::vector<LineSegmentDecision> segments;
  bool centre_covered = false; // some triangle covers the centre, or some segment the pixel
  // The multisampled path (any scene that is not is_single_sample): per sample and segment.
  std::optional<MsaaDecision> msaa;
  // A path primitive: its samples, mask and area.
  std::optional<PathDecision> path;
  // rasterize_primitive emits a fragment (helpers aside) at the pixel: the multisampled path's
  // fragment masks, a path's mask or area, else centre_covered.
  bool covered = false;
};

// Returns the decision of primitive p of a prepared scene at pixel (x, y).
// Preconditions: p < scene.primitives.size(); 0 <= x < scene.width; 0 <= y < scene.height.
// rule: SCENE.OUTPUT.FRAGMENTS, MSAA.MASK.AND, MSAA.QUAD.HELPER
[[nodiscard]] PixelDecision decide_pixel(const PreparedScene& scene, std::size_t p, std::int32_t x,
                                         std::int32_t y);

} // namespace rastrules
