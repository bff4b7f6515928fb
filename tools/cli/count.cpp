// SPDX-License-Identifier: MIT
// Implements: SCENE.OUTPUT.COUNT

#include "count.hpp"

#include "chunk_pipe.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <span>
#include <stdexcept>
#include <variant>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "rastrules/io/scene_json.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/raster/fast_batch.hpp"

namespace rastrules::cli {
namespace {

void append_number(std::string& out, std::uint64_t v) {
  char digits[24];
  const auto end = std::to_chars(digits, digits + sizeof digits, v).ptr;
  out.append(digits, end);
}

} // namespace

FragmentCounts::FragmentCounts(std::size_t primitives, std::int32_t w, std::int32_t h)
    : width(w), height(h), per_primitive(primitives, 0) {
  const std::uint64_t pixels = static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h);
  if (pixels <= kMaxOverdrawPixels)
    hits.emplace(w, h);
}

namespace {

// Counts the triangles xy with the batch counter into c (their counts from per_primitive[first]
// on, the overdraw added to c's); false when it refuses them.
bool count_into(FragmentCounts& c, std::span<const float> xy, const PreparedScene& scene,
                const RenderOptions& options, std::size_t first) {
  const std::span<std::uint64_t> per = std::span(c.per_primitive).subspan(first, xy.size() / 6);
  const Isa isa = effective_isa(options);
  const raster::FastBatchResult r =
      c.hits
          ? raster::fast_count_batch(xy, scene.width, scene.height, scene.state, isa, per, *c.hits)
          : raster::fast_count_batch(xy, scene.width, scene.height, scene.state, isa, per);
  return r.status == raster::BatchStatus::kOk;
}

// The batch counter's counts of the triangles xy on scene's target and state, or nullopt when
// it refuses them (a vertex that does not snap, a target it does not take).
std::optional<FragmentCounts> count_batch(std::span<const float> xy, const PreparedScene& scene,
                                          const RenderOptions& options) {
  FragmentCounts c(xy.size() / 6, scene.width, scene.height);
  if (!count_into(c, xy, scene, options, 0))
    return std::nullopt;
  return c;
}

} // namespace

// rule: SCENE.INPUT.LIMITS
bool add_work_bounds(std::span<const float> xy, std::int32_t width, std::int32_t height,
                     std::uint64_t max_work, double& work) {
  // triangle_bound's work, summed in one loop without a branch a triangle (a call a triangle
  // returning an optional was 7 % of `render --count` on 10^6 small triangles). Every term is
  // an integer below 2^29, so the sums are exact, and the same as adding the terms to work one
  // by one, while work stays below 2^53 (far above any work limit).
  bool finite = true;
  double sum = 0;
  std::size_t i = 0;
#if defined(__SSE2__)
  // Four triangles at a time in SSE2 lanes (the baseline instruction set), each triangle's
  // x and y side by side: the same minima, maxima, double differences, clips, truncations and
  // products as below, lane by lane (minpd is "a < b ? a : b", the ternaries below), and
  // the products summed in other partial sums, which the sums' exactness allows. (Scalar, a
  // triangle's 50 operations were 6 % of `render --fragments OUT.bin` on 10^6 small triangles.)
  {
    const __m128d side = _mm_set_pd(static_cast<double>(height), static_cast<double>(width));
    const __m128d three = _mm_set1_pd(3.0);
    __m128 not_finite = _mm_setzero_ps(); // x - x summed: 0, or NaN from an infinity or a NaN
    __m128d sums = _mm_setzero_pd();
    // The clipped extents (cols, rows) of the triangle whose first two vertices are a (x0 y0 x1
    // y1) and whose third is b's low half (x2 y2).
    const auto extents = [&](__m128 a, __m128 b) {
      const __m128 lo = _mm_min_ps(_mm_min_ps(a, _mm_movehl_ps(a, a)), b);
      const __m128 hi = _mm_max_ps(_mm_max_ps(a, _mm_movehl_ps(a, a)), b);
      const __m128d span = _mm_sub_pd(_mm_cvtps_pd(hi), _mm_cvtps_pd(lo));
      const __m128d s = _mm_min_pd(span, side); // span < side ? span : side
      return _mm_min_pd(_mm_add_pd(_mm_cvtepi32_pd(_mm_cvttpd_epi32(s)), three), side);
    };
    for (; i + 24 <= xy.size(); i += 24) {
      __m128 v[6];
      for (int k = 0; k < 6; ++k) {
        v[k] = _mm_loadu_ps(&xy[i + 4 * static_cast<std::size_t>(k)]);
        not_finite = _mm_add_ps(not_finite, _mm_sub_ps(v[k], v[k]));
      }
      const __m128d e0 = extents(v[0], v[1]), e1 = extents(v[2], _mm_movehl_ps(v[1], v[1]));
      const __m128d e2 = extents(v[3], v[4]), e3 = extents(v[5], _mm_movehl_ps(v[4], v[4]));
      sums = _mm_add_pd(sums, _mm_mul_pd(_mm_unpacklo_pd(e0, e1), _mm_unpackhi_pd(e0, e1)));
      sums = _mm_add_pd(sums, _mm_mul_pd(_mm_unpacklo_pd(e2, e3), _mm_unpackhi_pd(e2, e3)));
    }
    finite = _mm_movemask_ps(_mm_cmpeq_ps(not_finite, _mm_setzero_ps())) == 0xF;
    double lanes[2];
    _mm_storeu_pd(lanes, sums);
    sum = lanes[0] + lanes[1];
  }
#endif
  for (; i < xy.size(); i += 6) {
    const float* t = &xy[i];
    finite &= bound_detail::finite_triangle(t);
    const float lo_x = std::min({t[0], t[2], t[4]}), hi_x = std::max({t[0], t[2], t[4]});
    const float lo_y = std::min({t[1], t[3], t[5]}), hi_y = std::max({t[1], t[3], t[5]});
    sum += bound_detail::clipped_extent(double{hi_x} - double{lo_x}, width) *
           bound_detail::clipped_extent(double{hi_y} - double{lo_y}, height);
  }
  if (!finite)
    return false;
  work += sum;
  return work <= static_cast<double>(max_work);
}

// rule: SCENE.OUTPUT.COUNT, FAST.BATCH.EQUALS.PLAIN
std::optional<FragmentCounts> batch_counts(const LoadedScene& loaded,
                                           const RenderOptions& options) {
  if (!loaded.prepared || options.traversal != Traversal::kFast)
    return std::nullopt;
  const PreparedScene& scene = *loaded.prepared;
  if (!is_single_sample(scene.msaa))
    return std::nullopt;
  std::vector<float> xy;
  xy.reserve(loaded.scene.primitives.size() * 6);
  for (const Primitive& p : loaded.scene.primitives) {
    if (p.type != PrimitiveType::kTriangle || p.v.size() != 3 || p.path)
      return std::nullopt;
    for (const FloatPoint& v : p.v)
      xy.insert(xy.end(), {v[0], v[1]});
  }
  std::optional<FragmentCounts> c = count_batch(xy, scene, options);
  // prepare() has snapped every vertex and checked the target: the batch cannot refuse them.
  if (!c)
    throw std::logic_error("the batch counter refused a prepared scene");
  return c;
}

// rule: SCENE.INPUT.FAST_READER, SCENE.INPUT.LIMITS
std::optional<FastForm> load_fast_form(std::string_view text, const RenderOptions& options,
                                       std::uint64_t max_work) {
  if (options.traversal != Traversal::kFast)
    return std::nullopt;
  // rule: FAST.THREADS.DETERMINISTIC
  // With threads the list is read in parts (the same coordinates).
  std::optional<io::FastTriangles> t = io::read_triangles_fast(text, options.threads);
  if (!t)
    return std::nullopt;
  // The scene without its triangles: its target checked and its state prepared as prepare()
  // does for the whole scene (the state does not depend on the primitives).
  auto base = load_scene(std::move(t->scene));
  auto* loaded = std::get_if<LoadedScene>(&base);
  if (!loaded || !loaded->prepared || !is_single_sample(loaded->prepared->msaa))
    return std::nullopt;
  const PreparedScene& scene = *loaded->prepared;
  // The work limit: the triangles' bound within it means their exact work is too (else the
  // whole scene is prepared, and the first primitive over the limit named).
  double work = 0;
  if (!add_work_bounds(t->xy, scene.width, scene.height, max_work, work))
    return std::nullopt;
  return FastForm{std::move(*loaded), std::move(t->xy)};
}

// rule: SCENE.INPUT.FAST_READER
std::optional<PreparedScene> prepared_head(const Scene& head) {
  auto base = load_scene(Scene(head));
  auto* loaded = std::get_if<LoadedScene>(&base);
  if (!loaded || !loaded->prepared || !is_single_sample(loaded->prepared->msaa))
    return std::nullopt;
  return std::move(*loaded->prepared);
}

namespace {

// rule: SCENE.OUTPUT.COUNT, SCENE.INPUT.FAST_READER, SCENE.INPUT.LIMITS, FAST.THREADS.DETERMINISTIC
// The batch counter fed as the text is read (io::stream_triangles_fast): each chunk's bound on
// the work is added up (declining past max_work, as load_fast_form does for the whole list) and
// the chunk counted, on this thread, or with two or more threads on a counting thread while this
// one reads on (ChunkPipe). The counts do not depend on the chunks or the threads: each
// triangle's count is its own, the pixels' are sums.
class CountStream final : public io::TriangleStream {
public:
  CountStream(const RenderOptions& options, std::uint64_t max_work)
      : options_(options), max_work_(max_work) {}

  bool begin(const Scene& head) override {
    std::optional<PreparedScene> scene = prepared_head(head);
    if (!scene)
      return false;
    scene_ = std::move(*scene);
    counts_.emplace(0, scene_.width, scene_.height);
    pipe_.emplace(options_.threads >= 2, [this](std::span<const float> xy) { return count(xy); });
    return true;
  }
  // The counts a triangle reserved at once (growing them by doubling copied 4 and 8 MB of counts
  // on 10^6 triangles); untouched pages of the reservation are never resident. Before the first
  // chunk: the counting thread does not touch them yet.
  void reserve(std::size_t triangles) override { counts_->per_primitive.reserve(triangles); }
  bool triangles(std::span<const float> xy) override { return pipe_->push(xy); }

  // The counts once the text is read to its end; nullopt when a chunk was refused.
  std::optional<FragmentCounts> take() {
    refused_ = pipe_ && !pipe_->finish();
    if (!pipe_ || refused_)
      return std::nullopt;
    return std::move(counts_);
  }
  // After take(): whether the text was of the form up to a chunk the batch unit or the work
  // limit refused (reading it another way would refuse it too).
  [[nodiscard]] bool refused() const { return refused_; }

private:
  // Counts the next triangles (on the counting thread when there is one), after their bound
  // on the work.
  bool count(std::span<const float> xy) {
    if (!add_work_bounds(xy, scene_.width, scene_.height, max_work_, work_))
      return false;
    FragmentCounts& c = *counts_;
    const std::size_t first = c.per_primitive.size();
    c.per_primitive.resize(first + xy.size() / 6, 0);
    return count_into(c, xy, scene_, options_, first);
  }

  const RenderOptions& options_;
  std::uint64_t max_work_;
  PreparedScene scene_;
  std::optional<FragmentCounts> counts_;
  double work_ = 0;
  bool refused_ = false;
  std::optional<ChunkPipe> pipe_; // last: stopped before the members its thread uses
};

} // namespace

// rule: SCENE.OUTPUT.COUNT, SCENE.INPUT.FAST_READER, SCENE.INPUT.LIMITS
std::optional<FragmentCounts> fast_form_counts(std::string_view text, const RenderOptions& options,
                                               std::uint64_t max_work) {
  if (options.traversal != Traversal::kFast)
    return std::nullopt;
  // Read and counted at once where the root keys come before the list; else the list is read
  // first (also where a key follows it).
  {
    CountStream stream(options, max_work);
    const bool read = io::stream_triangles_fast(text, stream).has_value();
    std::optional<FragmentCounts> counts = stream.take();
    if (read && counts)
      return counts;
    if (stream.refused())
      return std::nullopt;
  }
  const std::optional<FastForm> f = load_fast_form(text, options, max_work);
  if (!f)
    return std::nullopt;
  return count_batch(f->xy, *f->base.prepared, options);
}

// rule: SCENE.OUTPUT.COUNT
std::string counts_json(const FragmentCounts& c) {
  std::uint64_t total = 0;
  for (const std::uint64_t n : c.per_primitive)
    total += n;
  std::string out = "{\"primitives\": ";
  append_number(out, c.per_primitive.size());
  out += ", \"fragments\": ";
  append_number(out, total);
  out += ", \"per_primitive\": [";
  {
    // Formatted into a block of bytes appended when nearly full (a count takes at most 22), not
    // appended number by number: a tenth of `render --count`'s time on 10^6 triangles went to
    // the appends.
    std::array<char, 1 << 14> block;
    char* p = block.data();
    for (std::size_t i = 0; i < c.per_primitive.size(); ++i) {
      if (block.end() - p < 22) {
        out.append(block.data(), p);
        p = block.data();
      }
      if (i > 0) {
        *p++ = ',';
        *p++ = ' ';
      }
      // Most counts of many small triangles are one digit.
      const std::uint64_t v = c.per_primitive[i];
      if (v < 10)
        *p++ = static_cast<char>('0' + v);
      else
        p = std::to_chars(p, block.end(), v).ptr;
    }
    out.append(block.data(), p);
  }
  out += "], \"overdraw\": ";
  if (!c.hits) {
    out += "null}\n";
    return out;
  }
  // pixels[k - 1]: the pixels holding exactly k fragments.
  std::vector<std::uint64_t> pixels;
  for (std::size_t i = 0; i < c.hits->size(); ++i) {
    const std::uint32_t h = (*c.hits)[i];
    if (h == 0)
      continue;
    if (h > pixels.size())
      pixels.resize(h, 0);
    ++pixels[h - 1];
  }
  std::uint64_t touched = 0;
  for (const std::uint64_t n : pixels)
    touched += n;
  out += "{\"pixels_touched\": ";
  append_number(out, touched);
  out += ", \"max\": ";
  append_number(out, pixels.size());
  out += ", \"pixels\": [";
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    if (i > 0)
      out += ", ";
    append_number(out, pixels[i]);
  }
  out += "]}}\n";
  return out;
}

} // namespace rastrules::cli
