// SPDX-License-Identifier: MIT
// Built-in 2D "libraries" with one planted bug each (DRIVER.PATH.PLANTED), so that the 2D
// campaign shows it finds and shrinks each class of difference real libraries have:
//   float-accumulation  signed areas accumulated per cell in float32, as scanline accumulation
//                       rasterizers do (conflation where windings meet in a pixel);
//   4-bit-winding       the exact sample decision with the winding number kept in 4 bits;
//   flatten-quarter     the exact kernel on curves flattened to lines within 1/4 px.
// Implements: DRIVER.PATH.PLANTED

#include <algorithm>
#include <cmath>

#include "drivers.hpp"
#include "path_library.hpp"
#include "rastrules/path.hpp"

namespace rastrules::driver {
namespace {

enum class Bug { kFloatAccumulation, kWinding4, kFlattenQuarter };

constexpr std::int32_t kOne = kSubpixelOne;

// rule: DRIVER.PATH.PLANTED
// Adds the line (x0, y0) -> (x1, y1) (pixels) to the accumulation rows: for each pixel row it
// crosses, the part in each column adds d (1 - (xmid - column)) to its cell and the rest of d to
// the next cell, d being the signed height of the part; a prefix sum along the row then gives
// each pixel its signed covered area. Columns left of the target take everything into column 0.
void accumulate(std::vector<float>& acc, std::int32_t w, std::int32_t h, float x0, float y0,
                float x1, float y1) {
  if (y0 == y1)
    return;
  float dir = 1.0f;
  if (y0 > y1) {
    std::swap(x0, x1);
    std::swap(y0, y1);
    dir = -1.0f;
  }
  const float dxdy = (x1 - x0) / (y1 - y0);
  const auto stride = static_cast<std::size_t>(w) + 2;
  for (auto row = static_cast<std::int32_t>(std::floor(std::max(y0, 0.0f)));
       row < h && static_cast<float>(row) < y1; ++row) {
    const float ya = std::max(y0, static_cast<float>(row));
    const float yb = std::min(y1, static_cast<float>(row + 1));
    if (yb <= ya)
      continue;
    float xa = x0 + (ya - y0) * dxdy;
    float xb = x0 + (yb - y0) * dxdy;
    // Split at every column boundary between xa and xb.
    const float lo = std::min(xa, xb), hi = std::max(xa, xb);
    float t0 = 0.0f;
    std::vector<float> cuts;
    for (float c = std::floor(lo) + 1.0f; c < hi; c += 1.0f)
      cuts.push_back((c - xa) / (xb - xa));
    if (xb < xa)
      std::reverse(cuts.begin(), cuts.end());
    cuts.push_back(1.0f);
    for (const float t1 : cuts) {
      const float pa = xa + (xb - xa) * t0, pb = xa + (xb - xa) * t1;
      const float d = dir * (yb - ya) * (t1 - t0);
      float mid = 0.5f * (pa + pb);
      float col = std::floor(mid);
      if (col < 0.0f) {
        col = 0.0f;
        mid = 0.0f;
      }
      t0 = t1;
      if (col >= static_cast<float>(w))
        continue;
      const std::size_t at = static_cast<std::size_t>(row) * stride + static_cast<std::size_t>(col);
      acc[at] += d * (1.0f - (mid - col));
      acc[at + 1] += d * (mid - col);
    }
  }
}

// rule: DRIVER.PATH.PLANTED
// Flattens a curve by halving it until every control point is within 1/4 px of its chord.
void flatten(path::Point a, const path::Segment& s, std::vector<path::Point>& out, int depth) {
  const std::size_t n = path::point_count(s.kind);
  const path::Point end = s.p[n - 1];
  const double dx = end.x - a.x, dy = end.y - a.y, len = std::hypot(dx, dy);
  double far = 0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double px = s.p[i].x - a.x, py = s.p[i].y - a.y;
    far = std::max(far, len > 0 ? std::abs(px * dy - py * dx) / len : std::hypot(px, py));
  }
  if (far <= kOne / 4.0 || depth >= 16) {
    out.push_back(end);
    return;
  }
  auto mid = [](path::Point p, path::Point q) {
    return path::Point{static_cast<std::int32_t>((std::int64_t{p.x} + q.x) / 2),
                       static_cast<std::int32_t>((std::int64_t{p.y} + q.y) / 2)};
  };
  path::Segment l, r;
  l.kind = r.kind = s.kind;
  if (s.kind == path::SegmentKind::kQuadratic) {
    const path::Point m0 = mid(a, s.p[0]), m1 = mid(s.p[0], end), m = mid(m0, m1);
    l.p = {m0, m, {}};
    r.p = {m1, end, {}};
  } else {
    const path::Point m0 = mid(a, s.p[0]), m1 = mid(s.p[0], s.p[1]), m2 = mid(s.p[1], end);
    const path::Point n0 = mid(m0, m1), n1 = mid(m1, m2), m = mid(n0, n1);
    l.p = {m0, n0, m};
    r.p = {n1, m2, end};
  }
  flatten(a, l, out, depth + 1);
  flatten(l.p[path::point_count(l.kind) - 1], r, out, depth + 1);
}

path::Path flattened(const path::Path& p) {
  path::Path out;
  out.fill_rule = p.fill_rule;
  for (const path::Contour& c : p.contours) {
    path::Contour f;
    f.start = c.start;
    path::Point cur = c.start;
    for (const path::Segment& s : c.segments) {
      std::vector<path::Point> pts;
      if (s.kind == path::SegmentKind::kLine)
        pts.push_back(s.p[0]);
      else
        flatten(cur, s, pts, 0);
      for (const path::Point q : pts) {
        path::Segment l;
        l.p[0] = q;
        f.segments.push_back(l);
      }
      cur = s.p[path::point_count(s.kind) - 1];
    }
    out.contours.push_back(std::move(f));
  }
  return out;
}

class PlantedPathDriver final : public detail::PathLibraryDriver {
public:
  PlantedPathDriver(DriverInfo info, Bug bug) : PathLibraryDriver(std::move(info)), bug_(bug) {}

protected:
  // rule: DRIVER.PATH.PLANTED
  std::optional<std::string> raster(const detail::PathJob& job,
                                    std::vector<std::uint8_t>& alpha) override {
    const path::Path& p = *job.path;
    const std::int32_t w = job.width, h = job.height;
    auto at = [w](std::int32_t x, std::int32_t y) {
      return static_cast<std::size_t>(y) * static_cast<std::size_t>(w) +
             static_cast<std::size_t>(x);
    };
    switch (bug_) {
    case Bug::kFloatAccumulation: {
      const auto stride = static_cast<std::size_t>(w) + 2;
      std::vector<float> acc(stride * static_cast<std::size_t>(h) + 1, 0.0f);
      auto px = [](std::int32_t v) { return static_cast<float>(v) / static_cast<float>(kOne); };
      for (const path::Contour& c : p.contours) {
        path::Point cur = c.start;
        for (const path::Segment& s : c.segments) {
          accumulate(acc, w, h, px(cur.x), px(cur.y), px(s.p[0].x), px(s.p[0].y));
          cur = s.p[0];
        }
        accumulate(acc, w, h, px(cur.x), px(cur.y), px(c.start.x), px(c.start.y));
      }
      for (std::int32_t y = 0; y < h; ++y) {
        float sum = 0.0f;
        for (std::int32_t x = 0; x < w; ++x) {
          sum += acc[static_cast<std::size_t>(y) * stride + static_cast<std::size_t>(x)];
          float a = std::abs(sum);
          if (p.fill_rule == path::FillRule::kNonZero) {
            a = std::min(a, 1.0f);
          } else {
            a = std::fmod(a, 2.0f);
            if (a > 1.0f)
              a = 2.0f - a;
          }
          alpha[at(x, y)] = static_cast<std::uint8_t>(a * 255.0f + 0.5f);
        }
      }
      return std::nullopt;
    }
    case Bug::kWinding4:
      for (std::int32_t y = 0; y < h; ++y)
        for (std::int32_t x = 0; x < w; ++x) {
          const std::int64_t wn = path::winding_number(
              p, {x * kOne + kOne / 2, y * kOne + kOne / 2}, FillConvention::kTopLeft);
          const std::int64_t w4 = ((wn + 8) % 16 + 16) % 16 - 8;
          alpha[at(x, y)] = path::fill_holds(p.fill_rule, w4) ? 1 : 0;
        }
      return std::nullopt;
    case Bug::kFlattenQuarter: {
      const path::Path f = flattened(p);
      if (job.antialiased) {
        path::cover_area_alpha(f, w, h, alpha);
      } else {
        for (const path::SampleCoverage& c :
             path::cover_samples(f, SamplePattern{}, FillConvention::kTopLeft, w, h))
          alpha[at(c.x, c.y)] = 1;
      }
      return std::nullopt;
    }
    }
    return std::nullopt;
  }

private:
  Bug bug_;
};

} // namespace

namespace detail {

// rule: DRIVER.PATH.PLANTED
std::unique_ptr<Driver> open_planted_path(std::string_view arg, std::string* error) {
  PathSupport ps;
  ps.nonzero = ps.evenodd = true;
  ps.grid_raw = 1;
  ps.grid = "16.8";
  Bug bug{};
  if (arg == "float-accumulation") {
    bug = Bug::kFloatAccumulation;
    ps.area = true;
    ps.antialiased_method = "signed areas accumulated per cell in float32 (planted)";
  } else if (arg == "4-bit-winding") {
    bug = Bug::kWinding4;
    ps.samples = ps.quadratics = ps.cubics = true;
    ps.aliased_method = "exact winding number kept in 4 bits (planted)";
  } else if (arg == "flatten-quarter") {
    bug = Bug::kFlattenQuarter;
    ps.samples = ps.area = ps.quadratics = ps.cubics = true;
    ps.aliased_method = ps.antialiased_method =
        "the exact kernel on curves flattened within 1/4 px (planted)";
  } else {
    *error = "driver 'imprecise-path' needs one of: float-accumulation, 4-bit-winding, "
             "flatten-quarter (got '" +
             std::string(arg) + "')";
    return nullptr;
  }
  return std::make_unique<PlantedPathDriver>(
      path_library_info("imprecise-path:" + std::string(arg),
                        "built-in 2D rasterizer with a planted bug: " +
                            (ps.area && !ps.samples ? ps.antialiased_method : ps.aliased_method),
                        ps, 4096),
      bug);
}

} // namespace detail
} // namespace rastrules::driver
