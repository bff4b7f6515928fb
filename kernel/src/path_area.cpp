// SPDX-License-Identifier: MIT
// 2D paths: exact area coverage and its 8-bit alpha (spec/rules/path.md, PATH.AREA.EXACT,
// PATH.AREA.CELLS, PATH.AREA.ALPHA). Each pixel row is decided cell by cell from signed
// integrals of the winding number in exact 128-bit fractions wherever the cell provably holds
// at most two winding numbers; a row where a cell does not goes to the slab method, which is
// exact for any boundary.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "path_area_rows.hpp"
#include "path_detail.hpp"
#include "rastrules/fixed.hpp"
#include "rastrules/formula/edge.hpp"
#include "rastrules/formula/path_area.hpp"
#include "rastrules/path.hpp"

namespace rastrules::path {
namespace {

using Rational = boost::multiprecision::cpp_rational;
using BigInt = boost::multiprecision::cpp_int;
using detail::ActiveEdges;
using detail::add_run;
using detail::DownEdge;
using detail::floor_of;
using detail::RowAreas;

// Returns the x of edge e, whose slope dx/dy is `slope`, at height y (ya <= y <= yb).
Rational x_at(const DownEdge& e, const Rational& slope, const Rational& y) {
  return Rational(e.xa) + (y - e.ya) * slope;
}

// The slab method of PATH.AREA.EXACT for every row: exact rationals, any boundary.
class SlabRows {
public:
  // Makes nothing until the first row (the cell method usually decides every row).
  SlabRows(const std::vector<DownEdge>& edges, FillRule rule, std::int32_t w)
      : edges_(edges), rule_(rule), w_(w) {}

  // Emits row j's areas, in_row holding the edges with ya < the row's bottom and yb > its top.
  void row(std::int32_t j, const std::vector<const DownEdge*>& in_row,
           const std::function<void(const AreaCoverage&)>& emit) {
    const std::int64_t y0 = std::int64_t{j} * kSubpixelOne;
    const std::int64_t y1 = y0 + kSubpixelOne;
    const FillRule rule = rule_;
    const std::int32_t w = w_;
    if (!row_) {
      row_.emplace(w);
      slopes_.reserve(edges_.size());
      for (const DownEdge& e : edges_)
        slopes_.emplace_back(e.xb - e.xa, e.yb - e.ya);
    }
    RowAreas& row = *row_;
    const auto slope_of = [&](const DownEdge* e) -> const Rational& {
      return slopes_[static_cast<std::size_t>(e - edges_.data())];
    };
    const Rational pixel_area(std::int64_t{kSubpixelOne} * kSubpixelOne);
    // Cut heights: the row's top and bottom, every end inside it, every crossing of two edges.
    std::vector<Rational> cuts{Rational(y0), Rational(y1)};
    for (const DownEdge* e : in_row) {
      if (e->ya > y0)
        cuts.emplace_back(e->ya);
      if (e->yb < y1)
        cuts.emplace_back(e->yb);
    }
    for (std::size_t p = 0; p < in_row.size(); ++p) {
      const DownEdge& e = *in_row[p];
      for (std::size_t q = p + 1; q < in_row.size(); ++q) {
        const DownEdge& f = *in_row[q];
        if (std::max(e.xa, e.xb) < std::min(f.xa, f.xb) ||
            std::max(f.xa, f.xb) < std::min(e.xa, e.xb))
          continue; // apart in x: they cannot cross
        const std::int64_t lo = std::max({e.ya, f.ya, y0});
        const std::int64_t hi = std::min({e.yb, f.yb, y1});
        if (lo >= hi)
          continue;
        const Rational& se = slope_of(&e);
        const Rational& sf = slope_of(&f);
        const Rational dlo = x_at(e, se, Rational(lo)) - x_at(f, sf, Rational(lo));
        const Rational dhi = x_at(e, se, Rational(hi)) - x_at(f, sf, Rational(hi));
        if ((dlo < 0 && dhi > 0) || (dlo > 0 && dhi < 0))
          cuts.push_back(Rational(lo) + Rational(hi - lo) * dlo / (dlo - dhi));
      }
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());

    struct Piece {
      const DownEdge* e;
      Rational xa, xb, key;
    };
    std::vector<Piece> pieces;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const Rational& ya = cuts[k];
      const Rational& yb = cuts[k + 1];
      pieces.clear();
      for (const DownEdge* e : in_row) {
        if (e->ya <= ya && e->yb >= yb) {
          Rational xa = x_at(*e, slope_of(e), ya);
          Rational xb = x_at(*e, slope_of(e), yb);
          Rational key = xa + xb; // twice the x at mid-slab: no two edges cross inside the slab
          pieces.push_back(Piece{e, std::move(xa), std::move(xb), std::move(key)});
        }
      }
      std::sort(pieces.begin(), pieces.end(),
                [](const Piece& p, const Piece& q) { return p.key < q.key; });
      // Left of every piece the winding number is 0 (the boundary is closed, so the directions
      // of the pieces crossing a horizontal line sum to 0); passing piece m from left to right
      // subtracts its direction (PATH.WINDING counts the crossings right of the point).
      const Rational hgt = yb - ya;
      std::int64_t wn = 0;
      std::size_t run_start = 0;
      bool in_run = false;
      for (std::size_t m = 0; m < pieces.size(); ++m) {
        wn -= pieces[m].e->dir;
        const bool filled = fill_holds(rule, wn);
        if (filled && !in_run) {
          run_start = m;
          in_run = true;
        } else if (!filled && in_run) {
          add_run(row, w, pieces[run_start].xa, pieces[run_start].xb, pieces[m].xa, pieces[m].xb,
                  hgt);
          in_run = false;
        }
      }
    }
    Rational running = 0;
    for (std::int64_t c = row.touched_lo; c <= row.touched_hi; ++c) {
      const auto k = static_cast<std::size_t>(c);
      running += row.full_diff[k];
      row.full_diff[k] = 0;
      const Rational a = row.partial[k] + running;
      row.partial[k] = 0;
      if (a != 0)
        emit(AreaCoverage{static_cast<std::int32_t>(c), j, a / pixel_area, Rational(0)});
    }
    row.full_diff[static_cast<std::size_t>(row.touched_hi + 1)] = 0;
    row.touched_lo = w;
    row.touched_hi = -1;
  }

private:
  const std::vector<DownEdge>& edges_;
  FillRule rule_;
  std::int32_t w_;
  std::optional<RowAreas> row_;
  std::vector<Rational> slopes_;
};

// Bit budgets of the cell method (PATH.AREA.CELLS), for raw coordinates |v| <= 2^23
// (PATH.GEOMETRY) and targets of at most kMaxTargetSide = 2^14 px (area_rows refuses larger
// ones): x at a row line times |dy| (xn) and y at a column line times |dx| (yn) within 2^23
// times the run; border positions below 2^34, compared by cross products in __int128;
// orientations within 2^49 and the common point's numerators within 2^74; the ramp integrals
// in [0, 2^94] and every fraction sum checked for overflow (a sum that would leave __int128 is
// taken in cpp_rational); full-width covers |dir kW h| <= 2^16 an edge, < 2^42 for the 2^26
// edges a 64 MiB scene can hold. proofs/path/area_budget.cpp proves them with Z3 on the
// templates of rastrules/formula/path_area.hpp, which the code below calls.
__extension__ typedef __int128 I128;
__extension__ typedef unsigned __int128 U128;

constexpr std::int64_t kW = kSubpixelOne;   // a pixel's side, raw
constexpr std::int64_t kCellArea = kW * kW; // a pixel's area, raw squared

// Whether raw coordinate v lies on a pixel grid line.
constexpr bool on_grid(std::int64_t v) {
  return (v & (kW - 1)) == 0;
}

using detail::kSelect;

int sign_of(std::int64_t v) {
  return (v > 0) - (v < 0);
}

int ctz128(U128 v) {
  const auto lo = static_cast<std::uint64_t>(v);
  return lo != 0 ? __builtin_ctzll(lo) : 64 + __builtin_ctzll(static_cast<std::uint64_t>(v >> 64));
}

// Binary gcd; gcd(0, b) = b.
U128 gcd128(U128 a, U128 b) {
  if (a == 0)
    return b;
  if (b == 0)
    return a;
  const int shift = ctz128(a | b);
  a >>= ctz128(a);
  while (b != 0) {
    b >>= ctz128(b);
    if (a > b)
      std::swap(a, b);
    b -= a;
  }
  return a << shift;
}

U128 abs128(I128 v) {
  return v < 0 ? U128(0) - static_cast<U128>(v) : static_cast<U128>(v);
}

// A fraction n / d, d > 0, in lowest terms after reduce().
struct Frac {
  I128 n = 0;
  I128 d = 1;
  void reduce() {
    const U128 g = gcd128(abs128(n), static_cast<U128>(d));
    if (g > 1) {
      n /= static_cast<I128>(g);
      d /= static_cast<I128>(g);
    }
  }
};

// s += f exactly (s in lowest terms only where the plain sum would leave __int128); false, s
// unspecified, where even the reduced sum would.
bool add_to(Frac& s, const Frac& f) {
  if (f.n == 0)
    return true;
  I128 den = 0, a = 0, b = 0, num = 0;
  if (!__builtin_mul_overflow(s.d, f.d, &den) && !__builtin_mul_overflow(s.n, f.d, &a) &&
      !__builtin_mul_overflow(f.n, s.d, &b) && !__builtin_add_overflow(a, b, &num)) {
    s = Frac{num, den};
    return true;
  }
  s.reduce();
  const I128 g = static_cast<I128>(gcd128(static_cast<U128>(s.d), static_cast<U128>(f.d)));
  const I128 sd = s.d / g, fd = f.d / g;
  if (__builtin_mul_overflow(s.d, fd, &den) || __builtin_mul_overflow(s.n, fd, &a) ||
      __builtin_mul_overflow(f.n, sd, &b) || __builtin_add_overflow(a, b, &num))
    return false;
  s = Frac{num, den};
  s.reduce();
  return true;
}

BigInt big_of(I128 v) {
  const U128 m = abs128(v);
  BigInt r = static_cast<std::uint64_t>(m >> 64);
  r <<= 64;
  r += static_cast<std::uint64_t>(m);
  return v < 0 ? BigInt(-r) : r;
}

Rational rational_of(Frac f) {
  constexpr I128 kLo = std::numeric_limits<std::int64_t>::min();
  constexpr I128 kHi = std::numeric_limits<std::int64_t>::max();
  if (f.n < kLo || f.n > kHi || f.d > kHi)
    f.reduce();
  if (f.n < kLo || f.n > kHi || f.d > kHi)
    return Rational(big_of(f.n), big_of(f.d));
  if (f.d == 1)
    return Rational(static_cast<std::int64_t>(f.n));
  return Rational(static_cast<std::int64_t>(f.n), static_cast<std::int64_t>(f.d)); // reduces
}

// A line edge of the boundary as drawn, zero-length ones left out, with the edges before and
// after it in its contour (among those kept).
struct CellEdge {
  std::int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  std::uint32_t prev = 0, next = 0;
  [[nodiscard]] std::int64_t ymin() const { return std::min(y0, y1); }
  [[nodiscard]] std::int64_t ymax() const { return std::max(y0, y1); }
};

// Whether the closed segments e and f meet at a point of the closed square [l, l + kW] x
// [t, t + kW]; collinear segments that overlap count as meeting anywhere (conservative).
bool meet_in_cell(const CellEdge& e, const CellEdge& f, std::int64_t l, std::int64_t t) {
  // Orientations (edge functions, |.| <= 2^49 in range).
  using formula::edge_value;
  const std::int64_t o1 = edge_value(e.x0, e.y0, e.x1, e.y1, f.x0, f.y0);
  const std::int64_t o2 = edge_value(e.x0, e.y0, e.x1, e.y1, f.x1, f.y1);
  if ((o1 > 0 && o2 > 0) || (o1 < 0 && o2 < 0))
    return false;
  const std::int64_t o3 = edge_value(f.x0, f.y0, f.x1, f.y1, e.x0, e.y0);
  const std::int64_t o4 = edge_value(f.x0, f.y0, f.x1, f.y1, e.x1, e.y1);
  if ((o3 > 0 && o4 > 0) || (o3 < 0 && o4 < 0))
    return false;
  if (o1 == 0 && o2 == 0) { // collinear: meet iff their extents overlap
    const bool overlap_x = std::max(std::min(e.x0, e.x1), std::min(f.x0, f.x1)) <=
                           std::min(std::max(e.x0, e.x1), std::max(f.x0, f.x1));
    const bool overlap_y = std::max(std::min(e.y0, e.y1), std::min(f.y0, f.y1)) <=
                           std::min(std::max(e.y0, e.y1), std::max(f.y0, f.y1));
    return overlap_x && overlap_y;
  }
  // One common point: e(u), u = o3 / (o3 - o4) (o3 != o4 as the lines are not parallel here).
  const formula::CellMeetPoint<I128> m =
      formula::cell_meet_point<I128>(e.x0, e.y0, e.x1, e.y1, o3, o4, kSelect);
  return formula::cell_meet_inside<I128>(m, l, t);
}

// The integral over y in [ya, ya + h] of max(x(y) - lo, 0), x linear from pa / q to pb / q,
// times 2 q |dx| (dx: the edge's run, != 0, with |pb - pa| = h |dx|); in [0, 2^94].
I128 ramp_integral(I128 pa, I128 pb, std::int64_t q, std::int64_t h, std::int64_t adx,
                   std::int64_t lo) {
  return formula::cell_ramp_integral<I128>(pa, pb, q, h, adx, lo, kSelect);
}

// One cell's records of a pixel row: a piece of an edge in the cell, a crossing of the
// boundary with the cell's border (at perimeter position p / q, clockwise from the top-left
// corner, changing the winding number by dw), a part of the cell's integral of w.
struct PieceRec {
  std::int32_t col = 0;
  std::uint32_t edge = 0;
};
struct CrossRec {
  std::int32_t col = 0;
  std::int32_t dw = 0;
  std::int64_t p = 0, q = 1;   // position p / q on the border, q > 0
  std::int64_t sn = 0, sd = 1; // where positions tie: the order sn / sd, sd > 0
};
struct PartRec {
  std::int32_t col = 0;
  Frac f;
};

// A row's result for one cell, kept until the whole row is decided.
struct CellArea {
  std::int32_t col = 0;
  Frac area;        // px^2 (not reduced); when big is false
  bool big = false; // the value is in CellRows::big_
};

// The cell method of PATH.AREA.CELLS: decides a pixel row cell by cell, or declines it.
class CellRows {
public:
  CellRows(const detail::Boundary& b, std::size_t contours, FillRule rule, std::int32_t w,
           std::int32_t h)
      : rule_(rule), w_(w), force_(static_cast<std::size_t>(h), 0),
        full_diff_(static_cast<std::size_t>(w) + 2, 0),
        wind_diff_(static_cast<std::size_t>(w) + 2, 0) {
    // Edges by contour (boundary_into lists each contour's segments, then its closing line).
    std::size_t k = 0;
    for (std::size_t ci = 0; ci < contours; ++ci) {
      const std::size_t first = edges_.size();
      for (; k < b.lines.size() && b.lines[k].contour == ci; ++k) {
        const detail::Edge& e = b.lines[k];
        if (e.x0 != e.x1 || e.y0 != e.y1)
          edges_.push_back(CellEdge{e.x0, e.y0, e.x1, e.y1, 0, 0});
      }
      const std::size_t n = edges_.size() - first;
      if (n == 0)
        continue;
      std::int64_t x_lo = edges_[first].x0, x_hi = x_lo, y_lo = edges_[first].y0, y_hi = y_lo;
      for (std::size_t i = 0; i < n; ++i) {
        CellEdge& e = edges_[first + i];
        e.prev = static_cast<std::uint32_t>(first + (i + n - 1) % n);
        e.next = static_cast<std::uint32_t>(first + (i + 1) % n);
        x_lo = std::min(x_lo, e.x0);
        x_hi = std::max(x_hi, e.x0);
        y_lo = std::min(y_lo, e.y0);
        y_hi = std::max(y_hi, e.y0);
      }
      // A contour inside one cell bounds a region that touches no side of the cell: the cell
      // method cannot see its winding number (PATH.AREA.CELLS).
      if (floor_div(x_lo, kW) == floor_div(x_hi, kW) &&
          floor_div(y_lo, kW) == floor_div(y_hi, kW)) {
        const std::int64_t row = floor_div(y_lo, kW);
        if (row >= 0 && row < h)
          force_[static_cast<std::size_t>(row)] = 1;
      }
    }
    if (k != b.lines.size())
      throw std::logic_error("path: boundary lines out of contour order");
    order_.resize(edges_.size());
    for (std::size_t i = 0; i < order_.size(); ++i)
      order_[i] = static_cast<std::uint32_t>(i);
    std::sort(order_.begin(), order_.end(), [&](std::uint32_t p, std::uint32_t q) {
      return edges_[p].ymin() != edges_[q].ymin() ? edges_[p].ymin() < edges_[q].ymin() : p < q;
    });
  }

  // Decides row j and returns true (its areas: results(), big()), or returns false where a cell
  // of the row needs the slab method. Rows must come in increasing order.
  bool row(std::int32_t j);
  // The last row's cells with nonzero area, by column; the values of those marked big, in order.
  [[nodiscard]] const std::vector<CellArea>& results() const { return out_; }
  [[nodiscard]] const std::vector<Rational>& big() const { return big_; }

private:
  bool collect(std::int32_t j);
  bool decide(std::int32_t j);
  bool cell_area(std::int32_t c, std::int64_t t, std::int64_t wind, std::int64_t full,
                 std::size_t pieces_at, std::size_t pieces_end, std::size_t cross_at,
                 std::size_t cross_end, std::size_t parts_at, std::size_t parts_end);

  FillRule rule_;
  std::int32_t w_;
  std::vector<CellEdge> edges_;
  std::vector<std::uint32_t> order_; // edges by ymin
  std::size_t next_ = 0;
  std::vector<std::uint32_t> active_;
  std::vector<std::uint8_t> force_;
  std::vector<std::int64_t> full_diff_, wind_diff_;
  std::int32_t lo_ = 0, hi_ = -1; // the row's columns that may have area
  std::vector<PieceRec> pieces_;
  std::vector<CrossRec> crosses_;
  std::vector<PartRec> parts_;
  std::vector<std::uint32_t> touched_; // the entries of the diffs that may not be 0
  std::vector<CellArea> out_;
  std::vector<Rational> big_;
};

// Collects row j's pieces, crossings and integrals (PATH.AREA.CELLS); false where the row is
// the slab method's (a contour inside one cell). A cell's pieces are the edges that meet its
// interior; its crossings are where they cross the cell's border moved into it by
// infinitesimals (x by eps, y by delta), so that a vertex on a grid line and an edge along one
// are decided like any other point.
bool CellRows::collect(std::int32_t j) {
  const std::int64_t t = std::int64_t{j} * kW, bot = t + kW;
  while (next_ < order_.size() && edges_[order_[next_]].ymin() <= bot)
    active_.push_back(order_[next_++]);
  std::erase_if(active_, [&](std::uint32_t i) { return edges_[i].ymax() < t; });
  pieces_.clear();
  crosses_.clear();
  parts_.clear();
  lo_ = w_;
  hi_ = -1;
  if (force_[static_cast<std::size_t>(j)] != 0)
    return false;
  const std::int64_t w = w_;
  const auto bump = [&](std::vector<std::int64_t>& diff, std::int64_t at, std::int64_t v) {
    diff[static_cast<std::size_t>(at)] += v;
    touched_.push_back(static_cast<std::uint32_t>(at));
  };
  const auto add_full = [&](std::int64_t before, std::int64_t v) { // columns [0, before)
    if (before <= 0)
      return;
    bump(full_diff_, 0, v);
    bump(full_diff_, std::min(before, w), -v);
  };
  const auto add_wind = [&](std::int64_t upto, std::int64_t v) { // columns [0, upto]
    if (upto < 0)
      return;
    bump(wind_diff_, 0, v);
    bump(wind_diff_, std::min(upto + 1, w), -v);
  };
  const auto add_span = [&](std::int64_t cmin, std::int64_t cmax) {
    lo_ = static_cast<std::int32_t>(std::min<std::int64_t>(lo_, std::max<std::int64_t>(cmin, 0)));
    hi_ = static_cast<std::int32_t>(std::max<std::int64_t>(hi_, std::min(cmax, w - 1)));
  };
  const auto add_pieces = [&](std::int64_t cmin, std::int64_t cmax, std::uint32_t i) {
    for (std::int64_t c = std::max<std::int64_t>(cmin, 0); c <= std::min(cmax, w - 1); ++c)
      pieces_.push_back(PieceRec{static_cast<std::int32_t>(c), i});
  };
  const auto cross = [&](std::int64_t c, int dw, std::int64_t p, std::int64_t q, std::int64_t sn,
                         std::int64_t sd) {
    if (c >= 0 && c < w)
      crosses_.push_back(CrossRec{static_cast<std::int32_t>(c), dw, p, q, sn, sd});
  };
  for (const std::uint32_t i : active_) {
    const CellEdge& e = edges_[i];
    const std::int64_t dx = e.x1 - e.x0, dy = e.y1 - e.y0;
    const int sdx = sign_of(dx);
    // Crossings of the column lines x = k kW, k in [k0, k1], at height yn / q_y (tie order:
    // -dy/dx); xlo, xhi (scaled by sc) the edge's x-range in the row.
    const auto column_lines = [&](std::int64_t xlo, std::int64_t xhi, std::int64_t sc,
                                  const auto& y_at) -> bool {
      const std::int64_t adx = dx > 0 ? dx : -dx;
      for (std::int64_t k = std::max<std::int64_t>(ceil_div(xlo, sc * kW), 0);
           k <= std::min(floor_div(xhi, sc * kW), w); ++k) {
        // At a grid corner (yn / qy = t or bot) the moved border meets the edge on a side, at
        // that side's end (position kW, 2 kW, 3 kW or 4 kW), never on the top or bottom.
        const auto [yn, qy] = y_at(k * kW);
        const std::int64_t line = k * kW * sc;
        if (xlo < line) // the right side of column k - 1, walked down
          cross(k - 1, sdx, formula::cell_right_position(yn, t, qy), qy, -dy * sdx, adx);
        if (line < xhi) // the left side of column k, walked up
          cross(k, -sdx, formula::cell_left_position(yn, t, qy), qy, -dy * sdx, adx);
      }
      return true;
    };
    if (dy == 0) {
      if (e.y0 <= t || e.y0 >= bot)
        continue; // on the row's border: it meets no cell's interior
      const std::int64_t xlo = std::min(e.x0, e.x1), xhi = std::max(e.x0, e.x1);
      add_pieces(floor_div(xlo, kW), ceil_div(xhi, kW) - 1, i);
      add_span(floor_div(xlo, kW), floor_div(xhi, kW));
      if (!column_lines(xlo, xhi, 1, [&](std::int64_t) {
            return std::pair{e.y0, std::int64_t{1}};
          }))
        return false;
      continue;
    }
    const std::int64_t ya = std::max(e.ymin(), t), yb = std::min(e.ymax(), bot), h = yb - ya;
    if (h <= 0)
      continue; // meets the row at one point of its border
    const int dir = sign_of(dy);
    const std::int64_t q = dy > 0 ? dy : -dy;
    const std::int64_t sn = dx * dir; // tie order on the top and bottom: dx/dy = sn / q
    if (dx == 0) {
      const std::int64_t c = floor_div(e.x0, kW), l = c * kW;
      if (on_grid(e.x0)) { // along a column line: no cell's interior, no cell's moved border
        add_full(c, dir * kW * h);
        add_span(c - 1, c - 1);
        if (ya == t)
          add_wind(c - 1, dir); // right of the top-left corners of the columns before it
        continue;
      }
      add_full(c, dir * kW * h);
      add_span(c, c);
      if (c >= 0 && c < w) {
        pieces_.push_back(PieceRec{static_cast<std::int32_t>(c), i});
        parts_.push_back(
            PartRec{static_cast<std::int32_t>(c), Frac{I128(dir) * (e.x0 - l) * h, 1}});
      }
      if (ya == t) {
        add_wind(c, dir);
        cross(c, -dir, formula::cell_top_position<std::int64_t>(e.x0, c, 1), 1, 0, 1);
      }
      if (yb == bot)
        cross(c, dir, formula::cell_bottom_position<std::int64_t>(e.x0, c, 1), 1, 0, 1);
      continue;
    }
    // x at height y is xn(y) / q exactly.
    const auto xn = [&](std::int64_t y) {
      return formula::cell_x_numerator<std::int64_t>(e.x0, e.y0, dx, dy, dir, y);
    };
    const std::int64_t pa = xn(ya), pb = xn(yb);
    const bool corner_a = ya == t && pa % (q * kW) == 0; // through a top corner of the row
    const bool corner_b = yb == bot && pb % (q * kW) == 0;
    const std::int64_t xlo = std::min(pa, pb), xhi = std::max(pa, pb);
    const std::int64_t cmin = floor_div(xlo, q * kW), cmax = floor_div(xhi, q * kW);
    add_full(cmin, dir * kW * h);
    add_span(cmin, cmax);
    add_pieces(cmin, ceil_div(xhi, q * kW) - 1, i);
    if (ya == t) { // crosses the row's top: w at the top-left corners of columns <= ca
      const std::int64_t ca = floor_div(pa, q * kW);
      if (corner_a) {
        add_wind(ca - 1, dir); // right of the top-left corners before it; no top side crossed
      } else {
        add_wind(ca, dir);
        cross(ca, -dir, formula::cell_top_position(pa, ca, q), q, sn, q);
      }
    }
    if (yb == bot && !corner_b) {
      const std::int64_t cb = floor_div(pb, q * kW);
      cross(cb, dir, formula::cell_bottom_position(pb, cb, q), q, sn, q);
    }
    const std::int64_t adx = dx > 0 ? dx : -dx;
    if (!column_lines(xlo, xhi, q, [&](std::int64_t x) {
          return std::pair{formula::cell_y_numerator<std::int64_t>(e.x0, e.y0, dx, dy, sdx, x),
                           adx};
        }))
      return false;
    const std::int64_t den = 2 * q * adx;
    for (std::int64_t c = std::max<std::int64_t>(cmin, 0); c <= std::min(cmax, w - 1); ++c) {
      const I128 v =
          ramp_integral(pa, pb, q, h, adx, c * kW) - ramp_integral(pa, pb, q, h, adx, c * kW + kW);
      parts_.push_back(PartRec{static_cast<std::int32_t>(c), Frac{dir > 0 ? v : -v, den}});
    }
  }
  return true;
}

// Decides cell c of row t from its winding number at the top-left corner, its integral of w
// from the edges right of it (full, raw squared) and its records; false where it needs the
// slab method.
bool CellRows::cell_area(std::int32_t c, std::int64_t t, std::int64_t wind, std::int64_t full,
                         std::size_t pieces_at, std::size_t pieces_end, std::size_t cross_at,
                         std::size_t cross_end, std::size_t parts_at, std::size_t parts_end) {
  const auto put = [&](Frac f) {
    if (f.n != 0)
      out_.push_back(CellArea{c, f, false});
  };
  if (pieces_at == pieces_end) { // no boundary in the cell: one winding number
    put(Frac{fill_holds(rule_, wind) ? 1 : 0, 1});
    return true;
  }
  // The boundary's pieces must not meet but where consecutive edges join, nor double back.
  const std::int64_t l = std::int64_t{c} * kW;
  for (std::size_t p = pieces_at; p < pieces_end; ++p) {
    const CellEdge& e = edges_[pieces_[p].edge];
    for (std::size_t r = p + 1; r < pieces_end; ++r) {
      const std::uint32_t fi = pieces_[r].edge;
      const CellEdge& f = edges_[fi];
      if (e.next == fi || e.prev == fi) {
        const std::int64_t ex = e.x1 - e.x0, ey = e.y1 - e.y0, fx = f.x1 - f.x0, fy = f.y1 - f.y0;
        if (formula::cell_doubles_back<std::int64_t>(ex, ey, fx, fy))
          return false; // doubles back (a contour of two edges always does)
        continue;
      }
      if (meet_in_cell(e, f, l, t))
        return false;
    }
  }
  // Every region of the cell touches its border: the winding numbers met walking around it
  // clockwise are all the cell has, consecutive integers [lo, hi].
  std::sort(crosses_.begin() + static_cast<std::ptrdiff_t>(cross_at),
            crosses_.begin() + static_cast<std::ptrdiff_t>(cross_end),
            [](const CrossRec& a, const CrossRec& b) {
              return formula::cell_border_before<I128>(a.p, a.q, a.sn, a.sd, b.p, b.q, b.sn, b.sd);
            });
  std::int64_t cur = wind, lo = wind, hi = wind;
  for (std::size_t k = cross_at; k < cross_end; ++k) {
    cur += crosses_[k].dw;
    lo = std::min(lo, cur);
    hi = std::max(hi, cur);
  }
  if (cur != wind)
    throw std::logic_error("path: a cell's border walk does not close (PATH.AREA.CELLS)");
  const bool f_lo = fill_holds(rule_, lo), f_hi = fill_holds(rule_, hi);
  bool constant = lo == hi;
  if (rule_ == FillRule::kNonZero && (lo >= 1 || hi <= -1))
    constant = true;
  if (constant) {
    put(Frac{f_lo ? 1 : 0, 1});
    return true;
  }
  if (hi != lo + 1)
    return false; // three or more winding numbers: the fill rule is not affine on them
  // w in {lo, lo + 1}: area = fill(lo) + (fill(lo + 1) - fill(lo)) (I / A - lo), I the integral
  // of w over the cell (raw squared) and A the cell's area.
  Frac integral{full, 1};
  bool fits = true;
  for (std::size_t k = parts_at; k < parts_end && fits; ++k)
    fits = add_to(integral, parts_[k].f);
  const int beta = static_cast<int>(f_hi) - static_cast<int>(f_lo);
  if (fits) {
    // (f_lo A d + beta (n - lo A d)) / (A d)
    I128 ad = 0, lo_ad = 0, diff = 0, num = 0, base = 0;
    fits = !__builtin_mul_overflow(integral.d, I128(kCellArea), &ad) &&
           !__builtin_mul_overflow(ad, static_cast<I128>(lo), &lo_ad) &&
           !__builtin_sub_overflow(integral.n, lo_ad, &diff) &&
           !__builtin_mul_overflow(ad, static_cast<I128>(f_lo ? 1 : 0), &base) &&
           !__builtin_add_overflow(base, diff * beta, &num);
    if (fits) {
      put(Frac{num, ad}); // reduced when made a Rational
      return true;
    }
  }
  Rational big(full);
  for (std::size_t k = parts_at; k < parts_end; ++k)
    big += rational_of(parts_[k].f);
  Rational a = Rational(f_lo ? 1 : 0) + beta * (big / kCellArea - lo);
  if (a != 0) {
    out_.push_back(CellArea{c, Frac{}, true});
    big_.push_back(std::move(a));
  }
  return true;
}

bool CellRows::decide(std::int32_t j) {
  out_.clear();
  big_.clear();
  const auto by_col = [](const auto& a, const auto& b) { return a.col < b.col; };
  std::sort(pieces_.begin(), pieces_.end(), by_col);
  std::sort(crosses_.begin(), crosses_.end(), by_col);
  std::sort(parts_.begin(), parts_.end(), by_col);
  // Below lo_ the diffs have entries at 0 only (every other entry is at a column where its
  // edge has a piece, or at w).
  std::int64_t full = full_diff_[0], wind = wind_diff_[0];
  std::size_t pa = 0, ca = 0, ra = 0;
  const std::int64_t t = std::int64_t{j} * kW;
  for (std::int32_t c = lo_; c <= hi_; ++c) {
    if (c > 0) {
      full += full_diff_[static_cast<std::size_t>(c)];
      wind += wind_diff_[static_cast<std::size_t>(c)];
    }
    std::size_t pe = pa, ce = ca, re = ra;
    while (pe < pieces_.size() && pieces_[pe].col == c)
      ++pe;
    while (ce < crosses_.size() && crosses_[ce].col == c)
      ++ce;
    while (re < parts_.size() && parts_[re].col == c)
      ++re;
    if (!cell_area(c, t, wind, full, pa, pe, ca, ce, ra, re))
      return false;
    pa = pe;
    ca = ce;
    ra = re;
  }
  return true;
}

bool CellRows::row(std::int32_t j) {
  const bool collected = collect(j);
  const bool decided = collected && decide(j);
  for (const std::uint32_t k : touched_) {
    full_diff_[k] = 0;
    wind_diff_[k] = 0;
  }
  touched_.clear();
  return decided;
}

// Returns floor(255 n / d + 1/2) for n / d in [0, 1], d > 0 (PATH.AREA.ALPHA).
std::uint8_t alpha_of(Frac f) {
  I128 num = 0, den = 0;
  for (int pass = 0; pass < 2; ++pass) {
    if (!__builtin_mul_overflow(f.n, I128(510), &num) && !__builtin_add_overflow(num, f.d, &num) &&
        !__builtin_mul_overflow(f.d, I128(2), &den))
      return static_cast<std::uint8_t>(num / den);
    f.reduce();
  }
  return detail::alpha_of(rational_of(f));
}

// Walks the rows of [0, w) x [0, h) that some edge reaches into: cells_row(j, cells) for a row
// the cell method decided, slabs.row(j, in_row, slab_pixel) for the others.
template <class CellsRow>
void area_rows(const detail::Boundary& b, std::size_t contours, FillRule rule, std::int32_t w,
               std::int32_t h, detail::AreaMethod method, detail::AreaRows* rows,
               const std::vector<std::uint8_t>* only, CellsRow&& cells_row,
               const std::function<void(const AreaCoverage&)>& slab_pixel) {
  if (w <= 0 || h <= 0)
    return;
  if (!b.curves.empty()) { // PATH.AREA.CURVE: pieces of curves, chords by slabs, lenses added
    detail::cover_area_curves(b, rule, w, h, slab_pixel, only);
    return;
  }
  const std::vector<DownEdge> edges = detail::down_edges(b);
  std::vector<const DownEdge*> active_list;
  ActiveEdges active(edges, active_list);
  SlabRows slabs(edges, rule, w);
  CellRows cells(b, contours, rule, w, h);
  std::vector<const DownEdge*> in_row;
  for (std::int32_t j = 0; j < h; ++j) {
    const std::int64_t y0 = std::int64_t{j} * kSubpixelOne;
    const std::int64_t y1 = y0 + kSubpixelOne;
    in_row.clear();
    for (const DownEdge* e : active.advance(y0, y1 - 1))
      if (e->ya < y1 && e->yb > y0)
        in_row.push_back(e);
    if (in_row.empty())
      continue; // no edge reaches into the row: w = 0 in all of it
    if (only != nullptr && (*only)[static_cast<std::size_t>(j)] == 0)
      continue; // decided already (PATH.AREA.FAST)
    if (method != detail::AreaMethod::kSlabs && cells.row(j)) {
      cells_row(j, cells);
      if (rows != nullptr)
        ++rows->cells;
      continue;
    }
    slabs.row(j, in_row, slab_pixel);
    if (rows != nullptr)
      ++rows->slabs;
  }
}

} // namespace

namespace detail {

namespace {
// The cell method's budgets assume targets of at most kMaxTargetSide a side.
void check_side(std::int32_t w, std::int32_t h) {
  if (w > 0 && h > 0 && (w > kMaxTargetSide || h > kMaxTargetSide))
    throw std::invalid_argument(
        "path: area coverage of a target wider or taller than 16384 px (PATH.AREA.CELLS)");
}
} // namespace

// rule: PATH.AREA.ALPHA
std::uint8_t alpha_of(const Rational& a) {
  // floor(a * 255 + 1/2) = (510 n + d) / (2 d) for a = n / d in [0, 1], d > 0: a quotient of
  // non-negative integers, at most 255.
  const BigInt n = boost::multiprecision::numerator(a);
  const BigInt d = boost::multiprecision::denominator(a);
  const BigInt q = (n * 510 + d) / (d * 2);
  return static_cast<std::uint8_t>(q.convert_to<int>());
}

// rule: PATH.AREA.EXACT, PATH.AREA.CELLS
void cover_area_by(const Path& path, std::int32_t w, std::int32_t h, AreaMethod method,
                   const std::function<void(const AreaCoverage&)>& emit, AreaRows* rows) {
  check_side(w, h);
  area_rows(
      detail::boundary_of(path), path.contours.size(), path.fill_rule, w, h,
      method == AreaMethod::kFast || method == AreaMethod::kSweep ? AreaMethod::kCells : method,
      rows, nullptr,
      [&](std::int32_t j, const CellRows& cells) {
        std::size_t k = 0;
        for (const CellArea& a : cells.results())
          emit(AreaCoverage{a.col, j, a.big ? cells.big()[k++] : rational_of(a.area), Rational(0)});
      },
      emit);
}

// rule: PATH.AREA.ALPHA, PATH.AREA.CELLS
void cover_alpha_by(const Path& path, std::int32_t w, std::int32_t h, AreaMethod method,
                    std::span<std::uint8_t> out, AreaRows* rows) {
  if (w <= 0 || h <= 0)
    return;
  const auto stride = static_cast<std::size_t>(w);
  if (out.size() != stride * static_cast<std::size_t>(h))
    throw std::invalid_argument("path: alpha buffer is not w * h bytes (PATH.AREA.ALPHA)");
  check_side(w, h);
  // One workspace a thread, as alpha_fast's: the vectors keep their room from the last path.
  thread_local Boundary b;
  boundary_into(path, b);
  thread_local std::vector<std::uint8_t> undecided;
  undecided.clear();
  // Rows decided by the sweep, then the fast cells; the others (undecided) go to the exact
  // methods.
  std::size_t swept = 0;
  if (method == AreaMethod::kSweep) {
    if (alpha_sweep(b, path.fill_rule, w, h, out, undecided))
      swept = static_cast<std::size_t>(std::count(undecided.begin(), undecided.end(), 0));
    if (rows != nullptr)
      rows->swept += swept;
    method = AreaMethod::kFast; // the rows it left (all, where it declined the path)
  }
  if (method == AreaMethod::kFast) {
    if (swept < static_cast<std::size_t>(h)) {
      thread_local std::vector<std::uint8_t> left;
      left.assign(undecided.begin(), undecided.end());
      alpha_fast(b, path.fill_rule, w, h, out, undecided, swept > 0 ? &left : nullptr);
      if (rows != nullptr)
        rows->fast +=
            static_cast<std::size_t>(std::count(undecided.begin(), undecided.end(), 0)) - swept;
    }
    for (std::size_t j = 0; j < undecided.size(); ++j)
      if (undecided[j] != 0)
        std::fill_n(out.begin() + static_cast<std::ptrdiff_t>(j * stride), stride, std::uint8_t{0});
    if (std::find(undecided.begin(), undecided.end(), 1) == undecided.end())
      return;
  } else {
    std::fill(out.begin(), out.end(), std::uint8_t{0});
  }
  area_rows(
      b, path.contours.size(), path.fill_rule, w, h, method, rows,
      method == AreaMethod::kFast ? &undecided : nullptr,
      [&](std::int32_t j, const CellRows& cells) {
        std::uint8_t* row = out.data() + static_cast<std::size_t>(j) * stride;
        std::size_t k = 0;
        for (const CellArea& a : cells.results())
          row[a.col] = a.big ? alpha_of(cells.big()[k++]) : alpha_of(a.area);
      },
      [&](const AreaCoverage& a) {
        out[static_cast<std::size_t>(a.y) * stride + static_cast<std::size_t>(a.x)] =
            alpha_of(a.area);
      });
}

} // namespace detail

// rule: PATH.AREA.EXACT
void cover_area(const Path& path, std::int32_t w, std::int32_t h,
                const std::function<void(const AreaCoverage&)>& emit) {
  detail::cover_area_by(path, w, h, detail::AreaMethod::kCells, emit, nullptr);
}

// rule: PATH.AREA.ALPHA
void cover_area_alpha(const Path& path, std::int32_t w, std::int32_t h,
                      std::span<std::uint8_t> alpha) {
  // Paths of lines: the exact integer cells are faster than the certified doubles there
  // (2-3x on glyph flattenings); paths with curves: the fast cells (PATH.AREA.FAST) first.
  const bool curves = std::any_of(path.contours.begin(), path.contours.end(), [](const Contour& c) {
    return std::any_of(c.segments.begin(), c.segments.end(),
                       [](const Segment& g) { return g.kind != SegmentKind::kLine; });
  });
  detail::cover_alpha_by(
      path, w, h, curves ? detail::AreaMethod::kSweep : detail::AreaMethod::kCells, alpha, nullptr);
}

// rule: PATH.AREA.EXACT, PATH.AREA.CURVE, PATH.WINDING
PixelWindings winding_areas(const Path& path, std::int32_t x, std::int32_t y, std::int32_t w,
                            std::int32_t h) {
  if (w > kMaxTargetSide || h > kMaxTargetSide)
    throw std::invalid_argument(
        "path: area coverage of a target wider or taller than 16384 px (PATH.AREA.CELLS)");
  if (x < 0 || y < 0 || x >= w || y >= h)
    throw std::invalid_argument("path: a pixel outside the target (PATH.AREA.EXACT)");
  return detail::pixel_windings(detail::boundary_of(path), path.fill_rule, x, y, w, h);
}

// rule: PATH.AREA.EXACT
std::vector<AreaCoverage> cover_area(const Path& path, std::int32_t w, std::int32_t h) {
  std::vector<AreaCoverage> out;
  cover_area(path, w, h, [&](const AreaCoverage& a) { out.push_back(a); });
  return out;
}

} // namespace rastrules::path
