// SPDX-License-Identifier: MIT
// The thread pool of the render entry points (FAST.THREADS.DETERMINISTIC): work units with
// indices 0 .. n-1 run on up to `threads` standard-library threads that take the next unit from
// an atomic counter. Callers store each unit's result at its index and combine them in index
// order, so nothing they produce depends on the thread count or on scheduling.
// Implements: FAST.THREADS.DETERMINISTIC

#pragma once

#include <cstddef>
#include <functional>

namespace rastrules {

// The largest thread count a render accepts (`--threads`, RenderOptions::threads).
inline constexpr unsigned kMaxThreads = 256;

// Calls unit(i) once for each i in [0, n) on min(threads, n) threads (threads == 0 is read as
// 1, more than kMaxThreads as kMaxThreads). With one thread (or one unit) every unit runs on the
// calling thread, in index order, and no thread is created; otherwise the calling thread works
// as one of the threads. Units are taken in increasing index order. When units throw, the
// exception of the lowest-index failing unit is rethrown to the caller after every thread has
// stopped, and units after it may not run (every unit before it has run): the same exception
// for every thread count. A thread that cannot be created leaves its share to the others.
// rule: FAST.THREADS.DETERMINISTIC
void run_units(std::size_t n, unsigned threads, const std::function<void(std::size_t)>& unit);

// Calls produce(i) for each i in [0, n) on a pool of min(threads, n) threads created once, and
// consume(i) on the calling thread in increasing i, each after produce(i) has returned. At most
// `window` units (>= 1) are produced ahead of the last consumed one, so produce(i) may write a
// slot i % window that consume(i) reads. With one thread every produce(i) runs on the calling
// thread just before consume(i), and no thread is created. The first exception in index order
// (from produce(i) or consume(i)) stops the pool and is rethrown after every thread has
// stopped; consume(j) never runs for j past it: the same outcome for every thread count.
// rule: FAST.THREADS.DETERMINISTIC
void run_ordered(std::size_t n, unsigned threads, std::size_t window,
                 const std::function<void(std::size_t)>& produce,
                 const std::function<void(std::size_t)>& consume);

} // namespace rastrules
