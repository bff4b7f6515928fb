// SPDX-License-Identifier: MIT
// Exact oracle for 2D paths (rastrules/oracle/path.hpp). No kernel code, no kernel formula:
// lines are decided by the words of the boundary convention, curves by exact root isolation
// (Sturm-Tarski queries over GMP rationals), areas by a CGAL arrangement over GMP rationals.
// Implements (as oracle): PATH.GEOMETRY, PATH.CONTOUR.CLOSE, PATH.WINDING, PATH.FILL.RULE,
//   PATH.SAMPLE.TIE, PATH.COVER.SAMPLE, PATH.AREA.EXACT, PATH.DEGENERATE

#include "rastrules/oracle/path.hpp"

#include <gmpxx.h>

#include <CGAL/Arr_extended_dcel.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/convex_hull_2.h>

#include <algorithm>
#include <cstdint>
#include <deque>
#include <iterator>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rastrules::oracle::path {
namespace {

// (sx, sy) of PATH.SAMPLE.TIE: the fill convention's inclusive sides (TRI.FILL.CONVENTION, read
// by the triangle oracle's parse_fill) say where the sample moves: "left" edges inclusive means
// the sample moves right (+x), "top" edges inclusive means it moves down (+y, y down).
// rule: PATH.SAMPLE.TIE, TRI.FILL.CONVENTION
struct Displacement {
  int sx = 1;
  int sy = 1;
};

Displacement displacement(const std::string& fill) {
  const FillSides f = parse_fill(fill);
  return Displacement{f.left ? 1 : -1, f.top ? 1 : -1};
}

int sign64(std::int64_t v) {
  return v > 0 ? 1 : v < 0 ? -1 : 0;
}

// ---------------------------------------------------------------------------------------------
// Lines, by the contract's words.

// Returns the contribution of the directed line a -> b to w(s') (PATH.WINDING,
// PATH.SAMPLE.TIE): s' = (X + sx e, Y + sy e^2).
//  - In y: the ray from s' meets the line iff s'.y lies strictly between y0 and y1. As s'.y =
//    Y + sy e^2 differs from every rational, that is y0 <= Y < y1 (or y1 <= Y < y0) for sy = +1
//    and y0 < Y <= y1 (or y1 < Y <= y0) for sy = -1. A horizontal line never meets it.
//  - In x: the line's x at height s'.y is xc + O(e^2), xc its x at height Y; s'.x = X + sx e.
//    So the crossing is right of s' iff xc > X, or xc == X and sx = -1.
//  - Sign: +1 where the boundary goes down (y1 > y0), -1 where it goes up.
// Exact in 64-bit integers: |coordinate| < 2^28 (checked by check_range), so differences are
// below 2^29, products below 2^58 and their sum below 2^59.
// rule: PATH.WINDING, PATH.SAMPLE.TIE
int line_crossing(const Raw2& a, const Raw2& b, const Raw2& s, Displacement d) {
  const std::int64_t x0 = a[0], y0 = a[1], x1 = b[0], y1 = b[1], X = s[0], Y = s[1];
  if (y0 == y1)
    return 0;
  const std::int64_t lo = std::min(y0, y1), hi = std::max(y0, y1);
  const bool in_y = d.sy > 0 ? (lo <= Y && Y < hi) : (lo < Y && Y <= hi);
  if (!in_y)
    return 0;
  // xc - X = ((x0 - X)(y1 - y0) + (x1 - x0)(Y - y0)) / (y1 - y0).
  const int side = sign64((x0 - X) * (y1 - y0) + (x1 - x0) * (Y - y0)) * sign64(y1 - y0);
  const bool right = side > 0 || (side == 0 && d.sx < 0);
  if (!right)
    return 0;
  return y1 > y0 ? 1 : -1;
}

// ---------------------------------------------------------------------------------------------
// Polynomials over Q (coefficient of t^i at index i, no trailing zeros; empty is 0).

using Poly = std::vector<mpq_class>;

Poly trimmed(Poly p) {
  while (!p.empty() && p.back() == 0)
    p.pop_back();
  return p;
}

mpq_class eval(const Poly& p, const mpq_class& t) {
  mpq_class r = 0;
  for (auto it = p.rbegin(); it != p.rend(); ++it)
    r = r * t + *it;
  return r;
}

Poly deriv(const Poly& p) {
  Poly r;
  for (std::size_t i = 1; i < p.size(); ++i)
    r.push_back(p[i] * static_cast<long>(i));
  return trimmed(r);
}

Poly mul(const Poly& a, const Poly& b) {
  if (a.empty() || b.empty())
    return {};
  Poly r(a.size() + b.size() - 1, mpq_class(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j)
      r[i + j] += a[i] * b[j];
  return trimmed(r);
}

// Euclidean division a = q b + r, deg r < deg b; b nonzero.
std::pair<Poly, Poly> divmod(Poly a, const Poly& b) {
  if (b.empty())
    throw std::logic_error("oracle: polynomial division by zero");
  a = trimmed(std::move(a));
  Poly q(a.size() >= b.size() ? a.size() - b.size() + 1 : 0, mpq_class(0));
  while (!a.empty() && a.size() >= b.size()) {
    const std::size_t shift = a.size() - b.size();
    const mpq_class c = a.back() / b.back();
    q[shift] = c;
    for (std::size_t i = 0; i < b.size(); ++i)
      a[shift + i] -= c * b[i];
    a.pop_back(); // the leading coefficient is now exactly zero
    a = trimmed(std::move(a));
  }
  return {trimmed(q), a};
}

// Returns the number of sign changes in the values of the sequence at t, zeros dropped.
int variations(const std::vector<Poly>& seq, const mpq_class& t) {
  int changes = 0, last = 0;
  for (const Poly& p : seq) {
    const int s = sgn(eval(p, t));
    if (s == 0)
      continue;
    if (last != 0 && s != last)
      ++changes;
    last = s;
  }
  return changes;
}

// Tarski query: returns the sum over the distinct roots r of P in (a, b) of sign Q(r), for P
// nonzero and P(a), P(b) != 0. Sturm-Tarski theorem (Basu, Pollack, Roy, "Algorithms in Real
// Algebraic Geometry", Thm 2.58): it equals Var(a) - Var(b) of the signed remainder sequence
// of P and P'Q. (Q = 1 counts the distinct roots: Sturm's theorem.) The proof goes through the
// Cauchy index of P'Q/P, whose pole at a root of multiplicity m has residue m Q(r): the
// theorem holds for P with multiple roots too.
int tarski_query(const Poly& p, const Poly& q, const mpq_class& a, const mpq_class& b) {
  if (eval(p, a) == 0 || eval(p, b) == 0)
    throw std::logic_error("oracle: Tarski query with a root at an end");
  std::vector<Poly> seq{p, mul(deriv(p), q)};
  while (!seq.back().empty()) {
    Poly r = divmod(seq[seq.size() - 2], seq.back()).second;
    for (mpq_class& c : r)
      c = -c;
    seq.push_back(trimmed(std::move(r)));
  }
  seq.pop_back();
  return variations(seq, a) - variations(seq, b);
}

// Appends to `out` intervals (a, b) with rational ends that are not roots of p, each holding
// exactly one distinct root of p, covering every root of p in (lo, hi); p(lo), p(hi) != 0.
void isolate(const Poly& p, const mpq_class& lo, const mpq_class& hi,
             std::vector<std::pair<mpq_class, mpq_class>>& out) {
  const int n = tarski_query(p, Poly{mpq_class(1)}, lo, hi);
  if (n == 0)
    return;
  if (n == 1) {
    out.emplace_back(lo, hi);
    return;
  }
  mpq_class c = (lo + hi) / 2;
  while (eval(p, c) == 0) // p has at most deg p roots: this ends
    c = (c + hi) / 2;
  isolate(p, lo, c, out);
  isolate(p, c, hi, out);
}

// Power-basis coordinates of a Bezier piece of degree 1, 2 or 3 from its control points.
Poly bezier(const std::vector<mpq_class>& c) {
  switch (c.size()) {
  case 2:
    return trimmed({c[0], c[1] - c[0]});
  case 3:
    return trimmed({c[0], 2 * (c[1] - c[0]), c[0] - 2 * c[1] + c[2]});
  case 4:
    return trimmed(
        {c[0], 3 * (c[1] - c[0]), 3 * (c[0] - 2 * c[1] + c[2]), c[3] - 3 * c[2] + 3 * c[1] - c[0]});
  default:
    throw std::logic_error("oracle: a Bezier piece has 2 to 4 control points");
  }
}

// Returns the contribution of the polynomial piece (x(t), y(t)), t in [0, 1], to w(s').
//
// Reading of the infinitesimals. The ray from s' = (X + sx e, Y + sy e^2) meets the piece
// where f(t) := y(t) - Y = sy e^2. As e -> 0 those roots gather at the roots t0 of f in [0, 1]
// (f not identically 0; a piece with y constant never meets the ray, as s'.y is not rational).
//  - Signed count: near t0 the crossings of the level sy e^2 sum, with +1 where y increases,
//    to H(f(t0+)) - H(f(t0-)) (H(v) = 1 if v > 0, f(t0+-) the sign of f just beside t0), since
//    |f| there is a nonzero constant times a power of (t - t0), far larger than e^2. At an end
//    of the piece the value there is f(0) - sy e^2 = -sy e^2: H = 1 iff sy = -1.
//  - Side: those crossings have x -> x(t0). If x(t0) != X that decides. If x(t0) == X (the
//    boundary passes through s), the crossings sit at X + O(e^(2/m)) for a root of multiplicity
//    m; the decision below takes them as exactly X + o(e), i.e. right of s' iff sx = -1, which
//    is the contract's rule for lines (m = 1, offset O(e^2)) and what splitting the curve into
//    y-monotone pieces and applying the line rule to each gives. For m >= 2 (a horizontal
//    tangent or a horizontal inflection exactly at s) the literal s + (sx e, sy e^2) would
//    instead compare the offsets e^(2/m) with e (a curvature comparison for m = 2), and for a
//    quadratic whose arc is the displacement parabola itself (P0 = s, P1 = s + (sx/2, 0) px,
//    P2 = s + (sx, sy) px) s' lies on the boundary: the literal reading is undefined there.
//    This oracle implements the lexicographic reading (y displaced infinitely less than any
//    power of the x displacement), which agrees with the literal one whenever m = 1: it is
//    PATH.SAMPLE.TIE as spec/rules/path.md states it (s + (hx eps, hy delta), delta << eps).
// rule: PATH.WINDING, PATH.SAMPLE.TIE
std::int64_t piece_crossings(const Poly& x, const Poly& y, const Raw2& s, Displacement d) {
  Poly f = y;
  if (f.empty())
    f.push_back(mpq_class(0));
  f[0] -= mpq_class(static_cast<long>(s[1]));
  f = trimmed(f);
  if (f.size() <= 1)
    return 0; // constant: never on the ray's line, or horizontal on it (s'.y differs)
  Poly g = x;
  if (g.empty())
    g.push_back(mpq_class(0));
  g[0] -= mpq_class(static_cast<long>(s[0]));
  g = trimmed(g);
  const auto right_of = [&](int side) { return side > 0 || (side == 0 && d.sx < 0); };
  const int h_end = d.sy < 0 ? 1 : 0; // H(-sy e^2)
  // f = t^k (1 - t)^j h with h(0), h(1) != 0; on (0, 1) f and h have the same sign.
  Poly h = f;
  bool root0 = false, root1 = false;
  while (h.front() == 0) {
    h.erase(h.begin());
    root0 = true;
  }
  while (eval(h, mpq_class(1)) == 0) {
    h = divmod(h, Poly{mpq_class(1), mpq_class(-1)}).first;
    root1 = true;
  }
  std::int64_t total = 0;
  const auto H = [](const mpq_class& v) { return v > 0 ? 1 : 0; };
  if (root0 && right_of(sgn(eval(g, mpq_class(0)))))
    total += H(eval(h, mpq_class(0))) - h_end;
  if (root1 && right_of(sgn(eval(g, mpq_class(1)))))
    total += h_end - H(eval(h, mpq_class(1)));
  std::vector<std::pair<mpq_class, mpq_class>> roots;
  if (h.size() > 1)
    isolate(h, mpq_class(0), mpq_class(1), roots);
  for (const auto& [a, b] : roots) {
    // One distinct root r of h in (a, b): sign g(r) is the Tarski query of g on it.
    if (right_of(tarski_query(h, g, a, b)))
      total += H(eval(h, b)) - H(eval(h, a));
  }
  return total;
}

mpq_class q_of(std::int64_t v) {
  return mpq_class(mpz_class(static_cast<long>(v)));
}

std::int64_t roots_crossing(const std::vector<Raw2>& ctrl, const Raw2& s, Displacement d) {
  // A Bezier piece lies in the hull of its control points: when s.y is strictly outside their
  // y range, f has no root in [0, 1]; when s.x is beyond their largest x, every crossing is
  // left of s'. Either way the piece adds nothing (a shortcut, not a decision).
  std::int64_t lo_y = ctrl[0][1], hi_y = lo_y, hi_x = ctrl[0][0];
  for (const Raw2& p : ctrl) {
    lo_y = std::min(lo_y, p[1]);
    hi_y = std::max(hi_y, p[1]);
    hi_x = std::max(hi_x, p[0]);
  }
  if (s[1] < lo_y || s[1] > hi_y || s[0] > hi_x)
    return 0;
  std::vector<mpq_class> xs, ys;
  for (const Raw2& p : ctrl) {
    xs.push_back(q_of(p[0]));
    ys.push_back(q_of(p[1]));
  }
  return piece_crossings(bezier(xs), bezier(ys), s, d);
}

constexpr std::int64_t kLimit = std::int64_t{1} << 28;

bool in_range(const Raw2& r) {
  return r[0] > -kLimit && r[0] < kLimit && r[1] > -kLimit && r[1] < kLimit;
}

// Path coordinates are snapped (|raw| <= 2^23); the oracle accepts up to 2^28.
void check_range(const Path& p) {
  const auto ok = in_range;
  for (const Contour& c : p.contours) {
    if (!ok(c.start))
      throw std::invalid_argument("oracle: path coordinate beyond 2^28 raw");
    for (const Piece& pc : c.pieces) {
      const std::size_t n = pc.kind == PieceKind::kLine        ? 1
                            : pc.kind == PieceKind::kQuadratic ? 2
                                                               : 3;
      if (pc.to.size() != n)
        throw std::invalid_argument("oracle: a piece has the wrong number of points");
      for (const Raw2& r : pc.to) {
        if (!ok(r))
          throw std::invalid_argument("oracle: path coordinate beyond 2^28 raw");
      }
    }
  }
}

std::int64_t winding_impl(const Path& p, const Raw2& s, const std::string& fill, bool all_roots) {
  check_range(p);
  if (!in_range(s))
    throw std::invalid_argument("oracle: sample beyond 2^28 raw");
  const Displacement d = displacement(fill);
  std::int64_t w = 0;
  for (const Contour& c : p.contours) {
    Raw2 cur = c.start;
    const auto add = [&](const std::vector<Raw2>& ctrl) {
      if (ctrl.size() == 2 && !all_roots) {
        w += line_crossing(ctrl[0], ctrl[1], s, d);
      } else {
        w += roots_crossing(ctrl, s, d);
      }
    };
    for (const Piece& pc : c.pieces) {
      std::vector<Raw2> ctrl{cur};
      ctrl.insert(ctrl.end(), pc.to.begin(), pc.to.end());
      add(ctrl);
      cur = pc.to.back();
    }
    if (cur != c.start) // closed for filling by a straight line back to the start
      add({cur, c.start});
  }
  return w;
}

} // namespace

// rule: PATH.FILL.RULE
bool fills(const std::string& fill_rule, std::int64_t w) {
  if (fill_rule == "nonzero")
    return w != 0;
  if (fill_rule == "evenodd")
    return w % 2 != 0;
  throw std::invalid_argument("oracle: unknown fill rule '" + fill_rule + "'");
}

bool has_curves(const Path& p) {
  for (const Contour& c : p.contours)
    for (const Piece& pc : c.pieces)
      if (pc.kind != PieceKind::kLine)
        return true;
  return false;
}

// rule: PATH.WINDING, PATH.SAMPLE.TIE
std::int64_t winding(const Path& p, const Raw2& s, const std::string& fill) {
  return winding_impl(p, s, fill, false);
}

std::int64_t winding_by_roots(const Path& p, const Raw2& s, const std::string& fill) {
  return winding_impl(p, s, fill, true);
}

// rule: PATH.FILL.RULE, PATH.SAMPLE.TIE
bool covers(const Path& p, const Raw2& s, const std::string& fill) {
  return fills(p.fill_rule, winding(p, s, fill));
}

std::vector<SampleMask> cover_samples(const Path& p, const std::vector<msaa::Offset>& pattern,
                                      const std::string& fill, std::int32_t w, std::int32_t h) {
  if (pattern.empty() || pattern.size() > 32)
    throw std::invalid_argument("oracle: a pattern has 1 to 32 samples");
  (void)fills(p.fill_rule, 0); // a bad fill rule is an error even on an empty target
  std::vector<SampleMask> out;
  for (std::int32_t y = 0; y < h; ++y) {
    for (std::int32_t x = 0; x < w; ++x) {
      std::uint32_t mask = 0;
      for (std::size_t k = 0; k < pattern.size(); ++k) {
        if (covers(p, msaa::sample_raw(x, y, pattern[k]), fill))
          mask |= std::uint32_t{1} << k;
      }
      if (mask != 0)
        out.push_back(SampleMask{x, y, mask});
    }
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Area, by an arrangement.

namespace {

using AK = CGAL::Simple_cartesian<CGAL::Gmpq>;
using Traits = CGAL::Arr_segment_traits_2<AK>;
using Dcel = CGAL::Arr_face_extended_dcel<Traits, std::optional<std::int64_t>>;
using Arr = CGAL::Arrangement_2<Traits, Dcel>;
using APoint = AK::Point_2;
using ASegment = AK::Segment_2;

mpq_class to_mpq(const CGAL::Gmpq& q) {
  return mpq_class(q.mpq());
}

APoint apoint(const Raw2& r) {
  return APoint(CGAL::Gmpq(static_cast<long>(r[0])), CGAL::Gmpq(static_cast<long>(r[1])));
}

// The path as straight segments, closing lines included, zero-length ones left out: each
// curve split 'depth' times at t = 1/2 (de Casteljau, exact) and replaced by its pieces'
// chords, the pieces' control polygons kept in 'pieces' (where the chords may differ from the
// curve: each piece and its chord lie in the hull of its control points).
struct Flat {
  std::vector<ASegment> segs;
  std::vector<std::vector<APoint>> pieces;
};

void split_curve(const std::vector<APoint>& c, int depth, Flat& out) {
  if (depth == 0) {
    if (c.front() != c.back())
      out.segs.emplace_back(c.front(), c.back());
    out.pieces.push_back(c);
    return;
  }
  std::vector<std::vector<APoint>> levels{c};
  while (levels.back().size() > 1) {
    std::vector<APoint> next;
    for (std::size_t i = 0; i + 1 < levels.back().size(); ++i)
      next.push_back(CGAL::midpoint(levels.back()[i], levels.back()[i + 1]));
    levels.push_back(next);
  }
  std::vector<APoint> left, right;
  for (const auto& l : levels)
    left.push_back(l.front());
  for (auto l = levels.rbegin(); l != levels.rend(); ++l)
    right.push_back(l->back());
  split_curve(left, depth - 1, out);
  split_curve(right, depth - 1, out);
}

// depth < 0: curves are not allowed (exact areas of lines only).
Flat flatten(const Path& p, int depth) {
  Flat out;
  for (const Contour& c : p.contours) {
    Raw2 cur = c.start;
    for (const Piece& pc : c.pieces) {
      if (pc.kind == PieceKind::kLine) {
        if (pc.to.back() != cur)
          out.segs.emplace_back(apoint(cur), apoint(pc.to.back()));
      } else {
        if (depth < 0)
          throw std::invalid_argument("oracle: exact area coverage of curves is not modelled");
        std::vector<APoint> ctrl{apoint(cur)};
        for (const Raw2& r : pc.to)
          ctrl.push_back(apoint(r));
        split_curve(ctrl, depth, out);
      }
      cur = pc.to.back();
    }
    if (cur != c.start)
      out.segs.emplace_back(apoint(cur), apoint(c.start));
  }
  return out;
}

mpz_class floor_q(const mpq_class& q) {
  mpz_class r;
  mpz_fdiv_q(r.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
  return r;
}

using PixelMap = std::map<std::pair<std::int64_t, std::int64_t>, mpq_class>; // (y, x) -> px^2

// The pixels of [0, w) x [0, h) that the box [lo, hi] (raw) reaches, closed: [i0, i1) x
// [j0, j1); empty when i0 >= i1 or j0 >= j1.
std::array<std::int64_t, 4> pixel_range(const mpq_class& lo_x, const mpq_class& lo_y,
                                        const mpq_class& hi_x, const mpq_class& hi_y,
                                        std::int32_t w, std::int32_t h) {
  return {std::max<std::int64_t>(0, floor_q(lo_x / 256).get_si()),
          std::max<std::int64_t>(0, floor_q(lo_y / 256).get_si()),
          std::min<std::int64_t>(w, floor_q(hi_x / 256).get_si() + 1),
          std::min<std::int64_t>(h, floor_q(hi_y / 256).get_si() + 1)};
}

PixelMap areas_of(const std::string& fill_rule, const std::vector<ASegment>& path_segs,
                  std::int32_t w, std::int32_t h);

} // namespace

namespace {

// The exact area (px^2) where the fill rule holds, per pixel of [0, w) x [0, h), of the region
// bounded by the directed segments: a CGAL arrangement of the segments and the grid lines of
// the pixels their box reaches, the winding number of every face propagated from the
// unbounded face, and the area of the faces where the rule holds.
// rule: PATH.AREA.EXACT, PATH.WINDING, PATH.FILL.RULE
PixelMap areas_of(const std::string& fill_rule, const std::vector<ASegment>& path_segs,
                  std::int32_t w, std::int32_t h) {
  if (path_segs.empty() || w <= 0 || h <= 0)
    return {};
  // The pixels the path's bounding box reaches, within the target; no other pixel has area.
  mpq_class lo_x = to_mpq(path_segs[0].source().x()), hi_x = lo_x;
  mpq_class lo_y = to_mpq(path_segs[0].source().y()), hi_y = lo_y;
  for (const ASegment& sg : path_segs) {
    for (const APoint& q : {sg.source(), sg.target()}) {
      lo_x = std::min(lo_x, to_mpq(q.x()));
      hi_x = std::max(hi_x, to_mpq(q.x()));
      lo_y = std::min(lo_y, to_mpq(q.y()));
      hi_y = std::max(hi_y, to_mpq(q.y()));
    }
  }
  const auto [i0, j0, i1, j1] = pixel_range(lo_x, lo_y, hi_x, hi_y, w, h);
  if (i0 >= i1 || j0 >= j1)
    return {};

  // The path's segments and the grid lines of those pixels, in raw units.
  std::vector<ASegment> curves = path_segs;
  for (std::int64_t i = i0; i <= i1; ++i)
    curves.emplace_back(apoint({256 * i, 256 * j0}), apoint({256 * i, 256 * j1}));
  for (std::int64_t j = j0; j <= j1; ++j)
    curves.emplace_back(apoint({256 * i0, 256 * j}), apoint({256 * i1, 256 * j}));
  Arr arr;
  CGAL::insert(arr, curves.begin(), curves.end());

  // m(e): the path segments lying along the halfedge e, +1 each in e's direction, -1 against.
  // Crossing a directed boundary piece from its right to its left raises the winding number
  // by one (PATH.WINDING: +1 where the boundary goes +y, counted on the ray towards +x), and
  // the face of a CGAL halfedge is the one on its left: w(e.face) = w(e.twin.face) + m(e).
  const auto multiplicity = [&](Arr::Halfedge_const_handle e) {
    const APoint& src = e->source()->point();
    const APoint& tgt = e->target()->point();
    std::int64_t m = 0;
    for (const ASegment& s : path_segs) {
      if (s.has_on(src) && s.has_on(tgt)) {
        const auto dot = (s.target().x() - s.source().x()) * (tgt.x() - src.x()) +
                         (s.target().y() - s.source().y()) * (tgt.y() - src.y());
        m += dot > 0 ? 1 : -1;
      }
    }
    return m;
  };
  const auto for_each_ccb_edge = [](Arr::Face_handle f, auto&& fn) {
    if (f->has_outer_ccb()) {
      auto c = f->outer_ccb(), e = c;
      do {
        fn(Arr::Halfedge_handle(c));
      } while (++c != e);
    }
    for (auto hole = f->inner_ccbs_begin(); hole != f->inner_ccbs_end(); ++hole) {
      auto c = *hole, e = c;
      do {
        fn(Arr::Halfedge_handle(c));
      } while (++c != e);
    }
  };
  std::deque<Arr::Face_handle> todo{arr.unbounded_face()};
  arr.unbounded_face()->set_data(std::int64_t{0});
  while (!todo.empty()) {
    const Arr::Face_handle f = todo.front();
    todo.pop_front();
    const std::int64_t wf = *f->data();
    for_each_ccb_edge(f, [&](Arr::Halfedge_handle e) {
      const Arr::Face_handle g = e->twin()->face();
      const std::int64_t wg = wf - multiplicity(e);
      if (!g->data()) {
        g->set_data(wg);
        todo.push_back(g);
      } else if (*g->data() != wg) {
        throw std::logic_error("oracle: inconsistent winding numbers across an edge");
      }
    });
  }

  // The area of every face where the fill rule holds, summed per pixel (shoelace over every
  // boundary cycle: the outer one counter-clockwise in CGAL's axes, holes clockwise, antennas
  // traversed both ways adding nothing).
  std::map<std::pair<std::int64_t, std::int64_t>, mpq_class> area; // (y, x) -> raw^2
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
    if (f->is_unbounded())
      continue;
    if (!f->data())
      throw std::logic_error("oracle: a face not reached from the unbounded face");
    if (!fills(fill_rule, *f->data()))
      continue;
    mpq_class twice = 0;
    std::optional<std::array<mpq_class, 4>> box; // min x, min y, max x, max y of the outer cycle
    {
      auto c = f->outer_ccb(), e = c;
      do {
        const mpq_class x = to_mpq(c->source()->point().x()), y = to_mpq(c->source()->point().y());
        if (!box) {
          box = std::array<mpq_class, 4>{x, y, x, y};
        } else {
          (*box)[0] = std::min((*box)[0], x);
          (*box)[1] = std::min((*box)[1], y);
          (*box)[2] = std::max((*box)[2], x);
          (*box)[3] = std::max((*box)[3], y);
        }
      } while (++c != e);
    }
    for_each_ccb_edge(f, [&](Arr::Halfedge_handle e) {
      const APoint& a = e->source()->point();
      const APoint& b = e->target()->point();
      twice += to_mpq(a.x() * b.y() - b.x() * a.y());
    });
    if (twice == 0)
      continue;
    // Inside the grid's outer box: exactly one pixel, the grid lines bound every such face.
    const auto& bx = *box;
    if (bx[0] < 256 * i0 || bx[2] > 256 * i1 || bx[1] < 256 * j0 || bx[3] > 256 * j1)
      continue; // outside the pixels of the grid
    const mpq_class qx = bx[0] / 256, qy = bx[1] / 256;
    const mpz_class px = qx.get_num() / qx.get_den(); // floor: both are >= 0
    const mpz_class py = qy.get_num() / qy.get_den();
    if (bx[2] > 256 * (px + 1) || bx[3] > 256 * (py + 1))
      throw std::logic_error("oracle: a face spans two pixels");
    area[{py.get_si(), px.get_si()}] += twice / 2 / 65536;
  }
  for (auto& [yx, a] : area) {
    if (a < 0)
      throw std::logic_error("oracle: negative face area");
    a.canonicalize();
  }
  std::erase_if(area, [](const auto& e) { return e.second == 0; });
  return area;
}

PixelArea pixel_area(const std::pair<std::int64_t, std::int64_t>& yx, const mpq_class& a) {
  return PixelArea{static_cast<std::int32_t>(yx.second), static_cast<std::int32_t>(yx.first),
                   a.get_num().get_str(), a.get_den().get_str(), a.get_d()};
}

} // namespace

// rule: PATH.AREA.EXACT, PATH.WINDING, PATH.FILL.RULE
std::vector<PixelArea> cover_area(const Path& p, std::int32_t w, std::int32_t h) {
  check_range(p);
  (void)fills(p.fill_rule, 0);
  std::vector<PixelArea> out;
  for (const auto& [yx, a] : areas_of(p.fill_rule, flatten(p, -1).segs, w, h))
    out.push_back(pixel_area(yx, a));
  return out;
}

// rule: PATH.AREA.EXACT
std::vector<PixelAreaBound> cover_area_bounded(const Path& p, std::int32_t w, std::int32_t h,
                                               int depth) {
  check_range(p);
  (void)fills(p.fill_rule, 0);
  if (depth < 0 || depth > 16)
    throw std::invalid_argument("oracle: subdivision depth outside [0, 16]");
  const Flat flat = flatten(p, depth);
  const PixelMap area = areas_of(p.fill_rule, flat.segs, w, h);
  // Where the curve and its flattening differ, their winding numbers may differ: only inside
  // the hull of some piece (outside all of them, the path deforms into its flattening without
  // crossing the point). So the fill sets differ in a pixel on at most the area of the hulls
  // of the pieces whose (closed) box meets the pixel.
  PixelMap bound;
  for (const std::vector<APoint>& piece : flat.pieces) {
    std::vector<APoint> hull;
    CGAL::convex_hull_2(piece.begin(), piece.end(), std::back_inserter(hull));
    mpq_class twice = 0;
    for (std::size_t i = 0; i < hull.size(); ++i) {
      const APoint& a = hull[i];
      const APoint& b = hull[(i + 1) % hull.size()];
      twice += to_mpq(a.x() * b.y() - b.x() * a.y());
    }
    const mpq_class hull_area = abs(twice) / 2 / 65536;
    if (hull_area == 0)
      continue;
    mpq_class lo_x = to_mpq(piece[0].x()), hi_x = lo_x, lo_y = to_mpq(piece[0].y()), hi_y = lo_y;
    for (const APoint& q : piece) {
      lo_x = std::min(lo_x, to_mpq(q.x()));
      hi_x = std::max(hi_x, to_mpq(q.x()));
      lo_y = std::min(lo_y, to_mpq(q.y()));
      hi_y = std::max(hi_y, to_mpq(q.y()));
    }
    // Closed: a box ending exactly on a grid line also counts for the pixel beyond it.
    const auto [i0, j0, i1, j1] = pixel_range(lo_x - 1, lo_y - 1, hi_x + 1, hi_y + 1, w, h);
    for (std::int64_t j = j0; j < j1; ++j)
      for (std::int64_t i = i0; i < i1; ++i)
        bound[{j, i}] += hull_area;
  }
  std::map<std::pair<std::int64_t, std::int64_t>, std::pair<mpq_class, mpq_class>> all;
  for (const auto& [yx, a] : area)
    all[yx].first = a;
  for (const auto& [yx, b] : bound)
    all[yx].second = b;
  std::vector<PixelAreaBound> out;
  for (auto& [yx, ab] : all) {
    ab.second.canonicalize();
    out.push_back(PixelAreaBound{pixel_area(yx, ab.first), ab.second.get_num().get_str(),
                                 ab.second.get_den().get_str(), ab.second.get_d()});
  }
  return out;
}

} // namespace rastrules::oracle::path
