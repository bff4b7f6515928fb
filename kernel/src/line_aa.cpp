// SPDX-License-Identifier: MIT
// Antialiased lines (D3D reference algorithm) in fixed point: the width-1 rectangle clipped
// against the five squares R0..R4 of each pixel, areas by the shoelace formula, all integer.
// Implements: LINE.AA.RECT, LINE.AA.COVERAGE, LINE.AA.FRAGMENT, LINE.AA.ZERO_LENGTH,
//             LINE.AA.PRECISION, LINE.AA.TRAVERSAL, LINE.AA.BLEND
//
// Units. Positions relative to the pixel centre c, in raw 16.8 units (1/256 px), are scaled by
// 2^kG: one unit of a polygon coordinate is 2^-(kG+8) = 2^-32 px. The error budget that
// follows from this choice is derived in spec/rules/line_aa.md (LINE.AA.PRECISION).

#include <algorithm>
#include <array>
#include <cstdint>

#include "rastrules/formula/aa.hpp"
#include "rastrules/line.hpp"
#include "rastrules/line_aa.hpp"

namespace rastrules {
namespace {

__extension__ typedef __int128 I128;
__extension__ typedef unsigned __int128 U128;
using I64 = std::int64_t;

// Extra fractional bits below the 1/256 px raw unit.
constexpr int kG = 24;
constexpr I128 kScale = I128{1} << kG;

// Half-widths of R0..R4 in raw units (0.5, 0.75, 1.0, 1.25, 1.5 px), and the weights m_i with
// coverage = sum_i area_i * m_i / 18000, because 1 / (5 * width_i^2) = m_i / 18000 for
// widths 1, 1.5, 2, 2.5, 3 (m_i = 14400 / k_i^2 with width_i = k_i / 2).
// rule: LINE.AA.COVERAGE
constexpr std::array<I64, 5> kHalfRaw = {128, 192, 256, 320, 384};
constexpr std::array<I64, 5> kWeight = {3600, 1600, 900, 576, 400};
constexpr I64 kWeightDen = 18000;
constexpr I64 kR4HalfRaw = 384;
constexpr I64 kHalfWidthRaw = 128; // the rectangle is 1 px wide: 0.5 px either side

// Returns floor(sqrt(v)).
U128 isqrt(U128 v) {
  U128 r = 0;
  U128 bit = U128{1} << 126;
  while (bit > v)
    bit >>= 2;
  while (bit != 0) {
    if (v >= r + bit) {
      v -= r + bit;
      r = (r >> 1) + bit;
    } else {
      r >>= 1;
    }
    bit >>= 2;
  }
  return r;
}

// Returns num / den rounded to the nearest integer, halves away from zero (den != 0), so that
// negating num negates the result exactly.
I128 div_round(I128 num, I128 den) {
  if (den < 0) {
    num = -num;
    den = -den;
  }
  const bool neg = num < 0;
  const I128 m = neg ? -num : num;
  const I128 q = (2 * m + den) / (2 * den);
  return neg ? -q : q;
}

// Returns whether v * sqrt(D) < w, for D > 0 and w >= 0, exactly (callers: |v| < 2^26,
// w < 2^31, D < 2^49, so v^2 D < 2^101 and w^2 < 2^62; proofs/line_aa/aa_formulas.cpp).
bool times_sqrt_less(I128 v, I128 w, I128 D) {
  return formula::times_sqrt_less<I128>(v, w, D);
}

struct Pt {
  I128 x;
  I128 y;
};

// A clip outputs at most the input's vertices plus one per sign change, so at most twice as
// many: 4 -> 8 -> 16 -> 32 -> 64 bounds every case (convex inputs need only 8).
struct Poly {
  std::array<Pt, 64> v{};
  int n = 0;
};

// Half-plane nx * X + ny * Y <= k, X and Y in scaled units.
struct HalfPlane {
  I64 nx;
  I64 ny;
  I128 k;
};

// Sutherland-Hodgman against one half-plane; new vertices rounded to the nearest unit.
Poly clip(const Poly& in, const HalfPlane& h) {
  Poly out;
  if (in.n == 0)
    return out;
  auto side = [&](const Pt& p) { return I128{h.nx} * p.x + I128{h.ny} * p.y - h.k; };
  for (int i = 0; i < in.n; ++i) {
    const Pt& prev = in.v[static_cast<std::size_t>((i + in.n - 1) % in.n)];
    const Pt& cur = in.v[static_cast<std::size_t>(i)];
    const I128 sp = side(prev);
    const I128 sc = side(cur);
    const bool prev_in = sp <= 0;
    const bool cur_in = sc <= 0;
    if (prev_in != cur_in) {
      // I = (prev * (-sc) + cur * sp) / (sp - sc); |sp|, |sc| <= |n . (cur - prev)| < 2^60.
      const I128 den = sp - sc;
      out.v[static_cast<std::size_t>(out.n++)] =
          Pt{div_round(prev.x * -sc + cur.x * sp, den), div_round(prev.y * -sc + cur.y * sp, den)};
    }
    if (cur_in)
      out.v[static_cast<std::size_t>(out.n++)] = cur;
  }
  return out;
}

// Returns |twice the signed area| in scaled units squared.
I128 twice_area(const Poly& p) {
  I128 s = 0;
  for (int i = 0; i < p.n; ++i) {
    const Pt& u = p.v[static_cast<std::size_t>(i)];
    const Pt& w = p.v[static_cast<std::size_t>((i + 1) % p.n)];
    s += u.x * w.y - w.x * u.y;
  }
  return s < 0 ? -s : s;
}

struct Frame {
  I64 ax, ay, bx, by; // endpoints relative to the pixel centre, raw units
};

// Returns the canonical representative of the line relative to the pixel centre under the
// symmetries of the squares R_i (mirror in x, mirror in y) and endpoint order: d >= 0 in both
// components and, among the candidates, the lexicographically smallest (ax, ay, bx, by).
Frame canonical(I64 ax, I64 ay, I64 bx, I64 by) {
  Frame best{};
  bool have = false;
  for (int t = 0; t < 8; ++t) {
    const I64 sx = (t & 1) ? -1 : 1;
    const I64 sy = (t & 2) ? -1 : 1;
    Frame f = (t & 4) ? Frame{sx * bx, sy * by, sx * ax, sy * ay}
                      : Frame{sx * ax, sy * ay, sx * bx, sy * by};
    if (f.bx - f.ax < 0 || f.by - f.ay < 0)
      continue;
    const auto key = [](const Frame& g) { return std::array<I64, 4>{g.ax, g.ay, g.bx, g.by}; };
    if (!have || key(f) < key(best)) {
      best = f;
      have = true;
    }
  }
  return best;
}

// Exact: does the rectangle overlap the open square R4 in positive area? Separating axes of
// two convex polygons: x, y, d and the normal of d. Canonical frame (dx, dy >= 0), D > 0.
// rule: LINE.AA.FRAGMENT
bool overlaps_r4(const Frame& f, I64 D) {
  const I64 dx = f.bx - f.ax;
  const I64 dy = f.by - f.ay;
  const I128 w = I128{kHalfWidthRaw};
  const I128 D128 = D;
  // x: rectangle x-extent [ax - 128 dy / L, bx + 128 dy / L] against (-384, 384).
  if (!times_sqrt_less(I128{f.ax} - kR4HalfRaw, w * dy, D128))
    return false;
  if (!times_sqrt_less(-(I128{f.bx} + kR4HalfRaw), w * dy, D128))
    return false;
  // y: [ay - 128 dx / L, by + 128 dx / L].
  if (!times_sqrt_less(I128{f.ay} - kR4HalfRaw, w * dx, D128))
    return false;
  if (!times_sqrt_less(-(I128{f.by} + kR4HalfRaw), w * dx, D128))
    return false;
  // d: rectangle [d.A, d.B], square (-S, S) with S = 384 (dx + dy).
  const I128 S = I128{kR4HalfRaw} * (dx + dy);
  const I128 dA = I128{dx} * f.ax + I128{dy} * f.ay;
  const I128 dB = I128{dx} * f.bx + I128{dy} * f.by;
  if (!(dA < S && dB > -S))
    return false;
  // normal n1 = (-dy, dx): rectangle n1.A +- 128 L, square (-S, S).
  I128 nA = -I128{dy} * f.ax + I128{dx} * f.ay;
  if (nA < 0)
    nA = -nA;
  // v = |n1 . A| - S < 128 sqrt(D): true when v < 0, else compare the squares.
  const I128 v = nA - S;
  return v < 0 || v * v < w * w * D128;
}

} // namespace

// rule: LINE.AA.COVERAGE, LINE.AA.RECT, LINE.AA.ZERO_LENGTH, LINE.AA.PRECISION
AACoverage aa_line_coverage(Vec2 a, Vec2 b, std::int32_t px, std::int32_t py) {
  const I64 cx = I64{px} * kSubpixelOne + kSubpixelHalf;
  const I64 cy = I64{py} * kSubpixelOne + kSubpixelHalf;
  // The rectangle lies within 128 raw of the segment's bounding box: a pixel whose open R4
  // misses that box has coverage 0. This also bounds |c - a| by 2^24 + 512 raw for every
  // pixel examined further, which the bit budget of LINE.AA.PRECISION assumes.
  {
    const I64 ax = a.x.raw(), ay = a.y.raw(), bx = b.x.raw(), by = b.y.raw();
    if (cx - kR4HalfRaw >= std::max(ax, bx) + kHalfWidthRaw ||
        cx + kR4HalfRaw <= std::min(ax, bx) - kHalfWidthRaw ||
        cy - kR4HalfRaw >= std::max(ay, by) + kHalfWidthRaw ||
        cy + kR4HalfRaw <= std::min(ay, by) - kHalfWidthRaw) {
      return {};
    }
  }
  const Frame f = canonical(a.x.raw() - cx, a.y.raw() - cy, b.x.raw() - cx, b.y.raw() - cy);
  const I64 dx = f.bx - f.ax;
  const I64 dy = f.by - f.ay;
  const I64 D = dx * dx + dy * dy; // < 2^49
  // rule: LINE.AA.ZERO_LENGTH
  if (D == 0)
    return {};
  if (!overlaps_r4(f, D))
    return {};

  // The four half-planes of the rectangle (LINE.AA.RECT), q = p - c in raw units:
  //   end at a:  d . (q - A) >= 0          end at b:  d . (q - B) <= 0
  //   sides:     |n1 . (q - A)| <= 128 L   with n1 = (-dy, dx), L = |d|.
  // 128 L 2^kG = sqrt(D * 2^(14 + 2 kG)) is rounded down to an integer R (D < 2^49, so the
  // radicand is < 2^111).
  const I128 R = static_cast<I128>(isqrt(static_cast<U128>(D) << (14 + 2 * kG)));
  const I128 dA = I128{dx} * f.ax + I128{dy} * f.ay;
  const I128 dB = I128{dx} * f.bx + I128{dy} * f.by;
  const I128 nA = -I128{dy} * f.ax + I128{dx} * f.ay;
  const std::array<HalfPlane, 4> planes = {
      HalfPlane{-dx, -dy, -dA * kScale},
      HalfPlane{dx, dy, dB * kScale},
      HalfPlane{-dy, dx, nA * kScale + R},
      HalfPlane{dy, -dx, -nA * kScale + R},
  };

  I128 sum = 0;
  for (std::size_t i = 0; i < kHalfRaw.size(); ++i) {
    const I128 H = kHalfRaw[i] * kScale;
    Poly p;
    p.n = 4;
    p.v[0] = Pt{-H, -H};
    p.v[1] = Pt{H, -H};
    p.v[2] = Pt{H, H};
    p.v[3] = Pt{-H, H};
    for (const HalfPlane& h : planes)
      p = clip(p, h);
    sum += twice_area(p) * kWeight[i];
  }
  // q16 = sum_i (T_i / 2^65 px^2) * m_i / 18000 * 2^16, rounded to nearest, halves up.
  const I128 den = I128{kWeightDen} << 49;
  I128 q = (2 * sum + den) / (2 * den);
  q = std::clamp<I128>(q, 1, I128{1} << kAACoverageBits);
  return AACoverage{true, static_cast<std::uint32_t>(q)};
}

// rule: LINE.AA.TRAVERSAL, RASTER.TARGET.CLIP
void rasterize_aa_line(Vec2 a, Vec2 b, std::int32_t width, std::int32_t height,
                       const AAEmit& emit) {
  if (a == b || width <= 0 || height <= 0)
    return;
  const I64 ax = a.x.raw(), ay = a.y.raw(), bx = b.x.raw(), by = b.y.raw();
  const I64 dx = bx - ax, dy = by - ay;
  const I64 D = dx * dx + dy * dy;
  // The rectangle lies within 128 raw of the segment's bounding box; pixel p's R4 is the open
  // interval (256 p - 256, 256 p + 512) on each axis.
  const I64 xmin = std::min(ax, bx) - kHalfWidthRaw, xmax = std::max(ax, bx) + kHalfWidthRaw;
  const I64 ymin = std::min(ay, by) - kHalfWidthRaw, ymax = std::max(ay, by) + kHalfWidthRaw;
  const I64 px0 = std::max<I64>(0, floor_div(xmin - 512, 256) + 1);
  const I64 px1 = std::min<I64>(width - 1, ceil_div(xmax + 256, 256) - 1);
  const I64 py0 = std::max<I64>(0, floor_div(ymin - 512, 256) + 1);
  const I64 py1 = std::min<I64>(height - 1, ceil_div(ymax + 256, 256) - 1);
  // Per row, a necessary condition from the normal axis narrows the columns:
  // |n1 . (c - a)| < 128 L + 384 (|dx| + |dy|) <= M.
  I64 lc = static_cast<I64>(isqrt(static_cast<U128>(D)));
  if (lc * lc < D)
    ++lc;
  const I64 M = kHalfWidthRaw * lc + kR4HalfRaw * ((dx < 0 ? -dx : dx) + (dy < 0 ? -dy : dy));
  for (I64 py = py0; py <= py1; ++py) {
    I64 lo = px0, hi = px1;
    if (dy != 0) {
      // dy (cx - ax) in (t - M, t + M) with t = dx (cy - ay); cx = 256 px + 128.
      const I64 cy = py * 256 + 128;
      I64 t = dx * (cy - ay);
      I64 e = dy;
      if (e < 0) {
        e = -e;
        t = -t;
      }
      lo = std::max(lo, floor_div(ax * e + t - M - 128 * e, 256 * e));
      hi = std::min(hi, ceil_div(ax * e + t + M - 128 * e, 256 * e));
    }
    for (I64 px = lo; px <= hi; ++px) {
      const AACoverage c =
          aa_line_coverage(a, b, static_cast<std::int32_t>(px), static_cast<std::int32_t>(py));
      if (c.positive)
        emit(static_cast<std::int32_t>(px), static_cast<std::int32_t>(py), c.q16);
    }
  }
}

// rule: LINE.AA.BLEND
std::uint8_t aa_blend_unorm8(std::uint8_t src, std::uint8_t src_alpha, std::uint8_t dst,
                             std::uint32_t coverage_q16) {
  // out = dst + (src - dst) * (sa / 255) * (cov / 65536), in units of 1/255: exactly
  // N / (255 * 65536) with N >= 0 (a convex combination of src and dst).
  const I64 den = I64{255} << kAACoverageBits;
  const I64 n = formula::aa_blend_numerator<I64>(src, src_alpha, dst, coverage_q16, den);
  return static_cast<std::uint8_t>((2 * n + den) / (2 * den));
}

} // namespace rastrules
