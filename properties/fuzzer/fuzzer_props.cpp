// SPDX-License-Identifier: MIT
// Campaign outputs on random campaigns of the imprecise driver (its variants, profiles, modes,
// seeds, sizes): the groups count every mismatch and scene once and are the classification of
// each finding.
// Implements (properties for): FUZZ.GROUP

#include <algorithm>
#include <cstdint>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
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

} // namespace
