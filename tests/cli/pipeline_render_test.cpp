// SPDX-License-Identifier: MIT
// Pipeline scenes through the command line: `rastrules render` and `explain` route them to
// rastrules::pipe::run_pipeline and write the fields of SCENE.OUTPUT.PIPELINE, the depth buffer
// (--depth-out, --png-depth) and the resolved target; the other commands refuse them.
//
// Hand-checked values: d24 stores floor(z * 16777215 + 0.5): 0.5 -> 8388608, 0.25 -> 4194304,
// the clear value 1 -> 16777215; d16: 0.5 -> 32768, 1 -> 65535. On the window-space
// triangle (0, 0), (4, 0), (0, 4) an attribute with values (0, 4, 0) is the evaluation point's
// x: 0.5 at the centre of pixel (0, 0), 1.5 at pixel (1, 0).

#include <array>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support.hpp"

namespace {

using json = nlohmann::json;
using rastrules::test::read_file;
using rastrules::test::read_png;
using rastrules::test::run_cli;
using rastrules::test::TempDir;

// Renders the scene and returns the parsed fragment list (fails the test on any error).
json render(const std::string& scene, const std::vector<std::string>& extra = {}) {
  const TempDir dir;
  const auto path = dir.write("scene.json", scene);
  std::vector<std::string> args = {"render", path.string(), "--fragments", "-"};
  args.insert(args.end(), extra.begin(), extra.end());
  const auto r = run_cli(args);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  if (r.status != 0)
    return json::object({{"fragments", json::array()}});
  return json::parse(r.out);
}

// (x, y, mask) of each fragment.
std::vector<std::array<int, 3>> coverage(const json& doc) {
  std::vector<std::array<int, 3>> out;
  for (const json& f : doc["fragments"])
    out.push_back({f["x"].get<int>(), f["y"].get<int>(), f["mask"].get<int>()});
  return out;
}

constexpr const char* kWindowTriangle =
    R"({"target": {"width": 8, "height": 8}, "primitives": [{"type": "triangle", "v": [[1, 1], [6, 2], [2, 6]]}]})";
// The same triangle in clip space: x = 2 X / 8 - 1, y = 1 - 2 Y / 8, all exact in float32.
constexpr const char* kClipTriangle =
    R"({"target": {"width": 8, "height": 8}, "primitives": [{"type": "triangle",
        "pos": [[-0.75, 0.75, 0], [0.5, 0.5, 0], [-0.5, -0.5, 0, 1]]}]})";

// rule: SCENE.PIPELINE, SCENE.OUTPUT.PIPELINE, PIPE.CLIP.UNCLIPPED
TEST(CliPipeline, ClipSpaceTriangleCoversWhatItsWindowSpaceImageCovers) {
  const json window = render(kWindowTriangle);
  const json clip = render(kClipTriangle);
  ASSERT_FALSE(window["fragments"].empty());
  EXPECT_EQ(coverage(clip), coverage(window));
  // Neither depth nor attributes asked for: only the plain fields (no part: not clipped).
  for (const json& f : clip["fragments"]) {
    EXPECT_EQ(f.size(), 4u) << f.dump();
    EXPECT_FALSE(f.contains("bary") || f.contains("attr") || f.contains("depth") ||
                 f.contains("part"));
  }
  // The transform applies: a model matrix halving x and y of doubled positions.
  const json transformed = render(
      R"({"target": {"width": 8, "height": 8},
          "transform": {"model": [0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]},
          "primitives": [{"type": "triangle", "pos": [[-1.5, 1.5, 0], [1, 1, 0], [-1, -1, 0]]}]})");
  EXPECT_EQ(coverage(transformed), coverage(window));
  // Window-space vertices with z and w are a pipeline scene with the same coverage.
  const json zw = render(
      R"({"target": {"width": 8, "height": 8}, "primitives": [{"type": "triangle",
          "v": [[1, 1], [6, 2], [2, 6]], "z": [0, 0.5, 1], "w": [1, 2, 4]}]})");
  EXPECT_EQ(coverage(zw), coverage(window));
}

// rule: SCENE.OUTPUT.PIPELINE, PIPE.INTERP.LINEAR, PIPE.INTERP.FLAT
TEST(CliPipeline, AttributesAndBarycentricsAtPixelCentres) {
  const json doc = render(
      R"({"target": {"width": 2, "height": 1}, "provoking_vertex": "last",
          "attributes": [{"name": "x", "interpolation": "linear"}, {"name": "p"},
                         {"name": "id", "interpolation": "flat"}],
          "primitives": [{"type": "triangle", "v": [[0, 0], [4, 0], [0, 4]],
                          "attr": [[0, 0, 7], [4, 4, 8], [0, 0, 9]]}]})");
  const json& f = doc["fragments"];
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(f[0]["attr"], json::parse(R"({"x": 0.5, "p": 0.5, "id": 9})"));
  EXPECT_EQ(f[1]["attr"], json::parse(R"({"x": 1.5, "p": 1.5, "id": 9})"));
  // Field order of SCENE.OUTPUT.PIPELINE (in the text: nlohmann::json sorts keys).
  const TempDir dir;
  const auto path = dir.write(
      "s.json", R"({"target": {"width": 1, "height": 1}, "depth": {}, "attributes": [{"name": "a"}],
      "primitives": [{"type": "triangle", "v": [[0, 0], [4, 0], [0, 4]], "attr": [[1], [1], [1]]}]})");
  const auto r = run_cli({"render", path.string(), "--fragments", "-"});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::size_t prim = r.out.find("\"prim\""), x = r.out.find("\"x\""),
                    mask = r.out.find("\"mask\""), bary = r.out.find("\"bary\""),
                    attr = r.out.find("\"attr\""), depth = r.out.find("\"depth\""),
                    passed = r.out.find("\"passed\"");
  EXPECT_TRUE(prim < x && x < mask && mask < bary && bary < attr && attr < depth && depth < passed)
      << r.out;
  // bary: e0 + e1 + e2 = A (PIPE.BARY.SUM).
  const json b = json::parse(r.out)["fragments"][0]["bary"];
  ASSERT_EQ(b.size(), 4u);
  EXPECT_EQ(b[0].get<long long>() + b[1].get<long long>() + b[2].get<long long>(),
            b[3].get<long long>());
}

// Three window-space triangles over the whole 2x2 target at depths 0.5, 0.25, 0.75.
std::string three_layers(const std::string& depth) {
  return R"({"target": {"width": 2, "height": 2}, "depth": )" + depth + R"(, "primitives": [
      {"type": "triangle", "v": [[0, 0], [4, 0], [0, 4]], "z": [0.5, 0.5, 0.5]},
      {"type": "triangle", "v": [[0, 0], [4, 0], [0, 4]], "z": [0.25, 0.25, 0.25]},
      {"type": "triangle", "v": [[0, 0], [4, 0], [0, 4]], "z": [0.75, 0.75, 0.75]}]})";
}

// rule: SCENE.OUTPUT.PIPELINE, PIPE.DEPTH.TEST, PIPE.DEPTH.FORMAT
TEST(CliPipeline, DepthTestPassedMasksAndTheDepthBuffer) {
  const TempDir dir;
  const auto scene = dir.write("scene.json", three_layers(R"({"func": "less"})"));
  const auto r = run_cli({"render", scene.string(), "--fragments", (dir / "f.json").string(),
                          "--depth-out", (dir / "d.json").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const json f = json::parse(read_file(dir / "f.json"))["fragments"];
  ASSERT_EQ(f.size(), 12u);
  for (std::size_t i = 0; i < 12; ++i) {
    const int prim = f[i]["prim"].get<int>();
    const int stored[] = {8388608, 4194304};
    EXPECT_EQ(f[i]["passed"].get<int>(), prim == 2 ? 0 : 1) << i;
    // The third layer fails everywhere: killed, without depth values (PIPE.DEPTH.KILL).
    if (prim == 2) {
      EXPECT_FALSE(f[i].contains("depth")) << f[i].dump();
    } else {
      EXPECT_EQ(f[i]["depth"], json::array({stored[prim]})) << i;
    }
  }
  const json d = json::parse(read_file(dir / "d.json"));
  EXPECT_EQ(d, json::parse(R"({"format": "d24", "width": 2, "height": 2, "samples": 1,
                               "depth": [4194304, 4194304, 4194304, 4194304]})"));
  // greater: the first and the third pass; always without writes: every fragment passes and
  // the buffer keeps the clear value.
  const json greater = render(three_layers(R"({"func": "greater", "clear": 0})"));
  for (const json& g : greater["fragments"]) {
    EXPECT_EQ(g["passed"].get<int>(), g["prim"].get<int>() == 1 ? 0 : 1) << g.dump();
  }
  const auto a = dir.write("always.json",
                           three_layers(R"({"func": "always", "write": false, "format": "d16"})"));
  ASSERT_EQ(run_cli({"render", a.string(), "--fragments", (dir / "fa.json").string(), "--depth-out",
                     (dir / "da.json").string()})
                .status,
            0);
  const json always = json::parse(read_file(dir / "fa.json"));
  for (const json& g : always["fragments"])
    EXPECT_EQ(g["passed"].get<int>(), 1);
  EXPECT_EQ(json::parse(read_file(dir / "da.json"))["depth"],
            json::array({65535, 65535, 65535, 65535}));
  EXPECT_EQ(render(three_layers(R"({"format": "d16"})"))["fragments"][0]["depth"],
            json::array({32768}));
  EXPECT_EQ(render(three_layers(R"({"format": "d32f"})"))["fragments"][0]["depth"],
            json::array({0.5}));
}

// rule: SCENE.OUTPUT.PIPELINE, PIPE.DEPTH.TEST
TEST(CliPipeline, MultisampledDepthHasOneValuePerCoveredSample) {
  const json doc = render(
      R"({"target": {"width": 2, "height": 2}, "samples": 4, "depth": {"format": "d32f"},
          "primitives": [{"type": "triangle", "v": [[0, 0], [2, 0], [0, 2]], "z": [0.5, 0.5, 0.5]}]})");
  // The hand-checked masks of tests/cli/msaa_test.cpp: pixel (0,0) 0b1111, (1,0) and (0,1) 0b101.
  for (const json& f : doc["fragments"]) {
    const int mask = f["mask"].get<int>();
    EXPECT_EQ(f["depth"].size(),
              static_cast<std::size_t>(std::popcount(static_cast<unsigned>(mask))))
        << f.dump();
    EXPECT_EQ(f["passed"].get<int>(), mask);
    for (const json& z : f["depth"])
      EXPECT_EQ(z.get<double>(), 0.5);
  }
}

// rule: SCENE.OUTPUT.PIPELINE, PIPE.CLIP.POLYGON, PIPE.VIEWPORT.SCISSOR
TEST(CliPipeline, ClippedTrianglesCarryTheirPartAndTheViewportScissors) {
  // z < 0 at the third vertex: clipped by the near plane into a quadrilateral, two fan triangles.
  const json doc = render(
      R"({"target": {"width": 8, "height": 8}, "primitives": [{"type": "triangle",
          "pos": [[-1, -1, 0.5], [1, -1, 0.5], [0, 1, -0.5]]}]})");
  std::set<int> parts;
  for (const json& f : doc["fragments"]) {
    ASSERT_TRUE(f.contains("part")) << f.dump();
    parts.insert(f["part"].get<int>());
  }
  EXPECT_EQ(parts, (std::set<int>{0, 1}));
  // A viewport in the right half: only its pixels receive fragments.
  const json half = render(
      R"({"target": {"width": 8, "height": 4}, "viewport": {"x": 4, "width": 4},
          "primitives": [{"type": "triangle", "pos": [[-1, -1, 0], [3, -1, 0], [-1, 3, 0]]}]})");
  EXPECT_EQ(half["fragments"].size(), 16u);
  for (const json& f : half["fragments"])
    EXPECT_GE(f["x"].get<int>(), 4);
}

// rule: SCENE.OUTPUT.PIPELINE, FAST.THREADS.DETERMINISTIC, FAST.EQUALS.PLAIN
TEST(CliPipeline, ThreadsAndTraversalChangeNothing) {
  const TempDir dir;
  const auto scene = dir.write("scene.json", three_layers(R"({"func": "less_equal"})"));
  const auto base = run_cli({"render", scene.string(), "--fragments", "-"});
  ASSERT_EQ(base.status, 0) << base.err;
  for (const std::vector<std::string>& extra :
       {std::vector<std::string>{"--threads", "2"},
        std::vector<std::string>{"--traversal", "plain"},
        std::vector<std::string>{"--traversal", "fast", "--threads", "3"}}) {
    std::vector<std::string> args = {"render", scene.string(), "--fragments", "-"};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = run_cli(args);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, base.out) << extra[0];
  }
}

// rule: SCENE.OUTPUT.PIPELINE, MSAA.RESOLVE.AVERAGE
TEST(CliPipeline, PicturesOfCoverageAndDepthAndTheResolvedTarget) {
  const TempDir dir;
  const auto scene = dir.write("scene.json",
                               R"({"target": {"width": 2, "height": 1}, "depth": {}, "primitives": [
          {"type": "triangle", "v": [[0, 0], [4, 0], [0, 4]], "z": [0, 0, 0], "color": [255, 0, 0, 255]},
          {"type": "triangle", "v": [[1, 0], [4, 0], [1, 4]], "z": [0.5, 0.5, 0.5], "color": [0, 255, 0, 255]}]})");
  const auto r = run_cli({"render", scene.string(), "--png", (dir / "c.png").string(), "--resolve",
                          (dir / "r.png").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(read_png(dir / "c.png").has_value());
  const auto resolved = rastrules::test::read_png_rgba(dir / "r.png");
  ASSERT_TRUE(resolved.has_value());
  // The second triangle lies behind the first: the target stays red.
  EXPECT_EQ(resolved->rgba_at(0, 0), (std::array<std::uint8_t, 4>{255, 0, 0, 255}));
  EXPECT_EQ(resolved->rgba_at(1, 0), (std::array<std::uint8_t, 4>{255, 0, 0, 255}));
  // --png-depth: black where depth 0 was written; magnified 32 times, the pixel centres.
  const auto d =
      run_cli({"render", scene.string(), "--png", (dir / "d.png").string(), "--png-depth"});
  ASSERT_EQ(d.status, 0) << d.err;
  const auto depth = read_png(dir / "d.png");
  ASSERT_TRUE(depth.has_value());
  EXPECT_EQ(depth->at(16, 16), (std::array<std::uint8_t, 3>{0, 0, 0}));
  EXPECT_EQ(depth->at(48, 16), (std::array<std::uint8_t, 3>{0, 0, 0}));
}

// rule: SCENE.OUTPUT.PIPELINE, SCENE.INPUT.ERRORS
TEST(CliPipeline, DepthOutputsNeedDepthAndCheckDrawsPipelineScenesWithDriversThatCan) {
  const TempDir dir;
  const auto clip = dir.write("clip.json", kClipTriangle);
  const auto plain = dir.write("plain.json", kWindowTriangle);
  const auto no_depth =
      run_cli({"render", clip.string(), "--png", (dir / "a.png").string(), "--png-depth"});
  EXPECT_EQ(no_depth.status, 2);
  EXPECT_NE(no_depth.err.find("--png-depth: the scene has no \"depth\""), std::string::npos)
      << no_depth.err;
  const auto plain_out =
      run_cli({"render", plain.string(), "--depth-out", (dir / "d.json").string()});
  EXPECT_EQ(plain_out.status, 2);
  EXPECT_NE(plain_out.err.find("--depth-out: a window-space scene"), std::string::npos)
      << plain_out.err;
  const auto without_png = run_cli({"render", clip.string(), "--fragments", "-", "--png-depth"});
  EXPECT_EQ(without_png.status, 2);
  EXPECT_FALSE(std::filesystem::exists(dir / "a.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "d.json"));
  // rule: DRIVER.VALUES
  // check compares pipeline scenes (coverage and values) with drivers that draw them; a
  // coverage-only driver refuses them, naming the first pipeline field.
  const auto check = run_cli({"check", clip.string(), "--driver", "reference"});
  EXPECT_EQ(check.status, 0) << check.err;
  EXPECT_NE(check.out.find("result      no difference"), std::string::npos) << check.out;
  const auto refused = run_cli({"check", clip.string(), "--driver", "imprecise:float-edges"});
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("pipeline state (primitives[0].pos, SCENE.PIPELINE) not supported"),
            std::string::npos)
      << refused.err;
  // The fragment limit holds for pipeline scenes.
  const auto limited = run_cli(
      {"render", clip.string(), "--fragments", (dir / "f.json").string(), "--max-fragments", "3"});
  EXPECT_EQ(limited.status, 2);
  EXPECT_NE(limited.err.find("(limit SCENE.INPUT.LIMITS)"), std::string::npos) << limited.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "f.json"));
}

// rule: SCENE.OUTPUT.PIPELINE
TEST(CliPipeline, ExplainListsThePixelsFragments) {
  const TempDir dir;
  const auto scene = dir.write("scene.json", three_layers("{}"));
  const auto text = run_cli({"explain", scene.string(), "--pixel", "1,0"});
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("3 fragments"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("depth [4194304] (d24), passed 0b1"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("killed: no sample passed the depth test"), std::string::npos)
      << text.out;
  EXPECT_NE(
      text.out.find("drawn triangle: snapped (0, 0), (4, 0), (0, 4), window z [0.25, 0.25, 0.25]"),
      std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("covered by: primitives 0, 1"), std::string::npos) << text.out;
  const auto j = run_cli({"explain", scene.string(), "--pixel", "1,0", "--json"});
  ASSERT_EQ(j.status, 0) << j.err;
  const json doc = json::parse(j.out);
  EXPECT_EQ(doc["pixel"], json::array({1, 0}));
  EXPECT_EQ(doc["fragments"].size(), 3u);
  EXPECT_EQ(doc["covered_by"], json::array({0, 1}));
  const auto outside = run_cli({"explain", scene.string(), "--pixel", "2,0"});
  EXPECT_EQ(outside.status, 2);
}

// The clip-space example of README.md's "Using the command line" renders as shown there.
// rule: SCENE.PIPELINE
TEST(CliPipeline, TheReadmeExampleRenders) {
  const json doc = render(
      R"({"target": {"width": 16, "height": 8},
          "depth": {"format": "d24", "func": "less"},
          "attributes": [{"name": "u"}],
          "primitives": [{"type": "triangle", "pos": [[-0.75, -0.75, 0.5], [0.75, -0.75, 0.5, 2], [0, 0.75, 0.25]],
                          "attr": [[0], [1], [0.5]]}]})");
  ASSERT_FALSE(doc["fragments"].empty());
  for (const json& f : doc["fragments"]) {
    EXPECT_TRUE(f.contains("bary") && f.contains("attr") && f.contains("depth") &&
                f.contains("passed"));
    const double u = f["attr"]["u"].get<double>();
    EXPECT_GE(u, -0.01);
    EXPECT_LE(u, 1.01);
  }
}

} // namespace

namespace {

// The strip of the report on line strips: two segments, a linear and a flat attribute.
constexpr const char* kStrip = R"({"target": {"width": 16, "height": 16},
 "attributes": [{"name": "u", "interpolation": "linear"}, {"name": "k", "interpolation": "flat"}],
 "depth": {"format": "d24", "func": "always"},
 "primitives": [{"type": "line_strip",
   "pos": [[-0.9375, -0.9375, 0.25], [0.9375, -0.9375, 0.5], [0.9375, 0.9375, 0.75]],
   "attr": [[0, 10], [1, 20], [2, 30]]}]})";

// rule: PIPE.BARY.LINE, PIPE.INTERP.FLAT, LINE.STRIP.SEQUENCE, SCENE.OUTPUT.PIPELINE
TEST(CliPipeline, StripSegmentsAreInterpolatedFromTheirOwnVertices) {
  const json doc = render(kStrip);
  bool seen = false;
  for (const json& f : doc["fragments"]) {
    if (f["x"] != 15 || f["y"] != 1 || !f.contains("seg") || f["seg"] != 1)
      continue;
    seen = true;
    EXPECT_EQ(f["bary"], json::parse("[983040, 13762560, 0, 14745600]"));
    EXPECT_EQ(f["attr"]["k"], 20);
    EXPECT_EQ(f["depth"], json::parse("[12303291]"));
  }
  EXPECT_TRUE(seen);
}

// rule: PIPE.OPT.TILES, PIPE.OPT.HIZ, PIPE.OPT.EARLY_Z, PIPE.OPT.FAST_CLEAR
TEST(CliPipeline, PipelinePlainGivesTheSameBytes) {
  const TempDir dir;
  const auto path = dir.write("scene.json", kStrip);
  const auto fast = run_cli({"render", path.string(), "--fragments", "-"});
  const auto plain = run_cli({"render", path.string(), "--fragments", "-", "--pipeline-plain"});
  ASSERT_EQ(fast.status, 0) << fast.err;
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_EQ(fast.out, plain.out);
  // A coverage-only scene: the plain traversal, the same bytes.
  const auto path2 = dir.write("tri.json", kWindowTriangle);
  const auto a = run_cli({"render", path2.string(), "--fragments", "-"});
  const auto b = run_cli({"render", path2.string(), "--fragments", "-", "--pipeline-plain"});
  ASSERT_EQ(b.status, 0) << b.err;
  EXPECT_EQ(a.out, b.out);
}

} // namespace
