// SPDX-License-Identifier: MIT
// Oracle antialiased-line coverage: the rectangle of LINE.AA.RECT built from its corners,
// clipped against each square R_i by Sutherland-Hodgman, areas by the shoelace formula, all in
// the exact field Q(sqrt(D)) over GMP rationals. Structure deliberately unlike the kernel's
// (the kernel clips the squares by the rectangle's half-planes in fixed point; here the
// rectangle polygon is clipped by the squares, exactly, in pixel units).
// Implements (as oracle): LINE.AA.RECT, LINE.AA.COVERAGE, LINE.AA.FRAGMENT,
//   LINE.AA.ZERO_LENGTH, LINE.AA.PRECISION, LINE.AA.BLEND

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include <CGAL/Gmpq.h>

#include "rastrules/oracle/line_aa.hpp"

namespace rastrules::oracle {
namespace {

using Q = CGAL::Gmpq;

// An element a + b * sqrt(D) of Q(sqrt(D)). When D is a perfect square the root is rational
// and every element is built with b = 0, so a^2 - b^2 D below never vanishes for x != 0.
struct Ext {
  Q a;
  Q b;
};

struct Field {
  Q D;
  Ext add(const Ext& x, const Ext& y) const { return {x.a + y.a, x.b + y.b}; }
  Ext sub(const Ext& x, const Ext& y) const { return {x.a - y.a, x.b - y.b}; }
  Ext mul(const Ext& x, const Ext& y) const {
    return {x.a * y.a + x.b * y.b * D, x.a * y.b + x.b * y.a};
  }
  Ext div(const Ext& x, const Ext& y) const {
    const Q n = y.a * y.a - y.b * y.b * D; // y * conj(y), rational, nonzero for y != 0
    const Ext c = mul(x, Ext{y.a, -y.b});
    return {c.a / n, c.b / n};
  }
  int sign(const Ext& x) const {
    const int sa = CGAL::sign(x.a);
    const int sb = CGAL::sign(x.b);
    if (sb == 0)
      return sa;
    if (sa == 0 || sa == sb)
      return sb;
    // Opposite signs: the larger magnitude wins; a^2 == b^2 D is impossible here (D is not a
    // perfect square whenever b != 0).
    return (x.a * x.a > x.b * x.b * D) ? sa : sb;
  }
  double approx(const Ext& x) const {
    return CGAL::to_double(x.a) + CGAL::to_double(x.b) * std::sqrt(CGAL::to_double(D));
  }
};

Ext rat(const Q& q) {
  return {q, Q(0)};
}

struct P2 {
  Ext x;
  Ext y;
};

// Returns the integer square root when v is a perfect square, else -1.
std::int64_t exact_root(std::int64_t v) {
  std::int64_t r = static_cast<std::int64_t>(std::sqrt(static_cast<long double>(v)));
  while (r * r > v)
    --r;
  while ((r + 1) * (r + 1) <= v)
    ++r;
  return r * r == v ? r : -1;
}

// Keeps the part of polygon `poly` where s * (coord - bound) <= 0 (coord = x when on_x, else
// y; s = +1 keeps coord <= bound, s = -1 keeps coord >= bound).
std::vector<P2> clip_axis(const Field& F, const std::vector<P2>& poly, bool on_x, const Q& bound,
                          int s) {
  std::vector<P2> out;
  const std::size_t n = poly.size();
  auto val = [&](const P2& p) {
    const Ext c = on_x ? p.x : p.y;
    const Ext diff = F.sub(c, rat(bound));
    return s > 0 ? diff : F.sub(rat(Q(0)), diff);
  };
  for (std::size_t i = 0; i < n; ++i) {
    const P2& p = poly[i];
    const P2& q = poly[(i + 1) % n];
    const Ext vp = val(p);
    const Ext vq = val(q);
    const bool pin = F.sign(vp) <= 0;
    const bool qin = F.sign(vq) <= 0;
    if (pin)
      out.push_back(p);
    if (pin != qin) {
      // The point of segment pq where coord == bound: p + t (q - p), t = vp / (vp - vq).
      const Ext t = F.div(vp, F.sub(vp, vq));
      out.push_back(
          P2{F.add(p.x, F.mul(t, F.sub(q.x, p.x))), F.add(p.y, F.mul(t, F.sub(q.y, p.y)))});
    }
  }
  return out;
}

Ext polygon_area(const Field& F, const std::vector<P2>& poly) {
  Ext s{Q(0), Q(0)};
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const P2& p = poly[i];
    const P2& q = poly[(i + 1) % n];
    s = F.add(s, F.sub(F.mul(p.x, q.y), F.mul(q.x, p.y)));
  }
  if (F.sign(s) < 0)
    s = F.sub(rat(Q(0)), s);
  return F.div(s, rat(Q(2)));
}

struct Line {
  Field F;
  std::vector<P2> rect; // empty for a zero-length line
};

// rule: LINE.AA.RECT, LINE.AA.ZERO_LENGTH
Line make_line(const AARaw& a, const AARaw& b) {
  Line l;
  const std::int64_t dxr = b[0] - a[0];
  const std::int64_t dyr = b[1] - a[1];
  const std::int64_t Dr = dxr * dxr + dyr * dyr;
  l.F.D = Q(static_cast<double>(Dr)); // < 2^50: exact in a double
  if (Dr == 0)
    return l; // a 1 x 0 rectangle: area 0 against every square
  // Pixel units: p = raw / 256. Unit normal u = (-dy, dx) / L with L = sqrt(Dr) / 256 and
  // (dx, dy) = (dxr, dyr) / 256, so u = (-dyr, dxr) / sqrt(Dr) = (-dyr, dxr) * sqrt(Dr) / Dr.
  const std::int64_t r = exact_root(Dr);
  Ext inv_root; // 1 / sqrt(Dr)
  if (r >= 0) {
    inv_root = rat(Q(1) / Q(static_cast<double>(r)));
  } else {
    inv_root = Ext{Q(0), Q(1) / l.F.D};
  }
  const Ext half = rat(Q(1, 2));
  const Ext ux = l.F.mul(rat(Q(static_cast<double>(-dyr))), inv_root);
  const Ext uy = l.F.mul(rat(Q(static_cast<double>(dxr))), inv_root);
  const Ext hx = l.F.mul(ux, half);
  const Ext hy = l.F.mul(uy, half);
  const Q q256(256);
  const Ext ax = rat(Q(static_cast<double>(a[0])) / q256),
            ay = rat(Q(static_cast<double>(a[1])) / q256);
  const Ext bx = rat(Q(static_cast<double>(b[0])) / q256),
            by = rat(Q(static_cast<double>(b[1])) / q256);
  const Field& F = l.F;
  l.rect = {P2{F.add(ax, hx), F.add(ay, hy)}, P2{F.add(bx, hx), F.add(by, hy)},
            P2{F.sub(bx, hx), F.sub(by, hy)}, P2{F.sub(ax, hx), F.sub(ay, hy)}};
  return l;
}

// Area of the rectangle inside the square of half-width `half` (pixels) centred on the centre
// of pixel (px, py).
Ext area_in_square(const Line& l, std::int32_t px, std::int32_t py, const Q& half) {
  if (l.rect.empty())
    return rat(Q(0));
  const Q cx = Q(px) + Q(1, 2);
  const Q cy = Q(py) + Q(1, 2);
  std::vector<P2> p = l.rect;
  p = clip_axis(l.F, p, true, cx + half, +1);
  p = clip_axis(l.F, p, true, cx - half, -1);
  p = clip_axis(l.F, p, false, cy + half, +1);
  p = clip_axis(l.F, p, false, cy - half, -1);
  if (p.size() < 3)
    return rat(Q(0));
  return polygon_area(l.F, p);
}

// rule: LINE.AA.COVERAGE
Ext coverage(const Line& l, std::int32_t px, std::int32_t py) {
  // R0..R4: widths 1, 1.5, 2, 2.5, 3 (half-widths 1/2, 3/4, 1, 5/4, 3/2).
  const std::array<Q, 5> widths = {Q(1), Q(3, 2), Q(2), Q(5, 2), Q(3)};
  Ext sum{Q(0), Q(0)};
  for (const Q& w : widths) {
    const Ext area = area_in_square(l, px, py, w / Q(2));
    sum = l.F.add(sum, l.F.div(area, rat(w * w * Q(5))));
  }
  return sum;
}

} // namespace

AACheck aa_check(const AARaw& a, const AARaw& b, std::int32_t px, std::int32_t py,
                 std::uint32_t q16) {
  const Line l = make_line(a, b);
  const Ext c = coverage(l, px, py);
  const Field& F = l.F;
  AACheck r;
  r.positive = F.sign(c) > 0;
  r.approx = F.approx(c);
  // diff = 65536 * exact - q16
  const Ext diff = F.sub(F.mul(c, rat(Q(65536))), rat(Q(static_cast<double>(q16))));
  const Ext one = rat(Q(1));
  r.within_bound = F.sign(F.sub(diff, one)) <= 0 && F.sign(F.add(diff, one)) >= 0;
  const Ext tight = rat(Q(513, 1024));
  r.nearest = F.sign(F.sub(diff, tight)) <= 0 && F.sign(F.add(diff, tight)) >= 0;
  return r;
}

int aa_compare(const AARaw& a, const AARaw& b, std::int32_t px, std::int32_t py, std::int64_t num,
               std::int64_t den) {
  const Line l = make_line(a, b);
  const Ext c = coverage(l, px, py);
  return l.F.sign(l.F.sub(c, rat(Q(static_cast<double>(num)) / Q(static_cast<double>(den)))));
}

// rule: LINE.AA.FRAGMENT
std::vector<std::array<std::int32_t, 2>> aa_pixels(const AARaw& a, const AARaw& b, std::int32_t w,
                                                   std::int32_t h) {
  const Line l = make_line(a, b);
  std::vector<std::array<std::int32_t, 2>> out;
  for (std::int32_t y = 0; y < h; ++y) {
    for (std::int32_t x = 0; x < w; ++x) {
      // Coverage > 0 iff the rectangle meets the largest square R4 in positive area (every
      // term is >= 0 and R0..R3 lie inside R4).
      if (l.F.sign(area_in_square(l, x, y, Q(3, 2))) > 0)
        out.push_back({x, y});
    }
  }
  return out;
}

// rule: LINE.AA.BLEND
bool aa_blend_ok(std::uint32_t src, std::uint32_t sa, std::uint32_t dst, std::uint32_t cov,
                 std::uint32_t out) {
  const Q alpha = Q(static_cast<int>(sa), 255) * Q(static_cast<double>(cov)) / Q(65536);
  const Q exact =
      Q(static_cast<int>(dst)) + (Q(static_cast<int>(src)) - Q(static_cast<int>(dst))) * alpha;
  // out is the rounding, halves up: out - 1/2 <= exact < out + 1/2.
  const Q o(static_cast<int>(out));
  return o - Q(1, 2) <= exact && exact < o + Q(1, 2);
}

} // namespace rastrules::oracle
