// SPDX-License-Identifier: MIT
// Depth and attribute values of pipeline scenes: the reference and `rastrules render` as an
// external driver report the kernel's values, the protocol reads them strictly, the comparison
// measures each value against the exactly rounded one (exact and legal modes), and the values
// campaign generates its hard cases.

#include <gtest/gtest.h>

#include <unistd.h>

#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <variant>

#include "fuzzer_test_support.hpp"
#include "rastrules/driver/driver.hpp"
#include "rastrules/driver/external.hpp"
#include "rastrules/fuzzer/fuzzer.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/pipeline.hpp"

namespace rastrules::fuzzer {
namespace {

using test::open;

// A clip-space scene with one attribute of each interpolation and a depth state: a triangle
// with a w ratio of 1000 and a line strip.
Scene pipeline_scene(pipe::DepthFormat format, pipe::Provoking provoking, bool strip) {
  Scene s;
  s.width = 12;
  s.height = 10;
  s.conventions.depth = format;
  s.conventions.provoking = provoking;
  s.attributes = {{"u", pipe::Interpolation::kPerspective, pipe::Location::kCenter},
                  {"v", pipe::Interpolation::kLinear, pipe::Location::kCenter},
                  {"k", pipe::Interpolation::kFlat, pipe::Location::kCenter}};
  pipe::DepthState d;
  d.func = pipe::CompareFunc::kAlways;
  s.depth = d;
  Primitive t;
  t.type = PrimitiveType::kTriangle;
  t.v.clear();
  t.pos = {{-0.9f, -0.8f, 0.1f, 1.0f}, {0.9f, -0.6f, 0.0005f, 0.001f}, {0.1f, 0.9f, 0.4f, 0.5f}};
  t.attr = {{0.0f, 1.0f, 10.0f}, {1.0f, 2.0f, 20.0f}, {0.25f, 3.0f, 30.0f}};
  s.primitives.push_back(t);
  if (strip) {
    Primitive l;
    l.type = PrimitiveType::kLineStrip;
    l.v.clear();
    l.pos = {{-0.95f, 0.9f, 0.2f, 1.0f}, {0.5f, 0.2f, 0.1f, 0.25f}, {0.9f, -0.9f, 0.9f, 1.0f}};
    l.attr = {{1.0f, 0.0f, 1.0f}, {2.0f, 1.0f, 2.0f}, {3.0f, 5.0f, 3.0f}};
    s.primitives.push_back(l);
  }
  return s;
}

driver::Drawing draw_values(driver::Driver& d, const Scene& s) {
  driver::ValuesResult r = d.draw_values(s);
  EXPECT_TRUE(std::holds_alternative<driver::Drawing>(r))
      << std::get<driver::DriverError>(r).message;
  return std::holds_alternative<driver::Drawing>(r) ? std::get<driver::Drawing>(r)
                                                    : driver::Drawing{};
}

// rule: DRIVER.VALUES, DRIVER.REFERENCE
TEST(DriverValues, TheReferenceReportsTheKernelsValuesForEveryFormatAndProvokingVertex) {
  auto ref = open("reference");
  ASSERT_TRUE(ref->info().values);
  for (const auto format :
       {pipe::DepthFormat::kD16, pipe::DepthFormat::kD24, pipe::DepthFormat::kD32F}) {
    for (const auto provoking : {pipe::Provoking::kFirst, pipe::Provoking::kLast}) {
      const Scene s = pipeline_scene(format, provoking, true);
      const driver::Drawing d = draw_values(*ref, s);
      ASSERT_FALSE(d.fragments.empty());
      ASSERT_EQ(d.values.size(), d.fragments.size());
      auto run = pipe::run_pipeline(s);
      ASSERT_TRUE(std::holds_alternative<pipe::PipeResult>(run));
      const pipe::PipeResult& r = std::get<pipe::PipeResult>(run);
      // Every non-helper fragment of the pipeline, with its values, is reported.
      std::size_t n = 0;
      for (std::size_t i = 0; i < r.fragments.size(); ++i) {
        if (r.fragments[i].helper)
          continue;
        ++n;
        bool found = false;
        for (std::size_t j = 0; j < d.fragments.size() && !found; ++j) {
          found = d.fragments[j] == r.fragments[i] && d.values[j].part == r.data[i].part &&
                  d.values[j].attr == r.data[i].attr && d.values[j].depth == r.data[i].depth;
        }
        EXPECT_TRUE(found) << "fragment " << i;
      }
      EXPECT_EQ(n, d.fragments.size());
      // draw() gives the same fragments, and the coverage of the kernel's render().
      auto cov = ref->draw(s);
      ASSERT_TRUE(std::holds_alternative<std::vector<Fragment>>(cov));
      EXPECT_EQ(std::get<std::vector<Fragment>>(cov), d.fragments);
    }
  }
}

// rule: DRIVER.VALUES, DRIVER.EXTERNAL.PROTOCOL, FUZZ.VALUES.EXACT
TEST(DriverValues, RastrulesRenderIsAnExternalDriverThatReturnsTheSameValues) {
  auto ref = open("reference");
  auto ext = open("external:" + std::string(RASTRULES_CLI) + " render - --fragments -");
  ASSERT_TRUE(ext->info().values);
  for (const auto format : {pipe::DepthFormat::kD24, pipe::DepthFormat::kD32F}) {
    const Scene s = pipeline_scene(format, pipe::Provoking::kLast, true);
    const driver::Drawing a = draw_values(*ref, s);
    const driver::Drawing b = draw_values(*ext, s);
    EXPECT_EQ(a.fragments, b.fragments);
    EXPECT_EQ(a.values, b.values);
    std::string err;
    auto c = draw_and_compare(*ext, s, Profile::kVulkan, Mode::kExact, &err);
    ASSERT_TRUE(c) << err;
    EXPECT_TRUE(c->match);
    ASSERT_TRUE(c->values);
    EXPECT_EQ(c->values->beyond, 0u);
    EXPECT_GT(c->values->attributes, 0u);
    EXPECT_GT(c->values->depths, 0u);
  }
}

// rule: DRIVER.EXTERNAL.PROTOCOL, DRIVER.VALUES
TEST(DriverValues, TheProtocolReadsValuesStrictlyNamingTheFragmentAndField) {
  const Scene s = pipeline_scene(pipe::DepthFormat::kD16, pipe::Provoking::kFirst, false);
  const auto error_of = [&](const std::string& fragment) {
    auto r = driver::parse_external_drawing("{\"fragments\": [" + fragment + "]}", s);
    return std::holds_alternative<std::string>(r) ? std::get<std::string>(r) : std::string();
  };
  const std::string ok =
      R"({"prim": 0, "part": 2, "x": 1, "y": 1, "mask": 1, "bary": [1, 2, 3, 6], )"
      R"("attr": {"k": 10, "u": 0.5, "v": "NaN"}, "depth": [65535], "passed": 1})";
  EXPECT_EQ(error_of(ok), "");
  auto r = driver::parse_external_drawing("{\"fragments\": [" + ok + "]}", s);
  const auto& d = std::get<driver::Drawing>(r);
  ASSERT_EQ(d.values.size(), 1u);
  EXPECT_EQ(d.values[0].part, 2u);
  EXPECT_EQ(d.values[0].attr[0], 0.5f);
  EXPECT_TRUE(std::isnan(d.values[0].attr[1]));
  EXPECT_EQ(d.values[0].attr[2], 10.0f);
  EXPECT_EQ(d.values[0].depth[0].unorm, 65535u);
  EXPECT_NE(error_of(R"({"prim": 0, "x": 1, "y": 1, "attr": {"u": 1, "v": 2}})")
                .find("fragments[0].attr.k: missing"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"prim": 0, "x": 1, "y": 1, "attr": {"w": 1}})")
                .find("fragments[0].attr.w: not an attribute the scene declares"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"prim": 0, "x": 1, "y": 1, "attr": {"u": [1]}})")
                .find("fragments[0].attr.u: must be a number"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"prim": 0, "x": 1, "y": 1, "depth": [65536]})")
                .find("fragments[0].depth[0]: must be an integer in [0, 65535] (d16)"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"prim": 0, "x": 1, "y": 1, "depth": []})")
                .find("fragments[0].depth: 0 value(s) for the 1 sample(s) of mask 1"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"prim": 0, "x": 1, "y": 1, "passed": 2})")
                .find("fragments[0].passed: must be a sample mask"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"prim": 0, "x": 1, "y": 1, "bary": [1, 2, 3]})")
                .find("fragments[0].bary: must be [e0, e1, e2, A], four integers"),
            std::string::npos);
  // The same pixel in two parts is two fragments; twice in one part a duplicate.
  EXPECT_EQ(
      error_of(R"({"prim": 0, "part": 0, "x": 1, "y": 1}, {"prim": 0, "part": 1, "x": 1, "y": 1})"),
      "");
  EXPECT_NE(
      error_of(R"({"prim": 0, "part": 1, "x": 1, "y": 1}, {"prim": 0, "part": 1, "x": 1, "y": 1})")
          .find("fragments[1]: duplicate"),
      std::string::npos);
  // Values the scene has no place for.
  Scene plain = s;
  plain.attributes.clear();
  plain.depth.reset();
  for (Primitive& p : plain.primitives)
    p.attr.clear();
  auto bad = driver::parse_external_drawing(
      R"({"fragments": [{"prim": 0, "x": 1, "y": 1, "attr": {"u": 1}}]})", plain);
  ASSERT_TRUE(std::holds_alternative<std::string>(bad));
  EXPECT_NE(std::get<std::string>(bad).find("fragments[0].attr: the scene declares no attributes"),
            std::string::npos);
  bad = driver::parse_external_drawing(
      R"({"fragments": [{"prim": 0, "x": 1, "y": 1, "depth": [0]}]})", plain);
  ASSERT_TRUE(std::holds_alternative<std::string>(bad));
  EXPECT_NE(std::get<std::string>(bad).find("fragments[0].depth: the scene has no depth"),
            std::string::npos);
}

float ulps_up(float v, int n) {
  return std::bit_cast<float>(std::bit_cast<std::uint32_t>(v) + static_cast<std::uint32_t>(n));
}

// rule: FUZZ.VALUES.EXACT, FUZZ.VALUES.LEGAL
TEST(ValueComparison, DistancesAreMeasuredFromTheExactlyRoundedValueInEachMode) {
  auto ref = open("reference");
  const Scene s = pipeline_scene(pipe::DepthFormat::kD24, pipe::Provoking::kFirst, false);
  const driver::Drawing d = draw_values(*ref, s);
  std::string err;
  for (const Mode mode : {Mode::kExact, Mode::kLegal}) {
    auto same = compare_values(s, d, Profile::kVulkan, mode, &err);
    ASSERT_TRUE(same) << err;
    EXPECT_EQ(same->beyond, 0u);
    EXPECT_EQ(same->attributes, 3 * d.fragments.size());
    EXPECT_EQ(same->depths, d.fragments.size());
    ASSERT_TRUE(same->worst_attribute && same->worst_depth);
    EXPECT_LE(same->worst_attribute->distance, 1.0); // PIPE.INTERP.BOUND: within one step
    EXPECT_LE(same->worst_depth->distance, 1.0);
  }
  // A linear attribute 1000 steps off and a flat one 1 step off are beyond both modes; a D24
  // depth one unit off is beyond the exact mode only (Vulkan: round to nearest is a "should").
  driver::Drawing bent = d;
  const std::size_t mid = bent.fragments.size() / 2;
  bent.values[mid].attr[1] = ulps_up(bent.values[mid].attr[1], 1000);
  bent.values[mid].attr[2] = ulps_up(bent.values[mid].attr[2], 1);
  bent.values[0].depth[0].unorm += 1;
  auto exact = compare_values(s, bent, Profile::kVulkan, Mode::kExact, &err);
  ASSERT_TRUE(exact) << err;
  ASSERT_EQ(exact->diffs.size(), exact->beyond);
  EXPECT_GE(exact->beyond, 2u);
  bool linear = false, flat = false;
  for (const ValueDiff& v : exact->diffs) {
    EXPECT_FALSE(v.within);
    if (v.what == "attr v") {
      linear = true;
      EXPECT_EQ(v.rule, "PIPE.INTERP.LINEAR");
      EXPECT_GE(v.distance, 999.0);
      EXPECT_EQ(v.x, bent.fragments[mid].x);
    }
    if (v.what == "attr k") {
      flat = true;
      EXPECT_EQ(v.rule, "PIPE.INTERP.FLAT");
      EXPECT_EQ(v.distance, 1.0);
    }
  }
  EXPECT_TRUE(linear && flat);
  ASSERT_TRUE(exact->worst_attribute);
  EXPECT_GE(exact->worst_attribute->distance, 999.0);
  auto legal = compare_values(s, bent, Profile::kVulkan, Mode::kLegal, &err);
  ASSERT_TRUE(legal) << err;
  EXPECT_EQ(legal->beyond, 2u);
  for (const ValueDiff& v : legal->diffs)
    EXPECT_NE(v.what.substr(0, 5), "depth");
  // draw_and_compare: the case mismatches, grouped by the rule of its first value.
  Comparison c;
  c.values = *exact;
  const GroupKey k = classify(s, c);
  EXPECT_EQ(k.rule, exact->diffs.front().rule);
  EXPECT_NE(k.klass.find("triangle "), std::string::npos) << k.klass;
  // rule: FUZZ.GROUP
  // A coverage difference of a pipeline scene is the pipeline's (no window-space decision).
  Comparison coverage;
  coverage.missing = {DiffEntry{0, 3, 3, 1}};
  EXPECT_EQ(classify(s, coverage), (GroupKey{"SCENE.PIPELINE", "triangle missing"}));
}

// rule: FUZZ.VALUES.REPORT
TEST(ValueComparison, ACheckReportsTheValuesComparedAndTheWorstCases) {
  auto ref = open("reference");
  const Scene s = pipeline_scene(pipe::DepthFormat::kD32F, pipe::Provoking::kLast, true);
  Settings settings;
  settings.driver_name = "reference";
  const Summary sum = run_check(*ref, s, settings);
  ASSERT_TRUE(sum.error.empty()) << sum.error;
  EXPECT_EQ(sum.mismatches, 0u);
  EXPECT_EQ(sum.value_cases, 1u);
  EXPECT_GT(sum.value_attributes, 0u);
  EXPECT_GT(sum.value_depths, 0u);
  ASSERT_TRUE(sum.worst_attribute && sum.worst_depth);
  EXPECT_TRUE(sum.worst_attribute->within);
}

// rule: FUZZ.VALUES.GENERATE
TEST(ValueCampaign, GeneratedScenesAreDeterministicAndReachTheHardCases) {
  auto ref = open("reference");
  std::set<std::string> families;
  std::set<pipe::DepthFormat> formats;
  std::set<pipe::Provoking> provoking;
  bool w_ratio = false, behind = false, wide = false, strip = false, huge = false,
       subnormal = false, near0 = false, near1 = false, msaa = false;
  for (std::uint64_t i = 0; i < 300; ++i) {
    const auto c = generate_value_case(5, i, Profile::kVulkan, *ref);
    ASSERT_TRUE(c);
    const auto again = generate_value_case(5, i, Profile::kVulkan, *ref);
    ASSERT_TRUE(again);
    EXPECT_EQ(io::write_scene(c->scene), io::write_scene(again->scene));
    ASSERT_TRUE(std::holds_alternative<std::optional<PreparedScene>>(pipe::check_scene(c->scene)))
        << io::write_scene(c->scene);
    families.insert(c->family);
    msaa = msaa || c->scene.msaa.count() == 4;
    formats.insert(c->scene.conventions.depth);
    provoking.insert(c->scene.conventions.provoking);
    ASSERT_TRUE(c->scene.depth);
    ASSERT_FALSE(c->scene.attributes.empty());
    for (const Primitive& p : c->scene.primitives) {
      strip = strip || (p.type == PrimitiveType::kLineStrip && p.pos.size() >= 3);
      float wmin = INFINITY, wmax = 0;
      for (const pipe::Vec4f& v : p.pos) {
        wmin = std::min(wmin, v[3]);
        wmax = std::max(wmax, v[3]);
        behind = behind || v[2] < 0;
        wide = wide || std::fabs(v[0]) > v[3];
      }
      w_ratio = w_ratio || (!p.pos.empty() && wmax >= 1e5f * wmin);
      for (const auto& vertex : p.attr) {
        for (const float a : vertex) {
          huge = huge || std::fabs(a) >= 0x1p100f;
          subnormal = subnormal || (a != 0 && std::fabs(a) < 0x1p-126f);
        }
      }
      for (const float z : p.z) {
        near0 = near0 || (z > 0 && z < 0x1p-12f);
        near1 = near1 || (z < 1 && z > 1 - 0x1p-12f);
      }
    }
  }
  EXPECT_EQ(families.size(), kValueFamilies.size());
  EXPECT_EQ(formats.size(), 3u);
  EXPECT_EQ(provoking.size(), 2u);
  EXPECT_TRUE(w_ratio && behind && wide && strip && huge && subnormal && near0 && near1 && msaa)
      << w_ratio << behind << wide << strip << huge << subnormal << near0 << near1 << msaa;
  // An external driver that declares no values (DRIVER.EXTERNAL.CAPABILITIES) reports none.
  auto caps = driver::parse_capabilities(R"({"capabilities": {"values": false}})");
  ASSERT_TRUE(std::holds_alternative<driver::Capabilities>(caps));
  EXPECT_FALSE(std::get<driver::Capabilities>(caps).values);
  driver::DriverInfo info = ref->info();
  driver::apply_capabilities(std::get<driver::Capabilities>(caps), info);
  EXPECT_FALSE(info.values);
  EXPECT_TRUE(std::holds_alternative<std::string>(
      driver::parse_capabilities(R"({"capabilities": {"values": 1}})")));
  // A driver that reports no values gets no value scene, and says why.
  auto coverage_only = open("imprecise:float-edges");
  EXPECT_FALSE(generate_value_case(5, 0, Profile::kD3D11, *coverage_only));
  const auto why = value_families_not_generated(Profile::kD3D11, *coverage_only);
  ASSERT_EQ(why.size(), kValueFamilies.size());
  EXPECT_NE(why[0].second.find("reports no values"), std::string::npos);
}

// rule: FUZZ.VALUES.REPORT, FUZZ.REPORT
TEST(ValueCampaign, TheReportHoldsTheValuesTheirWorstCasesAndEachFindingsPicture) {
  auto d = open("imprecise:d24-truncate");
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("rastrules-values-" + std::to_string(::getpid()));
  Settings settings;
  settings.driver_name = "imprecise:d24-truncate";
  settings.values = true;
  settings.cases = 20;
  settings.out_dir = dir.string();
  const Summary s = run_fuzz(*d, settings);
  ASSERT_TRUE(s.error.empty()) << s.error;
  ASSERT_GT(s.unique, 0u);
  std::ifstream in(dir / "report.json");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const char* key : {"\"values_campaign\": true", "\"worst_depth\": {", "\"differences\": [",
                          "\"value\": \"depth[0]\"", "\"rule\": \"PIPE.DEPTH.FORMAT\""})
    EXPECT_NE(text.find(key), std::string::npos) << key;
  std::ifstream page(dir / "index.html");
  const std::string html((std::istreambuf_iterator<char>(page)), std::istreambuf_iterator<char>());
  EXPECT_NE(html.find("values beyond the allowance"), std::string::npos);
  EXPECT_NE(html.find("<td>depth[0]</td><td>PIPE.DEPTH.FORMAT</td>"), std::string::npos);
  for (const Finding& f : s.findings) {
    if (!f.duplicate_of) {
      EXPECT_TRUE(std::filesystem::exists(f.files.picture)) << f.files.picture;
    }
  }
  std::filesystem::remove_all(dir);
}

// rule: FUZZ.VALUES.REPORT, FUZZ.MERGE
TEST(ValueCampaign, ShardsMergeIntoTheCampaignsValuesAndRefuseACoverageShard) {
  auto d = open("imprecise:d24-truncate");
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("rastrules-values-merge-" + std::to_string(::getpid()));
  Settings whole;
  whole.driver_name = "imprecise:d24-truncate";
  whole.values = true;
  whole.cases = 30;
  whole.out_dir = (dir / "whole").string();
  const Summary w = run_fuzz(*d, whole);
  ASSERT_TRUE(w.error.empty()) << w.error;
  std::vector<std::string> dirs;
  for (std::uint64_t k = 0; k < 2; ++k) {
    Settings part = whole;
    part.shard_index = k;
    part.shard_count = 2;
    part.out_dir = (dir / ("shard" + std::to_string(k))).string();
    dirs.push_back(part.out_dir);
    ASSERT_TRUE(run_fuzz(*d, part).error.empty());
  }
  Settings merged;
  std::string description, err;
  auto m = merge_reports(dirs, &merged, &description, &err);
  ASSERT_TRUE(m) << err;
  EXPECT_TRUE(merged.values);
  EXPECT_EQ(m->value_cases, w.value_cases);
  EXPECT_EQ(m->value_attributes, w.value_attributes);
  EXPECT_EQ(m->value_depths, w.value_depths);
  ASSERT_TRUE(m->worst_depth && w.worst_depth);
  EXPECT_EQ(m->worst_depth->distance, w.worst_depth->distance);
  EXPECT_EQ(m->worst_depth_case, w.worst_depth_case);
  ASSERT_EQ(m->findings.size(), w.findings.size());
  for (std::size_t i = 0; i < w.findings.size(); ++i) {
    ASSERT_TRUE(m->findings[i].comparison.values && w.findings[i].comparison.values);
    EXPECT_EQ(m->findings[i].comparison.values->beyond, w.findings[i].comparison.values->beyond);
    EXPECT_EQ(m->findings[i].group, w.findings[i].group);
  }
  // A shard of a coverage campaign is not a shard of this one.
  Settings coverage = whole;
  coverage.values = false;
  coverage.shard_index = 1;
  coverage.shard_count = 2;
  coverage.out_dir = (dir / "coverage").string();
  auto plain = open("imprecise");
  ASSERT_TRUE(run_fuzz(*plain, coverage).error.empty());
  coverage.driver_name = "imprecise";
  EXPECT_FALSE(merge_reports({dirs[0], coverage.out_dir}, &merged, &description, &err));
  EXPECT_NE(err.find("values_campaign"), std::string::npos) << err;
  std::filesystem::remove_all(dir);
}

} // namespace
} // namespace rastrules::fuzzer
