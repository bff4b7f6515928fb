// SPDX-License-Identifier: MIT
// 2D paths: the 8-bit alpha of area coverage by one certified sweep (spec/rules/path.md,
// PATH.AREA.SWEEP). The accumulation of FreeType's gray raster and font-rs, on the path's own
// lines and curves (no flattening): every monotone piece is walked cell by cell, its signed
// area and cover added to dense cells, and a row swept left to right. Every number's error has
// a bound fixed in advance per piece (not carried through each operation), a cell's chains are
// checked with a few bits, and the alpha of a cell is written only where that bound and those
// bits decide it; a doubtful crossing order, a curve not cut into certified pieces, a cell that
// may hold three winding numbers or a rounding the bound cannot decide leaves the rows it
// touches to PATH.AREA.FAST and the exact methods, and a path too large for dense cells is
// declined whole. So the alphas never depend on this rule; only the time does.
// Implements: PATH.AREA.SWEEP

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <span>
#include <vector>

#include "path_detail.hpp"

namespace rastrules::path::detail {
namespace {

constexpr std::int64_t kW = kSubpixelOne; // a pixel's side, raw
constexpr double kWd = static_cast<double>(kW);
constexpr double kU = 0x1p-53; // the unit roundoff of double
// Coordinates and targets the sweep takes: |raw| <= 2^23 (power coefficients below 2^27, their
// products below 2^58), cells w h <= 2^18 (dense arrays of a few MiB at most).
constexpr std::int64_t kMaxRaw = std::int64_t{1} << 23;
constexpr std::size_t kMaxCells = std::size_t{1} << 18;
// Covers are fixed point, 2^-kFix raw, so that a row's running sum is exact and a crossing
// point shared by two cells cancels exactly right of them.
constexpr int kFix = 20;
constexpr double kFixScale = 0x1p20;
// A split point (where x' or y' vanishes inside a curve) must lie this far (raw) from every
// grid line: far above the error of its parameter's effect (the piece may overshoot the
// extremum by |x''| tau^2 / 2 < 2^30 2^-100) and of its evaluation (< 2^-20 raw).
constexpr double kSplitMargin = 0x1p-10;

// floor(x) for |x| < 2^62 (coordinates, cells' integrals over 2^16, 510 times an alpha): the
// same double as std::floor, which the baseline instruction set (no SSE4.1) makes a call.
[[gnu::always_inline]] inline double floor_of(double x) {
  const auto t = static_cast<double>(static_cast<std::int64_t>(x));
  return t > x ? t - 1 : t;
}

// A line or curve in power form relative to its start (x0, y0): x(t) = x0 + sum ax[k] t^k,
// coefficients exact integers (raw) held as doubles; Q(t) = integral from 0 to t of
// (x(s) - x0) y'(s) ds, its coefficients rounded, with a bound qerr on |Q computed - Q| over
// [0, 1] (coefficient roundings and Horner's rule); xerr, yerr the same for x(t) - x0 and
// y(t) - y0; dx_max, dy_max bounds of |x'|, |y'| on [0, 1].
struct Shape {
  int n = 1;
  double x0 = 0, y0 = 0;
  std::array<double, 4> ax{}, ay{};
  std::array<double, 7> q{};
  double qerr = 0, xerr = 0, yerr = 0, dx_max = 0, dy_max = 0;

  [[nodiscard]] double x_at(double t) const { return ((ax[3] * t + ax[2]) * t + ax[1]) * t; }
  [[nodiscard]] double y_at(double t) const { return ((ay[3] * t + ay[2]) * t + ay[1]) * t; }
  [[nodiscard]] double dx_at(double t) const { return (3 * ax[3] * t + 2 * ax[2]) * t + ax[1]; }
  [[nodiscard]] double dy_at(double t) const { return (3 * ay[3] * t + 2 * ay[2]) * t + ay[1]; }
  [[nodiscard]] double q_at(double t) const {
    return ((((q[6] * t + q[5]) * t + q[4]) * t + q[3]) * t + q[2]) * t * t;
  }
};

// A point of the boundary: raw coordinates, the cover coordinate in fixed point, and the
// bound on its distance from the true point along the grid line it lies on (0: exact).
struct Pt {
  double x = 0, y = 0;
  std::int64_t yfix = 0;
  double err = 0;
};

// A box (raw), the end points of a piece's visit to a cell widened by their bounds: a monotone
// piece's part between two of its points lies in their box.
struct Box {
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  void add(const Box& b) {
    x0 = std::min(x0, b.x0);
    x1 = std::max(x1, b.x1);
    y0 = std::min(y0, b.y0);
    y1 = std::max(y1, b.y1);
  }
};
[[gnu::always_inline]] inline Box box_of(const Pt& a, const Pt& b) {
  const double e = std::max(a.err, b.err);
  return Box{std::min(a.x, b.x) - e, std::max(a.x, b.x) + e, std::min(a.y, b.y) - e,
             std::max(a.y, b.y) + e};
}

// A cell: the integral of (x - left) dy of its visits (raw^2), their cover (fixed point), the
// sum of their bounds; the first piece of the first run of consecutive pieces and the last
// piece seen, the directions of all its visits (bit 0: x grows, 1: x falls, 2: y grows, 3: y
// falls), the first visit's flags (below), how many visits (up to 255), the first visit's box,
// and the visits' list in seen_ once there are two (first and last index + 1). How many runs it
// holds (0 to 3: more) is kept apart (runs_), so that only that byte is cleared a path.
struct Cell {
  double area = 0, err = 0;
  std::int64_t cover = 0;
  std::uint32_t head = 0, tail = 0;
  std::uint8_t dirs = 0, count = 0;
  std::uint16_t flags0 = 0;
  std::uint32_t first = 0, last = 0;
  Box box0;
};

// A visit in a cell's list: its piece, directions and flags (as Cell's), box, and the next
// (index + 1 in Sweep::seen_, 0 for none).
struct Seen {
  std::uint32_t id = 0;
  std::uint16_t flags = 0;
  Box box;
  std::uint32_t next = 0;
};

// A visit's flags beside its directions (bits 0-3): it starts at its piece's start, it ends at
// its end, it runs along a grid line (a side of the cell); the sides of the cell its start
// lies on (bits 8-11) and its end (bits 12-15).
constexpr int kStarts = 16, kEnds = 32, kAlong = 64;
// A cell's sides (for the ends of a visit).
constexpr int kTop = 1, kRight = 2, kBottom = 4, kLeft = 8;
constexpr int start_sides(int flags) {
  return (flags >> 8) & 15;
}
constexpr int end_sides(int flags) {
  return (flags >> 12) & 15;
}

// PieceRef::shape of a line (lines have no Shape).
constexpr std::uint32_t kLine = 0xFFFFFFFFu;

struct PieceRef {
  std::uint32_t shape = 0, id = 0; // its shape (kLine: none), and its id (Sweep::contours_)
  double t0 = 0, t1 = 1;
  Pt a, b;
  int sx = 0, sy = 0;
};

class Sweep {
public:
  bool run(const Boundary& b, FillRule rule, std::int32_t w, std::int32_t h,
           std::span<std::uint8_t> out, std::vector<std::uint8_t>& undecided);

private:
  bool build(const Boundary& b);
  bool add_curve_pieces(std::uint32_t si, std::uint32_t& id);
  void walk_flat(const Pt& a, const Pt& b, std::uint32_t id, int dirs);
  bool walk_line(std::uint32_t id, const Pt& a, const Pt& b, int sx, int sy);
  bool walk_curve(const PieceRef& p, std::uint32_t id);
  // The root of x(t) = target (in_x) or y(t) = target on [lo, hi], where the coordinate runs
  // with sign sgn and crosses target strictly inside; a certified bracket [blo, bhi] and t.
  // f_lo, f_hi: the coordinate less target near lo and at hi (a start for the steps).
  bool root(const Shape& s, bool in_x, int sgn, double target, double lo, double hi, double f_lo,
            double f_hi, double& t, double& blo, double& bhi) const;
  void visit(std::int64_t row, std::int64_t col, std::uint32_t id, int dirs, double area,
             std::int64_t cover, double err, const Box& box);
  void touch(std::int64_t row, std::int64_t col, std::uint32_t id, int dirs, const Box& box);
  bool record(std::int64_t row, std::int64_t col, std::uint32_t id, int dirs, bool first, bool last,
              int sides, double area, double err, const Pt& a, const Pt& n, bool on_col);
  bool two_windings(const Cell& c, std::uint8_t runs) const;
  // Whether pieces p and q, joined (p ends where q starts), meet nowhere else however sharply
  // they turn: one is a line and the other's shape has all its control points but the joint
  // strictly on one side of that line (its convex hull holds it).
  bool turn_apart(std::uint32_t p, std::uint32_t q) const;
  void sweep(std::span<std::uint8_t> out);
  bool sweep_row(std::size_t r, std::uint8_t* row) const;
  // Leaves the rows from raw height y0 to y1 (and one more each way) to the other methods.
  void doubt(double y0, double y1);

  FillRule rule_ = FillRule::kNonZero;
  std::int32_t w_ = 0, h_ = 0;
  std::size_t stride_ = 0;
  std::vector<SegmentRef> refs_;
  std::vector<Shape> shapes_;
  std::vector<PieceRef> pieces_;
  // Per contour: the ids of its first and last pieces (ids run on within a contour and skip
  // one between contours, so that consecutive ids mean consecutive pieces of one contour).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> contours_;
  std::vector<Cell> cells_;
  std::vector<Seen> seen_;
  std::vector<std::uint8_t> runs_;
  std::vector<std::int64_t> left_cover_; // a row's cover left of the target
  std::uint8_t* doubted_ = nullptr;      // a byte a row: 1 where the sweep does not decide it
};

// rule: PATH.AREA.SWEEP
void Sweep::doubt(double y0, double y1) {
  const double lo = std::max(floor_of(std::min(y0, y1) * (1 / kWd)) - 1, 0.0);
  const double hi = std::min(floor_of(std::max(y0, y1) * (1 / kWd)) + 1, h_ - 1.0);
  for (double j = lo; j <= hi; ++j)
    doubted_[static_cast<std::size_t>(j)] = 1;
}

// rule: PATH.AREA.SWEEP
// A walk's visit from a to n (the piece's first, its last; sides: the cell's sides a and n lie
// on, n's shifted by 4), and on a column line its touch of the cell left of it; true where it
// was the piece's last.
bool Sweep::record(std::int64_t row, std::int64_t col, std::uint32_t id, int dirs, bool first,
                   bool last, int sides, double area, double err, const Pt& a, const Pt& n,
                   bool on_col) {
  const Box box = box_of(a, n);
  const int flags =
      dirs | (first ? kStarts : 0) | (last ? kEnds : 0) | (on_col ? kAlong : 0) | (sides << 8);
  visit(row, col, id, flags, area, n.yfix - a.yfix, err, box);
  if (on_col)
    touch(row, col - 1, id, flags, box);
  return last;
}

void Sweep::touch(std::int64_t row, std::int64_t col, std::uint32_t id, int dirs, const Box& box) {
  visit(row, col, id, dirs, 0, 0, 0, box);
}

// rule: PATH.AREA.SWEEP
void Sweep::visit(std::int64_t row, std::int64_t col, std::uint32_t id, int dirs, double area,
                  std::int64_t cover, double err, const Box& box) {
  if (row < 0 || row >= h_ || col >= w_)
    return; // right of the target: no cell left of it depends on it
  const auto r = static_cast<std::size_t>(row);
  if (col < 0) {
    left_cover_[r] += cover; // left of the target: its cover alone
    return;
  }
  const std::size_t i = r * stride_ + static_cast<std::size_t>(col);
  Cell& c = cells_[i];
  std::uint8_t& runs = runs_[i];
  if (runs == 0) {
    c = Cell{area,  err,
             cover, id,
             id,    static_cast<std::uint8_t>(dirs & 15),
             1,     static_cast<std::uint16_t>(dirs),
             0,     0,
             box};
    runs = 1;
    return;
  }
  c.area += area;
  c.cover += cover;
  c.err += err;
  c.dirs = static_cast<std::uint8_t>(c.dirs | (dirs & 15));
  // The list of visits, for cells where more than the directions must be looked at.
  if (c.count == 1) {
    seen_.push_back(Seen{c.head, c.flags0, c.box0, 0});
    c.first = c.last = static_cast<std::uint32_t>(seen_.size());
  }
  if (c.count < 255) {
    seen_.push_back(Seen{id, static_cast<std::uint16_t>(dirs), box, 0});
    seen_[c.last - 1].next = static_cast<std::uint32_t>(seen_.size());
    c.last = static_cast<std::uint32_t>(seen_.size());
    ++c.count;
  }
  if (id != c.tail + 1)
    runs = static_cast<std::uint8_t>(std::min(runs + 1, 3));
  c.tail = id;
}

int dirs_of(int sx, int sy) {
  return (sx > 0 ? 1 : 0) | (sx < 0 ? 2 : 0) | (sy > 0 ? 4 : 0) | (sy < 0 ? 8 : 0);
}

// y in fixed point, truncated (any rounding will do: the same point gives the same value, and
// its error, below 2^-kFix raw, is in the point's bound).
std::int64_t fix_of(double y) {
  return static_cast<std::int64_t>(y * kFixScale);
}

// An end point with integer coordinates (raw): exact, its cover coordinate too.
Pt exact_point(double x, double y) {
  return Pt{x, y, static_cast<std::int64_t>(y) << kFix, 0};
}

// The sides of cell (row, col) that an exact point lies on (none for a point with a bound: the
// walk knows which line such a point lies on).
int sides_of(const Pt& p, std::int64_t row, std::int64_t col) {
  if (p.err != 0)
    return 0;
  const auto l = static_cast<double>(col * kW), t = static_cast<double>(row * kW);
  return (p.x == l ? kLeft : 0) | (p.x == l + kWd ? kRight : 0) | (p.y == t ? kTop : 0) |
         (p.y == t + kWd ? kBottom : 0);
}

// The sides a walk leaves a cell by (stepping in x with sign sx, in y with sy), or enters the
// next by (entering).
int step_sides(bool step_x, bool step_y, int sx, int sy, bool entering) {
  const int x = step_x ? ((sx > 0) != entering ? kRight : kLeft) : 0;
  const int y = step_y ? ((sy > 0) != entering ? kBottom : kTop) : 0;
  return x | y;
}

// The cell of coordinate v moving with sign s: on a grid line, the cell it moves into.
std::int64_t cell_of(double v, int s) {
  const double f = floor_of(v * (1 / kWd));
  if (f * kWd == v && s < 0)
    return static_cast<std::int64_t>(f) - 1;
  return static_cast<std::int64_t>(f);
}

// The column a piece starts in from x, moving with sign sx; on_col: it runs along that column's
// left line (sx == 0 on a grid line), so the cell left of it holds it too.
std::int64_t start_col(double x, int sx, bool& on_col) {
  const std::int64_t col = cell_of(x, sx);
  on_col = sx == 0 && x == static_cast<double>(col * kW);
  return col;
}

// rule: PATH.AREA.SWEEP
// A piece along which y is constant: no area and no cover, but its cells hold it for their
// chains (on a row line, the cells on both sides).
void Sweep::walk_flat(const Pt& a, const Pt& b, std::uint32_t id, int dirs) {
  const double e = std::max(a.err, b.err);
  const double xl = std::min(a.x, b.x), xr = std::max(a.x, b.x);
  const auto row = static_cast<std::int64_t>(floor_of(a.y * (1 / kWd)));
  const bool on_line = e == 0 && a.y == static_cast<double>(row * kW);
  const std::int64_t c0 = cell_of(xl, 1), c1 = cell_of(xr, -1);
  // The cells of a's and b's ends (c0 holds the left one).
  const bool a_left = a.x <= b.x;
  for (std::int64_t c = std::max<std::int64_t>(c0, 0); c <= std::min<std::int64_t>(c1, w_ - 1);
       ++c) {
    const auto left = static_cast<double>(c * kW);
    const Box box{std::max(xl, left) - e, std::min(xr, left + kWd) + e, a.y - e, a.y + e};
    const bool starts = c == (a_left ? c0 : c1), ends = c == (a_left ? c1 : c0);
    // Between its cells it crosses column lines (left to right where a is left of b).
    const int in = starts ? sides_of(a, row, c) : (a_left ? kLeft : kRight);
    const int out = ends ? sides_of(b, row, c) : (a_left ? kRight : kLeft);
    const int flags = dirs | (starts ? kStarts : 0) | (ends ? kEnds : 0) | (on_line ? kAlong : 0) |
                      (in << 8) | (out << 12);
    touch(row, c, id, flags, box);
    if (on_line)
      touch(row - 1, c, id, flags, box);
  }
}

// rule: PATH.AREA.SWEEP
// A line from a to b (exact integer end points), walked with exact integer tests for which
// grid line comes first; crossing coordinates are one division each, within 2 u of their
// magnitude.
bool Sweep::walk_line(std::uint32_t id, const Pt& a, const Pt& b, int sx, int sy) {
  const auto x0 = static_cast<std::int64_t>(a.x), y0 = static_cast<std::int64_t>(a.y);
  const auto x1 = static_cast<std::int64_t>(b.x), y1 = static_cast<std::int64_t>(b.y);
  const std::int64_t dx = x1 - x0, dy = y1 - y0;
  const int dirs = dirs_of(sx, sy);
  // Axis-parallel lines are exact throughout.
  const double ep =
      (dx == 0 || dy == 0) ? 0.0 : 4 * kU * static_cast<double>(kMaxRaw) + 1 / kFixScale;
  if (sy == 0) {
    walk_flat(a, b, id, dirs);
    return true;
  }
  std::int64_t row = cell_of(a.y, sy);
  bool on_col = false;
  std::int64_t col = start_col(a.x, sx, on_col);
  Pt p = a;
  int in = sides_of(a, row, col);
  for (int guard = 0; guard < 4 * (w_ + h_) + 64; ++guard) {
    const std::int64_t X = sx > 0 ? (col + 1) * kW : col * kW;
    const std::int64_t Y = sy > 0 ? (row + 1) * kW : row * kW;
    const bool reach_x = sx != 0 && (sx > 0 ? x1 > X : x1 < X);
    const bool reach_y = sy > 0 ? y1 > Y : y1 < Y;
    Pt n = b;
    bool step_x = false, step_y = false;
    if (reach_x || reach_y) {
      if (reach_x && reach_y) {
        // |X - x0| |dy| against |Y - y0| |dx|: which line the segment meets first.
        const std::int64_t kx = std::abs(X - x0) * std::abs(dy);
        const std::int64_t ky = std::abs(Y - y0) * std::abs(dx);
        step_x = kx <= ky;
        step_y = ky <= kx;
      } else {
        step_x = reach_x;
        step_y = reach_y;
      }
      if (step_x && step_y) {
        n = Pt{static_cast<double>(X), static_cast<double>(Y), Y << kFix, 0};
      } else if (step_x) {
        const double yn =
            static_cast<double>(y0) + static_cast<double>((X - x0) * dy) / static_cast<double>(dx);
        n = Pt{static_cast<double>(X), yn, fix_of(yn), ep};
      } else {
        const double xn =
            static_cast<double>(x0) + static_cast<double>((Y - y0) * dx) / static_cast<double>(dy);
        n = Pt{xn, static_cast<double>(Y), Y << kFix, ep};
      }
    }
    const double left = static_cast<double>(col * kW);
    const double area = 0.5 * ((p.x - left) + (n.x - left)) * (n.y - p.y);
    const double err =
        p.err == 0 && n.err == 0
            ? 0.0
            : 2048 * (p.err + n.err) + 8 * kU * (std::abs(area) + kWd * std::abs(n.y - p.y));
    const bool last = !step_x && !step_y;
    const int out = last ? sides_of(n, row, col) : step_sides(step_x, step_y, sx, sy, false);
    if (record(row, col, id, dirs, guard == 0, last, in | (out << 4), area, err, p, n, on_col))
      return true;
    p = n;
    in = step_sides(step_x, step_y, sx, sy, true);
    if (step_x)
      col += sx;
    if (step_y)
      row += sy;
  }
  return false;
}

// rule: PATH.AREA.SWEEP
bool Sweep::root(const Shape& s, bool in_x, int sgn, double target, double lo, double hi,
                 double f_lo, double f_hi, double& t, double& blo, double& bhi) const {
  const std::array<double, 4>& c = in_x ? s.ax : s.ay;
  const auto f = [&](double u) { return ((c[3] * u + c[2]) * u + c[1]) * u - target; };
  const double ferr = (in_x ? s.xerr : s.yerr) + kU * std::abs(target);
  t = -1;
  if (s.n == 2 && c[2] != 0) {
    // The quadratic formula (the root in [lo, hi]); the bracket below certifies it.
    const double disc = c[1] * c[1] + 4 * c[2] * target;
    if (disc >= 0) {
      const double sq = std::sqrt(disc);
      const double qv = -0.5 * (c[1] + (c[1] >= 0 ? sq : -sq));
      const double r1 = qv / c[2], r2 = qv != 0 ? -target / qv : r1;
      const double slack = 0x1p-30;
      if (r1 >= lo - slack && r1 <= hi + slack)
        t = std::clamp(r1, lo, hi);
      else if (r2 >= lo - slack && r2 <= hi + slack)
        t = std::clamp(r2, lo, hi);
    }
  }
  if (t < 0) {
    // Safeguarded Newton steps from a Newton step at lo (the crossing is usually within a
    // pixel of the walk's point there), else the secant's point; [a, b] keeps the sign change.
    double a = lo, b = hi;
    const double d_lo = (3 * c[3] * lo + 2 * c[2]) * lo + c[1];
    t = d_lo != 0 ? lo - f_lo / d_lo : -1;
    if (!(t > a && t < b))
      t = f_lo == f_hi ? 0.5 * (a + b) : a + (b - a) * (f_lo / (f_lo - f_hi));
    if (!(t > a && t < b))
      t = 0.5 * (a + b);
    for (int it = 0; it < 30; ++it) {
      const double ft = f(t);
      if (std::abs(ft) <= 2 * ferr)
        break;
      if (ft * sgn < 0)
        a = t;
      else
        b = t;
      const double d = (3 * c[3] * t + 2 * c[2]) * t + c[1];
      double next = d != 0 ? t - ft / d : 0.5 * (a + b);
      if (!(next > a && next < b))
        next = 0.5 * (a + b);
      const double step = std::abs(next - t);
      t = next;
      // A Newton step of 2^-26 leaves t within about 2^-50 of the root (quadratic
      // convergence); the bracket below checks it either way.
      if (step <= 0x1p-26)
        break;
    }
  }
  // A bracket whose ends have certified signs: f(blo) sgn < 0 < f(bhi) sgn, or an end of
  // [lo, hi] (whose sign the caller knows).
  for (double d = 0x1p-44; d <= 0x1p-20; d *= 64) {
    blo = t - d;
    bhi = t + d;
    bool ok_lo = true, ok_hi = true;
    if (blo <= lo)
      blo = lo;
    else
      ok_lo = f(blo) * sgn < -ferr;
    if (bhi >= hi)
      bhi = hi;
    else
      ok_hi = f(bhi) * sgn > ferr;
    if (ok_lo && ok_hi)
      return true;
  }
  return false;
}

// rule: PATH.AREA.SWEEP
// A monotone curve piece from p.a to p.b: at each step the next column and row lines it
// reaches, their crossings' certified brackets (apart, or the path is declined), the visit's
// area Q(t_b) - Q(t_a) + (x0 - left)(y(t_b) - y(t_a)) and its cover.
bool Sweep::walk_curve(const PieceRef& p, std::uint32_t id) {
  const Shape& s = shapes_[p.shape];
  const int sx = p.sx, sy = p.sy;
  const int dirs = dirs_of(sx, sy);
  if (sy == 0) {
    walk_flat(p.a, p.b, id, dirs); // y constant: a horizontal curve
    return true;
  }
  std::int64_t row = cell_of(p.a.y, sy);
  bool on_col = false;
  std::int64_t col = start_col(p.a.x, sx, on_col);
  Pt a = p.a;
  int in = sides_of(a, row, col);
  double ta = p.t0, ta_lo = p.t0;
  double qa = s.q_at(ta), ya = s.y_at(ta);
  // A crossing's point moves at most this far (raw, in x and in y) over its bracket.
  const double span = s.dx_max + s.dy_max;
  std::int64_t x_line = std::numeric_limits<std::int64_t>::min(), y_line = x_line;
  double txt = 0, txl = 0, txh = 0, tyt = 0, tyl = 0, tyh = 0;
  for (int guard = 0; guard < 4 * (w_ + h_) + 64; ++guard) {
    const std::int64_t X = sx > 0 ? (col + 1) * kW : col * kW;
    const std::int64_t Y = sy > 0 ? (row + 1) * kW : row * kW;
    const auto Xd = static_cast<double>(X), Yd = static_cast<double>(Y);
    const bool reach_x = sx != 0 && (sx > 0 ? p.b.x > Xd : p.b.x < Xd);
    const bool reach_y = sy > 0 ? p.b.y > Yd : p.b.y < Yd;
    Pt n = p.b;
    double tn = p.t1, tn_lo = p.t1;
    bool step_x = false, step_y = false;
    if (reach_x || reach_y) {
      // A crossing found but not taken stays valid while its line is still the next one.
      // A crossing without a certified bracket, or two that may coincide (near a grid
      // corner): the cells of the rest of the piece are not known, so the rows it spans
      // from here are left (the rows before hold all of its visits there).
      if (reach_x && X != x_line) {
        if (!root(s, true, sx, Xd - s.x0, ta_lo, p.t1, a.x - Xd, p.b.x - Xd, txt, txl, txh)) {
          doubt(a.y, p.b.y);
          return true;
        }
        x_line = X;
      }
      if (reach_y && Y != y_line) {
        if (!root(s, false, sy, Yd - s.y0, ta_lo, p.t1, a.y - Yd, p.b.y - Yd, tyt, tyl, tyh)) {
          doubt(a.y, p.b.y);
          return true;
        }
        y_line = Y;
      }
      if (reach_x && reach_y) {
        if (txh < tyl) {
          step_x = true;
        } else if (tyh < txl) {
          step_y = true;
        } else {
          doubt(a.y, p.b.y);
          return true;
        }
      } else {
        step_x = reach_x;
        step_y = reach_y;
      }
      if (step_x) {
        tn = txt;
        tn_lo = txl;
        const double yv = s.y0 + s.y_at(tn);
        n = Pt{Xd, yv, fix_of(yv), span * (txh - txl) + s.xerr + s.yerr + 1 / kFixScale};
      } else {
        tn = tyt;
        tn_lo = tyl;
        n = Pt{s.x0 + s.x_at(tn), Yd, Y << kFix,
               span * (tyh - tyl) + s.xerr + s.yerr + 1 / kFixScale};
      }
    }
    const double left = static_cast<double>(col * kW);
    const double qb = s.q_at(tn);
    const double yb = s.y_at(tn);
    const double dyv = yb - ya;
    const double area = (qb - qa) + (s.x0 - left) * dyv;
    const double err =
        2 * s.qerr + (std::abs(s.x0 - left) + 4 * kWd) * 2 * (s.yerr + a.err + n.err) +
        2048 * (a.err + n.err) +
        8 * kU * (std::abs(area) + std::abs(qb) + std::abs(qa) + kWd * std::abs(dyv));
    const bool last = !step_x && !step_y;
    const int out = last ? sides_of(n, row, col) : step_sides(step_x, step_y, sx, sy, false);
    if (record(row, col, id, dirs, guard == 0, last, in | (out << 4), area, err, a, n, on_col))
      return true;
    in = step_sides(step_x, step_y, sx, sy, true);
    a = n;
    ta = tn;
    ta_lo = tn_lo;
    qa = qb;
    ya = yb;
    if (step_x)
      col += sx;
    if (step_y)
      row += sy;
  }
  return false;
}

// Roots of c0 + c1 t + c2 t^2 strictly inside (0, 1), ascending; false where two roots may be
// too close to tell (a discriminant near 0).
bool roots_inside(double c0, double c1, double c2, std::array<double, 2>& r, int& n) {
  n = 0;
  if (c2 == 0) {
    if (c1 != 0) {
      const double t = -c0 / c1;
      if (t > 0 && t < 1)
        r[static_cast<std::size_t>(n++)] = t;
    }
    return true;
  }
  const double disc = c1 * c1 - 4 * c2 * c0;
  const double scale = c1 * c1 + std::abs(4 * c2 * c0);
  if (std::abs(disc) <= 0x1p-30 * scale)
    return false;
  if (disc < 0)
    return true;
  const double sq = std::sqrt(disc);
  const double qv = -0.5 * (c1 + (c1 >= 0 ? sq : -sq));
  double t1 = qv / c2, t2 = qv != 0 ? c0 / qv : t1;
  if (t1 > t2)
    std::swap(t1, t2);
  for (const double t : {t1, t2})
    if (t > 0 && t < 1)
      r[static_cast<std::size_t>(n++)] = t;
  return true;
}

// Whether v lies within kSplitMargin of a grid line.
bool near_line(double v) {
  const double m = v - kWd * floor_of(v * (1 / kWd));
  return m < kSplitMargin || kWd - m < kSplitMargin;
}

int sign_of(double v) {
  return v > 0 ? 1 : (v < 0 ? -1 : 0);
}

// rule: PATH.AREA.SWEEP
bool Sweep::add_curve_pieces(std::uint32_t si, std::uint32_t& id) {
  const Shape& s = shapes_[si];
  std::array<double, 6> cuts{};
  int nc = 0;
  cuts[static_cast<std::size_t>(nc++)] = 0;
  for (const bool in_x : {true, false}) {
    const std::array<double, 4>& c = in_x ? s.ax : s.ay;
    std::array<double, 2> r{};
    int n = 0;
    if (!roots_inside(c[1], 2 * c[2], 3 * c[3], r, n))
      return false;
    for (int k = 0; k < n; ++k)
      cuts[static_cast<std::size_t>(nc++)] = r[static_cast<std::size_t>(k)];
  }
  cuts[static_cast<std::size_t>(nc++)] = 1;
  for (int k = 1; k < nc; ++k) // at most six cuts: insertion
    for (int m = k;
         m > 0 && cuts[static_cast<std::size_t>(m)] < cuts[static_cast<std::size_t>(m - 1)]; --m)
      std::swap(cuts[static_cast<std::size_t>(m)], cuts[static_cast<std::size_t>(m - 1)]);
  Pt a = exact_point(s.x0, s.y0);
  for (int k = 0; k + 1 < nc; ++k) {
    const double t0 = cuts[static_cast<std::size_t>(k)], t1 = cuts[static_cast<std::size_t>(k + 1)];
    if (!(t1 > t0))
      continue;
    Pt b;
    if (t1 == 1) {
      b = exact_point(s.x0 + s.ax[1] + s.ax[2] + s.ax[3], s.y0 + s.ay[1] + s.ay[2] + s.ay[3]);
    } else {
      const double bx = s.x0 + s.x_at(t1), by = s.y0 + s.y_at(t1);
      if (near_line(bx) || near_line(by))
        return false;
      b = Pt{bx, by, fix_of(by), s.xerr + s.yerr + 1 / kFixScale};
    }
    PieceRef p;
    p.shape = si;
    p.t0 = t0;
    p.t1 = t1;
    p.a = a;
    p.b = b;
    // Directions from the end points (the piece is monotone), which the derivative at the
    // middle must confirm; 0 only where the coordinate is constant on the whole curve.
    const double tm = 0.5 * (t0 + t1);
    const bool x_flat = s.ax[1] == 0 && s.ax[2] == 0 && s.ax[3] == 0;
    const bool y_flat = s.ay[1] == 0 && s.ay[2] == 0 && s.ay[3] == 0;
    p.sx = x_flat ? 0 : sign_of(b.x - a.x);
    p.sy = y_flat ? 0 : sign_of(b.y - a.y);
    if ((!x_flat && (p.sx == 0 || sign_of(s.dx_at(tm)) != p.sx)) ||
        (!y_flat && (p.sy == 0 || sign_of(s.dy_at(tm)) != p.sy)))
      return false;
    p.id = id++;
    pieces_.push_back(p);
    a = b;
  }
  return true;
}

// rule: PATH.AREA.SWEEP
bool Sweep::build(const Boundary& b) {
  std::vector<SegmentRef>& refs = refs_;
  segments_in_order(b, refs);
  std::uint32_t id = 0;
  std::size_t current = static_cast<std::size_t>(-1);
  for (const SegmentRef& r : refs) {
    std::array<Point, 4> cp{};
    const int degree = control_points(b, r, cp);
    for (int k = 0; k <= degree; ++k) {
      const Point& q = cp[static_cast<std::size_t>(k)];
      if (std::abs(std::int64_t{q.x}) > kMaxRaw || std::abs(std::int64_t{q.y}) > kMaxRaw)
        return false;
    }
    if (r.contour != current) {
      if (current != static_cast<std::size_t>(-1))
        ++id; // a gap between contours
      current = r.contour;
      contours_.push_back({id, id});
    }
    if (degree == 1) { // a line: its exact end points are all its walk needs
      if (cp[0] == cp[1])
        continue; // a point (PATH.DEGENERATE)
      PieceRef p;
      p.shape = kLine;
      p.a = exact_point(cp[0].x, cp[0].y);
      p.b = exact_point(cp[1].x, cp[1].y);
      p.sx = sign_of(cp[1].x - cp[0].x);
      p.sy = sign_of(cp[1].y - cp[0].y);
      p.id = id++;
      pieces_.push_back(p);
      contours_.back().second = id - 1;
      continue;
    }
    const auto si = static_cast<std::uint32_t>(shapes_.size());
    Shape& s = shapes_.emplace_back();
    s.n = degree;
    s.x0 = cp[0].x;
    s.y0 = cp[0].y;
    const auto power = [&](auto get) {
      const double p0 = get(cp[0]), p1 = get(cp[1]), p2 = get(cp[2]), p3 = get(cp[3]);
      if (degree == 1)
        return std::array<double, 4>{0, p1 - p0, 0, 0};
      if (degree == 2)
        return std::array<double, 4>{0, 2 * (p1 - p0), p0 - 2 * p1 + p2, 0};
      return std::array<double, 4>{0, 3 * (p1 - p0), 3 * (p0 - 2 * p1 + p2),
                                   p3 - 3 * p2 + 3 * p1 - p0};
    };
    s.ax = power([](Point q) { return static_cast<double>(q.x); });
    s.ay = power([](Point q) { return static_cast<double>(q.y); });
    if (s.ax[1] == 0 && s.ax[2] == 0 && s.ax[3] == 0 && s.ay[1] == 0 && s.ay[2] == 0 &&
        s.ay[3] == 0) {
      shapes_.pop_back();
      continue; // a point (PATH.DEGENERATE)
    }
    // Bounds over [0, 1]: sums of |coefficients| (|t|^k <= 1); Horner's rule on degree m
    // within gamma(2m) of that sum; Q's coefficients M_k / k with M_k exact in 64 bits
    // (|M_k| < 2^58), rounded twice.
    double sx_abs = 0, sy_abs = 0;
    for (int k = 1; k <= 3; ++k) {
      sx_abs += std::abs(s.ax[static_cast<std::size_t>(k)]);
      sy_abs += std::abs(s.ay[static_cast<std::size_t>(k)]);
      s.dx_max += k * std::abs(s.ax[static_cast<std::size_t>(k)]);
      s.dy_max += k * std::abs(s.ay[static_cast<std::size_t>(k)]);
    }
    s.xerr = 8 * kU * sx_abs;
    s.yerr = 8 * kU * sy_abs;
    double q_abs = 0;
    for (int k = 2; k <= 2 * degree; ++k) {
      std::int64_t mk = 0;
      for (int i = std::max(1, k - degree); i <= std::min(degree, k - 1); ++i) {
        const int j = k - i;
        mk += static_cast<std::int64_t>(s.ax[static_cast<std::size_t>(i)]) * j *
              static_cast<std::int64_t>(s.ay[static_cast<std::size_t>(j)]);
      }
      s.q[static_cast<std::size_t>(k)] = static_cast<double>(mk) / k;
      q_abs += std::abs(s.q[static_cast<std::size_t>(k)]);
    }
    s.qerr = 32 * kU * q_abs;
    const std::size_t first_piece = pieces_.size();
    if (!add_curve_pieces(si, id)) {
      // A curve not cut into certified monotone pieces (extrema too close to tell, or near a
      // grid line): the rows of its control points' box are not the sweep's, and the curve
      // is left out (an id apart: no piece is joined to it).
      pieces_.resize(first_piece);
      ++id;
      const auto [y_lo, y_hi] = control_y_range(cp, degree);
      doubt(y_lo, y_hi);
    }
    contours_.back().second = id - 1;
  }
  return true;
}

// Whether the pieces of directions d are monotone in x or in y (bits as Cell's): then their
// chain does not cross itself.
bool monotone(int d) {
  return (d & 3) != 3 || (d & 12) != 12;
}

bool apart(const Box& p, const Box& q) {
  return p.x1 < q.x0 || q.x1 < p.x0 || p.y1 < q.y0 || q.y1 < p.y0;
}

// An arc of a cell: its box, directions, and the sides its start and its end lie on.
struct ArcInfo {
  Box box;
  int dirs = 0, start = 0, end = 0;
};

// The side of arc a holding arc b, whose box is apart from a's: +1 the side of the higher
// winding number, -1 the lower, 0 not known. a is monotone in x or in y (a graph over that
// coordinate, vertical or horizontal pieces as jumps) with both ends on the cell's border, so it
// cuts the cell into two sides. Monotone in x with sense sx: below it (greater y) the winding is
// higher by sx (crossing a curve moving in +x downwards adds one); what lies above a's box is
// above it and what lies below is below; what lies left of its box is below it where the end
// at its least x lies on the top side (the region beside that end reaches under the arc) and
// above where it lies on the bottom side, and likewise right of it with the end at its greatest
// x. Monotone in y with sense sy the same with x and y exchanged: right of it the winding is
// lower by sy.
// rule: PATH.AREA.SWEEP
int side_of(const ArcInfo& a, const Box& b) {
  const auto pick = [](int sides, int near, int far, int sign) {
    if ((sides & near) != 0 && (sides & far) == 0)
      return sign;
    if ((sides & far) != 0 && (sides & near) == 0)
      return -sign;
    return 0;
  };
  if ((a.dirs & 3) != 3 && (a.dirs & 3) != 0) {
    const int sx = (a.dirs & 1) != 0 ? 1 : -1;
    const int lo_end = sx > 0 ? a.start : a.end, hi_end = sx > 0 ? a.end : a.start;
    if (b.y1 < a.box.y0)
      return -sx;
    if (b.y0 > a.box.y1)
      return sx;
    if (b.x1 < a.box.x0)
      return pick(lo_end, kTop, kBottom, sx);
    if (b.x0 > a.box.x1)
      return pick(hi_end, kTop, kBottom, sx);
    return 0;
  }
  if ((a.dirs & 12) != 12 && (a.dirs & 12) != 0) {
    const int sy = (a.dirs & 4) != 0 ? 1 : -1;
    const int lo_end = sy > 0 ? a.start : a.end, hi_end = sy > 0 ? a.end : a.start;
    if (b.x1 < a.box.x0)
      return sy;
    if (b.x0 > a.box.x1)
      return -sy;
    if (b.y1 < a.box.y0)
      return pick(lo_end, kLeft, kRight, -sy);
    if (b.y0 > a.box.y1)
      return pick(hi_end, kLeft, kRight, -sy);
  }
  return 0;
}

// rule: PATH.AREA.SWEEP
bool Sweep::turn_apart(std::uint32_t p, std::uint32_t q) const {
  const auto find = [&](std::uint32_t id) {
    const auto it = std::lower_bound(pieces_.begin(), pieces_.end(), id,
                                     [](const PieceRef& r, std::uint32_t x) { return r.id < x; });
    return it != pieces_.end() && it->id == id ? &*it : nullptr;
  };
  const PieceRef* a = find(p);
  const PieceRef* b = find(q);
  if (a == nullptr || b == nullptr)
    return false;
  // The line (from the joint J along d) and the other piece, whose shape ends at J.
  const bool a_line = a->shape == kLine;
  if (!a_line && b->shape != kLine)
    return false;
  const PieceRef& line = a_line ? *a : *b;
  const PieceRef& other = a_line ? *b : *a;
  const double jx = a->b.x, jy = a->b.y; // exact: a shape's end
  const double dx = (a_line ? line.a.x : line.b.x) - jx, dy = (a_line ? line.a.y : line.b.y) - jy;
  // 3 (P_k - J) for the other shape's control points, from its power form (exact integers
  // below 2^27; the cross products below 2^53).
  std::array<std::array<double, 2>, 4> cp{};
  int n = 1;
  if (other.shape == kLine) {
    cp[0] = {3 * other.a.x, 3 * other.a.y};
    cp[1] = {3 * other.b.x, 3 * other.b.y};
  } else {
    const Shape& s = shapes_[other.shape];
    n = s.n;
    const double x0 = 3 * s.x0, y0 = 3 * s.y0;
    if (n == 2) {
      cp[0] = {x0, y0};
      cp[1] = {x0 + 1.5 * s.ax[1], y0 + 1.5 * s.ay[1]};
      cp[2] = {x0 + 3 * (s.ax[1] + s.ax[2]), y0 + 3 * (s.ay[1] + s.ay[2])};
    } else {
      cp[0] = {x0, y0};
      cp[1] = {x0 + s.ax[1], y0 + s.ay[1]};
      cp[2] = {x0 + 2 * s.ax[1] + s.ax[2], y0 + 2 * s.ay[1] + s.ay[2]};
      cp[3] = {x0 + 3 * (s.ax[1] + s.ax[2] + s.ax[3]), y0 + 3 * (s.ay[1] + s.ay[2] + s.ay[3])};
    }
  }
  int sign = 0;
  bool at_joint = false;
  for (int k = 0; k <= n; ++k) {
    const double ex = cp[static_cast<std::size_t>(k)][0] - 3 * jx;
    const double ey = cp[static_cast<std::size_t>(k)][1] - 3 * jy;
    if (ex == 0 && ey == 0 && (k == 0 || k == n) && !at_joint) {
      at_joint = true; // the joint itself, once, at an end
      continue;
    }
    const double c = dx * ey - dy * ex;
    const int sk = c > 0 ? 1 : (c < 0 ? -1 : 0);
    if (sk == 0 || (sign != 0 && sk != sign))
      return false;
    sign = sk;
  }
  return at_joint;
}

// rule: PATH.AREA.SWEEP
// Whether a cell holds at most two winding numbers, and they differ by one. Its visits form
// arcs: consecutive pieces of one contour joined inside the cell (the one ending where the
// next starts), and a contour's last piece joined to its first. One run of consecutive pieces
// monotone in x or in y is a graph: any straight path in the cell crosses it with alternating
// signs. Else (b) one arc that does not cross itself (two pieces that meet at a joint do not
// turn back into each other's quadrant or are apart by turn_apart, any other two have boxes
// apart), whose ends lie on the
// border, cuts the cell into two sides; or (c) several arcs, each of one sense in y and the two
// of opposite senses, with boxes apart in x (left of the left one, between, right of the right
// one: W + d, W, W - d' with d = d'), or the same with x and y exchanged; or (d) several arcs,
// each monotone in x or in y from border to border and apart from the others, each with all the
// others on its side of the same sign (side_of): then they bound one region between them, and
// beyond each arc the winding differs from it by that sign's opposite, the same for all.
bool Sweep::two_windings(const Cell& c, std::uint8_t runs) const {
  if (runs == 1 && monotone(c.dirs))
    return true;
  if (c.count < 2 || c.count > 8)
    return false;
  std::array<const Seen*, 8> v{};
  int n = 0;
  for (std::uint32_t k = c.first; k != 0; k = seen_[k - 1].next)
    v[static_cast<std::size_t>(n++)] = &seen_[k - 1];
  const auto joined = [](const Seen& p, const Seen& q) {
    return q.id == p.id + 1 && (p.flags & kEnds) != 0 && (q.flags & kStarts) != 0;
  };
  // Runs of joined visits (segs of them, from cut[s] to cut[s + 1]).
  std::array<int, 9> cut{};
  int segs = 0;
  for (int i = 0; i < n; ++i)
    if (i == 0 || !joined(*v[static_cast<std::size_t>(i - 1)], *v[static_cast<std::size_t>(i)]))
      cut[static_cast<std::size_t>(segs++)] = i;
  cut[static_cast<std::size_t>(segs)] = n;
  // A run that ends with its contour's last piece, at its end, goes on with the run that starts
  // with that contour's first piece at its start (the contour closes there).
  std::array<int, 8> next{};
  std::array<bool, 8> has_prev{};
  next.fill(-1);
  for (int r = 0; r < segs; ++r) {
    const Seen& l = *v[static_cast<std::size_t>(cut[static_cast<std::size_t>(r + 1)] - 1)];
    if ((l.flags & kEnds) == 0)
      continue;
    const auto it =
        std::upper_bound(contours_.begin(), contours_.end(), l.id,
                         [](std::uint32_t x, const std::pair<std::uint32_t, std::uint32_t>& k) {
                           return x < k.first;
                         });
    if (l.id != (it - 1)->second)
      continue;
    for (int q = 0; q < segs; ++q) {
      const Seen& f = *v[static_cast<std::size_t>(cut[static_cast<std::size_t>(q)])];
      if (f.id == (it - 1)->first && (f.flags & kStarts) != 0) {
        if (q == r)
          return false; // a whole contour inside the cell
        next[static_cast<std::size_t>(r)] = q;
        has_prev[static_cast<std::size_t>(q)] = true;
      }
    }
  }
  // The arcs: order[at[a], at[a + 1]) for arc a.
  std::array<const Seen*, 8> order{};
  std::array<int, 9> at{};
  int arcs = 0, m = 0;
  for (int r = 0; r < segs; ++r) {
    if (has_prev[static_cast<std::size_t>(r)])
      continue;
    at[static_cast<std::size_t>(arcs++)] = m;
    for (int q = r; q >= 0 && m < n; q = next[static_cast<std::size_t>(q)])
      for (int i = cut[static_cast<std::size_t>(q)]; i < cut[static_cast<std::size_t>(q + 1)]; ++i)
        order[static_cast<std::size_t>(m++)] = v[static_cast<std::size_t>(i)];
  }
  at[static_cast<std::size_t>(arcs)] = m;
  if (m != n)
    return false; // runs in a cycle (not expected): in doubt
  if (arcs == 1) {
    for (int a = 0; a < m; ++a)
      for (int b = a + 1; b < m; ++b) {
        const Seen& p = *order[static_cast<std::size_t>(a)];
        const Seen& q = *order[static_cast<std::size_t>(b)];
        if (!(b == a + 1 ? monotone((p.flags | q.flags) & 15) || turn_apart(p.id, q.id)
                         : apart(p.box, q.box)))
          return false;
      }
    return true;
  }
  std::array<ArcInfo, 8> arc{};
  bool simple = true; // every arc a cut from border to border, off the grid lines
  for (int a = 0; a < arcs; ++a) {
    ArcInfo& info = arc[static_cast<std::size_t>(a)];
    const int lo = at[static_cast<std::size_t>(a)], hi = at[static_cast<std::size_t>(a + 1)];
    info.box = order[static_cast<std::size_t>(lo)]->box;
    for (int i = lo; i < hi; ++i) {
      const Seen& p = *order[static_cast<std::size_t>(i)];
      info.box.add(p.box);
      info.dirs |= p.flags & 15;
      // Joints inside the cell: an arc that touches the border between its ends cuts it in
      // more than two.
      if ((p.flags & kAlong) != 0 || (i + 1 < hi && end_sides(p.flags) != 0))
        simple = false;
    }
    info.start = start_sides(order[static_cast<std::size_t>(lo)]->flags);
    info.end = end_sides(order[static_cast<std::size_t>(hi - 1)]->flags);
    if (info.start == 0 || info.end == 0 || !monotone(info.dirs))
      simple = false;
  }
  // (c): each arc of one sense in y, their boxes apart in x one after the other, the senses
  // alternating (left of the first, between two, right of the last: the windings go W, W + d,
  // W, W + d, ...); or the same with x and y exchanged.
  std::array<int, 8> idx{};
  for (int a = 0; a < arcs; ++a)
    idx[static_cast<std::size_t>(a)] = a;
  const auto alternate = [&](bool in_x) {
    const auto lo = [&](int a) {
      const Box& b = arc[static_cast<std::size_t>(a)].box;
      return in_x ? b.x0 : b.y0;
    };
    const auto hi = [&](int a) {
      const Box& b = arc[static_cast<std::size_t>(a)].box;
      return in_x ? b.x1 : b.y1;
    };
    const auto sense = [&](int a) {
      return arc[static_cast<std::size_t>(a)].dirs & (in_x ? 12 : 3);
    };
    std::sort(idx.begin(), idx.begin() + arcs, [&](int a, int b) { return lo(a) < lo(b); });
    for (int k = 0; k < arcs; ++k) {
      const int a = idx[static_cast<std::size_t>(k)];
      const int d = sense(a);
      if (d != (in_x ? 4 : 1) && d != (in_x ? 8 : 2))
        return false;
      if (k > 0) {
        const int p = idx[static_cast<std::size_t>(k - 1)];
        if (!(hi(p) < lo(a)) || sense(p) == d)
          return false;
      }
    }
    return true;
  };
  if (alternate(true) || alternate(false))
    return true;
  // (d): one region between all the arcs, the same change of winding beyond each.
  if (!simple)
    return false;
  int near = 0;
  for (int a = 0; a < arcs; ++a)
    for (int b = 0; b < arcs; ++b) {
      if (a == b)
        continue;
      const int side =
          side_of(arc[static_cast<std::size_t>(a)], arc[static_cast<std::size_t>(b)].box);
      if (side == 0 || (near != 0 && side != near))
        return false;
      near = side;
    }
  return true;
}

// rule: PATH.AREA.SWEEP, PATH.AREA.ALPHA
void Sweep::sweep(std::span<std::uint8_t> out) {
  const auto w = static_cast<std::size_t>(w_);
  for (std::int32_t j = 0; j < h_; ++j) {
    const auto r = static_cast<std::size_t>(j);
    if (doubted_[r] != 0 || !sweep_row(r, out.data() + r * w))
      doubted_[r] = 1;
  }
}

// rule: PATH.AREA.SWEEP, PATH.AREA.ALPHA
// Row r's alphas, or false where a cell may hold more than two winding numbers or its bound
// does not decide its rounding.
bool Sweep::sweep_row(std::size_t r, std::uint8_t* row) const {
  const auto w = static_cast<std::size_t>(w_);
  constexpr std::int64_t kWhole = kW << kFix; // a whole winding's cover
  const std::size_t at = r * stride_;
  std::int64_t s = left_cover_[r]; // the cover left of the cell
  // The alpha of a cell without boundary after the last cell with some (-1: not yet known).
  int empty_alpha = -1;
  for (std::size_t k = 0; k < w; ++k) {
    const std::uint8_t runs = runs_[at + k];
    if (runs == 0) {
      // No boundary in the cell: one winding number, minus the cover left of it, exact
      // (every point of the boundary left of it is shared by two visits there, in fixed
      // point, or lies on a row line).
      if (empty_alpha < 0) {
        if (s % kWhole != 0)
          return false;
        empty_alpha = fill_holds(rule_, -s / kWhole) ? 255 : 0;
      }
      row[k] = static_cast<std::uint8_t>(empty_alpha);
      continue;
    }
    empty_alpha = -1;
    const Cell& c = cells_[at + k];
    if (!two_windings(c, runs))
      return false;
    // I = the integral of w over the cell (raw^2): the winding at a point is minus the cover
    // left of it; c.area is the integral of (x - left) dy.
    const std::int64_t cs = s + c.cover;
    const double integral = c.area - kWd * (static_cast<double>(cs) * (1 / kFixScale));
    const double v = integral * (1.0 / (kWd * kWd));
    const double m = floor_of(v);
    const double f0 = fill_holds(rule_, static_cast<std::int64_t>(m)) ? 1.0 : 0.0;
    const double f1 = fill_holds(rule_, static_cast<std::int64_t>(m) + 1) ? 1.0 : 0.0;
    const double x = 510 * (f0 + (f1 - f0) * (v - m));
    const auto alpha_at = [](double y) {
      return std::clamp<std::int64_t>((static_cast<std::int64_t>(floor_of(y)) + 1) >> 1, 0, 255);
    };
    const std::int64_t alpha = alpha_at(x);
    // The cell's own visits bound its error: every other point in the cover left of it is
    // shared by two visits there and cancels, and what it shares with the cells right of it
    // is its own visits' end points.
    const double e = c.err;
    if (e > 0) {
      // |510 a - 510 a_true| <= 510 (the integral's bound / 2^16 + the roundings of the
      // integral and of v - m, a and x: 4 u (|v| + 1) and 2^-40); the alpha, clamped to
      // [0, 255] as the true 510 a lies in [0, 510], must be the same at both ends.
      const double d =
          510 * (e * (1.0 / (kWd * kWd)) + 4 * kU * (std::abs(v) + 1)) * (1 + 0x1p-40) + 0x1p-40;
      if (alpha_at(x - d) != alpha || alpha_at(x + d) != alpha)
        return false;
    }
    row[k] = static_cast<std::uint8_t>(alpha);
    s = cs;
  }
  return true;
}

// rule: PATH.AREA.SWEEP
bool Sweep::run(const Boundary& b, FillRule rule, std::int32_t w, std::int32_t h,
                std::span<std::uint8_t> out, std::vector<std::uint8_t>& undecided) {
  if (w <= 0 || h <= 0) {
    undecided.clear();
    return true;
  }
  rule_ = rule;
  w_ = w;
  h_ = h;
  stride_ = static_cast<std::size_t>(w);
  const std::size_t cells = stride_ * static_cast<std::size_t>(h);
  undecided.assign(static_cast<std::size_t>(h), 1);
  if (cells > kMaxCells)
    return false;
  std::fill(undecided.begin(), undecided.end(), std::uint8_t{0});
  doubted_ = undecided.data();
  shapes_.clear();
  pieces_.clear();
  contours_.clear();
  const auto walk = [&] {
    if (!build(b))
      return false;
    if (cells_.size() < cells)
      cells_.resize(cells);
    runs_.assign(cells, 0);
    seen_.clear();
    left_cover_.assign(static_cast<std::size_t>(h), 0);
    for (const PieceRef& p : pieces_) {
      const bool ok =
          p.shape == kLine ? walk_line(p.id, p.a, p.b, p.sx, p.sy) : walk_curve(p, p.id);
      if (!ok)
        return false;
    }
    return true;
  };
  if (!walk()) {
    std::fill(undecided.begin(), undecided.end(), std::uint8_t{1});
    return false;
  }
  sweep(out);
  return true;
}

} // namespace

// rule: PATH.AREA.SWEEP
bool alpha_sweep(const Boundary& b, FillRule rule, std::int32_t w, std::int32_t h,
                 std::span<std::uint8_t> out, std::vector<std::uint8_t>& undecided) {
  thread_local Sweep s;
  return s.run(b, rule, w, h, out, undecided);
}

} // namespace rastrules::path::detail
