// SPDX-License-Identifier: MIT
// Examples for BENCH.REPORT and BENCH.TARGETS: the Markdown and JSON shape, the targets'
// verdicts and the plot, on a synthetic report (no timing).

#include <gtest/gtest.h>

#include <cstdlib>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <unistd.h>

#include "ladder_test_util.hpp"
#include "rastrules/bench/ladder.hpp"
#include "rastrules/io/text.hpp"

namespace rb = rastrules::bench;

namespace {

// A report with made-up figures: decisions per second = base * factor per rung.
rb::LadderReport synthetic(double fast_factor, double lavapipe_seconds) {
  rb::LadderReport r;
  r.date = "2026-01-01T00:00:00Z";
  r.cpu = "test cpu";
  r.isa = "avx2";
  r.limit_isa = "avx2";
  r.batch_lanes = 8;
  r.limit_lanes = 8;
  r.scenes = {"small", "medium", "large", "hard"};
  r.sweep_t = {0, 1, 2};
  r.sweep_note = "synthetic";
  double factor = 0.5;
  for (const rb::Rung rung : rb::all_rungs()) {
    rb::RungResult rr;
    rr.rung = rung;
    const double f = rung == rb::Rung::kReference       ? 1.0
                     : rung == rb::Rung::kReferenceFast ? fast_factor
                     : rung == rb::Rung::kLimit         ? 4.0
                                                        : (factor += 0.25);
    for (const auto& name : r.scenes) {
      rb::FamilyResult fr;
      fr.scene = name;
      fr.triangles = 100;
      fr.decisions = 1000;
      fr.seconds = 1e-3 / f;
      fr.decisions_per_second = 1e6 * f;
      fr.triangles_per_second = 1e5 * f;
      fr.ratio_to_reference = f;
      if (rb::has_coverage(rung)) {
        fr.errors = rung == rb::Rung::kFloat ? 10 : 0;
        fr.watertight = rung == rb::Rung::kFloat ? 4 : 0;
      }
      rr.families.push_back(fr);
      rr.total_decisions += 1000;
      rr.total_errors += fr.errors.value_or(0);
      rr.total_watertight += fr.watertight.value_or(0);
    }
    if (rb::has_coverage(rung)) {
      rr.sweep = {{0, 0, 0, 0}, {1, 0, 0, 0}, {2, 0, 0, 0}};
      rr.range = rb::exact_range(rr.sweep);
    }
    r.rungs.push_back(rr);
  }
  r.lavapipe.available = lavapipe_seconds > 0;
  r.lavapipe.why_not = lavapipe_seconds > 0 ? "" : "no Vulkan CPU device";
  r.lavapipe.seconds = lavapipe_seconds;
  r.lavapipe.triangles = 100;
  r.lavapipe.threads = 2;
  r.lavapipe.threads_source = "synthetic";
  // reference-fast on 2 threads: 1.5 times its single-thread rate.
  r.threads = 2;
  r.config.threads = 2;
  for (const auto& name : r.scenes) {
    rb::FamilyResult fr;
    fr.scene = name;
    fr.triangles = 100;
    fr.decisions = 1000;
    fr.decisions_per_second = 1.5e6 * fast_factor;
    fr.triangles_per_second = 1.5e5 * fast_factor;
    fr.ratio_to_reference = 1.5 * fast_factor;
    r.fast_threaded.push_back(fr);
  }
  return r;
}

// Sets LP_NUM_THREADS (or unsets it for nullopt) for its lifetime, then restores it.
class LpNumThreads {
public:
  explicit LpNumThreads(const std::optional<std::string>& v) {
    if (const char* old = std::getenv("LP_NUM_THREADS"))
      old_ = old;
    if (v)
      setenv("LP_NUM_THREADS", v->c_str(), 1);
    else
      unsetenv("LP_NUM_THREADS");
  }
  ~LpNumThreads() {
    if (old_)
      setenv("LP_NUM_THREADS", old_->c_str(), 1);
    else
      unsetenv("LP_NUM_THREADS");
  }
  LpNumThreads(const LpNumThreads&) = delete;
  LpNumThreads& operator=(const LpNumThreads&) = delete;

private:
  std::optional<std::string> old_;
};

} // namespace

// rule: BENCH.LAVAPIPE
TEST(LadderLavapipe, ThreadCountComesFromLpNumThreadsElseTheOnlineProcessors) {
  {
    const LpNumThreads env{std::nullopt};
    const auto [n, source] = rb::lavapipe_threads();
    EXPECT_EQ(n, static_cast<unsigned>(sysconf(_SC_NPROCESSORS_ONLN)));
    EXPECT_NE(source.find("LP_NUM_THREADS unset"), std::string::npos) << source;
  }
  {
    const LpNumThreads env{std::string("3")};
    const auto [n, source] = rb::lavapipe_threads();
    EXPECT_EQ(n, 3u);
    EXPECT_EQ(source, "LP_NUM_THREADS=3");
  }
  {
    // 0: llvmpipe rasterizes on the calling thread, one thread.
    const LpNumThreads env{std::string("0")};
    const auto [n, source] = rb::lavapipe_threads();
    EXPECT_EQ(n, 1u);
    EXPECT_NE(source.find("calling thread"), std::string::npos) << source;
  }
  for (const char* bad : {"x", "2x", "-1", "257", " "}) {
    const LpNumThreads env{std::string(bad)};
    const auto [n, source] = rb::lavapipe_threads();
    EXPECT_EQ(n, 0u) << bad;
    EXPECT_NE(source.find("not an integer in [0, 256]"), std::string::npos) << source;
  }
}

// The whole ladder on the quick scenes with a fake lavapipe (no Vulkan), one repeat per figure:
// the threaded row, its counts and lavapipe's thread count reach the table and the JSON.
// rule: BENCH.METRIC.THROUGHPUT, BENCH.LAVAPIPE, BENCH.TARGETS
TEST(LadderRun, FakeLavapipeAndThreeThreadsReachTheTableAndTheJson) {
  if (!rb::test::has_reference_fast())
    GTEST_SKIP() << "reference-fast not built";
  const LpNumThreads env{std::string("5")};
  rb::LadderConfig c;
  c.quick = true;
  c.min_seconds = 0.0;
  c.threads = 3;
  int calls = 0;
  const rb::LavapipeTimer fake = [&calls](const rb::LadderScene& s) {
    ++calls;
    EXPECT_EQ(s.name, "small");
    rb::LavapipeFigure f;
    f.available = true;
    f.device = "fake lavapipe";
    f.includes = "nothing (a test double)";
    f.repeats = 1;
    f.seconds = 0.5;
    f.samples_passed = 12345;
    return f;
  };
  const rb::LadderReport r = rb::run_ladder(c, fake, {});
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(r.threads, 3u);
  EXPECT_EQ(r.lavapipe.threads, 5u);
  EXPECT_EQ(r.lavapipe.threads_source, "LP_NUM_THREADS=5");
  const rb::RungResult* fast = r.find(rb::Rung::kReferenceFast);
  ASSERT_NE(fast, nullptr);
  ASSERT_EQ(r.fast_threaded.size(), fast->families.size());
  for (std::size_t i = 0; i < r.fast_threaded.size(); ++i) {
    EXPECT_EQ(r.fast_threaded[i].scene, fast->families[i].scene);
    EXPECT_EQ(r.fast_threaded[i].covered, fast->families[i].covered) << r.fast_threaded[i].scene;
    EXPECT_EQ(r.fast_threaded[i].decisions, fast->families[i].decisions);
    EXPECT_GE(r.fast_threaded[i].repeats, 1);
  }
  const std::string md = rb::to_markdown(r);
  EXPECT_NE(md.find("\n| reference-fast x3 |"), std::string::npos) << md;
  EXPECT_NE(md.find("5 rasterizer threads: LP_NUM_THREADS=5"), std::string::npos) << md;
  EXPECT_NE(md.find("fake lavapipe"), std::string::npos) << md;
  // 3 threads against lavapipe's 5: compared per thread, the single-thread ratio beside it.
  EXPECT_NE(md.find("per thread (rastrules 3, lavapipe 5 threads"), std::string::npos) << md;
  EXPECT_NE(md.find("single-thread ratio (reference-fast on 1 thread against lavapipe on 5): "),
            std::string::npos)
      << md;
  // The limit steps as many lanes as the batch counter's rows on this processor (or under
  // RASTRULES_MAX_ISA), and the heading says both.
  EXPECT_EQ(r.batch_lanes, r.limit_lanes);
  EXPECT_NE(md.find("(batch counter rows: " + std::to_string(r.batch_lanes) +
                    " lanes; limit rung: " + r.limit_isa + ", " + std::to_string(r.limit_lanes) +
                    " lanes)"),
            std::string::npos)
      << md;
  const auto j = nlohmann::json::parse(rb::to_json(r));
  EXPECT_EQ(j.at("threads"), 3);
  EXPECT_EQ(j.at("lavapipe").at("threads"), 5);
  EXPECT_EQ(j.at("lavapipe").at("threads_source"), "LP_NUM_THREADS=5");
  EXPECT_EQ(j.at("lavapipe").at("samples_passed"), 12345);
  ASSERT_EQ(j.at("reference_fast_threaded").size(), r.fast_threaded.size());
  EXPECT_EQ(j.at("reference_fast_threaded").at(0).at("threads"), 3);
}

// rule: BENCH.REPORT
TEST(LadderReport, MarkdownHasOneRowPerRungAndTheTargets) {
  const std::string md = rb::to_markdown(synthetic(2.0, 1.0));
  for (const rb::Rung rung : rb::all_rungs())
    EXPECT_NE(md.find("| " + std::string(rb::to_string(rung)) + " |"), std::string::npos)
        << rb::to_string(rung);
  EXPECT_NE(md.find("| rung | small Mdec/s (x ref) | medium Mdec/s (x ref) |"), std::string::npos);
  EXPECT_NE(md.find("test cpu"), std::string::npos);
  EXPECT_NE(md.find("Targets"), std::string::npos);
  EXPECT_NE(md.find("0.01"), std::string::npos); // float's error fraction: 40 / 4000
  // rule: BENCH.METRIC.THROUGHPUT, BENCH.LAVAPIPE
  EXPECT_NE(md.find("| reference-fast x2 | 3 (3) |"), std::string::npos) << md;
  EXPECT_NE(md.find("2 rasterizer threads: synthetic"), std::string::npos) << md;
}

// rule: BENCH.REPORT
TEST(LadderReport, JsonHoldsEveryFigure) {
  const auto j = nlohmann::json::parse(rb::to_json(synthetic(2.0, 1.0)));
  EXPECT_EQ(j.at("isa"), "avx2");
  EXPECT_EQ(j.at("threads"), 2);
  ASSERT_EQ(j.at("reference_fast_threaded").size(), 4u);
  EXPECT_EQ(j.at("reference_fast_threaded").at(0).at("threads"), 2);
  EXPECT_EQ(j.at("lavapipe").at("threads"), 2);
  EXPECT_EQ(j.at("date"), "2026-01-01T00:00:00Z");
  ASSERT_EQ(j.at("rungs").size(), rb::all_rungs().size());
  const auto& f = j.at("rungs").at(0);
  EXPECT_EQ(f.at("rung"), "float");
  EXPECT_EQ(f.at("errors"), 40);
  EXPECT_DOUBLE_EQ(f.at("error_fraction").get<double>(), 0.01);
  EXPECT_EQ(f.at("scenes").size(), 4u);
  EXPECT_EQ(f.at("sweep").size(), 3u);
  EXPECT_EQ(f.at("exact_range"), 2);
  EXPECT_TRUE(j.at("rungs").back().at("exact_range").is_null()); // limit
  EXPECT_EQ(j.at("targets").size(), 4u);
  EXPECT_TRUE(j.at("lavapipe").at("available").get<bool>());
  EXPECT_EQ(j.at("batch_lanes"), 8);
  EXPECT_EQ(j.at("limit_lanes"), 8);
}

// rule: BENCH.TARGETS
TEST(LadderTargets, EachTargetSaysWhetherThisRunMetIt) {
  if (!rb::test::has_reference_fast())
    GTEST_SKIP() << "reference-fast not built";
  // fast = 3.8 x reference: 95 % of limit (4) at the same width (8 lanes), faster than float
  // (0.75) and float-simd (1); 100 triangles in 1 s for lavapipe against 3.8e5/s: 3800x.
  auto t = rb::check_targets(synthetic(3.8, 1.0));
  ASSERT_EQ(t.size(), 4u);
  for (const auto& c : t)
    EXPECT_EQ(c.met, std::optional<bool>(true)) << c.name << ": " << c.measured;
  EXPECT_NE(t[0].measured.find("95% of limit (batch rows 8 lanes, limit 8)"), std::string::npos)
      << t[0].measured;
  // 87.5 % of limit: below the 90 % target.
  EXPECT_EQ(rb::check_targets(synthetic(3.5, 1.0))[0].met, std::optional<bool>(false));
  // The limit at another width than the batch counter's rows: never met, whatever the ratio.
  rb::LadderReport wide = synthetic(3.8, 1.0);
  wide.limit_lanes = 16;
  t = rb::check_targets(wide);
  EXPECT_EQ(t[0].met, std::optional<bool>(false)) << t[0].measured;
  EXPECT_NE(t[0].measured.find("(batch rows 8 lanes, limit 16)"), std::string::npos)
      << t[0].measured;
  // fast = 0.6 x reference: 15 % of limit, slower than float (0.75) and float-simd (1);
  // lavapipe faster.
  t = rb::check_targets(synthetic(0.6, 1e-5));
  for (const auto& c : t)
    EXPECT_EQ(c.met, std::optional<bool>(false)) << c.name << ": " << c.measured;
  // Equal resources: rastrules on 2 threads (1.5 x 3.5e5 = 5.25e5/s) against lavapipe on 2
  // (100 per 10 ms = 1e4/s): 52.5x; the single-thread ratio (35x) is printed as well.
  t = rb::check_targets(synthetic(3.5, 1e-2));
  EXPECT_EQ(t[3].met, std::optional<bool>(true)) << t[3].measured;
  EXPECT_NE(t[3].measured.find("52.5x lavapipe, both on 2 threads (equal resources)"),
            std::string::npos)
      << t[3].measured;
  EXPECT_NE(t[3].measured.find("single-thread ratio (reference-fast on 1 thread against lavapipe "
                               "on 2): 35x"),
            std::string::npos)
      << t[3].measured;
  // Different thread counts: per thread. lavapipe on 8 threads: 1e4 / 8 per thread against
  // 5.25e5 / 2: 210x.
  auto r8 = synthetic(3.5, 1e-2);
  r8.lavapipe.threads = 8;
  t = rb::check_targets(r8);
  EXPECT_NE(t[3].measured.find("210x lavapipe per thread (rastrules 2, lavapipe 8 threads"),
            std::string::npos)
      << t[3].measured;
  // lavapipe's thread count unknown (LP_NUM_THREADS not understood): not measured, and why.
  auto unknown = synthetic(3.5, 1e-2);
  unknown.lavapipe.threads = 0;
  unknown.lavapipe.threads_source = "LP_NUM_THREADS=\"x\" is not an integer in [0, 256]: unknown";
  t = rb::check_targets(unknown);
  EXPECT_EQ(t[3].met, std::nullopt);
  EXPECT_NE(t[3].measured.find("thread count is unknown (LP_NUM_THREADS=\"x\""), std::string::npos)
      << t[3].measured;
  // Without lavapipe the third target is not measured.
  t = rb::check_targets(synthetic(3.5, 0.0));
  EXPECT_EQ(t[3].met, std::nullopt);
  EXPECT_NE(t[3].measured.find("no Vulkan CPU device"), std::string::npos);
}

// rule: BENCH.REPORT
TEST(LadderPlot, OneLabelledPointPerRungOnLogAxes) {
  const auto r = synthetic(2.0, 1.0);
  const rb::Plot p = rb::make_plot(r);
  ASSERT_EQ(p.rgb.size(),
            static_cast<std::size_t>(p.width) * static_cast<std::size_t>(p.height) * 3);
  // Every character of every label and tick has a glyph.
  for (const rb::Rung rung : rb::all_rungs())
    for (const char c : rb::to_string(rung))
      EXPECT_TRUE(rastrules::io::glyph(c).has_value()) << c;
  for (const char c : std::string("0123456789e-.,()/%:"))
    EXPECT_TRUE(rastrules::io::glyph(c).has_value()) << c;
  EXPECT_FALSE(rastrules::io::glyph('\x01').has_value());
  // The digit 1 is a vertical stroke with a base: row 6 is ".###.".
  EXPECT_EQ(rastrules::io::glyph('1')->at(6), 0b01110);
  // The plot is not blank: count non-white pixels.
  std::size_t ink = 0;
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x)
      if (p.at(x, y) != std::array<std::uint8_t, 3>{255, 255, 255})
        ++ink;
  EXPECT_GT(ink, 5000u);
}
