// SPDX-License-Identifier: MIT
// Decision records of one primitive at one pixel (rastrules/decision.hpp), built from the
// functions the rasterization paths decide with.
// Implements: SCENE.OUTPUT.FRAGMENTS, MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.LINE.MODE,
//             MSAA.QUAD.HELPER

#include "rastrules/decision.hpp"

#include "rastrules/line_aa.hpp"

#include <memory>
#include <utility>

namespace rastrules {

// rule: LINE.D3D.EXIT, LINE.VK.EXIT, LINE.AA.FRAGMENT, LINE.MAJOR.AXIS
LineSegmentDecision decide_line_segment(Vec2 a, Vec2 b, bool aa, LineMode mode, std::int32_t x,
                                        std::int32_t y) {
  LineSegmentDecision d;
  d.a = a;
  d.b = b;
  if (aa) {
    // rule: LINE.AA.FRAGMENT
    const AACoverage c = aa_line_coverage(a, b, x, y);
    d.x_major = is_x_major(a, b);
    d.covered = c.positive;
    d.coverage_q16 = c.q16;
    d.rule = rules::kLineAAFragment;
    return d;
  }
  d.diamond = explain_aliased_line_pixel(a, b, mode, x, y);
  d.x_major = d.diamond.x_major;
  d.covered = d.diamond.covered;
  d.rule = d.diamond.rule;
  return d;
}

// rule: MSAA.PATTERN.STANDARD, MSAA.PATTERN.CENTER, MSAA.PATTERN.CUSTOM
RuleId pattern_rule(PatternKind k) {
  // In PatternKind order; MSAA.PATTERN.GRID, the rule every pattern follows, for anything else.
  constexpr std::array<RuleId, 3> kByKind{rules::kMsaaPatternStandard, rules::kMsaaPatternCenter,
                                          rules::kMsaaPatternCustom};
  const auto i = static_cast<std::size_t>(k);
  return i < kByKind.size() ? kByKind[i] : rules::kMsaaPatternGrid;
}

// rule: MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10
RuleId centroid_rule(CentroidRule r) {
  return r == CentroidRule::kD3D11 ? rules::kMsaaCentroidD3D11 : rules::kMsaaCentroidD3D10;
}

namespace {

SegmentMaskDecision& segment_of(std::vector<SegmentMaskDecision>& segments, std::uint32_t seg) {
  for (SegmentMaskDecision& g : segments) {
    if (g.seg == seg)
      return g;
  }
  segments.push_back(SegmentMaskDecision{});
  segments.back().seg = seg;
  return segments.back();
}

// The coverage before the sample mask of segment seg of prim at pixel (x, y), as the
// multisampled path finds it: every sample of each triangle of the segment
// (sample_coverage), or every sample of a pixel a line drawn without triangles produces. 0
// outside the target, where the path emits nothing.
// rule: MSAA.COVER.SAMPLE, MSAA.LINE.MODE
std::uint32_t coverage_at(const PreparedScene& scene, const PreparedPrimitive& prim,
                          std::uint32_t seg, std::int32_t x, std::int32_t y) {
  if (x < 0 || y < 0 || x >= scene.width || y >= scene.height)
    return 0;
  std::uint32_t c = 0;
  if (!prim.triangles.empty()) {
    for (const PreparedTriangle& t : prim.triangles) {
      if (t.seg == seg)
        c |= sample_coverage(t.setup, x, y, scene.msaa.pattern);
    }
    return c;
  }
  const LineSegmentDecision g =
      decide_line_segment(prim.v[seg], prim.v[seg + 1], prim.aa, scene.conventions.line_mode, x, y);
  return g.covered ? full_mask(scene.msaa.count()) : 0u;
}

// Each sample of the pixel: every triangle decided there, the samples found covered and the
// kernel's coverage per segment.
// rule: MSAA.SAMPLE.POSITION, MSAA.COVER.SAMPLE
void decide_samples(const PreparedScene& scene, const PreparedPrimitive& prim, std::int32_t x,
                    std::int32_t y, MsaaDecision& m) {
  const MultisampleState& ms = scene.msaa;
  for (std::uint32_t k = 0; k < ms.count(); ++k) {
    SampleDecision sd;
    sd.index = k;
    sd.offset = ms.pattern.positions[k];
    sd.position = sample_position(x, y, sd.offset);
    for (const PreparedTriangle& t : prim.triangles) {
      TriangleDecision td = decide_triangle(t.setup, scene.state, sd.position);
      if (td.covered)
        segment_of(m.segments, t.seg).explained |= std::uint32_t{1} << k;
      sd.triangles.push_back(td);
    }
    m.samples.push_back(std::move(sd));
  }
  for (const PreparedTriangle& t : prim.triangles)
    segment_of(m.segments, t.seg).coverage |= sample_coverage(t.setup, x, y, ms.pattern);
}

// Whether the pixel runs as a helper lane of each segment: it has no fragment (of sample k,
// under sample shading) while another pixel of its 2x2 quad has one.
// rule: MSAA.QUAD.ALIGN, MSAA.QUAD.HELPER
void decide_helpers(const PreparedScene& scene, const PreparedPrimitive& prim, std::int32_t x,
                    std::int32_t y, MsaaDecision& m) {
  const MultisampleState& ms = scene.msaa;
  if (!ms.wants_quads())
    return;
  for (SegmentMaskDecision& g : m.segments) {
    std::uint32_t others = 0;
    for (std::int32_t lane = 0; lane < 4; ++lane) {
      const std::int32_t nx = (x & ~1) + (lane & 1);
      const std::int32_t ny = (y & ~1) + (lane >> 1);
      if (nx != x || ny != y)
        others |= fragment_mask(coverage_at(scene, prim, g.seg, nx, ny), ms);
    }
    if (ms.shading == ShadingRate::kSample) {
      g.helper_samples = others & ~g.mask;
    } else {
      g.helper = g.mask == 0 && others != 0;
    }
  }
}

// rule: MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.LINE.MODE, MSAA.CENTROID.D3D11
// rule: MSAA.CENTROID.D3D10
MsaaDecision decide_msaa(const PreparedScene& scene, const PreparedPrimitive& prim,
                         const PixelDecision& d) {
  const MultisampleState& ms = scene.msaa;
  MsaaDecision m;
  m.pattern_rule = pattern_rule(ms.pattern.kind);
  if (!prim.triangles.empty()) {
    decide_samples(scene, prim, d.x, d.y, m);
  } else {
    // rule: MSAA.LINE.MODE
    m.whole_pixel = true;
    for (const LineSegmentDecision& g : d.segments) {
      SegmentMaskDecision& sm = segment_of(m.segments, g.seg);
      if (g.covered)
        sm.coverage = sm.explained = full_mask(ms.count());
    }
  }
  for (SegmentMaskDecision& g : m.segments) {
    g.mask = fragment_mask(g.coverage, ms);
    if (ms.has_centroid)
      g.centroid = fragment_centroid(g.coverage, ms, scene.conventions.centroid);
  }
  decide_helpers(scene, prim, d.x, d.y, m);
  return m;
}

} // namespace

// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.PRIM.POINT, SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP
// rule: MSAA.MASK.AND
namespace {

// rule: SCENE.PRIM.PATH, PATH.WINDING, PATH.SAMPLE.TIE, PATH.FILL.RULE, PATH.AREA.EXACT
PathDecision decide_path(const PreparedScene& scene, const PreparedPrimitive& prim, std::int32_t x,
                         std::int32_t y) {
  PathDecision d;
  d.coverage = prim.coverage;
  d.fill_rule = prim.path->fill_rule;
  const SamplePattern& pattern = scene.msaa.pattern;
  std::uint32_t covered = 0;
  for (std::size_t k = 0; k < pattern.positions.size(); ++k) {
    PathSampleDecision sd;
    sd.index = static_cast<std::uint32_t>(k);
    sd.offset = pattern.positions[k];
    sd.position = sample_position(x, y, sd.offset);
    const path::Point s{sd.position.x.raw(), sd.position.y.raw()};
    sd.crossings = path::crossings(*prim.path, s, scene.conventions.fill);
    for (const path::SampleCrossing& c : sd.crossings)
      sd.winding += c.dir;
    sd.fills = path::fill_holds(prim.path->fill_rule, sd.winding);
    covered |= sd.fills ? std::uint32_t{1} << k : 0u;
    d.samples.push_back(std::move(sd));
  }
  const std::uint32_t keep = scene.msaa.effective_mask();
  if (prim.coverage == path::Coverage::kSamples) {
    d.mask = covered & keep;
    return d;
  }
  // rule: PATH.AREA.EXACT, PATH.AREA.CURVE
  // The pixel's parts by winding number; those that fill add up to its area (cover_area's,
  // which the fragments carry: fuzz_path holds the two computations to each other).
  d.windings = path::winding_areas(*prim.path, x, y, scene.width, scene.height);
  boost::multiprecision::cpp_rational area = 0;
  for (const path::WindingArea& part : d.windings.parts)
    if (part.fills)
      area += part.area;
  if (area != 0)
    d.area = ExactArea(std::make_shared<const path::AreaValue>(
        path::AreaValue{std::move(area), d.windings.error_bound}));
  d.mask = d.area ? keep : 0u;
  return d;
}

} // namespace

PixelDecision decide_pixel(const PreparedScene& scene, std::size_t p, std::int32_t x,
                           std::int32_t y) {
  const PreparedPrimitive& prim = scene.primitives[p];
  PixelDecision d;
  d.prim = p;
  d.x = x;
  d.y = y;
  // rule: SCENE.PRIM.PATH
  if (prim.type == PrimitiveType::kPath) {
    d.path = decide_path(scene, prim, x, y);
    d.covered = d.centre_covered = d.path->mask != 0;
    return d;
  }
  const Vec2 centre = pixel_center(x, y);
  for (const PreparedTriangle& t : prim.triangles) {
    d.triangles.push_back(decide_triangle(t.setup, scene.state, centre));
    d.triangle_seg.push_back(t.seg);
    d.centre_covered = d.centre_covered || d.triangles.back().covered;
  }
  if (prim.triangles.empty() && prim.type != PrimitiveType::kTriangle) {
    for (std::size_t k = 0; k + 1 < prim.v.size(); ++k) {
      LineSegmentDecision g =
          decide_line_segment(prim.v[k], prim.v[k + 1], prim.aa, scene.conventions.line_mode, x, y);
      g.seg = static_cast<std::uint32_t>(k);
      d.centre_covered = d.centre_covered || g.covered;
      d.segments.push_back(g);
    }
  }
  d.covered = d.centre_covered;
  if (!is_single_sample(scene.msaa)) {
    d.msaa = decide_msaa(scene, prim, d);
    d.covered = false;
    for (const SegmentMaskDecision& g : d.msaa->segments)
      d.covered = d.covered || g.mask != 0;
  }
  return d;
}

} // namespace rastrules
