// SPDX-License-Identifier: MIT
// Implements: SCENE.OUTPUT.COUNT

#include "count.hpp"

#include <algorithm>
#include <charconv>
#include <span>

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
  FragmentCounts c(loaded.scene.primitives.size(), scene.width, scene.height);
  const raster::FastBatchResult r = raster::fast_count_batch(
      xy, scene.width, scene.height, scene.state, effective_isa(options), c.per_primitive, c.hits);
  // prepare() has snapped every vertex and checked the target: the batch cannot refuse them.
  if (r.status != raster::BatchStatus::kOk)
    throw std::logic_error("the batch counter refused a prepared scene: " + raster::describe(r));
  return c;
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
