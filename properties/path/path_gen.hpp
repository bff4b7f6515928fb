// SPDX-License-Identifier: MIT
// Generators of 2D paths for the path properties, as a plain description that both sides are
// built from (the oracle's Path here, the kernel's in the kernel properties): polygons, stars
// (simple and self-intersecting), many contours, nested contours of both orientations,
// tie-heavy paths (points on pixel centres, corners and the 1/16 px sample grid, small
// coordinates), degenerate pieces (zero-length segments, one-point contours, doubled-back
// edges), convex polygons cut along a chord, and curves (quadratics and cubics with cusps and
// loops). Also the tie classes a path hits, for RC_CLASSIFY.
// Implements (generators for): PATH.WINDING, PATH.FILL.RULE, PATH.SAMPLE.TIE, PATH.AREA.EXACT

#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <numeric>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <rapidcheck.h>

#include "rastrules/oracle/msaa.hpp"
#include "rastrules/oracle/path.hpp"

namespace rastrules::path_gen {

namespace op = rastrules::oracle::path;
using Raw2 = op::Raw2;

// The snapped range: |raw| <= 2^23 (SNAP.VERTEX.RANGE, with 2^23 itself as a bound).
inline constexpr std::int64_t kMaxRaw = std::int64_t{1} << 23;

enum class PathKind {
  kPolygon,      // random vertices: often self-intersecting
  kStar,         // a star polygon {n/k} around a centre: simple for k = 1, else crossing
  kManyContours, // several random contours
  kNested,       // nested polygons around one centre, each orientation at random
  kTies,         // vertices on the 1/16 px grid of a tiny region: ties everywhere
  kDegenerate,   // repeated points, doubled-back edges, one-point and empty contours
  kHuge,         // vertices anywhere in the snapped range (+-2^23 raw) among near ones
  kCurves,       // quadratics and cubics among lines, some with cusps and loops
};

inline const char* name(PathKind k) {
  static constexpr std::array<const char*, 8> kNames = {
      "polygon", "star", "many contours", "nested", "ties", "degenerate", "huge", "curves"};
  return kNames[static_cast<std::size_t>(k)];
}

// A piece: degree 1 (line), 2 (quadratic), 3 (cubic); pts = controls then end.
struct GPiece {
  int degree = 1;
  std::vector<Raw2> pts;
};
struct GContour {
  Raw2 start{};
  std::vector<GPiece> pieces;
};
struct GPath {
  PathKind kind = PathKind::kPolygon;
  bool evenodd = false;
  std::vector<GContour> contours;
};

inline std::string fill_rule(const GPath& p) {
  return p.evenodd ? "evenodd" : "nonzero";
}

inline GContour polygon(const std::vector<Raw2>& pts) {
  GContour c{pts.front(), {}};
  for (std::size_t i = 1; i < pts.size(); ++i)
    c.pieces.push_back(GPiece{1, {pts[i]}});
  return c;
}

// The contour's vertices in order, start included (curves: every control point).
inline std::vector<Raw2> points(const GContour& c) {
  std::vector<Raw2> out{c.start};
  for (const GPiece& p : c.pieces)
    out.insert(out.end(), p.pts.begin(), p.pts.end());
  return out;
}

// The contour's end points in order, closed: start, each piece's end, start again.
inline std::vector<Raw2> closed_ends(const GContour& c) {
  std::vector<Raw2> ends{c.start};
  for (const GPiece& q : c.pieces)
    ends.push_back(q.pts.back());
  ends.push_back(c.start);
  return ends;
}

// The same contour traversed backwards (each piece's control points reversed).
inline GContour reversed(const GContour& c) {
  std::vector<Raw2> ends{c.start};
  for (const GPiece& p : c.pieces)
    ends.push_back(p.pts.back());
  // Start at c.start: first the closing line reversed (c.start -> last end), then every piece
  // reversed; the new contour ends at c.start, so its closing line adds nothing.
  GContour r{c.start, {}};
  if (ends.back() != c.start)
    r.pieces.push_back(GPiece{1, {ends.back()}});
  for (std::size_t i = c.pieces.size(); i-- > 0;) {
    const GPiece& p = c.pieces[i];
    GPiece q{p.degree, {}};
    for (std::size_t k = p.pts.size() - 1; k-- > 0;)
      q.pts.push_back(p.pts[k]);
    q.pts.push_back(ends[i]);
    r.pieces.push_back(q);
  }
  return r;
}

inline GPath translated(GPath p, std::int64_t dx, std::int64_t dy) {
  const auto t = [&](Raw2& r) {
    r[0] += dx;
    r[1] += dy;
  };
  for (GContour& c : p.contours) {
    t(c.start);
    for (GPiece& q : c.pieces)
      for (Raw2& r : q.pts)
        t(r);
  }
  return p;
}

// Returns whether every point of p lies in the snapped range, |raw| <= 2^23.
inline bool in_range(const GPath& p) {
  const auto ok = [](const Raw2& r) {
    return -kMaxRaw <= r[0] && r[0] <= kMaxRaw && -kMaxRaw <= r[1] && r[1] <= kMaxRaw;
  };
  for (const GContour& c : p.contours) {
    if (!ok(c.start))
      return false;
    for (const GPiece& q : c.pieces)
      if (!std::all_of(q.pts.begin(), q.pts.end(), ok))
        return false;
  }
  return true;
}

// Returns the path with every coordinate multiplied by k, each curve split at t = 1/2 (de
// Casteljau: with k a multiple of 8 every point stays an integer).
inline GPath scaled_and_split(const GPath& p, std::int64_t k) {
  const auto mul = [k](Raw2 r) { return Raw2{k * r[0], k * r[1]}; };
  const auto mid = [](Raw2 a, Raw2 b) { return Raw2{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2}; };
  GPath out{p.kind, p.evenodd, {}};
  for (const GContour& c : p.contours) {
    GContour oc{mul(c.start), {}};
    Raw2 cur = oc.start;
    for (const GPiece& q : c.pieces) {
      std::vector<Raw2> ctrl{cur};
      for (const Raw2& r : q.pts)
        ctrl.push_back(mul(r));
      if (q.degree == 1) {
        oc.pieces.push_back(GPiece{1, {ctrl[1]}});
      } else {
        // de Casteljau at 1/2: the left half's controls are the first points of each level,
        // the right half's the last ones.
        std::vector<std::vector<Raw2>> levels{ctrl};
        while (levels.back().size() > 1) {
          std::vector<Raw2> next;
          for (std::size_t i = 0; i + 1 < levels.back().size(); ++i)
            next.push_back(mid(levels.back()[i], levels.back()[i + 1]));
          levels.push_back(next);
        }
        GPiece left{q.degree, {}}, right{q.degree, {}};
        for (std::size_t l = 1; l < levels.size(); ++l)
          left.pts.push_back(levels[l].front());
        for (std::size_t l = levels.size() - 1; l-- > 0;)
          right.pts.push_back(levels[l].back());
        oc.pieces.push_back(left);
        oc.pieces.push_back(right);
      }
      cur = ctrl.back();
    }
    out.contours.push_back(oc);
  }
  return out;
}

inline bool has_curves(const GPath& p) {
  for (const GContour& c : p.contours)
    for (const GPiece& q : c.pieces)
      if (q.degree > 1)
        return true;
  return false;
}

inline op::Path to_oracle(const GPath& g) {
  op::Path p{fill_rule(g), {}};
  for (const GContour& c : g.contours) {
    op::Contour oc{c.start, {}};
    for (const GPiece& q : c.pieces) {
      const op::PieceKind k = q.degree == 1   ? op::PieceKind::kLine
                              : q.degree == 2 ? op::PieceKind::kQuadratic
                                              : op::PieceKind::kCubic;
      oc.pieces.push_back(op::Piece{k, q.pts});
    }
    p.contours.push_back(oc);
  }
  return p;
}

inline void show(const GPath& p, std::ostream& os) {
  os << name(p.kind) << ", " << fill_rule(p) << ":";
  for (const GContour& c : p.contours) {
    os << " M " << c.start[0] << " " << c.start[1];
    for (const GPiece& q : c.pieces) {
      os << (q.degree == 1 ? " L" : q.degree == 2 ? " Q" : " C");
      for (const Raw2& r : q.pts)
        os << " " << r[0] << " " << r[1];
    }
    os << " Z";
  }
  os << " (raw 1/256 px)";
}

// ---------------------------------------------------------------------------------------------
// Generators. Coordinates near a side x side px target.

template <class T> rc::Gen<T> full_size(rc::Gen<T> g) {
  return rc::gen::resize(100, std::move(g));
}

// One raw coordinate near [0, side] px: on the 1/16 px grid (samples), on pixel centres, on
// pixel corners, or anywhere on the 1/256 grid.
inline rc::Gen<std::int64_t> coord(std::int32_t side) {
  const std::int64_t lo = -192, hi = std::int64_t{side} * 256 + 192;
  return full_size(rc::gen::weightedOneOf<std::int64_t>(
      {{3, rc::gen::map(rc::gen::inRange<std::int64_t>(lo / 16, hi / 16 + 1),
                        [](std::int64_t k) { return 16 * k; })},
       {2, rc::gen::map(rc::gen::inRange<std::int64_t>(0, side),
                        [](std::int64_t k) { return 256 * k + 128; })},
       {1, rc::gen::map(rc::gen::inRange<std::int64_t>(0, side + 1),
                        [](std::int64_t k) { return 256 * k; })},
       {3, rc::gen::inRange<std::int64_t>(lo, hi + 1)}}));
}

inline rc::Gen<Raw2> point(std::int32_t side) {
  return rc::gen::exec([side] { return Raw2{*coord(side), *coord(side)}; });
}

inline std::vector<Raw2> random_points(std::int32_t side, int lo, int hi) {
  const int n = *rc::gen::inRange(lo, hi + 1);
  std::vector<Raw2> v;
  for (int i = 0; i < n; ++i) {
    Raw2 p = *point(side);
    // Shared axes now and then: horizontal and vertical edges.
    const int tie = i > 0 ? *rc::gen::inRange(0, 5) : 0;
    if (tie == 1)
      p[1] = v.back()[1];
    if (tie == 2)
      p[0] = v.back()[0];
    v.push_back(p);
  }
  return v;
}

// n points of a star polygon {n/k} (vertex i at angle 2 pi i k / n) around c, radius r raw,
// rounded to the given step (16: the sample grid).
inline std::vector<Raw2> star_points(Raw2 c, double r, int n, int k, double phase,
                                     std::int64_t step) {
  std::vector<Raw2> v;
  for (int i = 0; i < n; ++i) {
    const double a = phase + 2.0 * std::numbers::pi * i * k / n;
    const auto round_to = [step](double x) {
      return static_cast<std::int64_t>(std::llround(x / static_cast<double>(step))) * step;
    };
    v.push_back({c[0] + round_to(r * std::cos(a)), c[1] + round_to(r * std::sin(a))});
  }
  return v;
}

// Returns the least v + d, d in [0, 6), for which pred holds (every use asks for a residue
// modulo 2, 3 or 6).
template <class Pred> std::int64_t nudge(std::int64_t v, Pred pred) {
  for (std::int64_t d = 0; d < 6; ++d) {
    if (pred(v + d))
      return v + d;
  }
  throw std::logic_error("path_gen: no nudge found");
}

// A curve piece from cur through the sample-grid point S at t = 1/2, with a horizontal or
// vertical tangent, an exact cusp, or a horizontal inflection there: the ties of curves.
inline GPiece curve_through(const Raw2& cur, const Raw2& s, std::int32_t side) {
  const int form = *rc::gen::inRange(0, 6);
  Raw2 end = *point(side);
  switch (form) {
  case 0:   // quadratic, horizontal tangent at S: y(t) has its extremum there
  case 1:   // quadratic, vertical tangent at S
  case 2: { // quadratic through S
    // B(1/2) = (P0 + 2 P1 + P2) / 4 = S: P1 = (4 S - P0 - P2) / 2, P0 + P2 even.
    if (form == 0)
      end[1] = cur[1];
    if (form == 1)
      end[0] = cur[0];
    for (std::size_t k = 0; k < 2; ++k)
      end[k] = nudge(end[k], [&](std::int64_t v) { return (cur[k] + v) % 2 == 0; });
    const Raw2 ctrl{(4 * s[0] - cur[0] - end[0]) / 2, (4 * s[1] - cur[1] - end[1]) / 2};
    return GPiece{2, {ctrl, end}};
  }
  case 3: { // cubic with a cusp at S: B'(1/2) = 0 iff P3 = P0 + P1 - P2; B(1/2) = S iff
            // P2 = 4 S - P0 - 2 P1.
    const Raw2 p1 = *point(side);
    const Raw2 p2{4 * s[0] - cur[0] - 2 * p1[0], 4 * s[1] - cur[1] - 2 * p1[1]};
    return GPiece{3, {p1, p2, {cur[0] + p1[0] - p2[0], cur[1] + p1[1] - p2[1]}}};
  }
  case 4: { // cubic with a horizontal inflection at S: y controls S.y - k, S.y + k, S.y - k,
            // S.y + k (y(t) - S.y = 8 k (t - 1/2)^3), so the start's y is S.y - k.
    const std::int64_t k = s[1] - cur[1];
    const std::int64_t x1 = *coord(side);
    // x(1/2) = (x0 + 3 x1 + 3 x2 + x3) / 8 = S.x.
    const std::int64_t x3 = nudge(
        *coord(side), [&](std::int64_t v) { return (8 * s[0] - cur[0] - 3 * x1 - v) % 3 == 0; });
    const std::int64_t x2 = (8 * s[0] - cur[0] - 3 * x1 - x3) / 3;
    return GPiece{3, {{x1, s[1] + k}, {x2, s[1] - k}, {x3, s[1] + k}}};
  }
  default: { // cubic with a horizontal tangent at S: 3 (y1 + y2) = 8 S.y - y0 - y3 and
             // y2 - y1 = y0 - y3 (B'(1/2) = 3/4 (P3 + P2 - P1 - P0)).
    const std::int64_t y3 = nudge(end[1], [&](std::int64_t v) {
      const std::int64_t a = 8 * s[1] - cur[1] - v;
      return a % 3 == 0 && (a / 3 + cur[1] - v) % 2 == 0;
    });
    const std::int64_t sum = (8 * s[1] - cur[1] - y3) / 3, diff = cur[1] - y3;
    const std::int64_t y2 = (sum + diff) / 2, y1 = sum - y2;
    const std::int64_t x1 = *coord(side);
    const std::int64_t x3 =
        nudge(end[0], [&](std::int64_t v) { return (8 * s[0] - cur[0] - 3 * x1 - v) % 3 == 0; });
    const std::int64_t x2 = (8 * s[0] - cur[0] - 3 * x1 - x3) / 3;
    return GPiece{3, {{x1, y1}, {x2, y2}, {x3, y3}}};
  }
  }
}

inline rc::Gen<GContour> curve_contour(std::int32_t side) {
  return rc::gen::exec([side] {
    GContour c{*point(side), {}};
    const int n = *rc::gen::inRange(1, 5);
    Raw2 cur = c.start;
    for (int i = 0; i < n; ++i) {
      const int degree = *rc::gen::inRange(1, 4);
      GPiece q{degree, {}};
      for (int k = 0; k < degree; ++k)
        q.pts.push_back(*point(side));
      const int shape = *rc::gen::inRange(0, 7);
      if (degree == 3 && shape == 1) {
        // An exact cusp at t = 1/2: P3 = P0 + P1 - P2.
        q.pts[2] = {cur[0] + q.pts[0][0] - q.pts[1][0], cur[1] + q.pts[0][1] - q.pts[1][1]};
      } else if (degree == 3 && shape == 2) {
        // A loop: controls beyond the end points, crossing.
        const Raw2 end = q.pts[2];
        q.pts[0] = {end[0] + (end[0] - cur[0]), end[1] + (end[1] - cur[1]) / 2};
        q.pts[1] = {cur[0] - (end[0] - cur[0]), cur[1] + (end[1] - cur[1]) / 2};
      } else if (degree >= 2 && shape == 3) {
        // A horizontal tangent: a control at the start's height.
        q.pts[0][1] = cur[1];
      } else if (degree >= 2 && shape >= 5) {
        // Through a sample-grid point (often a pixel centre) with a tie there.
        const Raw2 s{16 * *rc::gen::inRange<std::int64_t>(0, side * 16),
                     16 * *rc::gen::inRange<std::int64_t>(0, side * 16)};
        q = curve_through(cur, *rc::gen::element(s, Raw2{s[0] | 128, s[1] | 128}), side);
      }
      cur = q.pts.back();
      c.pieces.push_back(q);
    }
    return c;
  });
}

// A path of the given kinds (curves only when `curves`), near a side x side px target.
inline rc::Gen<GPath> path(std::int32_t side, bool curves) {
  return full_size<GPath>(rc::gen::exec([side, curves] {
    GPath p;
    p.evenodd = *rc::gen::arbitrary<bool>();
    const int kinds = curves ? 8 : 7;
    p.kind = static_cast<PathKind>(*rc::gen::inRange(0, kinds));
    const Raw2 mid{side * 128, side * 128};
    switch (p.kind) {
    case PathKind::kPolygon:
      p.contours.push_back(polygon(random_points(side, 3, 8)));
      break;
    case PathKind::kStar: {
      const int n = *rc::gen::inRange(3, 10);
      const int k = *rc::gen::inRange(1, std::max(2, n / 2 + 1));
      const double r = *rc::gen::inRange(64, side * 128 + 64);
      const std::int64_t step = *rc::gen::element<std::int64_t>(1, 16, 128);
      p.contours.push_back(
          polygon(star_points(*point(side), r, n, k, *rc::gen::inRange(0, 100) / 16.0, step)));
      break;
    }
    case PathKind::kManyContours: {
      const int n = *rc::gen::inRange(2, 6);
      for (int i = 0; i < n; ++i)
        p.contours.push_back(polygon(random_points(side, 1, 5)));
      break;
    }
    case PathKind::kNested: {
      const int n = *rc::gen::inRange(2, 4);
      const int sides = *rc::gen::inRange(3, 7);
      for (int i = 0; i < n; ++i) {
        const double r = (side * 128.0 + 64.0) * (n - i) / n;
        GContour c = polygon(star_points(mid, r, sides, 1, 0.25 * i, 16));
        if (*rc::gen::arbitrary<bool>())
          c = reversed(c);
        p.contours.push_back(c);
      }
      break;
    }
    case PathKind::kTies: {
      // A region of about 2 x 2 px at the origin, on the 1/16 px grid (or coarser).
      const std::int64_t step = *rc::gen::element<std::int64_t>(16, 32, 64, 128);
      const int n = *rc::gen::inRange(1, 4);
      for (int i = 0; i < n; ++i) {
        std::vector<Raw2> v;
        const int m = *rc::gen::inRange(3, 7);
        for (int k = 0; k < m; ++k)
          v.push_back({step * *rc::gen::inRange<std::int64_t>(0, 512 / step + 1),
                       step * *rc::gen::inRange<std::int64_t>(0, 512 / step + 1)});
        p.contours.push_back(polygon(v));
      }
      break;
    }
    case PathKind::kDegenerate: {
      std::vector<Raw2> v = random_points(side, 2, 6);
      // Repeat a point (a zero-length segment), double back along an edge, add a one-point
      // contour and an empty one.
      v.insert(v.begin() + 1, v[0]);
      v.push_back(v[1]);
      v.push_back(v.back());
      p.contours.push_back(polygon(v));
      p.contours.push_back(GContour{*point(side), {}});
      p.contours.push_back(polygon({v[0], v[2], v[0]}));
      break;
    }
    case PathKind::kHuge: {
      // Far vertices (the range ends, 2^23 raw = 32768 px, and random far points) with near
      // ones: long edges crossing the target at every slope.
      std::vector<Raw2> v = random_points(side, 2, 5);
      const int far = *rc::gen::inRange(1, 4);
      for (int i = 0; i < far; ++i) {
        const auto c = [] {
          return *rc::gen::weightedOneOf<std::int64_t>(
              {{1, rc::gen::element<std::int64_t>(-kMaxRaw, kMaxRaw, -kMaxRaw + 1, kMaxRaw - 1)},
               {2, rc::gen::inRange<std::int64_t>(-kMaxRaw, kMaxRaw + 1)}});
        };
        const Raw2 q{c(), c()};
        v.insert(v.begin() + *rc::gen::inRange<std::ptrdiff_t>(
                                 0, static_cast<std::ptrdiff_t>(v.size()) + 1),
                 q);
      }
      p.contours.push_back(polygon(v));
      break;
    }
    case PathKind::kCurves: {
      const int n = *rc::gen::inRange(1, 4);
      for (int i = 0; i < n; ++i)
        p.contours.push_back(*curve_contour(side));
      break;
    }
    }
    return p;
  }));
}

// A convex polygon (clockwise or not) with a chord between two of its vertices, strictly
// inside it but for its ends: the two halves share the chord, traversed in opposite directions.
struct CutPolygon {
  GContour whole;
  GContour first;
  GContour second;
  bool chord_polyline = false;
};

// Returns twice the signed area of the triangle (a, b, c), exact (|raw| < 2^28).
inline std::int64_t orient(const Raw2& a, const Raw2& b, const Raw2& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// The convex hull of v (Andrew's monotone chain), without collinear points, counter-clockwise
// in CGAL's axes (clockwise on screen).
inline std::vector<Raw2> hull(std::vector<Raw2> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  if (v.size() < 3)
    return v;
  std::vector<Raw2> h(2 * v.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    while (k >= 2 && orient(h[k - 2], h[k - 1], v[i]) <= 0)
      --k;
    h[k++] = v[i];
  }
  for (std::size_t i = v.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && orient(h[k - 2], h[k - 1], v[i]) <= 0)
      --k;
    h[k++] = v[i];
  }
  h.resize(k - 1);
  return h;
}

inline bool strictly_inside_convex(const std::vector<Raw2>& h, const Raw2& p) {
  for (std::size_t i = 0; i < h.size(); ++i) {
    if (orient(h[i], h[(i + 1) % h.size()], p) <= 0)
      return false;
  }
  return true;
}

inline rc::Gen<CutPolygon> cut_polygon(std::int32_t side) {
  return full_size<CutPolygon>(rc::gen::exec([side] {
    std::vector<Raw2> h;
    while (h.size() < 4)
      h = hull(random_points(side, 4, 9));
    if (*rc::gen::arbitrary<bool>())
      std::reverse(h.begin(), h.end());
    const std::size_t n = h.size();
    const std::size_t k = *rc::gen::inRange<std::size_t>(2, n - 1); // chord h[0] -> h[k]
    // The chord: the straight line, or a polyline through interior points whose projections on
    // the chord increase (a simple path strictly inside but for its ends).
    std::vector<Raw2> chord;
    CutPolygon out;
    if (*rc::gen::arbitrary<bool>()) {
      const int m = *rc::gen::inRange(1, 4);
      const Raw2 a = h[0], b = h[k];
      const std::int64_t dx = b[0] - a[0], dy = b[1] - a[1];
      std::int64_t last = 0;
      for (int i = 1; i <= m; ++i) {
        const double t = static_cast<double>(i) / (m + 1);
        const double off = *rc::gen::inRange(-200, 201) / 400.0;
        const double fx = static_cast<double>(dx), fy = static_cast<double>(dy);
        const Raw2 q{a[0] + std::llround(t * fx - off * fy),
                     a[1] + std::llround(t * fy + off * fx)};
        const std::int64_t proj = (q[0] - a[0]) * dx + (q[1] - a[1]) * dy;
        const std::int64_t total = dx * dx + dy * dy;
        if (strictly_inside_convex(h, q) && proj > last && proj < total) {
          chord.push_back(q);
          last = proj;
        }
      }
      out.chord_polyline = !chord.empty();
    }
    std::vector<Raw2> first(h.begin(), h.begin() + static_cast<std::ptrdiff_t>(k + 1));
    first.insert(first.end(), chord.rbegin(), chord.rend()); // h[k] back to h[0]
    std::vector<Raw2> second(h.begin() + static_cast<std::ptrdiff_t>(k), h.end());
    second.push_back(h[0]);
    second.insert(second.end(), chord.begin(), chord.end()); // h[0] on to h[k]
    out.whole = polygon(h);
    out.first = polygon(first);
    out.second = polygon(second);
    return out;
  }));
}

// ---------------------------------------------------------------------------------------------
// Samples on ties

// Returns raw points that sit on the path's ties: every vertex and control point, the lattice
// points of the 1/16 px grid on each line segment (a few), and the raw points next to them.
inline std::vector<Raw2> tie_points(const GPath& p) {
  std::vector<Raw2> base;
  for (const GContour& c : p.contours) {
    const std::vector<Raw2> v = points(c);
    base.insert(base.end(), v.begin(), v.end());
    const std::vector<Raw2> ends = closed_ends(c);
    // A curve's point at t = 1/2 when it is a raw point: (P0 + 2 P1 + P2) / 4 or
    // (P0 + 3 P1 + 3 P2 + P3) / 8.
    for (std::size_t i = 0; i < c.pieces.size(); ++i) {
      const GPiece& q = c.pieces[i];
      if (q.degree == 1)
        continue;
      const std::int64_t den = q.degree == 2 ? 4 : 8;
      Raw2 m{};
      for (std::size_t k = 0; k < 2; ++k) {
        m[k] = q.degree == 2 ? ends[i][k] + 2 * q.pts[0][k] + q.pts[1][k]
                             : ends[i][k] + 3 * q.pts[0][k] + 3 * q.pts[1][k] + q.pts[2][k];
      }
      if (m[0] % den == 0 && m[1] % den == 0)
        base.push_back({m[0] / den, m[1] / den});
    }
    for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
      const Raw2 a = ends[i], b = ends[i + 1];
      const std::int64_t dx = b[0] - a[0], dy = b[1] - a[1];
      const std::int64_t g = std::gcd(std::abs(dx), std::abs(dy));
      if (g == 0)
        continue;
      const std::int64_t stepx = dx / g, stepy = dy / g;
      const std::int64_t count = std::min<std::int64_t>(g - 1, 4);
      for (std::int64_t j = 1; j <= count; ++j) {
        const std::int64_t at = j * g / (count + 1);
        base.push_back({a[0] + at * stepx, a[1] + at * stepy});
      }
    }
  }
  std::vector<Raw2> out;
  for (const Raw2& r : base) {
    out.push_back(r);
    out.push_back({r[0] + 1, r[1]});
    out.push_back({r[0] - 1, r[1]});
    out.push_back({r[0], r[1] + 1});
    out.push_back({r[0], r[1] - 1});
  }
  // Only points in the snapped range (the neighbours of a vertex at +-2^23 are not).
  std::erase_if(out, [](const Raw2& r) {
    return r[0] < -kMaxRaw || r[0] > kMaxRaw || r[1] < -kMaxRaw || r[1] > kMaxRaw;
  });
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

inline const std::vector<std::string>& conventions() {
  static const std::vector<std::string> k = {"top-left", "top-right", "bottom-left",
                                             "bottom-right"};
  return k;
}

// Tie classes of a path against the samples of a pattern on a side x side target: a sample on
// a vertex, a sample on a line segment, a horizontal or vertical segment through a sample.
struct Ties {
  bool on_vertex = false;
  bool on_edge = false;
  bool on_horizontal = false;
  bool on_vertical = false;
};

inline Ties ties(const GPath& p, const std::vector<rastrules::oracle::msaa::Offset>& pattern,
                 std::int32_t side) {
  Ties t;
  for (std::int32_t y = 0; y < side; ++y) {
    for (std::int32_t x = 0; x < side; ++x) {
      for (const auto& o : pattern) {
        const Raw2 s = rastrules::oracle::msaa::sample_raw(x, y, o);
        for (const GContour& c : p.contours) {
          const std::vector<Raw2> ends = closed_ends(c);
          for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
            const Raw2 a = ends[i], b = ends[i + 1];
            t.on_vertex = t.on_vertex || a == s;
            const bool on = orient(a, b, s) == 0 && std::min(a[0], b[0]) <= s[0] &&
                            s[0] <= std::max(a[0], b[0]) && std::min(a[1], b[1]) <= s[1] &&
                            s[1] <= std::max(a[1], b[1]) && a != b;
            t.on_edge = t.on_edge || on;
            t.on_horizontal = t.on_horizontal || (on && a[1] == b[1]);
            t.on_vertical = t.on_vertical || (on && a[0] == b[0]);
          }
        }
      }
    }
  }
  return t;
}

} // namespace rastrules::path_gen
