// SPDX-License-Identifier: MIT
// 2D paths: contours of lines and quadratic and cubic Bézier curves, filled under the nonzero
// or even-odd rule, with exact sample coverage (every fill convention, every sample pattern)
// and exact area coverage. Rules: spec/rules/path.md.
// Implements: PATH.GEOMETRY, PATH.CONTOUR.CLOSE, PATH.WINDING, PATH.FILL.RULE,
//             PATH.SAMPLE.TIE, PATH.COVER.SAMPLE, PATH.AREA.EXACT, PATH.DEGENERATE,
//             PATH.CURVE.SAMPLE, PATH.AREA.CELLS, PATH.AREA.ALPHA, PATH.AREA.CURVE,
//             PATH.AREA.FAST
// Needs, beyond the standard library, Boost.Multiprecision's headers (exact rational areas).

#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <boost/multiprecision/cpp_int.hpp>

#include "rastrules/msaa.hpp"
#include "rastrules/name_table.hpp"
#include "rastrules/path_types.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules::path {

// One crossing of the ray of PATH.WINDING from a sample displaced as PATH.SAMPLE.TIE says: the
// piece of the boundary that crossed it (segment == the contour's segment count for its closing
// line, PATH.CONTOUR.CLOSE) and its direction (+1 where the boundary runs down, -1 up).
struct SampleCrossing {
  std::size_t contour = 0;
  std::size_t segment = 0;
  int dir = 0;
  friend bool operator==(const SampleCrossing&, const SampleCrossing&) = default;
};

// Returns the crossings that make w(s') of PATH.SAMPLE.TIE for the sample at raw position s, by
// contour and segment (a curve may cross more than once): winding_number() is the sum of their
// dir, and explanations list them.
// rule: PATH.WINDING, PATH.SAMPLE.TIE
[[nodiscard]] std::vector<SampleCrossing> crossings(const Path& path, Point s, FillConvention fill);

// Returns w(s') of PATH.SAMPLE.TIE for the sample at raw position s: the winding number at s
// displaced by (hx eps, hy delta), delta << eps, (hx, hy) from the fill convention.
// rule: PATH.WINDING, PATH.SAMPLE.TIE
[[nodiscard]] std::int64_t winding_number(const Path& path, Point s, FillConvention fill);

// Returns whether the path covers the sample at raw position s (PATH.SAMPLE.TIE).
// rule: PATH.SAMPLE.TIE, PATH.FILL.RULE
[[nodiscard]] bool covers_sample(const Path& path, Point s, FillConvention fill);

// One pixel with at least one covered sample: bit k of mask is sample k of the pattern.
struct SampleCoverage {
  std::int32_t x = 0, y = 0;
  std::uint32_t mask = 0;
  friend bool operator==(const SampleCoverage&, const SampleCoverage&) = default;
};

// Returns every pixel of [0, w) x [0, h) with at least one covered sample, row by row (y, then
// x). Computes no area. Preconditions: 0 <= w, h <= kMaxTargetSide.
// rule: PATH.COVER.SAMPLE
[[nodiscard]] std::vector<SampleCoverage> cover_samples(const Path& path,
                                                        const SamplePattern& pattern,
                                                        FillConvention fill, std::int32_t w,
                                                        std::int32_t h);
// The same, each pixel passed to emit as it is found (memory: one row of the target).
void cover_samples(const Path& path, const SamplePattern& pattern, FillConvention fill,
                   std::int32_t w, std::int32_t h,
                   const std::function<void(const SampleCoverage&)>& emit);

// Writes the aliased coverage of [0, w) x [0, h) as a packed bitmap of one bit a pixel, the
// layout of FreeType's FT_PIXEL_MODE_MONO and of 1-bit surfaces: row y from bits[y * pitch],
// pixel x at bit 7 - x % 8 of the row's byte x / 8, set iff the path covers the pixel's centre
// (the one sample of standard_pattern(1), PATH.SAMPLE.TIE). Writes every byte of the buffer:
// the bits past w and the bytes past (w + 7) / 8 of a row are 0. Builds no record a pixel.
// Preconditions: 0 <= w, h <= kMaxTargetSide; pitch >= (w + 7) / 8 and bits.size() == h * pitch,
// else std::invalid_argument.
// rule: PATH.COVER.MONO
void cover_samples_mono(const Path& path, FillConvention fill, std::int32_t w, std::int32_t h,
                        std::span<std::uint8_t> bits, std::size_t pitch);
// Returns whether pixel (x, y) is set in a bitmap of cover_samples_mono's layout: the bit
// 7 - x % 8 of byte y * pitch + x / 8 (the reader of that layout, for callers comparing
// another 1-bit output with it). Preconditions: 0 <= x < 8 pitch, 0 <= y and
// (y + 1) * pitch <= bits.size().
// rule: PATH.COVER.MONO
[[nodiscard]] inline bool mono_bit(std::span<const std::uint8_t> bits, std::size_t pitch,
                                   std::int32_t x, std::int32_t y) {
  const auto ux = static_cast<std::size_t>(x);
  return ((bits[static_cast<std::size_t>(y) * pitch + ux / 8] >> (7 - ux % 8)) & 1u) != 0;
}

// One pixel with nonzero area: area in px^2 as a reduced rational, exact (error_bound 0) for
// paths of lines; for curves within error_bound of the exact area.
struct AreaCoverage {
  std::int32_t x = 0, y = 0;
  boost::multiprecision::cpp_rational area;
  boost::multiprecision::cpp_rational error_bound;
  friend bool operator==(const AreaCoverage&, const AreaCoverage&) = default;
};

// The value behind a path fragment's ExactArea (rastrules/scene.hpp): its area and the bound
// of AreaCoverage.
struct AreaValue {
  boost::multiprecision::cpp_rational area;
  boost::multiprecision::cpp_rational error_bound;
};

// Returns every pixel of [0, w) x [0, h) with nonzero area under the fill rule, row by row:
// exact for paths of lines; for paths with curves within each pixel's error_bound, and pixels
// with a nonzero bound are listed too (PATH.AREA.CURVE). A target side above kMaxTargetSide (the
// bound the cell method's budgets are proved for) throws std::invalid_argument.
// rule: PATH.AREA.EXACT, PATH.AREA.CURVE
[[nodiscard]] std::vector<AreaCoverage> cover_area(const Path& path, std::int32_t w,
                                                   std::int32_t h);
// The same, each pixel passed to emit as it is found (memory: one row of the target).
void cover_area(const Path& path, std::int32_t w, std::int32_t h,
                const std::function<void(const AreaCoverage&)>& emit);

// The part of a pixel where the winding number is `winding` (the faces of the arrangement of the
// boundary with that winding number, together), its area in px^2, and whether the fill rule
// holds there: the pixel's area (cover_area) is the sum of the parts that fill.
struct WindingArea {
  std::int64_t winding = 0;
  boost::multiprecision::cpp_rational area;
  bool fills = false;
  friend bool operator==(const WindingArea&, const WindingArea&) = default;
};
// A pixel's parts by increasing winding number (those of area 0 left out), exact for paths of
// lines; for curves each within error_bound of the exact part (PATH.AREA.CURVE).
struct PixelWindings {
  std::vector<WindingArea> parts;
  boost::multiprecision::cpp_rational error_bound;
};

// Returns the parts of pixel (x, y) of a w x h target by winding number, for explanations:
// where several windings meet in the pixel (conflation), which of them fill; the filled parts
// add up to cover_area(path, w, h)'s area of the pixel, and the bound is its bound. A pixel
// outside the target or a side above kMaxTargetSide: std::invalid_argument.
// rule: PATH.AREA.EXACT, PATH.AREA.CURVE, PATH.WINDING
[[nodiscard]] PixelWindings winding_areas(const Path& path, std::int32_t x, std::int32_t y,
                                          std::int32_t w, std::int32_t h);

// Writes the 8-bit alpha of every pixel of [0, w) x [0, h) into alpha (row by row, w * h
// bytes, else std::invalid_argument): floor(255 a + 1/2) of the exact area a of cover_area, so
// a pixel listed by cover_area may get alpha 0 (a < 1/510). Builds no rational where the area
// fits 128-bit fractions. Paths with curves: certified floating-point cells decide the alpha of
// the exact area where they can (PATH.AREA.FAST), the rows they leave get the alpha of
// cover_area's area (PATH.AREA.CURVE).
// rule: PATH.AREA.ALPHA, PATH.AREA.FAST
void cover_area_alpha(const Path& path, std::int32_t w, std::int32_t h,
                      std::span<std::uint8_t> alpha);

using rastrules::to_string;

} // namespace rastrules::path
