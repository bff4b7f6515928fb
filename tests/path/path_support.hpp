// SPDX-License-Identifier: MIT
// Paths written in pixels for the PATH.* examples, and brute-force views of the kernel's
// answers (every sample through covers_sample) to compare its row walks against.

#pragma once

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include "rastrules/path.hpp"

namespace rastrules::test {

// Returns the raw 16.8 point of (x, y) px; x * 256 and y * 256 must be integers.
inline path::Point pt(double x, double y) {
  const double rx = x * 256.0, ry = y * 256.0;
  if (rx != std::floor(rx) || ry != std::floor(ry))
    throw std::invalid_argument("pt: not on the 16.8 grid");
  return path::Point{static_cast<std::int32_t>(rx), static_cast<std::int32_t>(ry)};
}

// A contour of straight lines through the points (pixels), closed by PATH.CONTOUR.CLOSE.
inline path::Contour polygon(std::initializer_list<std::pair<double, double>> pts) {
  path::Contour c;
  bool first = true;
  for (const auto& [x, y] : pts) {
    if (first) {
      c.start = pt(x, y);
      first = false;
    } else {
      c.segments.push_back(path::Segment{path::SegmentKind::kLine, {pt(x, y), {}, {}}});
    }
  }
  return c;
}

// Segments to (x, y) px, through control points in px.
inline path::Segment line_to(double x, double y) {
  return {path::SegmentKind::kLine, {pt(x, y), {}, {}}};
}
inline path::Segment quad_to(double cx, double cy, double x, double y) {
  return {path::SegmentKind::kQuadratic, {pt(cx, cy), pt(x, y), {}}};
}
inline path::Segment cubic_to(double c1x, double c1y, double c2x, double c2y, double x, double y) {
  return {path::SegmentKind::kCubic, {pt(c1x, c1y), pt(c2x, c2y), pt(x, y)}};
}

// A contour from (x, y) px through the segments, closed by PATH.CONTOUR.CLOSE.
inline path::Contour contour(double x, double y, std::vector<path::Segment> segments) {
  path::Contour c;
  c.start = pt(x, y);
  c.segments = std::move(segments);
  return c;
}

// A contour of straight lines through raw 16.8 points, closed by PATH.CONTOUR.CLOSE.
inline path::Contour raw_polygon(std::initializer_list<path::Point> pts) {
  path::Contour c;
  c.start = *pts.begin();
  for (auto it = pts.begin() + 1; it != pts.end(); ++it)
    c.segments.push_back(path::Segment{path::SegmentKind::kLine, {*it, {}, {}}});
  return c;
}

// The ends of the coordinate range of PATH.GEOMETRY, raw.
inline constexpr std::int32_t kRangeLo = -(std::int32_t{1} << 23);
inline constexpr std::int32_t kRangeHi = std::int32_t{1} << 23;

// Returns the triangle (lo, lo) (hi, hi) (lo, hi) at the ends of the range: below the
// diagonal y = x, whose edge passes through every pixel centre (x, x).
inline path::Path range_triangle(path::FillRule rule) {
  return path::Path{
      rule, {raw_polygon({{kRangeLo, kRangeLo}, {kRangeHi, kRangeHi}, {kRangeLo, kRangeHi}})}};
}

// Returns the contour traversed the other way round (lines only).
inline path::Contour reversed(const path::Contour& c) {
  std::vector<path::Point> pts{c.start};
  for (const path::Segment& s : c.segments)
    pts.push_back(s.p[0]);
  path::Contour r;
  r.start = pts.back();
  for (std::size_t k = pts.size() - 1; k-- > 0;)
    r.segments.push_back(path::Segment{path::SegmentKind::kLine, {pts[k], {}, {}}});
  return r;
}

inline path::Path make_path(path::FillRule rule, std::vector<path::Contour> contours) {
  return path::Path{rule, std::move(contours)};
}

// Returns the masks of every pixel of the target computed sample by sample with covers_sample
// (no row walk), keyed by (y, x); pixels with mask 0 are absent.
inline std::map<std::pair<std::int32_t, std::int32_t>, std::uint32_t>
brute_masks(const path::Path& p, const SamplePattern& pattern, FillConvention fill, std::int32_t w,
            std::int32_t h) {
  std::map<std::pair<std::int32_t, std::int32_t>, std::uint32_t> m;
  for (std::int32_t y = 0; y < h; ++y)
    for (std::int32_t x = 0; x < w; ++x) {
      std::uint32_t mask = 0;
      for (std::size_t k = 0; k < pattern.positions.size(); ++k) {
        const Vec2 s = sample_position(x, y, pattern.positions[k]);
        if (path::covers_sample(p, path::Point{s.x.raw(), s.y.raw()}, fill))
          mask |= std::uint32_t{1} << k;
      }
      if (mask != 0)
        m[{y, x}] = mask;
    }
  return m;
}

inline std::map<std::pair<std::int32_t, std::int32_t>, std::uint32_t>
as_map(const std::vector<path::SampleCoverage>& v) {
  std::map<std::pair<std::int32_t, std::int32_t>, std::uint32_t> m;
  for (const path::SampleCoverage& c : v)
    m[{c.y, c.x}] = c.mask;
  return m;
}

inline std::map<std::pair<std::int32_t, std::int32_t>, boost::multiprecision::cpp_rational>
area_map(const std::vector<path::AreaCoverage>& v) {
  std::map<std::pair<std::int32_t, std::int32_t>, boost::multiprecision::cpp_rational> m;
  for (const path::AreaCoverage& c : v)
    m[{c.y, c.x}] = c.area;
  return m;
}

} // namespace rastrules::test
