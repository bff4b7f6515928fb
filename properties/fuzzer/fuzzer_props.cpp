// SPDX-License-Identifier: MIT
// Campaign outputs on random campaigns of the imprecise driver (its variants, profiles, modes,
// seeds, sizes): the groups count every mismatch and scene once and are the classification of
// each finding; a baseline fails exactly the groups it does not list; the JUnit XML and JSON
// summary count what the campaign found; N shards merged are the campaign. And the legal
// Bresenham allowance on random lines: the reference and one pixel fewer pass, a pixel two
// away or sample 0 alone on 4x does not; and a snapping tie rounded either way passes.
// Implements (properties for): FUZZ.GROUP, FUZZ.BASELINE, FUZZ.RESULTS, FUZZ.SHARD,
//   FUZZ.MERGE, FUZZ.COMPARE.LEGAL_LINES, FUZZ.COMPARE.LEGAL_TIES

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <rapidcheck/gtest.h>

#include "rastrules/driver/driver.hpp"
#include "rastrules/fuzzer/fuzzer.hpp"

namespace {

namespace fz = rastrules::fuzzer;
using rastrules::Fragment;
using rastrules::Scene;

struct Campaign {
  std::string driver;
  fz::Settings settings;
};

rc::Gen<Campaign> campaigns(std::uint64_t max_cases) {
  return rc::gen::map(
      rc::gen::tuple(rc::gen::element<std::string>("imprecise", "imprecise:float-edges",
                                                   "imprecise:fill-bottom-right",
                                                   "imprecise:4-bit-subpixel", "reference"),
                     rc::gen::element(fz::Profile::kD3D11, fz::Profile::kVulkan),
                     rc::gen::element(fz::Mode::kExact, fz::Mode::kLegal),
                     rc::gen::inRange<std::uint64_t>(0, 1000),
                     rc::gen::inRange<std::uint64_t>(1, max_cases + 1)),
      [](const auto& t) {
        Campaign c;
        c.driver = std::get<0>(t);
        c.settings.driver_name = c.driver;
        c.settings.profile = std::get<1>(t);
        c.settings.mode = std::get<2>(t);
        c.settings.seed = std::get<3>(t);
        c.settings.cases = std::get<4>(t);
        return c;
      });
}

std::unique_ptr<rastrules::driver::Driver> open(const std::string& name) {
  std::string err;
  auto d = rastrules::driver::open_driver(name, &err);
  RC_ASSERT(d != nullptr);
  return d;
}

// rule: FUZZ.GROUP
RC_GTEST_PROP(FuzzCampaign, GroupsCountEveryMismatchAndSceneOnce, ()) {
  const Campaign c = *campaigns(40);
  auto d = open(c.driver);
  const fz::Summary s = fz::run_fuzz(*d, c.settings);
  RC_ASSERT(s.error.empty());
  std::uint64_t count = 0, scenes = 0;
  std::set<fz::GroupKey> keys;
  for (const fz::Group& g : s.groups) {
    count += g.count;
    scenes += g.scenes;
    RC_ASSERT(keys.insert(g.key).second);
    RC_ASSERT(!g.key.rule.empty() && !g.key.klass.empty());
  }
  RC_ASSERT(std::is_sorted(keys.begin(), keys.end()));
  RC_ASSERT(count == s.mismatches);
  RC_ASSERT(scenes == s.unique);
  for (const fz::Finding& f : s.findings) {
    RC_ASSERT(f.group == fz::classify(f.shrunk, f.comparison));
    RC_ASSERT(keys.count(f.group) == 1u);
  }
}

// rule: FUZZ.BASELINE, FUZZ.RESULTS
RC_GTEST_PROP(FuzzCampaign, BaselineFailsExactlyTheGroupsItDoesNotList, ()) {
  const Campaign c = *campaigns(40);
  auto d = open(c.driver);
  fz::Summary s = fz::run_fuzz(*d, c.settings);
  RC_ASSERT(s.error.empty());
  const auto pick =
      *rc::gen::container<std::vector<bool>>(s.groups.size(), rc::gen::arbitrary<bool>());
  fz::Baseline b;
  b.path = "known.json";
  std::uint64_t listed = 0;
  for (std::size_t i = 0; i < s.groups.size(); ++i) {
    if (pick[i]) {
      b.known.push_back({s.groups[i].key, "FINDING.X", ""});
      ++listed;
    }
  }
  b.known.push_back({{"NO.SUCH.RULE", "triangle extra"}, "", ""}); // listed, never seen
  const std::uint64_t unknown = fz::apply_baseline(b, s);
  RC_ASSERT(unknown == s.groups.size() - listed);
  for (std::size_t i = 0; i < s.groups.size(); ++i)
    RC_ASSERT(s.groups[i].known == static_cast<bool>(pick[i]));
  // The JSON summary and the JUnit XML count the same.
  const auto j = nlohmann::json::parse(fz::summary_json(c.settings, "d", s, &b));
  RC_ASSERT(j["baseline"]["new_groups"].get<std::uint64_t>() == unknown);
  RC_ASSERT(j["baseline"]["entries_not_seen"].size() == 1u);
  RC_ASSERT(j["result"] == (unknown == 0 ? "pass" : "fail"));
  RC_ASSERT(j["cases"].get<std::uint64_t>() + j["skipped"]["cases"].get<std::uint64_t>() ==
            c.settings.cases);
  const std::string xml = fz::junit_xml(c.settings, s, &b);
  const auto occurrences = [&](const std::string& what) {
    std::uint64_t n = 0;
    for (auto at = xml.find(what); at != std::string::npos; at = xml.find(what, at + 1))
      ++n;
    return n;
  };
  std::uint64_t failing_families = 0;
  for (const auto& [family, n] : s.families) {
    bool bad = false;
    for (const fz::Finding& f : s.findings) {
      for (const fz::Group& g : s.groups)
        bad = bad || (f.family == family && g.key == f.group && !g.known);
    }
    failing_families += bad ? 1 : 0;
  }
  const std::uint64_t tests = s.groups.size() + s.families.size() +
                              s.families_not_generated.size() + (s.skipped != 0 ? 1 : 0);
  RC_ASSERT(occurrences("<testcase ") == tests);
  RC_ASSERT(occurrences("<failure ") == unknown + failing_families);
  RC_ASSERT(occurrences("tests=\"" + std::to_string(tests) + "\"") == 2u);
  RC_ASSERT(occurrences("failures=\"" + std::to_string(unknown + failing_families) + "\"") == 2u);
}

// rule: FUZZ.SHARD, FUZZ.MERGE
RC_GTEST_PROP(FuzzCampaign, ShardsMergedAreTheCampaign, ()) {
  Campaign c = *campaigns(30);
  const std::uint64_t n = *rc::gen::inRange<std::uint64_t>(1, 6);
  std::random_device rd;
  const auto root =
      std::filesystem::temp_directory_path() / ("rastrules-shard-props-" + std::to_string(rd()));
  auto d = open(c.driver);
  const fz::Summary whole = fz::run_fuzz(*d, c.settings);
  RC_ASSERT(whole.error.empty());
  std::vector<std::string> dirs;
  for (std::uint64_t k = 0; k < n; ++k) {
    fz::Settings part = c.settings;
    part.shard_index = k;
    part.shard_count = n;
    part.out_dir = (root / std::to_string(k)).string();
    dirs.push_back(part.out_dir);
    const fz::Summary p = fz::run_fuzz(*d, part);
    RC_ASSERT(p.error.empty());
    for (const fz::Finding& f : p.findings)
      RC_ASSERT(f.case_index % n == k);
  }
  fz::Settings merged_settings;
  std::string description, err;
  const auto m = fz::merge_reports(dirs, &merged_settings, &description, &err);
  std::error_code ec;
  std::filesystem::remove_all(root, ec);
  RC_ASSERT(m.has_value());
  RC_ASSERT(m->cases == whole.cases && m->skipped == whole.skipped);
  RC_ASSERT(m->mismatches == whole.mismatches && m->unique == whole.unique);
  RC_ASSERT(m->findings.size() == whole.findings.size());
  for (std::size_t i = 0; i < whole.findings.size(); ++i) {
    const fz::Finding& a = whole.findings[i];
    const fz::Finding& b = m->findings[i];
    RC_ASSERT(a.case_index == b.case_index && a.family == b.family && a.key == b.key);
    RC_ASSERT(a.group == b.group && a.duplicate_of == b.duplicate_of);
    RC_ASSERT(a.comparison.missing == b.comparison.missing);
    RC_ASSERT(a.comparison.extra == b.comparison.extra);
  }
  RC_ASSERT(m->groups.size() == whole.groups.size());
  for (std::size_t i = 0; i < whole.groups.size(); ++i) {
    RC_ASSERT(m->groups[i].key == whole.groups[i].key);
    RC_ASSERT(m->groups[i].count == whole.groups[i].count);
    RC_ASSERT(m->groups[i].example_case == whole.groups[i].example_case);
  }
}

// rule: FUZZ.COMPARE.LEGAL_LINES
RC_GTEST_PROP(FuzzLegalLines, ReferenceAndOneFewerPassFarPixelsAndSampleZeroDoNot, ()) {
  const auto coord =
      rc::gen::map(rc::gen::inRange(0, 33), [](int q) { return static_cast<float>(q) / 4.0F; });
  Scene s;
  s.width = 8;
  s.height = 8;
  s.conventions.line_mode = rastrules::LineMode::kVulkanBresenham;
  rastrules::Primitive line;
  line.type = rastrules::PrimitiveType::kLine;
  line.v = {{*coord, *coord}, {*coord, *coord}};
  s.primitives.push_back(line);
  const bool msaa = *rc::gen::arbitrary<bool>();
  if (msaa)
    rastrules::set_sample_pattern(s, rastrules::standard_pattern(4));
  auto r = rastrules::render(s);
  RC_PRE(std::holds_alternative<std::vector<Fragment>>(r));
  const std::vector<Fragment> exact = std::get<std::vector<Fragment>>(r);
  const auto legal = [&](const std::vector<Fragment>& got) {
    std::string err;
    const auto c = fz::compare(s, got, fz::Profile::kVulkan, fz::Mode::kLegal, &err);
    RC_ASSERT(c.has_value());
    return c->match;
  };
  RC_ASSERT(legal(exact));
  if (!exact.empty()) {
    auto fewer = exact;
    fewer.erase(fewer.begin() +
                *rc::gen::inRange<std::ptrdiff_t>(0, static_cast<std::ptrdiff_t>(fewer.size())));
    RC_ASSERT(legal(fewer));
    if (msaa) {
      auto sample0 = exact;
      for (Fragment& f : sample0)
        f.mask = 1;
      RC_ASSERT(!legal(sample0));
    }
    // A pixel at least two away from every exact pixel.
    for (std::int32_t y = 0; y < s.height; ++y) {
      for (std::int32_t x = 0; x < s.width; ++x) {
        const bool far = std::all_of(exact.begin(), exact.end(), [&](const Fragment& e) {
          return std::abs(e.x - x) >= 2 || std::abs(e.y - y) >= 2;
        });
        if (!far)
          continue;
        auto more = exact;
        more.push_back(Fragment{0, x, y, exact.front().mask});
        std::sort(more.begin(), more.end(), [](const Fragment& p, const Fragment& q) {
          return std::tie(p.y, p.x) < std::tie(q.y, q.x);
        });
        RC_ASSERT(!legal(more));
        return;
      }
    }
  }
}

// rule: FUZZ.COMPARE.LEGAL_TIES
RC_GTEST_PROP(FuzzLegalTies, EitherRoundingOfEveryTieIsLegal, ()) {
  // A point or a triangle with coordinates on the pixel grid's 1/256 steps or half-way
  // between two of them (a tie of SNAP.VERTEX.ROUND); the same primitive with any of its
  // ties rounded the other way draws what legal mode accepts.
  const auto coord =
      rc::gen::map(rc::gen::pair(rc::gen::inRange(256, 1792), rc::gen::arbitrary<bool>()),
                   [](const std::pair<int, bool>& p) {
                     return (static_cast<float>(p.first) + (p.second ? 0.5F : 0.0F)) / 256.0F;
                   });
  Scene s;
  s.width = 8;
  s.height = 8;
  const bool point = *rc::gen::arbitrary<bool>();
  rastrules::Primitive prim;
  prim.type = point ? rastrules::PrimitiveType::kPoint : rastrules::PrimitiveType::kTriangle;
  prim.v.assign(point ? 1 : 3, {0.0F, 0.0F});
  for (auto& v : prim.v)
    v = {*coord, *coord};
  s.primitives.push_back(prim);
  if (*rc::gen::arbitrary<bool>())
    rastrules::set_sample_pattern(s, rastrules::standard_pattern(4));
  Scene other = s;
  for (auto& v : other.primitives[0].v) {
    for (float& c : v) {
      const double raw = static_cast<double>(c) * 256.0;
      const double below = std::floor(raw);
      if (raw - below == 0.5 && *rc::gen::arbitrary<bool>()) {
        const double odd = std::fmod(below, 2.0) == 0.0 ? below + 1.0 : below;
        c = static_cast<float>(odd / 256.0);
      }
    }
  }
  auto r = rastrules::render(other);
  RC_PRE(std::holds_alternative<std::vector<Fragment>>(r));
  std::string err;
  const auto c = fz::compare(s, std::get<std::vector<Fragment>>(r), fz::Profile::kVulkan,
                             fz::Mode::kLegal, &err);
  RC_ASSERT(c.has_value());
  RC_ASSERT(c->match);
}

// A selection of families (FUZZ.FAMILIES) over random drivers, profiles, seeds and subsets:
// every generated case is of a selected family the driver draws; the families not generated
// are exactly the unselected ones ("not selected (--families)") and the selected ones the
// driver does not draw; and a case is generated whenever one selected family is drawable.
// rule: FUZZ.FAMILIES, FUZZ.GENERATE
RC_GTEST_PROP(FuzzFamilies, ASelectionIsObeyedAndWhatItLeavesOutIsListed, ()) {
  const std::string name = *rc::gen::element<std::string>("imprecise", "reference");
  const auto d = open(name);
  const auto profile = *rc::gen::element(fz::Profile::kD3D11, fz::Profile::kVulkan);
  std::vector<std::string> only;
  for (const std::string_view f : fz::kFamilies) {
    if (*rc::gen::arbitrary<bool>())
      only.emplace_back(f);
  }
  RC_PRE(!only.empty());
  const auto left = fz::families_not_generated(profile, *d, only);
  std::set<std::string> not_generated;
  for (const auto& [family, why] : left) {
    const bool selected = std::find(only.begin(), only.end(), family) != only.end();
    RC_ASSERT(selected == (why != "not selected (--families)"));
    not_generated.insert(family);
  }
  std::vector<std::string> drawable;
  for (const std::string& f : only) {
    if (not_generated.count(f) == 0)
      drawable.push_back(f);
  }
  const auto seed = *rc::gen::inRange<std::uint64_t>(0, 1u << 20);
  for (std::uint64_t i = 0; i < 6; ++i) {
    const auto c = fz::generate_case(seed, i, profile, *d, only);
    if (!drawable.empty())
      RC_ASSERT(c.has_value());
    if (c)
      RC_ASSERT(std::find(drawable.begin(), drawable.end(), c->family) != drawable.end());
  }
  RC_CLASSIFY(drawable.size() < only.size(), "a selected family not drawable");
}

} // namespace
