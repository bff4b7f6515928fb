// SPDX-License-Identifier: MIT
// rastrules explain: why each primitive covers, or does not cover, one pixel centre; on a
// multisampled scene, each sample of the pixel (MSAA.COVER.SAMPLE), the sample mask
// (MSAA.MASK.AND) and the centroid branch (MSAA.CENTROID.*).
// Every number shown is computed by the kernel (snap, setup_triangle, EdgeSetup::value_at,
// covers, sample_position, sample_coverage, centroid); this file only reports them and names
// the rule that decided.

#include <array>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "rastrules/io/fragment_json.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/line_aa.hpp"
#include "rastrules/line_aliased.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules::cli {
namespace {

struct EdgeReport {
  int from = 0, to = 0; // vertex indices as given in the scene
  Vec2 a, b;
  std::int64_t e = 0; // E at the sample, 1/65536 px^2
  bool top = false, left = false, horizontal = false, inclusive = false, inside = false;
  std::string kind;     // "top", "bottom", "left", "right"
  std::string decision; // rule ID and reason
};

// One triangle's report: a triangle primitive, one half of a point, or one half of a
// quadrilateral line segment.
struct PrimitiveReport {
  std::size_t index = 0;
  Primitive input; // the triangle's own vertices (for a point or a quad line: its corners)
  TriangleSetup setup;
  bool has_edges = false; // false for degenerate triangles
  bool culled = false;    // the edges are then shown for information only
  std::array<EdgeReport, 3> edges{};
  bool covered = false;
  bool inside_all_edges = false;
  std::vector<std::string> decided_by;
};

// One segment of a line or line strip at the pixel (aliased or antialiased).
struct SegReport {
  std::uint32_t seg = 0;
  Vec2 a, b;                      // snapped endpoints
  bool x_major = false;           // |dx| >= |dy|
  bool covered = false;           // the kernel's verdict for this pixel
  std::uint32_t coverage_q16 = 0; // antialiased lines
  LineDiamondDecision decision;   // aliased lines
};

// One sample of a multisampled pixel: each triangle of the primitive evaluated there.
struct SampleReport {
  std::uint32_t index = 0;
  SampleOffset offset;
  Vec2 position;
  std::vector<PrimitiveReport> tris; // as Report::tris, at this sample
};

// The coverage of one segment (0 for triangles and points) of a multisampled primitive.
struct SegmentMask {
  std::uint32_t seg = 0;
  std::uint32_t coverage = 0;  // the kernel's sample_coverage (before the mask)
  std::uint32_t explained = 0; // the samples the per-sample reports find covered
  std::uint32_t mask = 0;      // coverage & the sample mask (MSAA.MASK.AND)
  std::optional<Centroid> centroid;
};

// A multisampled primitive at the pixel.
struct MsaaReport {
  std::vector<SampleReport> samples; // empty for lines drawn without triangles
  bool whole_pixel = false;          // Bresenham lines: every sample of a produced pixel
  std::vector<SegmentMask> segments;
};

// The report of one primitive: a triangle (tris[0]), a point (tris: its two triangles), a
// quadrilateral line (tris: two per segment, tri_seg), or an aliased / antialiased line (segs).
struct Report {
  std::size_t index = 0;
  PrimitiveType type = PrimitiveType::kTriangle;
  bool aa = false;
  Primitive input;
  std::vector<Vec2> snapped;
  std::vector<PrimitiveReport> tris;
  std::vector<std::uint32_t> tri_seg;
  std::vector<SegReport> segs;
  bool covered = false;
  std::optional<MsaaReport> msaa; // multisampled scenes only
};

// Whether explain reports samples: more than one sample, or a centroid asked for.
bool multisampled(const PreparedScene& s) {
  return s.msaa.count() > 1 || s.msaa.has_centroid;
}

std::string mask_text(std::uint32_t m, std::uint32_t n) {
  std::string bits;
  for (std::uint32_t k = n; k-- > 0;)
    bits += ((m >> k) & 1u) != 0 ? '1' : '0';
  std::string list;
  for (std::uint32_t k = 0; k < n; ++k) {
    if (((m >> k) & 1u) != 0)
      list += (list.empty() ? "" : ", ") + std::to_string(k);
  }
  return "0b" + bits + " (" +
         (list.empty()
              ? "no sample"
              : "sample" + std::string(list.find(',') == std::string::npos ? " " : "s ") + list) +
         ")";
}

std::string offset_text(SampleOffset o) {
  return "(" + std::to_string(o.x) + ", " + std::to_string(o.y) + ")/16";
}

std::string px(Subpixel v) {
  return fixed_decimal(v.raw(), kSubpixelBits);
}
std::string point_px(Vec2 v) {
  return "(" + px(v.x) + ", " + px(v.y) + ")";
}
std::string point_raw(Vec2 v) {
  return "(" + std::to_string(v.x.raw()) + ", " + std::to_string(v.y.raw()) + ")";
}
std::string area_px2(std::int64_t raw) {
  return fixed_decimal(raw, 2 * kSubpixelBits);
}

std::string edge_decision(const EdgeReport& e, FillConvention fill) {
  if (e.e > 0)
    return "TRI.EDGE.FUNCTION: E > 0 -> inside";
  if (e.e < 0)
    return "TRI.EDGE.FUNCTION: E < 0 -> outside";
  const std::string verdict = e.inclusive ? "inside" : "outside";
  if (fill == FillConvention::kTopLeft) {
    return "TRI.FILL.TOP_LEFT: E == 0 on a " + e.kind + " edge" +
           (e.inclusive ? "" : " (neither top nor left)") + " -> " + verdict;
  }
  return "TRI.FILL.CONVENTION: E == 0 on a " + e.kind + " edge, " +
         (e.inclusive ? "inclusive" : "not inclusive") + " under " + std::string(to_string(fill)) +
         " -> " + verdict;
}

PrimitiveReport explain_triangle(std::size_t index, const Primitive& input,
                                 const TriangleSetup& setup, const RasterState& state,
                                 Vec2 sample) {
  PrimitiveReport r;
  r.index = index;
  r.input = input;
  r.setup = setup;
  r.covered = covers(setup, sample);
  if (setup.status == TriangleStatus::kDegenerate) {
    r.decided_by.push_back("TRI.DEGENERATE.ZERO_AREA: A == 0 after snapping -> covers nothing");
    return r;
  }
  // Culled triangles have no edges in their setup; show the edges they would have without
  // culling, for information.
  RasterState no_cull = state;
  no_cull.cull = CullMode::kNone;
  const TriangleSetup& edges_of =
      setup.status == TriangleStatus::kRasterized ? setup : setup_triangle(setup.snapped, no_cull);
  r.has_edges = true;
  r.culled = setup.status != TriangleStatus::kRasterized;
  const std::array<int, 3> order =
      setup.clockwise ? std::array<int, 3>{0, 1, 2} : std::array<int, 3>{0, 2, 1};
  r.inside_all_edges = true;
  for (std::size_t i = 0; i < 3; ++i) {
    const EdgeSetup& es = edges_of.edges[i];
    EdgeReport& e = r.edges[i];
    e.from = order[i];
    e.to = order[(i + 1) % 3];
    e.a = es.a;
    e.b = es.b;
    e.e = es.value_at(sample).raw();
    e.top = es.is_top;
    e.left = es.is_left;
    e.horizontal = es.a.y == es.b.y;
    e.kind = e.horizontal ? (es.is_top ? "top" : "bottom") : (es.is_left ? "left" : "right");
    e.inclusive = es.inclusive;
    e.inside = inside(es, sample);
    e.decision = edge_decision(e, state.fill);
    r.inside_all_edges = r.inside_all_edges && e.inside;
  }
  if (r.culled) {
    const bool back = setup.status == TriangleStatus::kCulledBack;
    r.decided_by.push_back(std::string("TRI.CULL.MODE: ") + (back ? "back" : "front") +
                           "-facing (" + (setup.clockwise ? "clockwise" : "counter-clockwise") +
                           " on screen, front face " + std::string(to_string(state.front_face)) +
                           ") and cull " + std::string(to_string(state.cull)) + " -> culled");
    r.decided_by.push_back("SNAP.CULL.AFTER_SNAP: the winding is that of the snapped vertices");
    return r;
  }
  int on_edges = 0;
  for (const EdgeReport& e : r.edges) {
    if (e.e == 0)
      ++on_edges;
    if (e.e == 0 || !e.inside) {
      r.decided_by.push_back("edge " + std::to_string(&e - r.edges.data()) + ": " + e.decision);
    }
  }
  if (on_edges == 2) {
    r.decided_by.push_back(
        std::string(state.fill == FillConvention::kTopLeft ? "TRI.FILL.TOP_LEFT"
                                                           : "TRI.FILL.CONVENTION") +
        ": the centre is a vertex (on two edges): inside only if both edges are inclusive");
  }
  if (r.covered) {
    r.decided_by.push_back("TRI.COVER.SAMPLE: inside all three edges -> covered");
  } else {
    r.decided_by.push_back("TRI.COVER.SAMPLE: outside at least one edge -> not covered");
  }
  return r;
}

// The text report of one triangle, each line starting with ind.
std::string triangle_text(const PrimitiveReport& r, const PreparedScene& s, const std::string& ind,
                          bool show_input = true) {
  std::string out;
  const TriangleSetup& t = r.setup;

  if (show_input) {
    out += ind + "vertices, input float32 -> snapped 16.8  [SNAP.VERTEX.ROUND]:\n";
    for (std::size_t i = 0; i < 3; ++i) {
      out += ind + "  v" + std::to_string(i) + " (" + io::format_float(r.input.v[i][0]) + ", " +
             io::format_float(r.input.v[i][1]) + ") -> " + point_px(t.snapped[i]) + " px = raw " +
             point_raw(t.snapped[i]) + "\n";
    }
  } else {
    out += ind + "vertices (snapped 16.8):";
    for (std::size_t i = 0; i < 3; ++i)
      out += " v" + std::to_string(i) + " " + point_px(t.snapped[i]);
    out += "\n";
  }
  out += ind + "twice signed area A = " + std::to_string(t.twice_area) +
         " raw = " + area_px2(t.twice_area) + " px^2: " +
         (t.twice_area == 0 ? std::string("degenerate")
                            : std::string(t.clockwise ? "clockwise" : "counter-clockwise") + ", " +
                                  (t.front_facing ? "front-facing" : "back-facing")) +
         "  [TRI.ORIENT.AREA, TRI.CULL.MODE]\n";
  out += ind + "status: " + std::string(to_string(t.status)) + "\n";
  if (r.has_edges) {
    out += ind + "edges in clockwise order" + (t.clockwise ? "" : " (v1 and v2 swapped)") +
           "  [TRI.ORIENT.NORMALISE]" +
           (r.culled ? ", for information only (the triangle is culled)" : "") + ":\n";
    for (std::size_t i = 0; i < 3; ++i) {
      const EdgeReport& e = r.edges[i];
      out += ind + "  edge " + std::to_string(i) + ": v" + std::to_string(e.from) + " " +
             point_px(e.a) + " -> v" + std::to_string(e.to) + " " + point_px(e.b) + "\n";
      out += ind + "    E at the centre = " + std::to_string(e.e) + " raw = " + area_px2(e.e) +
             " px^2  [TRI.EDGE.FUNCTION]\n";
      out += ind + "    " + e.kind + " edge: top " + (e.top ? "yes" : "no") + ", left " +
             (e.left ? "yes" : "no") + ", inclusive under " + std::string(to_string(s.state.fill)) +
             " " + (e.inclusive ? "yes" : "no") + "  [TRI.FILL.TOP_EDGE, TRI.FILL.LEFT_EDGE]\n";
      out += ind + "    " + std::string(e.inside ? "inside" : "outside") + ": " + e.decision + "\n";
    }
  }
  out += ind + "verdict: " + std::string(r.covered ? "covered" : "not covered") + "\n";
  out += ind + "decided by:\n";
  for (const std::string& d : r.decided_by)
    out += ind + "  " + d + "\n";
  if (r.culled) {
    out += ind + std::string("  (without culling the centre would be ") +
           (r.inside_all_edges ? "inside" : "outside") + ")\n";
  }
  return out;
}

std::string fraction_q16(std::uint32_t q) {
  return fixed_decimal(static_cast<std::int64_t>(q), kAACoverageBits);
}

// The diamond features named in a DiamondFeature bit set.
std::string features_text(std::uint32_t bits) {
  std::string out;
  for (std::uint32_t b = 1; b <= kFeatureCornerLeft; b <<= 1) {
    if ((bits & b) == 0)
      continue;
    out += (out.empty() ? "" : ", ") + std::string(to_string(static_cast<DiamondFeature>(b)));
  }
  return out.empty() ? "nothing" : out;
}

// The diamond test area of the pixel whose centre is c: corners at c +- (0.5, 0), (0, 0.5).
std::string diamond_text(Vec2 c) {
  auto at = [&](std::int32_t dx, std::int32_t dy) {
    return point_px(Vec2{Subpixel::from_raw(c.x.raw() + dx), Subpixel::from_raw(c.y.raw() + dy)});
  };
  const std::int32_t h = kSubpixelHalf;
  return "top " + at(0, -h) + ", right " + at(h, 0) + ", bottom " + at(0, h) + ", left " +
         at(-h, 0);
}

// The text of a point, a line or a line strip.
std::string other_text(const Report& r, const PreparedScene& s, Vec2 sample) {
  std::string out = "\nprimitive " + std::to_string(r.index) + ": " +
                    std::string(to_string(r.type)) + (r.aa ? " (antialiased)" : "") + "\n";
  out += "  vertices, input float32 -> snapped 16.8  [SNAP.VERTEX.ROUND]:\n";
  for (std::size_t i = 0; i < r.snapped.size(); ++i) {
    out += "    v" + std::to_string(i) + " (" + io::format_float(r.input.v[i][0]) + ", " +
           io::format_float(r.input.v[i][1]) + ") -> " + point_px(r.snapped[i]) + " px = raw " +
           point_raw(r.snapped[i]) + "\n";
  }
  if (r.type == PrimitiveType::kPoint) {
    // rule: SCENE.PRIM.POINT
    out += "  a 1x1 square centred on v0, drawn as two triangles (Z pattern) under the triangle "
           "rules, never culled  [SCENE.PRIM.POINT]\n";
    for (std::size_t k = 0; k < r.tris.size(); ++k) {
      out += "  triangle " + std::to_string(k) + " of the point:\n";
      out += triangle_text(r.tris[k], s, "    ", false);
    }
  } else if (!r.tris.empty()) {
    out += "  quadrilateral line (line_mode " + std::string(io::line_mode_name(s.line_mode)) +
           "): a rectangle of two triangles per segment under the triangle rules, never culled  "
           "[SCENE.LINE_MODE]\n";
    for (std::size_t k = 0; k < r.tris.size(); ++k) {
      out += "  segment " + std::to_string(r.tri_seg[k]) + ", triangle " + std::to_string(k % 2) +
             ":\n";
      out += triangle_text(r.tris[k], s, "    ", false);
    }
  } else {
    if (!r.aa)
      out += "  pixel's diamond test area: " + diamond_text(sample) + "\n";
    for (const SegReport& g : r.segs) {
      out += "  segment " + std::to_string(g.seg) + ": " + point_px(g.a) + " -> " + point_px(g.b) +
             ", " + (g.x_major ? "x-major" : "y-major") + "\n";
      if (r.aa) {
        out += "    coverage = " + fraction_q16(g.coverage_q16) + " (" +
               std::to_string(g.coverage_q16) +
               "/65536): mean over the squares R0..R4 (widths 1, 1.5, 2, 2.5, 3) of area(line "
               "rectangle & Ri) / area(Ri)  [SCENE.OUTPUT.COVERAGE]\n";
      } else {
        if (s.line_mode == LineMode::kD3DDiamond) {
          out += std::string("    test area: the diamond's interior, its lower-left and "
                             "lower-right edges and bottom corner") +
                 (g.x_major ? "" : ", and (y-major) its right corner") +
                 "; not the upper edges nor the other corners  [LINE.D3D.TEST_AREA]\n";
        } else {
          out += "    test area: the open diamond; both endpoints shifted by (-e, -e^2)  "
                 "[LINE.VK.TEST_AREA]\n";
        }
        const LineDiamondDecision& d = g.decision;
        if (d.zero_length)
          out += "    zero-length line  [LINE.ZERO_LENGTH]\n";
        out += "    the segment meets: " + features_text(d.met_features) + "\n";
        out += "    of which in the test area: " +
               features_text(d.met_features & d.included_features) + "\n";
        out += std::string("    enters the test area: ") + (d.entered ? "yes" : "no") +
               "; ends inside it: " + (d.end_inside ? "yes" : "no") + "\n";
        out += "    reason: " + std::string(d.reason) + "\n";
      }
      out +=
          std::string("    verdict: ") +
          (g.covered ? (r.aa ? "fragment (coverage > 0)" : "covered: the segment exits the diamond")
                     : (r.aa ? "no fragment (coverage 0)"
                             : "not covered: the segment does not exit the diamond")) +
          "\n";
    }
  }
  out += std::string("  verdict: ") + (r.covered ? "covered" : "not covered") + "\n";
  return out;
}

// Each sample of pixel (x, y) for one primitive: its triangles' edges at the sample, the
// kernel's coverage mask per segment, the mask AND and the centroid.
// rule: MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10
MsaaReport explain_samples(const PreparedScene& s, const PreparedPrimitive& prim, const Report& r,
                           std::int32_t x, std::int32_t y) {
  MsaaReport m;
  const MultisampleState& ms = s.msaa;
  const std::uint32_t n = ms.count();
  auto segment = [&](std::uint32_t seg) -> SegmentMask& {
    for (SegmentMask& g : m.segments) {
      if (g.seg == seg)
        return g;
    }
    m.segments.push_back(SegmentMask{seg, 0, 0, 0, std::nullopt});
    return m.segments.back();
  };
  if (!prim.triangles.empty()) {
    for (std::uint32_t k = 0; k < n; ++k) {
      SampleReport sr;
      sr.index = k;
      sr.offset = ms.pattern.positions[k];
      sr.position = sample_position(x, y, sr.offset);
      for (std::size_t t = 0; t < prim.triangles.size(); ++t) {
        PrimitiveReport tr = explain_triangle(r.index, r.tris[t].input, prim.triangles[t].setup,
                                              s.state, sr.position);
        if (tr.covered)
          segment(prim.triangles[t].seg).explained |= std::uint32_t{1} << k;
        sr.tris.push_back(std::move(tr));
      }
      m.samples.push_back(std::move(sr));
    }
    for (const PreparedTriangle& t : prim.triangles) {
      segment(t.seg).coverage |= sample_coverage(t.setup, x, y, ms.pattern);
    }
  } else {
    // rule: MSAA.LINE.MODE
    m.whole_pixel = true;
    for (const SegReport& g : r.segs) {
      SegmentMask& sm = segment(g.seg);
      if (g.covered)
        sm.coverage = sm.explained = full_mask(n);
    }
  }
  for (SegmentMask& g : m.segments) {
    g.mask = g.coverage & ms.effective_mask();
    if (ms.has_centroid)
      g.centroid = centroid(ms.centroid_rule, g.coverage, ms.sample_mask, ms.pattern);
  }
  return m;
}

// rule: SCENE.PRIM.POINT, SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP, SCENE.LINE_MODE
Report explain_primitive(const LoadedScene& loaded, std::size_t p, std::int32_t x, std::int32_t y,
                         Vec2 sample) {
  const PreparedScene& s = *loaded.prepared;
  const PreparedPrimitive& prim = s.primitives[p];
  Report r;
  r.index = p;
  r.type = prim.type;
  r.aa = prim.aa;
  r.input = loaded.scene.primitives[p];
  r.snapped = prim.v;
  for (const PreparedTriangle& t : prim.triangles) {
    Primitive corners = make_triangle({});
    if (prim.type == PrimitiveType::kTriangle)
      corners = r.input;
    PrimitiveReport tr = explain_triangle(p, corners, t.setup, s.state, sample);
    r.covered = r.covered || tr.covered;
    r.tris.push_back(std::move(tr));
    r.tri_seg.push_back(t.seg);
  }
  if (prim.triangles.empty() && prim.type != PrimitiveType::kTriangle) {
    // The kernel's verdict per segment (aliased_line_covers' explanation, or the AA
    // coverage); the fragment list agrees with it.
    for (std::size_t k = 0; k + 1 < prim.v.size(); ++k) {
      SegReport g;
      g.seg = static_cast<std::uint32_t>(k);
      g.a = prim.v[k];
      g.b = prim.v[k + 1];
      const std::int64_t dx = std::int64_t{g.b.x.raw()} - g.a.x.raw();
      const std::int64_t dy = std::int64_t{g.b.y.raw()} - g.a.y.raw();
      g.x_major = (dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy);
      if (prim.aa) {
        const AACoverage c = aa_line_coverage(g.a, g.b, x, y);
        g.covered = c.positive;
        g.coverage_q16 = c.q16;
      } else {
        g.decision = explain_aliased_line_pixel(g.a, g.b, s.line_mode, x, y);
        g.covered = g.decision.covered;
        g.x_major = g.decision.x_major;
      }
      r.covered = r.covered || g.covered;
      r.segs.push_back(g);
    }
  }
  if (multisampled(s)) {
    // A fragment exists when some sample in the mask is covered (MSAA.MASK.AND).
    r.msaa = explain_samples(s, prim, r, x, y);
    r.covered = false;
    for (const SegmentMask& g : r.msaa->segments)
      r.covered = r.covered || g.mask != 0;
  }
  return r;
}

std::string centroid_rule_id(CentroidRule r) {
  return r == CentroidRule::kD3D11 ? "MSAA.CENTROID.D3D11" : "MSAA.CENTROID.D3D10";
}

std::string pattern_rule_id(PatternKind k) {
  switch (k) {
  case PatternKind::kStandard:
    return "MSAA.PATTERN.STANDARD";
  case PatternKind::kCenter:
    return "MSAA.PATTERN.CENTER";
  case PatternKind::kCustom:
    return "MSAA.PATTERN.CUSTOM";
  }
  return "MSAA.PATTERN.GRID";
}

// The text of one primitive of a multisampled scene: each sample of the pixel.
// rule: MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10
std::string msaa_text(const Report& r, const PreparedScene& s, std::int32_t x, std::int32_t y) {
  const MsaaReport& m = *r.msaa;
  const MultisampleState& ms = s.msaa;
  const std::uint32_t n = ms.count();
  std::string out = "\nprimitive " + std::to_string(r.index) + ": " +
                    std::string(to_string(r.type)) + (r.aa ? " (antialiased)" : "") + "\n";
  out += "  vertices, input float32 -> snapped 16.8  [SNAP.VERTEX.ROUND]:\n";
  for (std::size_t i = 0; i < r.snapped.size(); ++i) {
    out += "    v" + std::to_string(i) + " (" + io::format_float(r.input.v[i][0]) + ", " +
           io::format_float(r.input.v[i][1]) + ") -> " + point_px(r.snapped[i]) + " px = raw " +
           point_raw(r.snapped[i]) + "\n";
  }
  const bool several = m.samples.empty() ? false : m.samples[0].tris.size() > 1;
  if (!m.samples.empty()) {
    for (std::size_t t = 0; t < r.tris.size(); ++t) {
      const PrimitiveReport& tr = r.tris[t];
      std::string name = several ? "  triangle " + std::to_string(t) +
                                       (r.type == PrimitiveType::kPoint
                                            ? " of the point"
                                            : " (segment " + std::to_string(r.tri_seg[t]) + ")")
                                 : std::string("  triangle");
      out += name + ": twice signed area A = " + std::to_string(tr.setup.twice_area) + " raw, " +
             (tr.setup.twice_area == 0
                  ? std::string("degenerate")
                  : std::string(tr.setup.clockwise ? "clockwise" : "counter-clockwise")) +
             ", status " + std::string(to_string(tr.setup.status)) +
             "  [TRI.ORIENT.AREA, TRI.CULL.MODE]\n";
    }
  }
  out += "  " + std::to_string(n) + " sample" + (n == 1 ? "" : "s") + ", " +
         std::string(to_string(ms.pattern.kind)) + " pattern  [" +
         pattern_rule_id(ms.pattern.kind) + "]\n";
  if (m.whole_pixel) {
    out += "  a " + std::string(io::line_mode_name(s.line_mode)) +
           " line covers every sample of each pixel it produces  [MSAA.LINE.MODE]\n";
    for (const SegReport& g : r.segs) {
      out += "  segment " + std::to_string(g.seg) + ": " +
             (g.covered ? "produces the pixel" : "does not produce the pixel") + "\n";
    }
  }
  for (const SampleReport& sr : m.samples) {
    out += "  sample " + std::to_string(sr.index) + " at " + offset_text(sr.offset) + " -> " +
           point_px(sr.position) + " px = raw " + point_raw(sr.position) +
           "  [MSAA.SAMPLE.POSITION]\n";
    for (std::size_t t = 0; t < sr.tris.size(); ++t) {
      const PrimitiveReport& tr = sr.tris[t];
      const std::string ind = several ? "      " : "    ";
      if (several)
        out += "    triangle " + std::to_string(t) + ":\n";
      if (!tr.has_edges) {
        out += ind + "degenerate: covers nothing  [TRI.DEGENERATE.ZERO_AREA]\n";
        continue;
      }
      for (std::size_t i = 0; i < 3; ++i) {
        const EdgeReport& e = tr.edges[i];
        out += ind + "edge " + std::to_string(i) + " v" + std::to_string(e.from) + "->v" +
               std::to_string(e.to) + " (" + e.kind + "): E = " + std::to_string(e.e) +
               " raw = " + area_px2(e.e) + " px^2 -> " + (e.inside ? "inside" : "outside") + ": " +
               e.decision + "\n";
      }
      if (tr.culled)
        out += ind + "culled: " + tr.decided_by.front() + "\n";
      out += ind + (tr.covered ? "covered" : "not covered") + "  [MSAA.COVER.SAMPLE]\n";
    }
  }
  for (const SegmentMask& g : m.segments) {
    const std::string seg = m.segments.size() > 1 || r.type == PrimitiveType::kLineStrip
                                ? "  segment " + std::to_string(g.seg) + ": "
                                : "  ";
    out += seg + "coverage " + mask_text(g.coverage, n) + "  [MSAA.COVER.SAMPLE]\n";
    if (g.explained != g.coverage) {
      out += seg + "internal error: the samples above say " + mask_text(g.explained, n) + "\n";
    }
    out += seg + "sample mask " + mask_text(ms.effective_mask(), n) + " -> fragment mask " +
           mask_text(g.mask, n) + "  [MSAA.MASK.AND]\n";
    if (g.centroid) {
      const Centroid& c = *g.centroid;
      const Vec2 at = sample_position(x, y, c.offset);
      out += seg + "centroid (" + std::string(to_string(ms.centroid_rule)) +
             "): " + std::string(to_string(c.branch)) + " -> " + offset_text(c.offset) + " = " +
             point_px(at) + " px  [" + centroid_rule_id(ms.centroid_rule) + "]" +
             (g.mask == 0 ? " (no fragment: the pixel is covered by no sample in the mask)" : "") +
             "\n";
    }
    out += seg + "verdict: " +
           (g.mask != 0 ? "fragment, mask " + std::to_string(g.mask) : std::string("no fragment")) +
           "\n";
  }
  if (m.segments.empty())
    out += "  verdict: no fragment\n";
  return out;
}

void print_text(const LoadedScene& loaded, std::int32_t x, std::int32_t y, Vec2 sample,
                const std::vector<Report>& reports) {
  const PreparedScene& s = *loaded.prepared;
  std::string out;
  out += "scene: " + std::to_string(s.width) + "x" + std::to_string(s.height) + " target, cull " +
         std::string(to_string(s.state.cull)) + ", front face " +
         std::string(to_string(s.state.front_face)) + ", fill " +
         std::string(to_string(s.state.fill)) +
         (s.line_mode != LineMode::kD3DDiamond
              ? ", line_mode " + std::string(io::line_mode_name(s.line_mode))
              : std::string()) +
         ", " + std::to_string(reports.size()) + " primitive" + (reports.size() == 1 ? "" : "s") +
         "\n";
  out += "pixel (" + std::to_string(x) + ", " + std::to_string(y) + "): centre " +
         point_px(sample) + " px = raw " + point_raw(sample) + "  [COORD.PIXEL.CENTER]\n";
  if (multisampled(s)) {
    const MultisampleState& ms = s.msaa;
    out += "multisampling: " + std::to_string(ms.count()) + " samples, " +
           std::string(to_string(ms.pattern.kind)) + " pattern, sample mask " +
           mask_text(ms.effective_mask(), ms.count()) + ", centroid " +
           (ms.has_centroid ? std::string(to_string(ms.centroid_rule)) : std::string("none")) +
           ", shading " + std::string(to_string(ms.shading)) + "  [SCENE.MSAA]\n";
  }
  std::vector<std::size_t> covering;
  for (const Report& report : reports) {
    if (report.msaa) {
      out += msaa_text(report, s, x, y);
      if (report.covered)
        covering.push_back(report.index);
      continue;
    }
    if (report.type != PrimitiveType::kTriangle) {
      out += other_text(report, s, sample);
      if (report.covered)
        covering.push_back(report.index);
      continue;
    }
    const PrimitiveReport& r = report.tris[0];
    out += "\nprimitive " + std::to_string(r.index) + ": triangle\n";
    out += triangle_text(r, s, "  ");
    if (r.covered)
      covering.push_back(r.index);
  }
  out += "\npixel (" + std::to_string(x) + ", " + std::to_string(y) + "): ";
  if (covering.empty()) {
    out += "covered by no primitive\n";
  } else {
    out += std::string("covered by primitive") + (covering.size() == 1 ? " " : "s ");
    for (std::size_t i = 0; i < covering.size(); ++i)
      out += (i ? ", " : "") + std::to_string(covering[i]);
    out += covering.size() > 1 ? " (overlap)\n" : "\n";
  }
  std::fputs(out.c_str(), stdout);
}

using ojson = nlohmann::ordered_json;

ojson point_json(Vec2 v) {
  return ojson::array({v.x.raw(), v.y.raw()});
}

ojson triangle_json(const PrimitiveReport& r) {
  using json = ojson;
  auto point = point_json;
  const TriangleSetup& t = r.setup;
  json p;
  p["prim"] = r.index;
  json in = json::array();
  for (const auto& v : r.input.v)
    in.push_back({io::format_float(v[0]), io::format_float(v[1])});
  p["input"] = in;
  json snapped = json::array();
  for (const Vec2& v : t.snapped)
    snapped.push_back(point(v));
  p["snapped_raw"] = snapped;
  p["twice_area_raw"] = t.twice_area;
  p["winding"] = t.twice_area == 0 ? "degenerate" : (t.clockwise ? "cw" : "ccw");
  p["front_facing"] = t.front_facing;
  p["status"] = to_string(t.status);
  json edges = json::array();
  if (r.has_edges) {
    for (const EdgeReport& e : r.edges) {
      edges.push_back({{"from", e.from},
                       {"to", e.to},
                       {"a_raw", point(e.a)},
                       {"b_raw", point(e.b)},
                       {"e_raw", e.e},
                       {"kind", e.kind},
                       {"top", e.top},
                       {"left", e.left},
                       {"inclusive", e.inclusive},
                       {"inside", e.inside},
                       {"decision", e.decision}});
    }
  }
  p["edges"] = edges;
  p["edges_informative_only"] = r.culled;
  p["covered"] = r.covered;
  p["decided_by"] = r.decided_by;
  return p;
}

ojson other_json(const Report& r) {
  using json = ojson;
  json p;
  p["prim"] = r.index;
  p["type"] = to_string(r.type);
  if (r.aa)
    p["aa"] = true;
  json in = json::array();
  for (const auto& v : r.input.v)
    in.push_back({io::format_float(v[0]), io::format_float(v[1])});
  p["input"] = in;
  json snapped = json::array();
  for (const Vec2& v : r.snapped)
    snapped.push_back(point_json(v));
  p["snapped_raw"] = snapped;
  if (!r.tris.empty()) {
    json tris = json::array();
    for (std::size_t k = 0; k < r.tris.size(); ++k) {
      json t = triangle_json(r.tris[k]);
      t.erase("input");
      if (r.type != PrimitiveType::kPoint)
        t["seg"] = r.tri_seg[k];
      tris.push_back(t);
    }
    p["triangles"] = tris;
  } else {
    json segs = json::array();
    for (const SegReport& g : r.segs) {
      json j = {{"seg", g.seg},
                {"a_raw", point_json(g.a)},
                {"b_raw", point_json(g.b)},
                {"x_major", g.x_major},
                {"covered", g.covered}};
      if (r.aa) {
        j["coverage_q16"] = g.coverage_q16;
        j["coverage"] = fraction_q16(g.coverage_q16);
      } else {
        j["met"] = features_text(g.decision.met_features);
        j["met_in_test_area"] =
            features_text(g.decision.met_features & g.decision.included_features);
        j["entered"] = g.decision.entered;
        j["end_inside"] = g.decision.end_inside;
        j["reason"] = g.decision.reason;
      }
      segs.push_back(j);
    }
    p["segments"] = segs;
  }
  p["covered"] = r.covered;
  return p;
}

// rule: MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10
ojson msaa_json(const Report& r, const PreparedScene& s) {
  using json = ojson;
  const MsaaReport& m = *r.msaa;
  json samples = json::array();
  for (const SampleReport& sr : m.samples) {
    json tris = json::array();
    bool covered = false;
    for (const PrimitiveReport& tr : sr.tris) {
      json edges = json::array();
      if (tr.has_edges) {
        for (const EdgeReport& e : tr.edges) {
          edges.push_back({{"from", e.from},
                           {"to", e.to},
                           {"kind", e.kind},
                           {"e_raw", e.e},
                           {"inclusive", e.inclusive},
                           {"inside", e.inside},
                           {"decision", e.decision}});
        }
      }
      tris.push_back(
          {{"status", to_string(tr.setup.status)}, {"edges", edges}, {"covered", tr.covered}});
      covered = covered || tr.covered;
    }
    samples.push_back({{"sample", sr.index},
                       {"offset", {sr.offset.x, sr.offset.y}},
                       {"position_raw", point_json(sr.position)},
                       {"triangles", tris},
                       {"covered", covered}});
  }
  json segs = json::array();
  for (const SegmentMask& g : m.segments) {
    json j = {{"seg", g.seg},
              {"coverage", g.coverage},
              {"sample_mask", s.msaa.effective_mask()},
              {"mask", g.mask},
              {"fragment", g.mask != 0}};
    if (g.centroid) {
      j["centroid"] = {{"rule", to_string(s.msaa.centroid_rule)},
                       {"branch", to_string(g.centroid->branch)},
                       {"offset", {g.centroid->offset.x, g.centroid->offset.y}}};
    }
    segs.push_back(j);
  }
  json out;
  out["samples"] = samples;
  if (m.whole_pixel)
    out["every_sample_of_produced_pixels"] = true;
  out["segments"] = segs;
  return out;
}

void print_json(const LoadedScene& loaded, std::int32_t x, std::int32_t y, Vec2 sample,
                const std::vector<Report>& reports) {
  using json = ojson;
  const PreparedScene& s = *loaded.prepared;
  auto point = point_json;
  json doc;
  doc["target"] = {{"width", s.width}, {"height", s.height}};
  doc["cull"] = to_string(s.state.cull);
  doc["front_face"] = to_string(s.state.front_face);
  doc["fill"] = to_string(s.state.fill);
  doc["line_mode"] = io::line_mode_name(s.line_mode);
  doc["pixel"] = {x, y};
  doc["sample_raw"] = point(sample);
  json prims = json::array();
  json covering = json::array();
  if (multisampled(s)) {
    doc["samples"] = s.msaa.count();
    doc["sample_pattern"] = to_string(s.msaa.pattern.kind);
    doc["sample_mask"] = s.msaa.effective_mask();
    if (s.msaa.has_centroid)
      doc["centroid"] = to_string(s.msaa.centroid_rule);
  }
  for (const Report& r : reports) {
    ojson p = r.type == PrimitiveType::kTriangle ? triangle_json(r.tris[0]) : other_json(r);
    if (r.msaa) {
      p["covered"] = r.covered;
      p["msaa"] = msaa_json(r, s);
    }
    prims.push_back(p);
    if (r.covered)
      covering.push_back(r.index);
  }
  doc["primitives"] = prims;
  doc["covered_by"] = covering;
  std::fputs((doc.dump(2) + "\n").c_str(), stdout);
}

// rule: SCENE.OUTPUT.PIPELINE
// A pipeline scene at one pixel: the fragments run_pipeline produced there, with what each
// carries and the drawn primitive (after clipping, divide, viewport, snapping and depth bias)
// it was interpolated from. Coverage itself is the kernel's; no edge values are shown.
int explain_pipeline(const Scene& scene, const pipe::PipeResult& result, std::int32_t x,
                     std::int32_t y, bool as_json) {
  const bool has_data = !result.data.empty();
  if (has_data && result.data.size() != result.fragments.size()) {
    return error("internal error: run_pipeline's fragment data do not match its fragments");
  }
  std::vector<Fragment> here;
  std::vector<pipe::FragmentData> here_data;
  for (std::size_t i = 0; i < result.fragments.size(); ++i) {
    const Fragment& f = result.fragments[i];
    if (f.x != x || f.y != y)
      continue;
    here.push_back(f);
    if (has_data)
      here_data.push_back(result.data[i]);
  }
  std::vector<std::uint32_t> covering;
  for (std::size_t i = 0; i < here.size(); ++i) {
    const std::uint32_t passed = has_data ? here_data[i].passed : here[i].mask;
    if (passed != 0 && (covering.empty() || covering.back() != here[i].prim))
      covering.push_back(here[i].prim);
  }
  const io::PipeOutputFields fields = io::pipe_output_fields(scene);
  const std::uint32_t n = scene.msaa.count();
  const auto drawn_of = [&](std::size_t i) -> const pipe::DrawnPrimitive* {
    if (!has_data || here_data[i].drawn >= result.drawn.size())
      return nullptr;
    return &result.drawn[here_data[i].drawn];
  };
  if (as_json) {
    const std::optional<std::string> text = io::pipe_fragments_to_json(here, here_data, fields);
    if (!text)
      return error("internal error: run_pipeline's fragments do not match the scene");
    ojson doc;
    doc["target"] = {{"width", scene.width}, {"height", scene.height}};
    doc["pixel"] = {x, y};
    doc["pipeline"] = true;
    doc["samples"] = n;
    if (scene.depth) {
      doc["depth"] = {{"format", io::depth_format_name(scene.depth->format)},
                      {"func", io::compare_func_name(scene.depth->func)}};
    }
    doc["fragments"] = ojson::parse(*text)["fragments"];
    for (std::size_t i = 0; i < here.size(); ++i) {
      const pipe::DrawnPrimitive* d = drawn_of(i);
      if (d == nullptr)
        continue;
      ojson snapped = ojson::array();
      for (const Vec2& v : d->snapped)
        snapped.push_back(point_json(v));
      doc["fragments"][i]["drawn"] = {
          {"type", to_string(d->type)}, {"snapped_raw", snapped}, {"z", d->z}, {"w", d->w}};
    }
    doc["covered_by"] = covering;
    std::fputs((doc.dump(2) + "\n").c_str(), stdout);
    return kExitOk;
  }
  std::string out = "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") of a " +
                    std::to_string(scene.width) + "x" + std::to_string(scene.height) +
                    " pipeline scene (SCENE.PIPELINE): " + std::to_string(here.size()) +
                    (here.size() == 1 ? " fragment" : " fragments") +
                    " (coverage after transform, clipping, divide, viewport and snapping)\n";
  for (std::size_t i = 0; i < here.size(); ++i) {
    const Fragment& f = here[i];
    const pipe::FragmentData* data = has_data ? &here_data[i] : nullptr;
    out += "primitives[" + std::to_string(f.prim) + "]";
    if (data != nullptr && data->part)
      out += " part " + std::to_string(*data->part);
    if (f.seg)
      out += " seg " + std::to_string(*f.seg);
    if (f.sample)
      out += " sample " + std::to_string(*f.sample);
    out += f.helper ? ": helper lane" : ": mask " + mask_text(f.mask, n);
    out += "\n";
    if (const pipe::DrawnPrimitive* d = drawn_of(i)) {
      std::string vs, zs, ws;
      for (const Vec2& v : d->snapped)
        vs += (vs.empty() ? "" : ", ") + point_px(v);
      for (std::size_t k = 0; k < std::min<std::size_t>(d->snapped.size(), 3); ++k) {
        zs += (k == 0 ? "" : ", ") + io::format_float(d->z[k]);
        ws += (k == 0 ? "" : ", ") + io::format_float(d->w[k]);
      }
      out += "  drawn " + std::string(to_string(d->type)) + ": snapped " + vs + ", window z [" +
             zs + "], w [" + ws + "]\n";
    }
    if (data == nullptr)
      continue;
    if (data->bary) {
      const pipe::Barycentrics& b = *data->bary;
      const pipe::DrawnPrimitive* d = drawn_of(i);
      const bool triangle = d == nullptr || d->type == PrimitiveType::kTriangle;
      out += std::string("  barycentrics (") + (triangle ? "PIPE.BARY.EXACT" : "PIPE.BARY.LINE") +
             "): e = [" + std::to_string(b.e[0]) + ", " + std::to_string(b.e[1]) + ", " +
             std::to_string(b.e[2]) + "], A = " + std::to_string(b.area) + " (e0 + e1 + e2 = A)\n";
    }
    for (std::size_t k = 0; k < scene.attributes.size() && k < data->attr.size(); ++k) {
      const pipe::AttributeDecl& a = scene.attributes[k];
      out += "  attr " + io::printable(a.name) + " = " + io::format_float(data->attr[k]) + " (" +
             std::string(io::interpolation_name(a.interpolation)) + ", " +
             std::string(io::location_name(a.location)) + ")\n";
    }
    if (scene.depth) {
      const bool killed = !f.helper && data->passed == 0;
      std::string depths;
      for (const pipe::DepthValue& d : data->depth) {
        depths += (depths.empty() ? "" : ", ") + io::depth_text(d, scene.depth->format);
      }
      out += killed ? std::string("  killed: no sample passed the depth test (PIPE.DEPTH.KILL)")
                    : "  depth [" + depths + "] (" +
                          std::string(io::depth_format_name(scene.depth->format)) + "), passed " +
                          mask_text(data->passed, n);
      out += " (depth.func " + std::string(io::compare_func_name(scene.depth->func)) +
             ", PIPE.DEPTH.TEST)\n";
    }
  }
  std::string list;
  for (const std::uint32_t p : covering)
    list += (list.empty() ? "" : ", ") + std::to_string(p);
  out += "covered by: " + (list.empty() ? std::string("nothing") : "primitives " + list) +
         (scene.depth ? " (samples that passed the depth test)\n" : "\n");
  std::fputs(out.c_str(), stdout);
  return kExitOk;
}

} // namespace

int run_explain(const Args& args) {
  std::optional<std::string> scene_path, pixel;
  bool as_json = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      print_usage(stdout);
      return kExitOk;
    } else if (a == "--json") {
      as_json = true;
    } else if (a == "--pixel" || a.rfind("--pixel=", 0) == 0) {
      if (a != "--pixel") {
        pixel = a.substr(8);
      } else if (i + 1 < args.size()) {
        pixel = args[++i];
      } else {
        return usage_error("--pixel needs X,Y");
      }
    } else if (a.size() > 1 && a[0] == '-') {
      return usage_error("explain: unknown option \"" + a + "\"");
    } else if (scene_path) {
      return usage_error("explain: more than one scene file");
    } else {
      scene_path = a;
    }
  }
  if (!scene_path)
    return usage_error("explain: missing SCENE.json");
  if (!pixel)
    return usage_error("explain: missing --pixel X,Y");
  const std::size_t comma = pixel->find(',');
  const auto px_x = comma == std::string::npos
                        ? std::nullopt
                        : parse_int(pixel->substr(0, comma), 0, kMaxTargetSide - 1);
  const auto px_y = comma == std::string::npos
                        ? std::nullopt
                        : parse_int(pixel->substr(comma + 1), 0, kMaxTargetSide - 1);
  if (!px_x || !px_y) {
    return usage_error("--pixel needs two integers X,Y in [0, " +
                       std::to_string(kMaxTargetSide - 1) + "]");
  }

  const auto loaded = load_scene(*scene_path);
  if (!loaded)
    return kExitBadInput;
  const auto x = static_cast<std::int32_t>(*px_x);
  const auto y = static_cast<std::int32_t>(*px_y);
  // rule: SCENE.OUTPUT.PIPELINE
  std::optional<pipe::PipeResult> result;
  if (!loaded->prepared) {
    result = run_pipeline_or_report(loaded->scene, RenderOptions{}, io::kDefaultMaxFragments);
    if (!result)
      return kExitBadInput;
  }
  // rule: SCENE.INPUT.ERRORS
  if (x >= loaded->scene.width || y >= loaded->scene.height) {
    return error("--pixel: (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                 std::to_string(loaded->scene.width) + "x" + std::to_string(loaded->scene.height) +
                 " target");
  }
  if (result)
    return explain_pipeline(loaded->scene, *result, x, y, as_json);
  const Vec2 sample = pixel_center(x, y);
  std::vector<Report> reports;
  reports.reserve(loaded->prepared->primitives.size());
  for (std::size_t p = 0; p < loaded->prepared->primitives.size(); ++p) {
    reports.push_back(explain_primitive(*loaded, p, x, y, sample));
  }
  if (as_json) {
    print_json(*loaded, x, y, sample, reports);
  } else {
    print_text(*loaded, x, y, sample, reports);
  }
  return kExitOk;
}

} // namespace rastrules::cli
