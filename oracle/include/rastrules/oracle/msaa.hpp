// SPDX-License-Identifier: MIT
// Multisampling written a second time, for machines: exact, slow, independent. Written from
// spec/rules/msaa.md and spec/scene.md (SCENE.MSAA, SCENE.OUTPUT.MSAA) with GMP rationals:
// its own copy of the sample tables (typed from the spec's table), sample positions as exact
// rationals, per-sample coverage through the exact triangle, point and quadrilateral-line
// oracles (oracle/triangle.hpp, oracle/point.hpp) and the aliased-line oracle (oracle/line.hpp),
// both centroid rules with exact squared distances, helper lanes of even-aligned quads,
// derivatives of the evaluation point, and resolve as an exact rational average. It never
// includes or calls kernel code, and shares none of its types: everything is plain integers
// and strings spelled as in spec/scene.md.
// Implements (as oracle): MSAA.PATTERN.GRID, MSAA.PATTERN.STANDARD, MSAA.PATTERN.CENTER,
//   MSAA.PATTERN.CUSTOM, MSAA.SAMPLE.POSITION, MSAA.COVER.SAMPLE, MSAA.MASK.AND,
//   MSAA.POINT.PER_SAMPLE, MSAA.LINE.MODE, MSAA.SHADING.PIXEL, MSAA.SHADING.SAMPLE,
//   MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10, MSAA.CENTROID.WITHIN, MSAA.QUAD.ALIGN,
//   MSAA.QUAD.LANE, MSAA.QUAD.HELPER, MSAA.DERIV.FINE, MSAA.DERIV.COARSE, MSAA.RESOLVE.AVERAGE

#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rastrules/oracle/triangle.hpp"

namespace rastrules::oracle::msaa {

// A position in raw 16.8 units (1/256 px), y down.
using Raw2 = std::array<std::int64_t, 2>;
using Rgba = std::array<std::uint8_t, 4>;

// A sample offset from the pixel centre in 1/16 px, +y down.
struct Offset {
  std::int32_t x = 0;
  std::int32_t y = 0;
  friend bool operator==(const Offset&, const Offset&) = default;
};

// Returns whether o lies on the 16 x 16 grid, each coordinate in [-8, 7] (MSAA.PATTERN.GRID).
bool on_grid(const Offset& o);

// The standard pattern of n in {1, 2, 4, 8, 16} samples (MSAA.PATTERN.STANDARD), in
// sample-index order; throws std::invalid_argument for any other n.
std::vector<Offset> standard_pattern(std::uint32_t n);

// n samples at (0, 0) (MSAA.PATTERN.CENTER); throws std::invalid_argument unless n is standard.
std::vector<Offset> center_pattern(std::uint32_t n);

// Returns sample o of pixel (px, py) in raw 16.8 units: (p + 1/2 + o/16) px computed as an
// exact rational and multiplied by 256 (throws std::logic_error if that were not an integer).
Raw2 sample_raw(std::int64_t px, std::int64_t py, const Offset& o);

// Per-sample coverage masks of pixel (px, py) (bit k: sample k covered, before the mask).
std::uint32_t triangle_mask(const std::array<Raw2, 3>& v, const State& state, std::int64_t px,
                            std::int64_t py, const std::vector<Offset>& pattern);
std::uint32_t point_mask(const Raw2& centre, const std::string& fill, std::int64_t px,
                         std::int64_t py, const std::vector<Offset>& pattern);
// mode: "quad-wide" | "quad-narrow".
std::uint32_t quad_line_mask(const Raw2& a, const Raw2& b, const std::string& mode,
                             const std::string& fill, std::int64_t px, std::int64_t py,
                             const std::vector<Offset>& pattern);

// Which branch of a centroid rule chose the point (MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10).
enum class Branch {
  kFullCoverageCenter,
  kFirstCovered,
  kNearestCovered,
  kNoneCoveredMaskSample,
  kNoneCoveredCenter,
};

struct CentroidPoint {
  Offset offset; // from the pixel centre, in 1/16 px
  Branch branch = Branch::kFullCoverageCenter;
  friend bool operator==(const CentroidPoint&, const CentroidPoint&) = default;
};

// Returns the centroid of a pixel with coverage c (before the mask) under sample mask m, for
// rule "d3d11" or "d3d10". Only the pattern's low n bits of c and m are used. For m == 0
// with nothing covered (no sample to choose), both rules give the centre, branch
// kNoneCoveredCenter.
CentroidPoint centroid(const std::string& rule, std::uint32_t c, std::uint32_t m,
                       const std::vector<Offset>& pattern);

// Returns whether the pixel centre lies in the closed convex hull of the pattern's samples,
// decided exactly (Caratheodory: a sample, a segment of two or a triangle of three contains
// it). True for every standard and centre pattern (MSAA.CENTROID.WITHIN).
bool centre_in_hull(const std::vector<Offset>& pattern);

// Returns the exact average of the samples, per channel, rounded to the nearest integer,
// ties to even (MSAA.RESOLVE.AVERAGE). Throws std::invalid_argument on an empty list.
Rgba resolve_pixel(const std::vector<Rgba>& samples);

// One primitive: type "triangle" (3 vertices), "point" (1), "line" (2), "line_strip" (>= 2),
// vertices already snapped (raw 16.8).
struct Primitive {
  std::string type = "triangle";
  std::vector<Raw2> v;
  bool aa = false;
  Rgba color = {255, 255, 255, 255};
};

// A multisampled scene. line_mode is spelled as in spec/scene.md: "d3d", "vulkan-bresenham",
// "quad-wide", "quad-narrow".
struct Input {
  std::int32_t width = 0;
  std::int32_t height = 0;
  State state;
  std::string line_mode = "d3d";
  bool multisample_enable = false; // D3D's MultisampleEnable (MSAA.LINE.MODE)
  std::vector<Offset> pattern = {Offset{}};
  std::uint32_t sample_mask = 0xFFFFFFFFu;
  std::optional<std::string> centroid; // "d3d11" | "d3d10"
  std::string shading = "pixel";       // "pixel" | "sample"
  bool quads = false;
  std::string derivatives = "none"; // "none" | "fine" | "coarse" (not "none" implies quads)
  Rgba clear_color = {0, 0, 0, 0};
  std::vector<Primitive> primitives;
};

// Derivatives of the evaluation point in 1/16 px.
struct Deriv {
  std::int64_t ddx_x = 0, ddx_y = 0, ddy_x = 0, ddy_y = 0;
  friend bool operator==(const Deriv&, const Deriv&) = default;
};

struct Fragment {
  std::uint32_t prim = 0;
  std::int32_t x = 0;
  std::int32_t y = 0;
  std::uint32_t mask = 0;
  std::optional<std::uint32_t> seg;
  std::optional<std::uint32_t> sample;
  bool helper = false;
  std::optional<CentroidPoint> centroid;
  std::optional<Deriv> derivatives;
  friend bool operator==(const Fragment&, const Fragment&) = default;
};

// Returns every fragment of the scene in the order of SCENE.OUTPUT.MSAA (prim, y, x, seg,
// sample; a missing seg or sample first), found by testing every sample of every pixel of the
// target. Throws std::invalid_argument for input outside what the oracle models: an
// antialiased line with one sample (oracle/line_aa.hpp models it), sample shading of
// Bresenham lines with several samples (bad input, MSAA.SHADING.SAMPLE), an empty or too long
// pattern, an offset off the grid, or an unknown string. (Quadrilateral lines on centre
// patterns of several samples are bad input for the kernel; a plain list of offsets does not
// say whether it is a centre pattern, so callers keep such scenes away.)
std::vector<Fragment> render(const Input& in);

// Returns the resolved target, row-major: every sample cleared to clear_color, each non-helper
// fragment writing its primitive's colour to the samples of its mask in the given order, then
// resolve_pixel on each pixel.
std::vector<Rgba> resolve(const Input& in, const std::vector<Fragment>& fragments);

} // namespace rastrules::oracle::msaa
