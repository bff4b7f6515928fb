// SPDX-License-Identifier: MIT
// `rastrules render --count OUT.json`: fragments per primitive and per pixel (overdraw), without
// a record per fragment; the batch counter where the scene allows it (SCENE.OUTPUT.COUNT).
// Implements: SCENE.OUTPUT.COUNT

#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cli.hpp"
#include "rastrules/raster/fast_batch.hpp"

namespace rastrules::cli {

// Targets of at most this many pixels get the per-pixel counts of the overdraw (a byte a pixel,
// and 4 bytes a pixel where a count passes 254: at most 320 MiB); larger ones the per-primitive
// counts alone.
inline constexpr std::uint64_t kMaxOverdrawPixels = std::uint64_t{1} << 26;

// The counts of one render.
// rule: SCENE.OUTPUT.COUNT
struct FragmentCounts {
  FragmentCounts(std::size_t primitives, std::int32_t width, std::int32_t height);
  std::int32_t width = 0;
  std::int32_t height = 0;
  std::vector<std::uint64_t> per_primitive;
  // Fragments per pixel (row-major; FAST.BATCH.PIXEL_COUNTS), none when the target has more
  // than kMaxOverdrawPixels.
  std::optional<raster::PixelCounts> hits;
  // Counts one fragment (of prim, at x, y inside the target).
  void add(std::uint32_t prim, std::int32_t x, std::int32_t y) {
    ++per_primitive[prim];
    if (hits)
      hits->add(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                static_cast<std::size_t>(x));
  }
};

// Counts the scene with the batch counter (fast_count_batch, FAST.BATCH.EQUALS.PLAIN) when it
// can: a window-space scene of triangles alone, single-sample (is_single_sample), with the fast
// traversal; nullopt otherwise (the caller counts the fragments it streams).
// rule: SCENE.OUTPUT.COUNT, FAST.BATCH.EQUALS.PLAIN
[[nodiscard]] std::optional<FragmentCounts> batch_counts(const LoadedScene& loaded,
                                                         const RenderOptions& options);

// An upper bound on primitive_work of the triangle (x0 y0 x1 y1 x2 y2) in a single-sample scene
// of a w x h target: its walk bounds (RASTER.WALK.BBOX) hold at most floor(s) + 1 pixel centres
// a row for a snapped span s, which is at most 1/256 px more than the span of the floats
// (SNAP.VERTEX.ROUND moves a coordinate by at most 1/512 px): floor(span) + 3 columns and rows
// (each clipped to the target) bound them with room to spare. Also the rows of its floats.
// nullopt for a coordinate that is not finite.
// rule: SCENE.INPUT.LIMITS
struct TriangleBound {
  double cols = 0, rows = 0;
  double lo_y = 0, hi_y = 0;
  [[nodiscard]] double work() const { return cols * rows; }
};
namespace bound_detail {

// Whether the six coordinates at t are finite: x - x is 0 for a finite x and NaN otherwise,
// which the sum keeps (one branch, not six).
inline bool finite_triangle(const float* t) {
  const float f = ((t[0] - t[0]) + (t[1] - t[1])) + ((t[2] - t[2]) + (t[3] - t[3])) +
                  ((t[4] - t[4]) + (t[5] - t[5]));
  return f == 0.0f;
}

// floor(span) + 3 clipped to the side, the span clipped to the side first: then the conversion
// to an integer (a truncation, the floor of a non-negative value) is in range and exact, and no
// call to floor() is made (the baseline instruction set has no rounding instruction: two calls
// a triangle were a tenth of the bounds' time). A NaN span gives the side (its triangle is
// refused as not finite apart).
inline double clipped_extent(double span, std::int32_t side) {
  const double s = span < side ? span : static_cast<double>(side);
  return std::min<double>(side, static_cast<double>(static_cast<std::int64_t>(s)) + 3);
}

} // namespace bound_detail

// Inline: the unit plan of a threaded list calls it for every triangle before the threads
// start (out of line, its optional went through memory and stalled on store forwarding: 20 ms of
// a 60 ms list of 10^6 small triangles).
inline std::optional<TriangleBound> triangle_bound(const float* t, std::int32_t w, std::int32_t h) {
  if (!bound_detail::finite_triangle(t))
    return std::nullopt;
  const float lo_x = std::min({t[0], t[2], t[4]}), hi_x = std::max({t[0], t[2], t[4]});
  const float lo_y = std::min({t[1], t[3], t[5]}), hi_y = std::max({t[1], t[3], t[5]});
  TriangleBound b;
  b.cols = bound_detail::clipped_extent(double{hi_x} - double{lo_x}, w);
  b.rows = bound_detail::clipped_extent(double{hi_y} - double{lo_y}, h);
  b.lo_y = lo_y;
  b.hi_y = hi_y;
  return b;
}

// rule: SCENE.INPUT.LIMITS
// Adds the work bounds (triangle_bound) of the triangles xy on a width x height target to
// `work`; false where a coordinate is not finite or the sum passes max_work (the caller then
// declines, and the scene's own load names the error).
[[nodiscard]] bool add_work_bounds(std::span<const float> xy, std::int32_t width,
                                   std::int32_t height, std::uint64_t max_work, double& work);

// A scene of the fast reader's form (io::read_triangles_fast: a target and triangles given by
// "type" and "v" alone) ready for the batch unit without its primitives built or prepared: the
// scene without primitives, loaded (its target checked, its state prepared), and six floats a
// triangle. nullopt when the traversal is not the fast one, the text is not of that form, the
// target or state is refused, the scene is not single-sample, or a bound on its work (at least
// the exact work of SCENE.INPUT.LIMITS) passes max_work: the caller then loads the scene as any
// other, which names every error.
// rule: SCENE.INPUT.FAST_READER, SCENE.INPUT.LIMITS
struct FastForm {
  LoadedScene base;
  std::vector<float> xy;
};
[[nodiscard]] std::optional<FastForm>
load_fast_form(std::string_view text, const RenderOptions& options, std::uint64_t max_work);

// The head of a scene of the fast form (its target and state, no primitives) loaded and
// prepared, as a stream of its triangles needs it: nullopt where the target or state is
// refused or the scene is not single-sample (the stream declines; the scene's own load names
// any error).
// rule: SCENE.INPUT.FAST_READER
[[nodiscard]] std::optional<PreparedScene> prepared_head(const Scene& head);

// Counts a scene of the fast reader's form (io::read_triangles_fast: a target and triangles given
// by "type" and "v" alone) with the batch counter without building its primitives or
// preparing them: the counts batch_counts() gives for the loaded scene. nullopt when the form,
// the traversal, the target, the work limit (max_work, checked on a bound) or a vertex that does
// not snap stands in the way: the caller then loads the scene and counts it as any other, which
// names every error as before.
// rule: SCENE.OUTPUT.COUNT, SCENE.INPUT.FAST_READER
[[nodiscard]] std::optional<FragmentCounts>
fast_form_counts(std::string_view text, const RenderOptions& options, std::uint64_t max_work);

// The counts as SCENE.OUTPUT.COUNT's JSON (one line, a newline at the end).
// rule: SCENE.OUTPUT.COUNT
[[nodiscard]] std::string counts_json(const FragmentCounts& c);

} // namespace rastrules::cli
