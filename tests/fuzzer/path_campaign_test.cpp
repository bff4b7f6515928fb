// SPDX-License-Identifier: MIT
// The 2D campaign (FUZZ.PATH.*): each planted bug of DRIVER.PATH.PLANTED is found, classified as
// the bug it is and shrunk to a path of at most 2 contours; the reference agrees with itself;
// classification of hand-made rasters; generation is deterministic and on the driver's grid.

#include <filesystem>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "rastrules/driver/driver.hpp"
#include "rastrules/fuzzer/paths.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/path.hpp"

namespace rastrules::fuzzer::paths {
namespace {

std::unique_ptr<driver::Driver> open(const std::string& name) {
  std::string error;
  auto d = driver::open_driver(name, &error);
  EXPECT_NE(d, nullptr) << error;
  return d;
}

std::size_t contours(const Scene& s) {
  std::size_t n = 0;
  for (const Primitive& p : s.primitives)
    if (p.path)
      n += p.path->contours.size();
  return n;
}

struct Planted {
  const char* bug;
  DiffClass klass;
  std::uint64_t cases; // enough for seed 1 to find it (the campaign is deterministic)
};

class PathPlantedBug : public ::testing::TestWithParam<Planted> {};

// rule: DRIVER.PATH.PLANTED, FUZZ.PATH.GENERATE, FUZZ.PATH.CLASSIFY, FUZZ.PATH.SHRINK
TEST_P(PathPlantedBug, IsFoundClassifiedAndShrunkToAtMostTwoContours) {
  auto d = open(std::string("imprecise-path:") + GetParam().bug);
  ASSERT_NE(d, nullptr);
  PathSettings settings;
  settings.cases = GetParam().cases;
  settings.max_findings = 1;
  const PathSummary s = run_path_fuzz(*d, settings);
  ASSERT_EQ(s.error, "");
  EXPECT_EQ(s.cases, GetParam().cases);
  const auto k = static_cast<std::size_t>(GetParam().klass);
  EXPECT_GT(s.cases_by_class[k], 0u) << "no case of class " << to_string(GetParam().klass);
  bool shrunk = false;
  for (const PathFinding& f : s.findings) {
    if (f.klass != GetParam().klass)
      continue;
    shrunk = true;
    EXPECT_LE(contours(f.shrunk), 2u) << "case " << f.case_index;
    EXPECT_GT(f.comparison.by_class[k], 0u) << "the shrunk scene lost the difference";
  }
  EXPECT_TRUE(shrunk);
}

INSTANTIATE_TEST_SUITE_P(
    Bugs, PathPlantedBug,
    ::testing::Values(Planted{"float-accumulation", DiffClass::kConflation, 30},
                      Planted{"4-bit-winding", DiffClass::kWindingOverflow, 100},
                      Planted{"flatten-quarter", DiffClass::kFlattening, 60}),
    [](const auto& param_info) {
      std::string n = param_info.param.bug;
      for (char& c : n)
        if (c == '-')
          c = '_';
      return n;
    });

// rule: FUZZ.PATH.COMPARE
TEST(PathCampaign, TheReferenceAgreesWithItselfOnEveryFamily) {
  auto d = open("reference");
  ASSERT_NE(d, nullptr);
  PathSettings settings;
  settings.cases = 48;
  const PathSummary s = run_path_fuzz(*d, settings);
  ASSERT_EQ(s.error, "");
  EXPECT_EQ(s.cases, 48u);
  EXPECT_EQ(s.mismatches, 0u);
  EXPECT_EQ(s.max_alpha_error, 0);
  EXPECT_EQ(s.families.size(), available_path_families(d->info()).size());
  // The reference decides ties top-left: the campaign says so.
  EXPECT_GT(s.tie_pixels, 0u);
  EXPECT_EQ(s.conventions & 1u, 1u);
}

Scene square_twice(path::FillRule rule, path::Coverage coverage) {
  Scene s;
  s.width = s.height = 2;
  FloatPath p;
  p.fill_rule = rule;
  p.coverage = coverage;
  for (int k = 0; k < 2; ++k) {
    FloatContour c;
    c.start = {0.5f, 0};
    for (const FloatPoint q : {FloatPoint{1, 0}, FloatPoint{1, 1}, FloatPoint{0.5f, 1}}) {
      FloatPathSegment seg;
      seg.p[0] = q;
      c.segments.push_back(seg);
    }
    p.contours.push_back(c);
  }
  s.primitives.push_back(make_path(std::move(p)));
  return s;
}

Fragment alpha_fragment(std::int32_t x, std::int32_t y, int alpha) {
  Fragment f(0, x, y, 1);
  f.area = ExactArea(std::make_shared<const path::AreaValue>(
      path::AreaValue{boost::multiprecision::cpp_rational(alpha, 255), 0}));
  return f;
}

// rule: FUZZ.PATH.CLASSIFY
TEST(PathCampaign, AHalfPixelDrawnTwiceUnderEvenOddIsConflationWhenFilledAndLegalWhenEmpty) {
  // Exact: empty (winding 2 is even). An accumulation rasterizer: |s| = 2 * 1/2 = 1 -> 255.
  const Scene s = square_twice(path::FillRule::kEvenOdd, path::Coverage::kArea);
  std::string error;
  auto c = compare_paths(s, {alpha_fragment(0, 0, 255)}, {}, &error);
  ASSERT_TRUE(c) << error;
  ASSERT_EQ(c->diffs.size(), 1u);
  EXPECT_EQ(c->diffs[0].expected, 0);
  EXPECT_EQ(c->diffs[0].actual, 255);
  EXPECT_EQ(c->diffs[0].klass, DiffClass::kConflation);
  EXPECT_NE(c->diffs[0].why.find("windings {0: 1/2, 2: 1/2}"), std::string::npos)
      << c->diffs[0].why;
  // The exact answer, and one alpha off it (within the default tolerance of 1).
  EXPECT_TRUE(compare_paths(s, {}, {}, &error)->match);
  EXPECT_TRUE(compare_paths(s, {alpha_fragment(0, 0, 1)}, {}, &error)->match);
  PathCompareOptions strict;
  strict.alpha_tolerance = 0;
  EXPECT_FALSE(compare_paths(s, {alpha_fragment(0, 0, 1)}, strict, &error)->match);
  // An alpha no model explains.
  auto other = compare_paths(s, {alpha_fragment(0, 0, 100)}, {}, &error);
  ASSERT_EQ(other->diffs.size(), 1u);
  EXPECT_EQ(other->diffs[0].klass, DiffClass::kOther);
}

// rule: FUZZ.PATH.COMPARE
TEST(PathCampaign, AnAliasedPixelCentreOnTheBoundaryIsALegalTieOrInExactModeADifference) {
  // The right half of pixel 0: its centre (0.5, 0.5) is on the left edge, inside under the
  // top-left convention (PATH.SAMPLE.TIE); a library that leaves it out is legal.
  const Scene s = square_twice(path::FillRule::kNonZero, path::Coverage::kSamples);
  std::string error;
  auto legal = compare_paths(s, {}, {}, &error);
  ASSERT_TRUE(legal) << error;
  EXPECT_TRUE(legal->match);
  EXPECT_EQ(legal->legal_ties, 1u);
  PathCompareOptions exact;
  exact.legal = false;
  auto strict = compare_paths(s, {}, exact, &error);
  ASSERT_EQ(strict->diffs.size(), 1u);
  EXPECT_EQ(strict->diffs[0].klass, DiffClass::kBoundaryTie);
}

// rule: FUZZ.PATH.GENERATE
TEST(PathCampaign, CasesAreDeterministicAndOnTheDriversGrid) {
  driver::DriverInfo info;
  info.paths.samples = info.paths.area = info.paths.nonzero = info.paths.evenodd = true;
  info.paths.quadratics = true;
  info.paths.grid_raw = 4;
  info.max_target_side = 64;
  for (std::uint64_t i = 0; i < 64; ++i) {
    const auto a = generate_path_case(7, i, info), b = generate_path_case(7, i, info);
    ASSERT_TRUE(a && b);
    EXPECT_EQ(a->family, b->family);
    EXPECT_EQ(io::write_scene(a->scene), io::write_scene(b->scene));
    auto prepared = prepare(a->scene);
    ASSERT_TRUE(std::holds_alternative<PreparedScene>(prepared)) << i;
    const path::Path& p = *std::get<PreparedScene>(prepared).primitives[0].path;
    for (const path::Contour& c : p.contours) {
      EXPECT_EQ(c.start.x % 4, 0);
      for (const path::Segment& seg : c.segments) {
        EXPECT_NE(seg.kind, path::SegmentKind::kCubic) << "the driver has no cubics";
        for (std::size_t k = 0; k < path::point_count(seg.kind); ++k)
          EXPECT_EQ(seg.p[k].y % 4, 0);
      }
    }
  }
}

} // namespace
} // namespace rastrules::fuzzer::paths

namespace rastrules::fuzzer::paths {
namespace {

// rule: FUZZ.PATH.REPORT
TEST(PathCampaign, TheReportListsEveryFindingWithItsScenesAndPicture) {
  auto d = open("imprecise-path:float-accumulation");
  ASSERT_NE(d, nullptr);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() /
      ("rastrules-fuzz2d-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
       "-" + std::to_string(reinterpret_cast<std::uintptr_t>(d.get())));
  std::filesystem::remove_all(dir);
  PathSettings settings;
  settings.cases = 30;
  settings.max_findings = 1;
  settings.out_dir = dir.string();
  const PathSummary s = run_path_fuzz(*d, settings);
  ASSERT_EQ(s.error, "");
  ASSERT_FALSE(s.findings.empty());
  EXPECT_TRUE(std::filesystem::exists(dir / "report.json"));
  for (const PathFinding& f : s.findings) {
    EXPECT_TRUE(std::filesystem::exists(f.scene_file)) << f.scene_file;
    EXPECT_TRUE(std::filesystem::exists(f.shrunk_file)) << f.shrunk_file;
    EXPECT_GT(std::filesystem::file_size(f.picture_file), 100u) << f.picture_file;
  }
  std::filesystem::remove_all(dir);
}

} // namespace
} // namespace rastrules::fuzzer::paths

namespace rastrules::fuzzer::paths {
namespace {

// rule: FUZZ.PATH.PROBE
TEST(PathProbe, FindsThePlantedAccumulationAndItsRounding) {
  auto d = open("imprecise-path:float-accumulation");
  ASSERT_NE(d, nullptr);
  const PathProbeReport r = probe_path_library(*d);
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.twice_evenodd, 255); // signed areas accumulated: conflation
  EXPECT_EQ(r.levels_x, 65);
  EXPECT_EQ(r.levels_y, 65);
  EXPECT_EQ(r.max_edge_error, 0);
  EXPECT_TRUE(r.quantisation.starts_with("floor(255 a + 1/2)")) << r.quantisation;
  EXPECT_EQ(r.quadratic, -1);        // no curves
  EXPECT_TRUE(r.convention.empty()); // no aliased paths
}

// rule: FUZZ.PATH.PROBE
TEST(PathProbe, ReportsEachLibrarysConventionGridAndMethod) {
  struct Expected {
    const char* driver;
    const char* convention;
    int twice_evenodd;
    const char* quantisation;
  };
  for (const Expected& e : {Expected{"cairo", "top-left", 0, "min(255, floor(256 a))"},
                            Expected{"agg",
                                     "none of PATH.SAMPLE.TIE's (left in, right in, top in, "
                                     "bottom in)",
                                     255, "min(255, floor(256 a))"},
                            Expected{"freetype",
                                     "none of PATH.SAMPLE.TIE's (left in, right in, "
                                     "top in, bottom in)",
                                     255, "min(255, floor(256 a))"}}) {
    std::string error;
    auto d = driver::open_driver(e.driver, &error);
    if (d == nullptr) {
      EXPECT_TRUE(error.starts_with("unknown driver")) << error;
      continue; // not built here
    }
    SCOPED_TRACE(e.driver);
    const PathProbeReport r = probe_path_library(*d);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.convention, e.convention);
    EXPECT_EQ(r.twice_evenodd, e.twice_evenodd);
    EXPECT_TRUE(r.quantisation.starts_with(e.quantisation)) << r.quantisation;
    EXPECT_EQ(r.snap_extent, 0);
    EXPECT_GE(r.levels_x, 60);
  }
}

} // namespace
} // namespace rastrules::fuzzer::paths
