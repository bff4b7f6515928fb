// SPDX-License-Identifier: MIT
// Path primitives in the scene (SCENE.PRIM.PATH, SCENE.OUTPUT.AREA): the two written forms
// read to one path, the writer's round trip, fragments of both coverage kinds through
// render(), the work of a path, and the checker against the path oracle, tampering named.

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "check_support.hpp"
#include "rastrules/check/check.hpp"
#include "rastrules/decision.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/path.hpp"

namespace rastrules::check {
namespace {

Scene read(const std::string& json) {
  auto r = io::read_scene(json);
  if (const auto* e = std::get_if<SceneError>(&r))
    ADD_FAILURE() << e->what();
  return std::get<Scene>(r);
}

std::vector<Fragment> frags(const Scene& s) {
  auto r = render(s);
  if (const auto* e = std::get_if<SceneError>(&r))
    ADD_FAILURE() << e->what();
  return std::get<std::vector<Fragment>>(r);
}

using test_support::mentions;

Mismatches check(const Scene& s, const std::vector<Fragment>& f) {
  return check_against_oracle(s, std::get<PreparedScene>(prepare(s)), f);
}

// rule: SCENE.PRIM.PATH, SCENE.PATH.DATA
TEST(PathScene, PathDataAndContoursReadToOnePathThatTheWriterKeeps) {
  const Scene a = read(R"({"target": {"width": 8, "height": 8}, "primitives": [
    {"type": "path", "d": "M 1 1 h 5 q 1 3 -2 4 C 3 6 2 6 1 5 z", "fill_rule": "evenodd"}]})");
  const Scene b = read(R"({"target": {"width": 8, "height": 8}, "primitives": [
    {"type": "path", "fill_rule": "evenodd", "contours": [[["M", 1, 1], ["L", 6, 1],
     ["Q", 7, 4, 4, 5], ["C", 3, 6, 2, 6, 1, 5]]]}]})");
  EXPECT_TRUE(io::same_scene(a, b));
  // Where "d" put each point is kept for messages: the start, then each segment's points.
  ASSERT_TRUE(a.primitives[0].path.has_value());
  EXPECT_EQ(a.primitives[0].path->d_offsets.size(), 1u + 1u + 2u + 3u);
  EXPECT_TRUE(b.primitives[0].path->d_offsets.empty());
  // The writer writes the contour form, which reads back to the same scene.
  const std::string text = io::write_scene(a);
  EXPECT_NE(text.find("\"contours\": [[[\"M\", 1, 1], [\"L\", 6, 1], [\"Q\", 7, 4, 4, 5]"),
            std::string::npos)
      << text;
  EXPECT_TRUE(io::same_scene(read(text), a));
  EXPECT_EQ(frags(a), frags(b));
}

// rule: SCENE.PRIM.PATH, PATH.SAMPLE.TIE
TEST(PathScene, AOneTrianglePathGivesTheTrianglesFragments) {
  for (const FillConvention fill : {FillConvention::kTopLeft, FillConvention::kBottomRight}) {
    Scene tri, pth;
    tri.width = pth.width = 12;
    tri.height = pth.height = 9;
    tri.conventions.fill = pth.conventions.fill = fill;
    tri.primitives.push_back(
        make_triangle({FloatPoint{1.5f, 0.5f}, FloatPoint{10.5f, 4.5f}, FloatPoint{2.5f, 8.5f}}));
    FloatPath p;
    p.contours.push_back(
        FloatContour{{1.5f, 0.5f},
                     {FloatPathSegment{path::SegmentKind::kLine, {{{10.5f, 4.5f}}}},
                      FloatPathSegment{path::SegmentKind::kLine, {{{2.5f, 8.5f}}}}}});
    pth.primitives.push_back(make_path(p));
    EXPECT_EQ(frags(tri), frags(pth)) << to_string(fill);
    EXPECT_TRUE(check(pth, frags(pth)).agree());
  }
}

// rule: SCENE.OUTPUT.AREA, PATH.AREA.EXACT
TEST(PathScene, AreaFragmentsCarryTheExactAreaAndItsAlpha) {
  // Half of pixel (1, 1) below its diagonal, pixel (2, 1) whole, and 1/512 of pixel (4, 1).
  const std::string d = "M 1 1 L 2 2 L 1 2 Z M 2 1 h 1 v 1 h -1 Z M 4 1 L 4.0625 1 L 4 1.0625 Z";
  const Scene s = read(R"({"target": {"width": 6, "height": 3}, "primitives": [
    {"type": "path", "coverage": "area", "d": ")" +
                       d + R"("}]})");
  const std::vector<Fragment> f = frags(s);
  ASSERT_EQ(f.size(), 3u);
  EXPECT_EQ(f[0].area.text(), "1/2");
  EXPECT_EQ(f[0].area.alpha(), 128); // floor(127.5 + 0.5)
  EXPECT_EQ(f[0].area.approx(), 0.5);
  EXPECT_EQ(f[1].area.text(), "1");
  EXPECT_EQ(f[1].area.alpha(), 255);
  EXPECT_EQ(f[2].area.text(), "1/512");
  EXPECT_EQ(f[2].area.alpha(), 0); // floor(255/512 + 1/2): a fragment with alpha 0
  EXPECT_EQ(f[2].area.approx(), 1.0 / 512.0);
  for (const Fragment& g : f)
    EXPECT_EQ(g.mask, 1u);
  EXPECT_TRUE(check(s, f).agree());
}

// rule: SCENE.OUTPUT.AREA
TEST(PathScene, TheAreasDoubleIsCorrectlyRounded) {
  // A triangle of area 1/3 of a pixel, and one of 1/6: n/d with small n and d, whose
  // correctly rounded double is IEEE division's.
  const Scene s = read(R"({"target": {"width": 4, "height": 2}, "primitives": [
    {"type": "path", "coverage": "area", "contours": [[["M", 0, 0], ["L", 1, 0], ["L", 0.6640625, 1]]]}]})");
  const std::vector<Fragment> f = frags(s);
  ASSERT_FALSE(f.empty());
  for (const Fragment& g : f) {
    const std::string t = g.area.text();
    const auto slash = t.find('/');
    const double n = std::stod(t.substr(0, slash));
    const double d = slash == std::string::npos ? 1.0 : std::stod(t.substr(slash + 1));
    EXPECT_EQ(g.area.approx(), n / d) << t;
  }
}

// rule: SCENE.PRIM.PATH, MSAA.MASK.AND
TEST(PathScene, MultisampledPathsAndTheSampleMask) {
  Scene s = read(R"({"target": {"width": 6, "height": 6}, "samples": 4, "sample_mask": 5,
    "primitives": [{"type": "path", "d": "M 0.3 0.2 L 5.7 1.1 L 2.2 5.8 Z M 4 4 h 2 v 2 h -2 Z"},
                   {"type": "path", "coverage": "area", "d": "M 0 0 L 3 0 L 0 3 Z"},
                   {"type": "triangle", "v": [[0, 0], [6, 0], [0, 6]]}]})");
  const std::vector<Fragment> f = frags(s);
  bool any = false;
  for (const Fragment& g : f) {
    EXPECT_EQ(g.mask & ~5u, 0u);
    if (g.prim == 1) {
      EXPECT_EQ(g.mask, 5u); // area fragments: every kept sample
    }
    any = any || g.prim == 0;
  }
  EXPECT_TRUE(any);
  EXPECT_TRUE(check(s, f).agree()) << check(s, f).mismatches.front();
}

// rule: SCENE.OUTPUT.AREA, MSAA.MASK.AND
// Found by fuzz_path (its corpus: crash_area_under_an_empty_sample_mask): the checker wanted
// the oracle's areas where a sample mask of 0 leaves no fragment.
TEST(PathSceneRegression, AnEmptySampleMaskLeavesNoAreaFragment) {
  const Scene s = read(R"({"target": {"width": 6, "height": 3}, "sample_mask": 0,
    "primitives": [{"type": "path", "coverage": "area", "d": "M 0.5 0 L 5 0.5 L 1 2.5 Z"}]})");
  const std::vector<Fragment> f = frags(s);
  EXPECT_TRUE(f.empty());
  EXPECT_TRUE(check(s, f).agree());
}

// rule: SCENE.PRIM.PATH, SCENE.OUTPUT.AREA
TEST(PathScene, TheCheckerNamesEveryTampering) {
  const Scene s = read(R"({"target": {"width": 8, "height": 6}, "primitives": [
    {"type": "triangle", "v": [[0, 0], [3, 0], [0, 3]]},
    {"type": "path", "fill_rule": "evenodd", "d": "M 1 1 L 7 1 L 4 5 Z M 2 2 L 6 2 L 4 4.5 Z"},
    {"type": "path", "coverage": "area", "d": "M 1 1 L 7 1 L 4 5 Z M 2 2 L 6 2 L 4 4.5 Z"}]})");
  const std::vector<Fragment> f = frags(s);
  EXPECT_TRUE(check(s, f).agree());
  auto tampered = [&](auto&& change) {
    std::vector<Fragment> g = f;
    change(g);
    return check(s, g);
  };
  const auto first_of = [](std::vector<Fragment>& g, std::uint32_t prim) -> Fragment& {
    return *std::find_if(g.begin(), g.end(), [&](const Fragment& x) { return x.prim == prim; });
  };
  EXPECT_TRUE(mentions(tampered([&](auto& g) { g.erase(g.begin() + 1); }), "only the oracle"));
  EXPECT_TRUE(mentions(tampered([&](auto& g) { first_of(g, 1).mask = 3; }), "kernel mask 3"));
  EXPECT_TRUE(
      mentions(tampered([&](auto& g) { first_of(g, 2).area = first_of(g, 1).area; }), "no area"));
  EXPECT_TRUE(mentions(tampered([&](auto& g) {
                         Fragment& a = first_of(g, 2);
                         Fragment& b = *(std::find(g.begin(), g.end(), a) + 1);
                         std::swap(a.area, b.area);
                       }),
                       "kernel area"));
  EXPECT_TRUE(mentions(tampered([&](auto& g) { first_of(g, 1).seg = 0; }), "does not have"));
}

// rule: SCENE.PRIM.PATH, PATH.WINDING, PATH.AREA.EXACT
TEST(PathScene, DecisionRecordsAgreeWithTheFragmentsAtEveryPixel) {
  const Scene s = read(R"({"target": {"width": 9, "height": 7}, "samples": 4,
    "primitives": [
      {"type": "path", "fill_rule": "evenodd", "d": "M 1 1 L 8 1 L 4 6 Z M 2 2 L 6 2 L 4 5 Z"},
      {"type": "path", "d": "M 0.5 0.5 Q 9 0 8 6 C 4 7 0 9 0.5 0.5 Z"},
      {"type": "path", "coverage": "area", "d": "M 1 1 L 8 1 L 4 6 Z M 2 2 L 6 2 L 4 5 Z"}]})");
  const PreparedScene ps = std::get<PreparedScene>(prepare(s));
  const std::vector<Fragment> f = frags(s);
  for (std::size_t p = 0; p < s.primitives.size(); ++p) {
    for (std::int32_t y = 0; y < s.height; ++y) {
      for (std::int32_t x = 0; x < s.width; ++x) {
        const PixelDecision d = decide_pixel(ps, p, x, y);
        ASSERT_TRUE(d.path.has_value());
        const auto it = std::find_if(f.begin(), f.end(), [&](const Fragment& g) {
          return g.prim == p && g.x == x && g.y == y;
        });
        EXPECT_EQ(d.covered, it != f.end()) << p << " " << x << "," << y;
        if (it == f.end())
          continue;
        EXPECT_EQ(d.path->mask, it->mask);
        EXPECT_EQ(d.path->area, it->area);
        std::int64_t sum = 0;
        for (const path::SampleCrossing& c : d.path->samples[0].crossings)
          sum += c.dir;
        EXPECT_EQ(sum, d.path->samples[0].winding);
      }
    }
  }
}

// rule: SCENE.INPUT.LIMITS, SCENE.PRIM.PATH
TEST(PathScene, TheWorkOfAPathIsItsRowsPiecesAndColumns) {
  // A 4 px square of 4 pieces on an 8x8 target: rows 0..5 are reached (a row beyond each piece
  // each way), by 3, 3, 2, 3, 3, 3 pieces; columns 0..5.
  Scene s = read(R"({"target": {"width": 8, "height": 8}, "primitives": [
    {"type": "path", "d": "M 0 0 L 4 0 L 4 4 L 0 4 Z"}]})");
  const auto work = [](const Scene& sc) {
    return primitive_work(std::get<PreparedScene>(prepare(sc)), 0);
  };
  const std::uint64_t cols = 6;
  EXPECT_EQ(work(s), (3 + 3 + 2 + 3 + 3 + 3) * kPathPieceWork + 6 * cols);
  s.primitives[0].path->coverage = path::Coverage::kArea;
  auto area_row = [](std::uint64_t c) {
    const std::uint64_t slabs = 2 * c + c * (c - 1) / 2 + 1;
    return (c * c + slabs * c) * kPathAreaWork + 6 * kPathAreaPixelWork;
  };
  EXPECT_EQ(work(s), 5 * area_row(3) + area_row(2));
  // The limit names the path like any primitive.
  const PreparedScene ps = std::get<PreparedScene>(prepare(s));
  EXPECT_EQ(first_primitive_over_work(ps, work(s) - 1), std::optional<std::size_t>(0));
  EXPECT_EQ(first_primitive_over_work(ps, work(s)), std::nullopt);
}

} // namespace
} // namespace rastrules::check
