// SPDX-License-Identifier: MIT
// Multithreaded rendering with results independent of the thread count: a pool of
// standard-library threads, one work unit per primitive, results stored per unit and
// concatenated in primitive order.
// Implements: FAST.THREADS.DETERMINISTIC

#include "rastrules/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

#include "rastrules/scene.hpp"

namespace rastrules {

// rule: FAST.THREADS.DETERMINISTIC
void run_units(std::size_t n, unsigned threads, const std::function<void(std::size_t)>& unit) {
  const std::size_t wanted = std::min<std::size_t>(std::clamp(threads, 1U, kMaxThreads), n);
  if (wanted <= 1) {
    for (std::size_t i = 0; i < n; ++i)
      unit(i); // inline, in order: the first throw stops it
    return;
  }
  std::atomic<std::size_t> next{0};
  // The lowest index of a unit that threw (n: none yet) and its exception. Units are claimed in
  // increasing order, so when a unit fails every unit before it has been claimed and runs to
  // its end; units after the lowest failure are skipped.
  std::atomic<std::size_t> first_failed{n};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto work = [&] {
    for (;;) {
      const std::size_t i = next.fetch_add(1, std::memory_order_relaxed);
      if (i >= n || i > first_failed.load(std::memory_order_acquire))
        return;
      try {
        unit(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failure_mutex);
        if (i < first_failed.load(std::memory_order_relaxed)) {
          failure = std::current_exception();
          first_failed.store(i, std::memory_order_release);
        }
      }
    }
  };
  {
    std::vector<std::jthread> pool;
    pool.reserve(wanted - 1);
    for (std::size_t t = 0; t + 1 < wanted; ++t) {
      try {
        pool.emplace_back(work);
      } catch (const std::system_error&) {
        break; // no more threads: the ones running (and this one) take the remaining units
      }
    }
    work();
  } // the jthreads join here
  if (failure)
    std::rethrow_exception(failure);
}

// rule: FAST.THREADS.DETERMINISTIC
void run_ordered(std::size_t n, unsigned threads, std::size_t window,
                 const std::function<void(std::size_t)>& produce,
                 const std::function<void(std::size_t)>& consume) {
  const std::size_t wanted = std::min<std::size_t>(std::clamp(threads, 1U, kMaxThreads), n);
  if (wanted <= 1) {
    for (std::size_t i = 0; i < n; ++i) {
      produce(i);
      consume(i);
    }
    return;
  }
  window = std::max<std::size_t>(window, 1);
  struct Slot {
    bool ready = false;
    std::exception_ptr failure;
  };
  std::mutex m;
  std::condition_variable produced; // a slot became ready
  std::condition_variable room;     // a unit was consumed, or stop
  std::vector<Slot> slots(window);
  std::size_t next = 0;     // the next unit to produce
  std::size_t consumed = 0; // units consumed so far
  bool stop = false;
  auto work = [&] {
    for (;;) {
      std::size_t i = 0;
      {
        std::unique_lock<std::mutex> lock(m);
        room.wait(lock, [&] { return stop || next >= n || next < consumed + window; });
        if (stop || next >= n)
          return;
        i = next++;
      }
      std::exception_ptr failure;
      try {
        produce(i);
      } catch (...) {
        failure = std::current_exception();
      }
      {
        const std::lock_guard<std::mutex> lock(m);
        slots[i % window].ready = true;
        slots[i % window].failure = failure;
      }
      produced.notify_one();
    }
  };
  std::exception_ptr failure;
  {
    std::vector<std::jthread> pool;
    pool.reserve(wanted);
    // Stops and joins the pool however this scope is left (consume may throw).
    struct Stopper {
      std::mutex& m;
      bool& stop;
      std::condition_variable& room;
      std::vector<std::jthread>& pool;
      ~Stopper() {
        {
          const std::lock_guard<std::mutex> lock(m);
          stop = true;
        }
        room.notify_all();
        pool.clear(); // joins
      }
    } stopper{m, stop, room, pool};
    for (std::size_t t = 0; t < wanted; ++t) {
      try {
        pool.emplace_back(work);
      } catch (const std::system_error&) {
        break; // fewer threads: the ones running take every unit
      }
    }
    if (pool.empty()) {
      // Not a single thread: produce on this one.
      for (std::size_t i = 0; i < n; ++i) {
        produce(i);
        consume(i);
      }
      return;
    }
    for (std::size_t i = 0; i < n; ++i) {
      Slot* slot = nullptr;
      {
        std::unique_lock<std::mutex> lock(m);
        produced.wait(lock, [&] { return slots[i % window].ready; });
        slot = &slots[i % window];
        failure = slot->failure;
      }
      if (failure)
        break;    // the lowest-index failure: later units are not consumed
      consume(i); // may throw: the stopper stops the pool
      {
        const std::lock_guard<std::mutex> lock(m);
        slot->ready = false;
        consumed = i + 1;
      }
      room.notify_all();
    }
  }
  if (failure)
    std::rethrow_exception(failure);
}

// rule: FAST.THREADS.DETERMINISTIC, SCENE.OUTPUT.FRAGMENTS
std::vector<Fragment> rasterize(const PreparedScene& scene, const RenderOptions& options) {
  const std::size_t n = scene.primitives.size();
  std::vector<std::vector<Fragment>> per_unit(n);
  run_units(n, options.threads,
            [&](std::size_t p) { per_unit[p] = rasterize_primitive(scene, p, options); });
  std::size_t total = 0;
  for (const auto& f : per_unit)
    total += f.size();
  std::vector<Fragment> out;
  out.reserve(total);
  for (auto& f : per_unit) {
    out.insert(out.end(), f.begin(), f.end());
    std::vector<Fragment>().swap(f); // release each unit's copy as soon as it is moved
  }
  return out; // primitives in order, each sorted by (y, x, seg, sample)
}

} // namespace rastrules
