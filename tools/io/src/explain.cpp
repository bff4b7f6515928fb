// SPDX-License-Identifier: MIT
// The explanation of one pixel (`rastrules explain`, rr_explain of the C API): why each primitive
// covers, or does not cover, one pixel centre; on a multisampled scene, each sample of the pixel
// (MSAA.COVER.SAMPLE), the sample mask (MSAA.MASK.AND) and the centroid branch (MSAA.CENTROID.*).
// The decisions are the kernel's records (rastrules/decision.hpp: decide_pixel), filled by the
// functions that decide coverage and naming their rules from rastrules/rules.hpp; this file
// only formats them, as text or JSON.

#include <array>
#include <cstdio>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "rastrules/decision.hpp"
#include "rastrules/io/explain.hpp"
#include "rastrules/io/fragment_json.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/line_aa.hpp"
#include "rastrules/line_aliased.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/rules.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules::io {
namespace {

// The scene explained: as read, and prepared when it has no pipeline state.
struct LoadedScene {
  const Scene& scene;
  const PreparedScene* prepared;
};

// The report of one primitive: the kernel's decision at the pixel, with the scene input it
// was prepared from.
struct Report {
  std::size_t index = 0;
  PrimitiveType type = PrimitiveType::kTriangle;
  bool aa = false;
  Primitive input;
  std::vector<Vec2> snapped;
  PixelDecision d;
  bool covered = false;      // the fragment masks when multisampled, else the centre
  bool show_samples = false; // multisampled(): the samples are reported
};

// Whether explain reports samples: more than one sample, a centroid asked for, or one sample
// whose coverage is not the pixel centre's (a custom position elsewhere, or a sample mask that
// removes it). Quads and sample shading alone do not change what a single centred sample covers.
// rule: MSAA.COVER.SAMPLE, MSAA.MASK.AND
bool multisampled(const PreparedScene& s) {
  const MultisampleState& ms = s.msaa;
  return ms.count() > 1 || ms.has_centroid || !(ms.pattern.positions[0] == SampleOffset{}) ||
         ms.effective_mask() != 1u;
}

std::string id(RuleId r) {
  return std::string(r.id);
}

// "[A, B]": the rules a line of the report follows.
std::string cite(std::initializer_list<RuleId> ids) {
  std::string out;
  for (const RuleId r : ids)
    out += (out.empty() ? "[" : ", ") + id(r);
  return out + "]";
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
// A rational as "n/d", or "n" when it is an integer.
std::string fraction_text(const boost::multiprecision::cpp_rational& q) {
  const auto& d = boost::multiprecision::denominator(q);
  return d == 1 ? boost::multiprecision::numerator(q).str()
                : boost::multiprecision::numerator(q).str() + "/" + d.str();
}

std::string area_px2(std::int64_t raw) {
  return fixed_decimal(raw, 2 * kSubpixelBits);
}

// "top", "bottom", "left" or "right".
std::string edge_kind(const EdgeDecision& e) {
  return e.horizontal ? (e.top ? "top" : "bottom") : (e.left ? "left" : "right");
}

// The rule that decided an edge and why.
// rule: TRI.EDGE.FUNCTION, TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION
std::string edge_reason(const EdgeDecision& e, FillConvention fill) {
  const std::int64_t v = e.e.raw();
  if (v > 0)
    return id(e.rule) + ": E > 0 -> inside";
  if (v < 0)
    return id(e.rule) + ": E < 0 -> outside";
  const std::string verdict = e.inside ? "inside" : "outside";
  if (e.rule == rules::kTriFillTopLeft) {
    return id(e.rule) + ": E == 0 on a " + edge_kind(e) + " edge" +
           (e.inclusive ? "" : " (neither top nor left)") + " -> " + verdict;
  }
  return id(e.rule) + ": E == 0 on a " + edge_kind(e) + " edge, " +
         (e.inclusive ? "inclusive" : "not inclusive") + " under " + std::string(to_string(fill)) +
         " -> " + verdict;
}

// The rules that decided a triangle, one line each.
// rule: TRI.DEGENERATE.ZERO_AREA, TRI.CULL.MODE, SNAP.CULL.AFTER_SNAP, TRI.COVER.SAMPLE
std::vector<std::string> decided_by(const TriangleDecision& d, const RasterState& state) {
  std::vector<std::string> out;
  const TriangleSetup& t = d.setup;
  if (!d.has_edges) {
    out.push_back(id(d.rule) + ": A == 0 after snapping -> covers nothing");
    return out;
  }
  if (d.culled) {
    const bool back = t.status == TriangleStatus::kCulledBack;
    out.push_back(id(d.rule) + ": " + (back ? "back" : "front") + "-facing (" +
                  (t.clockwise ? "clockwise" : "counter-clockwise") + " on screen, front face " +
                  std::string(to_string(state.front_face)) + ") and cull " +
                  std::string(to_string(state.cull)) + " -> culled");
    out.push_back(id(rules::kSnapCullAfterSnap) + ": the winding is that of the snapped vertices");
    return out;
  }
  for (std::size_t i = 0; i < 3; ++i) {
    const EdgeDecision& e = d.edges[i];
    if (e.e == EdgeValue{} || !e.inside)
      out.push_back("edge " + std::to_string(i) + ": " + edge_reason(e, state.fill));
  }
  if (d.on_edges == 2) {
    out.push_back(id(fill_rule(state.fill)) +
                  ": the centre is a vertex (on two edges): inside only if both edges are "
                  "inclusive");
  }
  out.push_back(id(d.rule) + (d.covered ? ": inside all three edges -> covered"
                                        : ": outside at least one edge -> not covered"));
  return out;
}

// The vertices of a primitive, input float32 and snapped, each line starting with ind.
std::string vertices_text(const Primitive& input, const std::vector<Vec2>& snapped,
                          const std::string& ind) {
  std::string out =
      ind + "vertices, input float32 -> snapped 16.8  " + cite({rules::kSnapVertexRound}) + ":\n";
  for (std::size_t i = 0; i < snapped.size(); ++i) {
    out += ind + "  v" + std::to_string(i) + " (" + io::format_float(input.v[i][0]) + ", " +
           io::format_float(input.v[i][1]) + ") -> " + point_px(snapped[i]) + " px = raw " +
           point_raw(snapped[i]) + "\n";
  }
  return out;
}

// The text of one edge of a triangle at the pixel centre.
std::string edge_text(const EdgeDecision& e, std::size_t i, const PreparedScene& s,
                      const std::string& ind) {
  std::string out = ind + "  edge " + std::to_string(i) + ": v" + std::to_string(e.from) + " " +
                    point_px(e.a) + " -> v" + std::to_string(e.to) + " " + point_px(e.b) + "\n";
  out += ind + "    E at the centre = " + std::to_string(e.e.raw()) +
         " raw = " + area_px2(e.e.raw()) + " px^2  " + cite({rules::kTriEdgeFunction}) + "\n";
  out += ind + "    " + edge_kind(e) + " edge: top " + (e.top ? "yes" : "no") + ", left " +
         (e.left ? "yes" : "no") + ", inclusive under " + std::string(to_string(s.state.fill)) +
         " " + (e.inclusive ? "yes" : "no") + "  " +
         cite({rules::kTriFillTopEdge, rules::kTriFillLeftEdge}) + "\n";
  out += ind + "    " + std::string(e.inside ? "inside" : "outside") + ": " +
         edge_reason(e, s.state.fill) + "\n";
  return out;
}

// The text report of one triangle, each line starting with ind.
std::string triangle_text(const TriangleDecision& d, const Primitive& input, const PreparedScene& s,
                          const std::string& ind, bool show_input = true) {
  std::string out;
  const TriangleSetup& t = d.setup;

  if (show_input) {
    out += vertices_text(input, std::vector<Vec2>(t.snapped.begin(), t.snapped.end()), ind);
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
         "  " + cite({rules::kTriOrientArea, rules::kTriCullMode}) + "\n";
  out += ind + "status: " + std::string(to_string(t.status)) + "\n";
  if (d.has_edges) {
    out += ind + "edges in clockwise order" + (t.clockwise ? "" : " (v1 and v2 swapped)") + "  " +
           cite({rules::kTriOrientNormalise}) +
           (d.culled ? ", for information only (the triangle is culled)" : "") + ":\n";
    for (std::size_t i = 0; i < 3; ++i)
      out += edge_text(d.edges[i], i, s, ind);
  }
  out += ind + "verdict: " + std::string(d.covered ? "covered" : "not covered") + "\n";
  out += ind + "decided by:\n";
  for (const std::string& line : decided_by(d, s.state))
    out += ind + "  " + line + "\n";
  if (d.culled) {
    out += ind + std::string("  (without culling the centre would be ") +
           (d.inside_all_edges ? "inside" : "outside") + ")\n";
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

// The text of one aliased or antialiased line segment at the pixel.
std::string segment_text(const LineSegmentDecision& g, bool aa, const PreparedScene& s) {
  std::string out = "  segment " + std::to_string(g.seg) + ": " + point_px(g.a) + " -> " +
                    point_px(g.b) + ", " + (g.x_major ? "x-major" : "y-major") + "\n";
  if (aa) {
    out += "    coverage = " + fraction_q16(g.coverage_q16) + " (" +
           std::to_string(g.coverage_q16) +
           "/65536): mean over the squares R0..R4 (widths 1, 1.5, 2, 2.5, 3) of area(line "
           "rectangle & Ri) / area(Ri)  " +
           cite({rules::kSceneOutputCoverage}) + "\n";
  } else {
    if (s.conventions.line_mode == LineMode::kD3DDiamond) {
      out += std::string("    test area: the diamond's interior, its lower-left and "
                         "lower-right edges and bottom corner") +
             (g.x_major ? "" : ", and (y-major) its right corner") +
             "; not the upper edges nor the other corners  " + cite({rules::kLineD3DTestArea}) +
             "\n";
    } else {
      out += "    test area: the open diamond; both endpoints shifted by (-e, -e^2)  " +
             cite({rules::kLineVkTestArea}) + "\n";
    }
    const LineDiamondDecision& d = g.diamond;
    if (d.zero_length)
      out += "    zero-length line  " + cite({rules::kLineZeroLength}) + "\n";
    out += "    the segment meets: " + features_text(d.met_features) + "\n";
    out += "    of which in the test area: " + features_text(d.met_features & d.included_features) +
           "\n";
    out += std::string("    enters the test area: ") + (d.entered ? "yes" : "no") +
           "; ends inside it: " + (d.end_inside ? "yes" : "no") + "\n";
    out += "    reason: " + std::string(d.reason) + "\n";
  }
  out += std::string("    verdict: ") +
         (g.covered ? (aa ? "fragment (coverage > 0)" : "covered: the segment exits the diamond")
                    : (aa ? "no fragment (coverage 0)"
                          : "not covered: the segment does not exit the diamond")) +
         "\n";
  return out;
}

// The text of a point, a line or a line strip.
std::string other_text(const Report& r, const PreparedScene& s, Vec2 sample) {
  std::string out = "\nprimitive " + std::to_string(r.index) + ": " +
                    std::string(to_string(r.type)) + (r.aa ? " (antialiased)" : "") + "\n";
  out += vertices_text(r.input, r.snapped, "  ");
  const PixelDecision& d = r.d;
  if (r.type == PrimitiveType::kPoint) {
    // rule: SCENE.PRIM.POINT
    out += "  a 1x1 square centred on v0, drawn as two triangles (Z pattern) under the triangle "
           "rules, never culled  " +
           cite({rules::kScenePrimPoint}) + "\n";
    for (std::size_t k = 0; k < d.triangles.size(); ++k) {
      out += "  triangle " + std::to_string(k) + " of the point:\n";
      out += triangle_text(d.triangles[k], r.input, s, "    ", false);
    }
  } else if (!d.triangles.empty()) {
    out += "  quadrilateral line (line_mode " +
           std::string(io::line_mode_name(s.conventions.line_mode)) +
           "): a rectangle of two triangles per segment under the triangle rules, never culled  " +
           cite({rules::kSceneLineMode}) + "\n";
    for (std::size_t k = 0; k < d.triangles.size(); ++k) {
      out += "  segment " + std::to_string(d.triangle_seg[k]) + ", triangle " +
             std::to_string(k % 2) + ":\n";
      out += triangle_text(d.triangles[k], r.input, s, "    ", false);
    }
  } else {
    if (!r.aa)
      out += "  pixel's diamond test area: " + diamond_text(sample) + "\n";
    for (const LineSegmentDecision& g : d.segments)
      out += segment_text(g, r.aa, s);
  }
  out += std::string("  verdict: ") + (r.covered ? "covered" : "not covered") + "\n";
  return out;
}

// rule: SCENE.PRIM.POINT, SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP, SCENE.LINE_MODE
Report explain_primitive(const LoadedScene& loaded, std::size_t p, std::int32_t x, std::int32_t y,
                         Vec2 /*sample*/) {
  const PreparedScene& s = *loaded.prepared;
  const PreparedPrimitive& prim = s.primitives[p];
  Report r;
  r.index = p;
  r.type = prim.type;
  r.aa = prim.aa;
  r.input = loaded.scene.primitives[p];
  r.snapped = prim.v;
  r.d = decide_pixel(s, p, x, y);
  // A fragment exists when some sample in the mask is covered (MSAA.MASK.AND).
  r.show_samples = multisampled(s) && r.d.msaa.has_value();
  r.covered = r.show_samples ? r.d.covered : r.d.centre_covered;
  return r;
}

// "contour C segment S" or "contour C closing line" (PATH.CONTOUR.CLOSE).
std::string piece_text(const FloatPath& path, const path::SampleCrossing& c) {
  const bool closing =
      c.contour < path.contours.size() && c.segment >= path.contours[c.contour].segments.size();
  return "contour " + std::to_string(c.contour) +
         (closing ? " closing line" : " segment " + std::to_string(c.segment));
}

// A path primitive at the pixel: every sample's crossings, winding number and the fill rule's
// verdict, then the fragment (its mask, or its exact area and alpha). The kernel's decision
// record (decide_pixel) is formatted, nothing recomputed.
// rule: SCENE.PRIM.PATH, PATH.WINDING, PATH.SAMPLE.TIE, PATH.FILL.RULE, PATH.AREA.EXACT
std::string path_text(const Report& r, const PreparedScene& s) {
  const PathDecision& d = *r.d.path;
  const FloatPath& fp = *r.input.path;
  std::size_t segments = 0;
  for (const FloatContour& c : fp.contours)
    segments += c.segments.size();
  std::string out =
      "\nprimitive " + std::to_string(r.index) + ": path, " + std::string(to_string(d.fill_rule)) +
      ", " + std::to_string(fp.contours.size()) + " contour" +
      (fp.contours.size() == 1 ? "" : "s") + ", " + std::to_string(segments) + " segment" +
      (segments == 1 ? "" : "s") + ", coverage \"" + std::string(to_string(d.coverage)) + "\"  " +
      cite({rules::kScenePrimPath}) + "\n";
  const bool area = d.coverage == path::Coverage::kArea;
  for (const PathSampleDecision& sd : d.samples) {
    out += "  sample " + std::to_string(sd.index) + " at " + offset_text(sd.offset) + " -> " +
           point_px(sd.position) + " px = raw " + point_raw(sd.position) +
           (area ? " (for information)" : "") + "\n";
    std::string list;
    for (const path::SampleCrossing& c : sd.crossings)
      list +=
          (list.empty() ? "" : ", ") + piece_text(fp, c) + " (" + (c.dir > 0 ? "+1" : "-1") + ")";
    out += "    crossings of its ray to the right (displaced for fill " +
           std::string(to_string(s.state.fill)) +
           "): " + (list.empty() ? std::string("none") : list) + "  " +
           cite({rules::kPathWinding, rules::kPathSampleTie, rules::kPathContourClose}) + "\n";
    out += "    winding " + std::to_string(sd.winding) + ": " +
           std::string(to_string(d.fill_rule)) + (sd.fills ? " holds" : " does not hold") +
           (area       ? ""
            : sd.fills ? " -> covered"
                       : " -> not covered") +
           "  " + cite({rules::kPathFillRule}) + "\n";
  }
  if (area) {
    // The faces of the boundary's arrangement in the pixel, by winding number.
    out += "  the pixel by winding number (the faces of the boundary in it)  " +
           cite({rules::kPathWinding, rules::kPathAreaExact}) + "\n";
    for (const path::WindingArea& part : d.windings.parts) {
      const std::string exact = fraction_text(part.area);
      char approx[32];
      std::snprintf(approx, sizeof approx, "%.6g", part.area.convert_to<double>());
      out += "    winding " + std::to_string(part.winding) + ": " +
             (exact.size() <= 24 ? exact + " px^2 (about " + approx + ")"
                                 : std::string("about ") + approx + " px^2") +
             ", " + std::string(to_string(d.fill_rule)) +
             (part.fills ? " holds" : " does not hold") + "  " + cite({rules::kPathFillRule}) +
             "\n";
    }
    if (d.area) {
      const std::string bound = d.area.bound_text();
      out += "  area " + d.area.text() + " px^2 (about " + std::to_string(d.area.approx()) +
             (bound.empty() ? std::string()
                            : ", within " + bound + " px^2 of the exact area of the curves  " +
                                  cite({rules::kPathAreaCurve})) +
             "), alpha " + std::to_string(d.area.alpha()) + " -> fragment, mask " +
             mask_text(d.mask, s.msaa.count()) + "  " +
             cite({rules::kPathAreaExact, rules::kSceneOutputArea}) + "\n";
    } else {
      out += "  area 0 -> no fragment  " + cite({rules::kPathAreaExact}) + "\n";
    }
  } else {
    out += "  mask " + mask_text(d.mask, s.msaa.count()) +
           (d.mask != 0 ? " -> fragment" : " -> no fragment") + "  " + cite({rules::kSceneMsaa}) +
           "\n";
  }
  return out;
}

// The per-sample lines of one sample of a multisampled primitive.
// rule: MSAA.SAMPLE.POSITION, MSAA.COVER.SAMPLE
std::string sample_text(const SampleDecision& sd, const PreparedScene& s, bool several) {
  std::string out = "  sample " + std::to_string(sd.index) + " at " + offset_text(sd.offset) +
                    " -> " + point_px(sd.position) + " px = raw " + point_raw(sd.position) + "  " +
                    cite({rules::kMsaaSamplePosition}) + "\n";
  for (std::size_t t = 0; t < sd.triangles.size(); ++t) {
    const TriangleDecision& tr = sd.triangles[t];
    const std::string ind = several ? "      " : "    ";
    if (several)
      out += "    triangle " + std::to_string(t) + ":\n";
    if (!tr.has_edges) {
      out += ind + "degenerate: covers nothing  " + cite({tr.rule}) + "\n";
      continue;
    }
    for (std::size_t i = 0; i < 3; ++i) {
      const EdgeDecision& e = tr.edges[i];
      out += ind + "edge " + std::to_string(i) + " v" + std::to_string(e.from) + "->v" +
             std::to_string(e.to) + " (" + edge_kind(e) + "): E = " + std::to_string(e.e.raw()) +
             " raw = " + area_px2(e.e.raw()) + " px^2 -> " + (e.inside ? "inside" : "outside") +
             ": " + edge_reason(e, s.state.fill) + "\n";
    }
    if (tr.culled)
      out += ind + "culled: " + decided_by(tr, s.state).front() + "\n";
    out += ind + (tr.covered ? "covered" : "not covered") + "  " + cite({rules::kMsaaCoverSample}) +
           "\n";
  }
  return out;
}

// The mask lines of one segment of a multisampled primitive.
// rule: MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10
std::string segment_mask_text(const SegmentMaskDecision& g, const std::string& seg,
                              const PreparedScene& s, std::int32_t x, std::int32_t y) {
  const MultisampleState& ms = s.msaa;
  const std::uint32_t n = ms.count();
  std::string out =
      seg + "coverage " + mask_text(g.coverage, n) + "  " + cite({rules::kMsaaCoverSample}) + "\n";
  if (g.explained != g.coverage) {
    out += seg + "internal error: the samples above say " + mask_text(g.explained, n) + "\n";
  }
  out += seg + "sample mask " + mask_text(ms.effective_mask(), n) + " -> fragment mask " +
         mask_text(g.mask, n) + "  " + cite({rules::kMsaaMaskAnd}) + "\n";
  if (g.centroid) {
    const Centroid& c = *g.centroid;
    const Vec2 at = sample_position(x, y, c.offset);
    out += seg + "centroid (" + std::string(to_string(s.conventions.centroid)) +
           "): " + std::string(to_string(c.branch)) + " -> " + offset_text(c.offset) + " = " +
           point_px(at) + " px  " + cite({centroid_rule(s.conventions.centroid)}) +
           (g.mask == 0 ? " (no fragment: the pixel is covered by no sample in the mask)" : "") +
           "\n";
  }
  out += seg + "verdict: " +
         (g.mask != 0 ? "fragment, mask " + std::to_string(g.mask) : std::string("no fragment")) +
         "\n";
  return out;
}

// The text of one primitive of a multisampled scene: each sample of the pixel.
// rule: MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10
std::string msaa_text(const Report& r, const PreparedScene& s, std::int32_t x, std::int32_t y) {
  const MsaaDecision& m = *r.d.msaa;
  const MultisampleState& ms = s.msaa;
  const std::uint32_t n = ms.count();
  std::string out = "\nprimitive " + std::to_string(r.index) + ": " +
                    std::string(to_string(r.type)) + (r.aa ? " (antialiased)" : "") + "\n";
  out += vertices_text(r.input, r.snapped, "  ");
  const bool several = m.samples.empty() ? false : m.samples[0].triangles.size() > 1;
  if (!m.samples.empty()) {
    for (std::size_t t = 0; t < r.d.triangles.size(); ++t) {
      const TriangleSetup& setup = r.d.triangles[t].setup;
      std::string name = several
                             ? "  triangle " + std::to_string(t) +
                                   (r.type == PrimitiveType::kPoint
                                        ? " of the point"
                                        : " (segment " + std::to_string(r.d.triangle_seg[t]) + ")")
                             : std::string("  triangle");
      out += name + ": twice signed area A = " + std::to_string(setup.twice_area) + " raw, " +
             (setup.twice_area == 0
                  ? std::string("degenerate")
                  : std::string(setup.clockwise ? "clockwise" : "counter-clockwise")) +
             ", status " + std::string(to_string(setup.status)) + "  " +
             cite({rules::kTriOrientArea, rules::kTriCullMode}) + "\n";
    }
  }
  out += "  " + std::to_string(n) + " sample" + (n == 1 ? "" : "s") + ", " +
         std::string(to_string(ms.pattern.kind)) + " pattern  " + cite({m.pattern_rule}) + "\n";
  if (m.whole_pixel) {
    const bool d3d = s.conventions.line_mode == LineMode::kD3DDiamond && n > 1;
    out += "  a " + std::string(io::line_mode_name(s.conventions.line_mode)) + " line" +
           (d3d ? " without MultisampleEnable" : "") +
           " covers every sample of each pixel it produces  " + cite({rules::kMsaaLineMode}) + "\n";
    for (const LineSegmentDecision& g : r.d.segments) {
      out += "  segment " + std::to_string(g.seg) + ": " +
             (g.covered ? "produces the pixel" : "does not produce the pixel") + "\n";
    }
  }
  for (const SampleDecision& sd : m.samples)
    out += sample_text(sd, s, several);
  for (const SegmentMaskDecision& g : m.segments) {
    const std::string seg = m.segments.size() > 1 || r.type == PrimitiveType::kLineStrip
                                ? "  segment " + std::to_string(g.seg) + ": "
                                : "  ";
    out += segment_mask_text(g, seg, s, x, y);
  }
  if (m.segments.empty())
    out += "  verdict: no fragment\n";
  return out;
}

std::string text_report(const LoadedScene& loaded, std::int32_t x, std::int32_t y, Vec2 sample,
                        const std::vector<Report>& reports) {
  const PreparedScene& s = *loaded.prepared;
  std::string out;
  out += "scene: " + std::to_string(s.width) + "x" + std::to_string(s.height) + " target, cull " +
         std::string(to_string(s.state.cull)) + ", front face " +
         std::string(to_string(s.state.front_face)) + ", fill " +
         std::string(to_string(s.state.fill)) +
         (s.conventions.line_mode != LineMode::kD3DDiamond
              ? ", line_mode " + std::string(io::line_mode_name(s.conventions.line_mode))
              : std::string()) +
         ", " + std::to_string(reports.size()) + " primitive" + (reports.size() == 1 ? "" : "s") +
         "\n";
  out += "pixel (" + std::to_string(x) + ", " + std::to_string(y) + "): centre " +
         point_px(sample) + " px = raw " + point_raw(sample) + "  " +
         cite({rules::kCoordPixelCenter}) + "\n";
  if (multisampled(s)) {
    const MultisampleState& ms = s.msaa;
    out +=
        "multisampling: " + std::to_string(ms.count()) + " samples, " +
        std::string(to_string(ms.pattern.kind)) + " pattern, sample mask " +
        mask_text(ms.effective_mask(), ms.count()) + ", centroid " +
        (ms.has_centroid ? std::string(to_string(s.conventions.centroid)) : std::string("none")) +
        ", shading " + std::string(to_string(ms.shading)) + "  " + cite({rules::kSceneMsaa}) + "\n";
  }
  std::vector<std::size_t> covering;
  for (const Report& report : reports) {
    if (report.d.path) {
      out += path_text(report, s);
    } else if (report.show_samples) {
      out += msaa_text(report, s, x, y);
    } else if (report.type != PrimitiveType::kTriangle) {
      out += other_text(report, s, sample);
    } else {
      out += "\nprimitive " + std::to_string(report.index) + ": triangle\n";
      out += triangle_text(report.d.triangles[0], report.input, s, "  ");
    }
    if (report.covered)
      covering.push_back(report.index);
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
  return out;
}

using ojson = nlohmann::ordered_json;

ojson point_json(Vec2 v) {
  return ojson::array({v.x.raw(), v.y.raw()});
}

// The primitive's vertices as given, each an array of two float texts.
ojson input_json(const Primitive& input) {
  ojson in = ojson::array();
  for (const auto& v : input.v)
    in.push_back({io::format_float(v[0]), io::format_float(v[1])});
  return in;
}

// Snapped vertices, each an array of two raw values.
ojson points_json(std::span<const Vec2> points) {
  ojson out = ojson::array();
  for (const Vec2& v : points)
    out.push_back(point_json(v));
  return out;
}

ojson triangle_json(std::size_t index, const Primitive& input, const TriangleDecision& d,
                    const RasterState& state) {
  using json = ojson;
  auto point = point_json;
  const TriangleSetup& t = d.setup;
  json p;
  p["prim"] = index;
  p["input"] = input_json(input);
  p["snapped_raw"] = points_json(t.snapped);
  p["twice_area_raw"] = t.twice_area;
  p["winding"] = t.twice_area == 0 ? "degenerate" : (t.clockwise ? "cw" : "ccw");
  p["front_facing"] = t.front_facing;
  p["status"] = to_string(t.status);
  json edges = json::array();
  if (d.has_edges) {
    for (const EdgeDecision& e : d.edges) {
      edges.push_back({{"from", e.from},
                       {"to", e.to},
                       {"a_raw", point(e.a)},
                       {"b_raw", point(e.b)},
                       {"e_raw", e.e.raw()},
                       {"kind", edge_kind(e)},
                       {"top", e.top},
                       {"left", e.left},
                       {"inclusive", e.inclusive},
                       {"inside", e.inside},
                       {"decision", edge_reason(e, state.fill)}});
    }
  }
  p["edges"] = edges;
  p["edges_informative_only"] = d.culled;
  p["covered"] = d.covered;
  p["decided_by"] = decided_by(d, state);
  return p;
}

ojson other_json(const Report& r, const PreparedScene& s) {
  using json = ojson;
  json p;
  p["prim"] = r.index;
  p["type"] = to_string(r.type);
  if (r.aa)
    p["aa"] = true;
  p["input"] = input_json(r.input);
  p["snapped_raw"] = points_json(r.snapped);
  if (!r.d.triangles.empty()) {
    json tris = json::array();
    for (std::size_t k = 0; k < r.d.triangles.size(); ++k) {
      json t = triangle_json(r.index, r.input, r.d.triangles[k], s.state);
      t.erase("input");
      if (r.type != PrimitiveType::kPoint)
        t["seg"] = r.d.triangle_seg[k];
      tris.push_back(t);
    }
    p["triangles"] = tris;
  } else {
    json segs = json::array();
    for (const LineSegmentDecision& g : r.d.segments) {
      json j = {{"seg", g.seg},
                {"a_raw", point_json(g.a)},
                {"b_raw", point_json(g.b)},
                {"x_major", g.x_major},
                {"covered", g.covered}};
      if (r.aa) {
        j["coverage_q16"] = g.coverage_q16;
        j["coverage"] = fraction_q16(g.coverage_q16);
      } else {
        j["met"] = features_text(g.diamond.met_features);
        j["met_in_test_area"] = features_text(g.diamond.met_features & g.diamond.included_features);
        j["entered"] = g.diamond.entered;
        j["end_inside"] = g.diamond.end_inside;
        j["reason"] = g.diamond.reason;
      }
      segs.push_back(j);
    }
    p["segments"] = segs;
  }
  p["covered"] = r.covered;
  return p;
}

// rule: SCENE.PRIM.PATH, PATH.WINDING, PATH.FILL.RULE, PATH.AREA.EXACT
ojson path_json(const Report& r) {
  using json = ojson;
  const PathDecision& d = *r.d.path;
  json p;
  p["prim"] = r.index;
  p["type"] = "path";
  p["fill_rule"] = to_string(d.fill_rule);
  p["coverage"] = to_string(d.coverage);
  json samples = json::array();
  for (const PathSampleDecision& sd : d.samples) {
    json crossings = json::array();
    for (const path::SampleCrossing& c : sd.crossings)
      crossings.push_back({{"contour", c.contour}, {"segment", c.segment}, {"dir", c.dir}});
    samples.push_back({{"sample", sd.index},
                       {"offset", {sd.offset.x, sd.offset.y}},
                       {"position_raw", point_json(sd.position)},
                       {"crossings", crossings},
                       {"winding", sd.winding},
                       {"fills", sd.fills}});
  }
  p["samples"] = samples;
  p["mask"] = d.mask;
  if (d.coverage == path::Coverage::kArea) {
    p["area"] = d.area ? d.area.text() : "0";
    json parts = json::array();
    for (const path::WindingArea& part : d.windings.parts)
      parts.push_back(
          {{"winding", part.winding}, {"area", fraction_text(part.area)}, {"fills", part.fills}});
    p["windings"] = parts;
    if (d.area && !d.area.bound_text().empty())
      p["area_bound"] = d.area.bound_text(); // rule: PATH.AREA.CURVE
    p["alpha"] = d.area.alpha();
  }
  p["covered"] = r.covered;
  return p;
}

// rule: MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10
ojson msaa_json(const Report& r, const PreparedScene& s) {
  using json = ojson;
  const MsaaDecision& m = *r.d.msaa;
  json samples = json::array();
  for (const SampleDecision& sd : m.samples) {
    json tris = json::array();
    bool covered = false;
    for (const TriangleDecision& tr : sd.triangles) {
      json edges = json::array();
      if (tr.has_edges) {
        for (const EdgeDecision& e : tr.edges) {
          edges.push_back({{"from", e.from},
                           {"to", e.to},
                           {"kind", edge_kind(e)},
                           {"e_raw", e.e.raw()},
                           {"inclusive", e.inclusive},
                           {"inside", e.inside},
                           {"decision", edge_reason(e, s.state.fill)}});
        }
      }
      tris.push_back(
          {{"status", to_string(tr.setup.status)}, {"edges", edges}, {"covered", tr.covered}});
      covered = covered || tr.covered;
    }
    samples.push_back({{"sample", sd.index},
                       {"offset", {sd.offset.x, sd.offset.y}},
                       {"position_raw", point_json(sd.position)},
                       {"triangles", tris},
                       {"covered", covered}});
  }
  json segs = json::array();
  for (const SegmentMaskDecision& g : m.segments) {
    json j = {{"seg", g.seg},
              {"coverage", g.coverage},
              {"sample_mask", s.msaa.effective_mask()},
              {"mask", g.mask},
              {"fragment", g.mask != 0}};
    if (g.centroid) {
      j["centroid"] = {{"rule", to_string(s.conventions.centroid)},
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

std::string json_report(const LoadedScene& loaded, std::int32_t x, std::int32_t y, Vec2 sample,
                        const std::vector<Report>& reports) {
  using json = ojson;
  const PreparedScene& s = *loaded.prepared;
  auto point = point_json;
  json doc;
  doc["target"] = {{"width", s.width}, {"height", s.height}};
  doc["cull"] = to_string(s.state.cull);
  doc["front_face"] = to_string(s.state.front_face);
  doc["fill"] = to_string(s.state.fill);
  doc["line_mode"] = io::line_mode_name(s.conventions.line_mode);
  doc["pixel"] = {x, y};
  doc["sample_raw"] = point(sample);
  json prims = json::array();
  json covering = json::array();
  if (multisampled(s)) {
    doc["samples"] = s.msaa.count();
    doc["sample_pattern"] = to_string(s.msaa.pattern.kind);
    doc["sample_mask"] = s.msaa.effective_mask();
    if (s.msaa.has_centroid)
      doc["centroid"] = to_string(s.conventions.centroid);
  }
  for (const Report& r : reports) {
    ojson p = r.d.path ? path_json(r)
              : r.type == PrimitiveType::kTriangle
                  ? triangle_json(r.index, r.input, r.d.triangles[0], s.state)
                  : other_json(r, s);
    if (r.show_samples) {
      p["covered"] = r.covered;
      p["msaa"] = msaa_json(r, s);
    }
    prims.push_back(p);
    if (r.covered)
      covering.push_back(r.index);
  }
  doc["primitives"] = prims;
  doc["covered_by"] = covering;
  return doc.dump(2) + "\n";
}

// rule: SCENE.OUTPUT.PIPELINE
// A pipeline scene at one pixel: the fragments run_pipeline produced there, with what each
// carries and the drawn primitive (after clipping, divide, viewport, snapping and depth bias)
// it was interpolated from. Coverage itself is the kernel's; no edge values are shown.
std::variant<std::string, SceneError> pipeline_report(const Scene& scene,
                                                      const pipe::PipeResult& result,
                                                      std::int32_t x, std::int32_t y,
                                                      bool as_json) {
  const bool has_data = !result.data.empty();
  if (has_data && result.data.size() != result.fragments.size()) {
    return SceneError{"",
                      "internal error: run_pipeline's fragment data do not match its fragments"};
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
      return SceneError{"", "internal error: run_pipeline's fragments do not match the scene"};
    ojson doc;
    doc["target"] = {{"width", scene.width}, {"height", scene.height}};
    doc["pixel"] = {x, y};
    doc["pipeline"] = true;
    doc["samples"] = n;
    if (scene.depth) {
      doc["depth"] = {{"format", io::depth_format_name(scene.conventions.depth)},
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
    return doc.dump(2) + "\n";
  }
  std::string out = "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") of a " +
                    std::to_string(scene.width) + "x" + std::to_string(scene.height) +
                    " pipeline scene (" + id(rules::kScenePipeline) +
                    "): " + std::to_string(here.size()) +
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
      out += std::string("  barycentrics (") +
             id(triangle ? rules::kPipeBaryExact : rules::kPipeBaryLine) + "): e = [" +
             std::to_string(b.e[0]) + ", " + std::to_string(b.e[1]) + ", " +
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
        depths += (depths.empty() ? "" : ", ") + io::depth_text(d, scene.conventions.depth);
      }
      out += killed
                 ? "  killed: no sample passed the depth test (" + id(rules::kPipeDepthKill) + ")"
                 : "  depth [" + depths + "] (" +
                       std::string(io::depth_format_name(scene.conventions.depth)) + "), passed " +
                       mask_text(data->passed, n);
      out += " (depth.func " + std::string(io::compare_func_name(scene.depth->func)) + ", " +
             id(rules::kPipeDepthTest) + ")\n";
    }
  }
  std::string list;
  for (const std::uint32_t p : covering)
    list += (list.empty() ? "" : ", ") + std::to_string(p);
  out += "covered by: " + (list.empty() ? std::string("nothing") : "primitives " + list) +
         (scene.depth ? " (samples that passed the depth test)\n" : "\n");
  return out;
}

} // namespace

std::string explain_window_pixel(const Scene& scene, const PreparedScene& prepared, std::int32_t x,
                                 std::int32_t y, bool as_json) {
  const LoadedScene loaded{scene, &prepared};
  const Vec2 sample = pixel_center(x, y);
  std::vector<Report> reports;
  reports.reserve(prepared.primitives.size());
  for (std::size_t p = 0; p < prepared.primitives.size(); ++p)
    reports.push_back(explain_primitive(loaded, p, x, y, sample));
  return as_json ? json_report(loaded, x, y, sample, reports)
                 : text_report(loaded, x, y, sample, reports);
}

std::variant<std::string, SceneError> explain_pipeline_pixel(const Scene& scene,
                                                             const pipe::PipeResult& result,
                                                             std::int32_t x, std::int32_t y,
                                                             bool as_json) {
  return pipeline_report(scene, result, x, y, as_json);
}

std::string fixed_decimal(std::int64_t raw, int frac_bits) {
  const bool negative = raw < 0;
  const std::uint64_t mag =
      negative ? 0 - static_cast<std::uint64_t>(raw) : static_cast<std::uint64_t>(raw);
  const std::uint64_t whole = mag >> frac_bits;
  const std::uint64_t frac = mag & ((std::uint64_t{1} << frac_bits) - 1);
  std::string s = (negative ? "-" : "") + std::to_string(whole);
  if (frac == 0)
    return s;
  // frac / 2^k = frac * 5^k / 10^k; frac < 2^16 and 5^16 < 2^38, so no overflow.
  std::uint64_t pow5 = 1;
  for (int i = 0; i < frac_bits; ++i)
    pow5 *= 5;
  std::string digits = std::to_string(frac * pow5);
  digits.insert(0, static_cast<std::size_t>(frac_bits) - digits.size(), '0');
  while (!digits.empty() && digits.back() == '0')
    digits.pop_back();
  return s + "." + digits;
}

} // namespace rastrules::io
