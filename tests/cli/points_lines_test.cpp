// SPDX-License-Identifier: MIT
// Points, lines, line strips and antialiased lines through the scene format, the kernel's
// scene entry points and `rastrules render` / `explain`: hand-checked fragment lists, the
// exact coverage text, (prim, y, x, seg) order, and a point's two triangles never overlapping.

#include <algorithm>
#include <cstdint>
#include <set>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "rastrules/io/fragment_json.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/point.hpp"
#include "rastrules/raster/walk.hpp"
#include "rastrules/scene.hpp"
#include "support.hpp"

namespace {

using rastrules::Fragment;
using rastrules::LineMode;
using rastrules::PrimitiveType;
using rastrules::test::render_fragments;
using rastrules::test::run_cli;
using rastrules::test::TempDir;

// Points on a centre, a corner and a vertical edge midpoint (cull back: points are never
// culled); a line along a row of centres; a strip running back over itself; a vertical
// (y-major) line through centres; a line along the bottom corners of a row of diamonds.
constexpr const char* kScene =
    R"({"target": {"width": 8, "height": 4}, "cull": "back", "primitives": [
 {"type": "point", "v": [[1.5, 1.5]]},
 {"type": "point", "v": [[4.0, 2.0]]},
 {"type": "point", "v": [[6.0, 1.5]]},
 {"type": "line", "v": [[0.5, 3.5], [4.5, 3.5]]},
 {"type": "line_strip", "v": [[1.5, 0.5], [5.5, 0.5], [2.5, 0.5]]},
 {"type": "line", "v": [[7.5, 0.5], [7.5, 3.5]]},
 {"type": "line", "aa": false, "v": [[0, 2], [4, 2]]}]})";

std::string frag(int prim, int x, int y, int seg = -1) {
  return "  {\"prim\": " + std::to_string(prim) + ", \"x\": " + std::to_string(x) +
         ", \"y\": " + std::to_string(y) + ", \"mask\": 1" +
         (seg >= 0 ? ", \"seg\": " + std::to_string(seg) : "") + "}";
}

// rule: SCENE.PRIM.POINT, SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP, SCENE.OUTPUT.FRAGMENTS
TEST(CliPointsLines, HandCheckedFragmentsOfPointsLinesAndAStrip) {
  // Point (1.5, 1.5): square [1, 2)^2 holds the centre (1.5, 1.5). Point (4, 2): square
  // [3.5, 4.5) x [1.5, 2.5): the centre (3.5, 1.5) is on its left and top sides (included),
  // the other three on the right or bottom side (excluded). Point (6, 1.5): left side x = 5.5
  // through (5.5, 1.5), included. Line (0.5, 3.5) -> (4.5, 3.5): starts inside pixel 0's
  // diamond and exits it; ends at pixel 4's centre, inside its diamond: x = 0..3. Strip
  // segment 0 draws x = 1..4 of row 0, segment 1 (leftwards from 5.5 to 2.5) x = 5, 4, 3: pixels
  // 3 and 4 appear once per segment. The vertical line exits the diamonds of rows 0..2. The
  // line y = 2 touches only the bottom corners of row 1's diamonds (included, x-major) and the
  // top corners of row 2's (excluded): row 1, x = 0..3.
  const std::vector<std::string> expected = {
      frag(0, 1, 1),    frag(1, 3, 1),    frag(2, 5, 1),    frag(3, 0, 3),    frag(3, 1, 3),
      frag(3, 2, 3),    frag(3, 3, 3),    frag(4, 1, 0, 0), frag(4, 2, 0, 0), frag(4, 3, 0, 0),
      frag(4, 3, 0, 1), frag(4, 4, 0, 0), frag(4, 4, 0, 1), frag(4, 5, 0, 1), frag(5, 7, 0),
      frag(5, 7, 1),    frag(5, 7, 2),    frag(6, 0, 1),    frag(6, 1, 1),    frag(6, 2, 1),
      frag(6, 3, 1)};
  std::string text = "{\"fragments\": [";
  for (std::size_t i = 0; i < expected.size(); ++i)
    text += (i == 0 ? "\n" : ",\n") + expected[i];
  text += "\n]}\n";
  const auto r = render_fragments(kScene);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.fragments, text);
  EXPECT_NE(r.out.find("7 primitives, 21 fragments"), std::string::npos) << r.out;
}

// rule: SCENE.OUTPUT.COVERAGE
TEST(CoverageText, IsTheExactDecimalOfQ16Over65536) {
  using rastrules::io::format_coverage;
  EXPECT_EQ(format_coverage(32768), "0.5");
  EXPECT_EQ(format_coverage(1), "0.0000152587890625");
  EXPECT_EQ(format_coverage(49152), "0.75");
  EXPECT_EQ(format_coverage(65535), "0.9999847412109375");
  EXPECT_EQ(format_coverage(65536), "1.0");
  EXPECT_EQ(format_coverage(0), "0.0");
  // Every value: "0.D" with D = q * 5^16 / 10^(16 - len(D)) exactly, no trailing zero, and
  // distinct values give distinct texts.
  std::set<std::string> seen;
  for (std::uint32_t q = 1; q < 65536; ++q) {
    const std::string t = format_coverage(q);
    ASSERT_EQ(t.rfind("0.", 0), 0u) << t;
    const std::string d = t.substr(2);
    ASSERT_TRUE(!d.empty() && d.size() <= 16 && d.back() != '0') << t;
    std::uint64_t scale = 1;
    for (std::size_t k = d.size(); k < 16; ++k)
      scale *= 10;
    ASSERT_EQ(std::stoull(d) * scale, std::uint64_t{q} * 152587890625u) << q << " -> " << t;
    seen.insert(t);
  }
  EXPECT_EQ(seen.size(), 65535u);
}

// rule: SCENE.OUTPUT.COVERAGE, SCENE.PRIM.LINE
TEST(CliPointsLines, AntialiasedFragmentsCarryCoverageAndOthersDoNot) {
  const auto r = render_fragments(R"({"target": {"width": 12, "height": 6}, "primitives": [
    {"type": "line", "v": [[7.0, 2.5], [11.0, 2.5]], "aa": true},
    {"type": "line", "v": [[0.5, 4.5], [6.5, 4.5]]},
    {"type": "line_strip", "aa": true, "v": [[1.5, 1.5], [3.5, 1.5], [3.5, 3.5]]}]})");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.fragments);
  std::size_t aa = 0;
  bool centre_seen = false;
  for (const auto& f : doc["fragments"]) {
    const int prim = f["prim"].get<int>();
    EXPECT_EQ(f.contains("coverage"), prim != 1) << f.dump();
    EXPECT_EQ(f.contains("seg"), prim == 2) << f.dump();
    if (!f.contains("coverage"))
      continue;
    ++aa;
    const double c = f["coverage"].get<double>();
    EXPECT_GT(c, 0.0);
    EXPECT_LE(c, 1.0);
    if (prim == 0 && f["x"] == 8 && f["y"] == 2) {
      // Pixel (8, 2) lies on the line's axis, 1 px from its start and 2 px from its end: the
      // rectangle covers R0 fully and a 1 px band of every wider square:
      // (1 + 1.5/2.25 + 2/4 + 2.5/6.25 + 3/9) / 5 = 0.58, within 1/65536 (LINE.AA.PRECISION).
      EXPECT_NEAR(c, 0.58, 1.0 / 65536.0);
      centre_seen = true;
    }
  }
  EXPECT_TRUE(centre_seen);
  EXPECT_GT(aa, 20u);
}

// rule: SCENE.PRIM.LINE_STRIP, SCENE.OUTPUT.FRAGMENTS
TEST(SceneModel, StripFragmentsAreSortedByPrimYXSegAndEqualTheirSegments) {
  rastrules::Scene s;
  s.width = 16;
  s.height = 10;
  for (const LineMode mode : {LineMode::kD3DDiamond, LineMode::kVulkanBresenham,
                              LineMode::kQuadWide, LineMode::kQuadNarrow}) {
    s.conventions.line_mode = mode;
    s.primitives.clear();
    rastrules::Primitive strip;
    strip.type = PrimitiveType::kLineStrip;
    strip.v = {{1.5f, 1.5f}, {12.5f, 1.5f}, {2.25f, 1.75f}, {7.6f, 8.9f}, {1.5f, 1.5f}};
    s.primitives.push_back(strip);
    const auto all = std::get<std::vector<Fragment>>(rastrules::render(s));
    ASSERT_FALSE(all.empty());
    EXPECT_TRUE(std::is_sorted(all.begin(), all.end(), rastrules::fragment_before));
    for (std::size_t i = 1; i < all.size(); ++i) {
      EXPECT_TRUE(rastrules::fragment_before(all[i - 1], all[i])) << "duplicate fragment " << i;
    }
    // The strip equals its segments drawn as independent lines (LINE.STRIP.SEQUENCE).
    std::vector<std::tuple<int, int, unsigned>> from_strip, from_lines;
    for (const Fragment& f : all) {
      ASSERT_TRUE(f.seg.has_value());
      from_strip.emplace_back(f.y, f.x, *f.seg);
    }
    for (std::size_t k = 0; k + 1 < strip.v.size(); ++k) {
      rastrules::Scene one = s;
      rastrules::Primitive line;
      line.type = PrimitiveType::kLine;
      line.v = {strip.v[k], strip.v[k + 1]};
      one.primitives = {line};
      const auto rendered = rastrules::render(one);
      for (const Fragment& f : std::get<std::vector<Fragment>>(rendered)) {
        EXPECT_FALSE(f.seg.has_value());
        from_lines.emplace_back(f.y, f.x, static_cast<unsigned>(k));
      }
    }
    std::sort(from_lines.begin(), from_lines.end());
    EXPECT_EQ(from_strip, from_lines) << rastrules::to_string(mode);
  }
}

// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.PRIM.LINE_STRIP
TEST(FragmentWriter, RefusesFragmentsOutOfPrimYXSegOrder) {
  Fragment a{0, 3, 0, 1u, 0u, std::nullopt};
  Fragment b{0, 3, 0, 1u, 1u, std::nullopt};
  EXPECT_TRUE(rastrules::fragment_before(a, b));
  EXPECT_FALSE(rastrules::fragment_before(b, a));
  EXPECT_FALSE(rastrules::fragment_before(a, a));
  std::FILE* devnull = std::fopen("/dev/null", "wb");
  ASSERT_NE(devnull, nullptr);
  {
    rastrules::io::FragmentWriter w(devnull);
    EXPECT_TRUE(w.add(a));
    EXPECT_TRUE(w.add(b));
    EXPECT_FALSE(w.add(a)); // seg 0 after seg 1 at the same pixel
    EXPECT_FALSE(w.add(b)); // a duplicate
    EXPECT_TRUE(w.finish());
    EXPECT_EQ(w.count(), 2u);
  }
  std::fclose(devnull);
}

// A point's two triangles never cover one pixel centre twice, under every fill convention and
// for every subpixel position of the centre within a pixel (the union is a plain sum).
// rule: SCENE.PRIM.POINT
TEST(SceneModel, PointTrianglesNeverOverlapUnderAnyFillConvention) {
  using rastrules::FillConvention;
  for (const FillConvention fill : {FillConvention::kTopLeft, FillConvention::kTopRight,
                                    FillConvention::kBottomLeft, FillConvention::kBottomRight}) {
    rastrules::RasterState state;
    state.fill = fill;
    state.cull = rastrules::CullMode::kBack;
    int covered_total = 0;
    for (std::int32_t dy = 0; dy < 256; dy += 4) {
      for (std::int32_t dx = 0; dx < 256; dx += 4) {
        const rastrules::Vec2 c{rastrules::Subpixel::from_raw(3 * 256 + dx),
                                rastrules::Subpixel::from_raw(3 * 256 + dy)};
        std::set<std::pair<int, int>> seen;
        int count = 0;
        for (const auto& t : rastrules::setup_point(c, state)) {
          EXPECT_EQ(t.status, rastrules::TriangleStatus::kRasterized);
          rastrules::raster::walk_triangle(t, 8, 8, [&](std::int32_t x, std::int32_t y) {
            ++count;
            EXPECT_TRUE(seen.insert({x, y}).second) << "pixel (" << x << ", " << y << ") twice";
          });
        }
        EXPECT_EQ(count, 1) << "a 1x1 half-open square holds exactly one centre";
        covered_total += count;
      }
    }
    EXPECT_EQ(covered_total, 64 * 64);
  }
}

// rule: SCENE.PRIM.POINT, SCENE.PRIM.LINE, SCENE.LINE_MODE
TEST(SceneModel, PrepareRejectsWhatTheReaderRejects) {
  rastrules::Scene s;
  s.width = 8;
  s.height = 8;
  rastrules::Primitive p;
  p.type = PrimitiveType::kPoint;
  p.v = {{1.0f, 1.0f}, {2.0f, 2.0f}};
  s.primitives = {p};
  EXPECT_EQ(std::get<rastrules::SceneError>(rastrules::render(s)).what(),
            "primitives[0].v: a point must have exactly 1 vertex [x, y], got 2");
  p.v = {{1.0f, 1.0f}};
  p.aa = true;
  s.primitives = {p};
  EXPECT_EQ(std::get<rastrules::SceneError>(rastrules::render(s)).field, "primitives[0].aa");
  p.type = PrimitiveType::kLine;
  p.v = {{1.0f, 1.0f}, {5.0f, 2.0f}};
  s.primitives = {p};
  s.conventions.line_mode = LineMode::kVulkanBresenham;
  EXPECT_EQ(std::get<rastrules::SceneError>(rastrules::render(s)).field, "primitives[0].aa");
  s.conventions.line_mode = LineMode::kD3DDiamond;
  EXPECT_TRUE(std::holds_alternative<std::vector<Fragment>>(rastrules::render(s)));
  // The point range: the largest centre whose square fits, and one subpixel beyond it.
  p = rastrules::Primitive{};
  p.type = PrimitiveType::kPoint;
  p.v = {{static_cast<float>(rastrules::kMaxPointRaw) / 256.0f, 0.0f}};
  s.primitives = {p};
  EXPECT_TRUE(std::holds_alternative<std::vector<Fragment>>(rastrules::render(s)));
  p.v = {{static_cast<float>(rastrules::kMaxPointRaw + 1) / 256.0f, 0.0f}};
  s.primitives = {p};
  EXPECT_EQ(std::get<rastrules::SceneError>(rastrules::render(s)).field, "primitives[0].v[0][0]");
  p.v = {{0.0f, static_cast<float>(rastrules::kMinPointRaw - 1) / 256.0f}};
  s.primitives = {p};
  EXPECT_EQ(std::get<rastrules::SceneError>(rastrules::render(s)).field, "primitives[0].v[0][1]");
}

// rule: SCENE.FORMAT.V1, SCENE.LINE_MODE, SCENE.PRIM.LINE_STRIP
TEST(SceneIo, PointsLinesStripsAndLineModeRoundTrip) {
  for (const char* mode : {"d3d", "vulkan-bresenham", "quad-wide", "quad-narrow"}) {
    const std::string aa = std::string(mode) == "d3d" ? ", \"aa\": true" : "";
    const std::string text =
        std::string(R"({"target": {"width": 8, "height": 8}, "line_mode": ")") + mode +
        R"(", "primitives": [{"type": "point", "v": [[1.25, 2]]},
      {"type": "line", "v": [[0.1, 0.2], [7, 7.5]])" +
        aa + R"(},
      {"type": "line_strip", "v": [[1, 1], [2, 3], [4, 1], [6, 6]]},
      {"type": "triangle", "v": [[1, 1], [6, 2], [2, 6]]}]})";
    const auto first = rastrules::io::read_scene(text);
    ASSERT_TRUE(std::holds_alternative<rastrules::Scene>(first))
        << std::get<rastrules::SceneError>(first).what();
    const auto& s = std::get<rastrules::Scene>(first);
    ASSERT_EQ(s.primitives.size(), 4u);
    EXPECT_EQ(rastrules::io::line_mode_name(s.conventions.line_mode), mode);
    EXPECT_EQ(s.primitives[0].type, PrimitiveType::kPoint);
    EXPECT_EQ(s.primitives[1].aa, !aa.empty());
    EXPECT_EQ(s.primitives[2].v.size(), 4u);
    const std::string written = rastrules::io::write_scene(s);
    const auto again = rastrules::io::read_scene(written);
    ASSERT_TRUE(std::holds_alternative<rastrules::Scene>(again)) << written;
    EXPECT_EQ(rastrules::io::write_scene(std::get<rastrules::Scene>(again)), written);
  }
}

// rule: SCENE.PRIM.LINE, SCENE.PRIM.POINT
TEST(CliExplain, ShowsTheDiamondDecisionAndThePointTriangles) {
  const TempDir dir;
  const auto scene = dir.write("scene.json", kScene);
  // Pixel (4, 3): the line along row 3 ends at its centre, inside the diamond: not covered.
  const auto r = run_cli({"explain", scene.string(), "--pixel", "4,3"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("primitive 3: line"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("pixel's diamond test area: top (4.5, 3), right (5, 3.5), bottom (4.5, 4), "
                       "left (4, 3.5)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("ends inside it: yes"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("not covered: the segment does not exit the diamond"), std::string::npos)
      << r.out;
  // Pixel (3, 1): the point at (4, 2) covers it through its first triangle's top-left corner.
  const auto p = run_cli({"explain", scene.string(), "--pixel", "3,1", "--json"});
  ASSERT_EQ(p.status, 0) << p.err;
  const auto doc = nlohmann::json::parse(p.out);
  EXPECT_EQ(doc["covered_by"], nlohmann::json::array({1, 6})); // and the line along y = 2
  const auto& point = doc["primitives"][1];
  EXPECT_EQ(point["type"], "point");
  ASSERT_EQ(point["triangles"].size(), 2u);
  EXPECT_NE(point["triangles"][0]["covered"], point["triangles"][1]["covered"]);
  EXPECT_EQ(doc["primitives"][4]["segments"].size(), 2u);
}

} // namespace
