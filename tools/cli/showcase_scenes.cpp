// SPDX-License-Identifier: MIT
// The built-in showcase scenes. Every coordinate here is a float32 chosen to land on the
// cases the rules decide: pixel centres on edges and vertices, shared edges, half-subpixel
// snapping ties, slivers, and the ends of the supported range.

#include "showcase_scenes.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <utility>
#include <vector>

namespace rastrules::cli {
namespace {

using Point = std::array<float, 2>;

Primitive tri(Point a, Point b, Point c) {
  Primitive p;
  p.type = PrimitiveType::kTriangle;
  p.v = {a, b, c};
  return p;
}

Scene make_scene(std::int32_t w, std::int32_t h, RasterState state = {}) {
  Scene s;
  s.width = w;
  s.height = h;
  set_raster_state(s, state);
  return s;
}

// In the style of the D3D11.3 triangle rasterization diagram (img/TriRast.png): a 16x8
// target with a large triangle, two tiny ones covering no centre, a diamond split along a
// horizontal edge through a row of centres, a fan around a pixel centre, a small triangle
// whose vertical left edge runs through a centre, a square split along a diagonal through
// centres, a tall sliver and a triangle leaving the target at the bottom.
Scene d3d_diagram() {
  Scene s = make_scene(16, 8);
  auto& p = s.primitives;
  p.push_back(tri({1.0f, 0.95f}, {6.0f, 2.0f}, {2.0f, 3.95f}));
  p.push_back(tri({5.25f, 1.2f}, {6.25f, 1.2f}, {6.25f, 0.3f}));
  p.push_back(tri({6.7f, 1.2f}, {7.75f, 1.2f}, {7.6f, 0.45f}));
  p.push_back(tri({9.5f, 0.75f}, {11.75f, 2.5f}, {7.75f, 2.5f})); // diamond, upper half
  p.push_back(tri({7.75f, 2.5f}, {11.75f, 2.5f}, {9.5f, 5.25f})); // diamond, lower half
  const Point c{7.5f, 4.5f};                                      // fan centre: a pixel centre
  p.push_back(tri(c, {1.0f, 6.0f}, {3.5f, 4.5f}));
  p.push_back(tri(c, {5.5f, 7.5f}, {1.0f, 6.0f}));
  p.push_back(tri(c, {7.5f, 7.5f}, {5.5f, 7.5f}));
  p.push_back(tri(c, {9.5f, 6.0f}, {7.5f, 7.5f}));
  p.push_back(tri({11.5f, 5.0f}, {12.5f, 5.5f}, {11.5f, 6.5f})); // left edge through (11.5, 5.5)
  p.push_back(tri({13.5f, 5.5f}, {15.5f, 5.5f}, {13.5f, 7.5f})); // square, split on the diagonal
  p.push_back(tri({15.5f, 5.5f}, {15.5f, 7.5f}, {13.5f, 7.5f}));
  p.push_back(tri({14.5f, -0.2f}, {14.6f, 4.6f}, {13.5f, 1.5f})); // tall sliver
  p.push_back(
      tri({9.5f, 7.5f}, {10.5f, 7.5f}, {9.5f, 9.5f})); // vertex on a centre, leaves the target
  return s;
}

// A fan of 16 triangles around a pixel centre, every outer vertex on a pixel centre too, so
// that every edge passes through centres: each centre inside the outline is covered once.
Scene fan() {
  Scene s = make_scene(24, 24);
  const std::array<Point, 16> rim = {{{22.5f, 12.5f},
                                      {21.5f, 16.5f},
                                      {19.5f, 19.5f},
                                      {16.5f, 21.5f},
                                      {12.5f, 22.5f},
                                      {8.5f, 21.5f},
                                      {5.5f, 19.5f},
                                      {3.5f, 16.5f},
                                      {2.5f, 12.5f},
                                      {3.5f, 8.5f},
                                      {5.5f, 5.5f},
                                      {8.5f, 3.5f},
                                      {12.5f, 2.5f},
                                      {16.5f, 3.5f},
                                      {19.5f, 5.5f},
                                      {21.5f, 8.5f}}};
  for (std::size_t i = 0; i < rim.size(); ++i) {
    // Alternate the vertex order: coverage does not depend on the winding with culling off.
    const Point a = rim[i], b = rim[(i + 1) % rim.size()];
    s.primitives.push_back(i % 2 == 0 ? tri({12.5f, 12.5f}, a, b) : tri({12.5f, 12.5f}, b, a));
  }
  return s;
}

// A deterministic generator (xorshift64*) for the jittered mesh.
class Rng {
public:
  explicit Rng(std::uint64_t seed) : s_(seed) {}
  std::uint64_t next() {
    s_ ^= s_ >> 12;
    s_ ^= s_ << 25;
    s_ ^= s_ >> 27;
    return s_ * 0x2545F4914F6CDD1DULL;
  }
  // Returns an integer in [lo, hi].
  std::int32_t in(std::int32_t lo, std::int32_t hi) {
    return lo + static_cast<std::int32_t>(next() % static_cast<std::uint64_t>(hi - lo + 1));
  }

private:
  std::uint64_t s_;
};

// A grid of 8 x 6 cells, 4 px each, whose interior vertices are jittered by whole subpixels;
// one vertex in three sits exactly on a pixel centre. Cells are split along alternating
// diagonals and every other triangle is given counter-clockwise.
Scene jittered_grid() {
  Scene s = make_scene(32, 24);
  constexpr int kNx = 8, kNy = 6, kCell = 4;
  Rng rng(0x5EEDu);
  std::array<std::array<Point, kNx + 1>, kNy + 1> v{};
  for (int j = 0; j <= kNy; ++j) {
    for (int i = 0; i <= kNx; ++i) {
      std::int32_t x = i * kCell * 256, y = j * kCell * 256;
      if (i > 0 && i < kNx && j > 0 && j < kNy) {
        if (rng.in(0, 2) == 0) {
          x += 128; // a pixel centre
          y += 128;
        } else {
          x += rng.in(-300, 300);
          y += rng.in(-300, 300);
        }
      }
      v[static_cast<std::size_t>(j)][static_cast<std::size_t>(i)] =
          Point{static_cast<float>(x) / 256.0f, static_cast<float>(y) / 256.0f};
    }
  }
  int n = 0;
  for (std::size_t j = 0; j < kNy; ++j) {
    for (std::size_t i = 0; i < kNx; ++i) {
      const Point a = v[j][i], b = v[j][i + 1], c = v[j + 1][i + 1], d = v[j + 1][i];
      std::array<Primitive, 2> halves = (i + j) % 2 == 0
                                            ? std::array<Primitive, 2>{tri(a, b, c), tri(a, c, d)}
                                            : std::array<Primitive, 2>{tri(a, b, d), tri(b, c, d)};
      for (Primitive& p : halves) {
        if (n++ % 2 == 1)
          std::swap(p.v[1], p.v[2]);
        s.primitives.push_back(p);
      }
    }
  }
  return s;
}

// Ties on every edge type: a square of four triangles meeting at a pixel centre with its
// corners on pixel centres (diagonal edges through centres), a rectangle split into two with
// horizontal and vertical edges along rows and columns of centres, and a triangle whose three
// vertices are pixel centres.
Scene ties(FillConvention fill) {
  RasterState state;
  state.fill = fill;
  Scene s = make_scene(14, 12, state);
  auto& p = s.primitives;
  const Point c{5.5f, 5.5f}, nw{1.5f, 1.5f}, ne{9.5f, 1.5f}, se{9.5f, 9.5f}, sw{1.5f, 9.5f};
  p.push_back(tri(c, nw, ne));
  p.push_back(tri(c, ne, se));
  p.push_back(tri(c, se, sw));
  p.push_back(tri(c, sw, nw));
  p.push_back(tri({10.5f, 1.5f}, {12.5f, 1.5f}, {12.5f, 6.5f})); // horizontal top, vertical right
  p.push_back(tri({10.5f, 1.5f}, {12.5f, 6.5f}, {10.5f, 6.5f})); // vertical left, horizontal bottom
  p.push_back(tri({10.5f, 8.5f}, {12.5f, 10.5f}, {10.5f, 10.5f}));
  return s;
}

// Culling after snapping: pairs of equal triangles with both windings, a triangle that is
// degenerate only after snapping, and one whose winding flips when snapped.
Scene culling(CullMode cull, FrontFace front) {
  RasterState state;
  state.cull = cull;
  state.front_face = front;
  Scene s = make_scene(16, 8, state);
  auto& p = s.primitives;
  p.push_back(tri({0.5f, 0.5f}, {4.5f, 0.5f}, {0.5f, 4.5f}));    // clockwise
  p.push_back(tri({4.5f, 0.5f}, {4.5f, 4.5f}, {0.5f, 4.5f}));    // clockwise
  p.push_back(tri({5.5f, 0.5f}, {5.5f, 4.5f}, {9.5f, 0.5f}));    // counter-clockwise
  p.push_back(tri({9.5f, 0.5f}, {5.5f, 4.5f}, {9.5f, 4.5f}));    // counter-clockwise
  p.push_back(tri({10.5f, 1.5f}, {14.5f, 2.5f}, {11.5f, 6.5f})); // clockwise
  p.push_back(tri({10.5f, 1.5f}, {11.5f, 6.5f}, {14.5f, 2.5f})); // the same, counter-clockwise
  // Degenerate after snapping: y = 1.001 and 1.0019 both snap to 1 (raw 256).
  p.push_back(tri({1.0f, 6.0f}, {5.0f, 6.001f}, {9.0f, 6.0019f}));
  // Clockwise as floats (A = 0.004 px^2), counter-clockwise once snapped.
  p.push_back(tri({0.0f, 7.0f}, {10.0f, 7.003f}, {5.0f, 7.0019f}));
  return s;
}

// Slivers and needles: triangles one subpixel wide along rows and columns of centres and
// along a diagonal, and long needles crossing the whole target.
Scene slivers() {
  Scene s = make_scene(32, 16);
  auto& p = s.primitives;
  constexpr float kSub = 1.0f / 256.0f;
  p.push_back(tri({0.5f, 2.5f}, {31.5f, 2.5f}, {0.5f, 2.5f + kSub}));  // top edge on a row
  p.push_back(tri({0.5f, 4.5f - kSub}, {31.5f, 4.5f}, {0.5f, 4.5f}));  // bottom edge on a row
  p.push_back(tri({3.5f, 6.5f}, {3.5f + kSub, 15.5f}, {3.5f, 15.5f})); // left edge on a column
  p.push_back(tri({6.5f, 6.5f}, {6.5f, 15.5f}, {6.5f - kSub, 15.5f})); // right edge on a column
  p.push_back(tri({8.5f, 6.5f}, {15.5f, 13.5f}, {8.5f + kSub, 6.5f})); // diagonal through centres
  p.push_back(tri({-40.0f, 7.25f}, {70.0f, 7.75f}, {-40.0f, 7.2578125f}));   // long needle
  p.push_back(tri({16.0f, 0.1f}, {31.9f, 15.9f}, {16.02f, 0.1f}));           // thin, steep
  p.push_back(tri({17.5f, 5.5f}, {30.5f, 14.5f}, {17.5f + 2 * kSub, 5.5f})); // needle from a centre
  return s;
}

// Triangles far larger than the target with vertices at the ends of the supported range,
// [-32768, 32767.99609375]. The first two share the diagonal x = y, which runs through the
// centres (i + 0.5, i + 0.5): together they cover the target exactly once.
Scene huge() {
  Scene s = make_scene(32, 32);
  auto& p = s.primitives;
  constexpr float kMin = -32768.0f, kMax = 32767.99609375f;
  p.push_back(tri({kMin, kMin}, {kMax, kMin}, {kMax, kMax}));
  p.push_back(tri({kMin, kMin}, {kMax, kMax}, {kMin, kMax}));
  p.push_back(tri({kMin, 20.5f}, {kMax, 0.5f}, {kMax, kMax}));
  return s;
}

// Snapping ties: coordinates exactly half-way between two subpixels (odd multiples of 1/512),
// which round half to even, so some land on pixel centres and some just miss them.
Scene snap_ties() {
  Scene s = make_scene(16, 8);
  auto& p = s.primitives;
  constexpr float kHalfSub = 1.0f / 512.0f;
  // x = 2.5 + 1/512: raw 640.5 -> 640 (even): the left edge runs through the centres x = 2.5.
  p.push_back(tri({2.5f + kHalfSub, 0.5f}, {3.5f, 0.5f}, {2.5f + kHalfSub, 7.5f}));
  // x = 5.5 + 3/512: raw 1409.5 -> 1410 (even) = 5.5078125: just right of the centres x = 5.5.
  p.push_back(tri({5.5f + 3 * kHalfSub, 0.5f}, {6.5f, 0.5f}, {5.5f + 3 * kHalfSub, 7.5f}));
  // Right edge: x = 9.5 - 1/512: raw 2431.5 -> 2432 (even) = 9.5: on the centres, excluded.
  p.push_back(tri({8.5f, 0.5f}, {9.5f - kHalfSub, 0.5f}, {9.5f - kHalfSub, 7.5f}));
  // Top edge: y = 2.5 - 1/512 -> 2.5 (raw 639.5 -> 640); bottom y = 5.5 + 1/512 -> 5.5.
  p.push_back(tri({10.5f, 2.5f - kHalfSub}, {15.5f, 2.5f - kHalfSub}, {15.5f, 5.5f + kHalfSub}));
  // Near zero: -1/512 snaps to 0 (raw -0.5 -> 0), 1/512 to 0 as well.
  p.push_back(
      tri({-kHalfSub, -kHalfSub}, {1.5f + kHalfSub, kHalfSub}, {kHalfSub, 1.5f - kHalfSub}));
  return s;
}

Primitive point(Point c) {
  Primitive p;
  p.type = PrimitiveType::kPoint;
  p.v = {c};
  return p;
}

Primitive line(Point a, Point b, bool aa = false) {
  Primitive p;
  p.type = PrimitiveType::kLine;
  p.v = {a, b};
  p.aa = aa;
  return p;
}

Primitive strip(std::vector<Point> v, bool aa = false) {
  Primitive p;
  p.type = PrimitiveType::kLineStrip;
  p.v = std::move(v);
  p.aa = aa;
  return p;
}

// Points on every kind of tie: centred on a pixel centre, on a pixel corner, on the middle of
// a vertical and of a horizontal pixel edge (their squares' sides run through centres), one
// subpixel off a centre, at the target's corner (the square holds no centre of the target),
// and at an arbitrary position.
// rule: SCENE.PRIM.POINT
Scene points(FillConvention fill) {
  RasterState state;
  state.fill = fill;
  state.cull = CullMode::kBack; // points are never culled
  Scene s = make_scene(16, 6, state);
  auto& p = s.primitives;
  p.push_back(point({1.5f, 1.5f})); // on a centre: exactly that pixel
  p.push_back(point({4.0f, 2.0f})); // on a corner: square sides through 4 centres
  p.push_back(point({7.0f, 1.5f})); // on a vertical edge: left/right sides through centres
  p.push_back(point({9.5f, 3.0f})); // on a horizontal edge: top/bottom sides through centres
  p.push_back(point({12.5f + 1.0f / 256.0f, 1.5f})); // one subpixel right of a centre
  p.push_back(point({0.0f, 0.0f}));                  // at the target's corner
  p.push_back(point({13.3f, 4.7f}));                 // anywhere
  p.push_back(point({15.5f, 5.5f}));                 // the last pixel
  return s;
}

// Aliased lines through diamond corners and along diamond edges: along a row of centres (left
// and right corners), along a pixel row boundary (top and bottom corners), along diamond edges
// at exactly 45 degrees both ways, a vertical line through centres (y-major), endpoints on
// centres and on corners, a zero-length line, and a line drawn in both directions.
// rule: SCENE.PRIM.LINE, SCENE.LINE_MODE
Scene lines(LineMode mode) {
  Scene s = make_scene(16, 12);
  s.conventions.line_mode = mode;
  auto& p = s.primitives;
  p.push_back(line({0.5f, 0.5f}, {7.5f, 0.5f}));   // along centres: end on a centre
  p.push_back(line({0.0f, 2.0f}, {7.0f, 2.0f}));   // along top/bottom corners of the diamonds
  p.push_back(line({0.5f, 3.0f}, {5.5f, 8.0f}));   // 45 degrees along diamond edges
  p.push_back(line({7.5f, 8.0f}, {12.5f, 3.0f}));  // 45 degrees, the other way
  p.push_back(line({14.5f, 0.5f}, {14.5f, 6.5f})); // vertical through centres (y-major)
  p.push_back(line({9.0f, 1.0f}, {13.0f, 2.0f}));  // corner to corner
  p.push_back(line({3.5f, 10.5f}, {3.5f, 10.5f})); // zero length
  p.push_back(line({6.2f, 9.7f}, {13.8f, 11.1f})); // shallow, arbitrary
  p.push_back(line({13.8f, 10.1f}, {6.2f, 8.7f})); // the same shape drawn right to left
  return s;
}

// A line strip whose third segment runs back over the first: pixels drawn by two segments
// appear once per segment (seg 0 and seg 2), as independent lines would draw them.
// rule: SCENE.PRIM.LINE_STRIP
Scene line_strip_scene() {
  Scene s = make_scene(16, 8);
  auto& p = s.primitives;
  p.push_back(strip({{1.5f, 1.5f}, {9.5f, 1.5f}, {9.5f, 5.5f}, {3.5f, 1.5f}, {3.2f, 6.8f}}));
  p.push_back(line({1.5f, 1.5f}, {9.5f, 1.5f})); // segment 0 as an independent line
  return s;
}

// Antialiased lines (the D3D reference algorithm): horizontal on a row of centres and between
// rows, 45 degrees, steep, short, and a strip.
// rule: SCENE.PRIM.LINE, SCENE.OUTPUT.COVERAGE
Scene aa_lines() {
  Scene s = make_scene(16, 12);
  auto& p = s.primitives;
  p.push_back(line({1.0f, 1.5f}, {9.0f, 1.5f}, true));
  p.push_back(line({1.0f, 3.0f}, {9.0f, 3.0f}, true));
  p.push_back(line({1.5f, 5.5f}, {6.5f, 10.5f}, true));
  p.push_back(line({12.25f, 0.5f}, {13.75f, 10.5f}, true));
  p.push_back(line({10.5f, 5.5f}, {10.75f, 5.5f}, true));
  p.push_back(strip({{7.5f, 6.5f}, {10.5f, 9.5f}, {14.5f, 8.5f}}, true));
  return s;
}

// Quadrilateral lines, 1.4 px (D3D with multisampling) or 1.0 px (Vulkan strict lines):
// horizontal and vertical through centres, 45 degrees, arbitrary, and zero length.
// rule: SCENE.LINE_MODE
Scene quad_lines(LineMode mode) {
  Scene s = make_scene(16, 12);
  s.conventions.line_mode = mode;
  s.cull = CullMode::kFront; // quadrilateral lines are never culled
  auto& p = s.primitives;
  p.push_back(line({0.5f, 1.5f}, {7.5f, 1.5f}));
  p.push_back(line({1.0f, 4.0f}, {7.0f, 4.0f}));
  p.push_back(line({10.5f, 0.5f}, {10.5f, 6.5f}));
  p.push_back(line({1.0f, 6.0f}, {6.0f, 11.0f}));
  p.push_back(line({8.3f, 10.6f}, {15.2f, 7.1f}));
  p.push_back(line({13.5f, 2.5f}, {13.5f, 2.5f}));
  p.push_back(strip({{12.0f, 4.0f}, {15.0f, 4.0f}, {12.0f, 6.0f}}));
  return s;
}

// Multisampling (SCENE.MSAA). Sample k of pixel (i, j) under the 4x standard pattern sits at
// (i, j) + (0.5, 0.5) + o_k / 16 with o = (-2,-6), (6,-2), (-6,2), (2,6): for example sample 0 at
// (i + 0.375, j + 0.125) and sample 1 at (i + 0.875, j + 0.375).

Primitive coloured(Primitive p, Rgba8 c) {
  p.color = c;
  return p;
}

Scene msaa_scene(std::int32_t w, std::int32_t h, SamplePattern pattern) {
  Scene s = make_scene(w, h);
  set_sample_pattern(s, std::move(pattern));
  s.clear_color = {0, 0, 0, 255};
  return s;
}

// 4x: edges through samples. Three triangles share edges: a horizontal top edge through
// sample 0 of every pixel of row 1 (y = 1.125), a diagonal shared edge from sample 0 of pixel
// (1, 1) to sample 0 of pixel (5, 5) through sample 0 of (2, 2), (3, 3), (4, 4), and a vertical
// edge through sample 1 of column 7 (x = 7.875); vertices on samples. Each tied sample goes to
// exactly one of the triangles sharing the edge (top-left rule per sample).
// rule: MSAA.COVER.SAMPLE, MSAA.PATTERN.STANDARD
Scene msaa_ties() {
  Scene s = msaa_scene(10, 8, standard_pattern(4));
  auto& p = s.primitives;
  const Point a{1.375f, 1.125f}, b{7.875f, 1.125f}, c{5.375f, 5.125f}, d{1.375f, 7.125f},
      e{7.875f, 7.375f};
  p.push_back(coloured(tri(a, b, c), {230, 60, 40, 255}));
  p.push_back(coloured(tri(a, c, d), {40, 160, 60, 255}));
  p.push_back(coloured(tri(b, e, c), {40, 90, 220, 255}));
  p.push_back(coloured(tri(c, e, d), {230, 200, 40, 255})); // closes the fan at sample 0 of (5, 5)
  return s;
}

// 8x and 16x: a small fan around a pixel centre with a point and a sliver.
// rule: MSAA.COVER.SAMPLE, MSAA.POINT.PER_SAMPLE, MSAA.RESOLVE.AVERAGE
Scene msaa_fan(std::uint32_t samples) {
  Scene s = msaa_scene(10, 8, standard_pattern(samples));
  auto& p = s.primitives;
  const Point c{4.5f, 3.5f};
  p.push_back(coloured(tri(c, {1.0f, 0.5f}, {8.25f, 1.0f}), {220, 50, 50, 255}));
  p.push_back(coloured(tri(c, {8.25f, 1.0f}, {6.5f, 7.5f}), {50, 180, 70, 255}));
  p.push_back(coloured(tri(c, {6.5f, 7.5f}, {1.0f, 0.5f}), {60, 80, 220, 255}));
  p.push_back(coloured(point({8.5f, 5.5f}), {250, 220, 40, 255}));
  p.push_back(coloured(tri({0.25f, 6.0f}, {5.0f, 6.4375f}, {0.25f, 6.125f}), {200, 80, 200, 255}));
  return s;
}

// The centre pattern: 4 samples at the pixel centre; every pixel is all or nothing, like one
// sample, and a Vulkan Bresenham line covers every sample of its pixels.
// rule: MSAA.PATTERN.CENTER, MSAA.LINE.MODE
Scene msaa_center() {
  Scene s = msaa_scene(10, 8, center_pattern(4));
  s.conventions.line_mode = LineMode::kVulkanBresenham;
  auto& p = s.primitives;
  p.push_back(coloured(tri({0.5f, 0.5f}, {6.5f, 0.5f}, {0.5f, 6.5f}), {220, 60, 40, 255}));
  p.push_back(coloured(tri({6.5f, 0.5f}, {6.5f, 6.5f}, {0.5f, 6.5f}), {40, 150, 220, 255}));
  p.push_back(coloured(point({8.0f, 2.0f}), {250, 220, 40, 255}));
  p.push_back(coloured(line({7.2f, 4.3f}, {9.8f, 7.6f}), {255, 255, 255, 255}));
  return s;
}

// A custom pattern on the grid's extremes, with a repeated position: (-8,-8) is the pixel's
// top-left corner (reachable), (7, 7) the last grid point before the bottom-right corner.
// rule: MSAA.PATTERN.CUSTOM, MSAA.PATTERN.GRID
Scene msaa_custom() {
  Scene s = msaa_scene(8, 6, custom_pattern({{-8, -8}, {7, -8}, {-8, 7}, {7, 7}, {0, 0}, {0, 0}}));
  auto& p = s.primitives;
  p.push_back(coloured(tri({1.0f, 1.0f}, {7.0f, 1.0f}, {1.0f, 5.0f}), {220, 60, 40, 255}));
  p.push_back(coloured(tri({7.0f, 1.0f}, {7.0f, 5.0f}, {1.0f, 5.0f}), {40, 150, 220, 255}));
  p.push_back(coloured(point({3.5f, 3.0f}), {250, 220, 40, 255}));
  return s;
}

// Centroids: partially covered pixels along slanted edges, a sample mask that removes sample 1
// and helper lanes (which have no covered sample), under the D3D11 or the D3D10 rule, with
// fine derivatives of the evaluation point.
// rule: MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10, MSAA.MASK.AND, MSAA.DERIV.FINE
Scene msaa_centroid(CentroidRule rule) {
  Scene s = msaa_scene(10, 8, standard_pattern(4));
  s.msaa.has_centroid = true;
  s.conventions.centroid = rule;
  s.msaa.sample_mask = 0b1101;
  s.msaa.derivatives = DerivativeMode::kFine;
  auto& p = s.primitives;
  p.push_back(coloured(tri({0.8f, 0.3f}, {9.3f, 2.1f}, {2.2f, 7.6f}), {220, 60, 40, 255}));
  p.push_back(coloured(tri({9.7f, 3.4f}, {9.6f, 7.8f}, {5.1f, 7.7f}), {40, 150, 220, 255}));
  return s;
}

// Sample-frequency shading: one fragment per covered sample in the mask, quads per sample index
// with helper lanes, coarse derivatives; lines drawn as 1.4 px quadrilaterals (MSAA.LINE.MODE).
// rule: MSAA.SHADING.SAMPLE, MSAA.QUAD.HELPER, MSAA.DERIV.COARSE, MSAA.LINE.MODE
Scene msaa_sample_shading() {
  Scene s = msaa_scene(8, 6, standard_pattern(4));
  s.msaa.shading = ShadingRate::kSample;
  s.msaa.quads = true;
  s.msaa.derivatives = DerivativeMode::kCoarse;
  auto& p = s.primitives;
  p.push_back(coloured(tri({0.6f, 0.4f}, {5.3f, 1.2f}, {1.4f, 4.7f}), {220, 60, 40, 255}));
  p.push_back(coloured(line({4.0f, 4.5f}, {7.5f, 2.0f}), {40, 150, 220, 255}));
  return s;
}

// Resolve: half-transparent colours over an opaque clear colour; overlapping primitives, an
// edge shared through samples, antialiased and aliased D3D lines (1.4 px quadrilaterals under
// multisampling, not antialiased), and a point.
// rule: MSAA.RESOLVE.AVERAGE, MSAA.LINE.MODE
Scene msaa_resolve() {
  Scene s = msaa_scene(12, 8, standard_pattern(4));
  s.clear_color = {16, 32, 48, 255};
  auto& p = s.primitives;
  p.push_back(coloured(tri({0.5f, 0.5f}, {8.3f, 1.7f}, {2.2f, 7.4f}), {255, 0, 0, 128}));
  p.push_back(coloured(tri({3.1f, 2.2f}, {11.6f, 3.3f}, {6.4f, 7.9f}), {0, 255, 0, 255}));
  p.push_back(coloured(line({0.5f, 7.5f}, {11.5f, 4.25f}, true), {255, 255, 255, 255}));
  p.push_back(coloured(line({9.0f, 0.5f}, {11.5f, 2.0f}), {0, 0, 255, 200}));
  p.push_back(coloured(point({10.5f, 6.5f}), {255, 255, 0, 255}));
  return s;
}

// A path of the given contours: each a start and commands "L x y", "Q cx cy x y" or
// "C c1x c1y c2x c2y x y" as number lists (2, 4 or 6 numbers).
Primitive path_of(path::FillRule rule, path::Coverage coverage,
                  std::initializer_list<std::initializer_list<std::initializer_list<float>>> cs) {
  FloatPath fp;
  fp.fill_rule = rule;
  fp.coverage = coverage;
  for (const auto& c : cs) {
    FloatContour contour;
    bool first = true;
    for (const auto& cmd : c) {
      const std::vector<float> v(cmd);
      if (first) {
        contour.start = {v[0], v[1]};
        first = false;
        continue;
      }
      FloatPathSegment seg;
      seg.kind = v.size() == 2   ? path::SegmentKind::kLine
                 : v.size() == 4 ? path::SegmentKind::kQuadratic
                                 : path::SegmentKind::kCubic;
      for (std::size_t k = 0; k * 2 < v.size(); ++k)
        seg.p[k] = {v[2 * k], v[2 * k + 1]};
      contour.segments.push_back(seg);
    }
    fp.contours.push_back(std::move(contour));
  }
  return make_path(std::move(fp));
}

// The conflation cases of 2D rasterizers, at area coverage: a square drawn twice inside its
// pixels under even-odd (exactly empty, where signed-area accumulation shows a 2x area), a
// doubled-back diagonal (no gap), a pentagram (its centre has winding 2: hole under even-odd,
// filled under nonzero), and a square with a hole of the same orientation (nonzero fills it).
// rule: SCENE.PRIM.PATH, PATH.AREA.EXACT, PATH.FILL.RULE
Scene path_conflation() {
  using path::Coverage;
  using path::FillRule;
  Scene s = make_scene(16, 8);
  auto& p = s.primitives;
  p.push_back(path_of(FillRule::kEvenOdd, Coverage::kArea,
                      {{{1.25f, 1.25f}, {3.75f, 1.25f}, {3.75f, 3.75f}, {1.25f, 3.75f}},
                       {{1.25f, 1.25f}, {3.75f, 1.25f}, {3.75f, 3.75f}, {1.25f, 3.75f}}}));
  p.push_back(path_of(
      FillRule::kNonZero, Coverage::kArea,
      {{{1.0f, 4.5f}, {4.5f, 7.5f}, {1.0f, 7.5f}}, {{1.0f, 4.5f}, {4.5f, 4.5f}, {4.5f, 7.5f}}}));
  const auto star = [](float cx, float cy, float r) {
    std::vector<float> v;
    for (int k = 0; k < 5; ++k) {
      const double a = -1.5707963267948966 + 4.0 * 3.141592653589793 * k / 5.0;
      v.push_back(static_cast<float>(cx + r * std::cos(a)));
      v.push_back(static_cast<float>(cy + r * std::sin(a)));
    }
    return v;
  };
  for (const auto& [cx, rule] :
       {std::pair{7.5f, FillRule::kEvenOdd}, std::pair{11.5f, FillRule::kNonZero}}) {
    const std::vector<float> v = star(cx, 3.5f, 3.2f);
    p.push_back(path_of(rule, Coverage::kArea,
                        {{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}, {v[8], v[9]}}}));
  }
  p.push_back(path_of(FillRule::kNonZero, Coverage::kArea,
                      {{{13.0f, 0.5f}, {15.5f, 0.5f}, {15.5f, 7.5f}, {13.0f, 7.5f}},
                       {{13.75f, 2.0f}, {14.75f, 2.0f}, {14.75f, 6.0f}, {13.75f, 6.0f}}}));
  return s;
}

// Curves decided exactly per sample at 4x: a quadratic bulge, a cubic with a loop (its loop
// has winding 2: filled under nonzero, a hole under even-odd), a cusp, and curves through
// sample positions.
// rule: SCENE.PRIM.PATH, PATH.CURVE.SAMPLE, PATH.COVER.SAMPLE
Scene path_curves() {
  using path::Coverage;
  using path::FillRule;
  Scene s = make_scene(16, 8);
  set_sample_pattern(s, standard_pattern(4));
  auto& p = s.primitives;
  p.push_back(
      path_of(FillRule::kNonZero, Coverage::kSamples, {{{0.5f, 7.5f}, {2.5f, -2.0f, 4.5f, 7.5f}}}));
  for (const auto& [x0, rule] :
       {std::pair{5.0f, FillRule::kNonZero}, std::pair{10.0f, FillRule::kEvenOdd}}) {
    p.push_back(path_of(rule, Coverage::kSamples,
                        {{{x0, 6.5f}, {x0 + 9.0f, 0.0f, x0 - 4.0f, 0.0f, x0 + 5.0f, 6.5f}}}));
  }
  p.push_back(path_of(FillRule::kNonZero, Coverage::kSamples,
                      {{{11.0f, 7.75f}, {15.5f, 4.0f, 11.0f, 4.0f, 15.5f, 7.75f}}}));
  return s;
}

} // namespace

std::vector<ShowcaseScene> showcase_scenes() {
  std::vector<ShowcaseScene> out;
  out.push_back({"d3d-diagram", "the cases of the D3D11.3 triangle diagram", d3d_diagram()});
  out.push_back({"fan", "16 triangles around a pixel centre, all edges through centres", fan()});
  out.push_back(
      {"jittered-grid", "96-triangle mesh, jittered vertices, mixed windings", jittered_grid()});
  out.push_back({"ties-top-left", "edge ties of every kind, fill top-left (D3D)",
                 ties(FillConvention::kTopLeft)});
  out.push_back({"ties-top-right", "the same, fill top-right", ties(FillConvention::kTopRight)});
  out.push_back({"ties-bottom-left", "the same, fill bottom-left (GL read top-down)",
                 ties(FillConvention::kBottomLeft)});
  out.push_back(
      {"ties-bottom-right", "the same, fill bottom-right", ties(FillConvention::kBottomRight)});
  out.push_back({"cull-back", "cull back, front face cw, windings decided after snapping",
                 culling(CullMode::kBack, FrontFace::kClockwise)});
  out.push_back({"cull-front-ccw", "cull front, front face ccw",
                 culling(CullMode::kFront, FrontFace::kCounterClockwise)});
  out.push_back(
      {"slivers", "slivers one subpixel wide on rows, columns and diagonals; needles", slivers()});
  out.push_back({"huge", "triangles at the ends of the coordinate range", huge()});
  out.push_back(
      {"snap-ties", "coordinates half-way between subpixels (round half to even)", snap_ties()});
  out.push_back({"points", "points on centres, corners and edge midpoints, fill top-left",
                 points(FillConvention::kTopLeft)});
  out.push_back({"points-bottom-right", "the same points, fill bottom-right",
                 points(FillConvention::kBottomRight)});
  out.push_back({"lines-d3d", "aliased lines through diamond corners and along edges (D3D)",
                 lines(LineMode::kD3DDiamond)});
  out.push_back(
      {"lines-vulkan", "the same lines, Vulkan Bresenham", lines(LineMode::kVulkanBresenham)});
  out.push_back({"line-strip", "a strip running back over itself: one fragment per segment",
                 line_strip_scene()});
  out.push_back(
      {"lines-aa", "antialiased lines: coverage of the D3D reference algorithm", aa_lines()});
  out.push_back({"quad-lines-1.4", "quadrilateral lines 1.4 px wide (D3D multisampling)",
                 quad_lines(LineMode::kQuadWide)});
  out.push_back({"quad-lines-1.0", "quadrilateral lines 1.0 px wide (Vulkan strict)",
                 quad_lines(LineMode::kQuadNarrow)});
  out.push_back(
      {"msaa-4x-ties", "4x: shared edges through sample points, vertices on samples", msaa_ties()});
  out.push_back({"msaa-8x", "8x standard pattern: a fan, a point and a sliver", msaa_fan(8)});
  out.push_back({"msaa-16x", "the same at 16x", msaa_fan(16)});
  out.push_back(
      {"msaa-center-4x", "4 samples at the centre: all or nothing per pixel", msaa_center()});
  out.push_back({"msaa-custom", "a custom pattern on the grid's extremes, one position twice",
                 msaa_custom()});
  out.push_back({"msaa-centroid-d3d11", "centroids (D3D11 rule), sample mask 0b1101, fine ddx/ddy",
                 msaa_centroid(CentroidRule::kD3D11)});
  out.push_back({"msaa-centroid-d3d10", "the same under the D3D10 reference rule",
                 msaa_centroid(CentroidRule::kD3D10)});
  out.push_back({"msaa-sample-shading", "sample shading, quads per sample, coarse ddx/ddy",
                 msaa_sample_shading()});
  out.push_back(
      {"msaa-resolve", "colours over a clear colour, resolved by averaging", msaa_resolve()});
  out.push_back({"paths-conflation",
                 "2D paths, exact areas: a square drawn twice under even-odd, a doubled-back "
                 "diagonal, pentagrams, a hole",
                 path_conflation()});
  out.push_back(
      {"paths-curves", "curves decided per sample at 4x: a bulge, loops, a cusp", path_curves()});
  return out;
}

} // namespace rastrules::cli
