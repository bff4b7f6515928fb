// SPDX-License-Identifier: MIT
// The fragment list of a scene of the fast reader's form written from the batch unit's runs
// (SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.BINARY), on one thread or several: no fragment record
// is built, and with threads each thread makes the bytes of whole units of triangles (or of
// bands of rows of a large one) that the calling thread writes in order.
// Implements: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.BINARY, FAST.THREADS.DETERMINISTIC

#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "rastrules/io/fragment_binary.hpp"
#include "rastrules/io/fragment_json.hpp"
#include "rastrules/isa.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules::cli {

// A unit of the threaded list: triangles [first, last) whole, or (band) triangle `first`'s rows
// y_first to y_last alone; bound: the unit's work bound in pixels (at least its fragments).
struct RunUnit {
  std::uint32_t first = 0;
  std::uint32_t last = 0;
  bool band = false;
  std::int32_t y_first = 0;
  std::int32_t y_last = 0;
  double bound = 0;
};

// The units of the triangles xy (six finite floats a triangle) on a width x height target, in
// the order of the list: consecutive triangles whose work bounds ((floor(span) + 3) pixel
// centres an axis, clipped to the target: load_fast_form's) sum to at most `group_budget`
// pixels (at most kMaxRunUnitTriangles of them) share a unit; a triangle whose bound passes
// `group_budget` is cut into bands of whole rows of at most `band_budget` pixels of its bound
// each (at least a row), covering every row it can reach (its floats' rows widened by a pixel:
// snapping moves a vertex by at most 1/512 px).
inline constexpr std::uint32_t kMaxRunUnitTriangles = 4096;
[[nodiscard]] std::vector<RunUnit> plan_run_units(std::span<const float> xy, std::int32_t width,
                                                  std::int32_t height, double group_budget,
                                                  double band_budget);

// The fragments fast_count_batch counts for the triangles xy, on `threads` threads (the
// triangles in that many contiguous parts, counted in parallel and added); nullopt when it
// refuses one (a vertex that does not snap).
// rule: FAST.BATCH.EQUALS.PLAIN, FAST.THREADS.DETERMINISTIC
[[nodiscard]] std::optional<std::uint64_t> count_fast_list(std::span<const float> xy,
                                                           std::int32_t width, std::int32_t height,
                                                           const RasterState& state, Isa isa,
                                                           unsigned threads);

// What write_fast_list wrote.
struct FastListResult {
  bool ok = true;            // false: the runs disagree with a count (internal error)
  bool declined = false;     // a vertex that does not snap, or more than max_fragments
  std::uint64_t covered = 0; // fragments written
  bool in_order = true;      // every fragment came after the previous one (the writer checked)
};

// Writes the fragments fast_runs_batch finds for the triangles xy to exactly one of json and
// binary (the other null), in the list's order, with `threads` threads (1: straight from the
// runs). The same bytes for every thread count (FAST.THREADS.DETERMINISTIC). It stops, declined,
// at a triangle that does not snap or once more than max_fragments fragments are found, having
// written part of the list (a caller writing where that cannot be taken back counts the
// triangles with fast_count_batch first). first_prim: the primitive index of xy's first
// triangle (a list written a chunk at a time).
// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.BINARY, FAST.THREADS.DETERMINISTIC
[[nodiscard]] FastListResult write_fast_list(std::span<const float> xy, std::int32_t width,
                                             std::int32_t height, const RasterState& state, Isa isa,
                                             unsigned threads, std::uint64_t max_fragments,
                                             io::FragmentWriter* json,
                                             io::FragmentBinaryWriter* binary,
                                             std::uint32_t first_prim = 0);

} // namespace rastrules::cli
