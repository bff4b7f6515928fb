// SPDX-License-Identifier: MIT
// Helpers for the example tests: triangles and samples written in pixels, covered-pixel
// sets, and small ASCII pictures of a target so that expectations can be checked on squared
// paper. Every helper goes through the kernel's public API; none re-implements a rule.

#pragma once

#include <array>
#include <compare>
#include <cstdint>
#include <initializer_list>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "rastrules/fixed.hpp"
#include "rastrules/scene.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules::test {

// A position in window coordinates, in pixels (origin top-left, y down).
struct Px {
  double x = 0.0;
  double y = 0.0;
};

// A pixel (i, j) of the render target. Ordered as fragments are: by row, then column.
struct Pixel {
  std::int32_t x = 0;
  std::int32_t y = 0;
  friend constexpr bool operator==(const Pixel&, const Pixel&) = default;
  friend constexpr std::strong_ordering operator<=>(const Pixel& a, const Pixel& b) {
    if (const auto c = a.y <=> b.y; c != 0)
      return c;
    return a.x <=> b.x;
  }
};
std::ostream& operator<<(std::ostream& os, const Pixel& p);

// Returns the snapped value of coordinate v (SNAP.VERTEX.ROUND).
// Preconditions: v is exactly a float32 and snaps without error; otherwise throws
// std::invalid_argument (a test that needs the error path calls snap_to_subpixel itself).
[[nodiscard]] Subpixel snap_px(double v);

// Returns the sample at (x, y) px. Preconditions: x * 256 and y * 256 are integers in the
// vertex range (a sample is a point of the 16.8 grid); otherwise throws std::invalid_argument.
[[nodiscard]] Vec2 sample_px(double x, double y);

// Returns the setup of the triangle with vertices a, b, c in pixels, snapped as a scene is.
[[nodiscard]] TriangleSetup triangle_px(Px a, Px b, Px c, const RasterState& state = {});

// Returns the pixels the traversal emits for t on a width x height target, in emission order.
[[nodiscard]] std::vector<Pixel> walk_pixels(const TriangleSetup& t, std::int32_t width,
                                             std::int32_t height);

// Returns the pixels of a width x height target whose centre t covers (covers() at every
// centre, no traversal), sorted by (y, x).
[[nodiscard]] std::vector<Pixel> centre_pixels(const TriangleSetup& t, std::int32_t width,
                                               std::int32_t height);

// Returns the pixels marked with `mark` in a picture of the target, one string per row from
// the top (row 0) down, one character per pixel; sorted by (y, x).
[[nodiscard]] std::vector<Pixel> pixels_in_picture(std::initializer_list<std::string_view> rows,
                                                   char mark = '#');

// Returns a picture of the pixels ('#') on a width x height target ('.' elsewhere), rows
// separated by newlines, for readable failure messages.
[[nodiscard]] std::string picture(const std::vector<Pixel>& pixels, std::int32_t width,
                                  std::int32_t height);

// Returns a primitive of type t with vertices in pixels (exact float32 values).
[[nodiscard]] Primitive prim_px(PrimitiveType t, std::vector<FloatPoint> v);

// Returns a scene of triangles given in pixels.
[[nodiscard]] Scene scene_px(std::int32_t width, std::int32_t height, const RasterState& state,
                             std::initializer_list<std::array<Px, 3>> triangles);

// Returns the fragments of prim `prim` as pixels, in output order.
[[nodiscard]] std::vector<Pixel> pixels_of(const std::vector<Fragment>& fragments,
                                           std::uint32_t prim);

// Returns "" when the kernel's decision records agree with its rasterization: for every
// primitive p and every pixel (x, y) of the target, decide_pixel(scene, p, x, y) says covered
// exactly when rasterize_primitive(scene, p) has a fragment (not a helper) there; each
// triangle's record is covered exactly when covers() says so and then was decided by
// TRI.COVER.SAMPLE; each line segment's record equals the fragment of its segment (and its
// antialiasing coverage); and, on the multisampled path, each segment's record has the
// fragment's mask (the OR of its per-sample fragments under sample shading), its centroid,
// its helper lanes, and a coverage that the per-sample triangle records explain. Otherwise a
// description of the first disagreement. Preconditions: a prepared scene of at most 64x64.
// rule: TRI.COVER.SAMPLE, MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.QUAD.HELPER
[[nodiscard]] std::string decision_disagreement(const PreparedScene& scene);

// Returns n primitives of type t (a line strip has three vertices) from a fixed seed, with
// vertices on a grid of 1/steps px over the width x height target and a one-pixel margin, so
// that many vertices, edges and pixel centres or samples tie.
[[nodiscard]] std::vector<Primitive> tie_heavy_primitives(PrimitiveType t, std::size_t n,
                                                          std::uint32_t seed, std::int32_t width,
                                                          std::int32_t height, int steps = 2);

// Returns prepare(scene); throws std::invalid_argument naming the error if it is rejected.
[[nodiscard]] PreparedScene prepared(const Scene& scene);

// The four fill conventions, for loops over all of them.
inline constexpr FillConvention kAllConventions[] = {
    FillConvention::kTopLeft, FillConvention::kTopRight, FillConvention::kBottomLeft,
    FillConvention::kBottomRight};

} // namespace rastrules::test
