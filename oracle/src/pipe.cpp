// SPDX-License-Identifier: MIT
// Exact oracle for the pipeline (rastrules/oracle/pipe.hpp), written from spec/rules/pipe.md.
// Every arithmetic step is an exact GMP rational; the spec's fl32()/fl64() formulas round each
// step with round_binary() below (round to nearest, ties to even, subnormals and overflow as
// IEEE 754 binary32/binary64 define them), never with the hardware's float unit.

#include "rastrules/oracle/pipe.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rastrules::oracle::pipe {
namespace {

using Q = mpq_class;
using Z = mpz_class;

// ---------------------------------------------------------------------------------------------
// Exact rationals and rounding

Q exact(double d) {
  if (!std::isfinite(d))
    throw std::logic_error("oracle: exact() of a non-finite value");
  return Q(d); // mpq_set_d is exact
}
Q exact_i(std::int64_t v) {
  return Q(Z(static_cast<long>(v)));
}

// 2^e as a rational, any sign of e.
Q pow2(long e) {
  Z one(1);
  Z p;
  if (e >= 0) {
    mpz_mul_2exp(p.get_mpz_t(), one.get_mpz_t(), static_cast<mp_bitcnt_t>(e));
    return Q(p);
  }
  mpz_mul_2exp(p.get_mpz_t(), one.get_mpz_t(), static_cast<mp_bitcnt_t>(-e));
  Q r(one, p);
  r.canonicalize();
  return r;
}

// floor(log2(a)) for a > 0.
long floor_log2(const Q& a) {
  const long nb = static_cast<long>(mpz_sizeinbase(a.get_num_mpz_t(), 2));
  const long db = static_cast<long>(mpz_sizeinbase(a.get_den_mpz_t(), 2));
  const long e = nb - db; // a in [2^(e - 1), 2^(e + 1))
  return a >= pow2(e) ? e : e - 1;
}

Z floor_q(const Q& q) {
  Z r;
  mpz_fdiv_q(r.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
  return r;
}

// The integer nearest to q, ties to even.
Z round_half_even(const Q& q) {
  const Z fl = floor_q(q);
  const Q frac = q - Q(fl);
  const Q half(1, 2);
  if (frac < half)
    return fl;
  if (frac > half)
    return fl + 1;
  return mpz_even_p(fl.get_mpz_t()) != 0 ? fl : Z(fl + 1);
}

Q abs_q(const Q& q) {
  return q < 0 ? Q(-q) : q;
}

// The binary floating-point value nearest to q (p significand bits, normal exponents
// [emin, emax], subnormals below), ties to even; +-infinity when it overflows. A nonzero q that
// rounds to zero keeps its sign. Returned as a double (binary32 values are doubles exactly).
double round_binary(const Q& q, long p, long emin, long emax) {
  const int sign = sgn(q);
  if (sign == 0)
    return 0.0;
  const Q a = abs_q(q);
  long e = floor_log2(a);
  if (e < emin)
    e = emin;                     // subnormal: the spacing of the smallest binade
  const long shift = e - (p - 1); // the spacing is 2^shift
  const Z n = round_half_even(a * pow2(-shift));
  if (n == 0)
    return sign < 0 ? -0.0 : 0.0;
  // n * 2^shift >= 2^(emax + 1) overflows.
  const long top = static_cast<long>(mpz_sizeinbase(n.get_mpz_t(), 2)) - 1 + shift;
  if (top > emax) {
    return sign < 0 ? -std::numeric_limits<double>::infinity()
                    : std::numeric_limits<double>::infinity();
  }
  const double mag = std::ldexp(n.get_d(), static_cast<int>(shift)); // n < 2^54: exact
  return sign < 0 ? -mag : mag;
}

float rn32(const Q& q) {
  return static_cast<float>(round_binary(q, 24, -126, 127));
}
double rn64(const Q& q) {
  return round_binary(q, 53, -1022, 1023);
}

bool neg(double d) {
  return std::signbit(d);
}

// fl32(x - y) and fl64(x - y): x + (-y) exactly as IEEE 754 defines subtraction.
float fl32_sub(float a, float b) {
  return fl32_add(a, -b);
}
double fl64_sub(double a, double b) {
  return fl64_add(a, -b);
}

// Exactly: ulp32 of the exact value x.
Q ulp32_q(const Q& x) {
  if (x == 0)
    return pow2(-149);
  long e = floor_log2(abs_q(x));
  if (e < -126)
    e = -126;
  return pow2(e - 23);
}

Q clamp_q(const Q& v, const Q& lo, const Q& hi) {
  return v < lo ? lo : (v > hi ? hi : v);
}

std::string show(double d) {
  std::ostringstream os;
  os << std::setprecision(17) << d << " (" << std::hexfloat << d << ")";
  return os.str();
}

} // namespace

// ---------------------------------------------------------------------------------------------
// Rounding

namespace {

enum class Op { kMul, kAdd, kDiv };

// fl(a op b) in T (float or double): the exact result rounded once. Infinities, NaN and
// division by zero involve no rounding and are left to the hardware's IEEE 754 rules. An exact
// zero takes IEEE's sign: the XOR of the signs for * and /; +0 for a sum unless both are -0.
template <class T> T rounded(T a, T b, Op op) {
  if (!std::isfinite(a) || !std::isfinite(b) || (op == Op::kDiv && b == T(0)))
    return op == Op::kMul ? a * b : (op == Op::kAdd ? a + b : a / b);
  const Q r = op == Op::kMul ? Q(exact(a) * exact(b))
                             : (op == Op::kAdd ? Q(exact(a) + exact(b)) : Q(exact(a) / exact(b)));
  if (r == 0) {
    const bool negative = op == Op::kAdd ? (neg(a) && neg(b)) : (neg(a) != neg(b));
    return negative ? -T(0) : T(0);
  }
  if constexpr (sizeof(T) == sizeof(float))
    return rn32(r);
  else
    return rn64(r);
}

} // namespace

float fl32_mul(float a, float b) {
  return rounded(a, b, Op::kMul);
}
float fl32_add(float a, float b) {
  return rounded(a, b, Op::kAdd);
}
float fl32_div(float a, float b) {
  return rounded(a, b, Op::kDiv);
}
double fl64_mul(double a, double b) {
  return rounded(a, b, Op::kMul);
}
double fl64_add(double a, double b) {
  return rounded(a, b, Op::kAdd);
}
double fl64_div(double a, double b) {
  return rounded(a, b, Op::kDiv);
}

float nearest_float(double d) {
  if (!std::isfinite(d))
    return static_cast<float>(d);
  const Q r = exact(d);
  if (r == 0)
    return neg(d) ? -0.0f : 0.0f;
  return rn32(r);
}

double ulp32(double x) {
  if (!std::isfinite(x))
    throw std::invalid_argument("oracle: ulp32 of a non-finite value");
  return rn64(ulp32_q(exact(x))); // a power of two: exact
}

// ---------------------------------------------------------------------------------------------
// Transforms and viewport

// Row r: fl32(((m[r][0]*x + m[r][1]*y) + m[r][2]*z) + m[r][3]*w), every step rounded.
// rule: PIPE.TRANSFORM.FLOAT32
Vec4 transform(const Mat4& m, const Vec4& v) {
  Vec4 out{};
  for (std::size_t r = 0; r < 4; ++r) {
    float acc = fl32_mul(m[4 * r + 0], v[0]);
    acc = fl32_add(acc, fl32_mul(m[4 * r + 1], v[1]));
    acc = fl32_add(acc, fl32_mul(m[4 * r + 2], v[2]));
    acc = fl32_add(acc, fl32_mul(m[4 * r + 3], v[3]));
    out[r] = acc;
  }
  return out;
}

// xn = fl32(x / w), ...; Xrt = fl32((xn + 1) * W * 0.5 + X0) evaluated left to right;
// Yrt = fl32((1 - yn) * H * 0.5 + Y0); Zrt = fl32(MinDepth + zn * (MaxDepth - MinDepth)).
// rule: PIPE.VIEWPORT.TRANSFORM
WindowVertex to_window(const Vec4& p, const Viewport& vp) {
  const float xn = fl32_div(p[0], p[3]);
  const float yn = fl32_div(p[1], p[3]);
  float zn = fl32_div(p[2], p[3]);
  // Beyond float32 (only without depth clipping) zn saturates (PIPE.VIEWPORT.TRANSFORM).
  if (std::isinf(zn))
    zn = zn > 0 ? FLT_MAX : -FLT_MAX;
  WindowVertex out;
  out.x = fl32_add(fl32_mul(fl32_mul(fl32_add(xn, 1.0f), vp.width), 0.5f), vp.x);
  out.y = fl32_add(fl32_mul(fl32_mul(fl32_sub(1.0f, yn), vp.height), 0.5f), vp.y);
  out.z = fl32_add(vp.min_depth, fl32_mul(zn, fl32_sub(vp.max_depth, vp.min_depth)));
  out.w = p[3];
  return out;
}

// rule: PIPE.VIEWPORT.SCISSOR
Rect viewport_scissor(const Viewport& vp) {
  const auto fl = [](float v) { return static_cast<std::int64_t>(floor_q(exact(v)).get_si()); };
  return Rect{fl(vp.x), fl(vp.y), fl(fl32_add(vp.x, vp.width)), fl(fl32_add(vp.y, vp.height))};
}

// ---------------------------------------------------------------------------------------------
// Clipping with the spec's double formulas

// rule: PIPE.CLIP.VOLUME
Volume clip_volume(const std::vector<Vec4>& vs, const Viewport& vp, bool depth_clip) {
  Volume vol;
  vol.depth_clip = depth_clip;
  (void)vs; // the volume does not depend on the primitive (PIPE.CLIP.VOLUME)
  vol.w_min = rn64(pow2(kWMinLog2)); // a power of two: exact
  const double g = kGuardBand;
  const double x0 = vp.x, y0 = vp.y, w = vp.width, h = vp.height;
  // gx_lo = fl64((-G - X0) * 2 / W - 1), gx_hi = fl64((G - X0) * 2 / W - 1),
  // gy_lo = fl64(1 - (G - Y0) * 2 / H), gy_hi = fl64(1 - (-G - Y0) * 2 / H).
  vol.gx_lo = fl64_sub(fl64_div(fl64_mul(fl64_sub(-g, x0), 2.0), w), 1.0);
  vol.gx_hi = fl64_sub(fl64_div(fl64_mul(fl64_sub(g, x0), 2.0), w), 1.0);
  vol.gy_lo = fl64_sub(1.0, fl64_div(fl64_mul(fl64_sub(g, y0), 2.0), h));
  vol.gy_hi = fl64_sub(1.0, fl64_div(fl64_mul(fl64_sub(-g, y0), 2.0), h));
  return vol;
}

namespace {

constexpr std::size_t kPlaneCount = 7; // w, x_lo, x_hi, y_lo, y_hi, z_near, z_far

bool plane_used(const Volume& vol, std::size_t plane) {
  return plane < 5 || vol.depth_clip;
}

// A vertex between planes: doubles (PIPE.CLIP.COMPUTE rounds to float32 once, at the end).
struct DVertex {
  std::array<double, 4> pos{};
  std::vector<double> attr;
};

// The fl64 signed distance of p to plane: w - kWMin, x - gx_lo*w, gx_hi*w - x, y - gy_lo*w,
// gy_hi*w - y, z, w - z.
// rule: PIPE.CLIP.COMPUTE
double distance(const Volume& vol, std::size_t plane, const std::array<double, 4>& p) {
  const double x = p[0], y = p[1], z = p[2], w = p[3];
  switch (plane) {
  case 0:
    return fl64_sub(w, vol.w_min);
  case 1:
    return fl64_sub(x, fl64_mul(vol.gx_lo, w));
  case 2:
    return fl64_sub(fl64_mul(vol.gx_hi, w), x);
  case 3:
    return fl64_sub(y, fl64_mul(vol.gy_lo, w));
  case 4:
    return fl64_sub(fl64_mul(vol.gy_hi, w), y);
  case 5:
    return z;
  default:
    return fl64_sub(w, z);
  }
}

// fl64(i + fl64(t * fl64(o - i))).
double lerp_component(double i, double o, double t) {
  return fl64_add(i, fl64_mul(t, fl64_sub(o, i)));
}

std::array<double, 4> widen(const Vec4& p) {
  return {p[0], p[1], p[2], p[3]};
}

} // namespace

bool inside(const Volume& vol, const Vec4& p) {
  for (std::size_t k = 0; k < kPlaneCount; ++k) {
    if (plane_used(vol, k) && !(distance(vol, k, widen(p)) >= 0.0))
      return false;
  }
  return true;
}

namespace {
// The intersection of the edge (in, out), d_in >= 0 > d_out, with a plane, as PIPE.CLIP.POLYGON
// computes it: from the endpoint e nearer the plane (|d_e| smaller; the inside one on a tie),
// e + t (f - e) with t = d_e / (d_e - d_f) in fl64, then w raised to kWMin when below.
DVertex cut_edge(const Volume& vol, const DVertex& in, double d_in, const DVertex& out,
                 double d_out) {
  const bool from_in = !(fl64_add(d_in, d_out) > 0.0); // d_in <= -d_out, exactly
  const DVertex& e = from_in ? in : out;
  const DVertex& f = from_in ? out : in;
  const double de = from_in ? d_in : d_out, df = from_in ? d_out : d_in;
  const double t = fl64_div(de, fl64_sub(de, df));
  DVertex v;
  for (std::size_t c = 0; c < 4; ++c)
    v.pos[c] = lerp_component(e.pos[c], f.pos[c], t);
  v.attr.resize(e.attr.size());
  for (std::size_t a = 0; a < e.attr.size(); ++a)
    v.attr[a] = lerp_component(e.attr[a], f.attr.at(a), t);
  if (v.pos[3] < vol.w_min)
    v.pos[3] = vol.w_min;
  return v;
}
} // namespace

// rule: PIPE.CLIP.POLYGON, PIPE.CLIP.COMPUTE
std::vector<ClipVertex> clip_polygon(const std::vector<ClipVertex>& polygon, const Volume& vol) {
  std::vector<DVertex> cur;
  for (const ClipVertex& v : polygon) {
    DVertex d{widen(v.pos), {}};
    for (const float a : v.attr)
      d.attr.push_back(a);
    cur.push_back(std::move(d));
  }
  for (std::size_t plane = 0; plane < kPlaneCount && !cur.empty(); ++plane) {
    if (!plane_used(vol, plane))
      continue;
    std::vector<DVertex> next;
    const std::size_t n = cur.size();
    for (std::size_t i = 0; i < n; ++i) {
      const DVertex& p = cur[i];
      const DVertex& q = cur[(i + 1) % n];
      const double dp = distance(vol, plane, p.pos);
      const double dq = distance(vol, plane, q.pos);
      const bool pin = dp >= 0.0, qin = dq >= 0.0;
      if (pin)
        next.push_back(p);
      if (pin != qin) {
        // From the endpoint e nearer the plane (the inside one on a tie) towards the other f:
        // e + t (f - e), t = d_e / (d_e - d_f), whichever of p, q comes first in the walk;
        // w raised to kWMin when rounding left it below.
        next.push_back(cut_edge(vol, pin ? p : q, pin ? dp : dq, pin ? q : p, pin ? dq : dp));
      }
    }
    cur = std::move(next);
  }
  // Fewer than 3 vertices draw no fan triangle: the triangle is discarded.
  std::vector<ClipVertex> out;
  if (cur.size() < 3)
    return out;
  for (const DVertex& d : cur) {
    ClipVertex v;
    for (std::size_t c = 0; c < 4; ++c)
      v.pos[c] = nearest_float(d.pos[c]);
    for (const double a : d.attr)
      v.attr.push_back(nearest_float(a));
    out.push_back(std::move(v));
  }
  return out;
}

// rule: PIPE.CLIP.LINE, PIPE.CLIP.COMPUTE
std::optional<std::array<ClipVertex, 2>> clip_segment(const ClipVertex& a, const ClipVertex& b,
                                                      const Volume& vol) {
  const auto to_d = [](const ClipVertex& v) {
    DVertex d{widen(v.pos), {}};
    for (const float x : v.attr)
      d.attr.push_back(x);
    return d;
  };
  std::array<DVertex, 2> e{to_d(a), to_d(b)};
  for (std::size_t plane = 0; plane < kPlaneCount; ++plane) {
    if (!plane_used(vol, plane))
      continue;
    const double d0 = distance(vol, plane, e[0].pos), d1 = distance(vol, plane, e[1].pos);
    const bool in0 = d0 >= 0.0, in1 = d1 >= 0.0;
    if (!in0 && !in1)
      return std::nullopt;
    if (in0 == in1)
      continue;
    // Move the outside endpoint to the intersection (cut_edge: from the nearer endpoint).
    const std::size_t o = in0 ? 1 : 0, i = 1 - o;
    const double di = in0 ? d0 : d1, dout = in0 ? d1 : d0;
    e[o] = cut_edge(vol, e[i], di, e[o], dout);
  }
  std::array<ClipVertex, 2> out;
  for (std::size_t j = 0; j < 2; ++j) {
    for (std::size_t c = 0; c < 4; ++c)
      out[j].pos[c] = nearest_float(e[j].pos[c]);
    for (const double x : e[j].attr)
      out[j].attr.push_back(nearest_float(x));
  }
  return out;
}

// rule: PIPE.VIEWPORT.RANGE
std::vector<std::string> viewport_violations(const Viewport& vp) {
  std::vector<std::string> out;
  const Q lo(-32768), hi(32767);
  const auto in_range = [&](float v) {
    return std::isfinite(v) && exact(v) >= lo && exact(v) <= hi;
  };
  const auto axis = [&](float origin, float size, const char* o, const char* sz) {
    if (!in_range(origin))
      out.emplace_back(o);
    if (!std::isfinite(size) || !(size > 0.0f)) {
      out.emplace_back(sz);
    } else if (std::isfinite(origin)) {
      const Q end = exact(origin) + exact(size);
      if (end < lo || end > hi) {
        out.emplace_back(o);
        out.emplace_back(sz);
      }
    }
  };
  axis(vp.x, vp.width, "x", "width");
  axis(vp.y, vp.height, "y", "height");
  const auto unit = [](float v) { return std::isfinite(v) && v >= 0.0f && v <= 1.0f; };
  if (!unit(vp.min_depth))
    out.emplace_back("min_depth");
  if (!unit(vp.max_depth))
    out.emplace_back("max_depth");
  if (unit(vp.min_depth) && unit(vp.max_depth) && vp.min_depth > vp.max_depth) {
    out.emplace_back("min_depth");
    out.emplace_back("max_depth");
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Exact projection and the exact clipper

namespace {

using QPoint = std::array<Q, 2>; // window position in raw 16.8 units
using QVec4 = std::array<Q, 4>;

// Exact window x, y in raw units (256 per pixel), and z.
std::array<Q, 3> project_q(const QVec4& p, const Viewport& vp) {
  const Q half(1, 2);
  const Q x = (p[0] / p[3] + 1) * exact(vp.width) * half + exact(vp.x);
  const Q y = (1 - p[1] / p[3]) * exact(vp.height) * half + exact(vp.y);
  const Q z = exact(vp.min_depth) + p[2] / p[3] * (exact(vp.max_depth) - exact(vp.min_depth));
  return {x * 256, y * 256, z};
}

QVec4 exact4(const Vec4& v) {
  return {exact(v[0]), exact(v[1]), exact(v[2]), exact(v[3])};
}

// The exact signed distance to plane (coefficients: vol's doubles taken exactly).
Q distance_q(const Volume& vol, std::size_t plane, const QVec4& p) {
  switch (plane) {
  case 0:
    return p[3] - exact(vol.w_min);
  case 1:
    return p[0] - exact(vol.gx_lo) * p[3];
  case 2:
    return exact(vol.gx_hi) * p[3] - p[0];
  case 3:
    return p[1] - exact(vol.gy_lo) * p[3];
  case 4:
    return exact(vol.gy_hi) * p[3] - p[1];
  case 5:
    return p[2];
  default:
    return p[3] - p[2];
  }
}

std::optional<std::int64_t> to_i64(const Z& z) {
  if (!z.fits_slong_p())
    return std::nullopt;
  return static_cast<std::int64_t>(z.get_si());
}

// E_ab(s) = (bx - ax)(sy - ay) - (by - ay)(sx - ax).
Q edge_q(const QPoint& a, const QPoint& b, const QPoint& s) {
  return (b[0] - a[0]) * (s[1] - a[1]) - (b[1] - a[1]) * (s[0] - a[0]);
}

Q dist2_point(const QPoint& a, const QPoint& s) {
  const Q dx = s[0] - a[0], dy = s[1] - a[1];
  return dx * dx + dy * dy;
}

// Squared Euclidean distance of s to the closed segment ab.
Q dist2_segment(const QPoint& a, const QPoint& b, const QPoint& s) {
  const Q ex = b[0] - a[0], ey = b[1] - a[1];
  const Q len2 = ex * ex + ey * ey;
  if (len2 == 0)
    return dist2_point(a, s);
  const Q dot = (s[0] - a[0]) * ex + (s[1] - a[1]) * ey;
  if (dot <= 0)
    return dist2_point(a, s);
  if (dot >= len2)
    return dist2_point(b, s);
  const Q cross = edge_q(a, b, s);
  return cross * cross / len2;
}

} // namespace

ExactWindow project_exact(const Vec4& p, const Viewport& vp) {
  if (!(p[3] > 0.0f))
    throw std::invalid_argument("oracle: project_exact needs w > 0");
  const auto q = project_q(exact4(p), vp);
  ExactWindow out;
  out.x = rn64(q[0] / 256);
  out.y = rn64(q[1] / 256);
  out.z = rn64(q[2]);
  out.raw_x = to_i64(round_half_even(q[0]));
  out.raw_y = to_i64(round_half_even(q[1]));
  return out;
}

std::optional<std::int64_t> snap_unbounded(double v) {
  if (!std::isfinite(v))
    return std::nullopt;
  return to_i64(round_half_even(exact(v) * 256));
}

struct ExactRegion::Impl {
  std::vector<QPoint> v;
  std::vector<int> origin; // of edge (v_i, v_i+1)
};

ExactRegion::ExactRegion(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
ExactRegion::ExactRegion(const ExactRegion& o) : impl_(std::make_unique<Impl>(*o.impl_)) {}
ExactRegion& ExactRegion::operator=(const ExactRegion& o) {
  if (this != &o)
    impl_ = std::make_unique<Impl>(*o.impl_);
  return *this;
}
ExactRegion::ExactRegion(ExactRegion&&) noexcept = default;
ExactRegion& ExactRegion::operator=(ExactRegion&&) noexcept = default;
ExactRegion::~ExactRegion() = default;

// rule: PIPE.CLIP.GUARD_BAND_BOUND
ExactRegion ExactRegion::unclipped_triangle(const std::array<Vec4, 3>& clip, const Viewport& vp) {
  auto impl = std::make_unique<Impl>();
  for (const Vec4& c : clip) {
    if (!(c[3] > 0.0f))
      throw std::invalid_argument("oracle: unclipped_triangle needs w > 0");
    const auto q = project_q(exact4(c), vp);
    impl->v.push_back({Q(round_half_even(q[0])), Q(round_half_even(q[1]))});
  }
  impl->origin = {0, 1, 2};
  return ExactRegion(std::move(impl));
}

// The same Sutherland-Hodgman walk as clip_polygon, with exact distances, t and vertices.
// rule: PIPE.CLIP.POLYGON, PIPE.CLIP.GUARD_BAND_BOUND
ExactRegion ExactRegion::clipped_polygon(const std::array<Vec4, 3>& clip, const Volume& vol,
                                         const Viewport& vp) {
  // Each vertex carries the origin of its outgoing edge (to the next vertex).
  std::vector<std::pair<QVec4, int>> cur;
  for (std::size_t i = 0; i < 3; ++i)
    cur.emplace_back(exact4(clip[i]), static_cast<int>(i));
  for (std::size_t plane = 0; plane < kPlaneCount && !cur.empty(); ++plane) {
    if (!plane_used(vol, plane))
      continue;
    std::vector<std::pair<QVec4, int>> next;
    const std::size_t n = cur.size();
    for (std::size_t i = 0; i < n; ++i) {
      const QVec4& p = cur[i].first;
      const QVec4& q = cur[(i + 1) % n].first;
      const int edge = cur[i].second;
      const Q dp = distance_q(vol, plane, p), dq = distance_q(vol, plane, q);
      const bool pin = dp >= 0, qin = dq >= 0;
      if (pin)
        next.emplace_back(p, edge); // to q or to the intersection: the same line
      if (pin != qin) {
        // The exact intersection does not depend on the direction; kept as the spec writes it.
        const QVec4& in = pin ? p : q;
        const QVec4& out = pin ? q : p;
        const Q di = pin ? dp : dq, dout = pin ? dq : dp;
        const Q t = di / (di - dout);
        QVec4 v;
        for (std::size_t c = 0; c < 4; ++c)
          v[c] = in[c] + t * (out[c] - in[c]);
        // Leaving the half-space the next edge runs along the plane; entering it, along p q.
        next.emplace_back(v, pin ? -1 - static_cast<int>(plane) : edge);
      }
    }
    cur = std::move(next);
  }
  auto impl = std::make_unique<Impl>();
  for (const auto& [p, edge] : cur) {
    if (!(p[3] > 0))
      throw std::logic_error("oracle: exactly clipped vertex with w <= 0");
    const auto q = project_q(p, vp);
    impl->v.push_back({q[0], q[1]});
    impl->origin.push_back(edge);
  }
  return ExactRegion(std::move(impl));
}

ExactRegion::Side ExactRegion::classify(const Raw2& sample, std::int64_t near_raw) const {
  const std::vector<QPoint>& v = impl_->v;
  const QPoint s{exact_i(sample[0]), exact_i(sample[1])};
  const std::size_t n = v.size();
  if (n == 0)
    return Side::kOutside;
  const Q near2 = exact_i(near_raw) * exact_i(near_raw);
  for (std::size_t i = 0; i < n; ++i) {
    if (dist2_segment(v[i], v[(i + 1) % n], s) <= near2)
      return Side::kNear;
  }
  return strictly_inside(sample) ? Side::kInside : Side::kOutside;
}

const std::vector<int>& ExactRegion::edge_origins() const {
  return impl_->origin;
}

bool ExactRegion::near_edge(const Raw2& sample, std::int64_t near_raw, std::size_t i) const {
  const std::vector<QPoint>& v = impl_->v;
  const QPoint s{exact_i(sample[0]), exact_i(sample[1])};
  const Q near2 = exact_i(near_raw) * exact_i(near_raw);
  return dist2_segment(v.at(i), v[(i + 1) % v.size()], s) <= near2;
}

bool ExactRegion::strictly_inside(const Raw2& sample) const {
  const std::vector<QPoint>& v = impl_->v;
  const std::size_t n = v.size();
  if (n < 3)
    return false;
  const QPoint s{exact_i(sample[0]), exact_i(sample[1])};
  // The orientation of the convex polygon: the sign of the sum of E_{v_i v_i+1}(v0).
  Q area(0);
  for (std::size_t i = 0; i < n; ++i)
    area += edge_q(v[i], v[(i + 1) % n], v[0]);
  if (area == 0)
    return false;
  const int sigma = sgn(area);
  for (std::size_t i = 0; i < n; ++i) {
    const QPoint& a = v[i];
    const QPoint& b = v[(i + 1) % n];
    if (a == b)
      continue;
    if (sgn(edge_q(a, b, s)) != sigma)
      return false;
  }
  return true;
}

std::array<std::int64_t, 4> ExactRegion::bounds_raw() const {
  const std::vector<QPoint>& v = impl_->v;
  if (v.empty())
    return {0, 0, -1, -1};
  Q x0 = v[0][0], y0 = v[0][1], x1 = v[0][0], y1 = v[0][1];
  for (const QPoint& p : v) {
    x0 = std::min(x0, p[0]);
    y0 = std::min(y0, p[1]);
    x1 = std::max(x1, p[0]);
    y1 = std::max(y1, p[1]);
  }
  const auto clamp64 = [](const Z& z) {
    const Z lo(std::numeric_limits<long>::min() / 2), hi(std::numeric_limits<long>::max() / 2);
    return static_cast<std::int64_t>((z < lo ? lo : (z > hi ? hi : z)).get_si());
  };
  return {clamp64(floor_q(x0)), clamp64(floor_q(y0)), clamp64(floor_q(x1) + 1),
          clamp64(floor_q(y1) + 1)};
}

std::vector<std::array<double, 2>> ExactRegion::vertices_px() const {
  std::vector<std::array<double, 2>> out;
  for (const QPoint& p : impl_->v)
    out.push_back({rn64(p[0] / 256), rn64(p[1] / 256)});
  return out;
}

std::size_t ExactRegion::size() const {
  return impl_->v.size();
}

// ---------------------------------------------------------------------------------------------
// Barycentrics

// rule: PIPE.BARY.EXACT, PIPE.BARY.SUM
Bary barycentrics(const std::array<Raw2, 3>& v, const Raw2& s) {
  const auto z = [](std::int64_t x) { return Z(static_cast<long>(x)); };
  // E_ab(p) = (bx - ax)(py - ay) - (by - ay)(px - ax), exactly.
  const auto edge = [&](const Raw2& a, const Raw2& b, const Raw2& p) -> Z {
    return (z(b[0]) - z(a[0])) * (z(p[1]) - z(a[1])) - (z(b[1]) - z(a[1])) * (z(p[0]) - z(a[0]));
  };
  const auto i64 = [](const Z& x) {
    const auto r = to_i64(x);
    if (!r)
      throw std::logic_error("oracle: an edge value does not fit in int64");
    return *r;
  };
  Bary b;
  b.e = {i64(edge(v[1], v[2], s)), i64(edge(v[2], v[0], s)), i64(edge(v[0], v[1], s))};
  b.area = i64(edge(v[0], v[1], v[2]));
  return b;
}

bool inside_closed(const Bary& b) {
  if (b.area == 0)
    return false;
  for (const std::int64_t e : b.e) {
    if ((b.area > 0 && e < 0) || (b.area < 0 && e > 0))
      return false;
  }
  return true;
}

// ---------------------------------------------------------------------------------------------
// Interpolation

namespace {

struct Perspective {
  Q num, den; // sum(e_i a_i / w_i), sum(e_i / w_i), exact
  Q abs_den;  // sum |e_i / w_i|
};

Perspective perspective_parts(const Bary& b, const std::array<float, 3>& a,
                              const std::array<float, 3>& w) {
  Perspective p;
  for (std::size_t i = 0; i < 3; ++i) {
    const Q ew = exact_i(b.e[i]) / exact(w[i]);
    p.num += ew * exact(a[i]);
    p.den += ew;
    p.abs_den += abs_q(ew);
  }
  return p;
}

int area_sign(const Bary& b) {
  return b.area > 0 ? 1 : (b.area < 0 ? -1 : 0);
}

// Whether got lies in [x - bound, x + bound], or is +-FLT_MAX with the interval reaching past it
// (saturation, PIPE.INTERP.HORIZON).
bool accept(float got, const Q& x, const Q& bound, bool& saturated) {
  const Q g = exact(got);
  const Q lo = x - bound, hi = x + bound;
  if (lo <= g && g <= hi)
    return true;
  const Q fmax = exact(FLT_MAX);
  if (got == FLT_MAX && hi >= fmax)
    return saturated = true;
  if (got == -FLT_MAX && lo <= -fmax)
    return saturated = true;
  return false;
}

void range_check(InterpCheck& c, const Bary& b, const std::array<float, 3>& a, const Q& bound) {
  c.inside = inside_closed(b);
  if (!c.inside)
    return;
  const float lo = std::min({a[0], a[1], a[2]});
  const float hi = std::max({a[0], a[1], a[2]});
  const Q g = exact(c.got);
  c.in_range = exact(lo) - bound <= g && g <= exact(hi) + bound;
}

} // namespace

std::optional<double> perspective_exact(const Bary& b, const std::array<float, 3>& a,
                                        const std::array<float, 3>& w) {
  const Perspective p = perspective_parts(b, a, w);
  if (sgn(p.den) * area_sign(b) <= 0)
    return std::nullopt;
  return rn64(p.num / p.den);
}

namespace {
// rn32 saturated at +-FLT_MAX (PIPE.INTERP.HORIZON: no interpolated value is infinite).
float nearest32_saturated(const Q& q) {
  const float f = rn32(q);
  return std::isinf(f) ? (f > 0 ? FLT_MAX : -FLT_MAX) : f;
}
} // namespace

std::optional<float> perspective_nearest32(const Bary& b, const std::array<float, 3>& a,
                                           const std::array<float, 3>& w) {
  const Perspective p = perspective_parts(b, a, w);
  if (sgn(p.den) * area_sign(b) <= 0)
    return std::nullopt;
  return nearest32_saturated(p.num / p.den);
}

float linear_nearest32(const Bary& b, const std::array<float, 3>& a) {
  if (b.area == 0)
    throw std::invalid_argument("oracle: linear_nearest32 on a degenerate triangle");
  Q sum;
  for (std::size_t i = 0; i < 3; ++i)
    sum += exact_i(b.e[i]) * exact(a[i]);
  return nearest32_saturated(sum / exact_i(b.area));
}

double linear_exact(const Bary& b, const std::array<float, 3>& a) {
  if (b.area == 0)
    throw std::invalid_argument("oracle: linear_exact on a degenerate triangle");
  Q sum;
  for (std::size_t i = 0; i < 3; ++i)
    sum += exact_i(b.e[i]) * exact(a[i]);
  return rn64(sum / exact_i(b.area));
}

namespace {
// The common end of both checks: the bound ulp32(x) + 2^-48 S of PIPE.INTERP.BOUND, then the
// kernel's value against it and, inside the triangle, against the vertex values' range.
void judge(InterpCheck& c, const Bary& b, const std::array<float, 3>& a, const Q& x, const Q& s,
           float got) {
  const Q bound = ulp32_q(x) + pow2(-48) * s;
  c.s = rn64(s);
  c.bound = rn64(bound);
  if (!c.finite)
    return;
  c.ok = accept(got, x, bound, c.saturated);
  range_check(c, b, a, bound);
  c.ok = c.ok && c.in_range;
}
} // namespace

// rule: PIPE.INTERP.PERSPECTIVE, PIPE.INTERP.HORIZON, PIPE.INTERP.BOUND
InterpCheck check_perspective(const Bary& b, const std::array<float, 3>& a,
                              const std::array<float, 3>& w, float flat, float got) {
  if (b.area == 0)
    throw std::invalid_argument("oracle: check_perspective on a degenerate triangle");
  InterpCheck c;
  c.got = got;
  c.finite = std::isfinite(got);
  const Perspective p = perspective_parts(b, a, w);
  // The kernel decides the horizon on a double denominator: within a few double roundings of
  // zero either answer is possible.
  if (abs_q(p.den) <= p.abs_den * pow2(-48)) {
    c.near_horizon = true;
    c.exact = flat;
    c.ok = c.finite;
    return c;
  }
  if (sgn(p.den) * area_sign(b) < 0) {
    c.horizon = true;
    c.exact = flat;
    c.ok = c.finite && got == flat;
    return c;
  }
  const Q x = p.num / p.den;
  // S = (sum|e_i q_i a_i| + |x| sum|e_i q_i|) / |sum e_i q_i| with q_i = fl64(1 / w_i).
  Q sa, sq, dq;
  for (std::size_t i = 0; i < 3; ++i) {
    const Q eq = exact_i(b.e[i]) * exact(fl64_div(1.0, static_cast<double>(w[i])));
    sa += abs_q(eq * exact(a[i]));
    sq += abs_q(eq);
    dq += eq;
  }
  c.exact = rn64(x);
  if (dq == 0) { // unreachable beside the near-horizon test; kept for safety
    c.near_horizon = true;
    c.ok = c.finite;
    return c;
  }
  judge(c, b, a, x, (sa + abs_q(x) * sq) / abs_q(dq), got);
  return c;
}

// rule: PIPE.INTERP.LINEAR, PIPE.INTERP.HORIZON, PIPE.INTERP.BOUND
InterpCheck check_linear(const Bary& b, const std::array<float, 3>& a, float got) {
  if (b.area == 0)
    throw std::invalid_argument("oracle: check_linear on a degenerate triangle");
  InterpCheck c;
  c.got = got;
  c.finite = std::isfinite(got);
  Q sum, sa;
  for (std::size_t i = 0; i < 3; ++i) {
    const Q ea = exact_i(b.e[i]) * exact(a[i]);
    sum += ea;
    sa += abs_q(ea);
  }
  const Q area = exact_i(b.area);
  const Q x = sum / area;
  c.exact = rn64(x);
  judge(c, b, a, x, sa / abs_q(area), got);
  return c;
}

std::string InterpCheck::describe() const {
  std::ostringstream os;
  os << "got " << show(static_cast<double>(got)) << ", exact " << show(exact) << ", bound "
     << show(bound) << ", S " << show(s) << ", |got - exact| "
     << show(std::fabs(static_cast<double>(got) - exact)) << (finite ? "" : ", NOT FINITE")
     << (horizon ? ", beyond the horizon (flat expected)" : "")
     << (near_horizon ? ", near the horizon" : "") << (saturated ? ", saturated" : "")
     << (inside ? ", inside" : ", outside") << (in_range ? "" : ", OUTSIDE [min, max] + bound");
  return os.str();
}

// rule: PIPE.INTERP.FLAT
float flat_value(const std::vector<float>& vertex_values, const std::string& provoking) {
  if (vertex_values.empty())
    throw std::invalid_argument("oracle: flat_value of no vertex");
  if (provoking == "first")
    return vertex_values.front();
  if (provoking == "last")
    return vertex_values.back();
  throw std::invalid_argument("oracle: unknown provoking vertex '" + provoking + "'");
}

// ---------------------------------------------------------------------------------------------
// Depth

namespace {

int unorm_bits(const std::string& format) {
  if (format == "d16")
    return 16;
  if (format == "d24")
    return 24;
  if (format == "d32f")
    return 0;
  throw std::invalid_argument("oracle: unknown depth format '" + format + "'");
}

// floor(d (2^n - 1) + 1/2) exactly, or the nearest float32, of an exact clamped depth.
// rule: PIPE.DEPTH.FORMAT
Stored store_q(const Q& d, const std::string& format) {
  const int bits = unorm_bits(format);
  Stored s;
  if (bits == 0) {
    s.f = d == 0 ? 0.0f : rn32(d);
    return s;
  }
  const Q scale = pow2(bits) - 1;
  const Z u = floor_q(d * scale + Q(1, 2));
  if (u < 0 || u > Z(scale))
    throw std::logic_error("oracle: stored depth out of range");
  s.unorm = static_cast<std::uint32_t>(u.get_ui());
  return s;
}

bool stored_less(const Stored& a, const Stored& b, const std::string& format) {
  return unorm_bits(format) == 0 ? a.f < b.f : a.unorm < b.unorm;
}

struct DepthParts {
  Q x, s; // sum(e_i Z_i) / area, sum|e_i Z_i| / |area|
};

DepthParts depth_parts(const Bary& b, const std::array<float, 3>& z) {
  if (b.area == 0)
    throw std::invalid_argument("oracle: depth on a degenerate triangle");
  Q sum, sa;
  for (std::size_t i = 0; i < 3; ++i) {
    const Q ez = exact_i(b.e[i]) * exact(z[i]);
    sum += ez;
    sa += abs_q(ez);
  }
  const Q area = exact_i(b.area);
  return {sum / area, sa / abs_q(area)};
}

std::string show_stored(const Stored& s, const std::string& format) {
  return unorm_bits(format) == 0 ? show(static_cast<double>(s.f)) : std::to_string(s.unorm);
}

} // namespace

double depth_exact(const Bary& b, const std::array<float, 3>& z) {
  return rn64(depth_parts(b, z).x);
}

// rule: PIPE.DEPTH.CLAMP, PIPE.DEPTH.FORMAT
Stored store_exact(double d, float min_depth, float max_depth, const std::string& format) {
  return store_q(clamp_q(exact(d), exact(min_depth), exact(max_depth)), format);
}

// rule: PIPE.DEPTH.INTERP, PIPE.DEPTH.CLAMP, PIPE.DEPTH.FORMAT
Stored depth_stored_nearest(const Bary& b, const std::array<float, 3>& z, float min_depth,
                            float max_depth, const std::string& format) {
  return store_q(clamp_q(depth_parts(b, z).x, exact(min_depth), exact(max_depth)), format);
}

// rule: PIPE.DEPTH.INTERP, PIPE.DEPTH.BOUND
DepthCheck check_depth_interp(const Bary& b, const std::array<float, 3>& z, double got) {
  const DepthParts p = depth_parts(b, z);
  DepthCheck c;
  c.exact = rn64(p.x);
  c.clamped = c.exact;
  const Q bound = pow2(-50) * p.s;
  c.bound = rn64(bound);
  c.got_z = got;
  c.ok = std::isfinite(got) && abs_q(exact(got) - p.x) <= bound;
  return c;
}

// rule: PIPE.DEPTH.BOUND, PIPE.DEPTH.CLAMP, PIPE.DEPTH.FORMAT
DepthCheck check_depth_stored(const Bary& b, const std::array<float, 3>& z, float min_depth,
                              float max_depth, const std::string& format, const Stored& got) {
  const DepthParts p = depth_parts(b, z);
  const Q lo_d = exact(min_depth), hi_d = exact(max_depth);
  const bool unorm = unorm_bits(format) != 0;
  // UNORM: values within (2^n - 1) 2^-49 S of x (2^n - 1) round to the allowed integers; d32f:
  // values within 2^-50 S of x round to the allowed floats. Rounding is monotone, so the
  // allowed stored values are those between the roundings of the interval's ends.
  const Q margin = pow2(unorm ? -49 : -50) * p.s;
  DepthCheck c;
  c.exact = rn64(p.x);
  const Q clamped = clamp_q(p.x, lo_d, hi_d);
  c.clamped = rn64(clamped);
  c.bound = rn64(margin);
  c.expected = store_q(clamped, format);
  c.lo = store_q(clamp_q(p.x - margin, lo_d, hi_d), format);
  c.hi = store_q(clamp_q(p.x + margin, lo_d, hi_d), format);
  c.got = got;
  if (unorm) {
    c.ok = got.f == 0.0f && c.lo.unorm <= got.unorm && got.unorm <= c.hi.unorm;
  } else {
    c.ok = got.unorm == 0 && std::isfinite(got.f) && c.lo.f <= got.f && got.f <= c.hi.f;
  }
  return c;
}

std::string DepthCheck::describe(const std::string& format) const {
  std::ostringstream os;
  os << "format " << format << ": exact " << show(exact) << ", clamped " << show(clamped)
     << ", margin " << show(bound) << ", got z " << show(got_z) << ", got stored "
     << show_stored(got, format) << ", exactly rounded " << show_stored(expected, format)
     << ", allowed [" << show_stored(lo, format) << ", " << show_stored(hi, format) << "]";
  return os.str();
}

// rule: PIPE.DEPTH.BIAS
// Every float32 step of the bias saturates at +-FLT_MAX (PIPE.DEPTH.BIAS).
float sat32(float v) {
  return std::isinf(v) ? (v > 0 ? FLT_MAX : -FLT_MAX) : v;
}

float depth_bias(const std::array<Raw2, 3>& v, const std::array<float, 3>& z, std::int32_t bias,
                 float slope_scaled, float clamp, const std::string& format) {
  if (bias == 0 && slope_scaled == 0.0f)
    return 0.0f;
  float slope_term = 0.0f;
  if (slope_scaled != 0.0f) {
    const auto q = [](std::int64_t r) { return exact_i(r); };
    const Q x1 = q(v[1][0] - v[0][0]), y1 = q(v[1][1] - v[0][1]);
    const Q x2 = q(v[2][0] - v[0][0]), y2 = q(v[2][1] - v[0][1]);
    const Q z1 = exact(z[1]) - exact(z[0]), z2 = exact(z[2]) - exact(z[0]);
    const Q den = x1 * y2 - x2 * y1; // raw units squared
    float max_slope = 0.0f;
    if (den != 0) {
      // Z = Z0 + a (x - x0) + b (y - y0) through the three vertices; positions in pixels are
      // raw / 256, so the per-pixel derivatives are 256 times the per-raw-unit ones.
      const double ddx = rn64(Q((z1 * y2 - z2 * y1) * 256 / den));
      const double ddy = rn64(Q((x1 * z2 - x2 * z1) * 256 / den));
      max_slope = sat32(nearest_float(std::max(std::fabs(ddx), std::fabs(ddy))));
    }
    slope_term = sat32(fl32_mul(slope_scaled, max_slope));
  }
  float r = 0.0f;
  if (format == "d32f") {
    Q zmax(0);
    for (const float zi : z)
      zmax = std::max(zmax, abs_q(exact(zi)));
    const long e = zmax == 0 ? -126 : std::max(floor_log2(zmax), -126L);
    r = static_cast<float>(rn64(pow2(e - 23)));
  } else {
    const int bits = format.empty() ? 24 : unorm_bits(format);
    if (bits == 0)
      throw std::invalid_argument("oracle: bad depth format for depth_bias");
    r = rn32(Q(1) / (pow2(bits) - 1));
  }
  const float constant = fl32_mul(nearest_float(static_cast<double>(bias)), r);
  float total = sat32(fl32_add(constant, slope_term));
  if (clamp > 0.0f)
    total = std::min(clamp, total);
  else if (clamp < 0.0f)
    total = std::max(clamp, total);
  return total;
}

// rule: PIPE.DEPTH.TEST
bool depth_test(const std::string& func, const Stored& now, const Stored& old,
                const std::string& format) {
  const bool lt = stored_less(now, old, format);
  const bool gt = stored_less(old, now, format);
  const bool eq = !lt && !gt;
  if (func == "never")
    return false;
  if (func == "less")
    return lt;
  if (func == "equal")
    return eq;
  if (func == "less_equal")
    return lt || eq;
  if (func == "greater")
    return gt;
  if (func == "not_equal")
    return !eq;
  if (func == "greater_equal")
    return gt || eq;
  if (func == "always")
    return true;
  throw std::invalid_argument("oracle: unknown depth function '" + func + "'");
}

} // namespace rastrules::oracle::pipe
