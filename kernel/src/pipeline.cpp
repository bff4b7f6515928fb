// SPDX-License-Identifier: MIT
// The pipeline around the rules (spec/rules/pipe.md). Floating-point stages follow the spec's
// fl32/fl64 formulas operation by operation; the kernel is built with -ffp-contract=off so that
// no multiply-add is fused.
#include "rastrules/pipeline.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <utility>

#include "rastrules/formula/depth.hpp"
#include "rastrules/formula/edge.hpp"
#include "rastrules/msaa.hpp"

namespace rastrules::pipe {

// ---------------------------------------------------------------------------------------------
// Transforms and viewport

// rule: PIPE.TRANSFORM.FLOAT32
Vec4f transform(const Mat4f& m, const Vec4f& v) {
  Vec4f r{};
  for (std::size_t row = 0; row < 4; ++row) {
    const float* k = &m[row * 4];
    float acc = k[0] * v[0];
    acc = acc + k[1] * v[1];
    acc = acc + k[2] * v[2];
    acc = acc + k[3] * v[3];
    r[row] = acc;
  }
  return r;
}

// rule: PIPE.VIEWPORT.RANGE
std::optional<std::pair<std::string, std::string>> check_viewport(const Viewport& vp) {
  const auto bad = [](const char* f, const std::string& m) {
    return std::optional<std::pair<std::string, std::string>>{std::pair{std::string(f), m}};
  };
  const std::pair<const char*, float> all[] = {{"x", vp.x},
                                               {"y", vp.y},
                                               {"width", vp.width},
                                               {"height", vp.height},
                                               {"min_depth", vp.min_depth},
                                               {"max_depth", vp.max_depth}};
  for (const auto& [f, v] : all)
    if (!std::isfinite(v))
      return bad(f, "is not finite (PIPE.VIEWPORT.RANGE)");
  if (vp.x < -32768.0f || vp.x > 32767.0f)
    return bad("x", "must lie in [-32768, 32767] (PIPE.VIEWPORT.RANGE)");
  if (vp.y < -32768.0f || vp.y > 32767.0f)
    return bad("y", "must lie in [-32768, 32767] (PIPE.VIEWPORT.RANGE)");
  if (!(vp.width > 0.0f))
    return bad("width", "must be greater than 0 (PIPE.VIEWPORT.RANGE)");
  if (!(vp.height > 0.0f))
    return bad("height", "must be greater than 0 (PIPE.VIEWPORT.RANGE)");
  // The exact sums (not their float32 rounding): TwoSum gives s + err == a + b exactly.
  const auto exact_sum_outside = [](float a, float b) {
    const double x = a, y = b;
    const double s = x + y, bv = s - x, av = s - bv;
    const double err = (x - av) + (y - bv);
    const auto below = [&](double c) { return s < c || (s == c && err < 0.0); };
    const auto above = [&](double c) { return s > c || (s == c && err > 0.0); };
    return below(-32768.0) || above(32767.0);
  };
  if (exact_sum_outside(vp.x, vp.width))
    return bad("width", "x + width must lie in [-32768, 32767] (PIPE.VIEWPORT.RANGE)");
  if (exact_sum_outside(vp.y, vp.height))
    return bad("height", "y + height must lie in [-32768, 32767] (PIPE.VIEWPORT.RANGE)");
  if (vp.min_depth < 0.0f || vp.min_depth > 1.0f)
    return bad("min_depth", "must lie in [0, 1] (PIPE.VIEWPORT.RANGE)");
  if (vp.max_depth < 0.0f || vp.max_depth > 1.0f)
    return bad("max_depth", "must lie in [0, 1] (PIPE.VIEWPORT.RANGE)");
  if (vp.min_depth > vp.max_depth)
    return bad("min_depth", "must not exceed max_depth (PIPE.VIEWPORT.RANGE)");
  return std::nullopt;
}

// rule: PIPE.VIEWPORT.TRANSFORM
WindowVertex to_window(const Vec4f& p, const Viewport& vp) {
  const float xn = p[0] / p[3];
  const float yn = p[1] / p[3];
  float zn = p[2] / p[3];
  // Only without depth clipping can z / w leave the float32 range: it saturates.
  if (std::isinf(zn))
    zn = std::copysign(std::numeric_limits<float>::max(), zn);
  WindowVertex r;
  float t = xn + 1.0f;
  t = t * vp.width;
  t = t * 0.5f;
  r.x = t + vp.x;
  t = 1.0f - yn;
  t = t * vp.height;
  t = t * 0.5f;
  r.y = t + vp.y;
  const float range = vp.max_depth - vp.min_depth;
  const float zs = zn * range;
  r.z = vp.min_depth + zs;
  r.w = p[3];
  return r;
}

// rule: PIPE.VIEWPORT.SCISSOR
ScissorRect viewport_scissor(const Viewport& vp) {
  const float right = vp.x + vp.width;
  const float bottom = vp.y + vp.height;
  return ScissorRect{
      static_cast<std::int64_t>(std::floor(vp.x)), static_cast<std::int64_t>(std::floor(vp.y)),
      static_cast<std::int64_t>(std::floor(right)), static_cast<std::int64_t>(std::floor(bottom))};
}

// ---------------------------------------------------------------------------------------------
// Clipping

namespace {

constexpr int kPlaneCount = 7; // w, x_lo, x_hi, y_lo, y_hi, z_near, z_far

// The signed distance of (x, y, z, w) to plane k, in double (PIPE.CLIP.COMPUTE).
double plane_distance(const ClipVolume& vol, int k, const std::array<double, 4>& p) {
  switch (k) {
  case 0:
    return p[3] - vol.w_min;
  case 1:
    return p[0] - vol.gx_lo * p[3];
  case 2:
    return vol.gx_hi * p[3] - p[0];
  case 3:
    return p[1] - vol.gy_lo * p[3];
  case 4:
    return vol.gy_hi * p[3] - p[1];
  case 5:
    return p[2];
  default:
    return p[3] - p[2];
  }
}

bool plane_active(const ClipVolume& vol, int k) {
  return k < 5 || vol.depth_clip;
}

struct DVertex {
  std::array<double, 4> pos{};
  std::vector<double> attr;
};

DVertex widen(const ClipVertex& v) {
  DVertex d;
  for (std::size_t i = 0; i < 4; ++i)
    d.pos[i] = static_cast<double>(v.pos[i]);
  d.attr.assign(v.attr.begin(), v.attr.end());
  return d;
}

ClipVertex narrow(const DVertex& d) {
  ClipVertex v;
  for (std::size_t i = 0; i < 4; ++i)
    v.pos[i] = static_cast<float>(d.pos[i]);
  v.attr.reserve(d.attr.size());
  for (const double a : d.attr)
    v.attr.push_back(static_cast<float>(a));
  return v;
}

// The intersection of the edge between inside vertex in and outside vertex out with the plane
// whose distances are d_in >= 0 > d_out (PIPE.CLIP.POLYGON): computed from the endpoint nearer
// the plane (the inside one on a tie), so that t <= 1/2 and the result depends only on the two
// endpoints, never on the walking direction; its w raised to w_min if rounding left it below.
DVertex intersect(const DVertex& in, double d_in, const DVertex& out, double d_out, double w_min) {
  const bool from_in = d_in <= -d_out;
  const DVertex& e = from_in ? in : out;
  const DVertex& f = from_in ? out : in;
  const double de = from_in ? d_in : d_out, df = from_in ? d_out : d_in;
  const double t = de / (de - df);
  DVertex r;
  for (std::size_t i = 0; i < 4; ++i)
    r.pos[i] = e.pos[i] + t * (f.pos[i] - e.pos[i]);
  r.attr.resize(e.attr.size());
  for (std::size_t i = 0; i < e.attr.size(); ++i)
    r.attr[i] = e.attr[i] + t * (f.attr[i] - e.attr[i]);
  if (r.pos[3] < w_min)
    r.pos[3] = w_min;
  return r;
}

} // namespace

// rule: PIPE.CLIP.VOLUME
ClipVolume clip_volume(const std::vector<Vec4f>& /*vs*/, const Viewport& vp, bool depth_clip) {
  ClipVolume vol;
  vol.w_min = kWMin;
  const double x0 = vp.x, y0 = vp.y, w = vp.width, h = vp.height;
  vol.gx_lo = (-kGuardBand - x0) * 2.0 / w - 1.0;
  vol.gx_hi = (kGuardBand - x0) * 2.0 / w - 1.0;
  vol.gy_lo = 1.0 - (kGuardBand - y0) * 2.0 / h;
  vol.gy_hi = 1.0 - (-kGuardBand - y0) * 2.0 / h;
  vol.depth_clip = depth_clip;
  return vol;
}

bool inside(const ClipVolume& vol, const Vec4f& p) {
  const std::array<double, 4> d{p[0], p[1], p[2], p[3]};
  for (int k = 0; k < kPlaneCount; ++k)
    if (plane_active(vol, k) && !(plane_distance(vol, k, d) >= 0.0))
      return false;
  return true;
}

// rule: PIPE.CLIP.POLYGON, PIPE.CLIP.COMPUTE, PIPE.CLIP.UNCLIPPED
std::vector<ClipVertex> clip_polygon(const std::vector<ClipVertex>& polygon,
                                     const ClipVolume& vol) {
  if (std::all_of(polygon.begin(), polygon.end(),
                  [&](const ClipVertex& v) { return inside(vol, v.pos); }))
    return polygon;
  std::vector<DVertex> poly;
  poly.reserve(polygon.size());
  for (const ClipVertex& v : polygon)
    poly.push_back(widen(v));
  std::vector<DVertex> next;
  std::vector<double> d;
  for (int k = 0; k < kPlaneCount && !poly.empty(); ++k) {
    if (!plane_active(vol, k))
      continue;
    d.resize(poly.size());
    bool all_in = true;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      d[i] = plane_distance(vol, k, poly[i].pos);
      all_in = all_in && d[i] >= 0.0;
    }
    if (all_in)
      continue;
    next.clear();
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const std::size_t j = (i + 1) % poly.size();
      const bool pin = d[i] >= 0.0, qin = d[j] >= 0.0;
      if (pin)
        next.push_back(poly[i]);
      if (pin && !qin)
        next.push_back(intersect(poly[i], d[i], poly[j], d[j], vol.w_min));
      else if (!pin && qin)
        next.push_back(intersect(poly[j], d[j], poly[i], d[i], vol.w_min));
    }
    poly.swap(next);
  }
  std::vector<ClipVertex> out;
  if (poly.size() < 3)
    return out;
  out.reserve(poly.size());
  for (const DVertex& v : poly)
    out.push_back(narrow(v));
  return out;
}

// rule: PIPE.CLIP.LINE
std::optional<std::array<ClipVertex, 2>> clip_segment(const ClipVertex& a, const ClipVertex& b,
                                                      const ClipVolume& vol) {
  if (inside(vol, a.pos) && inside(vol, b.pos))
    return std::array<ClipVertex, 2>{a, b};
  DVertex p = widen(a), q = widen(b);
  for (int k = 0; k < kPlaneCount; ++k) {
    if (!plane_active(vol, k))
      continue;
    const double dp = plane_distance(vol, k, p.pos);
    const double dq = plane_distance(vol, k, q.pos);
    const bool pin = dp >= 0.0, qin = dq >= 0.0;
    if (!pin && !qin)
      return std::nullopt;
    if (pin && !qin)
      q = intersect(p, dp, q, dq, vol.w_min);
    else if (!pin && qin)
      p = intersect(q, dq, p, dp, vol.w_min);
  }
  return std::array<ClipVertex, 2>{narrow(p), narrow(q)};
}

// ---------------------------------------------------------------------------------------------
// Barycentrics and interpolation

// rule: PIPE.BARY.EXACT
Barycentrics barycentrics(const std::array<Vec2, 3>& v, Vec2 s) {
  const std::int64_t x0 = v[0].x.raw(), y0 = v[0].y.raw(), x1 = v[1].x.raw(), y1 = v[1].y.raw(),
                     x2 = v[2].x.raw(), y2 = v[2].y.raw(), sx = s.x.raw(), sy = s.y.raw();
  Barycentrics b;
  b.e[0] = formula::edge_value<std::int64_t>(x1, y1, x2, y2, sx, sy);
  b.e[1] = formula::edge_value<std::int64_t>(x2, y2, x0, y0, sx, sy);
  b.e[2] = formula::edge_value<std::int64_t>(x0, y0, x1, y1, sx, sy);
  b.area = formula::twice_signed_area<std::int64_t>(x0, y0, x1, y1, x2, y2);
  return b;
}

namespace {

// Rounds a finite double to float32, saturating beyond the float32 range
// (PIPE.INTERP.HORIZON).
float saturate_to_float(double r) {
  constexpr double kMax = static_cast<double>(std::numeric_limits<float>::max());
  if (r > kMax)
    return std::numeric_limits<float>::max();
  if (r < -kMax)
    return -std::numeric_limits<float>::max();
  return static_cast<float>(r);
}

} // namespace

// rule: PIPE.INTERP.PERSPECTIVE, PIPE.INTERP.HORIZON
float interpolate_perspective(const Barycentrics& b, const std::array<float, 3>& a,
                              const std::array<float, 3>& w, float flat) {
  if (b.area == 0)
    return flat;
  const double sign = b.area > 0 ? 1.0 : -1.0;
  std::array<double, 3> eq{};
  for (std::size_t i = 0; i < 3; ++i) {
    const double q = 1.0 / static_cast<double>(w[i]);
    eq[i] = (sign * static_cast<double>(b.e[i])) * q;
  }
  const double den = (eq[0] + eq[1]) + eq[2];
  if (!(den > 0.0) || !std::isfinite(den))
    return flat;
  const double num = (eq[0] * static_cast<double>(a[0]) + eq[1] * static_cast<double>(a[1])) +
                     eq[2] * static_cast<double>(a[2]);
  const double r = num / den;
  if (!std::isfinite(r))
    return flat;
  return saturate_to_float(r);
}

// rule: PIPE.INTERP.LINEAR, PIPE.INTERP.HORIZON
float interpolate_linear(const Barycentrics& b, const std::array<float, 3>& a) {
  if (b.area == 0)
    return a[0];
  const double num = (static_cast<double>(b.e[0]) * static_cast<double>(a[0]) +
                      static_cast<double>(b.e[1]) * static_cast<double>(a[1])) +
                     static_cast<double>(b.e[2]) * static_cast<double>(a[2]);
  return saturate_to_float(num / static_cast<double>(b.area));
}

// ---------------------------------------------------------------------------------------------
// Depth

// rule: PIPE.DEPTH.INTERP
double interpolate_depth(const Barycentrics& b, const std::array<float, 3>& z) {
  if (b.area == 0)
    return static_cast<double>(z[0]);
  const double num = (static_cast<double>(b.e[0]) * static_cast<double>(z[0]) +
                      static_cast<double>(b.e[1]) * static_cast<double>(z[1])) +
                     static_cast<double>(b.e[2]) * static_cast<double>(z[2]);
  return num / static_cast<double>(b.area);
}

// rule: PIPE.DEPTH.CLAMP, PIPE.DEPTH.FORMAT
DepthValue to_depth_format(double z, float min_depth, float max_depth, DepthFormat f) {
  // rule: PIPE.DEPTH.CLAMP
  z = std::min(static_cast<double>(max_depth), std::max(static_cast<double>(min_depth), z));
  DepthValue v;
  switch (f) {
  case DepthFormat::kD16:
  case DepthFormat::kD24: {
    const int bits = f == DepthFormat::kD16 ? formula::kDepthD16Bits : formula::kDepthD24Bits;
    v.unorm = static_cast<std::uint32_t>(std::floor(
        formula::unorm_rounding_argument(z, static_cast<double>(formula::unorm_max(bits)))));
    break;
  }
  case DepthFormat::kD32F:
    v.f = static_cast<float>(z);
    break;
  }
  return v;
}

// rule: PIPE.DEPTH.TEST
bool depth_test(CompareFunc func, const DepthValue& now, const DepthValue& old, DepthFormat f) {
  const auto cmp = [func](auto a, auto b) {
    switch (func) {
    case CompareFunc::kNever:
      return false;
    case CompareFunc::kLess:
      return a < b;
    case CompareFunc::kEqual:
      return a == b;
    case CompareFunc::kLessEqual:
      return a <= b;
    case CompareFunc::kGreater:
      return a > b;
    case CompareFunc::kNotEqual:
      return a != b;
    case CompareFunc::kGreaterEqual:
      return a >= b;
    case CompareFunc::kAlways:
      return true;
    }
    return false;
  };
  return f == DepthFormat::kD32F ? cmp(now.f, old.f) : cmp(now.unorm, old.unorm);
}

// rule: PIPE.DEPTH.BIAS
float depth_bias(const std::array<Vec2, 3>& v, const std::array<float, 3>& z, const DepthBias& bias,
                 std::optional<DepthFormat> format) {
  if (!bias.enabled())
    return 0.0f;
  float slope_term = 0.0f;
  if (bias.slope_scaled != 0.0f) {
    const double dx1 = static_cast<double>(v[1].x.raw() - v[0].x.raw());
    const double dy1 = static_cast<double>(v[1].y.raw() - v[0].y.raw());
    const double dx2 = static_cast<double>(v[2].x.raw() - v[0].x.raw());
    const double dy2 = static_cast<double>(v[2].y.raw() - v[0].y.raw());
    const double den = dx1 * dy2 - dx2 * dy1; // exact: |.| < 2^49
    float max_slope = 0.0f;
    if (den != 0.0) {
      const double dz1 = static_cast<double>(z[1]) - static_cast<double>(z[0]);
      const double dz2 = static_cast<double>(z[2]) - static_cast<double>(z[0]);
      const double ddx = (dz1 * dy2 - dz2 * dy1) * 256.0 / den;
      const double ddy = (dz2 * dx1 - dz1 * dx2) * 256.0 / den;
      max_slope = saturate_to_float(std::max(std::fabs(ddx), std::fabs(ddy)));
    }
    slope_term = saturate_to_float(static_cast<double>(bias.slope_scaled * max_slope));
  }
  float r = 0.0f;
  if (format == DepthFormat::kD32F) {
    float zmax = 0.0f;
    for (const float zi : z)
      zmax = std::max(zmax, std::fabs(zi));
    // exponent() is IEEE's: a subnormal (or zero) has exponent -126.
    int e = -126;
    if (zmax > 0.0f) {
      int fe = 0;
      (void)std::frexp(zmax, &fe); // zmax = f * 2^fe, f in [0.5, 1)
      e = std::max(fe - 1, -126);
    }
    r = std::ldexp(1.0f, e - 23);
  } else {
    const double n = format == DepthFormat::kD16 ? 65535.0 : 16777215.0;
    r = static_cast<float>(1.0 / n);
  }
  const float constant = static_cast<float>(bias.bias) * r;
  float total = saturate_to_float(static_cast<double>(constant + slope_term));
  if (bias.clamp > 0.0f)
    total = std::min(bias.clamp, total);
  else if (bias.clamp < 0.0f)
    total = std::max(bias.clamp, total);
  return total;
}

} // namespace rastrules::pipe
