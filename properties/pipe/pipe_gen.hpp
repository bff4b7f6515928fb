// SPDX-License-Identifier: MIT
// Generators and glue for the pipeline properties: float32 attributes of every magnitude (zero,
// tiny and subnormal, huge up to FLT_MAX, equal triples, mixed signs), clip w with ratios up to
// 1e30 and values near 0, window depths near the format limits, raw triangles (ties, slivers,
// needles, range limits) with evaluation points on vertices and edges, valid viewports (whole
// target, fractional, at the D3D limits, depth ranges near 0 and 1), clip-space vertices
// (inside, on planes, behind the eye, across the guard band, at 2^+-60 scales), matrices, and
// the conversions between the kernel's types (rastrules::pipe) and the oracle's plain ones.
// Implements (generators for): PIPE.BARY.EXACT, PIPE.INTERP.PERSPECTIVE, PIPE.INTERP.LINEAR,
//   PIPE.DEPTH.INTERP, PIPE.TRANSFORM.FLOAT32, PIPE.VIEWPORT.TRANSFORM, PIPE.CLIP.POLYGON

#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <rapidcheck.h>

#include "rastrules/gen/floats.hpp"
#include "rastrules/gen/triangles.hpp"
#include "rastrules/oracle/pipe.hpp"
#include "rastrules/oracle/triangle.hpp"
#include "rastrules/pipeline.hpp"

namespace rastrules::pipe_gen {

namespace op = rastrules::oracle::pipe;
namespace kp = rastrules::pipe;
using Raw2 = op::Raw2;
using RawTri = std::array<Raw2, 3>;

// RapidCheck scales ranges with the test size; these run at full size from the first case.
template <class T> rc::Gen<T> full_size(rc::Gen<T> g) {
  return rc::gen::resize(100, std::move(g));
}

inline constexpr std::int64_t kRawMin = -(std::int64_t{1} << 23);
inline constexpr std::int64_t kRawMax = (std::int64_t{1} << 23) - 1;

// ---------------------------------------------------------------------------------------------
// Printing

inline std::string fs(float v) {
  std::ostringstream os;
  gen::show_float(v, os);
  return os.str();
}
inline std::string fs(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v << " (" << std::hexfloat << v << ")";
  return os.str();
}
template <std::size_t N> std::string fs(const std::array<float, N>& a) {
  std::string s = "[";
  for (std::size_t i = 0; i < N; ++i)
    s += (i ? ", " : "") + fs(a[i]);
  return s + "]";
}
inline std::string fs(const std::vector<float>& a) {
  std::string s = "[";
  for (std::size_t i = 0; i < a.size(); ++i)
    s += (i ? ", " : "") + fs(a[i]);
  return s + "]";
}
inline std::string rs(const Raw2& r) {
  return "(" + std::to_string(r[0]) + ", " + std::to_string(r[1]) + ")";
}
inline std::string rs(const RawTri& t) {
  return rs(t[0]) + " " + rs(t[1]) + " " + rs(t[2]);
}

// ---------------------------------------------------------------------------------------------
// Floats

inline float from_bits(std::uint32_t b) {
  return std::bit_cast<float>(b);
}

// Any finite float (uniform bit pattern, NaN and infinities mapped to their neighbours).
inline rc::Gen<float> any_finite() {
  return rc::gen::map(rc::gen::arbitrary<std::uint32_t>(), [](std::uint32_t b) {
    float f = from_bits(b);
    if (!std::isfinite(f))
      f = std::copysign(std::numeric_limits<float>::max(), f);
    return f;
  });
}

// m * 2^e for a random 24-bit m and e in [lo, hi] (exact, finite for hi <= 104).
inline rc::Gen<float> scaled(int lo, int hi) {
  return rc::gen::apply(
      [](std::int32_t m, int e, bool negative) {
        const float v = std::ldexp(static_cast<float>(m), e);
        return negative ? -v : v;
      },
      rc::gen::inRange<std::int32_t>(1, 1 << 24), rc::gen::inRange(lo, hi + 1),
      rc::gen::arbitrary<bool>());
}

// An attribute value: small integers, [-1, 1], huge (to FLT_MAX), tiny and subnormal, zero,
// any finite bit pattern.
inline rc::Gen<float> attr_value() {
  return rc::gen::weightedOneOf<float>({
      {3, rc::gen::map(rc::gen::inRange(-8, 9), [](int k) { return static_cast<float>(k); })},
      {3, scaled(-24, -24)},   // in (-1, 1)
      {2, scaled(60, 104)},    // 1e25 .. FLT_MAX
      {2, scaled(-149, -120)}, // subnormal and tiny
      {1, rc::gen::element(0.0f, -0.0f, std::numeric_limits<float>::max(),
                           -std::numeric_limits<float>::max(),
                           std::numeric_limits<float>::denorm_min(), 1.0f, -1.0f)},
      {2, any_finite()},
  });
}

// Three attribute values: independent, all equal, two equal, one huge and two tiny, mixed signs
// of equal magnitude.
inline rc::Gen<std::array<float, 3>> attr_triple() {
  return rc::gen::weightedOneOf<std::array<float, 3>>({
      {4, rc::gen::apply(
              [](float a, float b, float c) {
                return std::array<float, 3>{a, b, c};
              },
              attr_value(), attr_value(), attr_value())},
      {1, rc::gen::map(attr_value(),
                       [](float a) {
                         return std::array<float, 3>{a, a, a};
                       })},
      {1, rc::gen::apply(
              [](float a, float b, int k) {
                std::array<float, 3> r{a, a, a};
                r[static_cast<std::size_t>(k)] = b;
                return r;
              },
              attr_value(), attr_value(), rc::gen::inRange(0, 3))},
      {1, rc::gen::apply(
              [](float big, float t0, float t1) {
                return std::array<float, 3>{big, t0, t1};
              },
              scaled(90, 104), scaled(-149, -100), scaled(-149, -100))},
      {1, rc::gen::map(attr_value(),
                       [](float a) {
                         return std::array<float, 3>{a, -a, a};
                       })},
  });
}

// A positive clip w: 1, around 1, any positive magnitude, near 0 (tiny, subnormal).
inline rc::Gen<float> w_value() {
  const auto positive = [](rc::Gen<float> g) {
    return rc::gen::map(std::move(g), [](float f) { return std::fabs(f); });
  };
  return rc::gen::weightedOneOf<float>({
      {2, rc::gen::just(1.0f)},
      {3, positive(scaled(-25, -22))},   // 0.5 .. 4
      {3, positive(scaled(-70, 40))},    // 2^-46 .. 2^64
      {1, positive(scaled(-149, -126))}, // subnormal and the smallest normals
  });
}

// Three w: equal, mild, ratios of 1e6 .. 1e30, one near 0.
inline rc::Gen<std::array<float, 3>> w_triple() {
  return rc::gen::weightedOneOf<std::array<float, 3>>({
      {3, rc::gen::apply(
              [](float a, float b, float c) {
                return std::array<float, 3>{a, b, c};
              },
              w_value(), w_value(), w_value())},
      {1, rc::gen::map(w_value(),
                       [](float a) {
                         return std::array<float, 3>{a, a, a};
                       })},
      {2, rc::gen::apply(
              [](float base, int ratio_exp, int k) {
                std::array<float, 3> r{base, base, base};
                r[static_cast<std::size_t>(k)] = std::ldexp(base, ratio_exp);
                return r;
              },
              rc::gen::element(1.0f, 0.75f, 3.0f),
              rc::gen::element(20, 40, 64, 100, -20, -40, -64, -100), rc::gen::inRange(0, 3))},
  });
}

// A window depth: in [0, 1], at or next to 0 and 1, tiny, and (window-space input) outside.
inline rc::Gen<float> depth_value() {
  return rc::gen::weightedOneOf<float>({
      {3, rc::gen::map(rc::gen::inRange<std::int32_t>(0, (1 << 24) + 1),
                       [](std::int32_t k) { return std::ldexp(static_cast<float>(k), -24); })},
      {2, rc::gen::element(0.0f, 1.0f, std::nextafter(1.0f, 0.0f), std::nextafter(0.0f, 1.0f), 0.5f,
                           std::ldexp(1.0f, -24), 1.0f - std::ldexp(1.0f, -16))},
      {1, rc::gen::map(scaled(-149, -20), [](float f) { return std::fabs(f); })},
      {1, rc::gen::map(scaled(-30, 3), [](float f) { return f; })},
  });
}
inline rc::Gen<std::array<float, 3>> depth_triple() {
  return rc::gen::weightedOneOf<std::array<float, 3>>({
      {4, rc::gen::apply(
              [](float a, float b, float c) {
                return std::array<float, 3>{a, b, c};
              },
              depth_value(), depth_value(), depth_value())},
      {1, rc::gen::map(depth_value(),
                       [](float a) {
                         return std::array<float, 3>{a, a, a};
                       })},
  });
}

// Depth bias states: zero, small and huge constant biases (beyond 2^24, the int32 ends),
// slope factors, clamps of either sign.
inline rc::Gen<kp::DepthBias> depth_bias_state() {
  return rc::gen::exec([] {
    kp::DepthBias b;
    b.bias = *rc::gen::weightedOneOf<std::int32_t>({
        {1, rc::gen::just(0)},
        {3, rc::gen::inRange(-1000, 1001)},
        {1, rc::gen::element(std::int32_t{1} << 24, (std::int32_t{1} << 24) + 1,
                             -(std::int32_t{1} << 25) - 3, std::numeric_limits<std::int32_t>::max(),
                             std::numeric_limits<std::int32_t>::min())},
    });
    b.slope_scaled = *rc::gen::weightedOneOf<float>({
        {1, rc::gen::just(0.0f)},
        {2, rc::gen::map(rc::gen::inRange(-64, 65),
                         [](int k) { return static_cast<float>(k) / 16.0f; })},
        {1, attr_value()},
    });
    b.clamp = *rc::gen::weightedOneOf<float>({
        {2, rc::gen::just(0.0f)},
        {1, rc::gen::map(rc::gen::inRange(-64, 65),
                         [](int k) { return std::ldexp(static_cast<float>(k), -12); })},
    });
    return b;
  });
}

// ---------------------------------------------------------------------------------------------
// Raw triangles and evaluation points

inline Vec2 to_vec2(const Raw2& r) {
  return Vec2{Subpixel::from_raw(static_cast<std::int32_t>(r[0])),
              Subpixel::from_raw(static_cast<std::int32_t>(r[1]))};
}
inline std::array<Vec2, 3> to_vec2(const RawTri& t) {
  return {to_vec2(t[0]), to_vec2(t[1]), to_vec2(t[2])};
}
inline op::Bary to_oracle(const kp::Barycentrics& b) {
  return op::Bary{b.e, b.area};
}

inline std::int64_t twice_area(const RawTri& t) {
  return (t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[1][1] - t[0][1]) * (t[2][0] - t[0][0]);
}

// A triangle of any kind of rastrules::gen (ties, slivers, needles, range limits, degenerate),
// snapped by the oracle; vertices that do not snap are replaced by the range's ends.
inline rc::Gen<RawTri> raw_triangle(bool allow_degenerate) {
  return rc::gen::map(
      gen::triangle_anywhere(24, 24), [allow_degenerate](const gen::GenTriangle& g) {
        RawTri t{};
        for (std::size_t i = 0; i < 3; ++i) {
          for (std::size_t k = 0; k < 2; ++k) {
            const auto r = oracle::snap(g.v[i][k]);
            t[i][k] = r ? *r : (g.v[i][k] > 0.0f ? kRawMax : kRawMin);
          }
        }
        // Move vertices by one raw unit (inward from the range's ends) until the area is not 0.
        const auto step = [](std::int64_t& c) { c += c < kRawMax ? 1 : -1; };
        for (std::size_t k = 0; !allow_degenerate && twice_area(t) == 0 && k < 6; ++k)
          step(t[1 + k % 2][k / 2 % 2]);
        if (!allow_degenerate && twice_area(t) == 0)
          t = RawTri{Raw2{0, 0}, Raw2{256, 0}, Raw2{0, 256}};
        return t;
      });
}

inline Raw2 clamp_raw(Raw2 r) {
  for (auto& c : r)
    c = std::clamp(c, kRawMin, kRawMax);
  return r;
}

// An evaluation point for t: a vertex, a lattice point on an edge, a point of the bounding box,
// the rounded centroid, a pixel centre near the triangle, anywhere in the vertex range.
inline rc::Gen<Raw2> sample_for(const RawTri& t) {
  const std::int64_t x0 = std::min({t[0][0], t[1][0], t[2][0]});
  const std::int64_t x1 = std::max({t[0][0], t[1][0], t[2][0]});
  const std::int64_t y0 = std::min({t[0][1], t[1][1], t[2][1]});
  const std::int64_t y1 = std::max({t[0][1], t[1][1], t[2][1]});
  const auto coord = [](std::int64_t lo, std::int64_t hi) { return rc::gen::inRange(lo, hi + 1); };
  return rc::gen::weightedOneOf<Raw2>({
      {1,
       rc::gen::map(rc::gen::inRange(0, 3), [t](int k) { return t[static_cast<std::size_t>(k)]; })},
      {2, rc::gen::exec([t] {
         const auto k = static_cast<std::size_t>(*rc::gen::inRange(0, 3));
         const Raw2 a = t[k], b = t[(k + 1) % 3];
         const gen::RawPoint ra{static_cast<std::int32_t>(a[0]), static_cast<std::int32_t>(a[1])};
         const gen::RawPoint rb{static_cast<std::int32_t>(b[0]), static_cast<std::int32_t>(b[1])};
         const auto pts = gen::points_on_open_segment(ra, rb, 16);
         if (pts.empty())
           return a;
         const gen::RawPoint p = *rc::gen::elementOf(pts);
         return Raw2{p[0], p[1]};
       })},
      {3, rc::gen::apply(
              [](std::int64_t x, std::int64_t y) {
                return Raw2{x, y};
              },
              coord(x0, x1), coord(y0, y1))},
      {1,
       rc::gen::just(Raw2{(t[0][0] + t[1][0] + t[2][0]) / 3, (t[0][1] + t[1][1] + t[2][1]) / 3})},
      {1, rc::gen::apply(
              [x0, y0](std::int64_t dx, std::int64_t dy) {
                return clamp_raw(Raw2{(x0 / 256 + dx) * 256 + 128, (y0 / 256 + dy) * 256 + 128});
              },
              coord(-2, 6), coord(-2, 6))},
      {1, rc::gen::apply(
              [](std::int64_t x, std::int64_t y) {
                return Raw2{x, y};
              },
              coord(kRawMin, kRawMax), coord(kRawMin, kRawMax))},
  });
}

// ---------------------------------------------------------------------------------------------
// Viewports, positions, matrices

inline op::Viewport to_oracle(const kp::Viewport& v) {
  return op::Viewport{v.x, v.y, v.width, v.height, v.min_depth, v.max_depth};
}

// A depth range: [0, 1], a point, near 0, near 1, random.
inline rc::Gen<std::pair<float, float>> depth_range() {
  const float below1 = std::nextafter(1.0f, 0.0f);
  return rc::gen::weightedOneOf<std::pair<float, float>>({
      {3, rc::gen::just(std::pair{0.0f, 1.0f})},
      {1, rc::gen::element(std::pair{0.0f, std::ldexp(1.0f, -24)}, std::pair{below1, 1.0f},
                           std::pair{1.0f, 1.0f}, std::pair{0.0f, 0.0f}, std::pair{0.5f, 0.5f},
                           std::pair{1.0f - std::ldexp(1.0f, -16), 1.0f})},
      {2, rc::gen::apply(
              [](float a, float b) {
                return std::pair{std::min(a, b), std::max(a, b)};
              },
              rc::gen::map(rc::gen::inRange<std::int32_t>(0, (1 << 24) + 1),
                           [](std::int32_t k) { return std::ldexp(static_cast<float>(k), -24); }),
              rc::gen::map(rc::gen::inRange<std::int32_t>(0, (1 << 24) + 1),
                           [](std::int32_t k) { return std::ldexp(static_cast<float>(k), -24); }))},
  });
}

// A viewport satisfying PIPE.VIEWPORT.RANGE for a width x height target: the whole target, a
// fractional sub-rectangle or larger one, or (wild) one at the D3D limits or of random size.
inline rc::Gen<kp::Viewport> viewport(std::int32_t width, std::int32_t height, bool wild = true) {
  return rc::gen::exec([width, height, wild] {
    kp::Viewport v;
    const int kind = *rc::gen::inRange(0, wild ? 4 : 2);
    const auto frac = [] { return static_cast<float>(*rc::gen::inRange(0, 256)) / 256.0f; };
    if (kind == 0) {
      v.width = static_cast<float>(width);
      v.height = static_cast<float>(height);
    } else if (kind == 1) {
      v.x = static_cast<float>(*rc::gen::inRange(-4, width)) + frac();
      v.y = static_cast<float>(*rc::gen::inRange(-4, height)) + frac();
      v.width = static_cast<float>(*rc::gen::inRange(1, 2 * width + 4)) + frac();
      v.height = static_cast<float>(*rc::gen::inRange(1, 2 * height + 4)) + frac();
    } else if (kind == 2) {
      // At the limits: from -32768 or to 32767.
      v.x = -32768.0f;
      v.width = static_cast<float>(*rc::gen::inRange(32768 + 1, 65536));
      v.y = static_cast<float>(*rc::gen::inRange(-200, height));
      v.height = *rc::gen::element(1.0f, 0.5f, 3.25f, 32767.0f - v.y);
    } else {
      v.x = *rc::gen::map(any_finite(),
                          [](float f) { return std::fmod(std::fabs(f), 64.0f) - 32.0f; });
      v.y = *rc::gen::map(any_finite(),
                          [](float f) { return std::fmod(std::fabs(f), 64.0f) - 32.0f; });
      v.width = *rc::gen::map(any_finite(),
                              [](float f) { return std::fmod(std::fabs(f), 100.0f) + 0.125f; });
      v.height = *rc::gen::map(any_finite(),
                               [](float f) { return std::fmod(std::fabs(f), 100.0f) + 0.125f; });
    }
    const auto [lo, hi] = *depth_range();
    v.min_depth = lo;
    v.max_depth = hi;
    RC_PRE(!kp::check_viewport(v).has_value());
    return v;
  });
}

// A clip-space position with |coordinates| <= 2^64.
inline rc::Gen<kp::Vec4f> clip_vertex() {
  return rc::gen::exec([] {
    const int kind = *rc::gen::inRange(0, 9);
    const auto unit = [] { return static_cast<float>(*rc::gen::inRange(-1024, 1025)) / 256.0f; };
    kp::Vec4f p{};
    switch (kind) {
    case 0: { // inside: x, y in [-w, w], z in [0, w]
      const float w = *rc::gen::element(1.0f, 0.5f, 2.0f, 3.75f);
      p = {unit() / 4.0f * w, unit() / 4.0f * w, std::fabs(unit()) / 4.0f * w, w};
      break;
    }
    case 1: // anywhere around the view, w of either sign
      p = {unit(), unit(), unit(), unit()};
      break;
    case 2: { // across the guard band: |x/w| up to 2^20
      const float w = *rc::gen::element(1.0f, 0.25f, 4.0f);
      p = {std::ldexp(unit(), *rc::gen::inRange(8, 21)) * w, unit() * w,
           std::fabs(unit()) / 4.0f * w, w};
      if (*rc::gen::arbitrary<bool>())
        std::swap(p[0], p[1]);
      break;
    }
    case 3: { // on a plane: z = 0, z = w, x = +-w, y = +-w
      const float w = *rc::gen::element(1.0f, 0.5f, 2.0f);
      p = {unit() / 4.0f * w, unit() / 4.0f * w, std::fabs(unit()) / 4.0f * w, w};
      const int which = *rc::gen::inRange(0, 4);
      if (which == 0)
        p[2] = 0.0f;
      if (which == 1)
        p[2] = w;
      if (which == 2)
        p[0] = *rc::gen::element(w, -w);
      if (which == 3)
        p[1] = *rc::gen::element(w, -w);
      break;
    }
    case 4: { // w near 0, or tiny against the other coordinates
      const float w = *rc::gen::element(0.0f, std::ldexp(1.0f, -40), std::ldexp(1.0f, -20),
                                        -std::ldexp(1.0f, -30), 1e-6f, std::ldexp(1.0f, -149));
      p = {unit(), unit(), std::fabs(unit()), w};
      break;
    }
    case 5: { // one scale 2^k for the whole vertex, k in [-60, 60]
      const int k = *rc::gen::inRange(-60, 61);
      p = {std::ldexp(unit(), k), std::ldexp(unit(), k), std::ldexp(std::fabs(unit()), k),
           std::ldexp(std::fabs(unit()) + 0.0625f, k)};
      break;
    }
    case 6: // raw random coordinates of any size up to 2^64
      for (auto& c : p)
        c = *scaled(-80, 40);
      break;
    case 7: { // tiny: the whole vertex scaled by 2^k, k in [-150, -100] (into the subnormals)
      const int k = *rc::gen::inRange(-150, -99);
      p = {std::ldexp(unit(), k), std::ldexp(unit(), k), std::ldexp(std::fabs(unit()), k),
           std::ldexp(unit(), k)};
      break;
    }
    default: // behind the eye
      p = {unit(), unit(), unit(), -std::fabs(unit()) - 0.125f};
      break;
    }
    return p;
  });
}

inline rc::Gen<kp::Mat4f> matrix() {
  return rc::gen::exec([] {
    const int kind = *rc::gen::inRange(0, 4);
    kp::Mat4f m{};
    if (kind == 0) { // identity with small integer or float perturbations
      for (std::size_t i = 0; i < 4; ++i)
        m[5 * i] = 1.0f;
      for (int k = *rc::gen::inRange(0, 4); k > 0; --k)
        m[static_cast<std::size_t>(*rc::gen::inRange(0, 16))] = *attr_value();
    } else if (kind == 1) { // a perspective projection (D3D: z in [0, w])
      const float f = *rc::gen::element(1.0f, 1.7320508f, 0.5f, 3.0f);
      const float n = *rc::gen::element(0.1f, 1.0f, 0.01f);
      const float fa = *rc::gen::element(100.0f, 10.0f, 1e6f);
      m = {f, 0, 0, 0, 0, f, 0, 0, 0, 0, fa / (fa - n), -n * fa / (fa - n), 0, 0, 1, 0};
    } else if (kind == 2) { // small values
      for (auto& c : m)
        c = static_cast<float>(*rc::gen::inRange(-16, 17)) / 8.0f;
    } else {
      for (auto& c : m)
        c = *scaled(-30, 10);
    }
    return m;
  });
}

// Whether every coordinate is finite with magnitude <= 2^64 (PIPE.INPUT.POSITION).
inline bool position_ok(const kp::Vec4f& p) {
  for (const float c : p) {
    if (!std::isfinite(c) || std::fabs(static_cast<double>(c)) > kp::kMaxPosition)
      return false;
  }
  return true;
}

inline std::string vs(const kp::Vec4f& p) {
  return fs(p);
}

inline op::Volume to_oracle(const kp::ClipVolume& v) {
  return op::Volume{v.w_min, v.gx_lo, v.gx_hi, v.gy_lo, v.gy_hi, v.depth_clip};
}

inline std::vector<op::ClipVertex> to_oracle(const std::vector<kp::ClipVertex>& vs) {
  std::vector<op::ClipVertex> out;
  for (const kp::ClipVertex& v : vs)
    out.push_back(op::ClipVertex{v.pos, v.attr});
  return out;
}

inline bool same_bits(float a, float b) {
  return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b) ||
         (std::isnan(a) && std::isnan(b));
}
inline bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b) ||
         (std::isnan(a) && std::isnan(b));
}

// The spec's names, spelled here rather than taken from the kernel's to_string().
inline std::string depth_format_name(kp::DepthFormat f) {
  switch (f) {
  case kp::DepthFormat::kD16:
    return "d16";
  case kp::DepthFormat::kD24:
    return "d24";
  case kp::DepthFormat::kD32F:
    return "d32f";
  }
  return "?";
}
inline std::string compare_name(kp::CompareFunc f) {
  switch (f) {
  case kp::CompareFunc::kNever:
    return "never";
  case kp::CompareFunc::kLess:
    return "less";
  case kp::CompareFunc::kEqual:
    return "equal";
  case kp::CompareFunc::kLessEqual:
    return "less_equal";
  case kp::CompareFunc::kGreater:
    return "greater";
  case kp::CompareFunc::kNotEqual:
    return "not_equal";
  case kp::CompareFunc::kGreaterEqual:
    return "greater_equal";
  case kp::CompareFunc::kAlways:
    return "always";
  }
  return "?";
}
inline rc::Gen<kp::DepthFormat> depth_format() {
  return rc::gen::element(kp::DepthFormat::kD16, kp::DepthFormat::kD24, kp::DepthFormat::kD32F);
}
inline rc::Gen<kp::CompareFunc> compare_func() {
  return rc::gen::element(kp::CompareFunc::kNever, kp::CompareFunc::kLess, kp::CompareFunc::kEqual,
                          kp::CompareFunc::kLessEqual, kp::CompareFunc::kGreater,
                          kp::CompareFunc::kNotEqual, kp::CompareFunc::kGreaterEqual,
                          kp::CompareFunc::kAlways);
}
inline op::Stored to_oracle(const kp::DepthValue& d) {
  return op::Stored{d.unorm, d.f};
}

} // namespace rastrules::pipe_gen

// How RapidCheck prints the kernel's viewport in counterexamples (found by argument-dependent
// lookup, so it lives in the kernel's namespace; it is property code, not kernel code).
namespace rastrules::pipe {
inline void showValue(const Viewport& v, std::ostream& os) {
  os << "{x " << pipe_gen::fs(v.x) << ", y " << pipe_gen::fs(v.y) << ", width "
     << pipe_gen::fs(v.width) << ", height " << pipe_gen::fs(v.height) << ", depth ["
     << pipe_gen::fs(v.min_depth) << ", " << pipe_gen::fs(v.max_depth) << "]}";
}
inline void showValue(DepthFormat f, std::ostream& os) {
  os << pipe_gen::depth_format_name(f);
}
inline void showValue(CompareFunc f, std::ostream& os) {
  os << pipe_gen::compare_name(f);
}
} // namespace rastrules::pipe
