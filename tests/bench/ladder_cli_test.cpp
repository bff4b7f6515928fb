// SPDX-License-Identifier: MIT
// Examples for BENCH.REPORT through the command line: `rastrules bench --ladder --quick --out
// DIR` writes ladder.md, ladder.json and ladder.png; bad options are one-line errors, exit 2.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support.hpp"

using rastrules::test::run_cli;
using rastrules::test::TempDir;

// rule: BENCH.REPORT
TEST(LadderCli, QuickRunWritesTheTableTheJsonAndThePlot) {
  TempDir dir;
  const auto out = dir / "ladder";
  const auto r = run_cli({"bench", "--ladder", "--quick", "--threads", "2", "--out", out.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("| reference |"), std::string::npos);
  // rule: BENCH.METRIC.THROUGHPUT, BENCH.LAVAPIPE
  EXPECT_NE(r.out.find("\n| reference-fast x2 |"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("rasterizer threads"), std::string::npos) << r.out;
  const std::string md = rastrules::test::read_file(out / "ladder.md");
  EXPECT_EQ(md, r.out);
  const auto j = nlohmann::json::parse(rastrules::test::read_file(out / "ladder.json"));
  EXPECT_TRUE(j.at("quick").get<bool>());
  EXPECT_GE(j.at("rungs").size(), 8u);
  EXPECT_EQ(j.at("threads"), 2);
  EXPECT_EQ(j.at("reference_fast_threaded").size(), j.at("scenes").size());
  EXPECT_TRUE(j.at("lavapipe").contains("threads"));
  EXPECT_FALSE(j.at("lavapipe").at("threads_source").get<std::string>().empty());
  // The reference and the exact oracle agree; the reference keeps its range to the top.
  for (const auto& rung : j.at("rungs")) {
    if (rung.at("rung") == "reference" || rung.at("rung") == "exact") {
      EXPECT_EQ(rung.at("errors"), 0);
      EXPECT_EQ(rung.at("watertight_violations"), 0);
      EXPECT_EQ(rung.at("exact_range"), 8192);
    }
  }
  const auto png = rastrules::test::read_png(out / "ladder.png");
  ASSERT_TRUE(png.has_value());
  EXPECT_GT(png->width, 0u);
}

// rule: BENCH.REPORT
TEST(LadderCli, BadOptionsAreOneLineErrors) {
  const auto none = run_cli({"bench"});
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("--ladder"), std::string::npos);
  for (const auto& args :
       std::vector<std::vector<std::string>>{{"bench", "--ladder", "--seed", "x"},
                                             {"bench", "--ladder", "--seed", "-1"},
                                             {"bench", "--ladder", "--seed"},
                                             {"bench", "--ladder", "--out", ""},
                                             {"bench", "--ladder", "--out", "/dev/null/sub"},
                                             {"bench", "--ladder", "--threads", "0"},
                                             {"bench", "--ladder", "--threads", "257"},
                                             {"bench", "--ladder", "--threads", "x"},
                                             {"bench", "--ladder", "--threads"}}) {
    const auto r = run_cli(args);
    EXPECT_EQ(r.status, 2) << args.back();
    EXPECT_EQ(r.err_lines().size(), 1u) << r.err;
    EXPECT_EQ(r.out, "");
  }
}
