// SPDX-License-Identifier: MIT
// Oracle aliased lines: the LINE.D3D.* and LINE.VK.* rules decided the way spec/rules/line.md
// words them, with CGAL's exact kernel over GMP rationals. The closed segment is intersected
// with the closed diamond (as two closed triangles, CGAL::intersection); the part found is
// then classified point by point (interior, which edge, which corner) against the tables of
// included edges and corners. Vulkan's perturbation uses the exact rational e = 2^-100 raw.
// No kernel code, no kernel formula (no half-plane system, no Fourier-Motzkin, no
// lexicographic epsilon).
// Implements (as oracle): LINE.MAJOR.AXIS, LINE.D3D.TEST_AREA, LINE.D3D.EXIT,
//   LINE.VK.TEST_AREA, LINE.VK.EXIT, LINE.ZERO_LENGTH, LINE.TARGET.CLIP

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/intersections.h>

#include "rastrules/oracle/line.hpp"

namespace rastrules::oracle {
namespace {

using Q = CGAL::Gmpq;
using K = CGAL::Simple_cartesian<Q>;
using Point = K::Point_2;
using Segment = K::Segment_2;
using Triangle = K::Triangle_2;

const Q kHalf(128); // h: half a diamond diagonal, 1/2 px in raw units

// The Vulkan perturbation e = 2^-100 raw. Small enough: the answer of "does the perturbed
// segment meet the open diamond / does the perturbed end lie in it" changes with e only where
// an end point crosses an edge line (a polynomial in e with integer coefficients below 2^27) or
// the segment's line crosses a corner (a quadratic in e with integer coefficients below 2^52);
// a nonzero integer polynomial of that size has no root in (0, 2^-53), so every e in (0, 2^-53]
// gives the same answers as an infinitesimal one.
Q vulkan_e() {
  Q e(1);
  for (int i = 0; i < 100; ++i)
    e /= Q(2);
  return e;
}

// The features of a diamond, by the words of LINE.DIAMOND.GEOMETRY.
enum class Where {
  kOutside,
  kInterior,
  kEdgeLowerLeft,
  kEdgeLowerRight,
  kEdgeUpperLeft,
  kEdgeUpperRight,
  kCornerBottom,
  kCornerTop,
  kCornerLeft,
  kCornerRight,
};

// Returns where p lies relative to the closed diamond |x - cx| + |y - cy| <= h (y down).
Where locate(const Point& p, const Point& c) {
  const Q u = p.x() - c.x(), v = p.y() - c.y();
  const Q au = u < 0 ? -u : u, av = v < 0 ? -v : v;
  const Q l1 = au + av;
  if (l1 > kHalf)
    return Where::kOutside;
  if (l1 < kHalf)
    return Where::kInterior;
  if (u == 0)
    return v > 0 ? Where::kCornerBottom : Where::kCornerTop;
  if (v == 0)
    return u > 0 ? Where::kCornerRight : Where::kCornerLeft;
  if (v > 0)
    return u < 0 ? Where::kEdgeLowerLeft : Where::kEdgeLowerRight;
  return u < 0 ? Where::kEdgeUpperLeft : Where::kEdgeUpperRight;
}

// LINE.D3D.TEST_AREA: the interior; the lower-left and lower-right edges; the bottom corner;
// for y-major lines also the right corner. Never the upper edges nor the top or left corners
// (nor the right corner of x-major lines).
// rule: LINE.D3D.TEST_AREA
bool d3d_included(Where w, bool x_major) {
  switch (w) {
  case Where::kInterior:
  case Where::kEdgeLowerLeft:
  case Where::kEdgeLowerRight:
  case Where::kCornerBottom:
    return true;
  case Where::kCornerRight:
    return !x_major;
  default:
    return false;
  }
}

// Returns the part of the closed segment s (or the point s when degenerate) inside the closed
// diamond centred at c, as its two end points (equal for a single point), or nothing.
std::optional<std::array<Point, 2>> clip_to_closed_diamond(const Point& a, const Point& b,
                                                           const Point& c) {
  if (a == b) {
    if (locate(a, c) == Where::kOutside)
      return std::nullopt;
    return std::array<Point, 2>{a, a};
  }
  const Point left(c.x() - kHalf, c.y()), right(c.x() + kHalf, c.y());
  const Point top(c.x(), c.y() - kHalf), bottom(c.x(), c.y() + kHalf);
  // The closed diamond is the union of two closed triangles sharing its horizontal diagonal.
  const std::array<Triangle, 2> halves = {Triangle(left, top, right),
                                          Triangle(left, right, bottom)};
  const Segment s(a, b);
  std::vector<Point> pts;
  for (const Triangle& t : halves) {
    const auto x = CGAL::intersection(s, t);
    if (!x)
      continue;
    if (const Point* p = boost::get<Point>(&*x)) {
      pts.push_back(*p);
    } else if (const Segment* q = boost::get<Segment>(&*x)) {
      pts.push_back(q->source());
      pts.push_back(q->target());
    }
  }
  if (pts.empty())
    return std::nullopt;
  // All points lie on s; the union of the pieces is convex (s meets a convex set), so it is
  // the span of the extreme points along s.
  const Q dx = b.x() - a.x(), dy = b.y() - a.y();
  auto along = [&](const Point& p) { return (p.x() - a.x()) * dx + (p.y() - a.y()) * dy; };
  const auto [mn, mx] = std::minmax_element(
      pts.begin(), pts.end(), [&](const Point& p, const Point& q) { return along(p) < along(q); });
  return std::array<Point, 2>{*mn, *mx};
}

Point midpoint(const Point& p, const Point& q) {
  return Point((p.x() + q.x()) / Q(2), (p.y() + q.y()) / Q(2));
}

// Whether the segment a -> b meets the set of included features: the part P of the segment in
// the closed diamond is a point or a segment. If P has a point strictly inside, its midpoint is
// one; otherwise P lies on one closed edge and its points are its two ends (edge or corner) and
// its relative interior (one open edge), represented by the midpoint.
template <class Included>
bool meets(const Point& a, const Point& b, const Point& c, Included included) {
  const auto part = clip_to_closed_diamond(a, b, c);
  if (!part)
    return false;
  const auto& [p, q] = *part;
  return included(locate(p, c)) || included(locate(q, c)) || included(locate(midpoint(p, q), c));
}

Point to_point(const LineRaw& r) {
  return Point(Q(r[0]), Q(r[1]));
}

} // namespace

bool aliased_line_covers(const LineRaw& ra, const LineRaw& rb, const std::string& mode,
                         std::int64_t px, std::int64_t py) {
  const Point c(Q(px * 256 + 128), Q(py * 256 + 128));
  const Point a = to_point(ra), b = to_point(rb);
  // rule: LINE.ZERO_LENGTH
  if (a == b)
    return false;
  if (mode == "d3d") {
    // rule: LINE.MAJOR.AXIS
    const Q dx = b.x() - a.x(), dy = b.y() - a.y();
    const bool x_major = dx != 0 && dy / dx >= Q(-1) && dy / dx <= Q(1);
    // rule: LINE.D3D.EXIT
    const auto inc = [&](Where w) { return d3d_included(w, x_major); };
    return meets(a, b, c, inc) && !inc(locate(b, c));
  }
  if (mode == "vulkan-bresenham") {
    // rule: LINE.VK.TEST_AREA, LINE.VK.EXIT
    const Q e = vulkan_e();
    const Point ae(a.x() - e, a.y() - e * e), be(b.x() - e, b.y() - e * e);
    const auto open = [](Where w) { return w == Where::kInterior; };
    return meets(ae, be, c, open) && !open(locate(be, c));
  }
  throw std::invalid_argument("oracle: unknown aliased line mode '" + mode + "'");
}

// rule: LINE.TARGET.CLIP
std::vector<std::array<std::int32_t, 2>> aliased_line_pixels(const LineRaw& a, const LineRaw& b,
                                                             const std::string& mode,
                                                             std::int32_t w, std::int32_t h) {
  auto floor256 = [](std::int64_t v) { return v >= 0 ? v / 256 : -((-v + 255) / 256); };
  const std::int64_t x0 = std::max<std::int64_t>(floor256(std::min(a[0], b[0])) - 2, 0);
  const std::int64_t x1 = std::min<std::int64_t>(floor256(std::max(a[0], b[0])) + 2, w - 1);
  const std::int64_t y0 = std::max<std::int64_t>(floor256(std::min(a[1], b[1])) - 2, 0);
  const std::int64_t y1 = std::min<std::int64_t>(floor256(std::max(a[1], b[1])) + 2, h - 1);
  std::vector<std::array<std::int32_t, 2>> out;
  for (std::int64_t y = y0; y <= y1; ++y) {
    for (std::int64_t x = x0; x <= x1; ++x) {
      if (aliased_line_covers(a, b, mode, x, y)) {
        out.push_back({static_cast<std::int32_t>(x), static_cast<std::int32_t>(y)});
      }
    }
  }
  return out;
}

} // namespace rastrules::oracle
