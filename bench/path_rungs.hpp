// SPDX-License-Identifier: MIT
// What accuracy costs for 2D paths (spec/bench.md BENCH.PATH.*): the comparators of the path
// ladder (supersampling with the kernel's sample patterns, signed-area accumulation in float and
// in 24.8 fixed point, as 2D libraries fill paths), curve flattening for the rungs that need
// lines, and the scenes (glyphs of a font, generated self-intersecting polygons). Comparators,
// not the product: they live here, never in kernel/.
// Implements: BENCH.PATH.RUNGS, BENCH.PATH.SCENES

#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "rastrules/path.hpp"

namespace rastrules::bench::paths {

// A scene: one or more paths, each in its own target (a glyph and its target, or a polygon).
// `curved` is what the source gave (curves kept); `lines` is the same outline of lines only
// (flatten()), which every area rung fills, since exact curve areas are not built. Every point of
// both is on the 26.6 grid (a multiple of 4 raw), so FreeType fills exactly the same outlines.
// rule: BENCH.PATH.SCENES
struct PathItem {
  path::Path curved;
  path::Path lines;
  std::int32_t width = 0;
  std::int32_t height = 0;
};
struct PathScene {
  std::string name;
  std::string note;
  std::vector<PathItem> items;
  [[nodiscard]] std::uint64_t pixels() const;
  [[nodiscard]] std::uint64_t segments() const; // of the lines-only outlines
};

// The flattening tolerance of flatten(), in pixels: every chord lies within it of its curve
// piece before the points are rounded to the 26.6 grid (which moves them by at most 1/128 px).
inline constexpr double kFlattenTolerance = 1.0 / 64.0;

// The path with every quadratic and cubic replaced by n chords at t = k / n (evaluated in
// double, rounded to the nearest 26.6 point; the ends kept exactly), n the least with the chord
// bound |d| / (4 n^2) (quadratic, d = P0 - 2 P1 + P2) or 3 M / (4 n^2) (cubic, M the larger
// second difference) at most `tolerance` px.
// rule: BENCH.PATH.SCENES
[[nodiscard]] path::Path flatten(const path::Path& p, double tolerance);

// Generated polygons in targets of side x side: star polygons {n/k} (self-intersecting),
// every contour drawn twice, a diagonal drawn down and back up, overlapping random polygons;
// seeded, points on the 26.6 grid; each under nonzero and evenodd.
// rule: BENCH.PATH.SCENES
[[nodiscard]] PathScene make_polygon_scene(std::uint64_t seed, std::int32_t side);

// Signed-area accumulation as 2D libraries do it (FreeType's "gray" raster, font-rs, stb):
// every line adds, to the cells (pixels) it crosses, its cover (signed height) and area (signed
// height times the sum of its x offsets in the cell); a sweep along each row sums the covers and
// gives each pixel the winding-weighted area w_sum = cover_so_far - area / 2, then coverage =
// min(1, |w_sum|) (nonzero) or the triangle wave of |w_sum| with period 2 (evenodd). Exact only
// where one winding number meets the pixel: elsewhere (conflation) it is not the area of
// PATH.AREA.EXACT. T = float: coordinates in pixels as float32, all arithmetic in float32.
// T = double: the same in float64 (used to find the conflation pixels). T = std::int64_t:
// coordinates in 1/256 px (24.8, FreeType's PIXEL_BITS = 8), crossings of cell edges rounded to
// the nearest 1/256 (ties away from zero), cover and area exact integers. Lines only: curves
// are flattened first (flatten()).
// rule: BENCH.PATH.RUNGS
template <class T>
void accumulate(const path::Path& lines, std::int32_t w, std::int32_t h, std::vector<double>& out);

// Supersampling: the kernel's sample coverage with the standard pattern of n samples (4, 16),
// coverage = set bits / n, per pixel (dense, row by row).
// rule: BENCH.PATH.RUNGS
void supersample(const path::Path& p, std::uint32_t n, std::int32_t w, std::int32_t h,
                 std::vector<double>& out);

} // namespace rastrules::bench::paths
