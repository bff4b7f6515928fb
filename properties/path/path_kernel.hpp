// SPDX-License-Identifier: MIT
// The generators' description of a path (path_gen.hpp) as the kernel's rastrules::path::Path.

#pragma once

#include <cstddef>
#include <cstdint>

#include "path_gen.hpp"
#include "rastrules/path_types.hpp"

namespace rastrules::path_kernel {

namespace pg = rastrules::path_gen;
namespace kp = rastrules::path;

inline kp::Point kpoint(const pg::Raw2& r) {
  return kp::Point{static_cast<std::int32_t>(r[0]), static_cast<std::int32_t>(r[1])};
}

inline kp::Path to_kernel(const pg::GPath& g) {
  kp::Path p;
  p.fill_rule = g.evenodd ? kp::FillRule::kEvenOdd : kp::FillRule::kNonZero;
  for (const pg::GContour& c : g.contours) {
    kp::Contour kc{kpoint(c.start), {}};
    for (const pg::GPiece& q : c.pieces) {
      kp::Segment s;
      s.kind = q.degree == 1   ? kp::SegmentKind::kLine
               : q.degree == 2 ? kp::SegmentKind::kQuadratic
                               : kp::SegmentKind::kCubic;
      for (std::size_t i = 0; i < q.pts.size(); ++i)
        s.p[i] = kpoint(q.pts[i]);
      kc.segments.push_back(s);
    }
    p.contours.push_back(kc);
  }
  return p;
}

} // namespace rastrules::path_kernel
