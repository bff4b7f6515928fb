// SPDX-License-Identifier: MIT
// The fuzzer finds each planted bug of the imprecise driver and shrinks it to the expected
// minimal scene; the reference finds nothing against itself.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <set>
#include <variant>

#include "fuzzer_test_support.hpp"
#include "rastrules/driver/driver.hpp"
#include "rastrules/driver/imprecise.hpp"
#include "rastrules/fuzzer/fuzzer.hpp"

namespace rastrules::fuzzer {
namespace {

using test::open;

Summary campaign(driver::Driver& d, const std::string& name, Profile profile, Mode mode,
                 std::uint64_t cases, std::uint64_t seed = 1) {
  Settings s;
  s.driver_name = name;
  s.profile = profile;
  s.mode = mode;
  s.cases = cases;
  s.seed = seed;
  return run_fuzz(d, s);
}

bool multiple_of(float v, int denominator) {
  const double x = static_cast<double>(v) * denominator;
  return x == std::floor(x);
}

// Whether the centre of pixel (px, py) lies exactly on an edge of the triangle (coordinates
// multiples of 1/256, exact in integers).
bool centre_on_edge(const Primitive& t, std::int32_t px, std::int32_t py) {
  const auto raw = [](float v) {
    return static_cast<std::int64_t>(std::lround(static_cast<double>(v) * 256));
  };
  const std::int64_t sx = px * 256 + 128, sy = py * 256 + 128;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& a = t.v[i];
    const auto& b = t.v[(i + 1) % 3];
    const std::int64_t ax = raw(a[0]), ay = raw(a[1]), bx = raw(b[0]), by = raw(b[1]);
    const std::int64_t e = (bx - ax) * (sy - ay) - (by - ay) * (sx - ax);
    const bool within = std::min(ax, bx) <= sx && sx <= std::max(ax, bx) &&
                        std::min(ay, by) <= sy && sy <= std::max(ay, by);
    if (e == 0 && within)
      return true;
  }
  return false;
}

// rule: DRIVER.IMPRECISE, FUZZ.SHRINK
TEST(PlantedBugs, FloatEdgesWithEGreaterOrEqualZeroShrinkToOneTriangleWithACentreOnAnEdge) {
  auto d = open("imprecise:float-edges");
  const Summary s = campaign(*d, "imprecise:float-edges", Profile::kD3D11, Mode::kExact, 200);
  ASSERT_TRUE(s.error.empty()) << s.error;
  ASSERT_GT(s.unique, 0u);
  int simplest = 0;
  for (const Finding& f : s.findings) {
    ASSERT_EQ(f.shrunk.primitives.size(), 1u) << f.key;
    const Primitive& t = f.shrunk.primitives[0];
    EXPECT_EQ(t.type, PrimitiveType::kTriangle);
    bool halves = true;
    for (const FloatPoint& v : t.v) {
      EXPECT_TRUE(multiple_of(v[0], 16) && multiple_of(v[1], 16)) << f.key;
      halves = halves && multiple_of(v[0], 2) && multiple_of(v[1], 2);
    }
    // E >= 0 only ever adds samples: each extra pixel has its centre on a (right or bottom)
    // edge, which the top-left rule excludes.
    EXPECT_TRUE(f.comparison.missing.empty()) << f.key;
    ASSERT_FALSE(f.comparison.extra.empty()) << f.key;
    for (const DiffEntry& e : f.comparison.extra)
      EXPECT_TRUE(centre_on_edge(t, e.x, e.y)) << f.key;
    EXPECT_LE(f.shrunk.width * f.shrunk.height, 32) << f.key;
    if (halves && f.shrunk.width == 1 && f.shrunk.height == 1 && f.comparison.extra.size() == 1)
      ++simplest;
  }
  // The most frequent minimal scene: a 1x1 target, a triangle on integers and halves, the one
  // pixel centre on its right or bottom edge.
  EXPECT_GE(simplest * 2, static_cast<int>(s.unique)) << simplest << " of " << s.unique;
}

// rule: DRIVER.IMPRECISE, FUZZ.SHRINK, FUZZ.COMPARE.LEGAL
TEST(PlantedBugs, BottomRightFillIsFoundUnderD3D11AndLegalUnderVulkan) {
  auto d = open("imprecise:fill-bottom-right");
  const Summary s = campaign(*d, "imprecise:fill-bottom-right", Profile::kD3D11, Mode::kExact, 200);
  ASSERT_TRUE(s.error.empty()) << s.error;
  ASSERT_GT(s.unique, 0u);
  bool unit_triangle = false;
  for (const Finding& f : s.findings) {
    ASSERT_EQ(f.shrunk.primitives.size(), 1u) << f.key;
    const Primitive& t = f.shrunk.primitives[0];
    for (const FloatPoint& v : t.v)
      EXPECT_TRUE(multiple_of(v[0], 16) && multiple_of(v[1], 16)) << f.key;
    EXPECT_FALSE(f.comparison.missing.empty() && f.comparison.extra.empty());
    for (const DiffEntry& e : f.comparison.missing)
      EXPECT_TRUE(centre_on_edge(t, e.x, e.y)) << f.key;
    for (const DiffEntry& e : f.comparison.extra)
      EXPECT_TRUE(centre_on_edge(t, e.x, e.y)) << f.key;
    unit_triangle = unit_triangle || (f.shrunk.width == 1 && f.shrunk.height == 1);
  }
  EXPECT_TRUE(unit_triangle) << "some finding shrinks to a 1x1 target";
  // d3d11 requires top-left: legal is exact there.
  EXPECT_EQ(
      campaign(*d, "imprecise:fill-bottom-right", Profile::kD3D11, Mode::kLegal, 200).mismatches,
      s.mismatches);
  // Vulkan allows any consistent convention: no mismatch, and bottom-right explains every case.
  const Summary v =
      campaign(*d, "imprecise:fill-bottom-right", Profile::kVulkan, Mode::kLegal, 200);
  EXPECT_EQ(v.mismatches, 0u);
  std::uint64_t bottom_right = 0;
  for (const auto& [f, n] : v.legal_conventions) {
    if (f == FillConvention::kBottomRight)
      bottom_right = n;
  }
  EXPECT_EQ(bottom_right, v.cases);
  // ... but exact comparison under vulkan still reports it.
  EXPECT_GT(
      campaign(*d, "imprecise:fill-bottom-right", Profile::kVulkan, Mode::kExact, 200).mismatches,
      0u);
}

// rule: DRIVER.IMPRECISE, FUZZ.SHRINK
TEST(PlantedBugs, FourBitSnappingShrinksToOneTriangleOffTheSixteenthGrid) {
  auto d = open("imprecise:4-bit-subpixel");
  const Summary s = campaign(*d, "imprecise:4-bit-subpixel", Profile::kD3D11, Mode::kExact, 300);
  ASSERT_TRUE(s.error.empty()) << s.error;
  ASSERT_GT(s.unique, 0u);
  for (const Finding& f : s.findings) {
    ASSERT_EQ(f.shrunk.primitives.size(), 1u) << f.key;
    // Only a coordinate off the 1/16 grid can snap differently; rounding it to 1/16 (what the
    // driver does) makes the reference agree with the driver.
    int off_grid = 0;
    Scene rounded = f.shrunk;
    for (FloatPoint& v : rounded.primitives[0].v) {
      for (float& c : v) {
        if (!multiple_of(c, 16))
          ++off_grid;
        c = static_cast<float>(std::nearbyint(static_cast<double>(c) * 16) / 16);
      }
    }
    EXPECT_GE(off_grid, 1) << f.key;
    EXPECT_LE(off_grid, 2) << f.key;
    auto drawn = d->draw(f.shrunk);
    ASSERT_TRUE(std::holds_alternative<std::vector<Fragment>>(drawn));
    std::string err;
    auto c = compare(rounded, std::get<std::vector<Fragment>>(drawn), Profile::kD3D11, Mode::kExact,
                     &err);
    ASSERT_TRUE(c.has_value()) << err;
    EXPECT_TRUE(c->match) << f.key;
  }
}

// rule: DRIVER.IMPRECISE
TEST(PlantedBugs, AllBugsTogetherAreFoundAndEveryFindingIsOnePrimitive) {
  auto d = open("imprecise");
  const Summary s = campaign(*d, "imprecise", Profile::kD3D11, Mode::kExact, 150);
  ASSERT_TRUE(s.error.empty()) << s.error;
  EXPECT_GT(s.unique, 0u);
  EXPECT_LE(s.unique, s.mismatches);
  for (const Finding& f : s.findings)
    EXPECT_EQ(f.shrunk.primitives.size(), 1u) << f.key;
}

// rule: FUZZ.COMPARE.EXACT, FUZZ.GENERATE
TEST(PlantedBugs, ReferenceAgainstItselfFindsNothingInEveryProfile) {
  auto d = open("reference");
  for (const Profile p : {Profile::kD3D11, Profile::kVulkan, Profile::kOpenGL}) {
    const Summary s = campaign(*d, "reference", p, Mode::kExact, 300, 7);
    EXPECT_TRUE(s.error.empty()) << s.error;
    EXPECT_EQ(s.cases + s.skipped, 300u);
    EXPECT_GT(s.cases, 250u);
    EXPECT_EQ(s.mismatches, 0u) << to_string(p);
  }
}

// rule: DRIVER.IMPRECISE
TEST(PlantedBugs, ImpreciseDriverNamesAndUnsupportedScenes) {
  std::string err;
  EXPECT_EQ(driver::open_driver("imprecise:wobbly", &err), nullptr);
  EXPECT_NE(err.find("imprecise:wobbly"), std::string::npos) << err;
  auto d = open("imprecise:4-bit-subpixel");
  EXPECT_EQ(d->info().subpixel_bits, 4);
  Scene s;
  s.width = 4;
  s.height = 4;
  Primitive p;
  p.type = PrimitiveType::kPoint;
  p.v = {{1.0f, 1.0f}};
  s.primitives.push_back(p);
  EXPECT_NE(d->unsupported(s).find("point"), std::string::npos);
  s.primitives[0] = make_triangle({FloatPoint{0, 0}, FloatPoint{4, 0}, FloatPoint{0, 4}});
  EXPECT_EQ(d->unsupported(s), "");
  // With no planted bug on the way (vertices on the 1/16 grid, no ties), it agrees with the
  // reference: the bugs, not the driver, make the differences.
  s.primitives[0] = make_triangle(
      {FloatPoint{0.25f, 0.125f}, FloatPoint{3.8125f, 0.3125f}, FloatPoint{0.0625f, 3.9375f}});
  auto drawn = d->draw(s);
  ASSERT_TRUE(std::holds_alternative<std::vector<Fragment>>(drawn));
  auto c = compare(s, std::get<std::vector<Fragment>>(drawn), Profile::kD3D11, Mode::kExact, &err);
  ASSERT_TRUE(c.has_value());
  EXPECT_TRUE(c->match);
  EXPECT_FALSE(c->expected.empty());
}

// A values campaign (FUZZ.VALUES.GENERATE) against a value-bug variant: findings, each shrunk to
// one primitive whose value (not coverage) differs, grouped under the rule of that value.
Summary value_campaign(const std::string& name, Profile profile, Mode mode, std::uint64_t cases) {
  auto d = open(name);
  Settings s;
  s.driver_name = name;
  s.profile = profile;
  s.mode = mode;
  s.cases = cases;
  s.values = true;
  return run_fuzz(*d, s);
}

void expect_value_findings(const Summary& s, const std::string& rule) {
  ASSERT_TRUE(s.error.empty()) << s.error;
  ASSERT_GT(s.unique, 0u);
  for (const Finding& f : s.findings) {
    EXPECT_EQ(f.shrunk.primitives.size(), 1u) << f.key;
    EXPECT_TRUE(f.comparison.missing.empty() && f.comparison.extra.empty()) << f.key;
    ASSERT_TRUE(f.comparison.values) << f.key;
    EXPECT_GT(f.comparison.values->beyond, 0u) << f.key;
    EXPECT_EQ(f.group.rule, rule) << f.key;
    for (const ValueDiff& v : f.comparison.values->diffs) {
      EXPECT_EQ(v.rule, rule) << f.key;
      EXPECT_FALSE(v.within);
      EXPECT_GT(v.distance, 0.0);
    }
  }
}

// rule: DRIVER.IMPRECISE.VALUES, FUZZ.VALUES.EXACT, FUZZ.VALUES.LEGAL, FUZZ.SHRINK
TEST(PlantedValueBugs, ScreenSpaceInterpolationIsFoundInBothModesAndShrunkToOnePrimitive) {
  const Summary exact = value_campaign("imprecise:screen-space", Profile::kD3D11, Mode::kExact, 80);
  expect_value_findings(exact, "PIPE.INTERP.PERSPECTIVE");
  // Off by far more than float32 noise: beyond what the APIs allow too.
  const Summary legal =
      value_campaign("imprecise:screen-space", Profile::kVulkan, Mode::kLegal, 80);
  expect_value_findings(legal, "PIPE.INTERP.PERSPECTIVE");
  ASSERT_TRUE(exact.worst_attribute);
  EXPECT_GT(exact.worst_attribute->distance, 1e6);
  EXPECT_FALSE(exact.worst_attribute->within);
}

// rule: DRIVER.IMPRECISE.VALUES, FUZZ.VALUES.EXACT, FUZZ.VALUES.LEGAL, FUZZ.SHRINK
TEST(PlantedValueBugs, TheWrongProvokingVertexIsFoundForTrianglesAndLinesUnderEitherConvention) {
  const Summary exact =
      value_campaign("imprecise:provoking-vertex", Profile::kD3D11, Mode::kExact, 80);
  expect_value_findings(exact, "PIPE.INTERP.FLAT");
  const Summary legal =
      value_campaign("imprecise:provoking-vertex", Profile::kOpenGL, Mode::kLegal, 80);
  expect_value_findings(legal, "PIPE.INTERP.FLAT");
  bool first = false, last = false, line = false;
  for (const Finding& f : exact.findings) {
    (f.shrunk.conventions.provoking == pipe::Provoking::kFirst ? first : last) = true;
    line = line || f.shrunk.primitives[0].type != PrimitiveType::kTriangle;
  }
  EXPECT_TRUE(first && last && line);
}

// rule: DRIVER.IMPRECISE.VALUES, FUZZ.VALUES.EXACT, FUZZ.VALUES.LEGAL, FUZZ.SHRINK
TEST(PlantedValueBugs, D24TruncationIsFoundExactlyAndIsLegalWhereRoundingIsOnlyAShould) {
  const Summary exact = value_campaign("imprecise:d24-truncate", Profile::kD3D11, Mode::kExact, 80);
  expect_value_findings(exact, "PIPE.DEPTH.FORMAT");
  for (const Finding& f : exact.findings) {
    EXPECT_EQ(f.shrunk.conventions.depth, pipe::DepthFormat::kD24) << f.key;
    for (const ValueDiff& v : f.comparison.values->diffs)
      EXPECT_EQ(v.got, v.expected - 1) << f.key; // truncation: one unit below the rounding
  }
  // Vulkan and OpenGL: rounding to nearest is a "should": truncation is within the allowance.
  EXPECT_EQ(value_campaign("imprecise:d24-truncate", Profile::kVulkan, Mode::kLegal, 80).mismatches,
            0u);
  // The reference against itself: no value beyond, and the largest distance at most one step.
  const Summary ref = value_campaign("reference", Profile::kD3D11, Mode::kExact, 80);
  EXPECT_EQ(ref.mismatches, 0u);
  EXPECT_GT(ref.value_attributes, 0u);
  ASSERT_TRUE(ref.worst_attribute && ref.worst_depth);
  EXPECT_LE(ref.worst_attribute->distance, 1.0);
  EXPECT_LE(ref.worst_depth->distance, 1.0);
}

} // namespace
} // namespace rastrules::fuzzer
