// SPDX-License-Identifier: MIT
// Examples for the ladder's metrics: BENCH.METRIC.ERROR, BENCH.METRIC.WATERTIGHT,
// BENCH.METRIC.TRANSLATION and BENCH.METRIC.THROUGHPUT (decisions), on synthetic data.

#include <gtest/gtest.h>

#include "rastrules/bench/ladder.hpp"

namespace rb = rastrules::bench;

// rule: BENCH.METRIC.ERROR
TEST(LadderMetrics, ErrorCountsDecisionsInExactlyOneCoverage) {
  const rb::Coverage exact = {rb::coverage_key(0, 1, 1), rb::coverage_key(0, 2, 1),
                              rb::coverage_key(1, 2, 1)};
  const rb::Coverage rung = {rb::coverage_key(0, 1, 1), rb::coverage_key(1, 2, 1),
                             rb::coverage_key(1, 3, 1), rb::coverage_key(2, 0, 0)};
  // missing (0, 2, 1); extra (1, 3, 1) and (2, 0, 0)
  EXPECT_EQ(rb::symmetric_difference(rung, exact), 3u);
  EXPECT_EQ(rb::symmetric_difference(exact, exact), 0u);
  EXPECT_EQ(rb::symmetric_difference({}, exact), 3u);
}

// rule: BENCH.METRIC.WATERTIGHT
TEST(LadderMetrics, WatertightCountsPixelsDrawnNeverOrTwice) {
  rb::LadderScene s;
  s.width = s.height = 8;
  s.is_mesh = true;
  s.rect_x0 = 1;
  s.rect_y0 = 1;
  s.rect_x1 = 3;
  s.rect_y1 = 2; // pixels (1, 1) and (2, 1)
  EXPECT_EQ(rb::watertight_violations(s, {}), 2u);
  EXPECT_EQ(rb::watertight_violations(s, {rb::coverage_key(0, 1, 1), rb::coverage_key(1, 2, 1)}),
            0u);
  // twice, never, and a pixel outside the rectangle that does not count
  EXPECT_EQ(rb::watertight_violations(s, {rb::coverage_key(0, 1, 1), rb::coverage_key(1, 1, 1),
                                          rb::coverage_key(1, 5, 5)}),
            2u);
  // Half-open on centres: a rectangle from 0.5 to 2.5 holds the centres 0.5 and 1.5.
  s.rect_x0 = s.rect_y0 = 0.5;
  s.rect_x1 = s.rect_y1 = 2.5;
  EXPECT_EQ(rb::watertight_violations(s, {rb::coverage_key(0, 0, 0), rb::coverage_key(0, 1, 0),
                                          rb::coverage_key(0, 0, 1), rb::coverage_key(0, 1, 1)}),
            0u);
}

// rule: BENCH.METRIC.TRANSLATION
TEST(LadderMetrics, ExactRangeIsTheLastCleanTranslationOfAnUnbrokenRun) {
  std::vector<rb::SweepPoint> sweep;
  for (const std::int64_t t : {0, 1, 2, 4, 8, 16})
    sweep.push_back({t, 0, 0, 0});
  EXPECT_EQ(rb::exact_range(sweep), std::optional<std::int64_t>(16));
  sweep[4].translation = 1; // t = 8 breaks translation invariance
  EXPECT_EQ(rb::exact_range(sweep), std::optional<std::int64_t>(4));
  sweep[4].translation = 0;
  sweep[5].errors = 3; // t = 16 differs from exact
  EXPECT_EQ(rb::exact_range(sweep), std::optional<std::int64_t>(8));
  sweep[0].watertight = 1; // already wrong untranslated: no range
  EXPECT_EQ(rb::exact_range(sweep), std::nullopt);
}

// rule: BENCH.METRIC.TRANSLATION
TEST(LadderMetrics, TranslationViolationsCompareWithTheShiftedUntranslatedResult) {
  const rb::Coverage at0 = {rb::coverage_key(0, 1, 2), rb::coverage_key(0, 2, 2)};
  const rb::Coverage at4 = {rb::coverage_key(0, 5, 6), rb::coverage_key(0, 6, 6)};
  EXPECT_EQ(rb::symmetric_difference(rb::shifted_back(at4, 4), at0), 0u);
  const rb::Coverage bad = {rb::coverage_key(0, 5, 6), rb::coverage_key(0, 7, 6)};
  EXPECT_EQ(rb::symmetric_difference(rb::shifted_back(bad, 4), at0), 2u);
  // The reference is translation invariant on a mesh across the sweep.
  const auto base = rb::make_mesh("t", 3, 3, 3, 12, 0.2, 4, 4, 16384, 16384);
  rb::Coverage c0;
  rb::run_rung(rb::Rung::kReference, base, &c0);
  for (const std::int32_t t : {1, 64, 8192}) {
    rb::Coverage ct;
    rb::run_rung(rb::Rung::kReference, rb::translated(base, t, 16384, 16384), &ct);
    EXPECT_EQ(rb::symmetric_difference(rb::shifted_back(ct, t), c0), 0u) << "t = " << t;
  }
}

// rule: BENCH.METRIC.THROUGHPUT
TEST(LadderMetrics, DecisionsAreBoundingBoxPixelsClippedToTheTarget) {
  rb::LadderScene s;
  s.width = 10;
  s.height = 4;
  // Bounding box centres x 1..8 (8 px), y 0..5 clipped to 0..3 (4 px).
  s.triangles.push_back({{{1.25f, 0.0f}, {8.75f, 0.0f}, {1.25f, 6.0f}}});
  EXPECT_EQ(rb::count_decisions(s), 32u);
  EXPECT_DOUBLE_EQ(rb::median({3.0, 1.0, 2.0}), 2.0);
  EXPECT_DOUBLE_EQ(rb::median({4.0, 1.0, 2.0, 3.0}), 2.5);
}
