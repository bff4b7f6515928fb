// SPDX-License-Identifier: MIT
// rastrules probe for 2D libraries (FUZZ.PATH.PROBE): the boundary convention, the grid, the
// antialiasing method and the quantisation of a library, measured with dedicated paths. Each
// probe is one scene of many path primitives (a library draws each alone), so that a library
// behind a process per scene (Skia, tiny-skia) is started a few times only.
// Implements: FUZZ.PATH.PROBE

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <variant>

#include "rastrules/fuzzer/paths.hpp"

namespace rastrules::fuzzer::paths {

namespace {

constexpr std::int32_t kOne = kSubpixelOne;

FloatPoint f(std::int64_t x, std::int64_t y) {
  return {static_cast<float>(x) / static_cast<float>(kOne),
          static_cast<float>(y) / static_cast<float>(kOne)};
}

// A contour through raw points.
FloatContour contour(const std::vector<std::array<std::int64_t, 2>>& pts) {
  FloatContour c;
  c.start = f(pts[0][0], pts[0][1]);
  for (std::size_t i = 1; i < pts.size(); ++i) {
    FloatPathSegment s;
    s.p[0] = f(pts[i][0], pts[i][1]);
    c.segments.push_back(s);
  }
  return c;
}

// The rectangle [x0, x1] x [y0, y1] (raw), clockwise on the y-down screen or counter-clockwise.
FloatContour rect(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1, bool cw) {
  if (cw)
    return contour({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
  return contour({{x0, y0}, {x0, y1}, {x1, y1}, {x1, y0}});
}

Primitive prim(std::vector<FloatContour> cs, path::Coverage coverage,
               path::FillRule rule = path::FillRule::kNonZero) {
  FloatPath p;
  p.coverage = coverage;
  p.fill_rule = rule;
  p.contours = std::move(cs);
  return make_path(std::move(p));
}

// Draws a scene of paths; per primitive, pixel -> value (1 aliased, alpha antialiased).
using Values = std::vector<std::map<std::pair<std::int32_t, std::int32_t>, int>>;
std::optional<Values> draw(driver::Driver& d, const Scene& s, std::string& error) {
  if (const std::string why = d.unsupported(s); !why.empty()) {
    error = "probe scene not supported: " + why;
    return std::nullopt;
  }
  auto r = d.draw(s);
  if (const auto* e = std::get_if<driver::DriverError>(&r)) {
    error = e->message;
    return std::nullopt;
  }
  Values v(s.primitives.size());
  for (const Fragment& fr : std::get<std::vector<Fragment>>(r))
    if (fr.prim < v.size())
      v[fr.prim][{fr.x, fr.y}] = fr.area ? fr.area.alpha() : 1;
  return v;
}

int at(const Values& v, std::size_t p, std::int32_t x, std::int32_t y) {
  const auto it = v[p].find({x, y});
  return it == v[p].end() ? 0 : it->second;
}

int exact_alpha(double a) {
  return static_cast<int>(std::floor(255.0 * a + 0.5));
}

} // namespace

// rule: FUZZ.PATH.PROBE
PathProbeReport probe_path_library(driver::Driver& d) {
  PathProbeReport r;
  const driver::PathSupport& ps = d.info().paths;
  const std::int32_t g = std::max<std::int32_t>(ps.grid_raw, 1);
  const std::int64_t half = kOne / 2;
  if (ps.samples) {
    // Boundary convention: the centres of pixels (1, 2), (3, 2), (2, 1), (2, 3) lie on the left,
    // right, top and bottom edges of [1.5, 3.5]^2.
    Scene s;
    s.width = s.height = 6;
    for (const bool cw : {true, false})
      s.primitives.push_back(
          prim({rect(kOne + half, kOne + half, 3 * kOne + half, 3 * kOne + half, cw)},
               path::Coverage::kSamples));
    // Snapping: a vertical left edge at 1.5 + d/256 px (d a multiple of the grid, |d| <= 64),
    // deciding the centre (1.5, 1.5) of pixel (1, 1).
    std::vector<std::int64_t> ds;
    for (std::int64_t dd = -64; dd <= 64; dd += g)
      ds.push_back(dd);
    for (const std::int64_t dd : ds)
      s.primitives.push_back(
          prim({rect(kOne + half + dd, kOne, 4 * kOne, 2 * kOne, true)}, path::Coverage::kSamples));
    auto v = draw(d, s, r.error);
    if (!v)
      return r;
    const std::array<std::pair<std::int32_t, std::int32_t>, 4> px = {
        {{1, 2}, {3, 2}, {2, 1}, {2, 3}}};
    for (std::size_t k = 0; k < 4; ++k) {
      r.on_edge_cw[k] = at(*v, 0, px[k].first, px[k].second) != 0;
      r.on_edge_ccw[k] = at(*v, 1, px[k].first, px[k].second) != 0;
    }
    if (r.on_edge_cw != r.on_edge_ccw) {
      r.convention = "depends on the contour's orientation";
    } else {
      const auto& e = r.on_edge_cw;
      const std::array<std::array<bool, 4>, 4> conventions = {
          {{true, false, true, false},   // top-left
           {false, true, true, false},   // top-right
           {true, false, false, true},   // bottom-left
           {false, true, false, true}}}; // bottom-right
      r.convention = "none of PATH.SAMPLE.TIE's (left " + std::string(e[0] ? "in" : "out") +
                     ", right " + (e[1] ? "in" : "out") + ", top " + (e[2] ? "in" : "out") +
                     ", bottom " + (e[3] ? "in" : "out") + ")";
      for (std::size_t c = 0; c < 4; ++c)
        if (e == conventions[c])
          r.convention = std::string(to_string(static_cast<FillConvention>(c)));
    }
    // The tie (d = 0) decides T; the extent is how far the edge moves, on the side where the
    // exact answer is not T, before the library's answer leaves T.
    const auto zero = static_cast<std::size_t>(std::find(ds.begin(), ds.end(), 0) - ds.begin());
    const bool tie_in = at(*v, 2 + zero, 1, 1) != 0;
    std::int32_t extent = 0;
    for (std::size_t k = 1; k <= zero; ++k) {
      const std::size_t i = tie_in ? zero + k : zero - k; // inside T: edge moved right
      if (i >= ds.size() || (at(*v, 2 + i, 1, 1) != 0) != tie_in)
        break;
      extent = static_cast<std::int32_t>(std::abs(ds[i]));
    }
    r.snap_extent = extent;
    if (extent == 0 && g > 1) {
      r.grid = "no snapping beyond its declared " + ps.grid + " grid (edges moved in steps of " +
               std::to_string(g) + "/256 px)";
    } else if (extent == 0) {
      r.grid = "1/256 px or finer (16.8, 24.8 or float)";
    } else {
      std::int32_t step = 1;
      while (step < 2 * extent)
        step *= 2;
      r.grid = "edges within " + std::to_string(extent) +
               "/256 px of a centre are on it: a grid of 1/" + std::to_string(kOne / step) + " px" +
               (step == 4 ? " (26.6)" : "");
    }
  }
  if (ps.area) {
    Scene s;
    s.width = s.height = 5;
    // A vertical and a horizontal edge across pixel (1, 1) in 65 steps of 1/64 px.
    for (std::int64_t k = 0; k <= 64; ++k)
      s.primitives.push_back(
          prim({rect(kOne + 4 * k, 0, 4 * kOne, 4 * kOne, true)}, path::Coverage::kArea));
    for (std::int64_t k = 0; k <= 64; ++k)
      s.primitives.push_back(
          prim({rect(0, kOne + 4 * k, 4 * kOne, 4 * kOne, true)}, path::Coverage::kArea));
    // Quantisation: areas k/256 of pixel (1, 1).
    const std::array<std::int64_t, 5> ks = {4, 64, 128, 192, 252};
    for (const std::int64_t k : ks)
      s.primitives.push_back(
          prim({rect(2 * kOne - k, 0, 4 * kOne, 4 * kOne, true)}, path::Coverage::kArea));
    // A half pixel drawn twice under even-odd (exact 0).
    const FloatContour hp = rect(kOne + half, kOne, 2 * kOne, 2 * kOne, true);
    s.primitives.push_back(prim({hp, hp}, path::Coverage::kArea, path::FillRule::kEvenOdd));
    auto v = draw(d, s, r.error);
    if (!v)
      return r;
    std::set<int> lx, ly;
    for (std::size_t k = 0; k <= 64; ++k) {
      const int ax = at(*v, k, 1, 1), ay = at(*v, 65 + k, 1, 1);
      lx.insert(ax);
      ly.insert(ay);
      const int e = exact_alpha(1.0 - static_cast<double>(k) / 64.0);
      r.max_edge_error = std::max({r.max_edge_error, std::abs(ax - e), std::abs(ay - e)});
    }
    r.levels_x = static_cast<int>(lx.size());
    r.levels_y = static_cast<int>(ly.size());
    auto along = [](int levels) {
      return levels >= 60 ? std::string("exact to 1/64 px")
                          : std::to_string(levels - 1) + " steps a pixel";
    };
    r.aa_method = (r.levels_x >= 60 && r.levels_y >= 60)
                      ? "area coverage (every 1/64 px step of an edge changes alpha)"
                      : "along x " + along(r.levels_x) + ", along y " + along(r.levels_y) +
                            " (sub-sampled coverage)";
    // rule: FUZZ.PATH.PROBE
    // The usual ways from an area a to 8 bits, tried in order.
    const std::vector<std::pair<std::string, std::function<int(std::int64_t)>>> formulas = {
        {"floor(255 a + 1/2)",
         [](std::int64_t k) { return static_cast<int>((510 * k + 256) / 512); }},
        {"floor(255 a)", [](std::int64_t k) { return static_cast<int>(255 * k / 256); }},
        {"min(255, floor(256 a))",
         [](std::int64_t k) { return static_cast<int>(std::min<std::int64_t>(255, k)); }},
        {"ceil(255 a)", [](std::int64_t k) { return static_cast<int>((255 * k + 255) / 256); }}};
    std::string seen;
    for (std::size_t i = 0; i < ks.size(); ++i)
      seen += (seen.empty() ? "" : ", ") + std::to_string(ks[i]) + "/256 -> " +
              std::to_string(at(*v, 130 + i, 1, 1));
    r.quantisation = "none of the usual (" + seen + ")";
    for (const auto& [name, fn] : formulas) {
      bool all = true;
      for (std::size_t i = 0; i < ks.size(); ++i)
        all = all && fn(ks[i]) == at(*v, 130 + i, 1, 1);
      if (all) {
        r.quantisation = name + " (" + seen + ")";
        break;
      }
    }
    r.twice_evenodd = at(*v, 130 + ks.size(), 1, 1);
    if (ps.quadratics || ps.cubics) {
      Scene q;
      q.width = q.height = 2;
      FloatContour c;
      c.start = {1, 1};
      FloatPathSegment seg;
      if (ps.quadratics) {
        seg.kind = path::SegmentKind::kQuadratic;
        seg.p = {FloatPoint{0, 1}, FloatPoint{0, 0}, FloatPoint{}};
      } else {
        // The same quadratic as a cubic: control points 2/3 of the way to (0, 1).
        seg.kind = path::SegmentKind::kCubic;
        seg.p = {FloatPoint{1.0f / 3.0f, 1}, FloatPoint{0, 1.0f / 3.0f}, FloatPoint{0, 0}};
      }
      c.segments.push_back(seg);
      q.primitives.push_back(prim({c}, path::Coverage::kArea));
      if (auto qv = draw(d, q, r.error))
        r.quadratic = at(*qv, 0, 0, 0);
      else
        return r;
    }
  }
  return r;
}

} // namespace rastrules::fuzzer::paths
