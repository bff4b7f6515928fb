// SPDX-License-Identifier: MIT
// Shrinking a path scene that shows a difference (FUZZ.PATH.SHRINK): greedy, deterministic,
// each step kept only when the difference is still there.
// Implements: FUZZ.PATH.SHRINK

#include <algorithm>
#include <cmath>

#include "rastrules/fuzzer/paths.hpp"

namespace rastrules::fuzzer::paths {

namespace {

constexpr std::int64_t kOne = kSubpixelOne;
constexpr int kMaxAttempts = 4000; // draws of the library while shrinking one finding

std::int64_t raw(float v) {
  return static_cast<std::int64_t>(std::llround(static_cast<double>(v) * kOne));
}
float to_float(std::int64_t r) {
  return static_cast<float>(r) / static_cast<float>(kOne);
}

// Every coordinate of every path of the scene, in order.
std::vector<float*> coordinates(Scene& s) {
  std::vector<float*> out;
  for (Primitive& p : s.primitives) {
    if (!p.path)
      continue;
    for (FloatContour& c : p.path->contours) {
      out.push_back(&c.start[0]);
      out.push_back(&c.start[1]);
      for (FloatPathSegment& seg : c.segments)
        for (std::size_t i = 0; i < path::point_count(seg.kind); ++i) {
          out.push_back(&seg.p[i][0]);
          out.push_back(&seg.p[i][1]);
        }
    }
  }
  return out;
}

// The candidate simplifications of a scene, simplest first.
std::vector<Scene> candidates(const Scene& s, std::int64_t grid) {
  std::vector<Scene> out;
  for (std::size_t p = 0; p < s.primitives.size(); ++p) {
    if (!s.primitives[p].path)
      continue;
    const FloatPath& fp = *s.primitives[p].path;
    // Fewer contours.
    if (fp.contours.size() > 1)
      for (std::size_t c = 0; c < fp.contours.size(); ++c) {
        Scene t = s;
        t.primitives[p].path->contours.erase(t.primitives[p].path->contours.begin() +
                                             static_cast<std::ptrdiff_t>(c));
        out.push_back(std::move(t));
      }
    // Two contours made one: A, a line back to A's start, a line to B's start, B, a line back
    // to B's start and the closing line to A's start. The two connecting lines run there and
    // back along one segment, so every winding number off that segment is unchanged: a
    // difference that needs many windings (a 4-bit overflow) shrinks to one contour too.
    if (fp.contours.size() > 1)
      for (std::size_t c = 0; c + 1 < fp.contours.size(); ++c) {
        Scene t = s;
        auto& cs = t.primitives[p].path->contours;
        FloatContour& a = cs[c];
        const FloatContour b = cs[c + 1];
        auto line_to = [&a](FloatPoint q) {
          FloatPathSegment seg;
          seg.p[0] = q;
          a.segments.push_back(seg);
        };
        line_to(a.start);
        line_to(b.start);
        a.segments.insert(a.segments.end(), b.segments.begin(), b.segments.end());
        line_to(b.start);
        cs.erase(cs.begin() + static_cast<std::ptrdiff_t>(c + 1));
        out.push_back(std::move(t));
      }
    // Fewer segments; curves made simpler.
    for (std::size_t c = 0; c < fp.contours.size(); ++c) {
      const auto& segs = fp.contours[c].segments;
      for (std::size_t k = 0; k < segs.size(); ++k) {
        if (segs.size() > 1) {
          Scene t = s;
          auto& ts = t.primitives[p].path->contours[c].segments;
          ts.erase(ts.begin() + static_cast<std::ptrdiff_t>(k));
          out.push_back(std::move(t));
        }
        if (segs[k].kind != path::SegmentKind::kLine) {
          Scene t = s;
          FloatPathSegment& ts = t.primitives[p].path->contours[c].segments[k];
          const FloatPoint end = ts.p[path::point_count(ts.kind) - 1];
          ts.kind = path::SegmentKind::kLine;
          ts.p = {end, FloatPoint{}, FloatPoint{}};
          out.push_back(std::move(t));
        }
        if (segs[k].kind == path::SegmentKind::kCubic) {
          Scene t = s;
          FloatPathSegment& ts = t.primitives[p].path->contours[c].segments[k];
          const std::int64_t cx = (raw(ts.p[0][0]) + raw(ts.p[1][0])) / 2 / grid * grid;
          const std::int64_t cy = (raw(ts.p[0][1]) + raw(ts.p[1][1])) / 2 / grid * grid;
          ts.kind = path::SegmentKind::kQuadratic;
          ts.p = {FloatPoint{to_float(cx), to_float(cy)}, ts.p[2], FloatPoint{}};
          out.push_back(std::move(t));
        }
      }
    }
  }
  // Simpler coordinates: each rounded to whole pixels, then halves, quarters, 1/16.
  Scene base = s;
  const std::vector<float*> coords = coordinates(base);
  for (const std::int64_t step : {kOne, kOne / 2, kOne / 4, kOne / 16}) {
    if (step < grid || step % grid != 0)
      continue;
    for (std::size_t i = 0; i < coords.size(); ++i) {
      const std::int64_t v = raw(*coords[i]);
      const std::int64_t r = (v >= 0 ? v + step / 2 : v - step / 2) / step * step;
      if (r == v)
        continue;
      Scene t = s;
      *coordinates(t)[i] = to_float(r);
      out.push_back(std::move(t));
    }
  }
  // The path moved one pixel toward the origin, and the target made as small as it holds.
  for (int axis = 0; axis < 2; ++axis) {
    Scene t = s;
    bool ok = true;
    const std::vector<float*> tc = coordinates(t);
    for (std::size_t i = static_cast<std::size_t>(axis); i < tc.size(); i += 2)
      ok = ok && *tc[i] >= 1.0f;
    if (!ok || tc.empty())
      continue;
    for (std::size_t i = static_cast<std::size_t>(axis); i < tc.size(); i += 2)
      *tc[i] -= 1.0f;
    out.push_back(std::move(t));
  }
  {
    Scene t = s;
    float mx = 0, my = 0;
    const std::vector<float*> tc = coordinates(t);
    for (std::size_t i = 0; i < tc.size(); ++i)
      (i % 2 == 0 ? mx : my) = std::max(i % 2 == 0 ? mx : my, *tc[i]);
    t.width = std::min(t.width, static_cast<std::int32_t>(std::ceil(mx)) + 1);
    t.height = std::min(t.height, static_cast<std::int32_t>(std::ceil(my)) + 1);
    t.width = std::max(t.width, 1);
    t.height = std::max(t.height, 1);
    if (t.width != s.width || t.height != s.height)
      out.push_back(std::move(t));
  }
  return out;
}

} // namespace

// rule: FUZZ.PATH.SHRINK
Scene shrink_path(const Scene& scene, std::int32_t grid,
                  const std::function<bool(const Scene&)>& still_differs) {
  Scene best = scene;
  int attempts = 0;
  bool progress = true;
  while (progress && attempts < kMaxAttempts) {
    progress = false;
    for (Scene& c : candidates(best, std::max<std::int64_t>(grid, 1))) {
      if (++attempts > kMaxAttempts)
        break;
      if (still_differs(c)) {
        best = std::move(c);
        progress = true;
        break;
      }
    }
  }
  return best;
}

} // namespace rastrules::fuzzer::paths
