// SPDX-License-Identifier: MIT
// Exact oracle for points and quadrilateral lines (rastrules/oracle/point.hpp).

#include "rastrules/oracle/point.hpp"
#include "rastrules/oracle/triangle.hpp"

#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace rastrules::oracle {
namespace {

mpz_class Z(std::int64_t v) {
  return mpz_class(static_cast<long>(v));
}
mpq_class Px(std::int64_t raw) { // raw 16.8 -> exact pixels
  mpq_class q(Z(raw), mpz_class(256));
  q.canonicalize();
  return q;
}

// Returns half the line width in pixels (LINE.QUAD.WIDTH).
mpq_class half_width_px(const std::string& mode) {
  if (mode == "quad-wide")
    return mpq_class(7, 10);
  if (mode == "quad-narrow")
    return mpq_class(1, 2);
  throw std::invalid_argument("oracle: unknown quadrilateral line mode '" + mode + "'");
}

std::int64_t to_i64(const mpz_class& z) {
  if (!z.fits_slong_p())
    throw std::logic_error("oracle: value does not fit");
  return static_cast<std::int64_t>(z.get_si());
}

// Returns the integer nearest to sqrt(x) for a rational x >= 0, ties to even: n = floor(sqrt(x))
// = floor(sqrt(floor(x))); then sqrt(x) vs n + 1/2 <=> x vs (n + 1/2)^2.
mpz_class round_sqrt(const mpq_class& x) {
  const mpz_class fl = x.get_num() / x.get_den(); // floor, x >= 0
  const mpz_class n = sqrt(fl);
  const mpq_class mid = (mpq_class(n) + mpq_class(1, 2)) * (mpq_class(n) + mpq_class(1, 2));
  if (x > mid)
    return n + 1;
  if (x < mid)
    return n;
  return (n % 2 == 0) ? n : mpz_class(n + 1);
}

} // namespace

bool point_in_range(const Raw2& c) {
  const mpq_class lo(-65535, 2);                               // -32767.5 px
  const mpq_class hi = mpq_class(32767) + mpq_class(127, 256); // 32767.49609375 px
  for (const std::int64_t v : c) {
    const mpq_class p = Px(v);
    if (p < lo || p > hi)
      return false;
  }
  return true;
}

bool point_covers(const Raw2& c, const Raw2& s, const std::string& fill) {
  const FillSides f = parse_fill(fill);
  const mpq_class half(1, 2);
  const mpq_class x = Px(s[0]), y = Px(s[1]);
  const mpq_class l = Px(c[0]) - half, r = Px(c[0]) + half;
  const mpq_class t = Px(c[1]) - half, b = Px(c[1]) + half;
  const bool in_x = f.left ? (l <= x && x < r) : (l < x && x <= r);
  const bool in_y = f.top ? (t <= y && y < b) : (t < y && y <= b);
  return in_x && in_y;
}

Raw2 quad_line_offset(const Raw2& a, const Raw2& b, const std::string& mode) {
  const mpz_class dx = Z(b[0]) - Z(a[0]);
  const mpz_class dy = Z(b[1]) - Z(a[1]);
  const mpz_class len2 = dx * dx + dy * dy;
  if (len2 == 0)
    throw std::invalid_argument("oracle: zero-length quadrilateral line");
  // Half width in raw units, and each offset component squared: (hw_raw * m)^2 / |d|^2.
  const mpq_class hw_raw = half_width_px(mode) * 256;
  const auto component = [&](const mpz_class& m) -> mpz_class {
    const mpq_class v2 = hw_raw * hw_raw * mpq_class(m * m) / mpq_class(len2);
    const mpz_class magnitude = round_sqrt(v2);
    return sgn(m) < 0 ? mpz_class(-magnitude) : magnitude;
  };
  // o* = hw (-dy, dx) / |d|.
  return Raw2{to_i64(component(mpz_class(-dy))), to_i64(component(dx))};
}

std::vector<Raw2> quad_line_corners(const Raw2& a, const Raw2& b, const std::string& mode) {
  if (a == b)
    return {};
  const Raw2 o = quad_line_offset(a, b, mode);
  return {Raw2{a[0] - o[0], a[1] - o[1]}, Raw2{b[0] - o[0], b[1] - o[1]},
          Raw2{b[0] + o[0], b[1] + o[1]}, Raw2{a[0] + o[0], a[1] + o[1]}};
}

bool quad_line_covers(const Raw2& a, const Raw2& b, const std::string& mode, const Raw2& s,
                      const std::string& fill) {
  const std::vector<Raw2> c = quad_line_corners(a, b, mode);
  if (c.empty())
    return false;
  const FillSides f = parse_fill(fill);
  const mpq_class sx = Px(s[0]), sy = Px(s[1]);
  for (std::size_t i = 0; i < 4; ++i) {
    const Raw2& p = c[i];
    const Raw2& q = c[(i + 1) % 4];
    const Raw2& r = c[(i + 2) % 4]; // a corner off this side: the interior's side
    const mpq_class px = Px(p[0]), py = Px(p[1]), qx = Px(q[0]), qy = Px(q[1]);
    const mpq_class rx = Px(r[0]), ry = Px(r[1]);
    bool inclusive = false;
    int side_s = 0, side_r = 0; // which side of the line through p, q
    if (py == qy) {
      // Exactly horizontal: a top side when the rest of the parallelogram lies below it.
      const bool top = ry > py;
      inclusive = f.top ? top : !top;
      side_s = sy > py ? 1 : (sy < py ? -1 : 0);
      side_r = top ? 1 : -1;
    } else {
      // Not horizontal: compare x with the side's x at the same height.
      const auto line_x = [&](const mpq_class& y) -> mpq_class {
        return px + (qx - px) * (y - py) / (qy - py);
      };
      const bool left = rx > line_x(ry); // interior on the +x side
      inclusive = f.left ? left : !left;
      const mpq_class lx = line_x(sy);
      side_s = sx > lx ? 1 : (sx < lx ? -1 : 0);
      side_r = left ? 1 : -1;
    }
    if (side_s == 0 ? !inclusive : side_s != side_r)
      return false;
  }
  return true;
}

} // namespace rastrules::oracle
