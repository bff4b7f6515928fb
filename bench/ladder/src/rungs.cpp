// SPDX-License-Identifier: MIT
// The rungs of the precision ladder (BENCH.LADDER.RUNGS). Each rung decides, for each triangle
// and each pixel centre of its bounding box clipped to the target, whether the centre is
// covered, and emits the covered ones in row-major order. The same template body is timed
// (counting) and checked (collecting keys).
// Implements: BENCH.LADDER.RUNGS, BENCH.METRIC.THROUGHPUT (decisions)

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <span>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

#include "float_rung.hpp"
#include "limit.hpp"
#include "rastrules/bench/ladder.hpp"
#include "rastrules/fixed.hpp"
#include "rastrules/formula/edge.hpp"
#include "rastrules/isa.hpp"
#include "rastrules/oracle/triangle.hpp"
#include "rastrules/parallel.hpp"
#include "rastrules/raster/fast.hpp"
#include "rastrules/raster/fast_batch.hpp"
#include "rastrules/raster/walk.hpp"
#include "rastrules/snap.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules::bench {

const std::vector<Rung>& all_rungs() {
  // reference-fast exists when the kernel's fast traversal is built (bench/ladder/CMakeLists.txt).
  static const std::vector<Rung> rungs = {
      Rung::kFloat,     Rung::kFloatSimd,     Rung::kDouble,      Rung::kScanline, Rung::kFixed4I32,
      Rung::kReference, Rung::kReferenceFast, Rung::kFixed16I128, Rung::kExact,    Rung::kLimit};
  return rungs;
}

std::optional<Rung> parse_rung(std::string_view name) {
  return from_name<Rung>(name);
}

bool has_coverage(Rung r) {
  return r != Rung::kLimit;
}

namespace {

struct Rect {
  std::int32_t x0 = 0, y0 = 0, x1 = -1, y1 = -1; // inclusive
};

// Rungs 1 and 2: edge functions in F of the unsnapped positions, all three >= 0 on the
// clockwise triangle, no tie rule.
// rule: BENCH.LADDER.RUNGS
template <class F, class Emit>
void raster_float(const FloatTriangle& tri, std::int32_t w, std::int32_t h, Emit&& emit) {
  const FloatSetup<F> s = float_setup<F>(tri, w, h);
  const F* x = s.x;
  const F* y = s.y;
  for (std::int32_t py = s.py0; py <= s.py1; ++py) {
    const F sy = static_cast<F>(py) + F(0.5);
    for (std::int32_t px = s.px0; px <= s.px1; ++px) {
      const F sx = static_cast<F>(px) + F(0.5);
      const F e0 = (x[1] - x[0]) * (sy - y[0]) - (y[1] - y[0]) * (sx - x[0]);
      const F e1 = (x[2] - x[1]) * (sy - y[1]) - (y[2] - y[1]) * (sx - x[1]);
      const F e2 = (x[0] - x[2]) * (sy - y[2]) - (y[0] - y[2]) * (sx - x[2]);
      if (e0 >= F(0) && e1 >= F(0) && e2 >= F(0))
        emit(px, py);
    }
  }
}

// Whether the float-simd rung runs its AVX2 loop: the processor has AVX2 and RASTRULES_MAX_ISA
// allows it (best_isa()); otherwise it runs the scalar float loop (the same centres).
bool float_simd_vectorised() {
  static const bool v = best_isa() != Isa::kScalar;
  return v;
}

// Rung 3: the article's scanline algorithm in float32. Vertices sorted by y; the rows of pixel
// centres y_c with y_top <= y_c < y_bottom; on each row the crossings with the long edge
// (top -> bottom) and the short edge of that half (top -> middle above the middle vertex,
// middle -> bottom from it), each started with x = x0 + (y_c - y0)(x1 - x0)/(y1 - y0) at its
// first row and stepped by (x1 - x0)/(y1 - y0) per row; centres x_l <= x_c < x_r filled.
// rule: BENCH.LADDER.RUNGS
template <class Emit>
void raster_scanline(const FloatTriangle& tri, std::int32_t w, std::int32_t h, Emit&& emit) {
  std::array<std::array<float, 2>, 3> v = tri;
  std::sort(v.begin(), v.end(), [](const auto& a, const auto& b) { return a[1] < b[1]; });
  const float ytop = v[0][1], ymid = v[1][1], ybot = v[2][1];
  if (!(ytop < ybot))
    return;
  // First and last row whose centre lies in [ytop, ybot).
  const auto first_row = [](float y) { return std::ceil(y - 0.5f); };
  std::int32_t r0 = static_cast<std::int32_t>(std::max(first_row(ytop), 0.0f));
  const float r_end = std::min(first_row(ybot), static_cast<float>(h)); // exclusive
  const std::int32_t r1 = static_cast<std::int32_t>(r_end) - 1;
  if (r0 > r1)
    return;
  const float long_dx = (v[2][0] - v[0][0]) / (ybot - ytop);
  float xl = v[0][0] + (static_cast<float>(r0) + 0.5f - ytop) * long_dx;
  // The short edge: top -> middle, then middle -> bottom.
  const std::int32_t mid_row = static_cast<std::int32_t>(first_row(ymid));
  auto start_short = [&](std::int32_t row, std::size_t a, std::size_t b, float& x, float& dx) {
    dx = (v[b][1] > v[a][1]) ? (v[b][0] - v[a][0]) / (v[b][1] - v[a][1]) : 0.0f;
    x = v[a][0] + (static_cast<float>(row) + 0.5f - v[a][1]) * dx;
  };
  float xs = 0, sdx = 0;
  bool lower = r0 >= mid_row;
  if (lower)
    start_short(r0, 1, 2, xs, sdx);
  else
    start_short(r0, 0, 1, xs, sdx);
  for (std::int32_t row = r0; row <= r1; ++row) {
    if (!lower && row >= mid_row) {
      lower = true;
      start_short(row, 1, 2, xs, sdx);
    }
    const float a = std::min(xl, xs), b = std::max(xl, xs);
    // Centres x + 1/2 in [a, b): x from ceil(a - 1/2) to ceil(b - 1/2) - 1.
    const float fx0 = std::max(std::ceil(a - 0.5f), 0.0f);
    const float fx1 = std::min(std::ceil(b - 0.5f), static_cast<float>(w));
    if (row >= 0) {
      for (std::int32_t x = static_cast<std::int32_t>(fx0); static_cast<float>(x) < fx1; ++x)
        emit(x, row);
    }
    xl += long_dx;
    xs += sdx;
  }
}

// Snaps to 2^bits subpixels, round half to even (the default rounding mode), as int64.
std::int64_t snap_bits(float v, int bits) {
  return static_cast<std::int64_t>(std::nearbyint(std::ldexp(static_cast<double>(v), bits)));
}

// Rung 4: 4 subpixel bits, the top-left rule, edge values in 32 bits: E = A*x + B*y + C at the
// first centre of each row, stepped by A per pixel, all wrapping in uint32.
// rule: BENCH.LADDER.RUNGS
template <class Emit>
void raster_fixed4(const FloatTriangle& tri, std::int32_t w, std::int32_t h, Emit&& emit) {
  std::int64_t vx[3], vy[3];
  for (std::size_t i = 0; i < 3; ++i) {
    vx[i] = snap_bits(tri[i][0], 4);
    vy[i] = snap_bits(tri[i][1], 4);
  }
  const auto area =
      formula::twice_signed_area<std::int64_t>(vx[0], vy[0], vx[1], vy[1], vx[2], vy[2]);
  if (area == 0)
    return;
  if (area < 0) {
    std::swap(vx[1], vx[2]);
    std::swap(vy[1], vy[2]);
  }
  const auto u32 = [](std::int64_t v) { return static_cast<std::uint32_t>(v); };
  std::uint32_t a[3], b[3], c[3], bias[3];
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t j = (i + 1) % 3;
    // E(p) = (bx - ax)(py - ay) - (by - ay)(px - ax) = A px + B py + C
    a[i] = u32(vy[i]) - u32(vy[j]);
    b[i] = u32(vx[j]) - u32(vx[i]);
    c[i] = (u32(vy[j]) - u32(vy[i])) * u32(vx[i]) - (u32(vx[j]) - u32(vx[i])) * u32(vy[i]);
    bias[i] = formula::is_inclusive_edge<true, true>(vx[i], vy[i], vx[j], vy[j]) ? 0u : ~0u;
  }
  const std::int64_t minx = std::min({vx[0], vx[1], vx[2]}), maxx = std::max({vx[0], vx[1], vx[2]});
  const std::int64_t miny = std::min({vy[0], vy[1], vy[2]}), maxy = std::max({vy[0], vy[1], vy[2]});
  const std::int64_t px0 = std::max<std::int64_t>(-rastrules::floor_div(-(minx - 8), 16), 0);
  const std::int64_t px1 = std::min<std::int64_t>(rastrules::floor_div(maxx - 8, 16), w - 1);
  const std::int64_t py0 = std::max<std::int64_t>(-rastrules::floor_div(-(miny - 8), 16), 0);
  const std::int64_t py1 = std::min<std::int64_t>(rastrules::floor_div(maxy - 8, 16), h - 1);
  for (std::int64_t py = py0; py <= py1; ++py) {
    const std::uint32_t sy = u32(py * 16 + 8), sx = u32(px0 * 16 + 8);
    std::uint32_t e[3];
    for (std::size_t i = 0; i < 3; ++i)
      e[i] = a[i] * sx + b[i] * sy + c[i] + bias[i];
    for (std::int64_t px = px0; px <= px1; ++px) {
      if ((static_cast<std::int32_t>(e[0]) | static_cast<std::int32_t>(e[1]) |
           static_cast<std::int32_t>(e[2])) >= 0)
        emit(static_cast<std::int32_t>(px), static_cast<std::int32_t>(py));
      for (std::size_t i = 0; i < 3; ++i)
        e[i] += a[i] * 16u;
    }
  }
}

// Rung 6: 16 subpixel bits, the top-left rule, __int128 edge values.
__extension__ typedef __int128 Int128;

// rule: BENCH.LADDER.RUNGS
template <class Emit>
void raster_fixed16(const FloatTriangle& tri, std::int32_t w, std::int32_t h, Emit&& emit) {
  Int128 vx[3], vy[3];
  for (std::size_t i = 0; i < 3; ++i) {
    vx[i] = snap_bits(tri[i][0], 16);
    vy[i] = snap_bits(tri[i][1], 16);
  }
  const Int128 area = formula::twice_signed_area<Int128>(vx[0], vy[0], vx[1], vy[1], vx[2], vy[2]);
  if (area == 0)
    return;
  if (area < 0) {
    std::swap(vx[1], vx[2]);
    std::swap(vy[1], vy[2]);
  }
  Int128 step[3], bias[3];
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t j = (i + 1) % 3;
    step[i] = -(vy[j] - vy[i]) * 65536;
    bias[i] = formula::is_inclusive_edge<true, true>(vx[i], vy[i], vx[j], vy[j]) ? 0 : -1;
  }
  constexpr std::int64_t kOne = 65536, kHalf = 32768;
  const auto lo = [](Int128 a, Int128 b, Int128 c) {
    return static_cast<std::int64_t>(std::min({a, b, c}));
  };
  const auto hi = [](Int128 a, Int128 b, Int128 c) {
    return static_cast<std::int64_t>(std::max({a, b, c}));
  };
  const std::int64_t px0 =
      std::max<std::int64_t>(-rastrules::floor_div(-(lo(vx[0], vx[1], vx[2]) - kHalf), kOne), 0);
  const std::int64_t px1 =
      std::min<std::int64_t>(rastrules::floor_div(hi(vx[0], vx[1], vx[2]) - kHalf, kOne), w - 1);
  const std::int64_t py0 =
      std::max<std::int64_t>(-rastrules::floor_div(-(lo(vy[0], vy[1], vy[2]) - kHalf), kOne), 0);
  const std::int64_t py1 =
      std::min<std::int64_t>(rastrules::floor_div(hi(vy[0], vy[1], vy[2]) - kHalf, kOne), h - 1);
  for (std::int64_t py = py0; py <= py1; ++py) {
    const Int128 sy = py * kOne + kHalf, sx = px0 * kOne + kHalf;
    Int128 e[3];
    for (std::size_t i = 0; i < 3; ++i) {
      const std::size_t j = (i + 1) % 3;
      e[i] = formula::edge_value<Int128>(vx[i], vy[i], vx[j], vy[j], sx, sy) + bias[i];
    }
    for (std::int64_t px = px0; px <= px1; ++px) {
      if (e[0] >= 0 && e[1] >= 0 && e[2] >= 0)
        emit(static_cast<std::int32_t>(px), static_cast<std::int32_t>(py));
      for (std::size_t i = 0; i < 3; ++i)
        e[i] += step[i];
    }
  }
}

// The reference's setup from float positions: SNAP.VERTEX.ROUND then setup_triangle.
// Preconditions: the positions snap (the ladder's scenes are inside SNAP.VERTEX.RANGE).
TriangleSetup reference_setup(const FloatTriangle& tri) {
  std::array<Vec2, 3> v;
  for (std::size_t i = 0; i < 3; ++i) {
    const SnapResult x = snap_to_subpixel(tri[i][0]);
    const SnapResult y = snap_to_subpixel(tri[i][1]);
    if (x.status != SnapStatus::kOk || y.status != SnapStatus::kOk)
      throw std::invalid_argument("ladder: a vertex does not snap");
    v[i] = Vec2{x.value, y.value};
  }
  return setup_triangle(v, RasterState{});
}

// Rung 7: the oracle, pixel by pixel over the bounding box of its own snapped vertices.
// rule: BENCH.LADDER.RUNGS
template <class Emit>
void raster_exact(const FloatTriangle& tri, std::int32_t w, std::int32_t h, Emit&& emit) {
  std::array<std::array<std::int64_t, 2>, 3> v;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto x = oracle::snap(tri[i][0]);
    const auto y = oracle::snap(tri[i][1]);
    if (!x || !y)
      throw std::invalid_argument("ladder: a vertex does not snap (oracle)");
    v[i] = {*x, *y};
  }
  const std::int64_t minx = std::min({v[0][0], v[1][0], v[2][0]}),
                     maxx = std::max({v[0][0], v[1][0], v[2][0]});
  const std::int64_t miny = std::min({v[0][1], v[1][1], v[2][1]}),
                     maxy = std::max({v[0][1], v[1][1], v[2][1]});
  const std::int64_t px0 = std::max<std::int64_t>(-rastrules::floor_div(-(minx - 128), 256), 0);
  const std::int64_t px1 = std::min<std::int64_t>(rastrules::floor_div(maxx - 128, 256), w - 1);
  const std::int64_t py0 = std::max<std::int64_t>(-rastrules::floor_div(-(miny - 128), 256), 0);
  const std::int64_t py1 = std::min<std::int64_t>(rastrules::floor_div(maxy - 128, 256), h - 1);
  const oracle::State state;
  for (std::int64_t py = py0; py <= py1; ++py)
    for (std::int64_t px = px0; px <= px1; ++px)
      if (oracle::covers(v, {px * 256 + 128, py * 256 + 128}, state))
        emit(static_cast<std::int32_t>(px), static_cast<std::int32_t>(py));
}

template <class Emit>
void run_one(Rung r, const FloatTriangle& tri, std::int32_t w, std::int32_t h, Emit&& emit) {
  switch (r) {
  case Rung::kFloat:
  case Rung::kFloatSimd: // run_rung calls the AVX2 loop itself when it can
    raster_float<float>(tri, w, h, emit);
    return;
  case Rung::kDouble:
    raster_float<double>(tri, w, h, emit);
    return;
  case Rung::kScanline:
    raster_scanline(tri, w, h, emit);
    return;
  case Rung::kFixed4I32:
    raster_fixed4(tri, w, h, emit);
    return;
  case Rung::kReference:
    raster::walk_triangle(reference_setup(tri), w, h, emit);
    return;
  case Rung::kReferenceFast:
    raster::walk_triangle_fast(reference_setup(tri), w, h, best_isa(), emit);
    return;
  case Rung::kFixed16I128:
    raster_fixed16(tri, w, h, emit);
    return;
  case Rung::kExact:
    raster_exact(tri, w, h, emit);
    return;
  case Rung::kLimit:
    return;
  }
}

// The scene's flat coordinates (LadderScene::xy), or a copy made now when a caller built the
// scene without flatten().
const std::vector<float>& coordinates(const LadderScene& s, std::vector<float>& tmp) {
  if (s.xy.size() == 6 * s.triangles.size())
    return s.xy;
  tmp = flat_coordinates(s.triangles);
  return tmp;
}

// rule: FAST.BATCH.EQUALS.PLAIN
// xy: the scene's triangles from index `first` on.
std::uint64_t batch_count(std::span<const float> xy, const LadderScene& s, Isa isa,
                          std::size_t first = 0) {
  raster::FastBatchResult r = raster::fast_count_batch(xy, s.width, s.height, RasterState{}, isa);
  if (r.status != raster::BatchStatus::kOk) {
    r.bad_triangle += first; // the scene's index, not the chunk's
    throw std::invalid_argument("ladder: scene " + s.name + ": " + raster::describe(r));
  }
  return r.covered;
}

} // namespace

// rule: BENCH.METRIC.THROUGHPUT
// A job is split into many small chunks that every participant claims from one counter: the
// calling thread claims too, so a worker that the operating system has not scheduled (a loaded
// machine) leaves its chunks to the others instead of holding the job up. The caller then waits
// only for chunks already claimed, and for workers inside the job (`active`): it closes the job
// (`open`) before it waits, and a worker enters only while the job is open, so a worker that
// wakes up late finds it closed and never touches a finished job. Workers spin for up to 100 us
// on the job counter before they sleep on the condition variable: back-to-back timed repeats
// find them awake (as a driver's do within a frame), and a loaded machine loses little to the
// spinning; an idle pool sleeps.
struct FastPool::Impl {
  struct Job {
    std::size_t chunks = 0;
    const std::function<void(std::size_t)>* body = nullptr;
    std::atomic<std::size_t> next{0};
    std::atomic<std::size_t> done{0};
    std::vector<std::exception_ptr> errors; // one per chunk
  };

  std::vector<std::thread> workers;
  std::mutex m;
  std::condition_variable go;
  std::atomic<std::uint64_t> generation{0};
  std::atomic<bool> stop{false};
  std::atomic<bool> open{false};
  std::atomic<unsigned> active{0};
  std::atomic<Job*> job{nullptr};

  static void relax() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#else
    std::this_thread::yield();
#endif
  }

  // Claims and runs chunks of j until none is left.
  static void claim(Job& j) {
    for (std::size_t c; (c = j.next.fetch_add(1, std::memory_order_relaxed)) < j.chunks;) {
      try {
        (*j.body)(c);
      } catch (...) {
        j.errors[c] = std::current_exception();
      }
      j.done.fetch_add(1, std::memory_order_acq_rel);
    }
  }

  void work() {
    std::uint64_t seen = 0;
    for (;;) {
      const auto start = std::chrono::steady_clock::now();
      std::uint32_t spins = 0;
      std::uint64_t g = 0;
      while ((g = generation.load(std::memory_order_acquire)) == seen &&
             !stop.load(std::memory_order_acquire)) {
        if (++spins % 256 == 0 &&
            std::chrono::steady_clock::now() - start > std::chrono::microseconds(100)) {
          std::unique_lock<std::mutex> l(m);
          go.wait(l, [&] { return generation.load() != seen || stop.load(); });
        } else {
          relax();
        }
      }
      if (stop.load(std::memory_order_acquire))
        return;
      seen = g;
      active.fetch_add(1); // sequentially consistent with run()'s open.store(false)
      if (open.load())
        claim(*job.load());
      active.fetch_sub(1);
    }
  }

  // Runs body(c) for every chunk c in [0, chunks) on this thread and the workers; rethrows
  // the lowest chunk's error.
  void run(std::size_t chunks, const std::function<void(std::size_t)>& body) {
    Job j;
    j.chunks = chunks;
    j.body = &body;
    j.errors.assign(chunks, nullptr);
    job.store(&j);
    open.store(true);
    {
      const std::lock_guard<std::mutex> g(m); // no sleeping worker misses the wake-up
      generation.fetch_add(1, std::memory_order_release);
    }
    go.notify_all();
    claim(j);
    for (std::uint32_t spins = 0; j.done.load(std::memory_order_acquire) != chunks; ++spins) {
      if (spins % 256 == 255)
        std::this_thread::yield();
      else
        relax();
    }
    open.store(false);
    for (std::uint32_t spins = 0; active.load() != 0; ++spins) {
      if (spins % 256 == 255)
        std::this_thread::yield();
      else
        relax();
    }
    for (const std::exception_ptr& e : j.errors)
      if (e)
        std::rethrow_exception(e);
  }
};

FastPool::FastPool(unsigned threads) : impl_(std::make_unique<Impl>()) {
  const unsigned n = std::clamp(threads, 1u, kMaxThreads);
  for (unsigned k = 1; k < n; ++k) {
    try {
      impl_->workers.emplace_back([this] { impl_->work(); });
    } catch (const std::system_error&) {
      break; // fewer threads: the same chunks, the same count
    }
  }
}

FastPool::~FastPool() {
  {
    const std::lock_guard<std::mutex> g(impl_->m);
    impl_->stop.store(true, std::memory_order_release);
  }
  impl_->go.notify_all();
  for (std::thread& t : impl_->workers)
    t.join();
}

unsigned FastPool::threads() const {
  return static_cast<unsigned>(impl_->workers.size()) + 1;
}

std::uint64_t FastPool::count(const LadderScene& s) {
  std::vector<float> tmp;
  const std::vector<float>& xy = coordinates(s, tmp);
  const std::size_t n = s.triangles.size();
  // 16 chunks a thread (one triangle at least each): small enough that the work of a thread
  // that is not scheduled moves to the others, large enough (about 150 small triangles) for the
  // batch counter's eight-at-a-time setup.
  const std::size_t chunks = std::max<std::size_t>(1, std::min<std::size_t>(n, 16 * threads()));
  std::vector<std::uint64_t> counts(chunks, 0);
  const Isa isa = best_isa();
  const std::function<void(std::size_t)> body = [&](std::size_t c) {
    const std::size_t b = n * c / chunks, e = n * (c + 1) / chunks;
    counts[c] = batch_count(std::span<const float>(xy).subspan(6 * b, 6 * (e - b)), s, isa, b);
  };
  impl_->run(chunks, body);
  std::uint64_t total = 0;
  for (const std::uint64_t c : counts)
    total += c;
  return total;
}

// rule: BENCH.METRIC.THROUGHPUT
std::uint64_t run_reference_fast_threaded(const LadderScene& s, unsigned threads) {
  FastPool pool(threads);
  return pool.count(s);
}

// rule: BENCH.LADDER.RUNGS
std::uint64_t run_rung(Rung r, const LadderScene& s, Coverage* out) {
  std::uint64_t n = 0;
  if (r == Rung::kLimit) {
    for (const auto& tri : s.triangles)
      n += limit_count(tri, s.width, s.height);
    return n;
  }
  if (r == Rung::kReferenceFast && out == nullptr) {
    // The timed path: the kernel's batch counter (FAST.BATCH.EQUALS.PLAIN): snapping, setup
    // and coverage of every triangle, small ones eight at a time.
    std::vector<float> tmp;
    return batch_count(coordinates(s, tmp), s, best_isa());
  }
  if (r == Rung::kFloatSimd && float_simd_vectorised()) {
    for (std::size_t i = 0; i < s.triangles.size(); ++i)
      n += float_simd_avx2(s.triangles[i], s.width, s.height, out, static_cast<std::uint32_t>(i));
    return n;
  }
  if (out == nullptr) {
    auto count = [&n](std::int32_t, std::int32_t) { ++n; };
    for (const auto& tri : s.triangles)
      run_one(r, tri, s.width, s.height, count);
    return n;
  }
  for (std::size_t i = 0; i < s.triangles.size(); ++i) {
    const auto id = static_cast<std::uint32_t>(i);
    auto collect = [&](std::int32_t x, std::int32_t y) {
      out->push_back(coverage_key(id, x, y));
      ++n;
    };
    run_one(r, s.triangles[i], s.width, s.height, collect);
  }
  return n;
}

// rule: BENCH.METRIC.THROUGHPUT
std::uint64_t count_decisions(const LadderScene& s) {
  std::uint64_t n = 0;
  for (const auto& tri : s.triangles) {
    const TriangleSetup t = reference_setup(tri);
    const raster::PixelRect r = raster::pixel_bounds(t, s.width, s.height);
    if (!r.empty())
      n +=
          static_cast<std::uint64_t>(r.x1 - r.x0 + 1) * static_cast<std::uint64_t>(r.y1 - r.y0 + 1);
  }
  return n;
}

} // namespace rastrules::bench
