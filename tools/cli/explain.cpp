// SPDX-License-Identifier: MIT
// rastrules explain: why each primitive covers, or does not cover, one pixel centre.
// Every number shown is computed by the kernel (snap, setup_triangle, EdgeSetup::value_at,
// covers); this file only reports them and names the rule that decided.

#include <array>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules::cli {
namespace {

struct EdgeReport {
  int from = 0, to = 0;  // vertex indices as given in the scene
  Vec2 a, b;
  std::int64_t e = 0;    // E at the sample, 1/65536 px^2
  bool top = false, left = false, horizontal = false, inclusive = false, inside = false;
  std::string kind;      // "top", "bottom", "left", "right"
  std::string decision;  // rule ID and reason
};

struct PrimitiveReport {
  std::size_t index = 0;
  Primitive input;
  TriangleSetup setup;
  bool has_edges = false;    // false for degenerate triangles
  bool culled = false;       // the edges are then shown for information only
  std::array<EdgeReport, 3> edges{};
  bool covered = false;
  bool inside_all_edges = false;
  std::vector<std::string> decided_by;
};

std::string px(Subpixel v) { return fixed_decimal(v.raw(), kSubpixelBits); }
std::string point_px(Vec2 v) { return "(" + px(v.x) + ", " + px(v.y) + ")"; }
std::string point_raw(Vec2 v) {
  return "(" + std::to_string(v.x.raw()) + ", " + std::to_string(v.y.raw()) + ")";
}
std::string area_px2(std::int64_t raw) { return fixed_decimal(raw, 2 * kSubpixelBits); }

std::string edge_decision(const EdgeReport& e, FillConvention fill) {
  if (e.e > 0) return "TRI.EDGE.FUNCTION: E > 0 -> inside";
  if (e.e < 0) return "TRI.EDGE.FUNCTION: E < 0 -> outside";
  const std::string verdict = e.inclusive ? "inside" : "outside";
  if (fill == FillConvention::kTopLeft) {
    return "TRI.FILL.TOP_LEFT: E == 0 on a " + e.kind + " edge" +
           (e.inclusive ? "" : " (neither top nor left)") + " -> " + verdict;
  }
  return "TRI.FILL.CONVENTION: E == 0 on a " + e.kind + " edge, " +
         (e.inclusive ? "inclusive" : "not inclusive") + " under " + std::string(to_string(fill)) +
         " -> " + verdict;
}

PrimitiveReport explain_primitive(std::size_t index, const Primitive& input,
                                  const TriangleSetup& setup, const RasterState& state, Vec2 sample) {
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
  const std::array<int, 3> order = setup.clockwise ? std::array<int, 3>{0, 1, 2}
                                                   : std::array<int, 3>{0, 2, 1};
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
    if (e.e == 0) ++on_edges;
    if (e.e == 0 || !e.inside) {
      r.decided_by.push_back("edge " + std::to_string(&e - r.edges.data()) + ": " + e.decision);
    }
  }
  if (on_edges == 2) {
    r.decided_by.push_back(std::string(state.fill == FillConvention::kTopLeft ? "TRI.FILL.TOP_LEFT"
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

void print_text(const LoadedScene& loaded, std::int32_t x, std::int32_t y, Vec2 sample,
                const std::vector<PrimitiveReport>& reports) {
  const PreparedScene& s = loaded.prepared;
  std::string out;
  out += "scene: " + std::to_string(s.width) + "x" + std::to_string(s.height) + " target, cull " +
         std::string(to_string(s.state.cull)) + ", front face " +
         std::string(to_string(s.state.front_face)) + ", fill " + std::string(to_string(s.state.fill)) +
         ", " + std::to_string(reports.size()) + " primitive" + (reports.size() == 1 ? "" : "s") + "\n";
  out += "pixel (" + std::to_string(x) + ", " + std::to_string(y) + "): centre " + point_px(sample) +
         " px = raw " + point_raw(sample) + "  [COORD.PIXEL.CENTER]\n";
  std::vector<std::size_t> covering;
  for (const PrimitiveReport& r : reports) {
    const TriangleSetup& t = r.setup;
    out += "\nprimitive " + std::to_string(r.index) + ": triangle\n";
    out += "  vertices, input float32 -> snapped 16.8  [SNAP.VERTEX.ROUND]:\n";
    for (std::size_t i = 0; i < 3; ++i) {
      out += "    v" + std::to_string(i) + " (" + io::format_float(r.input.v[i][0]) + ", " +
             io::format_float(r.input.v[i][1]) + ") -> " + point_px(t.snapped[i]) + " px = raw " +
             point_raw(t.snapped[i]) + "\n";
    }
    out += "  twice signed area A = " + std::to_string(t.twice_area) + " raw = " + area_px2(t.twice_area) +
           " px^2: " +
           (t.twice_area == 0 ? std::string("degenerate")
                              : std::string(t.clockwise ? "clockwise" : "counter-clockwise") +
                                    ", " + (t.front_facing ? "front-facing" : "back-facing")) +
           "  [TRI.ORIENT.AREA, TRI.CULL.MODE]\n";
    out += "  status: " + std::string(to_string(t.status)) + "\n";
    if (r.has_edges) {
      out += std::string("  edges in clockwise order") +
             (t.clockwise ? "" : " (v1 and v2 swapped)") + "  [TRI.ORIENT.NORMALISE]" +
             (r.culled ? ", for information only (the triangle is culled)" : "") + ":\n";
      for (std::size_t i = 0; i < 3; ++i) {
        const EdgeReport& e = r.edges[i];
        out += "    edge " + std::to_string(i) + ": v" + std::to_string(e.from) + " " + point_px(e.a) +
               " -> v" + std::to_string(e.to) + " " + point_px(e.b) + "\n";
        out += "      E at the centre = " + std::to_string(e.e) + " raw = " + area_px2(e.e) +
               " px^2  [TRI.EDGE.FUNCTION]\n";
        out += "      " + e.kind + " edge: top " + (e.top ? "yes" : "no") + ", left " +
               (e.left ? "yes" : "no") + ", inclusive under " + std::string(to_string(s.state.fill)) +
               " " + (e.inclusive ? "yes" : "no") + "  [TRI.FILL.TOP_EDGE, TRI.FILL.LEFT_EDGE]\n";
        out += "      " + std::string(e.inside ? "inside" : "outside") + ": " + e.decision + "\n";
      }
    }
    out += "  verdict: " + std::string(r.covered ? "covered" : "not covered") + "\n";
    out += "  decided by:\n";
    for (const std::string& d : r.decided_by) out += "    " + d + "\n";
    if (r.culled) {
      out += std::string("    (without culling the centre would be ") +
             (r.inside_all_edges ? "inside" : "outside") + ")\n";
    }
    if (r.covered) covering.push_back(r.index);
  }
  out += "\npixel (" + std::to_string(x) + ", " + std::to_string(y) + "): ";
  if (covering.empty()) {
    out += "covered by no primitive\n";
  } else {
    out += std::string("covered by primitive") + (covering.size() == 1 ? " " : "s ");
    for (std::size_t i = 0; i < covering.size(); ++i) out += (i ? ", " : "") + std::to_string(covering[i]);
    out += covering.size() > 1 ? " (overlap)\n" : "\n";
  }
  std::fputs(out.c_str(), stdout);
}

void print_json(const LoadedScene& loaded, std::int32_t x, std::int32_t y, Vec2 sample,
                const std::vector<PrimitiveReport>& reports) {
  using json = nlohmann::ordered_json;
  const PreparedScene& s = loaded.prepared;
  auto point = [](Vec2 v) { return json::array({v.x.raw(), v.y.raw()}); };
  json doc;
  doc["target"] = {{"width", s.width}, {"height", s.height}};
  doc["cull"] = to_string(s.state.cull);
  doc["front_face"] = to_string(s.state.front_face);
  doc["fill"] = to_string(s.state.fill);
  doc["pixel"] = {x, y};
  doc["sample_raw"] = point(sample);
  json prims = json::array();
  json covering = json::array();
  for (const PrimitiveReport& r : reports) {
    const TriangleSetup& t = r.setup;
    json p;
    p["prim"] = r.index;
    json in = json::array();
    for (const auto& v : r.input.v) in.push_back({io::format_float(v[0]), io::format_float(v[1])});
    p["input"] = in;
    json snapped = json::array();
    for (const Vec2& v : t.snapped) snapped.push_back(point(v));
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
    prims.push_back(p);
    if (r.covered) covering.push_back(r.index);
  }
  doc["primitives"] = prims;
  doc["covered_by"] = covering;
  std::fputs((doc.dump(2) + "\n").c_str(), stdout);
}

}  // namespace

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
  if (!scene_path) return usage_error("explain: missing SCENE.json");
  if (!pixel) return usage_error("explain: missing --pixel X,Y");
  const std::size_t comma = pixel->find(',');
  const auto px_x = comma == std::string::npos ? std::nullopt
                                                : parse_int(pixel->substr(0, comma), 0, kMaxTargetSide - 1);
  const auto px_y = comma == std::string::npos ? std::nullopt
                                                : parse_int(pixel->substr(comma + 1), 0, kMaxTargetSide - 1);
  if (!px_x || !px_y) {
    return usage_error("--pixel needs two integers X,Y in [0, " + std::to_string(kMaxTargetSide - 1) + "]");
  }

  const std::optional<LoadedScene> loaded = load_scene(*scene_path);
  if (!loaded) return kExitBadInput;
  const auto x = static_cast<std::int32_t>(*px_x);
  const auto y = static_cast<std::int32_t>(*px_y);
  // rule: SCENE.INPUT.ERRORS
  if (x >= loaded->prepared.width || y >= loaded->prepared.height) {
    return error("--pixel: (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                 std::to_string(loaded->prepared.width) + "x" + std::to_string(loaded->prepared.height) +
                 " target");
  }
  const Vec2 sample = pixel_center(x, y);
  std::vector<PrimitiveReport> reports;
  reports.reserve(loaded->prepared.triangles.size());
  for (std::size_t p = 0; p < loaded->prepared.triangles.size(); ++p) {
    reports.push_back(explain_primitive(p, loaded->scene.primitives[p], loaded->prepared.triangles[p],
                                        loaded->prepared.state, sample));
  }
  if (as_json) {
    print_json(*loaded, x, y, sample, reports);
  } else {
    print_text(*loaded, x, y, sample, reports);
  }
  return kExitOk;
}

}  // namespace rastrules::cli
