// SPDX-License-Identifier: MIT
// rastrules explain: the reasons given for one pixel centre, in text and in JSON.

#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support.hpp"

namespace {

using rastrules::test::explain_pixel;
using rastrules::test::run_cli;
using rastrules::test::TempDir;

// The square [1, 3]^2 split along x = y; the centre (1.5, 1.5) of pixel (1, 1) lies on the
// diagonal, a left edge of primitive 0 and a right edge of primitive 1.
constexpr const char* kSplit = R"({"target": {"width": 4, "height": 4}, "primitives": [
  {"type": "triangle", "v": [[1, 1], [3, 1], [3, 3]]},
  {"type": "triangle", "v": [[1, 1], [3, 3], [1, 3]]}]})";

bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

// rule: TRI.FILL.TOP_LEFT, TRI.FILL.LEFT_EDGE, TRI.EDGE.FUNCTION
TEST(CliExplain, NamesTheTopLeftRuleForACentreOnASharedDiagonal) {
  const auto r = explain_pixel("1,1", kSplit);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string& out = r.out;
  EXPECT_TRUE(contains(out, "pixel (1, 1): centre (1.5, 1.5) px = raw (384, 384)")) << out;
  // Primitive 0, edge 0 (1,1)->(3,1): E = 512 * 128 = 65536 = 1 px^2; edge 1: 3 px^2; edge 2 on
  // the diagonal: E = 0, a left edge.
  EXPECT_TRUE(contains(out, "E at the centre = 65536 raw = 1 px^2")) << out;
  EXPECT_TRUE(contains(out, "E at the centre = 196608 raw = 3 px^2")) << out;
  EXPECT_TRUE(contains(out, "TRI.FILL.TOP_LEFT: E == 0 on a left edge -> inside")) << out;
  EXPECT_TRUE(
      contains(out, "TRI.FILL.TOP_LEFT: E == 0 on a right edge (neither top nor left) -> outside"))
      << out;
  EXPECT_TRUE(contains(out, "TRI.COVER.SAMPLE: inside all three edges -> covered")) << out;
  EXPECT_TRUE(contains(out, "v0 (1, 1) -> (1, 1) px = raw (256, 256)")) << out;
  EXPECT_TRUE(contains(out, "twice signed area A = 262144 raw = 4 px^2: clockwise, front-facing"))
      << out;
  EXPECT_TRUE(contains(out, "pixel (1, 1): covered by primitive 0\n")) << out;
}

// rule: TRI.FILL.TOP_LEFT, TRI.FILL.TOP_EDGE
TEST(CliExplain, VertexOnTheCentreIsInsideOnlyWhenBothEdgesAreTopOrLeft) {
  // The top-left corner (1.5, 1.5) of [1.5, 3.5]^2 split along its anti-diagonal: primitive 0
  // has a top and a left edge there; the centre (3.5, 1.5) of pixel (3, 1), its top-right
  // vertex, lies on a top edge and a right edge.
  const std::string scene = R"({"target": {"width": 5, "height": 5}, "primitives": [
    {"type": "triangle", "v": [[1.5, 1.5], [3.5, 1.5], [1.5, 3.5]]}]})";
  const auto a = explain_pixel("1,1", scene);
  ASSERT_EQ(a.status, 0) << a.err;
  EXPECT_TRUE(contains(a.out, "TRI.FILL.TOP_LEFT: E == 0 on a top edge -> inside")) << a.out;
  EXPECT_TRUE(contains(a.out, "the centre is a vertex (on two edges)")) << a.out;
  EXPECT_TRUE(contains(a.out, "covered by primitive 0")) << a.out;
  const auto b = explain_pixel("3,1", scene);
  ASSERT_EQ(b.status, 0) << b.err;
  EXPECT_TRUE(contains(
      b.out, "TRI.FILL.TOP_LEFT: E == 0 on a right edge (neither top nor left) -> outside"))
      << b.out;
  EXPECT_TRUE(contains(b.out, "covered by no primitive")) << b.out;
}

// rule: TRI.FILL.CONVENTION
TEST(CliExplain, OtherFillConventionsAreNamed) {
  const auto r = explain_pixel("1,1", R"({"target": {"width": 4, "height": 4}, "fill": "top-right",
    "primitives": [{"type": "triangle", "v": [[1, 1], [3, 1], [3, 3]]}]})");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(
      r.out,
      "TRI.FILL.CONVENTION: E == 0 on a left edge, not inclusive under top-right -> outside"))
      << r.out;
  EXPECT_TRUE(contains(r.out, "covered by no primitive")) << r.out;
}

// rule: TRI.CULL.MODE, SNAP.CULL.AFTER_SNAP, TRI.DEGENERATE.ZERO_AREA
TEST(CliExplain, CulledAndDegenerateTrianglesSayWhy) {
  // Primitive 0 is counter-clockwise (back-facing, culled); primitive 1 has a non-zero area
  // as floats but collinear snapped vertices (y = 1.001 and 1.0019 both snap to raw 256).
  const auto r = explain_pixel("0,0", R"({"target": {"width": 4, "height": 4}, "cull": "back",
    "primitives": [
      {"type": "triangle", "v": [[0, 0], [0, 4], [4, 0]]},
      {"type": "triangle", "v": [[0, 1], [2, 1.001], [4, 1.0019]]}]})");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "TRI.CULL.MODE: back-facing (counter-clockwise on screen, front face "
                              "cw) and cull back -> culled"))
      << r.out;
  EXPECT_TRUE(contains(r.out, "(without culling the centre would be inside)")) << r.out;
  EXPECT_TRUE(contains(r.out, "TRI.DEGENERATE.ZERO_AREA: A == 0 after snapping -> covers nothing"))
      << r.out;
  EXPECT_TRUE(contains(r.out, "covered by no primitive")) << r.out;
}

// rule: SCENE.NUMBER.FLOAT32, SNAP.VERTEX.ROUND
TEST(CliExplain, ShowsTheFloat32InputAndItsSnappedValue) {
  // 16384 + 1/256 + 1/1024 + 1e-20 becomes the float32 16384 + 3/512 (raw 4194305.5), which
  // snaps to the even 4194306; a detour through double would give 4194305.
  const auto r = explain_pixel("0,0", R"({"target": {"width": 2, "height": 2}, "primitives": [
    {"type": "triangle", "v": [[16384.00488281250000000001, 0], [0, 0], [0, 1]]}]})");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "v0 (16384.006, 0) -> (16384.0078125, 0) px = raw (4194306, 0)"))
      << r.out;
}

TEST(CliExplain, JsonOutputCarriesTheSameDecisions) {
  const TempDir dir;
  const auto scene = dir.write("scene.json", kSplit);
  const auto r = run_cli({"explain", scene.string(), "--pixel=1,1", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["pixel"], nlohmann::json::array({1, 1}));
  EXPECT_EQ(doc["covered_by"], nlohmann::json::array({0}));
  const auto& p0 = doc["primitives"][0];
  EXPECT_EQ(p0["twice_area_raw"], 262144);
  ASSERT_EQ(p0["edges"].size(), 3u);
  EXPECT_EQ(p0["edges"][0]["e_raw"], 65536);
  EXPECT_EQ(p0["edges"][2]["e_raw"], 0);
  EXPECT_EQ(p0["edges"][2]["kind"], "left");
  EXPECT_EQ(p0["edges"][2]["inclusive"], true);
  EXPECT_EQ(doc["primitives"][1]["covered"], false);
  EXPECT_EQ(doc["primitives"][1]["edges"][0]["kind"], "right");
}

// rule: SCENE.INPUT.ERRORS
TEST(CliExplain, PixelOutsideTheTargetIsBadInput) {
  const auto r = explain_pixel("4,0", kSplit);
  EXPECT_EQ(r.status, 2);
  ASSERT_EQ(r.err_lines().size(), 1u) << r.err;
  EXPECT_TRUE(contains(r.err, "rastrules: error: --pixel: (4, 0) is outside the 4x4 target"))
      << r.err;
  EXPECT_EQ(r.out, "");
}

// rule: SCENE.INPUT.ERRORS
TEST(CliExplain, MalformedPixelIsAUsageError) {
  const TempDir dir;
  const auto scene = dir.write("scene.json", kSplit);
  for (const char* bad : {"1", "1,", "a,b", "-1,0", "1,2,3", "1.5,2"}) {
    const auto r = run_cli({"explain", scene.string(), "--pixel", bad});
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_TRUE(contains(r.err, "--pixel")) << bad << ": " << r.err;
    EXPECT_EQ(r.out, "") << bad;
  }
}

// One sample whose coverage is not the centre's is explained per sample, as the kernel decides
// it (before, explain judged the centre and could contradict render).
// rule: MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.PATTERN.CUSTOM
TEST(CliExplain, ASingleSampleAwayFromTheCentreOrMaskedAwayIsExplainedPerSample) {
  const TempDir dir;
  constexpr const char* kTriangle = R"("primitives": [
    {"type": "triangle", "v": [[0, 0], [4, 0], [0, 4]]}]})";
  // One custom sample at the pixel's top-left corner, (-8, -8)/16: pixel (2, 1) is decided at
  // (2, 1), inside, though its centre (2.5, 1.5) lies on the right edge x + y = 4.
  const auto custom = dir.write(
      "custom.json",
      std::string(R"({"target": {"width": 4, "height": 4}, "sample_pattern": [[-8, -8]], )") +
          kTriangle);
  const auto a = run_cli({"explain", custom.string(), "--pixel", "2,1"});
  ASSERT_EQ(a.status, 0) << a.err;
  EXPECT_TRUE(contains(a.out, "sample 0 at (-8, -8)/16 -> (2, 1) px")) << a.out;
  EXPECT_TRUE(contains(a.out, "pixel (2, 1): covered by primitive 0\n")) << a.out;
  const auto r = run_cli({"render", custom.string(), "--fragments", "-"});
  EXPECT_TRUE(contains(r.out, R"({"prim": 0, "x": 2, "y": 1, "mask": 1})")) << r.out;
  // A sample mask of 0 removes the only sample: no fragment, though the centre is covered.
  const auto masked = dir.write(
      "masked.json",
      std::string(R"({"target": {"width": 4, "height": 4}, "sample_mask": 0, )") + kTriangle);
  const auto b = run_cli({"explain", masked.string(), "--pixel", "0,0"});
  ASSERT_EQ(b.status, 0) << b.err;
  EXPECT_TRUE(contains(b.out, "sample mask 0b0 (no sample) -> fragment mask 0b0 (no sample)"))
      << b.out;
  EXPECT_TRUE(contains(b.out, "pixel (0, 0): covered by no primitive\n")) << b.out;
}

} // namespace

namespace {

// Two evenodd triangles, one inside the other: pixel (2, 2) has winding 2 at its centre (a
// hole under evenodd), and the area path's pixel there carries its exact area.
constexpr const char* kNested = R"({"target": {"width": 8, "height": 6}, "primitives": [
  {"type": "path", "fill_rule": "evenodd", "d": "M 1 1 L 7 1 L 4 5 Z M 2 2 L 6 2 L 4 4.5 Z"},
  {"type": "path", "coverage": "area", "fill_rule": "evenodd",
   "d": "M 1 1 L 7 1 L 4 5 Z M 2 2 L 6 2 L 4 4.5 Z"}]})";

// rule: SCENE.PRIM.PATH, PATH.WINDING, PATH.FILL.RULE, PATH.AREA.EXACT
TEST(CliExplainPath, NamesEveryCrossingTheWindingTheFacesAndTheExactArea) {
  const auto r = explain_pixel("3,3", kNested);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string& out = r.out;
  EXPECT_TRUE(contains(out, "primitive 0: path, evenodd, 2 contours, 4 segments, coverage "
                            "\"samples\"  [SCENE.PRIM.PATH]"))
      << out;
  // The centre (3.5, 3.5) is inside both triangles: the ray to the right crosses the right
  // side of each (segment 1 of each contour), both running down.
  EXPECT_TRUE(contains(out, "contour 0 segment 1 (+1), contour 1 segment 1 (+1)")) << out;
  EXPECT_TRUE(contains(out, "winding 2: evenodd does not hold -> not covered  [PATH.FILL.RULE]"))
      << out;
  EXPECT_TRUE(contains(out, "mask 0b0 (no sample) -> no fragment")) << out;
  EXPECT_TRUE(contains(out, "area 11/60 px^2")) << out;
  // The faces of the boundary in the pixel by winding number: the corner (3, 4) lies outside
  // both triangles, the rest inside one or both; only winding 1 fills under evenodd.
  EXPECT_TRUE(contains(out, "    winding 0: 1/24 px^2 (about 0.0416667), evenodd does not hold"))
      << out;
  EXPECT_TRUE(contains(out, "    winding 1: 11/60 px^2 (about 0.183333), evenodd holds")) << out;
  EXPECT_TRUE(contains(out, "    winding 2: 31/40 px^2 (about 0.775), evenodd does not hold"))
      << out;
  EXPECT_TRUE(contains(out, "alpha 47 -> fragment")) << out;
  EXPECT_TRUE(contains(out, "pixel (3, 3): covered by primitive 1\n")) << out;
  // The left side of the outer triangle is its closing line.
  const auto edge = explain_pixel("1,1", kNested);
  ASSERT_EQ(edge.status, 0) << edge.err;
  EXPECT_TRUE(contains(edge.out, "contour 0 segment 1 (+1)")) << edge.out;
}

// rule: SCENE.PRIM.PATH, PATH.WINDING
TEST(CliExplainPath, JsonCarriesTheCrossingsWindingsAndArea) {
  const TempDir dir;
  const auto r =
      run_cli({"explain", dir.write("scene.json", kNested).string(), "--pixel", "3,3", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  const auto& p0 = doc["primitives"][0];
  EXPECT_EQ(p0["type"], "path");
  EXPECT_EQ(p0["samples"][0]["winding"], 2);
  EXPECT_EQ(p0["samples"][0]["crossings"].size(), 2u);
  EXPECT_EQ(p0["covered"], false);
  const auto& p1 = doc["primitives"][1];
  EXPECT_EQ(p1["area"], "11/60");
  ASSERT_EQ(p1["windings"].size(), 3u);
  EXPECT_EQ(p1["windings"][1],
            nlohmann::json({{"winding", 1}, {"area", "11/60"}, {"fills", true}}));
  EXPECT_EQ(p1["windings"][2]["area"], "31/40");
  EXPECT_EQ(p1["alpha"], 47);
  EXPECT_EQ(doc["covered_by"], nlohmann::json::array({1}));
}

} // namespace
