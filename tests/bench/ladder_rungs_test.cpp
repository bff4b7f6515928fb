// SPDX-License-Identifier: MIT
// Examples for BENCH.LADDER.RUNGS and BENCH.LADDER.SCENES: what each rung draws on small
// hand-made cases whose answer is known.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "ladder_test_util.hpp"
#include "limit.hpp"
#include "rastrules/bench/ladder.hpp"
#include "rastrules/isa.hpp"

namespace rb = rastrules::bench;

namespace {

// Two triangles sharing the diagonal (0.5, 0.5) -> (4.5, 4.5), which passes through the pixel
// centres (0.5, 0.5), (1.5, 1.5), (2.5, 2.5), (3.5, 3.5): the rectangle [0.5, 4.5)^2.
rb::LadderScene diagonal_pair() {
  rb::LadderScene s;
  s.name = "pair";
  s.width = 8;
  s.height = 8;
  s.is_mesh = true;
  s.rect_x0 = s.rect_y0 = 0.5;
  s.rect_x1 = s.rect_y1 = 4.5;
  s.triangles.push_back({{{0.5f, 0.5f}, {4.5f, 0.5f}, {4.5f, 4.5f}}});
  s.triangles.push_back({{{0.5f, 0.5f}, {4.5f, 4.5f}, {0.5f, 4.5f}}});
  return s;
}

rb::Coverage cover(rb::Rung r, const rb::LadderScene& s) {
  rb::Coverage c;
  rb::run_rung(r, s, &c);
  return c;
}

// How many times each pixel is drawn.
std::map<std::pair<int, int>, int> draws(const rb::Coverage& c) {
  std::map<std::pair<int, int>, int> m;
  for (const auto k : c)
    ++m[{static_cast<int>(k & 0xffff), static_cast<int>((k >> 16) & 0xffff)}];
  return m;
}

} // namespace

// rule: BENCH.LADDER.RUNGS
TEST(LadderRungs, FloatDrawsSharedDiagonalCentresTwiceReferenceOnce) {
  const auto s = diagonal_pair();
  const auto f = draws(cover(rb::Rung::kFloat, s));
  const auto r = draws(cover(rb::Rung::kReference, s));
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(f.at({i, i}), 2) << "float, centre " << i;
    EXPECT_EQ(r.at({i, i}), 1) << "reference, centre " << i;
  }
  EXPECT_EQ(rb::watertight_violations(s, cover(rb::Rung::kFloat, s)), 4u);
  EXPECT_EQ(rb::watertight_violations(s, cover(rb::Rung::kDouble, s)), 4u);
  EXPECT_EQ(rb::watertight_violations(s, cover(rb::Rung::kReference, s)), 0u);
  EXPECT_EQ(rb::watertight_violations(s, cover(rb::Rung::kExact, s)), 0u);
  EXPECT_EQ(rb::watertight_violations(s, cover(rb::Rung::kFixed16I128, s)), 0u);
}

// rule: BENCH.LADDER.RUNGS
TEST(LadderRungs, TieRuleRungsAgreeWithExactOnTheHardMesh) {
  const auto s = rb::make_hard_mesh(6, 6, 4);
  const auto exact = cover(rb::Rung::kExact, s);
  EXPECT_EQ(rb::watertight_violations(s, exact), 0u);
  EXPECT_EQ(rb::symmetric_difference(cover(rb::Rung::kReference, s), exact), 0u);
  EXPECT_EQ(rb::symmetric_difference(cover(rb::Rung::kFixed16I128, s), exact), 0u);
  for (const rb::Rung r : rb::all_rungs()) {
    if (r == rb::Rung::kReferenceFast) {
      EXPECT_EQ(rb::symmetric_difference(cover(r, s), exact), 0u);
    }
  }
  // No tie rule: the float rung draws the diagonals' centres twice.
  EXPECT_GT(rb::watertight_violations(s, cover(rb::Rung::kFloat, s)), 0u);
}

// The article's half-open span: centres x_l <= x < x_r, rows y_top <= y < y_bottom.
// rule: BENCH.LADDER.RUNGS
TEST(LadderRungs, ScanlineFillsHalfOpenSpans) {
  rb::LadderScene s;
  s.width = s.height = 8;
  // A right triangle with the vertical edge x = 0.5 and the horizontal edge y = 0.5: rows
  // with centres 0.5 .. 3.5 and on row y the centres 0.5 <= x < 4.5 - y.
  s.triangles.push_back({{{0.5f, 0.5f}, {4.5f, 0.5f}, {0.5f, 4.5f}}});
  const auto d = draws(cover(rb::Rung::kScanline, s));
  std::map<std::pair<int, int>, int> want;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4 - y; ++x)
      want[{x, y}] = 1;
  EXPECT_EQ(d, want);
}

// fixed4-i32 wraps in uint32: the result is exact whenever the true edge values fit in 32
// bits (modular arithmetic), at any translation the kernel accepts; a triangle large enough
// for its values to leave 32 bits (about 2900 px) gets wrong answers.
// rule: BENCH.LADDER.RUNGS
TEST(LadderRungs, Fixed4I32IsWrongOnlyWhereItsValuesOverflow) {
  rb::LadderScene small;
  small.width = small.height = 16384;
  // Vertices on the 1/16 grid (so that 4 subpixel bits lose nothing), off every centre.
  small.triangles.push_back({{{1.0625f, 1.0f}, {9.25f, 3.125f}, {2.0f, 7.9375f}}});
  for (const std::int32_t t : {0, 1024, 8192}) {
    const auto s = rb::translated(small, t, 16384, 16384);
    EXPECT_EQ(
        rb::symmetric_difference(cover(rb::Rung::kFixed4I32, s), cover(rb::Rung::kReference, s)),
        0u)
        << "t = " << t;
  }
  rb::LadderScene big;
  big.width = big.height = 16384;
  big.triangles.push_back({{{0.0f, 0.0f}, {4000.0f, 0.0f}, {0.0f, 4000.0f}}});
  const auto ref = rb::run_rung(rb::Rung::kReference, big, nullptr);
  const auto f4 = rb::run_rung(rb::Rung::kFixed4I32, big, nullptr);
  EXPECT_NE(f4, ref);
}

// rule: BENCH.LADDER.SCENES
TEST(LadderScenes, MeshesCoverTheirRectangleExactly) {
  const auto m = rb::make_mesh("m", 7, 5, 4, 10, 0.2, 8, 8, 80, 80);
  ASSERT_EQ(m.triangles.size(), 40u);
  // Each triangle clockwise, vertices on the 1/256 grid; the exact answer draws every pixel of
  // the rectangle once.
  double area = 0;
  for (const auto& t : m.triangles) {
    const double a = (double(t[1][0]) - t[0][0]) * (double(t[2][1]) - t[0][1]) -
                     (double(t[1][1]) - t[0][1]) * (double(t[2][0]) - t[0][0]);
    EXPECT_GT(a, 0);
    area += a / 2;
    for (const auto& v : t)
      for (const float c : v)
        EXPECT_EQ(c * 256.0f, std::round(c * 256.0f));
  }
  EXPECT_DOUBLE_EQ(area, 50.0 * 40.0);
  EXPECT_EQ(rb::watertight_violations(m, cover(rb::Rung::kExact, m)), 0u);
  // Deterministic: the same seed gives the same mesh, another seed another one.
  EXPECT_EQ(rb::make_mesh("m", 7, 5, 4, 10, 0.2, 8, 8, 80, 80).triangles, m.triangles);
  EXPECT_NE(rb::make_mesh("m", 8, 5, 4, 10, 0.2, 8, 8, 80, 80).triangles, m.triangles);
  // The translation sweep: t = 0, then 2^k up to 8192.
  const auto sc = rb::make_scenes(rb::LadderConfig{true, 1, 0.02});
  ASSERT_EQ(sc.sweep.size(), 15u);
  EXPECT_EQ(sc.sweep.front(), 0);
  EXPECT_EQ(sc.sweep.back(), 8192);
  EXPECT_EQ(sc.timed.size(), 4u);
}

// rule: BENCH.LADDER.RUNGS
TEST(LadderRungs, LimitLoopsAgreeAndCountInsideCentres) {
  // A triangle on the 1/16 grid with no centre on an edge: the limit counts what fixed4-i32
  // draws.
  rb::LadderScene s;
  s.width = s.height = 200;
  s.triangles.push_back({{{3.0625f, 2.0f}, {150.25f, 40.125f}, {20.0f, 170.9375f}}});
  const auto setup = rb::limit_setup(s.triangles[0], s.width, s.height);
  const auto scalar = rb::limit_loop_scalar(setup);
  EXPECT_EQ(scalar, rb::run_rung(rb::Rung::kFixed4I32, s, nullptr));
  EXPECT_EQ(rb::run_rung(rb::Rung::kLimit, s, nullptr), scalar);
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx2")) {
    EXPECT_EQ(rb::limit_loop_avx2(setup), scalar);
  }
  if (__builtin_cpu_supports("avx512f")) {
    EXPECT_EQ(rb::limit_loop_avx512(setup), scalar);
  }
}

// rule: BENCH.METRIC.THROUGHPUT
TEST(LadderRungs, ReferenceFastOnThreadsCountsWhatOneThreadCounts) {
  if (!rb::test::has_reference_fast())
    GTEST_SKIP() << "reference-fast not built";
  rb::LadderConfig c;
  c.quick = true;
  const rb::LadderScenes scenes = rb::make_scenes(c);
  std::vector<rb::LadderScene> all = scenes.timed;
  all.push_back(scenes.translate_base);
  // Fewer triangles than threads: the chunks are the triangles, the rest of the threads idle.
  rb::LadderScene few = scenes.timed.front();
  few.name = "two triangles";
  few.triangles.resize(2);
  all.push_back(few);
  for (const rb::LadderScene& s : all) {
    const std::uint64_t one = rb::run_rung(rb::Rung::kReferenceFast, s, nullptr);
    EXPECT_GT(one, 0u) << s.name;
    // The plain walk counts the same (FAST.EQUALS.PLAIN), so a lost or doubled chunk shows.
    EXPECT_EQ(one, rb::run_rung(rb::Rung::kReference, s, nullptr)) << s.name;
    for (const unsigned n : {1u, 2u, 3u, 7u})
      EXPECT_EQ(rb::run_reference_fast_threaded(s, n), one) << s.name << ", " << n << " threads";
  }
}

// rule: BENCH.METRIC.THROUGHPUT, FAST.THREADS.DETERMINISTIC
TEST(LadderRungs, APersistentPoolCountsTheSameEveryTimeAndReportsAChunksError) {
  rb::LadderConfig c;
  c.quick = true;
  const rb::LadderScene s = rb::make_scenes(c).timed.front();
  const std::uint64_t one = rb::run_rung(rb::Rung::kReference, s, nullptr);
  rb::FastPool pool(3);
  EXPECT_GE(pool.threads(), 1u);
  for (int k = 0; k < 200; ++k)
    ASSERT_EQ(pool.count(s), one) << "repeat " << k;
  // A coordinate that does not snap in the last chunk: the worker's error reaches the caller,
  // and the pool still works afterwards.
  rb::LadderScene bad = s;
  bad.triangles.back()[1][0] = std::numeric_limits<float>::quiet_NaN();
  rb::flatten(bad);
  try {
    (void)pool.count(bad);
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    const std::string want = "triangle " + std::to_string(s.triangles.size() - 1) + ", vertex 1, x";
    EXPECT_NE(std::string(e.what()).find(want), std::string::npos) << e.what();
  }
  EXPECT_EQ(pool.count(s), one);
}

// The float-simd rung evaluates the float rung's edge functions in 8 lanes (AVX2, no fused
// multiply-add): the same centres, in the same order, on every scene family, ties included.
// With RASTRULES_MAX_ISA=scalar or without AVX2 it runs the scalar loop, and this holds
// trivially; the test names which ran.
// rule: BENCH.LADDER.RUNGS
TEST(LadderRungs, FloatSimdCoversExactlyTheFloatRungsCentres) {
  std::vector<rb::LadderScene> scenes = {diagonal_pair(), rb::make_hard_mesh(6, 6, 4)};
  scenes.push_back(rb::make_mesh("small", 5, 16, 16, 10, 0.2, 0.25, 0.75, 170, 170));
  scenes.push_back(rb::make_mesh("medium", 6, 4, 4, 45, 0.2, 3.0, 1.0, 190, 190));
  scenes.push_back(rb::translated(scenes[2], 4096, 16384, 16384));
  scenes.push_back(rb::translated(scenes[3], 8192, 16384, 16384));
  std::size_t covered = 0;
  for (const rb::LadderScene& s : scenes) {
    const rb::Coverage f = cover(rb::Rung::kFloat, s), v = cover(rb::Rung::kFloatSimd, s);
    EXPECT_EQ(v, f) << s.name;
    EXPECT_EQ(rb::run_rung(rb::Rung::kFloatSimd, s, nullptr), f.size()) << s.name;
    covered += f.size();
  }
  EXPECT_GT(covered, 1000u);
  RecordProperty("isa", std::string(rastrules::to_string(rastrules::best_isa())));
}
