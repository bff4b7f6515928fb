// SPDX-License-Identifier: MIT
// The path kernel's internal pieces shared by its translation units: the boundary as line
// edges and curves (closing lines added), the tie signs of a fill convention, and one crossing
// of a sample row.

#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

#include "rastrules/fixed.hpp"
#include "rastrules/formula/path.hpp"
#include "rastrules/path.hpp"

namespace rastrules::path::detail {

// The select of the formula templates (rastrules/formula/path_*.hpp) on concrete values.
inline constexpr auto kSelect = [](bool c, auto t, auto f) { return c ? t : f; };

// The displacement signs of PATH.SAMPLE.TIE: x_right is hx = +1, y_down is hy = +1.
struct Tie {
  bool x_right = true;
  bool y_down = true;
};
[[nodiscard]] Tie tie_of(FillConvention f);

// A directed line edge, raw 16.8.
// contour and segment say which piece of the path it is (segment == the contour's segment count
// for its closing line).
struct Edge {
  std::int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  std::size_t contour = 0, segment = 0;
};

// A quadratic (degree 2, p[0..2]) or cubic (degree 3, p[0..3]) Bézier curve, start point
// first.
struct Curve {
  int degree = 2;
  std::array<Point, 4> p{};
  std::size_t contour = 0, segment = 0;
};

// The boundary of a path: every line segment and closing line (PATH.CONTOUR.CLOSE), and every
// curve, each directed as drawn.
struct Boundary {
  std::vector<Edge> lines;
  std::vector<Curve> curves;
};
[[nodiscard]] Boundary boundary_of(const Path& path);
// The same into b (cleared first; no allocation once b has room).
void boundary_into(const Path& path, Boundary& b);
// A segment of a boundary: a line (curve false) or a curve, by its contour and segment, and its
// index in the boundary's list.
struct SegmentRef {
  std::size_t contour = 0, segment = 0;
  bool curve = false;
  std::size_t index = 0;
};
// The boundary's lines and curves in the order of their contours (contour, then segment), into
// refs (cleared first).
void segments_in_order(const Boundary& b, std::vector<SegmentRef>& refs);
// The control points of segment r of b into cp (a line's two first); its degree (1 a line).
int control_points(const Boundary& b, const SegmentRef& r, std::array<Point, 4>& cp);
// The least and greatest y (raw) of cp's first degree + 1 points: the convex hull, and so the
// segment, lies between them.
std::pair<double, double> control_y_range(const std::array<Point, 4>& cp, int degree);

// One crossing of the displaced horizontal line through a sample row: it counts for a sample
// at raw x iff x <= threshold (PATH.SAMPLE.TIE: x_c > x, or x_c == x and hx = -1); dir is +1
// where the boundary runs down, -1 up.
struct Crossing {
  std::int64_t threshold = 0;
  int dir = 0;
  [[nodiscard]] bool counts_at(std::int64_t x) const { return x <= threshold; }
};

// Returns the crossings of curve c with the line y = sy + hy delta (delta -> 0+), exactly
// (PATH.CURVE.SAMPLE; kernel/src/path_curve.cpp).
[[nodiscard]] std::vector<Crossing> curve_crossings(const Curve& c, std::int64_t sy, Tie t);

// The same by the rational path alone (no integer fast path): curve_crossings must equal it,
// which tests/path checks. fast = false is this; curve_crossings is fast = true.
[[nodiscard]] std::vector<Crossing> curve_crossings_exact(const Curve& c, std::int64_t sy, Tie t);
// Either, into out (cleared first; no allocation once out has room, so the row walk reuses one
// vector); fast chooses whether the integer paths are tried first.
void curve_crossings_into(const Curve& c, std::int64_t sy, Tie t, bool fast,
                          std::vector<Crossing>& out);
// The integer paths alone (no rational path), into out (cleared first): false, with out empty,
// where they leave the row to the rational path. tests/path checks which rows they decide.
[[nodiscard]] bool curve_crossings_integer(const Curve& c, std::int64_t sy, Tie t,
                                           std::vector<Crossing>& out);

// What the crossings of one curve with every row share, computed once (prepare_curve): the
// power coefficients of x and y, x's Lipschitz bound and filter bound (PATH.CURVE.FILTER), the
// cuts of [0, 1] at the estimated roots of y', and the control points' y-range.
// Where the roots of a curve's last two rows were, one a cut interval of its derivative (NaN:
// none there), so that the next row's Newton steps start near its root: the linear
// extrapolation of the two (the roots of consecutive rows move smoothly along a piece), or the
// last alone. Only a start: every estimate is still confined by exact signs, so the crossings
// do not depend on it (PATH.CURVE.FILTER).
struct RootHints {
  // Three rows' roots in rotating slots (record() moves indices, not arrays: a copy of the
  // roots just found, read as 16 bytes right after their 8-byte stores, stalled on store
  // forwarding on every row).
  std::array<std::array<double, 3>, 3> roots; // valid where masks' bits say
  std::array<unsigned, 3> masks{};
  std::array<std::int64_t, 3> rows{};
  std::uint8_t last = 0, before = 1, found = 2; // the slots
  // Forgets every row (cheap: no root is written).
  void reset() { masks = {0, 0, 0}; }
  // The start for cut interval i on row `row` (NaN: none).
  [[nodiscard]] double start(int i, std::int64_t row) const {
    const auto k = static_cast<std::size_t>(i);
    const unsigned bit = 1u << i;
    if ((masks[last] & bit) == 0)
      return std::numeric_limits<double>::quiet_NaN();
    const double l = roots[last][k];
    if ((masks[before] & bit) == 0 || rows[last] == rows[before])
      return l;
    return l + (l - roots[before][k]) * static_cast<double>(row - rows[last]) /
                   static_cast<double>(rows[last] - rows[before]);
  }
  // A root found in cut interval i on the row being estimated.
  void found_at(int i, double t) {
    roots[found][static_cast<std::size_t>(i)] = t;
    masks[found] |= 1u << i;
  }
  // Takes the roots found on `row` as the last.
  void record(std::int64_t row) {
    rows[found] = row;
    const std::uint8_t free = before;
    before = last;
    last = found;
    found = free;
    masks[found] = 0;
  }
};

__extension__ typedef __int128 CurveWide; // the curve test's wide integers (GCC/Clang)

// The y-monotone pieces of a cubic (PATH.CURVE.SAMPLE): [0, 1] cut at brackets of the roots of
// y' on the 2^30 grid, y' of one strict sign on each piece, proved when the curve is prepared;
// a row then crosses piece i iff y at its two ends lies on either side of the row, exactly.
struct MonotonePieces {
  int n = 0;                              // pieces; 0: none proved (every row takes the estimates)
  std::array<std::int64_t, 3> lo{}, hi{}; // each piece's ends k on the 2^30 grid
  // y(k / 2^30) at them as an exact key: 2 floor(y) where y is an integer, 2 floor(y) + 1
  // where not, so that the sign of key - 2 s.y is the sign of y - s.y for every integer row.
  std::array<std::int64_t, 3> ylo{}, yhi{};
  std::array<double, 3> ylo_d{}, yhi_d{}; // y there in double, for the estimates' start
  int brackets = 0;
  // A row with near_lo <= s.y <= near_hi might cross y inside a bracket: the estimates decide
  // it (the integer rows of the bracket's exact range of y).
  std::array<std::int64_t, 2> near_lo{}, near_hi{};
  // Where the next row's root estimate on each piece starts (a walk's rows, in order, on one
  // thread; only a start): the last root found there, t at row `row`, with the first two
  // Taylor coefficients of the inverse of y there, 1 / y' and -y'' / (2 y'^3), so that the
  // row s.y starts at t + d1 (s.y - row) + d2 (s.y - row)^2 (an error of the order of the cube
  // of the step in t, against its square for the extrapolation of two rows' roots).
  struct Last {
    double t = 0.0, d1 = 0.0, d2 = 0.0;
    std::int64_t row = 0;
    bool valid = false;
  };
  mutable std::array<Last, 3> last{};
};

struct PreparedCurve {
  const Curve* curve = nullptr;
  std::int64_t ymin = 0, ymax = 0;
  std::array<std::int64_t, 4> y{}, x{};
  std::int64_t x_lipschitz = 0;
  std::int64_t y_abs_rest = 0; // |y1| + |y2| + |y3|, for g's filter bound
  double x_bound = 0.0;
  // PATH.CURVE.COARSE's margin m = 2^-30 + 2 (E + R) around a crossing's x (coarse_crossing).
  double coarse_margin = 0.0;
  std::array<double, 4> cut{};
  int cuts = 1;
  MonotonePieces mono;
  // The start of the next row's root estimates (not part of the curve: a walk's rows, in
  // order, on one thread).
  mutable RootHints hints;
};
void prepare_curve(const Curve& c, PreparedCurve& p);
// The crossings of curve_crossings_into (fast), from a prepared curve: the same crossings,
// appended to out (scratch: room for the unprepared path, when the estimates give up).
//
// sample_x: kExactThresholds, or the raw x offset (mod 256) shared by every sample the row's
// crossings will be asked about (one sample in the row of the pattern). Then a crossing whose
// x lies strictly between two consecutive such samples, 256 q + sample_x and 256 (q + 1) +
// sample_x, may carry the threshold 256 q + sample_x in place of floor(x_c): every such sample
// counts it alike (PATH.CURVE.COARSE), and the root need not be found to 2^-30.
inline constexpr std::int64_t kExactThresholds = std::numeric_limits<std::int64_t>::min();
void curve_crossings_prepared(const PreparedCurve& p, std::int64_t sy, Tie t,
                              std::vector<Crossing>& out, std::vector<Crossing>& scratch,
                              std::int64_t sample_x = kExactThresholds);
// A row of a band (curve_crossings_band): its y and its sample_x, as above.
struct BandRow {
  std::int64_t sy = 0;
  std::int64_t sample_x = kExactThresholds;
};
// A band row's crossings in room its owner reserved: at[0 .. n), with room for every crossing
// the row can get (cap: one a line, three a curve: a cubic meets a line in three points at
// most, counted with multiplicity), so that an append is a store and a comparison, not a call.
// An append past cap would break that bound: a logic_error, never a write past the room.
struct RowCrossings {
  Crossing* at = nullptr;
  std::size_t n = 0;
  std::size_t cap = 0;
  [[nodiscard]] std::size_t size() const { return n; }
  [[nodiscard]] bool empty() const { return n == 0; }
  [[nodiscard]] Crossing* begin() const { return at; }
  [[nodiscard]] Crossing* end() const { return at + n; }
  Crossing& operator[](std::size_t i) const { return at[i]; }
  void push_back(const Crossing& c) {
    if (n == cap) [[unlikely]]
      overflow();
    at[n++] = c;
  }
  void resize(std::size_t k) { n = k; } // k <= n: forgets the crossings after k
  [[noreturn, gnu::cold, gnu::noinline]] static void overflow();
};
// The same for several rows of increasing y at once (a band of the row walk), row i's
// crossings appended to out[i] (out.size() >= rows.size(), each with room for three more):
// what the rows of one curve share is read once, and a row costs no call where the monotone
// pieces decide it. scratch and left: memory for the rows the pieces leave.
void curve_crossings_band(const PreparedCurve& p, std::span<const BandRow> rows, Tie t,
                          std::span<RowCrossings> out, std::vector<Crossing>& scratch,
                          std::vector<Crossing>& left);
// The monotone pieces alone (PATH.CURVE.SAMPLE): false, with nothing appended, where prepare_curve
// proved none (p.mono.n == 0) or they leave row sy to the estimates; else true with the row's
// crossings appended to out. For the tests that check which rows they decide (rows of one
// prepared curve in order, as the row walk asks them).
[[nodiscard]] bool curve_crossings_monotone(const PreparedCurve& p, std::int64_t sy, Tie t,
                                            std::vector<Crossing>& out,
                                            std::int64_t sample_x = kExactThresholds);

// The floating-point filter of PATH.CURVE.FILTER alone, for the properties that check it against
// exact arithmetic. For power coefficients c of a curve coordinate (|c_j| within the bounds of
// PATH.CURVE.SAMPLE) and 0 <= k <= 2^30: the sign of P(k / 2^30) where the filter decides it;
// and F where the filter proves F < x(t) < F + 1 for every t in [k, k + 1] / 2^30 (x with
// coefficients e). Nothing where the filter leaves the decision to the integer tests.
[[nodiscard]] std::optional<int> curve_filter_sign(const std::array<std::int64_t, 4>& c,
                                                   std::int64_t k);
[[nodiscard]] std::optional<std::int64_t> curve_filter_floor(const std::array<std::int64_t, 4>& e,
                                                             std::int64_t k);

// Area coverage of a boundary with curves (PATH.AREA.CURVE; kernel/src/path_area_curve.cpp):
// every pixel of [0, w) x [0, h) with a nonzero area or a nonzero error bound, row by row; only
// (when not null) the rows marked 1 in it.
void cover_area_curves(const Boundary& b, FillRule rule, std::int32_t w, std::int32_t h,
                       const std::function<void(const AreaCoverage&)>& emit,
                       const std::vector<std::uint8_t>* only = nullptr);
// The parts of pixel (x, y) by winding number (path::winding_areas), lines or curves.
[[nodiscard]] PixelWindings pixel_windings(const Boundary& b, FillRule rule, std::int32_t x,
                                           std::int32_t y, std::int32_t w, std::int32_t h);

// An edge oriented top end first (ya < yb), with the direction of the original (+1 down).
struct DownEdge {
  std::int64_t xa = 0, ya = 0, xb = 0, yb = 0;
  int dir = 0;
};

// Fills v with the non-horizontal line edges of the path, oriented top end first, sorted by ya
// (then by the other ends and the direction: the order of equal keys changes no answer, and a
// full key makes it independent of the sort).
inline void down_edges_into(const Boundary& b, std::vector<DownEdge>& v) {
  v.clear();
  v.reserve(b.lines.size());
  for (const Edge& e : b.lines) {
    if (e.y0 == e.y1)
      continue; // horizontal: never crossed, no area (PATH.DEGENERATE)
    if (e.y0 < e.y1)
      v.push_back(DownEdge{e.x0, e.y0, e.x1, e.y1, 1});
    else
      v.push_back(DownEdge{e.x1, e.y1, e.x0, e.y0, -1});
  }
  std::sort(v.begin(), v.end(), [](const DownEdge& p, const DownEdge& q) {
    return std::tie(p.ya, p.xa, p.yb, p.xb, p.dir) < std::tie(q.ya, q.xa, q.yb, q.xb, q.dir);
  });
}

// Returns the non-horizontal line edges of the path, oriented top end first, sorted by ya.
inline std::vector<DownEdge> down_edges(const Boundary& b) {
  std::vector<DownEdge> v;
  down_edges_into(b, v);
  return v;
}

// The largest raw sample x for which the crossing of e at height sy counts (PATH.BUDGET.LINE).
inline std::int64_t line_threshold(const DownEdge& e, std::int64_t sy, Tie t) {
  const std::int64_t n = formula::path_crossing_numerator<std::int64_t>(e.xa, e.ya, e.xb, e.yb, sy);
  const std::int64_t d = e.yb - e.ya;
  return t.x_right ? ceil_div(n, d) - 1 : floor_div(n, d);
}

// Edges that may span a sample row, kept while the rows go down the target (in active, which
// the caller owns and may reuse).
class ActiveEdges {
public:
  ActiveEdges(const std::vector<DownEdge>& sorted, std::vector<const DownEdge*>& active)
      : edges_(sorted), active_(active) {
    active_.clear();
  }
  // Makes the active list hold every edge with ya <= y_hi that does not end above y_lo.
  // Calls must come with non-decreasing y_lo and y_hi.
  const std::vector<const DownEdge*>& advance(std::int64_t y_lo, std::int64_t y_hi) {
    while (next_ < edges_.size() && edges_[next_].ya <= y_hi)
      active_.push_back(&edges_[next_++]);
    std::erase_if(active_, [&](const DownEdge* e) { return e->yb < y_lo; });
    return active_;
  }

private:
  const std::vector<DownEdge>& edges_;
  std::vector<const DownEdge*>& active_;
  std::size_t next_ = 0;
};

// How cover_area decides a pixel row: by cells where it can, else by slabs (PATH.AREA.CELLS),
// or by slabs alone (PATH.AREA.EXACT's computation, for tests that compare the two).
// kFast (cover_area_alpha alone) tries the certified floating-point cells of PATH.AREA.FAST first
// and leaves the rows they do not decide to kCells; kSweep (cover_area_alpha alone) tries
// PATH.AREA.SWEEP first and leaves the rows it does not decide to kCells, or, where it declines
// the whole path, goes on as kFast.
enum class AreaMethod { kCells, kSlabs, kFast, kSweep };
// Rows decided each way (rows no edge reaches into are neither; kFast counts every row it
// decides, those without edges too; swept: every row PATH.AREA.SWEEP decides, likewise).
struct AreaRows {
  std::size_t cells = 0, slabs = 0, fast = 0, swept = 0;
};
// PATH.AREA.FAST: writes the alpha of every row it decides into out (w * h bytes) and marks
// the others in undecided (1: left for the exact methods); false where it declines the whole
// path (then every row is marked). Only the rows marked in only, where given, are its (the
// others are neither written nor marked).
bool alpha_fast(const Boundary& b, FillRule rule, std::int32_t w, std::int32_t h,
                std::span<std::uint8_t> out, std::vector<std::uint8_t>& undecided,
                const std::vector<std::uint8_t>* only = nullptr);
// PATH.AREA.SWEEP: writes the alpha of every row it decides into out (w * h bytes) and marks
// the others in undecided (1: left for the other methods; their bytes of out hold anything);
// false where it declines the whole path (then every row is marked).
bool alpha_sweep(const Boundary& b, FillRule rule, std::int32_t w, std::int32_t h,
                 std::span<std::uint8_t> out, std::vector<std::uint8_t>& undecided);
// cover_area by the method given; rows, when not null, counts the rows.
void cover_area_by(const Path& path, std::int32_t w, std::int32_t h, AreaMethod method,
                   const std::function<void(const AreaCoverage&)>& emit, AreaRows* rows);
// cover_area_alpha by the method given.
void cover_alpha_by(const Path& path, std::int32_t w, std::int32_t h, AreaMethod method,
                    std::span<std::uint8_t> out, AreaRows* rows);
// floor(255 a + 1/2) for an area a in [0, 1] (PATH.AREA.ALPHA).
[[nodiscard]] std::uint8_t alpha_of(const boost::multiprecision::cpp_rational& a);

} // namespace rastrules::path::detail
