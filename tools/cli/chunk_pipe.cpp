// SPDX-License-Identifier: MIT
// Implements: FAST.THREADS.DETERMINISTIC, SCENE.INPUT.FAST_READER

#include "chunk_pipe.hpp"

#include <utility>

namespace rastrules::cli {

ChunkPipe::ChunkPipe(bool threaded, Consume consume) : consume_(std::move(consume)) {
  if (threaded) {
    free_.resize(kSlots);
    worker_ = std::thread([this] { work(); });
  }
}

ChunkPipe::~ChunkPipe() {
  (void)finish();
}

// rule: FAST.THREADS.DETERMINISTIC
bool ChunkPipe::push(std::span<const float> xy) {
  if (!worker_.joinable()) {
    refused_ = refused_ || !consume_(xy);
    return !refused_;
  }
  std::unique_lock lock(mutex_);
  space_.wait(lock, [&] { return !free_.empty() || refused_; });
  if (refused_)
    return false;
  std::vector<float> slot = std::move(free_.back());
  free_.pop_back();
  slot.assign(xy.begin(), xy.end());
  ready_.push_back(std::move(slot));
  lock.unlock();
  data_.notify_one();
  return true;
}

bool ChunkPipe::finish() {
  if (worker_.joinable()) {
    {
      const std::lock_guard lock(mutex_);
      done_ = true;
    }
    data_.notify_one();
    worker_.join();
  }
  return !refused_;
}

void ChunkPipe::work() {
  for (;;) {
    std::unique_lock lock(mutex_);
    data_.wait(lock, [&] { return !ready_.empty() || done_ || refused_; });
    if (refused_ || ready_.empty())
      return; // refused, or done with every chunk consumed
    std::vector<float> chunk = std::move(ready_.front());
    ready_.pop_front();
    lock.unlock();
    const bool ok = consume_(chunk);
    lock.lock();
    refused_ = refused_ || !ok;
    free_.push_back(std::move(chunk));
    lock.unlock();
    space_.notify_one();
  }
}

} // namespace rastrules::cli
