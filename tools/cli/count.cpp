// SPDX-License-Identifier: MIT
// Implements: SCENE.OUTPUT.COUNT

#include "count.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <span>
#include <stdexcept>
#include <variant>

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
    hits.assign(static_cast<std::size_t>(pixels), 0);
}

namespace {

// The batch counter's counts of the triangles xy on scene's target and state, or nullopt when
// it refuses them (a vertex that does not snap, a target it does not take).
std::optional<FragmentCounts> count_batch(std::span<const float> xy, const PreparedScene& scene,
                                          const RenderOptions& options) {
  FragmentCounts c(xy.size() / 6, scene.width, scene.height);
  const raster::FastBatchResult r = raster::fast_count_batch(
      xy, scene.width, scene.height, scene.state, effective_isa(options), c.per_primitive, c.hits);
  if (r.status != raster::BatchStatus::kOk)
    return std::nullopt;
  return c;
}

} // namespace

// rule: SCENE.INPUT.LIMITS
std::optional<TriangleBound> triangle_bound(const float* t, std::int32_t w, std::int32_t h) {
  double lo[2] = {t[0], t[1]}, hi[2] = {t[0], t[1]};
  for (int k = 0; k < 6; ++k) {
    if (!std::isfinite(t[k]))
      return std::nullopt;
    lo[k % 2] = std::min<double>(lo[k % 2], t[k]);
    hi[k % 2] = std::max<double>(hi[k % 2], t[k]);
  }
  TriangleBound b;
  b.cols = std::min<double>(w, std::floor(hi[0] - lo[0]) + 3);
  b.rows = std::min<double>(h, std::floor(hi[1] - lo[1]) + 3);
  b.lo_y = lo[1];
  b.hi_y = hi[1];
  return b;
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
  for (std::size_t i = 0; i < t->xy.size(); i += 6) {
    const std::optional<TriangleBound> b = triangle_bound(&t->xy[i], scene.width, scene.height);
    if (!b)
      return std::nullopt;
    work += b->work();
  }
  if (!(work <= static_cast<double>(max_work)))
    return std::nullopt;
  return FastForm{std::move(*loaded), std::move(t->xy)};
}

// rule: SCENE.OUTPUT.COUNT, SCENE.INPUT.FAST_READER, SCENE.INPUT.LIMITS
std::optional<FragmentCounts> fast_form_counts(std::string_view text, const RenderOptions& options,
                                               std::uint64_t max_work) {
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
  out.reserve(32 + c.per_primitive.size() * 4);
  append_number(out, c.per_primitive.size());
  out += ", \"fragments\": ";
  append_number(out, total);
  out += ", \"per_primitive\": [";
  for (std::size_t i = 0; i < c.per_primitive.size(); ++i) {
    if (i > 0)
      out += ", ";
    append_number(out, c.per_primitive[i]);
  }
  out += "], \"overdraw\": ";
  if (c.hits.empty()) {
    out += "null}\n";
    return out;
  }
  // pixels[k - 1]: the pixels holding exactly k fragments.
  std::vector<std::uint64_t> pixels;
  for (const std::uint32_t h : c.hits) {
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
