// SPDX-License-Identifier: MIT
// The path ladder's comparators and scenes (bench/path_rungs.hpp).
// Implements: BENCH.PATH.RUNGS, BENCH.PATH.SCENES

#include "path_rungs.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <random>
#include <type_traits>

#include "rastrules/msaa.hpp"

namespace rastrules::bench::paths {

namespace {

std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  const std::int64_t q = a / b;
  return (a % b != 0 && ((a < 0) != (b < 0))) ? q - 1 : q;
}

// a / b rounded to the nearest integer, ties away from zero (b != 0).
std::int64_t round_div(std::int64_t a, std::int64_t b) {
  if (b < 0)
    a = -a, b = -b;
  return a >= 0 ? (2 * a + b) / (2 * b) : -((-2 * a + b) / (2 * b));
}

// The number kinds of accumulate(): coordinates, one pixel, the crossing of a line with a
// horizontal or vertical grid line, the cell index of a value.
template <class T> struct Num {
  static constexpr T kOne = T(1);
  static T from_raw(std::int64_t r) { return static_cast<T>(r) / T(256); }
  // The first coordinate of the line (a0, b0) -> (a1, b1) where the second one is `at`.
  static T cross(T a0, T b0, T a1, T b1, T at) { return a0 + (at - b0) * (a1 - a0) / (b1 - b0); }
  static std::int64_t cell(T v) { return static_cast<std::int64_t>(std::floor(v)); }
  static double value(T cover_sum, T area) {
    return static_cast<double>(cover_sum - area * T(0.5));
  }
};
template <> struct Num<std::int64_t> {
  static constexpr std::int64_t kOne = 256;
  static std::int64_t from_raw(std::int64_t r) { return r; }
  static std::int64_t cross(std::int64_t a0, std::int64_t b0, std::int64_t a1, std::int64_t b1,
                            std::int64_t at) {
    return a0 + round_div((at - b0) * (a1 - a0), b1 - b0);
  }
  static std::int64_t cell(std::int64_t v) { return floor_div(v, kOne); }
  static double value(std::int64_t cover_sum, std::int64_t area) {
    return static_cast<double>(2 * kOne * cover_sum - area) / static_cast<double>(2 * kOne * kOne);
  }
};

template <class T> class Cells {
public:
  Cells(std::int32_t w, std::int32_t h)
      : w_(w), h_(h), cover_(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), T(0)),
        area_(cover_.size(), T(0)), left_(static_cast<std::size_t>(h), T(0)) {}

  // rule: BENCH.PATH.RUNGS
  void line(T xa, T ya, T xb, T yb) {
    using N = Num<T>;
    if (ya == yb)
      return;
    const T ylo = std::min(ya, yb), yhi = std::max(ya, yb);
    const std::int64_t r0 = N::cell(ylo);
    const std::int64_t r1 = N::cell(yhi) - (yhi == static_cast<T>(N::cell(yhi)) * N::kOne ? 1 : 0);
    for (std::int64_t r = std::max<std::int64_t>(r0, 0); r <= std::min<std::int64_t>(r1, h_ - 1);
         ++r) {
      const T top = static_cast<T>(r) * N::kOne, bottom = top + N::kOne;
      // The piece of the line in row r, in the line's direction.
      const T y0 = ya < yb ? std::max(ya, top) : std::min(ya, bottom);
      const T y1 = ya < yb ? std::min(yb, bottom) : std::max(yb, top);
      const T x0 = y0 == ya ? xa : N::cross(xa, ya, xb, yb, y0);
      const T x1 = y1 == yb ? xb : N::cross(xa, ya, xb, yb, y1);
      row_piece(r, x0, y0, x1, y1, xa, ya, xb, yb);
    }
  }

  // rule: BENCH.PATH.RUNGS
  void resolve(path::FillRule rule, std::vector<double>& out) const {
    out.assign(cover_.size(), 0.0);
    for (std::int32_t y = 0; y < h_; ++y) {
      T acc = left_[static_cast<std::size_t>(y)];
      for (std::int32_t x = 0; x < w_; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(w_) +
                              static_cast<std::size_t>(x);
        acc += cover_[i];
        const double v = std::abs(Num<T>::value(acc, area_[i]));
        if (rule == path::FillRule::kNonZero) {
          out[i] = std::min(1.0, v);
        } else {
          const double t = std::fmod(v, 2.0);
          out[i] = t <= 1.0 ? t : 2.0 - t;
        }
      }
    }
  }

private:
  // Splits the row piece (x0, y0) -> (x1, y1) at the pixel columns; each part adds to its cell.
  void row_piece(std::int64_t r, T x0, T y0, T x1, T y1, T xa, T ya, T xb, T yb) {
    using N = Num<T>;
    const T ymin = std::min(y0, y1), ymax = std::max(y0, y1);
    T cx = x0, cy = y0;
    if (x0 != x1) {
      const bool right = x1 > x0;
      std::int64_t k = right ? N::cell(x0) + 1 : N::cell(x0);
      if (!right && static_cast<T>(k) * N::kOne == x0)
        --k;
      while (right ? static_cast<T>(k) * N::kOne < x1 : static_cast<T>(k) * N::kOne > x1) {
        const T bx = static_cast<T>(k) * N::kOne;
        const T by = std::clamp(N::cross(ya, xa, yb, xb, bx), ymin, ymax);
        add(r, cx, cy, bx, by);
        cx = bx, cy = by;
        k += right ? 1 : -1;
      }
    }
    add(r, cx, cy, x1, y1);
  }

  void add(std::int64_t r, T sx0, T sy0, T sx1, T sy1) {
    using N = Num<T>;
    const T dy = sy1 - sy0;
    if (dy == T(0))
      return;
    std::int64_t c = 0;
    if constexpr (std::is_integral_v<T>)
      c = floor_div(sx0 + sx1, 2 * N::kOne);
    else
      c = N::cell((sx0 + sx1) * T(0.5));
    const std::size_t row = static_cast<std::size_t>(r);
    if (c < 0) {
      left_[row] += dy; // left of the target: its cover still reaches every pixel of the row
      return;
    }
    if (c >= w_)
      return;
    const T base = static_cast<T>(c) * N::kOne;
    const std::size_t i = row * static_cast<std::size_t>(w_) + static_cast<std::size_t>(c);
    cover_[i] += dy;
    area_[i] += (sx0 - base + sx1 - base) * dy;
  }

  std::int32_t w_, h_;
  std::vector<T> cover_, area_, left_;
};

} // namespace

std::uint64_t PathScene::pixels() const {
  std::uint64_t n = 0;
  for (const PathItem& it : items)
    n += static_cast<std::uint64_t>(it.width) * static_cast<std::uint64_t>(it.height);
  return n;
}

std::uint64_t PathScene::segments() const {
  std::uint64_t n = 0;
  for (const PathItem& it : items)
    for (const path::Contour& c : it.lines.contours)
      n += c.segments.size() + 1;
  return n;
}

// rule: BENCH.PATH.RUNGS
template <class T>
void accumulate(const path::Path& lines, std::int32_t w, std::int32_t h, std::vector<double>& out) {
  Cells<T> cells(w, h);
  for (const path::Contour& c : lines.contours) {
    path::Point cur = c.start;
    const auto to = [&](path::Point p) {
      cells.line(Num<T>::from_raw(cur.x), Num<T>::from_raw(cur.y), Num<T>::from_raw(p.x),
                 Num<T>::from_raw(p.y));
      cur = p;
    };
    for (const path::Segment& s : c.segments)
      to(s.p[0]); // lines only: flatten() first
    to(c.start);
  }
  cells.resolve(lines.fill_rule, out);
}

template void accumulate<float>(const path::Path&, std::int32_t, std::int32_t,
                                std::vector<double>&);
template void accumulate<double>(const path::Path&, std::int32_t, std::int32_t,
                                 std::vector<double>&);
template void accumulate<std::int64_t>(const path::Path&, std::int32_t, std::int32_t,
                                       std::vector<double>&);

// rule: BENCH.PATH.RUNGS
void supersample(const path::Path& p, std::uint32_t n, std::int32_t w, std::int32_t h,
                 std::vector<double>& out) {
  out.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0.0);
  for (const path::SampleCoverage& s :
       path::cover_samples(p, standard_pattern(n), FillConvention::kTopLeft, w, h))
    out[static_cast<std::size_t>(s.y) * static_cast<std::size_t>(w) +
        static_cast<std::size_t>(s.x)] = std::popcount(s.mask) / static_cast<double>(n);
}

// rule: BENCH.PATH.SCENES
path::Path flatten(const path::Path& p, double tolerance) {
  path::Path out;
  out.fill_rule = p.fill_rule;
  const auto on_grid = [](double v) {
    return static_cast<std::int32_t>(4 * std::llround(v / 4.0));
  };
  for (const path::Contour& c : p.contours) {
    path::Contour oc{c.start, {}};
    path::Point cur = c.start;
    const auto line_to = [&](path::Point q) {
      if (!(q == cur))
        oc.segments.push_back(path::Segment{path::SegmentKind::kLine, {q, {}, {}}});
      cur = q;
    };
    for (const path::Segment& s : c.segments) {
      if (s.kind == path::SegmentKind::kLine) {
        line_to(s.p[0]);
        continue;
      }
      const bool cubic = s.kind == path::SegmentKind::kCubic;
      const std::array<path::Point, 4> q{cur, s.p[0], s.p[1], cubic ? s.p[2] : s.p[1]};
      const auto second = [&](std::size_t i) { // |Q_i - 2 Q_i+1 + Q_i+2| in px
        return std::hypot(q[i].x - 2.0 * q[i + 1].x + q[i + 2].x,
                          q[i].y - 2.0 * q[i + 1].y + q[i + 2].y) /
               256.0;
      };
      const double bound = cubic ? 0.75 * std::max(second(0), second(1)) : 0.25 * second(0);
      const int n = std::max(1, static_cast<int>(std::ceil(std::sqrt(bound / tolerance))));
      const path::Point end = cubic ? s.p[2] : s.p[1];
      for (int k = 1; k < n; ++k) {
        const double t = static_cast<double>(k) / n, u = 1.0 - t;
        double x = 0, y = 0;
        if (cubic) {
          const double b0 = u * u * u, b1 = 3 * u * u * t, b2 = 3 * u * t * t, b3 = t * t * t;
          x = b0 * q[0].x + b1 * q[1].x + b2 * q[2].x + b3 * q[3].x;
          y = b0 * q[0].y + b1 * q[1].y + b2 * q[2].y + b3 * q[3].y;
        } else {
          const double b0 = u * u, b1 = 2 * u * t, b2 = t * t;
          x = b0 * q[0].x + b1 * q[1].x + b2 * q[2].x;
          y = b0 * q[0].y + b1 * q[1].y + b2 * q[2].y;
        }
        line_to(path::Point{on_grid(x), on_grid(y)});
      }
      line_to(end);
    }
    out.contours.push_back(std::move(oc));
  }
  return out;
}

// rule: BENCH.PATH.SCENES
PathScene make_polygon_scene(std::uint64_t seed, std::int32_t side) {
  PathScene s;
  s.name = "polygons";
  s.note = "stars {7/3} and {5/2}, a contour drawn twice, a diagonal drawn there and back, "
           "three overlapping random 9-gons; each nonzero and evenodd; " +
           std::to_string(side) + " px targets";
  std::mt19937_64 rng(seed);
  const double lo = 1.0 * 256, hi = (side - 1.0) * 256;
  std::uniform_real_distribution<double> coord(lo, hi);
  const auto grid = [](double v) { return static_cast<std::int32_t>(4 * std::llround(v / 4.0)); };
  const auto contour = [](const std::vector<path::Point>& pts) {
    path::Contour c{pts.front(), {}};
    for (std::size_t i = 1; i < pts.size(); ++i)
      c.segments.push_back(path::Segment{path::SegmentKind::kLine, {pts[i], {}, {}}});
    return c;
  };
  const auto star = [&](int n, int k, double phase) {
    std::vector<path::Point> pts;
    const double cx = side * 128.0, cy = side * 128.0, rad = (side / 2.0 - 2.0) * 256.0;
    for (int i = 0; i < n; ++i) {
      const double a = phase + 2.0 * std::numbers::pi * static_cast<double>(i * k) / n;
      pts.push_back({grid(cx + rad * std::cos(a)), grid(cy + rad * std::sin(a))});
    }
    return contour(pts);
  };
  const auto random_polygon = [&](int n) {
    std::vector<path::Point> pts;
    for (int i = 0; i < n; ++i)
      pts.push_back({grid(coord(rng)), grid(coord(rng))});
    return contour(pts);
  };
  std::vector<path::Path> shapes;
  shapes.push_back(path::Path{path::FillRule::kNonZero, {star(7, 3, 0.1)}});
  shapes.push_back(path::Path{path::FillRule::kNonZero, {star(5, 2, 0.3)}});
  {
    const path::Contour c = random_polygon(7);
    shapes.push_back(path::Path{path::FillRule::kNonZero, {c, c}});
  }
  {
    // The square [a, b]^2 as one contour that runs down its diagonal and back up.
    const std::int32_t a = grid(lo + 300), b = grid(hi - 300);
    shapes.push_back(path::Path{path::FillRule::kNonZero,
                                {contour({{a, a}, {b, b}, {a, b}, {a, a}, {b, a}, {b, b}})}});
  }
  shapes.push_back(path::Path{path::FillRule::kNonZero,
                              {random_polygon(9), random_polygon(9), random_polygon(9)}});
  for (const path::Path& p : shapes)
    for (const path::FillRule rule : {path::FillRule::kNonZero, path::FillRule::kEvenOdd}) {
      PathItem it;
      it.curved = p;
      it.curved.fill_rule = rule;
      it.lines = it.curved;
      it.width = side;
      it.height = side;
      s.items.push_back(std::move(it));
    }
  return s;
}

} // namespace rastrules::bench::paths
