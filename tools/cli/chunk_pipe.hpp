// SPDX-License-Identifier: MIT
// Chunks of triangles handed from the reader (io::stream_triangles_fast) to their consumer in
// order: on the reading thread, or on one consuming thread beside it through a bounded queue, so
// that reading a scene and counting or writing its fragments overlap (render --count, render
// --fragments OUT on a scene of the fast reader's form).
// Implements: FAST.THREADS.DETERMINISTIC, SCENE.INPUT.FAST_READER

#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <span>
#include <thread>
#include <vector>

namespace rastrules::cli {

// rule: FAST.THREADS.DETERMINISTIC
// Calls consume(xy) for each chunk pushed, in the order pushed, each after the one before has
// returned: on the pushing thread (threaded false), or on one thread of its own through a queue
// of kSlots chunks (push copies the chunk into a free slot, waiting while none is free). Once
// consume returns false it is not called again, and push and finish return false. The consumer
// sees the same chunks in the same order either way, so what it makes cannot depend on the
// threads. A pipe must be destroyed (or finished) before whatever consume uses: declare it
// after those members.
class ChunkPipe {
public:
  static constexpr std::size_t kSlots = 4;
  using Consume = std::function<bool(std::span<const float>)>;

  ChunkPipe(bool threaded, Consume consume);
  ChunkPipe(const ChunkPipe&) = delete;
  ChunkPipe& operator=(const ChunkPipe&) = delete;
  ~ChunkPipe();

  // Hands xy over; false once a chunk was refused.
  bool push(std::span<const float> xy);
  // Waits until every chunk pushed is consumed (and stops the thread); whether none was refused.
  bool finish();

private:
  void work();

  Consume consume_;
  std::mutex mutex_;
  std::condition_variable data_, space_;
  std::deque<std::vector<float>> ready_;
  std::vector<std::vector<float>> free_;
  bool refused_ = false; // guarded by mutex_ while the thread runs
  bool done_ = false;
  std::thread worker_;
};

} // namespace rastrules::cli
