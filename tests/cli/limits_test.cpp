// SPDX-License-Identifier: MIT
// SCENE.INPUT.LIMITS: each limit accepts its largest input and refuses the next one with one
// clear line naming the limit, exit status 2 and no output file. Large inputs are generated
// in temporary directories at test time (nothing big is committed).

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "rastrules/io/scene_json.hpp"
#include "rastrules/scene.hpp"
#include "support.hpp"

namespace {

using rastrules::test::read_file;
using rastrules::test::run_cli;
using rastrules::test::TempDir;
namespace io = rastrules::io;

void expect_one_error_line(const rastrules::test::RunResult& r, const std::string& expected) {
  EXPECT_EQ(r.status, 2);
  const auto lines = r.err_lines();
  ASSERT_EQ(lines.size(), 1u) << r.err.substr(0, 2000);
  EXPECT_EQ(lines[0].rfind("rastrules: error: ", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find(expected), std::string::npos)
      << "expected \"" << expected << "\" in: " << lines[0];
}

// Runs `rastrules render SCENE --fragments DIR/OUT --max-fragments LIMIT`.
rastrules::test::RunResult render_with_limit(const TempDir& dir, const std::filesystem::path& scene,
                                             const std::string& out, const std::string& limit) {
  return run_cli(
      {"render", scene.string(), "--fragments", (dir / out).string(), "--max-fragments", limit});
}

std::string head(int w, int h) {
  return "{\"version\": 1, \"target\": {\"width\": " + std::to_string(w) +
         ", \"height\": " + std::to_string(h) + "}, \"primitives\": [";
}

// `n` points (the primitive with the shortest text, so that the test stays fast).
std::string many_points(std::size_t n) {
  std::string s = head(8, 8);
  s.reserve(s.size() + n * 32);
  for (std::size_t i = 0; i < n; ++i) {
    s += i == 0 ? "" : ",";
    s += "{\"type\":\"point\",\"v\":[[1,1]]}";
  }
  return s + "]}";
}

// A line strip of `n` vertices zig-zagging inside an 8x8 target.
std::string long_strip(std::size_t n) {
  std::string s = head(8, 8) + "{\"type\": \"line_strip\", \"v\": [";
  s.reserve(s.size() + n * 8);
  for (std::size_t i = 0; i < n; ++i) {
    s += i == 0 ? "" : ",";
    s += (i % 2 == 0) ? "[1,1]" : "[6,5]";
  }
  return s + "]}]}";
}

// rule: SCENE.INPUT.LIMITS
TEST(Limits, FileOfExactlyTheSizeLimitIsReadAndOneByteMoreIsRefused) {
  const TempDir dir;
  const std::string scene = head(4, 4) + "]}";
  const std::string pad(io::kMaxSceneBytes - scene.size(), ' ');
  const auto at_limit = dir.write("at_limit.json", pad + scene);
  ASSERT_EQ(std::filesystem::file_size(at_limit), io::kMaxSceneBytes);
  const auto ok = run_cli({"render", at_limit.string(), "--fragments", (dir / "ok.json").string()});
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_EQ(read_file(dir / "ok.json"), "{\"fragments\": []}\n");

  const auto over = dir.write("over.json", pad + " " + scene);
  const auto r = run_cli({"render", over.string(), "--fragments", (dir / "out.json").string()});
  expect_one_error_line(
      r, "is larger than 64 MiB, the largest scene file accepted (limit SCENE.INPUT.LIMITS)");
  EXPECT_FALSE(std::filesystem::exists(dir / "out.json"));
}

// rule: SCENE.INPUT.LIMITS
TEST(Limits, PrimitiveCountLimitAcceptsTheLimitAndRefusesOneMore) {
  const auto at = io::read_scene(many_points(io::kMaxScenePrimitives));
  ASSERT_TRUE(std::holds_alternative<rastrules::Scene>(at))
      << std::get<rastrules::SceneError>(at).what();
  EXPECT_EQ(std::get<rastrules::Scene>(at).primitives.size(), io::kMaxScenePrimitives);

  const TempDir dir;
  const auto over = dir.write("over.json", many_points(io::kMaxScenePrimitives + 1));
  ASSERT_LT(std::filesystem::file_size(over), io::kMaxSceneBytes); // the count, not the size, fails
  const auto r = run_cli({"render", over.string(), "--fragments", (dir / "out.json").string()});
  expect_one_error_line(r, "primitives: more than 1048576 primitives (limit SCENE.INPUT.LIMITS)");
  EXPECT_FALSE(std::filesystem::exists(dir / "out.json"));
}

// rule: SCENE.INPUT.LIMITS, SCENE.PRIM.LINE_STRIP
TEST(Limits, StripVertexLimitAcceptsTheLimitAndRefusesOneMore) {
  const TempDir dir;
  const auto at = dir.write("at.json", long_strip(io::kMaxStripVertices));
  const auto ok = run_cli({"render", at.string(), "--fragments", (dir / "ok.json").string()});
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "ok.json"));

  const auto over = dir.write("over.json", long_strip(io::kMaxStripVertices + 1));
  const auto r = run_cli({"render", over.string(), "--fragments", (dir / "out.json").string()});
  expect_one_error_line(
      r, "primitives[0].v: more than 65536 vertices in one primitive (limit SCENE.INPUT.LIMITS)");
  EXPECT_FALSE(std::filesystem::exists(dir / "out.json"));
}

// rule: SCENE.INPUT.LIMITS
TEST(Limits, NestingDeeperThanTheFormatStopsAtTheFirstExtraLevel) {
  // A million levels where a coordinate belongs: refused at the first '[' beyond depth 5,
  // without recursion or memory proportional to the depth.
  const std::string deep(std::size_t{1} << 20, '[');
  const std::string text = head(4, 4) + "{\"type\": \"point\", \"v\": [[" + deep;
  const auto r = io::read_scene(text);
  ASSERT_TRUE(std::holds_alternative<rastrules::SceneError>(r));
  EXPECT_EQ(std::get<rastrules::SceneError>(r).what(),
            "primitives[0].v[0][0]: must be a number, \"NaN\", \"Infinity\" or \"-Infinity\", got "
            "an array");
  EXPECT_EQ(io::kMaxSceneNesting, 5u);
}

// rule: SCENE.INPUT.LIMITS, SCENE.OUTPUT.FRAGMENTS
TEST(Limits, FragmentLimitIsExactAndLeavesNoOutput) {
  const TempDir dir;
  // Two triangles covering the 16x8 target: 128 fragments.
  const auto scene = dir.write(
      "full.json", head(16, 8) + "{\"type\": \"triangle\", \"v\": [[0,0],[16,0],[0,8]]},"
                                 "{\"type\": \"triangle\", \"v\": [[16,0],[16,8],[0,8]]}]}");
  const auto ok = render_with_limit(dir, scene, "ok.json", "128");
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_NE(ok.out.find("128 fragments"), std::string::npos) << ok.out;

  const auto r = run_cli({"render", scene.string(), "--fragments", (dir / "out.json").string(),
                          "--png", (dir / "out.png").string(), "--max-fragments=127"});
  expect_one_error_line(r, "render: more than 127 fragments (limit SCENE.INPUT.LIMITS); raise it "
                           "with --max-fragments N");
  EXPECT_EQ(r.out, "");
  EXPECT_FALSE(std::filesystem::exists(dir / "out.json"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path()))
    ++files;
  EXPECT_EQ(files, 2u); // full.json and ok.json: no temporary file left behind
}

// rule: SCENE.INPUT.LIMITS
TEST(Limits, FragmentLimitStopsAHugeRenderEarly) {
  // A full-screen triangle on the largest target has 2^28 fragments; the limit stops the
  // traversal at the first fragment beyond it instead of walking (and writing) them all.
  const TempDir dir;
  const auto scene =
      dir.write("huge.json", head(16384, 16384) +
                                 "{\"type\": \"triangle\", \"v\": [[0,0],[32000,0],[0,32000]]}]}");
  const auto start = std::chrono::steady_clock::now();
  const auto r = render_with_limit(dir, scene, "out.json", "100000");
  const auto seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  expect_one_error_line(r, "render: more than 100000 fragments (limit SCENE.INPUT.LIMITS)");
  EXPECT_FALSE(std::filesystem::exists(dir / "out.json"));
  EXPECT_LT(seconds, 5.0);
}

// A line strip is collected whole before its fragments are sorted: the bound on what it may
// hold (2 x --max-fragments) stops it before memory grows with it, and says which primitive.
// rule: SCENE.INPUT.LIMITS
TEST(Limits, CollectedPrimitivesAreBoundedBeforeTheyAreSorted) {
  const TempDir dir;
  std::string strip = "{\"type\": \"line_strip\", \"v\": [";
  for (int i = 0; i < 16; ++i) {
    strip += std::string(i ? "," : "") + "[" + std::to_string(i % 2 ? 1020 : 2) + ".5," +
             std::to_string(2 + i * 60) + ".5]";
  }
  strip += "]}]}";
  const auto scene = dir.write("strip.json", head(1024, 1024) + strip);
  const auto r = render_with_limit(dir, scene, "out.json", "1000");
  expect_one_error_line(
      r, "render: primitives[0] touches more than 2000 pixels or fragments that must be held "
         "to be sorted (limit SCENE.INPUT.LIMITS, 2 x --max-fragments); raise it with "
         "--max-fragments N");
  EXPECT_FALSE(std::filesystem::exists(dir / "out.json"));
  const auto ok = render_with_limit(dir, scene, "ok.json", "100000");
  EXPECT_EQ(ok.status, 0) << ok.err;
}

// A multisampled primitive holds the pixels it touches, also those whose covered samples the
// sample mask removes: a sliver that covers only sample 1 of each pixel under mask 1 draws
// nothing, yet touches about 40 pixels, which count against the bound.
// rule: SCENE.INPUT.LIMITS, MSAA.MASK.AND
TEST(Limits, TouchedPixelsOfAMaskedPrimitiveCountAgainstTheBound) {
  const TempDir dir;
  const auto scene = dir.write(
      "sliver.json", "{\"target\": {\"width\": 64, \"height\": 4}, \"samples\": 2, "
                     "\"sample_pattern\": [[-8, -8], [7, 7]], \"sample_mask\": 1, \"primitives\": ["
                     "{\"type\": \"triangle\", \"v\": [[0, 0.9], [64, 0.9], [0, 1.0]]}]}");
  const auto r = render_with_limit(dir, scene, "out.json", "10");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("primitives[0] touches more than 20 pixels"), std::string::npos) << r.err;
  const auto ok = render_with_limit(dir, scene, "ok.json", "100");
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_NE(ok.out.find("0 fragments"), std::string::npos) << ok.out;
}

// rule: SCENE.INPUT.LIMITS
TEST(Limits, DefaultFragmentLimitIsStatedInTheUsage) {
  EXPECT_EQ(io::kDefaultMaxFragments, std::uint64_t{1} << 26);
  const auto r = run_cli({"--help"});
  EXPECT_NE(r.out.find("--max-fragments fragments (default 67108864)"), std::string::npos) << r.out;
}

// `n` long diagonal slivers across a 1024 x 1024 target that cover no pixel centre (y - x
// stays in [0.25, 0.254]): 0 fragments, yet each makes the plain traversal test every pixel
// of its 1024 x 1024 bounding box. extra: more keys of each primitive (a pipeline key makes it
// a pipeline scene).
std::string slivers(std::size_t n, const std::string& extra = "") {
  std::string s = head(1024, 1024);
  for (std::size_t i = 0; i < n; ++i) {
    s += i == 0 ? "" : ",";
    s += "{\"type\": \"triangle\", \"v\": [[0,0.25],[1024,1024.25],[1024,1024.254]]" + extra + "}";
  }
  return s + "]}";
}

// Issue 17 item 2: a scene of slivers has no fragment for the fragment limit to count, so its
// time was bounded by nothing. The work limit (--max-work, scaled down here from its default
// of 2^36) counts the pixels of each bounding box before anything is drawn: the same error,
// naming the primitive at which the sum passes it, for every thread count and traversal.
// rule: SCENE.INPUT.LIMITS, FAST.THREADS.DETERMINISTIC, FAST.EQUALS.PLAIN
TEST(Limits, WorkLimitRefusesSliversBeforeDrawingThem) {
  const TempDir dir;
  const auto scene = dir.write("slivers.json", slivers(3)); // 3 x 2^20 = 3145728 pixel tests
  for (const char* threads : {"1", "2"}) {
    for (const char* traversal : {"fast", "plain"}) {
      const auto r = run_cli({"render", scene.string(), "--fragments", (dir / "out.json").string(),
                              "--png", (dir / "out.png").string(), "--max-work", "3145727",
                              "--threads", threads, "--traversal", traversal});
      expect_one_error_line(r, "render: primitives[2] brings the work to more than 3145727 "
                               "sample tests (limit SCENE.INPUT.LIMITS); raise it with "
                               "--max-work N");
      EXPECT_EQ(r.out, "");
      EXPECT_FALSE(std::filesystem::exists(dir / "out.json"));
      EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
    }
  }
  // A pipeline scene (window-space depth per vertex): its clipped primitives are counted the
  // same way, before they are rasterized.
  const auto pipeline = dir.write("pipeline.json", slivers(3, ", \"z\": [0, 0, 0]"));
  const auto p = run_cli({"render", pipeline.string(), "--fragments", (dir / "out.json").string(),
                          "--max-work", "2097151"});
  expect_one_error_line(p, "primitives[1]: brings the work to more than 2097151 sample "
                           "tests (limit SCENE.INPUT.LIMITS); raise it with --max-work N");
  EXPECT_FALSE(std::filesystem::exists(dir / "out.json"));
}

// Both limits of a pipeline scene say how to raise them, as a coverage scene's do: the kernel
// types its error (SceneError::Kind), the command line no longer recognises the message text.
// rule: SCENE.INPUT.LIMITS
TEST(Limits, PipelineFragmentLimitSaysHowToRaiseIt) {
  const TempDir dir;
  const auto scene =
      dir.write("p.json", "{\"target\": {\"width\": 8, \"height\": 8}, \"primitives\": ["
                          "{\"type\": \"triangle\", \"v\": [[0, 0], [8, 0], [0, 8]], "
                          "\"z\": [0, 0, 0]}]}");
  const auto r = run_cli({"render", scene.string(), "--fragments", (dir / "out.json").string(),
                          "--max-fragments", "27"});
  expect_one_error_line(r, "primitives[0]: the scene produces more than 27 fragments (limit "
                           "SCENE.INPUT.LIMITS); raise it with --max-fragments N");
  EXPECT_FALSE(std::filesystem::exists(dir / "out.json"));
  EXPECT_EQ(run_cli({"render", scene.string(), "--fragments", (dir / "out.json").string(),
                     "--max-fragments", "28"})
                .status,
            0);
}

// rule: SCENE.INPUT.LIMITS
TEST(Limits, MaxWorkRaisesTheWorkLimit) {
  const TempDir dir;
  const auto scene = dir.write("slivers.json", slivers(3));
  for (const char* limit : {"3145728", "1152921504606846976"}) {
    const auto ok = run_cli({"render", scene.string(), "--fragments", (dir / "ok.json").string(),
                             "--threads", "2", "--max-work", limit});
    EXPECT_EQ(ok.status, 0) << ok.err;
    EXPECT_EQ(read_file(dir / "ok.json"), "{\"fragments\": []}\n");
  }
  // The default (2^36) is far above it, and stated in the usage.
  EXPECT_EQ(rastrules::kDefaultMaxWork, std::uint64_t{1} << 36);
  const auto dflt = run_cli({"render", scene.string(), "--fragments", (dir / "d.json").string()});
  EXPECT_EQ(dflt.status, 0) << dflt.err;
  const auto help = run_cli({"--help"});
  EXPECT_NE(help.out.find("more work than --max-work sample tests (default 68719476736"),
            std::string::npos)
      << help.out;
  for (const char* bad : {"0", "-1", "x", "1152921504606846977"}) {
    const auto r = run_cli(
        {"render", scene.string(), "--fragments", (dir / "o.json").string(), "--max-work", bad});
    EXPECT_EQ(r.err_lines(),
              std::vector<std::string>{
                  "rastrules: error: --max-work needs an integer in [1, 2^60], got \"" +
                  std::string(bad) + "\""})
        << bad;
    EXPECT_EQ(r.status, 2);
  }
}

// rule: SCENE.INPUT.ERRORS
TEST(Limits, MaxFragmentsNeedsAPositiveInteger) {
  const TempDir dir;
  const auto scene = dir.write("s.json", head(4, 4) + "]}");
  for (const char* bad : {"0", "-1", "abc", "1099511627777"}) {
    const auto r = run_cli({"render", scene.string(), "--fragments", (dir / "o.json").string(),
                            "--max-fragments", bad});
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_NE(r.err.find("--max-fragments needs an integer in [1, 2^40], got \"" +
                         std::string(bad) + "\""),
              std::string::npos)
        << r.err;
    EXPECT_EQ(r.err_lines().size(), 1u) << r.err; // one line, not the usage (issue 17 item 11)
    EXPECT_FALSE(std::filesystem::exists(dir / "o.json"));
  }
  // --scale and explain's --pixel: the same, one line naming the value.
  const auto scale =
      run_cli({"render", scene.string(), "--png", (dir / "o.png").string(), "--scale", "0"});
  EXPECT_EQ(scale.status, 2);
  EXPECT_EQ(scale.err_lines(),
            std::vector<std::string>{
                "rastrules: error: --scale needs an integer in [1, 4096], got \"0\""});
  const auto pixel = run_cli({"explain", scene.string(), "--pixel", "1;2"});
  EXPECT_EQ(pixel.status, 2);
  EXPECT_EQ(pixel.err_lines(),
            std::vector<std::string>{
                "rastrules: error: --pixel needs two integers X,Y in [0, 16383], got \"1;2\""});
}

} // namespace
