// SPDX-License-Identifier: MIT
// Generators for aliased-line properties: random lines and lines built to hit the ties of the
// diamond rules on purpose (through diamond corners, along diamond edges, exactly 45 degrees,
// end points on pixel centres or corners, zero length, axis-aligned, partly outside the
// target), and the tie classes of a line for RC_CLASSIFY / RC_TAG.

#pragma once

#include <algorithm>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include <rapidcheck.h>

#include "rastrules/fixed.hpp"
#include "rastrules/line.hpp"
#include "rastrules/oracle/line.hpp"

namespace rastrules::linegen {

// A small target keeps the exact oracle (every pixel of a bounding box) fast.
inline constexpr std::int32_t kTarget = 16;

struct RawLine {
  std::int64_t ax = 0, ay = 0, bx = 0, by = 0; // raw 16.8
  std::string kind;                            // how it was built
};

inline void showValue(const RawLine& l, std::ostream& os) {
  os << "RawLine{" << l.kind << ": (" << l.ax << ", " << l.ay << ") -> (" << l.bx << ", " << l.by
     << ") raw = (" << static_cast<double>(l.ax) / 256 << ", " << static_cast<double>(l.ay) / 256
     << ") -> (" << static_cast<double>(l.bx) / 256 << ", " << static_cast<double>(l.by) / 256
     << ") px}";
}

inline Vec2 vec(std::int64_t x, std::int64_t y) {
  return Vec2{Subpixel::from_raw(static_cast<std::int32_t>(x)),
              Subpixel::from_raw(static_cast<std::int32_t>(y))};
}
inline Vec2 start(const RawLine& l) {
  return vec(l.ax, l.ay);
}
inline Vec2 end(const RawLine& l) {
  return vec(l.bx, l.by);
}
inline oracle::LineRaw ostart(const RawLine& l) {
  return {l.ax, l.ay};
}
inline oracle::LineRaw oend(const RawLine& l) {
  return {l.bx, l.by};
}

// A raw coordinate near the target (two pixels of margin each side).
inline rc::Gen<std::int64_t> coord() {
  return rc::gen::inRange<std::int64_t>(-2 * 256, (kTarget + 2) * 256);
}
// A pixel centre coordinate (raw) near the target.
inline rc::Gen<std::int64_t> centre() {
  return rc::gen::map(rc::gen::inRange<std::int64_t>(-1, kTarget + 1),
                      [](std::int64_t k) { return 256 * k + 128; });
}
// A point that is a pixel centre or one of the four corners of its diamond.
inline rc::Gen<std::array<std::int64_t, 2>> diamond_point() {
  return rc::gen::apply(
      [](std::int64_t cx, std::int64_t cy, int which) {
        static constexpr std::int64_t kOff[5][2] = {
            {0, 0}, {128, 0}, {-128, 0}, {0, 128}, {0, -128}};
        return std::array<std::int64_t, 2>{cx + kOff[which][0], cy + kOff[which][1]};
      },
      centre(), centre(), rc::gen::inRange(0, 5));
}

inline rc::Gen<RawLine> random_line() {
  return rc::gen::apply(
      [](std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by) {
        return RawLine{ax, ay, bx, by, "random"};
      },
      coord(), coord(), coord(), coord());
}

// A line through a diamond point p with a small integer direction d: a = p - s d, b = p + t d.
inline rc::Gen<RawLine> through_diamond_point() {
  return rc::gen::apply(
      [](std::array<std::int64_t, 2> p, std::int64_t dx, std::int64_t dy, std::int64_t s,
         std::int64_t t, std::int64_t scale) {
        if (dx == 0 && dy == 0)
          dx = 1;
        dx *= scale;
        dy *= scale;
        return RawLine{p[0] - s * dx, p[1] - s * dy, p[0] + t * dx, p[1] + t * dy,
                       "through-corner-or-centre"};
      },
      diamond_point(), rc::gen::inRange<std::int64_t>(-4, 5), rc::gen::inRange<std::int64_t>(-4, 5),
      rc::gen::inRange<std::int64_t>(0, 4), rc::gen::inRange<std::int64_t>(0, 4),
      rc::gen::element<std::int64_t>(1, 16, 32, 64, 128));
}

// A line along a diamond edge direction (45 degrees) from a diamond point, possibly offset by
// a few raw units, so it runs along edges or just beside them.
inline rc::Gen<RawLine> along_edge() {
  return rc::gen::apply(
      [](std::array<std::int64_t, 2> p, int sx, int sy, std::int64_t len0, std::int64_t len1,
         std::int64_t off) {
        const std::int64_t dx = sx ? 1 : -1, dy = sy ? 1 : -1;
        return RawLine{p[0] - len0 * dx + off, p[1] - len0 * dy, p[0] + len1 * dx + off,
                       p[1] + len1 * dy, "45-degrees"};
      },
      diamond_point(), rc::gen::inRange(0, 2), rc::gen::inRange(0, 2),
      rc::gen::element<std::int64_t>(0, 64, 128, 256, 384, 640),
      rc::gen::element<std::int64_t>(0, 64, 128, 256, 384, 640, 1000),
      rc::gen::element<std::int64_t>(0, 0, 0, 1, -1, 128));
}

// Both end points on diamond points (centres or corners).
inline rc::Gen<RawLine> between_diamond_points() {
  return rc::gen::apply(
      [](std::array<std::int64_t, 2> a, std::array<std::int64_t, 2> b) {
        return RawLine{a[0], a[1], b[0], b[1], "diamond-points"};
      },
      diamond_point(), diamond_point());
}

inline rc::Gen<RawLine> zero_length() {
  return rc::gen::apply(
      [](std::int64_t x, std::int64_t y) {
        return RawLine{x, y, x, y, "zero-length"};
      },
      rc::gen::oneOf(coord(), centre()), rc::gen::oneOf(coord(), centre()));
}

inline rc::Gen<RawLine> axis_aligned() {
  return rc::gen::apply(
      [](std::int64_t a, std::int64_t b, std::int64_t c, bool horizontal) {
        return horizontal ? RawLine{a, c, b, c, "axis-aligned"}
                          : RawLine{c, a, c, b, "axis-aligned"};
      },
      coord(), coord(),
      rc::gen::oneOf(coord(), centre(),
                     rc::gen::map(centre(), [](std::int64_t v) { return v + 128; })),
      rc::gen::arbitrary<bool>());
}

// Long lines whose ends lie far outside the target (up to 64 px away).
inline rc::Gen<RawLine> partly_outside() {
  auto far = rc::gen::inRange<std::int64_t>(-64 * 256, (kTarget + 64) * 256);
  return rc::gen::apply(
      [](std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by) {
        return RawLine{ax, ay, bx, by, "partly-outside"};
      },
      far, far, far, far);
}

inline rc::Gen<RawLine> any_line() {
  return rc::gen::weightedOneOf<RawLine>({{3, random_line()},
                                          {4, through_diamond_point()},
                                          {3, along_edge()},
                                          {2, between_diamond_points()},
                                          {1, zero_length()},
                                          {1, axis_aligned()},
                                          {1, partly_outside()}});
}

// Tie classes of a line, computed from its coordinates (not from either implementation).
struct Ties {
  bool zero_length, forty_five, axis_aligned, start_on_centre, end_on_centre, end_on_corner,
      through_corner, outside;
};

inline bool is_corner_point(std::int64_t x, std::int64_t y) {
  auto m = [](std::int64_t v) { return ((v % 256) + 256) % 256; };
  return (m(x) == 128 && m(y) == 0) || (m(x) == 0 && m(y) == 128);
}
inline bool is_centre_point(std::int64_t x, std::int64_t y) {
  auto m = [](std::int64_t v) { return ((v % 256) + 256) % 256; };
  return m(x) == 128 && m(y) == 128;
}

inline Ties ties(const RawLine& l) {
  Ties t{};
  const std::int64_t dx = l.bx - l.ax, dy = l.by - l.ay;
  t.zero_length = dx == 0 && dy == 0;
  t.forty_five = !t.zero_length && (dx == dy || dx == -dy);
  t.axis_aligned = !t.zero_length && (dx == 0 || dy == 0);
  t.start_on_centre = is_centre_point(l.ax, l.ay);
  t.end_on_centre = is_centre_point(l.bx, l.by);
  t.end_on_corner = is_corner_point(l.bx, l.by);
  // Through a diamond corner: some corner point lies on the closed segment (corners are the
  // points (k + 1/2, j) and (k, j + 1/2) px); checked for corners of the bounding box.
  t.through_corner = false;
  if (!t.zero_length) {
    const std::int64_t x0 = std::min(l.ax, l.bx), x1 = std::max(l.ax, l.bx);
    const std::int64_t y0 = std::min(l.ay, l.by), y1 = std::max(l.ay, l.by);
    for (std::int64_t x = (x0 / 128 - 1) * 128; x <= x1 && !t.through_corner; x += 128) {
      if (x < x0)
        continue;
      // y on the line at x, when exact.
      if (dx == 0) {
        for (std::int64_t y = (y0 / 128 - 1) * 128; y <= y1; y += 128) {
          if (y >= y0 && is_corner_point(x, y))
            t.through_corner = true;
        }
        continue;
      }
      const std::int64_t num = l.ay * dx + (x - l.ax) * dy;
      if (num % dx != 0)
        continue;
      const std::int64_t y = num / dx;
      if (is_corner_point(x, y))
        t.through_corner = true;
    }
  }
  auto out = [](std::int64_t v) { return v < 0 || v >= kTarget * 256; };
  t.outside = out(l.ax) || out(l.ay) || out(l.bx) || out(l.by);
  return t;
}

} // namespace rastrules::linegen
