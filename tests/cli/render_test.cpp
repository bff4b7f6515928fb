// SPDX-License-Identifier: MIT
// rastrules render: exact fragment lists on hand-checked scenes, standard input and output,
// and the picture.

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "rastrules/io/picture.hpp"
#include "support.hpp"

namespace {

using rastrules::test::read_file;
using rastrules::test::render_fragments;
using rastrules::test::run_cli;
using rastrules::test::run_cli_peak;
using rastrules::test::TempDir;

std::string frag(int prim, int x, int y) {
  return "  {\"prim\": " + std::to_string(prim) + ", \"x\": " + std::to_string(x) +
         ", \"y\": " + std::to_string(y) + ", \"mask\": 1}";
}

std::string fragments(std::initializer_list<std::array<int, 3>> list) {
  std::string s = "{\"fragments\": [";
  bool first = true;
  for (const auto& f : list) {
    s += (first ? "\n" : ",\n") + frag(f[0], f[1], f[2]);
    first = false;
  }
  return s + (first ? "]}\n" : "\n]}\n");
}

// A 4x4 target split along the anti-diagonal x + y = 4, which runs through the centres
// (0.5, 3.5), (1.5, 2.5), (2.5, 1.5), (3.5, 0.5). For the first (clockwise) triangle that
// diagonal is a right edge (excluded), for the second a left edge (included).
constexpr const char* kSplitSquare = R"({"target": {"width": 4, "height": 4}, "primitives": [
  {"type": "triangle", "v": [[0, 0], [4, 0], [0, 4]]},
  {"type": "triangle", "v": [[4, 0], [4, 4], [0, 4]]}]})";

const std::string kSplitSquareFragments = fragments({{0, 0, 0},
                                                     {0, 1, 0},
                                                     {0, 2, 0},
                                                     {0, 0, 1},
                                                     {0, 1, 1},
                                                     {0, 0, 2},
                                                     {1, 3, 0},
                                                     {1, 2, 1},
                                                     {1, 3, 1},
                                                     {1, 1, 2},
                                                     {1, 2, 2},
                                                     {1, 3, 2},
                                                     {1, 0, 3},
                                                     {1, 1, 3},
                                                     {1, 2, 3},
                                                     {1, 3, 3}});

// A picture colour as Png::at() gives it.
std::array<std::uint8_t, 3> rgb(rastrules::io::Rgb c) {
  return {c.r, c.g, c.b};
}

// rule: SCENE.OUTPUT.FRAGMENTS, TRI.FILL.TOP_LEFT
TEST(CliRender, SplitSquareGivesEachDiagonalCentreToTheTriangleWithTheLeftEdge) {
  const auto r = render_fragments(kSplitSquare);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(r.fragments, kSplitSquareFragments);
  EXPECT_NE(r.out.find("2 primitives, 16 fragments"), std::string::npos) << r.out;
}

// rule: SCENE.OUTPUT.FRAGMENTS, TRI.FILL.TOP_LEFT
TEST(CliRender, DiagonalThroughCentresGoesToTheLeftEdgeSide) {
  // Square [1, 3]^2 split along x = y, which runs through the centres (1.5, 1.5) and
  // (2.5, 2.5): for the upper triangle it is a left edge (included), for the lower one a
  // right edge (excluded).
  const auto r = render_fragments(R"({"target": {"width": 4, "height": 4}, "primitives": [
    {"type": "triangle", "v": [[1, 1], [3, 1], [3, 3]]},
    {"type": "triangle", "v": [[1, 1], [3, 3], [1, 3]]}]})");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.fragments, fragments({{0, 1, 1}, {0, 2, 1}, {0, 2, 2}, {1, 1, 2}}));
}

// rule: SCENE.OUTPUT.FRAGMENTS, TRI.CULL.MODE, TRI.DEGENERATE.ZERO_AREA
TEST(CliRender, CulledAndDegenerateTrianglesProduceNoFragments) {
  const auto r = render_fragments(R"({"target": {"width": 4, "height": 4}, "cull": "back",
    "primitives": [
      {"type": "triangle", "v": [[0, 0], [0, 4], [4, 0]]},
      {"type": "triangle", "v": [[0, 0], [2, 2], [4, 4]]},
      {"type": "triangle", "v": [[0, 0], [1, 0], [0, 1]]}]})");
  ASSERT_EQ(r.status, 0) << r.err;
  // Only the third (clockwise, front-facing) triangle draws: the centre (0.5, 0.5) lies on
  // its hypotenuse x + y = 1, a right edge, so it is not covered either.
  EXPECT_EQ(r.fragments, fragments({}));
}

// rule: SCENE.OUTPUT.FRAGMENTS, RASTER.TARGET.CLIP
TEST(CliRender, FragmentsOutsideTheTargetAreNotWritten) {
  const auto r = render_fragments(R"({"target": {"width": 2, "height": 1}, "primitives": [
    {"type": "triangle", "v": [[-100, -100], [300, -100], [-100, 300]]}]})");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.fragments, fragments({{0, 0, 0}, {0, 1, 0}}));
}

// rule: SCENE.NUMBER.FLOAT32, SNAP.VERTEX.ROUND
TEST(CliRender, CoordinatesAreReadAsFloat32BeforeSnapping) {
  // Three left edges near the centres x = 0.5, 1.5, 2.5 of a 3x1 target:
  // - 0.5019531251: the nearest float32 is 0.501953125 = raw 128.5 exactly, which snaps to
  //   128 (ties to even) = 0.5, so the edge runs through the centre and includes it. (Read as
  //   a double, the text would snap to 129 and miss the centre.)
  // - 1.501953125 = raw 384.5 snaps to 384 = 1.5: on the centre, included.
  // - 2.505859375 = raw 641.5 snaps to 642 = 2.5078125: right of the centre, which is outside.
  const auto r = render_fragments(R"({"target": {"width": 3, "height": 1}, "primitives": [
    {"type": "triangle", "v": [[0.5019531251, -1], [1, -1], [0.5019531251, 3]]},
    {"type": "triangle", "v": [[1.501953125, -1], [2, -1], [1.501953125, 3]]},
    {"type": "triangle", "v": [[2.505859375, -1], [3, -1], [2.505859375, 3]]}]})");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.fragments, fragments({{0, 0, 0}, {1, 1, 0}}));
}

// rule: SCENE.OUTPUT.FRAGMENTS
TEST(CliRender, ReadsStandardInputAndWritesStandardOutput) {
  const TempDir dir;
  const auto scene = dir.write("scene.json", kSplitSquare);
  const auto r = run_cli({"render", "-", "--fragments", "-"}, scene.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, kSplitSquareFragments);
  EXPECT_EQ(r.err, "");
}

TEST(CliRender, WritesAPictureOfTheMagnifiedTarget) {
  const TempDir dir;
  const auto scene = dir.write("scene.json", kSplitSquare);
  const auto r = run_cli({"render", scene.string(), "--png", (dir / "out.png").string(),
                          "--fragments", (dir / "out.json").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto png = rastrules::test::read_png(dir / "out.png");
  ASSERT_TRUE(png.has_value());
  // Default scale: 32 image pixels per target pixel, plus the closing grid line.
  ASSERT_EQ(png->width, 4u * 32 + 1);
  ASSERT_EQ(png->height, 4u * 32 + 1);
  // Inside pixel (1, 0) (covered by primitive 0) and pixel (3, 3) (primitive 1), away from
  // the grid, the centre crosses and the edges.
  EXPECT_EQ(png->at(1 * 32 + 4, 0 * 32 + 28), rgb(rastrules::io::cover_colour(0)));
  EXPECT_EQ(png->at(3 * 32 + 4, 3 * 32 + 4), rgb(rastrules::io::cover_colour(1)));
  EXPECT_NE(rastrules::io::cover_colour(0), rastrules::io::cover_colour(1));
  EXPECT_EQ(read_file(dir / "out.json"), kSplitSquareFragments);
}

TEST(CliRender, PictureMarksOverlapsAndUncoveredPixels) {
  const TempDir dir;
  const auto scene =
      dir.write("scene.json", R"({"target": {"width": 3, "height": 2}, "primitives": [
    {"type": "triangle", "v": [[0, 0], [2, 0], [0, 2]]},
    {"type": "triangle", "v": [[0, 0], [2, 0], [0, 2]]}]})");
  const auto r =
      run_cli({"render", scene.string(), "--png", (dir / "out.png").string(), "--scale", "16"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto png = rastrules::test::read_png(dir / "out.png");
  ASSERT_TRUE(png.has_value());
  ASSERT_EQ(png->width, 3u * 16 + 1);
  ASSERT_EQ(png->height, 2u * 16 + 1);
  // Pixel (0, 0) is covered twice: its border is the overlap mark.
  EXPECT_EQ(png->at(0 * 16 + 1, 0 * 16 + 8), rgb(rastrules::io::kOverlapMark));
  EXPECT_EQ(png->at(0 * 16 + 15, 0 * 16 + 8), rgb(rastrules::io::kOverlapMark));
  // Pixel (2, 1) is not covered: background.
  EXPECT_EQ(png->at(2 * 16 + 4, 1 * 16 + 4), rgb(rastrules::io::kBackground));
}

// rule: SCENE.INPUT.ERRORS
TEST(CliRender, RefusesPicturesLargerThanTheLimitWithoutWritingAnything) {
  const TempDir dir;
  const auto scene =
      dir.write("scene.json", R"({"target": {"width": 5000, "height": 2}, "primitives": []})");
  const auto r = run_cli({"render", scene.string(), "--png", (dir / "out.png").string(),
                          "--fragments", (dir / "out.json").string()});
  EXPECT_EQ(r.status, 2);
  ASSERT_EQ(r.err_lines().size(), 1u) << r.err;
  EXPECT_NE(r.err.find("--png"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out.json"));
}

// rule: SCENE.INPUT.ERRORS
TEST(CliRender, UnwritableOutputIsAnErrorAndLeavesNothing) {
  const TempDir dir;
  const auto scene = dir.write("scene.json", kSplitSquare);
  const auto r = run_cli(
      {"render", scene.string(), "--fragments", (dir / "no-such-dir" / "out.json").string()});
  EXPECT_EQ(r.status, 2);
  ASSERT_EQ(r.err_lines().size(), 1u) << r.err;
  EXPECT_NE(r.err.find("cannot create"), std::string::npos) << r.err;
}

} // namespace

namespace {

TEST(CliRender, OutputsThatAreNotRegularFilesAreWrittenInPlace) {
  // A symbolic link (like /dev/null or a pipe) must not be replaced by a renamed temporary file.
  const TempDir dir;
  const auto scene = dir.write("scene.json", kSplitSquare);
  const auto real = dir.write("real.json", "");
  std::filesystem::create_symlink(real, dir / "link.json");
  const auto r = run_cli({"render", scene.string(), "--fragments", (dir / "link.json").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(std::filesystem::is_symlink(dir / "link.json"));
  EXPECT_EQ(read_file(real), kSplitSquareFragments);
}

// Issue 17 item 8, found 2026-11-25: --resolve kept every fragment (5.4 GB for a target whose
// samples take 256 MiB). The samples are now written as the fragments stream. Scaled down: 32
// triangles each covering a 512x512 target are 8.4 million fragments, over 600 MB as a list;
// the resolve holds 1 MiB of samples. Peak memory is the child's maximum resident set.
// rule: MSAA.RESOLVE.AVERAGE, MSAA.LIMITS, SCENE.INPUT.LIMITS
TEST(CliRender, TheResolveHoldsTheSamplesNotTheFragments) {
  const TempDir dir;
  std::string prims;
  for (int i = 0; i < 32; ++i) {
    prims += std::string(i == 0 ? "" : ", ") +
             R"({"type": "triangle", "v": [[0, 0], [1024, 0], [0, 1024]], "color": [)" +
             std::to_string(i * 8) + ", 0, 0, 255]}";
  }
  const auto scene = dir.write(
      "scene.json", R"({"target": {"width": 512, "height": 512}, "primitives": [)" + prims + "]}");
  long peak_kib = -1;
  const auto r =
      run_cli_peak({"render", scene.string(), "--resolve", (dir / "r.png").string()}, peak_kib);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_GE(peak_kib, 0) << "the peak was not measured";
  EXPECT_LT(peak_kib, 300L * 1024) << "peak resident set in KiB";
  // The last triangle's colour everywhere.
  const auto png = rastrules::test::read_png_rgba(dir / "r.png");
  ASSERT_TRUE(png.has_value());
  ASSERT_EQ(png->width, 512u);
  EXPECT_EQ(png->rgba_at(0, 0), (std::array<std::uint8_t, 4>{248, 0, 0, 255}));
  EXPECT_EQ(png->rgba_at(511, 511), (std::array<std::uint8_t, 4>{248, 0, 0, 255}));
}

// Issue 17 item 3, found 2026-11-25: a symlinked output was written in place, so a render that
// failed half way destroyed the link's target (a 3 GB partial JSON replaced it). The temporary
// now goes beside the real target and is renamed onto it only when complete.
// rule: SCENE.INPUT.ERRORS, SCENE.INPUT.LIMITS
TEST(CliRender, AFailedRenderLeavesALinkedOutputsTargetAsItWas) {
  const TempDir dir;
  const auto scene = dir.write("scene.json", kSplitSquare);
  const auto real = dir.write("real.json", "keep me");
  std::filesystem::create_symlink(real, dir / "link.json");
  const auto r = run_cli({"render", scene.string(), "--fragments", (dir / "link.json").string(),
                          "--max-fragments", "1"});
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(read_file(real), "keep me");
  EXPECT_TRUE(std::filesystem::is_symlink(dir / "link.json"));
  // No temporary is left beside the target or the link.
  for (const auto& e : std::filesystem::directory_iterator(dir.path()))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

// Issue 17 item 4, found 2026-11-25: two outputs naming one file ("F" and "F", or "F" and
// "./F") deleted the existing F and printed "cannot write: Success". Refused before any work.
// rule: SCENE.INPUT.ERRORS
TEST(CliRender, TwoOutputsNamingOneFileAreRefusedBeforeAnyWork) {
  const TempDir dir;
  const auto scene = dir.write("scene.json", kSplitSquare);
  const auto out = dir.write("out", "keep me");
  const std::string same_by_dot = (dir.path() / "." / "out").string();
  for (const auto& [first, second] :
       {std::pair{"--fragments", "--png"}, std::pair{"--png", "--resolve"},
        std::pair{"--fragments", "--depth-out"}}) {
    const auto r = run_cli({"render", scene.string(), first, out.string(), second, same_by_dot});
    EXPECT_EQ(r.status, 2) << first << " " << second;
    ASSERT_EQ(r.err_lines().size(), 1u) << r.err;
    EXPECT_NE(r.err.find("names the same file as"), std::string::npos) << r.err;
    EXPECT_EQ(read_file(out), "keep me");
  }
  // Through a link too.
  std::filesystem::create_symlink(out, dir / "alias");
  const auto r = run_cli(
      {"render", scene.string(), "--fragments", out.string(), "--png", (dir / "alias").string()});
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(read_file(out), "keep me");
}

// Issue 17 item 6, found 2026-11-25: a raw NUL byte ended the input (the JSON library's lexer
// reads it as the end), so a valid scene followed by NUL and garbage rendered with exit 0.
// rule: SCENE.INPUT.ERRORS
TEST(CliRender, ARawNulByteIsAParseErrorWithItsPosition) {
  const TempDir dir;
  const auto scene =
      dir.write("scene.json", std::string(kSplitSquare) + std::string(1, '\0') + "garbage");
  const auto r = run_cli({"render", scene.string(), "--fragments", "-"});
  EXPECT_EQ(r.status, 2);
  ASSERT_EQ(r.err_lines().size(), 1u) << r.err;
  EXPECT_NE(r.err.find("a raw NUL byte"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("parse error at line"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
}

} // namespace
