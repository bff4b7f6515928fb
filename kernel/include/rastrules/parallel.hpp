// SPDX-License-Identifier: MIT
// The thread pool of the render entry points (FAST.THREADS.DETERMINISTIC): work units with
// indices 0 .. n-1 run on up to `threads` standard-library threads that take the next unit from
// an atomic counter. Callers store each unit's result at its index and combine them in index
// order, so nothing they produce depends on the thread count or on scheduling.
// Implements: FAST.THREADS.DETERMINISTIC

#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

#include "rastrules/scene.hpp"

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

// The buffers of stream_ordered: fragments are handed from the pool to the calling thread in
// batches of `batch` fragments; a unit holds at most `batches_per_unit` full batches and one it
// fills, and at most `window` units (>= 1) are started ahead of the one being consumed.
struct StreamBuffers {
  std::size_t batch = 2048;
  std::size_t batches_per_unit = 2;
  std::size_t window = 2;
  // The most fragments buffered at once: every unit of the window with its full batches and
  // the one it fills, the batches the calling thread consumes (it takes a unit's full batches
  // at once: at most batches_per_unit), and up to `window` emptied batches kept for reuse. A
  // buffered fragment takes 16 bytes, plus sizeof(Fragment) when it has more than (prim, x, y, mask
  // 1): seg, coverage, sample, centroid, derivatives, helper.
  [[nodiscard]] std::size_t max_held() const {
    return (window * (batches_per_unit + 2) + batches_per_unit) * batch;
  }
};

// Bytes the producing threads make of each fragment (its JSON text, for example), so that the
// calling thread only concatenates them: encode(f, bytes) appends f's bytes on the thread that
// puts f; consume_bytes receives each batch's bytes on the calling thread right after consume
// has seen that batch's fragments, so every fragment's bytes arrive once, in consume's order.
// A batch's bytes are held with it (at most max_held() fragments' bytes in all).
// A batch's fragments in brief: how many, the first and the last (their order fields prim, x,
// y, seg and sample only: what fragment_before compares), and whether each comes before the
// next in (prim, y, x, seg, sample) order (fragment_before).
struct BatchSummary {
  std::size_t count = 0;
  Fragment first, last;
  bool in_order = true;
};

struct StreamEncoding {
  std::function<void(const Fragment&, std::string&)> encode;
  std::function<void(std::string_view)> consume_bytes;
  // When set, it replaces consume: each batch reaches the calling thread as its summary (made
  // on the thread that filled it) and its bytes, so that the calling thread does no work per
  // fragment (a caller that needs only the bytes, the count and the order).
  std::function<void(const BatchSummary&)> consume_summary;
};

// Streams the fragments of work units 0, 1, 2, ... produced on a pool of `threads` threads
// created once to consume, called on the calling thread in unit order and, within a unit, in
// the order produce(i, put) puts them: the calls consume sees do not depend on the thread count
// or on scheduling. plan(i) is called once for i = 0, 1, ... in increasing order, under the
// pool's lock, until it returns false (there is no unit i); units i and later are not produced.
// A unit whose fragments are not consumed as fast as they are put waits in put when it holds
// buffers.batches_per_unit full batches, so at most buffers.max_held() fragments are held,
// whatever the number of fragments or units. With one thread (or none that can be created)
// every unit is produced on the calling thread, its fragments passed straight to consume. An
// exception from produce(i) is rethrown after consume has seen every fragment unit i put before
// it; one from consume is rethrown at once; either way the pool stops first, and nothing after
// it is consumed: the same outcome for every thread count. With an encoding, its bytes reach
// consume_bytes as StreamEncoding says (on the calling thread, fragment by fragment, when every
// unit is produced there).
// rule: FAST.THREADS.DETERMINISTIC, SCENE.INPUT.LIMITS
void stream_ordered(
    unsigned threads, const StreamBuffers& buffers, const std::function<bool(std::size_t)>& plan,
    const std::function<void(std::size_t, const std::function<void(const Fragment&)>&)>& produce,
    const std::function<void(const Fragment&)>& consume, const StreamEncoding* encoding = nullptr);

// Produces units 0 .. n-1 as bytes on `threads` threads (threads - 1 created for the call and
// the calling thread) and hands them to consume on the calling thread in index order:
// produce(i, bytes) appends unit i's bytes to an empty string; consume(i, bytes) sees them, in
// order i = 0, 1, ... (the string is cleared and reused after it returns). The calling thread
// consumes the next unit when it is ready and otherwise produces one. At most `window` units
// (>= 1; 0 is read as 1) are produced or held ahead of the one consume waits for, so at most
// `window` units' bytes are held at once, whatever n. Threads block on condition variables
// when the window is full (no spinning: a loaded machine slows them, it does not stall them).
// With one thread every unit is produced on the calling thread right before it is consumed. An
// exception from produce(i) is rethrown after consume has seen every unit before i; one from
// consume at once; the pool stops first, and nothing after it is consumed: the same outcome for
// every thread count.
// rule: FAST.THREADS.DETERMINISTIC
void produce_ordered(std::size_t n, unsigned threads, std::size_t window,
                     const std::function<void(std::size_t, std::string&)>& produce,
                     const std::function<void(std::size_t, std::string&)>& consume);

} // namespace rastrules
