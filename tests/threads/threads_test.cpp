// SPDX-License-Identifier: MIT
// Threads change the time, not the result (FAST.THREADS.DETERMINISTIC): rasterize() with 1, 2,
// 3, 8 and 64 threads gives the single-threaded fragments on scenes of mixed primitives, with
// one sample and with 4 samples; the pool runs every unit once, inline for one thread, and
// rethrows the exception of the lowest-index failing unit whatever the thread count.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <new>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "rastrules/isa.hpp"
#include "rastrules/parallel.hpp"
#include "rastrules/scene.hpp"

namespace {

using rastrules::Fragment;
using rastrules::PrimitiveType;
using rastrules::RenderOptions;

rastrules::Primitive prim(PrimitiveType type, std::vector<rastrules::FloatPoint> v,
                          rastrules::Rgba8 color = {255, 255, 255, 255}) {
  rastrules::Primitive p;
  p.type = type;
  p.v = std::move(v);
  p.color = color;
  return p;
}

// 40 primitives of every type over a 24x24 target: triangles of several sizes (some sharing
// edges, one large), points, lines and line strips, with vertices on and off pixel centres.
rastrules::Scene mixed_scene() {
  rastrules::Scene s;
  s.width = 24;
  s.height = 24;
  for (int i = 0; i < 10; ++i) {
    const float o = static_cast<float>(i) * 2.0f;
    s.primitives.push_back(prim(PrimitiveType::kTriangle,
                                {{o, 0.5f}, {o + 7.25f, 3.0f}, {o + 1.5f, 12.5f}},
                                {static_cast<std::uint8_t>(20 * i), 10, 200, 255}));
    s.primitives.push_back(prim(PrimitiveType::kPoint, {{o + 0.5f, 20.5f}}));
    s.primitives.push_back(prim(PrimitiveType::kLine, {{0.5f, o + 0.75f}, {23.0f, 23.0f - o}}));
    s.primitives.push_back(
        prim(PrimitiveType::kLineStrip, {{o, 23.0f}, {o + 3.5f, 14.0f}, {23.5f, o}}));
  }
  s.primitives.push_back(
      prim(PrimitiveType::kTriangle, {{-3.0f, -2.0f}, {30.0f, 1.0f}, {2.0f, 29.0f}}));
  return s;
}

rastrules::PreparedScene prepared(const rastrules::Scene& s) {
  auto p = rastrules::prepare(s);
  if (const auto* e = std::get_if<rastrules::SceneError>(&p)) {
    ADD_FAILURE() << e->what();
    return {};
  }
  return std::get<rastrules::PreparedScene>(p);
}

void expect_same_for_every_thread_count(const rastrules::Scene& scene) {
  const rastrules::PreparedScene ps = prepared(scene);
  const std::vector<Fragment> single = rastrules::rasterize(ps);
  ASSERT_GT(single.size(), 500u); // enough work for every thread to take a unit
  for (const rastrules::Traversal t : {rastrules::Traversal::kPlain, rastrules::Traversal::kFast}) {
    RenderOptions one;
    one.traversal = t;
    const std::vector<Fragment> base = rastrules::rasterize(ps, one);
    for (const unsigned n : {1u, 2u, 3u, 8u, 64u}) {
      RenderOptions o = one;
      o.threads = n;
      const std::vector<Fragment> got = rastrules::rasterize(ps, o);
      EXPECT_EQ(got, base) << n << " threads, traversal " << rastrules::to_string(t);
      const auto rendered = rastrules::render(scene, o);
      ASSERT_TRUE(std::holds_alternative<std::vector<Fragment>>(rendered));
      EXPECT_EQ(std::get<std::vector<Fragment>>(rendered), base) << n << " threads (render)";
    }
  }
  RenderOptions plain;
  plain.traversal = rastrules::Traversal::kPlain;
  plain.threads = 8;
  EXPECT_EQ(rastrules::rasterize(ps, plain), single);
}

// rule: FAST.THREADS.DETERMINISTIC
TEST(ThreadsDeterministic, MixedSingleSampleSceneIsTheSameForEveryThreadCount) {
  expect_same_for_every_thread_count(mixed_scene());
}

// rule: FAST.THREADS.DETERMINISTIC
TEST(ThreadsDeterministic, MultisampledSceneWithQuadsIsTheSameForEveryThreadCount) {
  rastrules::Scene s = mixed_scene();
  set_sample_pattern(s, rastrules::standard_pattern(4));
  s.msaa.quads = true;
  s.msaa.derivatives = rastrules::DerivativeMode::kFine;
  s.msaa.has_centroid = true;
  expect_same_for_every_thread_count(s);
}

// rule: FAST.THREADS.DETERMINISTIC
TEST(ThreadsDeterministic, RenderReportsTheSameErrorForEveryThreadCount) {
  rastrules::Scene s = mixed_scene();
  s.primitives[7].v[1][0] = std::numeric_limits<float>::quiet_NaN();
  for (const unsigned n : {1u, 4u}) {
    RenderOptions o;
    o.threads = n;
    const auto r = rastrules::render(s, o);
    ASSERT_TRUE(std::holds_alternative<rastrules::SceneError>(r));
    EXPECT_EQ(std::get<rastrules::SceneError>(r).what(), "primitives[7].v[1][0]: is NaN");
  }
}

// rule: FAST.THREADS.DETERMINISTIC
TEST(ThreadsDeterministic, EmptySceneGivesNoFragments) {
  rastrules::Scene s;
  s.width = 4;
  s.height = 4;
  RenderOptions o;
  o.threads = 8;
  EXPECT_TRUE(rastrules::rasterize(prepared(s), o).empty());
}

// rule: FAST.THREADS.DETERMINISTIC
TEST(ThreadPool, RunsEveryUnitExactlyOnce) {
  for (const unsigned n : {0u, 1u, 2u, 3u, 8u, 64u, 1000u}) {
    std::vector<std::atomic<int>> runs(257);
    rastrules::run_units(runs.size(), n, [&](std::size_t i) { runs[i].fetch_add(1); });
    for (std::size_t i = 0; i < runs.size(); ++i)
      EXPECT_EQ(runs[i].load(), 1) << "unit " << i << ", " << n << " threads";
  }
  rastrules::run_units(0, 8, [](std::size_t) { FAIL() << "no unit to run"; });
}

// rule: FAST.THREADS.DETERMINISTIC
TEST(ThreadPool, OneThreadRunsInlineInOrder) {
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<std::size_t> order;
  rastrules::run_units(50, 1, [&](std::size_t i) {
    EXPECT_EQ(std::this_thread::get_id(), caller);
    order.push_back(i);
  });
  ASSERT_EQ(order.size(), 50u);
  for (std::size_t i = 0; i < order.size(); ++i)
    EXPECT_EQ(order[i], i);
  // One unit: no thread either, whatever is asked for.
  rastrules::run_units(1, 64, [&](std::size_t) { EXPECT_EQ(std::this_thread::get_id(), caller); });
}

// rule: FAST.THREADS.DETERMINISTIC
TEST(ThreadPool, SeveralThreadsAreUsed) {
  // Each unit waits until two distinct threads have arrived, so the pool must run two at once
  // (bounded wait: a pool that never does fails instead of hanging).
  std::atomic<int> arrived{0};
  std::atomic<bool> met{false};
  rastrules::run_units(2, 2, [&](std::size_t) {
    arrived.fetch_add(1);
    for (int spin = 0; spin < 2000000 && arrived.load() < 2; ++spin)
      std::this_thread::yield();
    if (arrived.load() >= 2)
      met = true;
  });
  EXPECT_TRUE(met.load());
}

// rule: FAST.THREADS.DETERMINISTIC
TEST(ThreadPool, TheLowestFailingUnitsExceptionReachesTheCaller) {
  for (const unsigned n : {1u, 2u, 3u, 8u, 64u}) {
    std::vector<std::atomic<int>> runs(200);
    try {
      rastrules::run_units(runs.size(), n, [&](std::size_t i) {
        runs[i].fetch_add(1);
        if (i == 37 || i == 150)
          throw std::runtime_error("unit " + std::to_string(i));
      });
      ADD_FAILURE() << "no exception with " << n << " threads";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "unit 37") << n << " threads";
    }
    for (std::size_t i = 0; i <= 37; ++i)
      EXPECT_EQ(runs[i].load(), 1) << "unit " << i << ", " << n << " threads";
  }
}

// rule: FAST.THREADS.DETERMINISTIC
TEST(ThreadPool, OutOfMemoryInAWorkerReachesTheCaller) {
  for (const unsigned n : {1u, 4u}) {
    EXPECT_THROW(rastrules::run_units(16, n,
                                      [](std::size_t i) {
                                        if (i == 9)
                                          throw std::bad_alloc();
                                      }),
                 std::bad_alloc)
        << n << " threads";
  }
}

// rule: FAST.THREADS.DETERMINISTIC
TEST(OrderedPool, ConsumesInOrderWithinTheWindowForEveryThreadCount) {
  for (const unsigned n : {1u, 2u, 3u, 8u, 64u}) {
    for (const std::size_t window : {std::size_t{1}, std::size_t{3}, std::size_t{32}}) {
      const std::size_t units = 300;
      std::vector<std::size_t> slot(window, units); // which unit each slot holds
      std::vector<std::atomic<int>> produced(units);
      std::atomic<std::size_t> consumed{0};
      std::atomic<bool> ahead_too_far{false};
      std::vector<std::size_t> order;
      rastrules::run_ordered(
          units, n, window,
          [&](std::size_t i) {
            if (i >= consumed.load() + window)
              ahead_too_far = true;
            produced[i].fetch_add(1);
            slot[i % window] = i;
          },
          [&](std::size_t i) {
            EXPECT_EQ(produced[i].load(), 1) << "unit " << i;
            EXPECT_EQ(slot[i % window], i) << "unit " << i << ": its slot was overwritten";
            order.push_back(i);
            consumed = i + 1;
          });
      EXPECT_FALSE(ahead_too_far.load()) << n << " threads, window " << window;
      ASSERT_EQ(order.size(), units);
      for (std::size_t i = 0; i < units; ++i)
        EXPECT_EQ(order[i], i);
    }
  }
}

// rule: FAST.THREADS.DETERMINISTIC
TEST(OrderedPool, TheFirstFailureInIndexOrderStopsItWhateverTheThreadCount) {
  for (const unsigned n : {1u, 2u, 8u}) {
    // A producer failure: units before it are consumed, none after.
    std::vector<std::size_t> order;
    try {
      rastrules::run_ordered(
          100, n, 8,
          [&](std::size_t i) {
            if (i == 41 || i == 77)
              throw std::runtime_error("unit " + std::to_string(i));
          },
          [&](std::size_t i) { order.push_back(i); });
      ADD_FAILURE() << "no exception with " << n << " threads";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "unit 41") << n << " threads";
    }
    ASSERT_EQ(order.size(), 41u) << n << " threads";
    // A consumer failure: rethrown as it is, nothing consumed after it.
    std::size_t last = 0;
    EXPECT_THROW(rastrules::run_ordered(
                     100, n, 4, [](std::size_t) {},
                     [&](std::size_t i) {
                       last = i;
                       if (i == 13)
                         throw std::bad_alloc();
                     }),
                 std::bad_alloc)
        << n << " threads";
    EXPECT_EQ(last, 13u);
  }
}

} // namespace
