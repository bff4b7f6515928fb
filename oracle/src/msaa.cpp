// SPDX-License-Identifier: MIT
// Exact oracle for multisampling (rastrules/oracle/msaa.hpp), written from spec/rules/msaa.md
// and spec/scene.md. Positions and distances are GMP rationals; every coverage decision is one
// of the exact oracles of triangle.hpp, point.hpp and line.hpp at an exact sample position.

#include "rastrules/oracle/msaa.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "rastrules/oracle/line.hpp"
#include "rastrules/oracle/line_aa.hpp"
#include "rastrules/oracle/point.hpp"
#include "rastrules/oracle/triangle.hpp"

namespace rastrules::oracle::msaa {
namespace {

mpq_class Q(std::int64_t v) {
  return mpq_class(mpz_class(static_cast<long>(v)));
}

std::int64_t to_i64(const mpq_class& q) {
  if (q.get_den() != 1 || !q.get_num().fits_slong_p())
    throw std::logic_error("oracle: value is not a 64-bit integer");
  return static_cast<std::int64_t>(q.get_num().get_si());
}

std::uint32_t bit(std::size_t k) {
  return std::uint32_t{1} << k;
}

std::uint32_t full(std::size_t n) {
  return n >= 32 ? 0xFFFFFFFFu : static_cast<std::uint32_t>((std::uint64_t{1} << n) - 1u);
}

void check_pattern(const std::vector<Offset>& pattern) {
  // rule: MSAA.PATTERN.CUSTOM, MSAA.LIMITS
  if (pattern.empty() || pattern.size() > 16)
    throw std::invalid_argument("oracle: a pattern has 1 to 16 samples");
  for (const Offset& o : pattern) {
    if (!on_grid(o))
      throw std::invalid_argument("oracle: sample offset off the [-8, 7] grid");
  }
}

// Exact position of sample o of pixel (px, py) in pixels.
// rule: MSAA.PATTERN.GRID
std::array<mpq_class, 2> sample_px(std::int64_t px, std::int64_t py, const Offset& o) {
  const mpq_class half(1, 2);
  mpq_class ox(o.x, 16), oy(o.y, 16);
  ox.canonicalize();
  oy.canonicalize();
  return {Q(px) + half + ox, Q(py) + half + oy};
}

// The closed pixel square [px, px + 1] x [py, py + 1] in raw units misses the closed box
// [lo, hi]: then no sample of the pixel lies in the box. Exact integer comparisons.
bool misses_box(std::int64_t px, std::int64_t py, const Raw2& lo, const Raw2& hi) {
  return 256 * px + 256 < lo[0] || 256 * px > hi[0] || 256 * py + 256 < lo[1] || 256 * py > hi[1];
}

template <class It> std::pair<Raw2, Raw2> box_of(It first, It last) {
  Raw2 lo = *first, hi = *first;
  for (It i = first; i != last; ++i) {
    lo = {std::min(lo[0], (*i)[0]), std::min(lo[1], (*i)[1])};
    hi = {std::max(hi[0], (*i)[0]), std::max(hi[1], (*i)[1])};
  }
  return {lo, hi};
}

// Squared distance of an offset from the centre in px^2, exact.
mpq_class dist2(const Offset& o) {
  mpq_class x(o.x, 16), y(o.y, 16);
  x.canonicalize();
  y.canonicalize();
  return x * x + y * y;
}

// Returns the index in `set` (a mask) nearest the centre, ties to the lower index
// ("starting from the pixel center and moving outward"), or nothing when set is empty.
// rule: MSAA.CENTROID.D3D10
std::optional<std::size_t> nearest(std::uint32_t set, const std::vector<Offset>& pattern) {
  std::optional<std::size_t> best;
  for (std::size_t k = 0; k < pattern.size(); ++k) {
    if ((set & bit(k)) == 0)
      continue;
    if (!best || dist2(pattern[k]) < dist2(pattern[*best]))
      best = k;
  }
  return best;
}

std::optional<std::size_t> first(std::uint32_t set, std::size_t n) {
  for (std::size_t k = 0; k < n; ++k) {
    if (set & bit(k))
      return k;
  }
  return std::nullopt;
}

// One unit of coverage: a whole primitive, or one segment of a line strip.
struct Unit {
  std::optional<std::uint32_t> seg;
  // kind: 0 triangle (v[0..2]), 1 point (v[0]), 2 quadrilateral line (v[0] -> v[1]),
  // 3 aliased line in every sample (v[0] -> v[1]), 4 aliased line, one sample,
  // 5 antialiased line in every sample of each pixel of positive coverage.
  int kind = 0;
  std::vector<Raw2> v;
  std::string mode; // quad or aliased line mode
};

std::string aliased_mode(const std::string& line_mode) {
  if (line_mode == "d3d" || line_mode == "vulkan-bresenham")
    return line_mode;
  throw std::invalid_argument("oracle: unknown line mode '" + line_mode + "'");
}

// The units a primitive draws, by SCENE.PRIM.* and MSAA.LINE.MODE.
// rule: MSAA.LINE.MODE, MSAA.POINT.PER_SAMPLE
std::vector<Unit> units_of(const Primitive& p, const Input& in) {
  const std::size_t n = in.pattern.size();
  std::vector<Unit> out;
  if (p.type == "triangle") {
    if (p.v.size() != 3)
      throw std::invalid_argument("oracle: a triangle has 3 vertices");
    out.push_back(Unit{std::nullopt, 0, p.v, ""});
    return out;
  }
  if (p.type == "point") {
    if (p.v.size() != 1)
      throw std::invalid_argument("oracle: a point has 1 vertex");
    out.push_back(Unit{std::nullopt, 1, p.v, ""});
    return out;
  }
  const bool strip = p.type == "line_strip";
  if (!strip && p.type != "line")
    throw std::invalid_argument("oracle: unknown type " + p.type);
  if (strip ? p.v.size() < 2 : p.v.size() != 2)
    throw std::invalid_argument("oracle: bad line vertex count");
  if (p.aa && in.line_mode != "d3d")
    throw std::invalid_argument("oracle: aa lines exist only in line mode d3d");
  int kind = 0;
  std::string mode;
  if (in.line_mode == "quad-wide" || in.line_mode == "quad-narrow") {
    kind = 2;
    mode = in.line_mode;
  } else if (in.line_mode == "d3d" && n > 1 && in.multisample_enable) {
    // A d3d line, aliased or antialiased, on a multisampled target with MultisampleEnable: a
    // quadrilateral line 1.4 px wide without antialiasing.
    kind = 2;
    mode = "quad-wide";
  } else if (in.line_mode == "d3d" && p.aa) {
    // Otherwise (one sample, or no MultisampleEnable) an antialiased line hits every sample of
    // each pixel it produces (its coverage is the single-sample line's, checked by line_aa's
    // oracle).
    kind = 5;
    mode = "d3d";
  } else if (in.line_mode == "d3d" || in.line_mode == "vulkan-bresenham") {
    kind = n > 1 ? 3 : 4;
    mode = aliased_mode(in.line_mode);
    if (n > 1 && in.shading == "sample" && in.line_mode == "vulkan-bresenham")
      throw std::invalid_argument("oracle: sample shading of Bresenham lines is bad input");
  } else {
    throw std::invalid_argument("oracle: unknown line mode '" + in.line_mode + "'");
  }
  for (std::size_t k = 0; k + 1 < p.v.size(); ++k) {
    out.push_back(
        Unit{strip ? std::optional<std::uint32_t>(static_cast<std::uint32_t>(k)) : std::nullopt,
             kind,
             {p.v[k], p.v[k + 1]},
             mode});
  }
  return out;
}

// Coverage of pixel (px, py) by a unit, before the mask (any pixel, inside the target or not).
// rule: MSAA.COVER.SAMPLE, MSAA.POINT.PER_SAMPLE, MSAA.LINE.MODE
std::uint32_t unit_mask(const Unit& u, const Input& in, std::int64_t px, std::int64_t py) {
  switch (u.kind) {
  case 0:
    return triangle_mask({u.v[0], u.v[1], u.v[2]}, in.state, px, py, in.pattern);
  case 1:
    return point_mask(u.v[0], in.state.fill, px, py, in.pattern);
  case 2:
    return quad_line_mask(u.v[0], u.v[1], u.mode, in.state.fill, px, py, in.pattern);
  default: {
    // An aliased line: the pixel is the line's (centre test of its own rules), and then every
    // sample of the pattern is covered; an antialiased one (kind 5): the pixel has positive
    // exact coverage (LINE.AA.RECT: within 3/2 px of the segment).
    const auto [lo, hi] = box_of(u.v.begin(), u.v.end());
    if (misses_box(px, py, {lo[0] - 512, lo[1] - 512}, {hi[0] + 512, hi[1] + 512}))
      return 0;
    const bool on_line = u.kind == 5 ? aa_compare(u.v[0], u.v[1], static_cast<std::int32_t>(px),
                                                  static_cast<std::int32_t>(py), 0, 1) > 0
                                     : aliased_line_covers(u.v[0], u.v[1], u.mode, px, py);
    return on_line ? full(in.pattern.size()) : 0;
  }
  }
}

// The evaluation point of a lane, in 1/16 px from the target origin.
struct Eval {
  mpq_class x, y;
};

} // namespace

bool on_grid(const Offset& o) {
  return o.x >= -8 && o.x <= 7 && o.y >= -8 && o.y <= 7;
}

// rule: MSAA.PATTERN.STANDARD
std::vector<Offset> standard_pattern(std::uint32_t n) {
  // Typed from the table of spec/rules/msaa.md, index for index.
  switch (n) {
  case 1:
    return {{0, 0}};
  case 2:
    return {{4, 4}, {-4, -4}};
  case 4:
    return {{-2, -6}, {6, -2}, {-6, 2}, {2, 6}};
  case 8:
    return {{1, -3}, {-1, 3}, {5, 1}, {-3, -5}, {-5, 5}, {-7, -1}, {3, 7}, {7, -7}};
  case 16:
    return {{1, 1},  {-1, -3}, {-3, 2},  {4, -1}, {-5, -2}, {2, 5},  {5, 3}, {3, -5},
            {-2, 6}, {0, -7},  {-4, -6}, {-6, 4}, {-8, 0},  {7, -4}, {6, 7}, {-7, -8}};
  default:
    throw std::invalid_argument("oracle: no standard pattern of " + std::to_string(n));
  }
}

// rule: MSAA.PATTERN.CENTER
std::vector<Offset> center_pattern(std::uint32_t n) {
  (void)standard_pattern(n); // the same counts
  return std::vector<Offset>(n, Offset{0, 0});
}

// rule: MSAA.SAMPLE.POSITION, MSAA.PATTERN.GRID
Raw2 sample_raw(std::int64_t px, std::int64_t py, const Offset& o) {
  if (!on_grid(o))
    throw std::invalid_argument("oracle: sample offset off the [-8, 7] grid");
  const auto p = sample_px(px, py, o);
  return {to_i64(p[0] * 256), to_i64(p[1] * 256)};
}

// rule: MSAA.COVER.SAMPLE
std::uint32_t triangle_mask(const std::array<Raw2, 3>& v, const State& state, std::int64_t px,
                            std::int64_t py, const std::vector<Offset>& pattern) {
  check_pattern(pattern);
  const auto [lo, hi] = box_of(v.begin(), v.end());
  if (misses_box(px, py, lo, hi))
    return 0; // no sample can lie in the closed triangle
  std::uint32_t m = 0;
  for (std::size_t k = 0; k < pattern.size(); ++k) {
    if (covers(v, sample_raw(px, py, pattern[k]), state))
      m |= bit(k);
  }
  return m;
}

// rule: MSAA.POINT.PER_SAMPLE
std::uint32_t point_mask(const Raw2& c, const std::string& fill, std::int64_t px, std::int64_t py,
                         const std::vector<Offset>& pattern) {
  check_pattern(pattern);
  if (misses_box(px, py, {c[0] - 128, c[1] - 128}, {c[0] + 128, c[1] + 128}))
    return 0;
  std::uint32_t m = 0;
  for (std::size_t k = 0; k < pattern.size(); ++k) {
    if (point_covers(c, sample_raw(px, py, pattern[k]), fill))
      m |= bit(k);
  }
  return m;
}

// rule: MSAA.LINE.MODE, MSAA.COVER.SAMPLE
std::uint32_t quad_line_mask(const Raw2& a, const Raw2& b, const std::string& mode,
                             const std::string& fill, std::int64_t px, std::int64_t py,
                             const std::vector<Offset>& pattern) {
  check_pattern(pattern);
  const std::vector<Raw2> corners = quad_line_corners(a, b, mode);
  if (corners.empty())
    return 0; // LINE.QUAD.ZERO_LENGTH
  const auto [lo, hi] = box_of(corners.begin(), corners.end());
  if (misses_box(px, py, lo, hi))
    return 0;
  std::uint32_t m = 0;
  for (std::size_t k = 0; k < pattern.size(); ++k) {
    if (quad_line_covers(a, b, mode, sample_raw(px, py, pattern[k]), fill))
      m |= bit(k);
  }
  return m;
}

// rule: MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10
CentroidPoint centroid(const std::string& rule, std::uint32_t c, std::uint32_t m,
                       const std::vector<Offset>& pattern) {
  check_pattern(pattern);
  const std::size_t n = pattern.size();
  const std::uint32_t all = full(n);
  c &= all;
  m &= all;
  const CentroidPoint centre_full{Offset{0, 0}, Branch::kFullCoverageCenter};
  const CentroidPoint centre_none{Offset{0, 0}, Branch::kNoneCoveredCenter};
  if (rule == "d3d11") {
    // 1. Every sample covered and in the mask (the mask applies first): the pixel centre.
    if ((c & m) == all)
      return centre_full;
    // 2. The first sample, in index order, covered and in the mask.
    if (const auto k = first(c & m, n))
      return CentroidPoint{pattern[*k], Branch::kFirstCovered};
    // 3. Nothing covered: the first sample of a partial mask, or the centre for a full mask
    //    (and for an empty one, which has no sample).
    if (m != all) {
      if (const auto k = first(m, n))
        return CentroidPoint{pattern[*k], Branch::kNoneCoveredMaskSample};
    }
    return centre_none;
  }
  if (rule == "d3d10") {
    const std::uint32_t cm = c & m; // the mask is applied first
    if (c == all && m == all)
      return centre_full;
    if (cm == 0) {
      if (m == all)
        return centre_none;
      if (const auto k = nearest(m, pattern))
        return CentroidPoint{pattern[*k], Branch::kNoneCoveredMaskSample};
      return centre_none;
    }
    return CentroidPoint{pattern[*nearest(cm, pattern)], Branch::kNearestCovered};
  }
  throw std::invalid_argument("oracle: unknown centroid rule '" + rule + "'");
}

// rule: MSAA.CENTROID.WITHIN
bool centre_in_hull(const std::vector<Offset>& pattern) {
  check_pattern(pattern);
  // Exact integer geometry on the 1/16 grid; the centre is (0, 0).
  const auto cross = [](const Offset& a, const Offset& b, std::int64_t x, std::int64_t y) {
    return (std::int64_t{b.x} - a.x) * (y - a.y) - (std::int64_t{b.y} - a.y) * (x - a.x);
  };
  const auto on_segment = [&](const Offset& a, const Offset& b) {
    return cross(a, b, 0, 0) == 0 && std::min(a.x, b.x) <= 0 && 0 <= std::max(a.x, b.x) &&
           std::min(a.y, b.y) <= 0 && 0 <= std::max(a.y, b.y);
  };
  const std::size_t n = pattern.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (pattern[i] == Offset{0, 0})
      return true;
    for (std::size_t j = i + 1; j < n; ++j) {
      if (on_segment(pattern[i], pattern[j]))
        return true;
      for (std::size_t k = j + 1; k < n; ++k) {
        const std::int64_t d0 = cross(pattern[i], pattern[j], 0, 0);
        const std::int64_t d1 = cross(pattern[j], pattern[k], 0, 0);
        const std::int64_t d2 = cross(pattern[k], pattern[i], 0, 0);
        if ((d0 >= 0 && d1 >= 0 && d2 >= 0) || (d0 <= 0 && d1 <= 0 && d2 <= 0)) {
          // Inside or on the closed triangle; a degenerate triple is covered by the segment
          // tests (all three crosses 0 with the centre off every segment means the centre lies
          // on the line but outside the points: reject that case).
          if (d0 == 0 && d1 == 0 && d2 == 0)
            continue;
          return true;
        }
      }
    }
  }
  return false;
}

// rule: MSAA.RESOLVE.AVERAGE
Rgba resolve_pixel(const std::vector<Rgba>& samples) {
  if (samples.empty())
    throw std::invalid_argument("oracle: resolve of no samples");
  Rgba out{};
  for (std::size_t ch = 0; ch < 4; ++ch) {
    mpq_class sum = 0;
    for (const Rgba& s : samples)
      sum += s[ch];
    const mpq_class avg = sum / Q(static_cast<std::int64_t>(samples.size()));
    // Nearest integer, ties to even: fl = floor(avg), frac = avg - fl.
    const mpz_class fl = avg.get_num() / avg.get_den(); // avg >= 0: truncation is floor
    const mpq_class frac = avg - mpq_class(fl);
    mpz_class r = fl;
    if (frac > mpq_class(1, 2) || (frac == mpq_class(1, 2) && fl % 2 != 0))
      r = fl + 1;
    out[ch] = static_cast<std::uint8_t>(r.get_ui());
  }
  return out;
}

// rule: MSAA.MASK.AND, MSAA.SHADING.PIXEL, MSAA.SHADING.SAMPLE, MSAA.QUAD.HELPER
// rule: MSAA.QUAD.ALIGN, MSAA.QUAD.LANE, MSAA.DERIV.FINE, MSAA.DERIV.COARSE
std::vector<Fragment> render(const Input& in) {
  check_pattern(in.pattern);
  if (in.width < 0 || in.height < 0)
    throw std::invalid_argument("oracle: negative target size");
  if (in.shading != "pixel" && in.shading != "sample")
    throw std::invalid_argument("oracle: unknown shading '" + in.shading + "'");
  if (in.derivatives != "none" && in.derivatives != "fine" && in.derivatives != "coarse")
    throw std::invalid_argument("oracle: unknown derivatives '" + in.derivatives + "'");
  const std::size_t n = in.pattern.size();
  const std::uint32_t m = in.sample_mask & full(n); // the mask restricted to the pattern
  const bool per_sample = in.shading == "sample";
  const bool quads = in.quads || in.derivatives != "none";
  std::vector<Fragment> out;
  for (std::size_t p = 0; p < in.primitives.size(); ++p) {
    for (const Unit& u : units_of(in.primitives[p], in)) {
      // Coverage of every pixel this unit may need: the target, and the lanes of quads that
      // stick out of it (odd width or height).
      const std::int32_t qw = in.width + (in.width & 1), qh = in.height + (in.height & 1);
      std::map<std::pair<std::int32_t, std::int32_t>, std::uint32_t> cov; // (y, x) -> c
      const auto c_at = [&](std::int32_t x, std::int32_t y) -> std::uint32_t {
        const auto key = std::make_pair(y, x);
        const auto it = cov.find(key);
        if (it != cov.end())
          return it->second;
        return cov[key] = unit_mask(u, in, x, y);
      };
      // The shading invocations: (x, y, sample or none) -> mask after the sample mask.
      // Under sample shading there is one per covered sample; the quad of an invocation is
      // per sample index.
      const std::vector<std::optional<std::uint32_t>> indices = [&] {
        std::vector<std::optional<std::uint32_t>> v;
        if (per_sample) {
          for (std::uint32_t k = 0; k < n; ++k)
            v.emplace_back(k);
        } else {
          v.emplace_back(std::nullopt);
        }
        return v;
      }();
      // The live mask of pixel (x, y) for one index: what the pixel writes there.
      const auto live = [&](std::int32_t x, std::int32_t y, const std::optional<std::uint32_t>& k) {
        if (x >= in.width || y >= in.height)
          return std::uint32_t{0}; // RASTER.TARGET.CLIP
        const std::uint32_t a = c_at(x, y) & m;
        return k ? (a & bit(*k)) : a;
      };
      // The coverage a lane's centroid sees: its own, or nothing on a helper lane ("nothing
      // covered, as on helper lanes", MSAA.CENTROID.D3D11 (3)), also when other samples of
      // the pixel are covered under sample shading.
      const auto lane_c = [&](std::int32_t x, std::int32_t y, std::uint32_t a) {
        return a == 0 ? std::uint32_t{0} : c_at(x, y);
      };
      // The evaluation point of lane (x, y) with live mask a for index k, in 1/16 px.
      const auto eval = [&](std::int32_t x, std::int32_t y, std::uint32_t a,
                            const std::optional<std::uint32_t>& k) {
        Offset o{0, 0};
        if (k) {
          o = in.pattern[*k];
        } else if (in.centroid) {
          o = centroid(*in.centroid, lane_c(x, y, a), m, in.pattern).offset;
        }
        return Eval{Q(16 * std::int64_t{x} + 8 + o.x), Q(16 * std::int64_t{y} + 8 + o.y)};
      };
      std::vector<Fragment> unit_frags;
      for (const auto& k : indices) {
        for (std::int32_t qy = 0; qy < qh; qy += 2) {
          for (std::int32_t qx = 0; qx < qw; qx += 2) {
            // Lane order of MSAA.QUAD.LANE: (x & 1) + 2 (y & 1).
            const std::array<std::array<std::int32_t, 2>, 4> lanes = {
                {{qx, qy}, {qx + 1, qy}, {qx, qy + 1}, {qx + 1, qy + 1}}};
            std::array<std::uint32_t, 4> a{};
            bool touched = false;
            for (std::size_t l = 0; l < 4; ++l) {
              a[l] = live(lanes[l][0], lanes[l][1], k);
              touched = touched || a[l] != 0;
            }
            if (!touched)
              continue;
            std::optional<std::array<Deriv, 4>> d;
            if (in.derivatives != "none") {
              std::array<Eval, 4> e;
              for (std::size_t l = 0; l < 4; ++l)
                e[l] = eval(lanes[l][0], lanes[l][1], a[l], k);
              std::array<Deriv, 4> dd{};
              for (std::size_t l = 0; l < 4; ++l) {
                // Fine: ddx across the lane's row, ddy across its column; coarse: lane 0's.
                const std::size_t ll = in.derivatives == "coarse" ? 0 : l;
                const std::size_t row = ll & 2u, col = ll & 1u;
                dd[l] = Deriv{to_i64(e[row + 1].x - e[row].x), to_i64(e[row + 1].y - e[row].y),
                              to_i64(e[col + 2].x - e[col].x), to_i64(e[col + 2].y - e[col].y)};
              }
              d = dd;
            }
            for (std::size_t l = 0; l < 4; ++l) {
              const std::int32_t x = lanes[l][0], y = lanes[l][1];
              if (x >= in.width || y >= in.height)
                continue; // not listed (MSAA.QUAD.HELPER)
              const bool helper = a[l] == 0;
              if (helper && !quads)
                continue;
              Fragment f;
              f.prim = static_cast<std::uint32_t>(p);
              f.x = x;
              f.y = y;
              f.mask = a[l];
              f.seg = u.seg;
              f.sample = k;
              f.helper = helper;
              if (in.centroid)
                f.centroid = centroid(*in.centroid, lane_c(x, y, a[l]), m, in.pattern);
              if (d)
                f.derivatives = (*d)[l];
              unit_frags.push_back(f);
            }
          }
        }
      }
      out.insert(out.end(), unit_frags.begin(), unit_frags.end());
    }
  }
  // SCENE.OUTPUT.MSAA order: (prim, y, x, seg, sample), a missing seg or sample first.
  const auto key = [](const Fragment& f) {
    return std::make_tuple(f.prim, f.y, f.x, f.seg.has_value(), f.seg.value_or(0),
                           f.sample.has_value(), f.sample.value_or(0));
  };
  std::stable_sort(out.begin(), out.end(),
                   [&](const Fragment& a, const Fragment& b) { return key(a) < key(b); });
  return out;
}

// rule: MSAA.RESOLVE.AVERAGE
std::vector<Rgba> resolve(const Input& in, const std::vector<Fragment>& fragments) {
  check_pattern(in.pattern);
  const std::size_t n = in.pattern.size();
  const auto w = static_cast<std::size_t>(in.width), h = static_cast<std::size_t>(in.height);
  std::vector<std::vector<Rgba>> samples(w * h, std::vector<Rgba>(n, in.clear_color));
  for (const Fragment& f : fragments) {
    if (f.helper)
      continue; // helper lanes write nothing
    if (f.prim >= in.primitives.size() || f.x < 0 || f.y < 0 || f.x >= in.width || f.y >= in.height)
      throw std::invalid_argument("oracle: fragment outside the scene");
    auto& px = samples[static_cast<std::size_t>(f.y) * w + static_cast<std::size_t>(f.x)];
    for (std::size_t k = 0; k < n; ++k) {
      if (f.mask & bit(k))
        px[k] = in.primitives[f.prim].color;
    }
  }
  std::vector<Rgba> out;
  out.reserve(w * h);
  for (const auto& s : samples)
    out.push_back(resolve_pixel(s));
  return out;
}

} // namespace rastrules::oracle::msaa
