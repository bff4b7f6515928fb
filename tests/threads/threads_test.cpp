// SPDX-License-Identifier: MIT
// Threads change the time, not the result (FAST.THREADS.DETERMINISTIC): rasterize() with 1, 2,
// 3, 8 and 64 threads gives the single-threaded fragments on scenes of mixed primitives, with
// one sample and with 4 samples; the pool runs every unit once, inline for one thread, and
// rethrows the exception of the lowest-index failing unit whatever the thread count; the
// streaming pool of the command line hands every fragment over in order through bounded
// buffers and stops at the first failure in that order.

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <new>
#include <optional>
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

// Unit i puts i % 7 * 40 fragments (with prim = i and x counting up; every third unit's
// fragments carry a sample, so they are kept whole) for i < units.
void put_unit(std::size_t i, const std::function<void(const Fragment&)>& put) {
  for (std::int32_t k = 0; k < static_cast<std::int32_t>(i % 7 * 40); ++k) {
    Fragment f{static_cast<std::uint32_t>(i), k, 0};
    if (i % 3 == 0)
      f.sample = 2;
    put(f);
  }
}

// rule: FAST.THREADS.DETERMINISTIC, SCENE.INPUT.LIMITS
TEST(StreamPool, ConsumesEveryFragmentInOrderWithBoundedBuffersForEveryThreadCount) {
  const std::size_t units = 60;
  std::vector<Fragment> expected;
  for (std::size_t i = 0; i < units; ++i)
    put_unit(i, [&](const Fragment& f) { expected.push_back(f); });
  for (const unsigned n : {1u, 2u, 3u, 8u, 64u}) {
    for (const rastrules::StreamBuffers b :
         {rastrules::StreamBuffers{.batch = 1, .batches_per_unit = 1, .window = 1},
          rastrules::StreamBuffers{.batch = 10, .batches_per_unit = 4, .window = 3},
          rastrules::StreamBuffers{}}) {
      std::atomic<std::size_t> planned{0}, live{0}, most_live{0}, put_count{0}, consumed{0},
          most_held{0};
      std::vector<Fragment> got;
      rastrules::stream_ordered(
          n, b,
          [&](std::size_t i) {
            EXPECT_EQ(i, planned.load()) << "planned out of order";
            planned = i + 1;
            return i < units;
          },
          [&](std::size_t i, const std::function<void(const Fragment&)>& put) {
            const std::size_t now = ++live;
            for (std::size_t m = most_live.load();
                 now > m && !most_live.compare_exchange_weak(m, now);) {
            }
            put_unit(i, [&](const Fragment& f) {
              // Fragments put and not yet consumed, this one included.
              const std::size_t held = ++put_count - consumed.load();
              for (std::size_t m = most_held.load();
                   held > m && !most_held.compare_exchange_weak(m, held);) {
              }
              put(f);
            });
            --live;
          },
          [&](const Fragment& f) {
            got.push_back(f);
            ++consumed;
          });
      EXPECT_EQ(planned.load(), units + 1) << n << " threads";
      EXPECT_LE(most_live.load(), std::max<std::size_t>(n, 1)) << n << " threads";
      EXPECT_LE(most_held.load(), b.max_held()) << n << " threads, batch " << b.batch;
      EXPECT_TRUE(got == expected) << n << " threads, batch " << b.batch;
    }
  }
}

// rule: FAST.THREADS.DETERMINISTIC
TEST(StreamPool, EncodedBytesArriveOnceInTheOrderOfTheFragments) {
  const std::size_t units = 40;
  // Each fragment's bytes name it; consume and consume_bytes interleave batch by batch, so the
  // bytes received so far never run ahead of the fragments consumed.
  const auto text = [](const Fragment& f) {
    return "(" + std::to_string(f.prim) + "," + std::to_string(f.x) + ")";
  };
  std::string expected;
  for (std::size_t i = 0; i < units; ++i)
    put_unit(i, [&](const Fragment& f) { expected += text(f); });
  for (const unsigned n : {1u, 2u, 5u}) {
    for (const rastrules::StreamBuffers b :
         {rastrules::StreamBuffers{.batch = 1, .batches_per_unit = 1, .window = 1},
          rastrules::StreamBuffers{.batch = 7, .batches_per_unit = 2, .window = 3}}) {
      std::string consumed_text, bytes;
      bool ahead = false;
      const rastrules::StreamEncoding encoding{
          .encode = [&](const Fragment& f, std::string& out) { out += text(f); },
          .consume_bytes =
              [&](std::string_view t) {
                bytes += t;
                ahead = ahead || bytes.size() > consumed_text.size();
              },
          .consume_summary = nullptr};
      rastrules::stream_ordered(
          n, b, [&](std::size_t i) { return i < units; }, put_unit,
          [&](const Fragment& f) { consumed_text += text(f); }, &encoding);
      EXPECT_EQ(bytes, expected) << n << " threads, batch " << b.batch;
      EXPECT_EQ(consumed_text, expected) << n << " threads, batch " << b.batch;
      EXPECT_FALSE(ahead) << n << " threads, batch " << b.batch;
    }
  }
}

// rule: FAST.THREADS.DETERMINISTIC
TEST(StreamPool, BatchSummariesReplaceConsumeAndChainInOrder) {
  const std::size_t units = 40;
  std::vector<Fragment> all;
  for (std::size_t i = 0; i < units; ++i)
    put_unit(i, [&](const Fragment& f) { all.push_back(f); });
  for (const unsigned n : {1u, 2u, 5u}) {
    const rastrules::StreamBuffers b{.batch = 7, .batches_per_unit = 2, .window = 3};
    std::size_t count = 0, consumed = 0, bytes = 0;
    bool chained = true, in_order = true;
    std::optional<Fragment> last;
    const rastrules::StreamEncoding encoding{
        .encode = [](const Fragment&, std::string& out) { out += 'x'; },
        .consume_bytes = [&](std::string_view t) { bytes += t.size(); },
        .consume_summary =
            [&](const rastrules::BatchSummary& s) {
              // Each summary starts where the previous one ended, in the fragments' order.
              chained = chained && s.count > 0 && count + s.count <= all.size() &&
                        s.first == all[count] && s.last == all[count + s.count - 1] &&
                        (!last || rastrules::fragment_before(*last, s.first));
              in_order = in_order && s.in_order;
              count += s.count;
              last = s.last;
            }};
    rastrules::stream_ordered(
        n, b, [&](std::size_t i) { return i < units; }, put_unit,
        [&](const Fragment&) { ++consumed; }, &encoding);
    EXPECT_EQ(consumed, 0u) << n << " threads";
    EXPECT_EQ(count, all.size()) << n << " threads";
    EXPECT_EQ(bytes, all.size()) << n << " threads";
    EXPECT_TRUE(chained) << n << " threads";
    EXPECT_TRUE(in_order) << n << " threads";
  }
  // A batch whose fragments are out of order says so.
  const rastrules::StreamEncoding encoding{
      .encode = [](const Fragment&, std::string&) {},
      .consume_bytes = [](std::string_view) {},
      .consume_summary = [&](const rastrules::BatchSummary& s) { EXPECT_FALSE(s.in_order); }};
  rastrules::stream_ordered(
      2, rastrules::StreamBuffers{.batch = 4, .batches_per_unit = 1, .window = 2},
      [](std::size_t i) { return i < 1; },
      [](std::size_t, const std::function<void(const Fragment&)>& put) {
        for (const std::int32_t x : {0, 1, 3, 2})
          put(Fragment{0, x, 0});
      },
      [](const Fragment&) {}, &encoding);
}

// rule: FAST.THREADS.DETERMINISTIC
TEST(StreamPool, TheFirstFailureInOrderStopsItWhateverTheThreadCount) {
  for (const unsigned n : {1u, 2u, 8u}) {
    const rastrules::StreamBuffers b{.batch = 16, .batches_per_unit = 2, .window = n + 1u};
    // A producer failure after some fragments: those are consumed first, nothing after.
    std::vector<Fragment> got;
    try {
      rastrules::stream_ordered(
          n, b, [](std::size_t i) { return i < 100; },
          [&](std::size_t i, const std::function<void(const Fragment&)>& put) {
            for (std::int32_t k = 0; k < 50; ++k)
              put(Fragment{static_cast<std::uint32_t>(i), k, 0});
            if (i == 41 || i == 77)
              throw std::runtime_error("unit " + std::to_string(i));
          },
          [&](const Fragment& f) { got.push_back(f); });
      ADD_FAILURE() << "no exception with " << n << " threads";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "unit 41") << n << " threads";
    }
    EXPECT_EQ(got.size(), 42u * 50u) << n << " threads";
    // A consumer failure: rethrown as it is, nothing consumed after it.
    std::size_t count = 0;
    EXPECT_THROW(rastrules::stream_ordered(
                     n, b, [](std::size_t i) { return i < 100; },
                     [&](std::size_t i, const std::function<void(const Fragment&)>& put) {
                       for (std::int32_t k = 0; k < 50; ++k)
                         put(Fragment{static_cast<std::uint32_t>(i), k, 0});
                     },
                     [&](const Fragment&) {
                       if (++count == 1234)
                         throw std::bad_alloc();
                     }),
                 std::bad_alloc)
        << n << " threads";
    EXPECT_EQ(count, 1234u);
    // A plan failure is the failure of the unit it plans.
    got.clear();
    try {
      rastrules::stream_ordered(
          n, b,
          [](std::size_t i) {
            if (i == 9)
              throw std::runtime_error("plan 9");
            return true;
          },
          [&](std::size_t i, const std::function<void(const Fragment&)>& put) {
            put(Fragment{static_cast<std::uint32_t>(i), 0, 0});
          },
          [&](const Fragment& f) { got.push_back(f); });
      ADD_FAILURE() << "no exception with " << n << " threads";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "plan 9") << n << " threads";
    }
    EXPECT_EQ(got.size(), 9u) << n << " threads";
  }
}

// rule: FAST.THREADS.DETERMINISTIC
// produce_ordered hands every unit's bytes to consume once, in index order, on the calling
// thread, with at most `window` units produced and not yet consumed (a slow consumer makes the
// threads wait), for every thread count and window; one thread produces inline.
TEST(OrderedBytes, EveryUnitReachesTheCallerOnceInOrderWithinTheWindow) {
  const std::thread::id caller = std::this_thread::get_id();
  for (const unsigned threads : {1u, 2u, 3u, 8u, 64u}) {
    for (const std::size_t window : {0u, 1u, 2u, 7u}) {
      for (const std::size_t n : {0u, 1u, 2u, 5u, 300u}) {
        std::atomic<int> held{0}, most{0};
        std::size_t expected = 0;
        rastrules::produce_ordered(
            n, threads, window,
            [&](std::size_t i, std::string& bytes) {
              EXPECT_TRUE(bytes.empty());
              const int now = held.fetch_add(1) + 1;
              for (int m = most.load(); now > m && !most.compare_exchange_weak(m, now);) {
              }
              if (threads == 1) {
                EXPECT_EQ(std::this_thread::get_id(), caller);
              }
              bytes = "unit " + std::to_string(i);
            },
            [&](std::size_t i, std::string& bytes) {
              EXPECT_EQ(std::this_thread::get_id(), caller);
              EXPECT_EQ(i, expected);
              EXPECT_EQ(bytes, "unit " + std::to_string(i));
              ++expected;
              if (i % 7 == 0) // a slow consumer: the window fills
                std::this_thread::sleep_for(std::chrono::microseconds(200));
              held.fetch_sub(1);
            });
        EXPECT_EQ(expected, n) << threads << " threads, window " << window;
        EXPECT_LE(most.load(), static_cast<int>(std::max<std::size_t>(window, 1)))
            << threads << " threads, window " << window << ", " << n << " units";
      }
    }
  }
}

// rule: FAST.THREADS.DETERMINISTIC
// A unit that throws: consume has seen exactly the units before it, and its exception reaches
// the caller; a consumer that throws: rethrown at once, nothing consumed after it.
TEST(OrderedBytes, TheFirstFailureInOrderStopsItWhateverTheThreadCount) {
  for (const unsigned threads : {1u, 2u, 3u, 8u}) {
    std::vector<std::size_t> seen;
    try {
      rastrules::produce_ordered(
          200, threads, 4,
          [](std::size_t i, std::string& bytes) {
            if (i == 37 || i == 90)
              throw std::runtime_error("unit " + std::to_string(i));
            bytes = "x";
          },
          [&](std::size_t i, std::string&) { seen.push_back(i); });
      ADD_FAILURE() << "no exception with " << threads << " threads";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "unit 37") << threads << " threads";
    }
    ASSERT_EQ(seen.size(), 37u) << threads << " threads";
    for (std::size_t i = 0; i < seen.size(); ++i)
      EXPECT_EQ(seen[i], i);
    std::size_t count = 0;
    EXPECT_THROW(rastrules::produce_ordered(
                     200, threads, 3, [](std::size_t, std::string& bytes) { bytes = "y"; },
                     [&](std::size_t, std::string&) {
                       if (++count == 20)
                         throw std::bad_alloc();
                     }),
                 std::bad_alloc)
        << threads << " threads";
    EXPECT_EQ(count, 20u);
  }
}

} // namespace
