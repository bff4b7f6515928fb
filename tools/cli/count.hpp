// SPDX-License-Identifier: MIT
// `rastrules render --count OUT.json`: fragments per primitive and per pixel (overdraw), without
// a record per fragment; the batch counter where the scene allows it (SCENE.OUTPUT.COUNT).
// Implements: SCENE.OUTPUT.COUNT

#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cli.hpp"

namespace rastrules::cli {

// Targets of at most this many pixels get the per-pixel counts of the overdraw (4 bytes a
// pixel: at most 256 MiB); larger ones the per-primitive counts alone.
inline constexpr std::uint64_t kMaxOverdrawPixels = std::uint64_t{1} << 26;

// The counts of one render.
// rule: SCENE.OUTPUT.COUNT
struct FragmentCounts {
  FragmentCounts(std::size_t primitives, std::int32_t width, std::int32_t height);
  std::int32_t width = 0;
  std::int32_t height = 0;
  std::vector<std::uint64_t> per_primitive;
  // Fragments per pixel (row-major), empty when the target has more than kMaxOverdrawPixels.
  std::vector<std::uint32_t> hits;
  // Counts one fragment (of prim, at x, y inside the target).
  void add(std::uint32_t prim, std::int32_t x, std::int32_t y) {
    ++per_primitive[prim];
    if (!hits.empty())
      ++hits[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
             static_cast<std::size_t>(x)];
  }
};

// Counts the scene with the batch counter (fast_count_batch, FAST.BATCH.EQUALS.PLAIN) when it
// can: a window-space scene of triangles alone, single-sample (is_single_sample), with the fast
// traversal; nullopt otherwise (the caller counts the fragments it streams).
// rule: SCENE.OUTPUT.COUNT, FAST.BATCH.EQUALS.PLAIN
[[nodiscard]] std::optional<FragmentCounts> batch_counts(const LoadedScene& loaded,
                                                         const RenderOptions& options);

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
