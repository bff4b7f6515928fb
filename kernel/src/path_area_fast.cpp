// SPDX-License-Identifier: MIT
// 2D paths: the 8-bit alpha of area coverage by certified floating-point cells (spec/rules/
// path.md, PATH.AREA.FAST). Every piece of the boundary (lines, and curves cut where x or y
// turns) is walked cell by cell, as signed-area accumulation rasterizers do, but every number
// carries a bound on its error (running error analysis, exact where the arithmetic is), and a
// cell's alpha is written only where (a) the cell provably holds at most two winding numbers
// and (b) the area's interval decides floor(255 a + 1/2). A row where a cell fails either test
// is left to the exact methods (PATH.AREA.CELLS, PATH.AREA.CURVE), so the answer never depends
// on this method; any doubt about the walk itself (a point that may lie on a grid line, two
// crossings that may coincide) leaves the whole path to them.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <tuple>
#include <vector>

#include "path_detail.hpp"
#include "rastrules/fixed.hpp"
#include "rastrules/formula/edge.hpp"
#include "rastrules/path.hpp"

namespace rastrules::path::detail {
namespace {

constexpr std::int64_t kW = kSubpixelOne; // a pixel's side, raw
constexpr double kWd = static_cast<double>(kW);
__extension__ typedef __int128 I128;

// ---------------------------------------------------------------------------------------------
// Numbers with a bound on their error: v is computed, |v - exact| <= e. Exact operations (whose
// rounding error is zero, found by error-free transformations) keep e = 0, so ties such as a
// half-covered pixel are decided exactly. Every bound is rounded up: a sum or product of a few
// non-negative terms has a relative rounding error below 8 u, which kUp covers.

constexpr double kU = 0x1p-53;
constexpr double kUp = 1.0 + 0x1p-49;
constexpr double kTiny = 0x1p-1000; // covers underflow in products

struct E {
  double v = 0, e = 0;
};

// The rounding error of a * b, exactly (Dekker's product with Veltkamp's split: no fused
// multiply-add needed, which the baseline instruction set lacks; no overflow in the ranges here).
[[gnu::always_inline]] inline double product_error(double a, double b, double p) {
  constexpr double kSplit = 134217729.0; // 2^27 + 1
  const double ca = kSplit * a, cb = kSplit * b;
  const double ah = ca - (ca - a), al = a - ah;
  const double bh = cb - (cb - b), bl = b - bh;
  return ((ah * bh - p) + ah * bl + al * bh) + al * bl;
}

E exact(double v) {
  return E{v, 0.0};
}

[[gnu::always_inline]] inline E add(E a, E b) {
  const double s = a.v + b.v;
  if (a.e == 0 && b.e == 0) { // TwoSum: the rounding error, exactly
    const double bb = s - a.v;
    const double err = (a.v - (s - bb)) + (b.v - bb);
    return E{s, std::abs(err)};
  }
  return E{s, (a.e + b.e + kU * std::abs(s)) * kUp};
}

[[gnu::always_inline]] inline E neg(E a) {
  return E{-a.v, a.e};
}

[[gnu::always_inline]] inline E sub(E a, E b) {
  return add(a, neg(b));
}

[[gnu::always_inline]] inline E mul(E a, E b) {
  if ((a.v == 0 && a.e == 0) || (b.v == 0 && b.e == 0))
    return E{};
  const double p = a.v * b.v;
  if (a.e == 0 && b.e == 0)
    return E{p, std::abs(product_error(a.v, b.v, p)) + (p == 0 ? kTiny : 0)};
  return E{p, (std::abs(a.v) * b.e + std::abs(b.v) * a.e + a.e * b.e + kU * std::abs(p) + kTiny) *
                  kUp};
}

// a * 2^k, exactly (no under- or overflow in the ranges used here).
E scale(E a, int k) {
  const double f = k >= 0 ? static_cast<double>(std::uint64_t{1} << k)
                          : 1.0 / static_cast<double>(std::uint64_t{1} << -k);
  return E{a.v * f, a.e * f};
}

// a / b; b must be bounded away from 0 (|b.v| > 2 b.e), else ok is cleared.
[[gnu::always_inline]] inline E div(E a, E b, bool& ok) {
  const double q = a.v / b.v;
  if (a.e == 0 && b.e == 0) {
    const double r = (a.v - q * b.v) - product_error(q, b.v, q * b.v); // the remainder, exactly
    return E{q, r == 0 ? 0.0 : (std::abs(r / b.v) + kU * std::abs(q) + kTiny) * kUp};
  }
  const double den = std::abs(b.v) - b.e;
  if (!(den > 0.5 * std::abs(b.v))) {
    ok = false;
    return E{q, 0};
  }
  return E{q, ((a.e + std::abs(q) * b.e) / den + kU * std::abs(q) + kTiny) * kUp};
}

// floor(x) for |x| < 2^52 (every value floored here is a coordinate over 256, an integral over
// the pixel's area or 510 times an area, far below): the same double as std::floor, which the
// baseline instruction set (no SSE4.1 rounding) makes a library call.
[[gnu::always_inline]] inline double floor_small(double x) {
  const auto i = static_cast<double>(static_cast<std::int64_t>(x)); // toward zero, exact
  return i > x ? i - 1.0 : i;
}

// The sign of a where its bound decides it, else 2.
int sign_of(E a) {
  if (a.v > a.e)
    return 1;
  if (a.v < -a.e)
    return -1;
  return (a.v == 0 && a.e == 0) ? 0 : 2;
}

// sign_of(sub(a, exact(g))), with a comparison where a is exact (the same answer: a rounded
// difference of two doubles has the sign of the exact one, and is 0 only where they are equal).
int sign_against(E a, double g) {
  if (a.e == 0)
    return a.v > g ? 1 : (a.v < g ? -1 : 0);
  return sign_of(sub(a, exact(g)));
}

// The alpha of a pixel with one winding number, v (exact in exact arithmetic: the integral of w
// over the pixel over its area); false where v's bound does not name one integer.
bool whole_winding(E v, FillRule rule, std::uint8_t& alpha) {
  const double r = std::nearbyint(v.v);
  if (!(std::abs(v.v - r) + v.e < 0.5))
    return false;
  alpha = fill_holds(rule, static_cast<std::int64_t>(r)) ? 255 : 0;
  return true;
}

// ---------------------------------------------------------------------------------------------
// Pieces of the boundary: monotone in x and in y, as a polynomial of degree n in t (power basis,
// relative to the reference point (x0, y0), coefficients exact integers of raw units) on
// [t0, t1]; lines have n = 1 and t in [0, 1].

// Horner's rule at t (a double) has |computed - exact| <= gamma(2n) sum |c_k| |t|^k, gamma(m)
// = m u / (1 - m u) (Higham, Accuracy and Stability of Numerical Algorithms, 5.1); a parameter
// known within t.e adds at most t.e times a bound of |p'| on [t - t.e, t + t.e].
constexpr double gamma_of(int m) {
  return (m * kU) / (1.0 - m * kU) * kUp;
}
// gamma_of(2n) for the degrees here, computed once (the same doubles: constant evaluation
// rounds as the processor does).
constexpr std::array<double, 13> kGamma2n = [] {
  std::array<double, 13> g{};
  for (int k = 0; k < 13; ++k)
    g[static_cast<std::size_t>(k)] = gamma_of(k);
  return g;
}();

struct Poly {
  int n = 1;
  std::array<double, 4> c{}; // c[0] = 0
  // p(t) with a bound, exact (e = 0) where every step is: for the ends of a curve's pieces,
  // which may lie on a grid line.
  [[nodiscard]] E at_exact(E t) const {
    E r = exact(c[static_cast<std::size_t>(n)]);
    for (int k = n - 1; k >= 0; --k)
      r = add(mul(r, t), exact(c[static_cast<std::size_t>(k)]));
    return r;
  }
  // p(t) with a bound.
  [[nodiscard]] E at(E t) const { return n == 3 ? at_n<3>(t) : (n == 2 ? at_n<2>(t) : at_n<1>(t)); }
  [[nodiscard]] double at_d(double t) const {
    return n == 3 ? at_d_n<3>(t) : (n == 2 ? at_d_n<2>(t) : at_d_n<1>(t));
  }
  [[nodiscard]] double slope_d(double t) const {
    return n == 3 ? slope_d_n<3>(t) : (n == 2 ? slope_d_n<2>(t) : slope_d_n<1>(t));
  }

private:
  // The loops unrolled for the degree N == n: the same operations in the same order as with n
  // in a variable.
  template <int N> [[nodiscard]] E at_n(E t) const {
    const double tv = t.v, at = std::abs(tv);
    double r = c[N], a = std::abs(r);
    for (int k = N - 1; k >= 0; --k) {
      r = r * tv + c[static_cast<std::size_t>(k)];
      a = a * at + std::abs(c[static_cast<std::size_t>(k)]);
    }
    double e = kGamma2n[2 * N] * a;
    if (t.e > 0) {
      const double m = at + t.e;
      double d = N * std::abs(c[N]);
      for (int k = N - 1; k >= 1; --k)
        d = d * m + k * std::abs(c[static_cast<std::size_t>(k)]);
      e += t.e * d * kUp;
    }
    return E{r, (e + kTiny) * kUp};
  }
  template <int N> [[nodiscard]] double at_d_n(double t) const {
    double r = c[N];
    for (int k = N - 1; k >= 0; --k)
      r = r * t + c[static_cast<std::size_t>(k)];
    return r;
  }
  template <int N> [[nodiscard]] double slope_d_n(double t) const {
    double r = N * c[N];
    for (int k = N - 1; k >= 1; --k)
      r = r * t + k * c[static_cast<std::size_t>(k)];
    return r;
  }
};

// A curve's (or line's) shared data: reference point, x(t) - x0, y(t) - y0, and the
// antiderivative Q(t) = integral from 0 to t of (x(s) - x0) y'(s) ds (degree 2n, coefficients
// with bounds).
struct Shape {
  std::int64_t x0 = 0, y0 = 0;
  Poly x, y;
  std::array<E, 7> q{}; // q[k]: coefficient of t^k
  int qn = 2;
  // Sums over k of |q_k|, of q_k's bounds, and of k (|q_k| + its bound): Horner's bound and the
  // parameter's term on [-1, 1] without a pass over the coefficients (set_q_sums).
  double q_abs = 0, q_err = 0, q_slope = 0;
  // Q(t) with a bound: Horner's on the coefficients' values, plus their own bounds, plus the
  // parameter's (|Q'| = |x - x0| |y'|, bounded from the coefficients' magnitudes).
  [[nodiscard]] E q_at(E t) const {
    return qn == 6 ? q_at_n<6>(t) : (qn == 4 ? q_at_n<4>(t) : q_at_n<2>(t));
  }
  void set_q_sums() {
    q_abs = q_err = q_slope = 0;
    for (int k = 1; k <= qn; ++k) {
      const E& qk = q[static_cast<std::size_t>(k)];
      q_abs += std::abs(qk.v);
      q_err += qk.e;
      q_slope += k * (std::abs(qk.v) + qk.e);
    }
    // Sums of a few non-negative terms: rounded up by kUp (relative error below 8 u).
    q_abs *= kUp;
    q_err *= kUp;
    q_slope *= kUp;
  }

private:
  // q_at unrolled for the degree QN == qn. For |t| + t.e <= 1 (every parameter of a curve's
  // pieces, t in [0, 1]) |t|^k <= 1 bounds every term: Horner's bound gamma(2 QN) sum |q_k|, the
  // coefficients' sum e_k, and the parameter's t.e sum k |q_k| (|Q'| on [t - t.e, t + t.e]), from
  // the shape's sums. Elsewhere the same bounds with the powers of |t| (a pass over the
  // coefficients).
  template <int QN> [[nodiscard]] E q_at_n(E t) const {
    const double tv = t.v, at = std::abs(tv);
    double r = q[QN].v;
    for (int k = QN - 1; k >= 0; --k)
      r = r * tv + q[static_cast<std::size_t>(k)].v;
    if (at + t.e <= 1.0)
      return E{r, (kGamma2n[2 * QN] * q_abs + q_err + t.e * q_slope + kTiny) * kUp};
    double a = std::abs(q[QN].v), ce = q[QN].e;
    for (int k = QN - 1; k >= 0; --k) {
      const E& qk = q[static_cast<std::size_t>(k)];
      a = a * at + std::abs(qk.v);
      ce = ce * at + qk.e;
    }
    double e = kGamma2n[2 * QN] * a + ce * kUp;
    if (t.e > 0) {
      const double m = at + t.e;
      double d = QN * (std::abs(q[QN].v) + q[QN].e);
      for (int k = QN - 1; k >= 1; --k)
        d = d * m +
            k * (std::abs(q[static_cast<std::size_t>(k)].v) + q[static_cast<std::size_t>(k)].e);
      e += t.e * d * kUp;
    }
    return E{r, (e + kTiny) * kUp};
  }
};

// A point of the boundary, raw, with bounds.
struct EPoint {
  E x, y;
};

struct Piece {
  std::uint32_t shape = 0;
  E t0, t1;
  EPoint p0, p1;
  int sx = 0, sy = 0; // signs of dx/dt and dy/dt on (t0, t1)
  bool line = false;  // shape is a line of the path (exact integer ends)
  bool gap = false;   // a shape before it was left out (its rows are not wanted)
};

// Which side of its cell a point of a sub-arc lies on (none: inside).
enum Side : std::uint8_t { kNone, kTop, kRight, kBottom, kLeft };

// A piece's part in one cell of the target (col in [0, w)), or its cover beyond the target's
// right side (col == w).
struct Sub {
  std::int32_t row = 0, col = 0;
  std::uint32_t piece = 0;
  E ta, tb;    // parameter range
  EPoint a, b; // end points
  Side sa = kNone, sb = kNone;
  bool interior = true;   // meets the cell's interior (false: along a column line, or col == w)
  bool along = false;     // along a column line (cover only)
  E area;                 // integral of (x - left) dy along the sub-arc, raw squared
  std::int32_t next = -1; // the next sub-arc of the boundary when it is in the same cell
};

// A chain's end on a cell's border: its position clockwise from the top-left corner (0 to 4,
// one per side) and the change of the winding number there.
struct End {
  E s;
  int dw = 0;
};

class FastAlpha {
public:
  // Starts a path: the buffers keep their room from the last one (one workspace a thread).
  // only: the rows wanted (a byte a row, 1: wanted), or null for all.
  void reset(FillRule rule, std::int32_t w, std::int32_t h, const std::vector<std::uint8_t>* only) {
    rule_ = rule;
    w_ = w;
    h_ = h;
    only_ = only;
    if (only != nullptr) {
      wanted_before_.assign(static_cast<std::size_t>(h) + 1, 0);
      for (std::size_t j = 0; j < static_cast<std::size_t>(h); ++j)
        wanted_before_[j + 1] = wanted_before_[j] + ((*only)[j] != 0 ? 1 : 0);
    }
    shapes_.clear();
    pieces_.clear();
    subs_.clear();
    refs_.clear();
    contour_first_.clear();
    seq_ = 0;
    last_row_ = last_idx_ = first_row_ = first_idx_ = -1;
    last_seq_ = first_seq_ = 0;
    q_shape_ = static_cast<std::uint32_t>(-1);
    gap_ = false;
  }

  // Builds the pieces and walks them; false where the walk is in doubt (the exact methods then
  // take every row).
  bool walk(const Boundary& b);
  // Orders each row's sub-arcs by column and order along the boundary (keys_, row_start_).
  void sort_rows();
  // Decides row j into out (w bytes); false where a cell of it is not certified.
  bool row(std::int32_t j, std::uint8_t* out);

private:
  // Whether a wanted row lies within one row of the raw heights y0 to y1.
  [[nodiscard]] bool wanted_near(double y0, double y1) const;
  [[nodiscard]] bool wanted(std::int32_t row) const {
    return only_ == nullptr || (*only_)[static_cast<std::size_t>(row)] != 0;
  }
  bool add_shape_pieces(std::uint32_t s, int degree);
  bool walk_piece(std::uint32_t pi);
  void emit(std::int32_t row, std::int32_t col, std::uint32_t pi, E ta, E tb, const EPoint& a,
            const EPoint& b, Side sa, Side sb, bool interior);
  [[nodiscard]] bool root(const Piece& p, bool in_x, double target, double from, E& t) const;
  [[nodiscard]] EPoint point_at(const Piece& p, E t) const;
  // One coordinate of point_at (x where in_x, else y).
  [[nodiscard]] E coordinate_at(const Piece& p, bool in_x, E t) const;
  [[nodiscard]] EPoint point_at_exact(const Shape& s, E t) const;
  [[nodiscard]] bool cell(std::int32_t j, std::vector<Sub>& subs, std::size_t at, std::size_t end,
                          E integral, std::uint8_t& alpha);
  [[nodiscard]] bool finish(E v, std::size_t interior, std::uint8_t& alpha) const;
  // Decides a cell of row j holding the sub-arcs of keys_[at, end), `integral` the integral of w
  // over it (its sub-arcs' areas and kW times the cover right of it, raw squared).
  [[nodiscard]] bool occupied_cell(std::int32_t j, std::size_t at, std::size_t end, E integral,
                                   std::uint8_t& alpha);
  [[nodiscard]] bool apart(const Sub& a, const Sub& b) const;
  [[nodiscard]] bool joint_ok(const Sub& first, const Sub& second) const;

  FillRule rule_ = FillRule::kNonZero;
  std::int32_t w_ = 0, h_ = 0;
  const std::vector<std::uint8_t>* only_ = nullptr;
  std::vector<std::uint32_t> wanted_before_; // wanted rows before row j (only_ given)
  bool gap_ = false;                         // a shape left out since the last piece
  std::vector<Shape> shapes_;
  std::vector<Piece> pieces_;
  std::vector<Sub> subs_, gathered_;
  // Row j's sub-arcs: keys_[row_start_[j], row_start_[j + 1]), each (column << 32) | index,
  // sorted: by column, then in the order they were emitted.
  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> row_start_, row_fill_;
  std::vector<std::uint8_t> has_prev_, seen_;
  std::vector<End> ends_;
  std::vector<std::pair<std::size_t, std::size_t>> chains_;
  std::vector<SegmentRef> refs_;
  std::vector<std::size_t> contour_first_;
  std::vector<E> cuts_;
  std::uint64_t seq_ = 0;
  // The last sub-arc emitted (row, index) with no gap after it, for linking.
  std::int32_t last_row_ = -1, last_idx_ = -1;
  std::uint64_t last_seq_ = 0;
  // The last Q(t) computed (emit): shape, t, value.
  std::uint32_t q_shape_ = static_cast<std::uint32_t>(-1);
  E q_t_, q_;
  // The current contour's first sub-arc, when it was emitted with no gap before it.
  std::uint64_t first_seq_ = 0;
  std::int32_t first_row_ = -1, first_idx_ = -1;
};

// ---------------------------------------------------------------------------------------------

bool FastAlpha::wanted_near(double y0, double y1) const {
  if (only_ == nullptr)
    return true;
  const double lo = std::floor(std::min(y0, y1) / kW) - 1;
  const double hi = std::floor(std::max(y0, y1) / kW) + 1;
  if (hi < 0 || lo >= h_)
    return false;
  const auto a = static_cast<std::size_t>(std::max(lo, 0.0));
  const auto b = static_cast<std::size_t>(std::min(hi, h_ - 1.0));
  return wanted_before_[b + 1] > wanted_before_[a];
}

EPoint FastAlpha::point_at_exact(const Shape& s, E t) const {
  return EPoint{add(exact(static_cast<double>(s.x0)), s.x.at_exact(t)),
                add(exact(static_cast<double>(s.y0)), s.y.at_exact(t))};
}

E FastAlpha::coordinate_at(const Piece& p, bool in_x, E t) const {
  const Shape& s = shapes_[p.shape];
  return in_x ? add(exact(static_cast<double>(s.x0)), s.x.at(t))
              : add(exact(static_cast<double>(s.y0)), s.y.at(t));
}

EPoint FastAlpha::point_at(const Piece& p, E t) const {
  return EPoint{coordinate_at(p, true, t), coordinate_at(p, false, t)};
}

// The parameter t in (t0, t1) of piece p where x(t) (in_x) or y(t) equals target, which the
// caller knows lies strictly between the piece's values there: bisection and Halley steps on a
// bracket whose end signs are certified; false where they cannot be.
bool FastAlpha::root(const Piece& p, bool in_x, double target, double from, E& t) const {
  const Shape& s = shapes_[p.shape];
  const Poly& f = in_x ? s.x : s.y;
  const double off = target - static_cast<double>(in_x ? s.x0 : s.y0); // exact
  const int dir = in_x ? p.sx : p.sy; // f - off goes from -dir to +dir
  if (p.line) {                       // one division: t = off / c1
    bool ok = true;
    t = div(exact(off), exact(f.c[1]), ok);
    return ok;
  }
  // An approximate root by safeguarded Halley steps in plain doubles, then a bracket around it
  // whose end signs are certified (the ends of the piece where nothing tighter is).
  double lo = p.t0.v, hi = p.t1.v;
  double x = 0;
  bool found = false;
  if (f.n == 2 && f.c[2] != 0) {
    // A quadratic piece: the roots of f - off (integer coefficients) in closed form (stable
    // form). Where the discriminant is exact in double, the quadratic formula's own error bound
    // (PATH.CURVE.FILTER's quadratic rows) puts each computed root within 3.01 u of the true one
    // relatively, so within 2^-50 max(1, |r|); a root that bound places inside the piece is its
    // one root (f is monotone there), and no bracket needs certifying. Else the root inside the
    // piece starts the bracket below.
    const auto ia = static_cast<std::int64_t>(f.c[2]), ib = static_cast<std::int64_t>(f.c[1]),
               ic = static_cast<std::int64_t>(-off);
    const I128 d = I128{ib} * ib - I128{4} * ia * ic;
    if (d >= 0) {
      const double q = -0.5 * (f.c[1] + std::copysign(std::sqrt(static_cast<double>(d)), f.c[1]));
      const std::array<double, 2> r{q / f.c[2], q != 0 ? -off / q : -1.0};
      if (d > 0 && d < (I128{1} << 53)) {
        const auto err = [](double v) { return 0x1p-50 * std::max(1.0, std::abs(v)); };
        const auto inside = [&](double v) {
          return v - err(v) > p.t0.v + p.t0.e && v + err(v) < p.t1.v - p.t1.e;
        };
        if (inside(r[0]) != inside(r[1])) {
          const double v = inside(r[0]) ? r[0] : r[1];
          t = E{v, err(v)};
          return true;
        }
      }
      for (const double v : r)
        if (v >= lo && v <= hi) {
          x = v;
          found = true;
        }
    }
  }
  if (!found) {
    // A start for the steps: a Newton step from `from`, the parameter where the walk is (the
    // crossing before, or the piece's start); else the chord's root, a poorer start on pieces
    // that span several cells.
    const double ff = f.at_d(from) - off, fd = f.slope_d(from);
    x = fd != 0 ? from - ff / fd : lo;
    if (!(x > lo && x < hi)) {
      const double flo = f.at_d(lo) - off, fhi = f.at_d(hi) - off;
      x = flo != fhi ? lo + (hi - lo) * (-flo / (fhi - flo)) : 0.5 * (lo + hi);
    }
  }
  double a = lo, b = hi; // the plain bracket
  for (int it = 0; it < (found ? 0 : 60); ++it) {
    if (!(x > a && x < b))
      x = 0.5 * (a + b);
    const double fx = f.at_d(x) - off;
    if (fx == 0)
      break;
    if ((fx < 0) == (dir > 0))
      a = x;
    else
      b = x;
    // Halley's step: cubic convergence, 4.1 steps a root against Newton's 5.5 (the ladder's
    // quick glyphs); f'' is one multiply-add more.
    const double d = f.slope_d(x);
    const double dd = f.n == 3 ? 6 * f.c[3] * x + 2 * f.c[2] : 2 * f.c[2];
    const double den = 2 * d * d - fx * dd;
    const double nx = den != 0 ? x - 2 * fx * d / den : 0.5 * (a + b);
    // Settled at a step of at most 2^-14 (the next would be about its cube): the bracket below
    // is certified whatever x is, and widening it a little more often costs less than the
    // steps saved (the ladder's Nimbus glyphs: 2.3 steps and 1.6 widenings a root, against 3.6
    // and 1.4 when waiting for a step of 2 u).
    if (std::abs(nx - x) <= 0x1p-14 * std::max(1.0, std::abs(x))) {
      x = nx;
      break;
    }
    x = nx;
  }
  x = std::clamp(x, lo, hi);
  // The sign of f(u) - off where certified, else 2: Horner's rule in plain doubles, its bound
  // gamma(2n) sum |c_k| for |u| <= 1 (every parameter here lies in [0, 1]), and the
  // subtraction's rounding; the same test as sign_of(sub(f.at(exact(u)), exact(off))) with
  // |u|^k <= 1 in Horner's bound.
  double c_abs = 0;
  for (int k = 1; k <= f.n; ++k)
    c_abs += std::abs(f.c[static_cast<std::size_t>(k)]);
  const double horner = (kGamma2n[static_cast<std::size_t>(2 * f.n)] * c_abs * kUp + kTiny) * kUp;
  const auto sgn = [&](double u) {
    const double r = f.at_d(u) - off;
    const double e = (horner + kU * std::abs(r)) * kUp;
    return r > e ? 1 : (r < -e ? -1 : 2);
  };
  bool lo_done = false, hi_done = false;
  for (double d = 4 * kU * std::max(1.0, std::abs(x)); !(lo_done && hi_done); d *= 16) {
    if (!lo_done) {
      if (x - d <= p.t0.v) {
        if (sgn(p.t0.v) != -dir)
          return false;
        lo = p.t0.v;
        lo_done = true;
      } else if (sgn(x - d) == -dir) {
        lo = x - d;
        lo_done = true;
      }
    }
    if (!hi_done) {
      if (x + d >= p.t1.v) {
        if (sgn(p.t1.v) != dir)
          return false;
        hi = p.t1.v;
        hi_done = true;
      } else if (sgn(x + d) == dir) {
        hi = x + d;
        hi_done = true;
      }
    }
  }
  const double mid = 0.5 * (lo + hi);
  t = E{mid, (std::max(mid - lo, hi - mid) + kU * std::abs(mid)) * kUp};
  return true;
}

// Splits shape s (a curve of the given degree) where x' or y' vanish inside (0, 1) and adds the
// monotone pieces; false where a split is in doubt.
bool FastAlpha::add_shape_pieces(std::uint32_t si, int degree) {
  const Shape& s = shapes_[si];
  std::vector<E>& cuts = cuts_;
  cuts.assign(1, exact(0.0));
  const auto derivative_roots = [&](const Poly& f) -> bool {
    // f' = a t^2 + b t + c (a = 0 for quadratics).
    const double a = degree == 3 ? 3 * f.c[3] : 0.0, b = 2 * f.c[2], c = f.c[1];
    bool ok = true;
    const auto keep = [&](E r) {
      if (r.v - r.e > 0 && r.v + r.e < 1)
        cuts.push_back(r);
      else if (!(r.v + r.e <= 0 || r.v - r.e >= 1))
        ok = false; // may lie at an end or inside: in doubt
    };
    if (a == 0) {
      if (b != 0)
        keep(div(exact(-c), exact(b), ok));
      return ok;
    }
    // A root at an end (a tangent along an axis there, as fonts put at their extrema): exact,
    // and the other root is then rational.
    if (c == 0) {
      keep(div(exact(-b), exact(a), ok));
      return ok;
    }
    if (a + b + c == 0) {
      keep(div(exact(c), exact(a), ok));
      return ok;
    }
    // Exact discriminant in 128 bits (|b|, |a|, |c| < 2^28).
    const I128 disc = I128(static_cast<std::int64_t>(b)) * static_cast<std::int64_t>(b) -
                      I128(4) * static_cast<std::int64_t>(a) * static_cast<std::int64_t>(c);
    if (disc < 0)
      return true;
    if (disc == 0) {
      keep(div(exact(-b), exact(2 * a), ok));
      return ok;
    }
    // sqrt of the discriminant with a bound: D as a double (rounded), then sqrt (rounded).
    const double dd = static_cast<double>(disc);
    const double de = std::abs(static_cast<double>(disc - static_cast<I128>(dd)));
    const double sq = std::sqrt(dd);
    const E root_d{sq, (de / (sq + std::sqrt(std::max(dd - de, 0.0))) + kU * sq) * kUp};
    // q = -(b + sign(b) sqrt(D)) / 2; roots q / a and c / q.
    const E qv = scale(neg(add(exact(b), b >= 0 ? root_d : neg(root_d))), -1);
    keep(div(qv, exact(a), ok));
    if (sign_of(qv) != 0 && sign_of(qv) != 2)
      keep(div(exact(c), qv, ok));
    else
      ok = false;
    return ok;
  };
  if (!derivative_roots(s.x) || !derivative_roots(s.y))
    return false;
  cuts.push_back(exact(1.0));
  std::sort(cuts.begin(), cuts.end(), [](E p, E q) { return p.v < q.v; });
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const E ta = cuts[k], tb = cuts[k + 1];
    if (ta.v == tb.v && ta.e == 0 && tb.e == 0)
      continue; // the same cut twice
    if (!(tb.v - tb.e > ta.v + ta.e))
      return false; // two cuts that may coincide (a cusp): in doubt
    Piece p;
    p.shape = si;
    p.t0 = ta;
    p.t1 = tb;
    p.p0 = ta.e == 0 && ta.v == 0 ? EPoint{exact(double(s.x0)), exact(double(s.y0))}
                                  : point_at_exact(s, ta);
    if (tb.e == 0 && tb.v == 1) { // the last control point: integer sums, exact
      p.p1 = EPoint{exact(static_cast<double>(s.x0) + s.x.at_d(1.0)),
                    exact(static_cast<double>(s.y0) + s.y.at_d(1.0))};
    } else {
      p.p1 = point_at_exact(s, tb);
    }
    // Directions from the derivative at the middle of the piece (no zero inside it).
    const double mid = 0.5 * (ta.v + tb.v);
    const auto dsign = [&](const Poly& f) -> int {
      if (f.c[1] == 0 && f.c[2] == 0 && f.c[3] == 0)
        return 0;
      const double d = f.slope_d(mid);
      return d > 0 ? 1 : (d < 0 ? -1 : 2);
    };
    p.sx = dsign(s.x);
    p.sy = dsign(s.y);
    if (p.sx == 2 || p.sy == 2)
      return false;
    // The ends must differ the way the signs say (certified), else the piece is too short to
    // walk safely.
    const int ex = sign_of(sub(p.p1.x, p.p0.x)), ey = sign_of(sub(p.p1.y, p.p0.y));
    if (ex != p.sx || ey != p.sy)
      return false;
    p.gap = gap_;
    gap_ = false;
    pieces_.push_back(p);
  }
  return true;
}

void FastAlpha::emit(std::int32_t row, std::int32_t col, std::uint32_t pi, E ta, E tb,
                     const EPoint& a, const EPoint& b, Side sa, Side sb, bool interior) {
  const std::uint64_t seq = ++seq_;
  if (row < 0 || row >= h_ || col < 0 || !wanted(row)) {
    last_row_ = -1; // a gap: the next sub-arc cannot link to anything before it
    return;
  }
  const Piece& p = pieces_[pi];
  std::vector<Sub>& r = subs_;
  const auto idx = static_cast<std::int32_t>(r.size());
  Sub& s = r.emplace_back(); // filled in place (a copy of 136 bytes a sub-arc saved)
  s.row = row;
  s.col = std::min(col, w_);
  s.piece = pi;
  s.ta = ta;
  s.tb = tb;
  s.a = a;
  s.b = b;
  s.sa = sa;
  s.sb = sb;
  const double right_line = static_cast<double>(std::int64_t{w_} * kW);
  if (col >= w_) { // right of the target: only its left line x = w counts as a side
    const auto fix = [&](Side& side, const EPoint& pt) {
      if ((side == kLeft || side == kRight) && !(pt.x.e == 0 && pt.x.v == right_line))
        side = kNone; // a line inside the region: the sub-arc beside it shares the point
      else if (side == kRight)
        side = kLeft;
    };
    fix(s.sa, a);
    fix(s.sb, b);
  }
  s.interior = interior && col < w_;
  // Along a column line; right of the target only the line x = w counts (along a line inside
  // that region its ends are shared like any other).
  s.along = !interior && (col < w_ || (a.x.e == 0 && a.x.v == right_line));
  if (s.interior) {
    const E cover = sub(b.y, a.y); // y(b) - y(a), raw
    const double left = static_cast<double>(std::int64_t{col} * kW);
    if (p.line) {
      // ((xa - l) + (xb - l)) / 2 (yb - ya)
      s.area = mul(scale(add(sub(a.x, exact(left)), sub(b.x, exact(left))), -1), cover);
    } else {
      const Shape& sh = shapes_[p.shape];
      // Q at ta is usually Q at the last sub-arc's tb (the walk goes on from there).
      const E qa = (q_shape_ == p.shape && q_t_.v == ta.v && q_t_.e == ta.e) ? q_ : sh.q_at(ta);
      q_ = sh.q_at(tb);
      q_t_ = tb;
      q_shape_ = p.shape;
      s.area = add(sub(q_, qa), mul(exact(static_cast<double>(sh.x0) - left), cover));
    }
  }
  if (s.interior && last_row_ == row && last_seq_ + 1 == seq &&
      r[static_cast<std::size_t>(last_idx_)].col == s.col)
    r[static_cast<std::size_t>(last_idx_)].next = idx;
  if (seq == first_seq_ && s.interior) {
    first_row_ = row;
    first_idx_ = idx;
  }
  if (s.interior) {
    last_row_ = row;
    last_idx_ = idx;
    last_seq_ = seq;
  } else {
    last_row_ = -1;
  }
}

// The cell of an exact coordinate v moving with sign s (on a grid line: the cell it moves into),
// or of a bounded one strictly inside a cell; false where that is in doubt or where the piece
// runs along a grid line (s == 0 on one).
bool cell_of(E v, int s, std::int64_t& c, bool& on_line) {
  on_line = false;
  if (v.e == 0) {
    const auto iv = static_cast<std::int64_t>(v.v);
    if (static_cast<double>(iv) == v.v && (iv & (kW - 1)) == 0) {
      on_line = true;
      c = floor_div(iv, kW) - (s < 0 ? 1 : 0);
      return true;
    }
    c = static_cast<std::int64_t>(floor_small(v.v / kWd));
    return true;
  }
  const double lo = floor_small((v.v - 2 * v.e) / kWd), hi = floor_small((v.v + 2 * v.e) / kWd);
  const double lo_line = lo * kWd, hi_line = (lo + 1) * kWd;
  if (lo != hi || !(v.v - 2 * v.e > lo_line) || !(v.v + 2 * v.e < hi_line))
    return false;
  c = static_cast<std::int64_t>(lo);
  return true;
}

// Whether point coordinate v lies on grid line g exactly (both exact).
bool on(E v, std::int64_t g) {
  return v.e == 0 && v.v == static_cast<double>(g);
}

bool FastAlpha::walk_piece(std::uint32_t pi) {
  const Piece p = pieces_[pi];
  const std::int64_t H = std::int64_t{h_} * kW;
  std::int64_t col = 0, row = 0;
  bool on_x = false, on_y = false;
  if (!cell_of(p.p0.x, p.sx, col, on_x) || !cell_of(p.p0.y, p.sy, row, on_y))
    return false;
  if (p.sy == 0 && on_y) { // along a row line: no area, no cell's interior
    last_row_ = -1;
    ++seq_;
    return true;
  }
  const bool along_column = p.sx == 0 && on_x;
  if (along_column)
    col = floor_div(static_cast<std::int64_t>(p.p0.x.v), kW); // the cells right of it
  // Clamp the column to [-1, w]: the cells left of the target take no part; those right of it
  // only the cover.
  col = std::clamp<std::int64_t>(col, -1, w_);
  EPoint cur = p.p0;
  E tc = p.t0;
  Side side_in = kNone;
  if (on_x && !along_column)
    side_in = p.sx > 0 ? kLeft : kRight;
  if (on_y)
    side_in = p.sy > 0 ? kTop : kBottom;
  // A curve's last crossing found of a column line and of a row line.
  struct Kept {
    bool valid = false;
    std::int64_t line = 0;
    E t;
  } kept_x, kept_y;
  for (int guard = 0;; ++guard) {
    if (guard > 4 * (w_ + h_) + 16)
      return false;
    // Stop above the target going up or below it going down.
    if ((row < 0 && p.sy < 0) || (row >= h_ && p.sy > 0) || (p.sy == 0 && (row < 0 || row >= h_)))
      break;
    if (col < 0 && p.sx <= 0)
      break; // left of the target for good: no effect on its cells
    // The next column line and row line in the direction of travel (jumping over the columns
    // and rows outside the target).
    bool has_x = false, has_y = false;
    std::int64_t X = 0, Y = 0;
    if (p.sx > 0 && col < w_) {
      X = (col + 1) * kW;
      has_x = true;
    } else if (p.sx < 0 && col >= 0) {
      X = std::min(col, std::int64_t{w_}) * kW;
      has_x = true;
    }
    if (p.sy > 0) {
      Y = std::max<std::int64_t>(row + 1, 0) * kW;
      has_y = Y <= H;
    } else if (p.sy < 0) {
      Y = std::min<std::int64_t>(row, h_) * kW;
      has_y = Y >= 0;
    }
    // Whether the piece crosses them strictly before its end (certified), or ends on them.
    const auto crosses = [&](bool has, E end, std::int64_t g, int s) -> int {
      if (!has)
        return 0;
      const int c = sign_against(end, static_cast<double>(g));
      if (c == 2)
        return -1; // in doubt
      return c == s ? 1 : 0;
    };
    const int cx = crosses(has_x, p.p1.x, X, p.sx), cy = crosses(has_y, p.p1.y, Y, p.sy);
    if (cx < 0 || cy < 0)
      return false;
    if (cx == 0 && cy == 0) { // ends in this cell
      Side side_out = kNone;
      if (!along_column) {
        if (on(p.p1.x, col * kW))
          side_out = kLeft;
        else if (on(p.p1.x, (col + 1) * kW))
          side_out = kRight;
      }
      if (on(p.p1.y, row * kW))
        side_out = kTop;
      else if (on(p.p1.y, (row + 1) * kW))
        side_out = kBottom;
      emit(static_cast<std::int32_t>(row), static_cast<std::int32_t>(col), pi, tc, p.t1, cur, p.p1,
           side_in, side_out, !along_column);
      return true;
    }
    // Which comes first.
    bool first_x = cx == 1, first_y = cy == 1;
    E tx, ty;
    // A curve's crossing of the line that did not come first stays valid for the next step
    // (the same line, the same piece): kept, not found again.
    const auto crossing = [&](bool in_x, std::int64_t g, Kept& kept, E& t) {
      if (kept.valid && kept.line == g) {
        t = kept.t;
        return true;
      }
      if (!root(p, in_x, static_cast<double>(g), tc.v, t))
        return false;
      kept = Kept{true, g, t};
      return true;
    };
    if (first_x && !p.line && !crossing(true, X, kept_x, tx))
      return false;
    if (first_y && !p.line && !crossing(false, Y, kept_y, ty))
      return false;
    if (first_x && first_y) {
      if (p.line) {
        const Shape& s = shapes_[p.shape];
        // t_X = (X - x0) / dx, t_Y = (Y - y0) / dy; compare |X - x0| |dy| with |Y - y0| |dx|.
        const I128 a = I128(std::abs(X - s.x0)) * static_cast<std::int64_t>(std::abs(s.y.c[1]));
        const I128 b = I128(std::abs(Y - s.y0)) * static_cast<std::int64_t>(std::abs(s.x.c[1]));
        first_x = a <= b;
        first_y = b <= a;
      } else if (tx.v + tx.e < ty.v - ty.e) {
        first_y = false;
      } else if (ty.v + ty.e < tx.v - tx.e) {
        first_x = false;
      } else {
        return false; // through a corner, or nearly: in doubt
      }
    }
    E tn;
    EPoint nxt;
    const Shape& sh = shapes_[p.shape];
    if (first_x) {
      if (p.line && !root(p, true, static_cast<double>(X), tc.v, tx))
        return false;
      tn = tx;
      nxt.x = exact(static_cast<double>(X));
    }
    if (first_y) {
      if (p.line && !root(p, false, static_cast<double>(Y), tc.v, ty))
        return false;
      if (!first_x)
        tn = ty;
      nxt.y = exact(static_cast<double>(Y));
    }
    bool ok = true;
    if (first_x && !first_y) // y = (y0 dx + (X - x0) dy) / dx for a line: one rounding
      nxt.y = p.line ? div(exact(static_cast<double>(sh.y0) * sh.x.c[1] +
                                 static_cast<double>(X - sh.x0) * sh.y.c[1]),
                           exact(sh.x.c[1]), ok)
                     : coordinate_at(p, false, tn);
    if (first_y && !first_x)
      nxt.x = p.line ? div(exact(static_cast<double>(sh.x0) * sh.y.c[1] +
                                 static_cast<double>(Y - sh.y0) * sh.x.c[1]),
                           exact(sh.y.c[1]), ok)
                     : coordinate_at(p, true, tn);
    if (!ok)
      return false;
    Side side_out = first_y ? (p.sy > 0 ? kBottom : kTop) : (p.sx > 0 ? kRight : kLeft);
    emit(static_cast<std::int32_t>(row), static_cast<std::int32_t>(col), pi, tc, tn, cur, nxt,
         side_in, side_out, !along_column);
    cur = nxt;
    tc = tn;
    side_in = kNone;
    if (first_x) {
      col = p.sx > 0 ? (col < 0 ? 0 : col + 1) : (col >= w_ ? w_ - 1 : col - 1);
      col = std::clamp<std::int64_t>(col, -1, w_);
      side_in = p.sx > 0 ? kLeft : kRight;
    }
    if (first_y) {
      row = p.sy > 0 ? (row < 0 ? 0 : row + 1) : (row >= h_ ? h_ - 1 : row - 1);
      side_in = p.sy > 0 ? kTop : kBottom;
    }
  }
  last_row_ = -1;
  ++seq_;
  return true;
}

bool FastAlpha::walk(const Boundary& b) {
  // Shapes in contour order: lines and curves merged by (contour, segment).
  std::vector<SegmentRef>& refs = refs_;
  segments_in_order(b, refs);
  shapes_.reserve(refs.size());
  // Contours: the first piece of each, to link a contour's last sub-arc to its first.
  std::vector<std::size_t>& contour_first = contour_first_;
  std::size_t current = static_cast<std::size_t>(-1);
  for (const SegmentRef& r : refs) {
    Shape s;
    std::array<Point, 4> cp{};
    const int degree = control_points(b, r, cp);
    s.x0 = cp[0].x;
    s.y0 = cp[0].y;
    const auto power = [&](auto get) {
      Poly f;
      f.n = degree;
      const double p0 = get(cp[0]), p1 = get(cp[1]), p2 = get(cp[2]), p3 = get(cp[3]);
      if (degree == 1) {
        f.c = {0, p1 - p0, 0, 0};
      } else if (degree == 2) {
        f.c = {0, 2 * (p1 - p0), p0 - 2 * p1 + p2, 0};
      } else {
        f.c = {0, 3 * (p1 - p0), 3 * (p0 - 2 * p1 + p2), p3 - 3 * p2 + 3 * p1 - p0};
      }
      return f;
    };
    s.x = power([](Point q) { return static_cast<double>(q.x); });
    s.y = power([](Point q) { return static_cast<double>(q.y); });
    const bool degenerate = s.x.c[1] == 0 && s.x.c[2] == 0 && s.x.c[3] == 0 && s.y.c[1] == 0 &&
                            s.y.c[2] == 0 && s.y.c[3] == 0;
    if (degenerate)
      continue; // a point (PATH.DEGENERATE)
    // A shape with no wanted row within a row of its control points (whose box holds it) has
    // no part in them; the pieces after it must not link to those before it.
    if (const auto [y_lo, y_hi] = control_y_range(cp, degree); !wanted_near(y_lo, y_hi)) {
      gap_ = true;
      continue;
    }
    // A curve that runs along a grid line (x or y constant on it, back and forth) is left to the
    // exact methods: along the target's right side x = w its sub-arcs were given the alpha of
    // a cover they do not have (PathCurveArea.FastCellsGiveTheAlphaOfTheArea, seed
    // 4470124809348599784).
    const auto along = [&](const Poly& f, std::int32_t v0) {
      return f.c[1] == 0 && f.c[2] == 0 && f.c[3] == 0 && (v0 & (kW - 1)) == 0;
    };
    if (degree > 1 && (along(s.x, cp[0].x) || along(s.y, cp[0].y)))
      return false;
    // Q(t) = integral of (x(s) - x0) y'(s): the coefficient of t^k is M_k / k, M_k the sum of
    // a_i j b_j over i + j = k, an integer (|raw| <= 2^23 makes |a_i|, |b_j| <= 12 2^23 < 2^27,
    // so |M_k| <= 3 * 3 * 2^54 < 2^58: exact in 64 bits), rounded once to a double m and divided
    // once: exact (bound 0) where |M_k| <= 2^53 and k divides it, else within
    // |M_k - m| / k + u |q_k| (M_k - m exact: |m| < 2^58 converts back exactly).
    s.qn = 2 * degree;
    s.q.fill(E{});
    for (int k = 2; k <= 2 * degree; ++k) {
      std::int64_t mk = 0;
      for (int i = std::max(1, k - degree); i <= std::min(degree, k - 1); ++i) {
        const int j = k - i;
        mk += static_cast<std::int64_t>(s.x.c[static_cast<std::size_t>(i)]) * j *
              static_cast<std::int64_t>(s.y.c[static_cast<std::size_t>(j)]);
      }
      const auto md = static_cast<double>(mk);
      const double qk = md / k;
      const std::int64_t lost = mk - static_cast<std::int64_t>(md);
      const bool whole = lost == 0 && std::abs(mk) <= (std::int64_t{1} << 53) && mk % k == 0;
      s.q[static_cast<std::size_t>(k)] = E{
          qk, whole ? 0.0
                    : (std::abs(static_cast<double>(lost)) / k + kU * std::abs(qk) + kTiny) * kUp};
    }
    s.set_q_sums();
    const auto si = static_cast<std::uint32_t>(shapes_.size());
    shapes_.push_back(s);
    if (r.contour != current) {
      current = r.contour;
      contour_first.push_back(pieces_.size());
    }
    if (degree == 1) {
      Piece p;
      p.shape = si;
      p.t0 = exact(0);
      p.t1 = exact(1);
      p.line = true;
      p.p0 = EPoint{exact(static_cast<double>(cp[0].x)), exact(static_cast<double>(cp[0].y))};
      p.p1 = EPoint{exact(static_cast<double>(cp[1].x)), exact(static_cast<double>(cp[1].y))};
      p.sx = s.x.c[1] > 0 ? 1 : (s.x.c[1] < 0 ? -1 : 0);
      p.sy = s.y.c[1] > 0 ? 1 : (s.y.c[1] < 0 ? -1 : 0);
      p.gap = gap_;
      gap_ = false;
      pieces_.push_back(p);
    } else if (!add_shape_pieces(si, degree)) {
      return false;
    }
  }
  contour_first.push_back(pieces_.size());
  for (std::size_t k = 0; k + 1 < contour_first.size(); ++k) {
    const std::size_t first = contour_first[k], end = contour_first[k + 1];
    if (first == end)
      continue;
    // The contour's first sub-arc (if its first step made one), to link its last one to it.
    first_seq_ = seq_ + 1;
    first_row_ = -1;
    last_row_ = -1;
    for (std::size_t pi = first; pi < end; ++pi) {
      if (pieces_[pi].gap && pi > first) {
        last_row_ = -1; // no link across the shapes left out
        ++seq_;
      }
      if (!walk_piece(static_cast<std::uint32_t>(pi)))
        return false;
    }
    if (last_row_ >= 0 && first_row_ == last_row_ && first_idx_ != last_idx_) {
      std::vector<Sub>& r = subs_;
      if (r[static_cast<std::size_t>(first_idx_)].col == r[static_cast<std::size_t>(last_idx_)].col)
        r[static_cast<std::size_t>(last_idx_)].next = first_idx_;
    }
  }
  return true;
}

// The side of the line through c's end J (at_end) or start J, direction (dx, dy), on which
// curve c lies, strictly, except at J: the sign of cross(d, c(t) - J) on [0, 1] without J, or 0
// where it is not one sign. Exact: g(t) = cross(d, c(t) - J) has integer coefficients and
// vanishes at J's parameter; its quotient h by (t - 1) or t must keep one sign on [0, 1].
// Only the part of c on [from / 2^16, 1] (at_end) or [0, from / 2^16] counts (the part in one
// cell).
constexpr std::int64_t kOne = std::int64_t{1} << 16;
int side_of_curve(const Shape& c, bool at_end, std::int64_t dx, std::int64_t dy,
                  std::int64_t from) {
  const auto n = static_cast<std::size_t>(c.x.n);
  std::array<I128, 4> g{};
  for (std::size_t k = 1; k <= n; ++k)
    g[k] = I128(dx) * static_cast<std::int64_t>(c.y.c[k]) -
           I128(dy) * static_cast<std::int64_t>(c.x.c[k]);
  // c(t) - J relative to c's reference point: J - (x0, y0) = (sum c_k) at the end, else 0.
  I128 jx = 0, jy = 0;
  if (at_end)
    for (std::size_t k = 1; k <= n; ++k) {
      jx += static_cast<std::int64_t>(c.x.c[k]);
      jy += static_cast<std::int64_t>(c.y.c[k]);
    }
  g[0] = -(I128(dx) * jy - I128(dy) * jx);
  // Divide out (t - 1) (at_end) or t as often as g vanishes there (J once, or twice where d is
  // c's tangent at J): g = (t - tJ)^m q with q(tJ) != 0.
  std::size_t deg = n;
  int m = 0;
  const auto sgn = [](I128 v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); };
  while (deg > 0) {
    if (at_end) {
      I128 sum = 0;
      for (std::size_t k = 0; k <= deg; ++k)
        sum += g[k];
      if (sum != 0)
        break;
      I128 carry = 0; // synthetic division by (t - 1)
      std::array<I128, 4> q{};
      for (std::size_t k = deg; k >= 1; --k) {
        carry += g[k];
        q[k - 1] = carry;
      }
      g = q;
    } else {
      if (g[0] != 0)
        break;
      for (std::size_t k = 0; k < deg; ++k)
        g[k] = g[k + 1];
      g[deg] = 0;
    }
    --deg;
    ++m;
  }
  if (m == 0)
    return 0; // J is not on the line: not a common vertex
  if (deg > 2)
    return 0;
  // q keeps one sign on the interval [u0, u1] = [k0, k1] / 2^16: at both ends, and at its
  // extremum where that lies inside (integers: q at K / 2^16 times 2^(16 deg)).
  const I128 k0 = at_end ? I128(from) : 0, k1 = at_end ? I128(kOne) : I128(from);
  // Horner in K with the powers of 2^16 folded in: q(K / 2^16) 2^(16 deg).
  const auto at = [&](I128 kk) {
    I128 v = 0, p = 1;
    for (std::size_t i = 0; i <= deg; ++i) {
      I128 term = g[i] * p;
      for (std::size_t r = i; r < deg; ++r)
        term *= kOne;
      v += term;
      p *= kk;
    }
    return v;
  };
  const int s0 = sgn(at(k0)), s1 = sgn(at(k1));
  if (s0 == 0 || s0 != s1)
    return 0;
  if (deg == 2 && g[2] != 0) {
    const I128 qa = g[2], qb = g[1];
    // t* = -b / (2 a) strictly inside (u0, u1)?
    const I128 num = -qb * kOne, lo = 2 * qa * k0, hi = 2 * qa * k1;
    const bool inside = qa > 0 ? (num > lo && num < hi) : (num < lo && num > hi);
    if (inside && sgn(4 * qa * g[0] - qb * qb) * sgn(qa) != s0)
      return 0; // q(t*) = q0 - b^2 / (4 a) has the other sign, or is 0
  }
  // (t - 1)^m has the sign (-1)^m on [0, 1); t^m is positive on (0, 1].
  return (at_end && m % 2 == 1) ? -s0 : s0;
}

// k with k / 2^16 <= t (t's bound included), in [0, 2^16]; and k with k / 2^16 >= t.
std::int64_t dyadic_below(E t) {
  return std::clamp<std::int64_t>(
      static_cast<std::int64_t>(std::floor((t.v - 2 * t.e) * static_cast<double>(kOne))) - 1, 0,
      kOne);
}
std::int64_t dyadic_above(E t) {
  return std::clamp<std::int64_t>(
      static_cast<std::int64_t>(std::ceil((t.v + 2 * t.e) * static_cast<double>(kOne))) + 1, 0,
      kOne);
}

// The direction of curve c at its end (at_end) or start, from its first nonzero derivative
// there (integers).
std::pair<std::int64_t, std::int64_t> tangent_of(const Shape& c, bool at_end) {
  const auto n = static_cast<std::size_t>(c.x.n);
  for (std::size_t d = 1; d <= n; ++d) { // the d-th derivative, up to a positive factor
    double tx = 0, ty = 0;
    for (std::size_t k = d; k <= n; ++k) {
      double f = 1; // k (k - 1) ... (k - d + 1) t^(k - d) at t = 1 (at_end), or k = d alone
      for (std::size_t m = 0; m < d; ++m)
        f *= static_cast<double>(k - m);
      if (!at_end && k != d)
        continue;
      tx += f * c.x.c[k];
      ty += f * c.y.c[k];
    }
    if (tx != 0 || ty != 0)
      return {static_cast<std::int64_t>(tx), static_cast<std::int64_t>(ty)};
  }
  return {0, 0};
}

// Whether curve c and the segment `line` meet only at their common vertex (c's end where
// at_end): c keeps to one side of the line's line.
bool curve_off_line(const Shape& c, bool at_end, const Shape& line, std::int64_t from) {
  return side_of_curve(c, at_end, static_cast<std::int64_t>(line.x.c[1]),
                       static_cast<std::int64_t>(line.y.c[1]), from) != 0;
}

// Whether curve a (ending at J) and curve b (starting at J) meet only at J: a line through J
// (either one's tangent there, their sum or their difference) with a strictly on one side and b
// on the other.
bool curves_apart(const Shape& a, const Shape& b, std::int64_t a_from, std::int64_t b_to) {
  const auto [ax, ay] = tangent_of(a, true);
  const auto [bx, by] = tangent_of(b, false);
  for (const auto& [dx, dy] : {std::pair{ax, ay}, std::pair{bx, by}, std::pair{ax + bx, ay + by},
                               std::pair{ax - bx, ay - by}}) {
    if (dx == 0 && dy == 0)
      continue;
    const int sa = side_of_curve(a, true, dx, dy, a_from),
              sb = side_of_curve(b, false, dx, dy, b_to);
    if (sa != 0 && sb != 0 && sa != sb)
      return true;
  }
  return false;
}

// Whether sub-arcs a and b of one cell provably do not meet (their boxes apart, or two lines
// that do not cross in the cell).
bool FastAlpha::apart(const Sub& a, const Sub& b) const {
  const auto box_apart = [](const EPoint& a0, const EPoint& a1, const EPoint& b0,
                            const EPoint& b1) {
    const auto hi = [](E p, E q) { return std::max(p.v + 2 * p.e, q.v + 2 * q.e); };
    const auto lo = [](E p, E q) { return std::min(p.v - 2 * p.e, q.v - 2 * q.e); };
    return hi(a0.x, a1.x) < lo(b0.x, b1.x) || hi(b0.x, b1.x) < lo(a0.x, a1.x) ||
           hi(a0.y, a1.y) < lo(b0.y, b1.y) || hi(b0.y, b1.y) < lo(a0.y, a1.y);
  };
  if (box_apart(a.a, a.b, b.a, b.b))
    return true;
  const Piece& pa = pieces_[a.piece];
  const Piece& pb = pieces_[b.piece];
  if (pa.line && pb.line) {
    // Exact: the whole segments do not meet (conservative for the cell).
    const Shape& s = shapes_[pa.shape];
    const Shape& t = shapes_[pb.shape];
    const std::int64_t ax0 = s.x0, ay0 = s.y0, ax1 = s.x0 + static_cast<std::int64_t>(s.x.c[1]),
                       ay1 = s.y0 + static_cast<std::int64_t>(s.y.c[1]);
    const std::int64_t bx0 = t.x0, by0 = t.y0, bx1 = t.x0 + static_cast<std::int64_t>(t.x.c[1]),
                       by1 = t.y0 + static_cast<std::int64_t>(t.y.c[1]);
    const auto orient = [](std::int64_t px, std::int64_t py, std::int64_t qx, std::int64_t qy,
                           std::int64_t rx, std::int64_t ry) { // |edge value| <= 2^49 in range
      const std::int64_t v = formula::edge_value(px, py, qx, qy, rx, ry);
      return v > 0 ? 1 : (v < 0 ? -1 : 0);
    };
    const int o1 = orient(ax0, ay0, ax1, ay1, bx0, by0), o2 = orient(ax0, ay0, ax1, ay1, bx1, by1);
    const int o3 = orient(bx0, by0, bx1, by1, ax0, ay0), o4 = orient(bx0, by0, bx1, by1, ax1, ay1);
    if (o1 * o2 > 0 || o3 * o4 > 0)
      return true;
    return false; // they meet (or are collinear): conservative
  }
  // Curves: boxes of halves, halving the larger one (each part of a monotone piece lies in
  // the box of its ends), within a budget.
  struct Span {
    const Piece* p;
    double t0, t1; // inside the parameter range (the ends are a and b)
    EPoint a, b;
  };
  const auto middle = [&](const Span& x) {
    const double t = 0.5 * (x.t0 + x.t1);
    if (x.p->line) {
      const E half = exact(0.5);
      return std::pair{t, EPoint{add(x.a.x, mul(half, sub(x.b.x, x.a.x))),
                                 add(x.a.y, mul(half, sub(x.b.y, x.a.y)))}};
    }
    return std::pair{t, point_at(*x.p, exact(t))};
  };
  const auto extent = [](const Span& x) {
    return std::abs(x.b.x.v - x.a.x.v) + std::abs(x.b.y.v - x.a.y.v);
  };
  int budget = 96;
  const auto separate = [&](const auto& self, const Span& x, const Span& y) -> bool {
    if (box_apart(x.a, x.b, y.a, y.b))
      return true;
    if (--budget < 0)
      return false;
    if (extent(x) >= extent(y)) {
      const auto [t, m] = middle(x);
      return self(self, Span{x.p, x.t0, t, x.a, m}, y) && self(self, Span{x.p, t, x.t1, m, x.b}, y);
    }
    const auto [t, m] = middle(y);
    return self(self, x, Span{y.p, y.t0, t, y.a, m}) && self(self, x, Span{y.p, t, y.t1, m, y.b});
  };
  return separate(separate, Span{&pa, a.ta.v, a.tb.v, a.a, a.b},
                  Span{&pb, b.ta.v, b.tb.v, b.a, b.b});
}

// Whether sub-arc `second`, which continues `first` in the same cell, meets it only at their
// joint: it does not turn back into the quadrant `first` came from, or where it does, the
// exact tests say they keep apart.
bool FastAlpha::joint_ok(const Sub& first, const Sub& second) const {
  const Piece& pf = pieces_[first.piece];
  const Piece& ps = pieces_[second.piece];
  if (ps.sx != -pf.sx || ps.sy != -pf.sy)
    return true;
  if (pf.line != ps.line) { // a curve and a line: apart if the curve keeps to one side
    const bool curve_first = !pf.line;
    const Sub& cs = curve_first ? first : second;
    return curve_off_line(shapes_[curve_first ? pf.shape : ps.shape], curve_first,
                          shapes_[curve_first ? ps.shape : pf.shape],
                          curve_first ? dyadic_below(cs.ta) : dyadic_above(cs.tb));
  }
  if (!pf.line) // two curves: in doubt unless a line through the joint separates them
    return curves_apart(shapes_[pf.shape], shapes_[ps.shape], dyadic_below(first.ta),
                        dyadic_above(second.tb));
  const Shape& sf = shapes_[pf.shape];
  const Shape& ss = shapes_[ps.shape];
  return sf.x.c[1] * ss.y.c[1] - sf.y.c[1] * ss.x.c[1] != 0; // else it doubles back
}

// Decides a cell that occupied_cell does not (its sub-arcs subs[at, end): three or more, or one
// or two that do not form one open chain), `integral` the integral of w over it (raw squared);
// false where it is not certified.
bool FastAlpha::cell(std::int32_t j, std::vector<Sub>& subs, std::size_t at, std::size_t end,
                     E integral, std::uint8_t& alpha) {
  const std::int32_t c = subs[at].col;
  std::size_t interior = 0;
  for (std::size_t k = at; k < end; ++k)
    interior += subs[k].interior ? 1u : 0u;
  const E v = scale(integral, -2 * kSubpixelBits); // I / A
  if (interior > 0) {
    // (a) No two sub-arcs meet but where one continues into the next, and those do not turn
    // back into each other's quadrant.
    for (std::size_t p = at; p < end; ++p) {
      const Sub& a = subs[p];
      if (!a.interior)
        continue;
      for (std::size_t q = p + 1; q < end; ++q) {
        const Sub& b = subs[q];
        if (!b.interior)
          continue;
        if (a.next == static_cast<std::int32_t>(q) || b.next == static_cast<std::int32_t>(p))
          continue; // consecutive: their joint is tested below
        if (!apart(a, b))
          return false;
      }
    }
    for (std::size_t p = at; p < end; ++p)
      if (subs[p].interior && subs[p].next >= 0 &&
          !joint_ok(subs[p], subs[static_cast<std::size_t>(subs[p].next)]))
        return false;
    // (b) The chains of sub-arcs, their ends on the border, and the winding numbers met walking
    // around it.
    std::vector<End>& ends = ends_;
    ends.clear();
    std::size_t closed = 0, open = 0;
    std::vector<std::uint8_t>& has_prev = has_prev_;
    has_prev.assign(end - at, 0);
    for (std::size_t k = at; k < end; ++k)
      if (subs[k].interior && subs[k].next >= 0)
        has_prev[static_cast<std::size_t>(subs[k].next) - at] = 1;
    const double l = static_cast<double>(std::int64_t{c} * kW);
    const double t = static_cast<double>(std::int64_t{j} * kW);
    const auto position = [&](const EPoint& pt, Side side, bool& ok) -> E {
      switch (side) {
      case kTop:
        return scale(sub(pt.x, exact(l)), -kSubpixelBits);
      case kRight:
        return add(exact(1), scale(sub(pt.y, exact(t)), -kSubpixelBits));
      case kBottom:
        return add(exact(2), scale(sub(exact(l + kWd), pt.x), -kSubpixelBits));
      case kLeft:
        return add(exact(3), scale(sub(exact(t + kWd), pt.y), -kSubpixelBits));
      case kNone:
        break;
      }
      ok = false;
      return E{};
    };
    const auto change = [&](const Piece& p, Side side) {
      switch (side) {
      case kTop:
        return -p.sy;
      case kRight:
        return p.sx;
      case kBottom:
        return p.sy;
      case kLeft:
        return -p.sx;
      case kNone:
        break;
      }
      return 0;
    };
    std::vector<std::uint8_t>& seen = seen_;
    seen.assign(end - at, 0);
    // Each open chain's first and last sub-arc; their ends must lie on the border (a side).
    std::vector<std::pair<std::size_t, std::size_t>>& chains = chains_;
    chains.clear();
    for (std::size_t k = at; k < end; ++k) {
      if (!subs[k].interior || has_prev[k - at] != 0)
        continue;
      ++open;
      // Walk the chain to its last sub-arc.
      std::size_t x = k;
      seen[x - at] = 1;
      while (subs[x].next >= 0) {
        x = static_cast<std::size_t>(subs[x].next);
        if (seen[x - at] != 0)
          return false;
        seen[x - at] = 1;
      }
      if (subs[k].sa == kNone || subs[x].sb == kNone)
        return false; // an end inside the cell
      chains.emplace_back(k, x);
    }
    for (std::size_t k = at; k < end; ++k) {
      if (!subs[k].interior || seen[k - at] != 0)
        continue;
      ++closed; // a cycle: a contour inside the cell
      for (std::size_t x = k; seen[x - at] == 0; x = static_cast<std::size_t>(subs[x].next)) {
        seen[x - at] = 1;
        if (subs[x].next < 0)
          return false;
      }
    }
    if (closed > 1 || (closed > 0 && open > 0))
      return false;
    if (open > 1) { // several chains: the winding numbers met walking around the border
      bool ok = true;
      for (const auto& [k, x] : chains) {
        const Sub& first = subs[k];
        const Sub& last = subs[x];
        ends.push_back(
            End{position(first.a, first.sa, ok), change(pieces_[first.piece], first.sa)});
        ends.push_back(End{position(last.b, last.sb, ok), change(pieces_[last.piece], last.sb)});
      }
      if (!ok)
        return false;
      std::sort(ends.begin(), ends.end(), [](const End& p, const End& q) { return p.s.v < q.s.v; });
      for (std::size_t k = 0; k < ends.size(); ++k) {
        const End& p = ends[k];
        const End& q = ends[(k + 1) % ends.size()];
        const double gap_hi = p.s.v + 2 * p.s.e + 1e-12;
        const double q_lo = q.s.v - 2 * q.s.e + (k + 1 == ends.size() ? 4.0 : 0.0);
        if (!(gap_hi < q_lo))
          return false; // two ends that may coincide
      }
      std::int64_t cur = 0, lo = 0, hi = 0;
      for (const End& p : ends) {
        cur += p.dw;
        lo = std::min(lo, cur);
        hi = std::max(hi, cur);
      }
      if (cur != 0 || hi - lo > 1)
        return false; // three or more winding numbers (or an inconsistent walk)
    }
  }
  return finish(v, interior, alpha);
}

// The alpha of a cell whose sub-arcs are certified (at most two winding numbers), from v = I / A.
bool FastAlpha::finish(E v, std::size_t interior, std::uint8_t& alpha) const {
  if (interior == 0)
    return whole_winding(v, rule_, alpha);
  // Windings {m, m + 1}: the area from I / A.
  const double m = floor_small(v.v);
  E cov;
  const auto fill = [&](double k) {
    return fill_holds(rule_, static_cast<std::int64_t>(k)) ? 1.0 : 0.0;
  };
  const auto alpha_of = [&](double y, double pad) {
    const auto a_lo = (static_cast<std::int64_t>(floor_small(y - pad)) + 1) >> 1;
    const auto a_hi = (static_cast<std::int64_t>(floor_small(y + pad)) + 1) >> 1;
    if (a_lo != a_hi)
      return false;
    alpha = static_cast<std::uint8_t>(std::clamp(a_lo, std::int64_t{0}, std::int64_t{255}));
    return true;
  };
  if (v.v - 2 * v.e > m && v.v + 2 * v.e < m + 1) {
    const double f0 = fill(m), f1 = fill(m + 1);
    if (v.e > 0) {
      // Plain doubles where v carries a bound (no tie to decide exactly): v - m and the sum
      // with f0 round once each, by at most u (both within [-1, 1]; (f1 - f0) (v - m) is exact,
      // f1 - f0 in {-1, 0, 1}), and 510 c once, by at most 510 u; so 510 c is within
      // 510 (e + 2 u) + 510 u < 510 e + 2^-42 of its true value.
      const double y = 510.0 * (f0 + (f1 - f0) * (v.v - m));
      return alpha_of(y, 2 * (510.0 * v.e * kUp + 0x1p-42) + 0x1p-40);
    }
    cov = f0 == f1 ? exact(f0) : add(exact(f0), mul(exact(f1 - f0), sub(v, exact(m))));
  } else {
    const double r = std::nearbyint(v.v);
    cov = E{fill(r), (std::abs(v.v - r) + v.e) * kUp};
  }
  // alpha = floor((510 c + 1) / 2) = (floor(510 c) + 1) >> 1, the same at both ends of 510 c's
  // interval (exactly 510 c where its bound is 0).
  const E y = mul(exact(510), cov);
  return alpha_of(y.v, y.e == 0 ? 0.0 : 2 * y.e + 0x1p-40);
}

void FastAlpha::sort_rows() {
  // A counting sort by row keeps the order of emission within a row; then each row's keys
  // (column, index) are sorted. Memory: the sub-arcs and the rows, not the cells.
  const std::size_t n = subs_.size();
  std::vector<std::uint32_t>& start = row_start_;
  start.assign(static_cast<std::size_t>(h_) + 1, 0);
  for (const Sub& sb : subs_)
    ++start[static_cast<std::size_t>(sb.row) + 1];
  for (std::size_t r = 0; r < static_cast<std::size_t>(h_); ++r)
    start[r + 1] += start[r];
  keys_.resize(n);
  std::vector<std::uint32_t>& at = row_fill_;
  at.assign(start.begin(), start.end() - 1);
  for (std::size_t k = 0; k < n; ++k)
    keys_[at[static_cast<std::size_t>(subs_[k].row)]++] =
        (static_cast<std::uint64_t>(subs_[k].col) << 32) | k; // col in [0, w], k < 2^32
  for (std::size_t r = 0; r < static_cast<std::size_t>(h_); ++r)
    std::sort(keys_.begin() + static_cast<std::ptrdiff_t>(start[r]),
              keys_.begin() + static_cast<std::ptrdiff_t>(start[r + 1]));
}

bool FastAlpha::occupied_cell(std::int32_t j, std::size_t at, std::size_t end, E integral,
                              std::uint8_t& alpha) {
  const auto index = [&](std::size_t k) {
    return static_cast<std::size_t>(keys_[k] & 0xFFFFFFFFu);
  };
  const E v = scale(integral, -2 * kSubpixelBits); // I / A
  if (end - at == 1) {
    const Sub& s = subs_[index(at)];
    if (!s.interior)
      return finish(v, 0, alpha);
    // One sub-arc, a part of one monotone piece: a simple arc, which must run from side to side.
    if (s.next < 0)
      return s.sa != kNone && s.sb != kNone && finish(v, 1, alpha);
  } else if (end - at == 2) {
    // Two sub-arcs, one continuing into the other (the commonest cell after one sub-arc): one
    // chain, so cell()'s (a) and (b) come to its joint and its two ends.
    const std::size_t k0 = index(at), k1 = index(at + 1);
    const Sub& s0 = subs_[k0];
    const Sub& s1 = subs_[k1];
    const Sub* first = nullptr;
    if (s0.interior && s1.interior) {
      if (s0.next == static_cast<std::int32_t>(k1) && s1.next < 0)
        first = &s0;
      else if (s1.next == static_cast<std::int32_t>(k0) && s0.next < 0)
        first = &s1;
    }
    if (first != nullptr) {
      const Sub& second = first == &s0 ? s1 : s0;
      return joint_ok(*first, second) && first->sa != kNone && second.sb != kNone &&
             finish(v, 2, alpha);
    }
  }
  // The general case: the cell's sub-arcs in the order they were emitted, links made local.
  std::vector<Sub>& g = gathered_;
  g.clear();
  for (std::size_t k = at; k < end; ++k)
    g.push_back(subs_[index(k)]);
  for (Sub& sb : g) {
    if (sb.next < 0)
      continue;
    std::int32_t local = -1;
    for (std::size_t k = at; k < end; ++k)
      if (index(k) == static_cast<std::size_t>(sb.next))
        local = static_cast<std::int32_t>(k - at);
    sb.next = local;
  }
  return cell(j, g, 0, g.size(), integral, alpha);
}

bool FastAlpha::row(std::int32_t j, std::uint8_t* out) {
  const std::size_t first = row_start_[static_cast<std::size_t>(j)];
  std::size_t end = row_start_[static_cast<std::size_t>(j) + 1];
  const auto column = [&](std::size_t k) { return static_cast<std::int32_t>(keys_[k] >> 32); };
  // The cover right of a cell, S = the sum of y(b) - y(a) over the sub-arcs right of it, is
  // summed by its end points so that those shared by two of them cancel exactly instead of
  // adding their errors: an end inside the cell (a vertex, a cut of a curve) is shared with the
  // sub-arc before or after it in the same cell, and an end on a column line with the sub-arc
  // on the other side of it (or on the same side). What is left are the ends on row lines
  // (exact; `base`, every cell right of this one) and the ends on the column line left of the
  // cell right of this one (`line`, with the pieces along that line). Then S is exact wherever
  // those crossings are (a half-covered pixel left of a curve is decided).
  E base, line;
  const auto fold = [&](std::size_t at, std::size_t to) { // a cell's ends, and its area
    line = E{};
    E area;
    for (std::size_t k = at; k < to; ++k) {
      const auto i = static_cast<std::size_t>(keys_[k] & 0xFFFFFFFFu);
      const Sub& s = subs_[i];
      if (s.interior)
        area = add(area, s.area);
      for (const auto& [side, y, sign] :
           {std::tuple{s.sa, s.a.y, -1.0}, std::tuple{s.sb, s.b.y, 1.0}}) {
        if (side == kTop || side == kBottom)
          base = add(base, E{sign * y.v, y.e});
        else if (side == kLeft || s.along) // a piece along a column line: on its left line
          line = add(line, E{sign * y.v, y.e});
        // kNone, kRight: cancelled by the sub-arc that shares the point.
      }
    }
    return area;
  };
  std::size_t at = end;
  while (at > first && column(at - 1) >= w_)
    --at;
  (void)fold(at, end);
  end = at;
  E right = add(base, line);
  bool decided = true;
  std::int32_t c = w_ - 1;
  while (c >= 0) {
    const std::int32_t next = end > first ? column(end - 1) : -1;
    if (next < c) {
      // A run of cells without sub-arcs: one winding number each, the same for all of them.
      if (!whole_winding(scale(right, -kSubpixelBits), rule_, out[c]))
        decided = false;
      std::memset(out + next + 1, out[c], static_cast<std::size_t>(c - next - 1));
      c = next;
      continue;
    }
    at = end;
    while (at > first && column(at - 1) == c)
      --at;
    const E above = scale(right, kSubpixelBits);
    const E area = fold(at, end);
    std::uint8_t a = 0;
    if (!occupied_cell(j, at, end, add(above, area), a))
      decided = false;
    out[c] = a;
    right = add(base, line);
    end = at;
    --c;
  }
  return decided;
}

} // namespace

// rule: PATH.AREA.FAST
bool alpha_fast(const Boundary& b, FillRule rule, std::int32_t w, std::int32_t h,
                std::span<std::uint8_t> out, std::vector<std::uint8_t>& undecided,
                const std::vector<std::uint8_t>* only) {
  const auto wanted = [&](std::int32_t j) {
    return only == nullptr || (*only)[static_cast<std::size_t>(j)] != 0;
  };
  undecided.assign(static_cast<std::size_t>(h), 1);
  thread_local FastAlpha f;
  f.reset(rule, w, h, only);
  if (!f.walk(b)) {
    for (std::int32_t j = 0; j < h; ++j)
      undecided[static_cast<std::size_t>(j)] = wanted(j) ? 1 : 0;
    return false;
  }
  f.sort_rows();
  for (std::int32_t j = 0; j < h; ++j) {
    std::uint8_t* row = out.data() + static_cast<std::size_t>(j) * static_cast<std::size_t>(w);
    undecided[static_cast<std::size_t>(j)] = wanted(j) && !f.row(j, row) ? 1 : 0;
  }
  return true;
}

} // namespace rastrules::path::detail
