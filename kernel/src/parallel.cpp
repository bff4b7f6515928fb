// SPDX-License-Identifier: MIT
// Multithreaded rendering with results independent of the thread count: a pool of
// standard-library threads, one work unit per primitive, results stored per unit and
// concatenated in primitive order; and a pool streaming work units' fragments in order
// through bounded buffers.
// Implements: FAST.THREADS.DETERMINISTIC

#include "rastrules/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <string>
#include <system_error>
#include <thread>
#include <tuple>
#include <vector>

#include "rastrules/scene.hpp"

namespace rastrules {

namespace {

// Starts up to n threads running work. A thread that cannot be created leaves its share to the
// ones running (and the calling thread).
template <class Work> std::vector<std::jthread> start_threads(std::size_t n, const Work& work) {
  std::vector<std::jthread> pool;
  pool.reserve(n);
  for (std::size_t t = 0; t < n; ++t) {
    try {
      pool.emplace_back(work);
    } catch (const std::system_error&) {
      break;
    }
  }
  return pool;
}

} // namespace

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
    std::vector<std::jthread> pool = start_threads(wanted - 1, work);
    work();
  } // the jthreads join here
  if (failure)
    std::rethrow_exception(failure);
}

namespace {

// Thrown in a pool thread's put when the pool stops: unwinds its unit, never seen outside.
struct PoolStopped {};

// The shared state of stream_ordered: per unit of the window (slot i % window) the full
// batches not yet consumed, whether the unit is done, and its exception.
class StreamPool {
public:
  // A batch: one 16-byte entry a fragment; a fragment with more than (prim, x, y, mask 1) is
  // kept whole beside it. A single-sample triangle's fragments take 16 bytes each.
  struct Batch {
    static constexpr std::uint32_t kPlain = ~std::uint32_t{0};
    struct Entry {
      std::uint32_t prim;
      std::int32_t x, y;
      std::uint32_t whole; // index in `whole`, or kPlain: Fragment{prim, x, y, 1}
    };
    std::vector<Entry> entries;
    std::vector<Fragment> whole;
    std::string bytes;    // the encoding's bytes of the fragments, when there is one
    BatchSummary summary; // with the encoding's consume_summary: instead of the entries

    void push_back(const Fragment& f) {
      const bool plain = f.mask == 1u && !f.seg && !f.coverage_q16 && !f.helper && !f.sample &&
                         !f.centroid && !f.derivatives && !f.area;
      entries.push_back(
          Entry{f.prim, f.x, f.y, plain ? kPlain : static_cast<std::uint32_t>(whole.size())});
      if (!plain)
        whole.push_back(f);
    }
    // The order fields of a fragment, as fragment_before compares them (a missing seg or
    // sample is -1, before every index).
    struct OrderKey {
      std::uint32_t prim = 0;
      std::int32_t y = 0, x = 0;
      std::int64_t seg = -1, sample = -1;
      [[nodiscard]] bool operator<(const OrderKey& o) const {
        return std::tie(prim, y, x, seg, sample) < std::tie(o.prim, o.y, o.x, o.seg, o.sample);
      }
      [[nodiscard]] Fragment fragment() const {
        Fragment f{prim, x, y, 1u};
        if (seg >= 0)
          f.seg = static_cast<std::uint32_t>(seg);
        if (sample >= 0)
          f.sample = static_cast<std::uint32_t>(sample);
        return f;
      }
    };
    // Counts f into the summary, keeping no entry (on the thread that fills the batch). Only
    // the order fields are kept, in integers (copying whole fragments, then building one a
    // fragment as a key, was a fifth of a producing thread's time); close_summary() writes the
    // first and last as fragments.
    void summarise(const Fragment& f) {
      const OrderKey key{f.prim, f.y, f.x, f.seg ? std::int64_t{*f.seg} : -1,
                         f.sample ? std::int64_t{*f.sample} : -1};
      if (summary.count == 0)
        first_key = key;
      else if (!(last_key < key))
        summary.in_order = false;
      last_key = key;
      ++summary.count;
    }
    void close_summary() {
      if (summary.count > 0) {
        summary.first = first_key.fragment();
        summary.last = last_key.fragment();
      }
    }
    OrderKey first_key, last_key;
    [[nodiscard]] std::size_t size() const { return entries.size() + summary.count; }
    [[nodiscard]] bool empty() const { return size() == 0; }
    void clear() {
      entries.clear();
      whole.clear();
      bytes.clear();
      summary = BatchSummary{};
    }
    void reserve(std::size_t n) { entries.reserve(n); }
    template <class F> void for_each(F&& f) const {
      for (const Entry& e : entries)
        f(e.whole == kPlain ? Fragment{e.prim, e.x, e.y, 1u} : whole[e.whole]);
    }
  };

  StreamPool(
      const StreamBuffers& b, const std::function<bool(std::size_t)>& plan,
      const std::function<void(std::size_t, const std::function<void(const Fragment&)>&)>& produce,
      const StreamEncoding* encoding)
      : b_(b), plan_(plan), produce_(produce), encoding_(encoding), slots_(b.window) {}

  // A pool thread: claims units in order while the window has room, produces them.
  void work() {
    for (;;) {
      std::size_t i = 0;
      {
        std::unique_lock<std::mutex> lock(m_);
        room_.wait(lock, [&] { return stop_ || ended_ || next_ < consumed_ + b_.window; });
        if (stop_ || ended_)
          return;
        i = next_;
        Slot& slot = slots_[i % b_.window];
        slot = Slot{};
        bool more = false;
        try {
          more = plan_(i);
        } catch (...) {
          // Unit i is its failure, and the last one.
          slot.failure = std::current_exception();
          slot.done = true;
          next_ = i + 1;
          ended_ = true;
          end_ = i + 1;
          produced_.notify_all();
          room_.notify_all();
          return;
        }
        if (!more) {
          ended_ = true;
          end_ = i;
          produced_.notify_all();
          room_.notify_all();
          return;
        }
        ++next_;
      }
      Batch batch = take_spare();
      const bool summarise = summarised();
      bool full = false; // the unit holds batches_per_unit full batches: wait before adding
      const auto put = [&](const Fragment& f) {
        if (full) {
          wait_for_room(i);
          full = false;
        }
        if (summarise)
          batch.summarise(f);
        else
          batch.push_back(f);
        if (encoding_ != nullptr)
          encoding_->encode(f, batch.bytes);
        if (batch.size() >= b_.batch)
          full = hand_over(i, batch);
      };
      std::exception_ptr failure;
      try {
        produce_(i, put);
      } catch (const PoolStopped&) {
        return;
      } catch (...) {
        failure = std::current_exception();
      }
      batch.close_summary();
      {
        const std::lock_guard<std::mutex> lock(m_);
        Slot& slot = slots_[i % b_.window];
        if (!batch.empty())
          slot.full.push_back(std::move(batch));
        slot.done = true;
        slot.failure = failure;
      }
      produced_.notify_all();
    }
  }

  // The calling thread: consumes units 0, 1, ... in order until the plan ends or a unit fails.
  void consume_all(const std::function<void(const Fragment&)>& consume) {
    std::vector<Batch> got; // a unit's full batches, taken at once (its storage reused)
    for (std::size_t i = 0;; ++i) {
      Slot& slot = slots_[i % b_.window];
      for (;;) {
        got.clear();
        {
          std::unique_lock<std::mutex> lock(m_);
          // Woken when the unit is done or holds batches_per_unit full batches (its producer
          // is about to wait), not at every batch: then it takes all of them at once. A wake-up
          // a batch put three threads on two cores through a context switch every 1536
          // fragments.
          produced_.wait(lock, [&] {
            return (ended_ && end_ <= i) ||
                   (i < next_ && (slot.done || slot.full.size() >= b_.batches_per_unit));
          });
          if (ended_ && end_ <= i)
            return;
          if (slot.full.empty()) { // done, every batch consumed
            if (slot.failure)
              std::rethrow_exception(slot.failure);
            consumed_ = i + 1;
            break;
          }
          got.swap(slot.full);
        }
        room_.notify_all(); // the unit's producer may be waiting to fill more
        for (Batch& batch : got) {
          if (summarised())
            encoding_->consume_summary(batch.summary);
          else
            batch.for_each(consume);
          if (encoding_ != nullptr)
            encoding_->consume_bytes(batch.bytes);
          batch.clear();
          give_spare(std::move(batch));
        }
      }
      room_.notify_all(); // the window moved
    }
  }

  // Stops the pool: threads waiting in put or for room return.
  void stop() {
    {
      const std::lock_guard<std::mutex> lock(m_);
      stop_ = true;
    }
    room_.notify_all();
  }

private:
  struct Slot {
    std::vector<Batch> full; // at most b_.batches_per_unit
    bool done = false;
    std::exception_ptr failure;
  };

  [[nodiscard]] bool summarised() const {
    return encoding_ != nullptr && encoding_->consume_summary;
  }

  // The number of full batches of a unit at which its waiting producer is woken.
  [[nodiscard]] std::size_t low_water() const { return b_.batches_per_unit / 2; }

  // Hands a full batch of unit i over and gives the producer an empty one. Returns whether the
  // unit now holds batches_per_unit full batches: then the producer waits (wait_for_room)
  // before it puts another fragment, not here, so that a unit whose fragments fill its batches
  // exactly (a band of batches_per_unit * batch pixels, all covered) ends without waiting for
  // the writer to reach it. (Waiting here made the thread ahead wait on every band: two
  // threads were no faster than one.) The memory held is the same: the batch given is empty
  // while the producer waits.
  bool hand_over(std::size_t i, Batch& batch) {
    batch.close_summary();
    const std::lock_guard<std::mutex> lock(m_);
    Slot& slot = slots_[i % b_.window];
    slot.full.push_back(std::move(batch));
    const bool full = slot.full.size() >= b_.batches_per_unit;
    if (full)
      produced_.notify_all(); // the writer waits for this (or for the unit's end)
    if (stop_)
      throw PoolStopped{};
    batch = take_spare_locked();
    return full;
  }

  // Waits until the writer has taken unit i's full batches down to low_water() (fewer wake-ups
  // than one a batch).
  void wait_for_room(std::size_t i) {
    std::unique_lock<std::mutex> lock(m_);
    Slot& slot = slots_[i % b_.window];
    room_.wait(lock, [&] { return stop_ || slot.full.size() <= low_water(); });
    if (stop_)
      throw PoolStopped{};
  }

  Batch take_spare() {
    const std::lock_guard<std::mutex> lock(m_);
    return take_spare_locked();
  }
  Batch take_spare_locked() {
    Batch batch;
    if (!spare_.empty()) {
      batch = std::move(spare_.back());
      spare_.pop_back();
    }
    if (!summarised())
      batch.reserve(b_.batch);
    return batch;
  }
  void give_spare(Batch&& batch) {
    const std::lock_guard<std::mutex> lock(m_);
    if (spare_.size() < b_.window) // beyond that, a freed batch is released
      spare_.push_back(std::move(batch));
  }

  const StreamBuffers& b_;
  const std::function<bool(std::size_t)>& plan_;
  const std::function<void(std::size_t, const std::function<void(const Fragment&)>&)>& produce_;
  const StreamEncoding* encoding_;
  std::mutex m_;
  std::condition_variable produced_; // a batch was handed over, a unit is done, or the plan ended
  std::condition_variable room_;     // a batch or a unit was consumed, or stop
  std::vector<Slot> slots_;
  std::vector<Batch> spare_; // emptied batches kept for reuse
  std::size_t next_ = 0;     // the next unit to claim
  std::size_t consumed_ = 0; // units consumed so far
  std::size_t end_ = 0;      // with ended_: the first unit that is not consumed
  bool ended_ = false;
  bool stop_ = false;
};

} // namespace

// rule: FAST.THREADS.DETERMINISTIC, SCENE.INPUT.LIMITS
void stream_ordered(
    unsigned threads, const StreamBuffers& buffers, const std::function<bool(std::size_t)>& plan,
    const std::function<void(std::size_t, const std::function<void(const Fragment&)>&)>& produce,
    const std::function<void(const Fragment&)>& consume, const StreamEncoding* encoding) {
  const unsigned wanted = std::clamp(threads, 1U, kMaxThreads);
  const auto inline_all = [&] {
    if (encoding == nullptr) {
      for (std::size_t i = 0; plan(i); ++i)
        produce(i, consume);
      return;
    }
    std::string bytes;
    const std::function<void(const Fragment&)> consume_encoded = [&](const Fragment& f) {
      if (encoding->consume_summary)
        encoding->consume_summary(BatchSummary{1, f, f, true});
      else
        consume(f);
      bytes.clear();
      encoding->encode(f, bytes);
      encoding->consume_bytes(bytes);
    };
    for (std::size_t i = 0; plan(i); ++i)
      produce(i, consume_encoded);
  };
  if (wanted <= 1) {
    inline_all();
    return;
  }
  StreamBuffers b = buffers;
  b.batch = std::max<std::size_t>(b.batch, 1);
  b.batches_per_unit = std::max<std::size_t>(b.batches_per_unit, 1);
  b.window = std::max<std::size_t>(b.window, 1);
  StreamPool pool(b, plan, produce, encoding);
  std::vector<std::jthread> threads_running;
  threads_running.reserve(wanted);
  // Stops and joins the pool however this scope is left (consume may throw).
  struct Stopper {
    StreamPool& pool;
    std::vector<std::jthread>& running;
    ~Stopper() {
      pool.stop();
      running.clear(); // joins
    }
  } stopper{pool, threads_running};
  for (unsigned t = 0; t < wanted; ++t) {
    try {
      threads_running.emplace_back([&pool] { pool.work(); });
    } catch (const std::system_error&) {
      break; // fewer threads: the ones running take every unit
    }
  }
  if (threads_running.empty()) {
    inline_all(); // not a single thread: produce on this one
    return;
  }
  pool.consume_all(consume);
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

// rule: FAST.THREADS.DETERMINISTIC
void produce_ordered(std::size_t n, unsigned threads, std::size_t window,
                     const std::function<void(std::size_t, std::string&)>& produce,
                     const std::function<void(std::size_t, std::string&)>& consume) {
  window = std::max<std::size_t>(window, 1);
  const std::size_t wanted = std::min<std::size_t>(std::clamp(threads, 1U, kMaxThreads), n);
  if (wanted <= 1) {
    std::string bytes;
    for (std::size_t i = 0; i < n; ++i) {
      bytes.clear();
      produce(i, bytes);
      consume(i, bytes);
    }
    return;
  }
  // Slot i % window holds unit i from when a thread takes it until consume has seen it.
  struct Slot {
    std::string bytes;
    bool ready = false;
    std::exception_ptr error;
  };
  std::vector<Slot> slots(std::min(window, n));
  std::mutex mutex;
  std::condition_variable room;  // the pool's threads wait for the window to move
  std::condition_variable ready; // the calling thread waits for the unit it needs
  std::size_t next = 0;          // the next unit a thread takes
  std::size_t consumed = 0;      // units consume has seen
  bool stop = false;
  // Takes the next unit if the window has room (lock held on entry and exit); false if not.
  const auto take_one = [&](std::unique_lock<std::mutex>& lock) {
    if (stop || next >= n || next >= consumed + slots.size())
      return false;
    const std::size_t i = next++;
    Slot& slot = slots[i % slots.size()];
    lock.unlock();
    try {
      produce(i, slot.bytes);
    } catch (...) {
      slot.error = std::current_exception();
    }
    lock.lock();
    slot.ready = true;
    return true;
  };
  const auto work = [&] {
    std::unique_lock<std::mutex> lock(mutex);
    for (;;) {
      room.wait(lock, [&] { return stop || next >= n || next < consumed + slots.size(); });
      const std::size_t i = next;
      if (!take_one(lock))
        return;
      if (i == consumed)
        ready.notify_one();
    }
  };
  // threads - 1 pool threads; the calling thread is the last: it consumes the next unit when it
  // is ready and otherwise produces one (so `threads` threads run, never more).
  std::vector<std::jthread> pool = start_threads(wanted - 1, work);
  const auto stop_pool = [&] {
    {
      const std::lock_guard<std::mutex> lock(mutex);
      stop = true;
    }
    room.notify_all();
    pool.clear(); // joins
  };
  std::unique_lock<std::mutex> lock(mutex);
  while (consumed < n) {
    Slot& slot = slots[consumed % slots.size()];
    if (!slot.ready) {
      if (!take_one(lock))
        ready.wait(lock, [&] { return slot.ready; });
      continue;
    }
    lock.unlock();
    if (slot.error) {
      const std::exception_ptr error = slot.error;
      stop_pool();
      std::rethrow_exception(error);
    }
    try {
      consume(consumed, slot.bytes);
    } catch (...) {
      stop_pool();
      throw;
    }
    slot.bytes.clear();
    lock.lock();
    slot.ready = false;
    ++consumed;
    room.notify_all();
  }
  lock.unlock();
  stop_pool();
}

} // namespace rastrules
