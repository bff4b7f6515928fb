// SPDX-License-Identifier: MIT
// The hard-case catalog (spec/cases/): every case holds, checked against its sidecar and the
// exact oracle, with and without the optimizations; and the checker can fail.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "rastrules/cases/cases.hpp"

namespace rastrules::cases {
namespace {

const std::filesystem::path kCases = std::filesystem::path(RASTRULES_SOURCE_DIR) / "spec" / "cases";

// rule: PIPE.CATALOG
TEST(PipeCatalog, EveryCaseHolds) {
  const auto scenes = catalog(kCases);
  ASSERT_GE(scenes.size(), 12u);
  for (const auto& scene : scenes) {
    const CaseReport r = check_case(scene);
    EXPECT_TRUE(r.ok()) << format_report({r});
    EXPECT_FALSE(r.rules.empty()) << r.name;
  }
}

// rule: PIPE.CATALOG
TEST(PipeCatalog, AWrongExpectationFails) {
  const auto dir = std::filesystem::temp_directory_path() / "rastrules_catalog_selftest";
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(kCases / "z_fighting_less.json", dir / "z.json",
                             std::filesystem::copy_options::overwrite_existing);
  std::ofstream(dir / "z.expect.json")
      << R"({"rules": ["PIPE.DEPTH.TEST"], "what": "wrong on purpose",
             "expect": {"passed_per_prim": {"1": 1}, "parts": [0]}})";
  const CaseReport r = check_case(dir / "z.json");
  EXPECT_EQ(r.failures.size(), 2u) << format_report({r});
  std::filesystem::remove(dir / "z.expect.json");
  EXPECT_FALSE(check_case(dir / "z.json").ok()); // no sidecar
  std::filesystem::remove_all(dir);
}

} // namespace
} // namespace rastrules::cases
