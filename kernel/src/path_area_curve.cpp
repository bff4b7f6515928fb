// SPDX-License-Identifier: MIT
// 2D paths: area coverage of paths with curves (spec/rules/path.md, PATH.AREA.CURVE). Every curve
// is cut at t = 1/2 (exactly, in rationals) into convex pieces; the polygon of the pieces'
// chords gets its exact areas by the slab method of PATH.AREA.EXACT, and each piece adds back,
// exactly, the area between it and its chord (its lens) where the lens lies in one pixel and no
// other piece comes near it. The few pieces left (those across a grid line at the deepest cut,
// and where two curves cross) are bounded, not corrected: each adds its lens area (its hull's,
// where it is not convex) to the error bound of every pixel its control points' box meets.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "path_area_rows.hpp"
#include "path_detail.hpp"
#include "rastrules/fixed.hpp"
#include "rastrules/path.hpp"

namespace rastrules::path::detail {
namespace {

__extension__ typedef __int128 I128;
__extension__ typedef unsigned __int128 U128;
// Products of two coordinate differences (|d| <= 2^122) and sums of two such: below 2^245.
using Wide = boost::multiprecision::checked_int256_t;

// Coordinates are raw (1/256 px) times 2^kScale: every control point of a curve halved at most
// kMaxDepth times is then an integer (a cubic's at depth d are multiples of 2^-3d raw), and
// |raw| < 2^31 stays below 2^121.
constexpr int kScale = 90;
constexpr int kMaxDepth = 30;
// One pixel is 2^kPixelShift scaled units.
constexpr int kPixelShift = kScale + kSubpixelBits;

// A point in scaled raw units, exact.
struct RPoint {
  I128 x = 0, y = 0;
  friend bool operator==(const RPoint&, const RPoint&) = default;
};

// (b - a) x (c - a): positive where a, b, c turn clockwise on the screen (y down).
Wide orient(const RPoint& a, const RPoint& b, const RPoint& c) {
  return Wide(b.x - a.x) * Wide(c.y - a.y) - Wide(b.y - a.y) * Wide(c.x - a.x);
}

template <class T> int sign_of(const T& v) {
  return v > 0 ? 1 : (v < 0 ? -1 : 0);
}

BigInt big_of(I128 v) {
  const bool negative = v < 0;
  const U128 u = negative ? U128{0} - static_cast<U128>(v) : static_cast<U128>(v);
  BigInt b = BigInt(static_cast<std::uint64_t>(u >> 64)) << 64;
  b += static_cast<std::uint64_t>(u);
  return negative ? BigInt(-b) : b;
}

// A scaled coordinate as a rational number of raw units.
Rational raw_of(I128 v) {
  return Rational(big_of(v)) / Rational(BigInt(1) << kScale);
}

// A piece of the boundary: a line (n = 1) or the part of a curve (n = 2, 3) between two dyadic
// parameters, as the Bézier curve of its control points p[0..n], directed as drawn.
struct Piece {
  int n = 1;
  std::array<RPoint, 4> p{};
  int depth = 0;
};

// The halves of a curve piece at t = 1/2 (de Casteljau: exact in rationals).
std::pair<Piece, Piece> halves(const Piece& c) {
  Piece l{c.n, {}, c.depth + 1};
  Piece r{c.n, {}, c.depth + 1};
  std::array<RPoint, 4> cur = c.p;
  l.p[0] = cur[0];
  r.p[static_cast<std::size_t>(c.n)] = cur[static_cast<std::size_t>(c.n)];
  for (int level = 1; level <= c.n; ++level) {
    for (int k = 0; k + level <= c.n; ++k) {
      const auto i = static_cast<std::size_t>(k);
      cur[i].x = (cur[i].x + cur[i + 1].x) / 2; // exact: depth <= kMaxDepth
      cur[i].y = (cur[i].y + cur[i + 1].y) / 2;
    }
    l.p[static_cast<std::size_t>(level)] = cur[0];
    r.p[static_cast<std::size_t>(c.n - level)] = cur[static_cast<std::size_t>(c.n - level)];
  }
  return {std::move(l), std::move(r)};
}

// Twice the signed area enclosed by the piece followed by its chord back (the integral of
// x dy - y dx), in raw^2: positive exactly where that loop winds +1 (PATH.WINDING).
Rational twice_lens(const Piece& c) {
  std::array<std::array<BigInt, 2>, 4> p{}, a{}; // control points; power coefficients
  for (int k = 0; k <= c.n; ++k) {
    const auto u = static_cast<std::size_t>(k);
    p[u] = {big_of(c.p[u].x), big_of(c.p[u].y)};
  }
  for (std::size_t d = 0; d < 2; ++d) {
    a[0][d] = p[0][d];
    if (c.n == 2) {
      a[1][d] = 2 * (p[1][d] - p[0][d]);
      a[2][d] = p[0][d] - 2 * p[1][d] + p[2][d];
    } else {
      a[1][d] = 3 * (p[1][d] - p[0][d]);
      a[2][d] = 3 * (p[0][d] - 2 * p[1][d] + p[2][d]);
      a[3][d] = 3 * (p[1][d] - p[2][d]) + p[3][d] - p[0][d];
    }
  }
  // The integral over [0, 1] of x y' - y x' is the sum over i and j >= 1 of
  // (a_i.x a_j.y - a_i.y a_j.x) j / (i + j); times 60, every term is an integer.
  BigInt s = 0;
  for (int i = 0; i <= c.n; ++i)
    for (int j = 1; j <= c.n; ++j) {
      const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
      s += (a[ui][0] * a[uj][1] - a[ui][1] * a[uj][0]) * (j * (60 / (i + j)));
    }
  const auto& last = p[static_cast<std::size_t>(c.n)];
  s += 60 * (last[0] * p[0][1] - p[0][0] * last[1]);
  return Rational(s) / Rational(BigInt(60) << (2 * kScale));
}

// The side of the chord its interior control points lie on, strictly (+1 or -1); 0 where one
// lies on the chord's line or they lie on both sides.
int chord_side(const Piece& c) {
  const RPoint& last = c.p[static_cast<std::size_t>(c.n)];
  int side = 0;
  for (int k = 1; k < c.n; ++k) {
    const int s = sign_of(orient(c.p[0], last, c.p[static_cast<std::size_t>(k)]));
    if (s == 0 || (side != 0 && s != side))
      return 0;
    side = s;
  }
  return side;
}

// Whether the control polygon closed by the chord is convex with every interior control point
// strictly on one side of the chord: then the piece is a convex arc, and its lens (the region
// between the arc and the chord) is a convex set inside the control points' hull.
bool convex_arc(const Piece& c) {
  const int side = chord_side(c);
  if (side == 0)
    return false;
  if (c.n == 2)
    return true; // a triangle
  const auto& p = c.p;
  const std::array<int, 4> turns{
      sign_of(orient(p[3], p[0], p[1])), sign_of(orient(p[0], p[1], p[2])),
      sign_of(orient(p[1], p[2], p[3])), sign_of(orient(p[2], p[3], p[0]))};
  return std::all_of(turns.begin(), turns.end(), [](int t) { return t >= 0; }) ||
         std::all_of(turns.begin(), turns.end(), [](int t) { return t <= 0; });
}

// Whether every control point lies on the chord's line (the chord not a point): the piece then
// differs from its chord on a set of measure zero (PATH.DEGENERATE).
bool straight(const Piece& c) {
  const RPoint& last = c.p[static_cast<std::size_t>(c.n)];
  if (c.p[0] == last)
    return false;
  for (int k = 1; k < c.n; ++k)
    if (orient(c.p[0], last, c.p[static_cast<std::size_t>(k)]) != 0)
      return false;
  return true;
}

bool all_equal(const Piece& c) {
  for (int k = 1; k <= c.n; ++k)
    if (!(c.p[static_cast<std::size_t>(k)] == c.p[0]))
      return false;
  return true;
}

// Twice an upper bound of the hull's area: the sum of every triangle of control points (a hull
// of at most four points is one of them or the union of two).
Rational twice_hull_bound(const Piece& c) {
  Wide s = 0;
  for (int i = 0; i <= c.n; ++i)
    for (int j = i + 1; j <= c.n; ++j)
      for (int k = j + 1; k <= c.n; ++k)
        s += abs(orient(c.p[static_cast<std::size_t>(i)], c.p[static_cast<std::size_t>(j)],
                        c.p[static_cast<std::size_t>(k)]));
  return Rational(BigInt(s)) / Rational(BigInt(1) << (2 * kScale));
}

struct Box {
  I128 x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

Box box_of(const Piece& c) {
  Box b{c.p[0].x, c.p[0].y, c.p[0].x, c.p[0].y};
  for (int k = 1; k <= c.n; ++k) {
    const RPoint& q = c.p[static_cast<std::size_t>(k)];
    b.x0 = std::min(b.x0, q.x);
    b.y0 = std::min(b.y0, q.y);
    b.x1 = std::max(b.x1, q.x);
    b.y1 = std::max(b.y1, q.y);
  }
  return b;
}

bool boxes_meet(const Box& a, const Box& b) {
  return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1;
}

// The pixel column (or row) of scaled coordinate v: floor(v / 2^kPixelShift).
std::int64_t cell_of(I128 v) {
  return static_cast<std::int64_t>(v >> kPixelShift); // arithmetic: rounds toward -infinity
}

// The pixel columns (or rows) whose closed span meets the closed interval [lo, hi].
std::pair<std::int64_t, std::int64_t> cells_meeting(I128 lo, I128 hi) {
  return {-cell_of(-lo) - 1, cell_of(hi)};
}

// Whether the closed hulls of a's and b's control points are disjoint: a line parallel or
// perpendicular to a line through two of their points separates them strictly.
bool separated(const Piece& a, const Piece& b) {
  for (const Piece* s : {&a, &b})
    for (int i = 0; i <= s->n; ++i)
      for (int j = i + 1; j <= s->n; ++j) {
        const RPoint& o = s->p[static_cast<std::size_t>(i)];
        const RPoint& q = s->p[static_cast<std::size_t>(j)];
        const Wide dx = Wide(q.x - o.x), dy = Wide(q.y - o.y);
        if (dx == 0 && dy == 0)
          continue;
        for (const bool across : {true, false}) {
          auto f = [&](const RPoint& r) -> Wide {
            if (across)
              return dx * Wide(r.y - o.y) - dy * Wide(r.x - o.x);
            return dx * Wide(r.x - o.x) + dy * Wide(r.y - o.y);
          };
          std::optional<Wide> amin, amax, bmin, bmax;
          for (int k = 0; k <= a.n; ++k) {
            const Wide v = f(a.p[static_cast<std::size_t>(k)]);
            amin = amin ? std::min(*amin, v) : v;
            amax = amax ? std::max(*amax, v) : v;
          }
          for (int k = 0; k <= b.n; ++k) {
            const Wide v = f(b.p[static_cast<std::size_t>(k)]);
            bmin = bmin ? std::min(*bmin, v) : v;
            bmax = bmax ? std::max(*bmax, v) : v;
          }
          if (*amax < *bmin || *bmax < *amin)
            return true;
        }
      }
  return false;
}

// Whether the closed hulls of a and b meet at v alone (v a control point of both): a line
// through v leaves a on one closed side and b on the other, one of them touching it at v only.
bool touch_only_at(const Piece& a, const Piece& b, const RPoint& v) {
  for (const Piece* s : {&a, &b})
    for (int i = 0; i <= s->n; ++i) {
      const RPoint& q = s->p[static_cast<std::size_t>(i)];
      if (q == v)
        continue;
      const Wide dx = Wide(q.x - v.x), dy = Wide(q.y - v.y);
      // Signs of a's and b's points (other than v) on the line through v and q.
      auto signs = [&](const Piece& t) {
        std::array<int, 3> count{}; // negative, zero, positive
        for (int k = 0; k <= t.n; ++k) {
          const RPoint& r = t.p[static_cast<std::size_t>(k)];
          if (r == v)
            continue;
          ++count[static_cast<std::size_t>(
              sign_of(Wide(dx * Wide(r.y - v.y) - dy * Wide(r.x - v.x))) + 1)];
        }
        return count;
      };
      const std::array<int, 3> sa = signs(a), sb = signs(b);
      for (const int side : {-1, 1}) {
        // a on the closed side `side`, b on the closed other side
        const auto same = static_cast<std::size_t>(1 + side),
                   other = static_cast<std::size_t>(1 - side);
        if (sa[other] != 0 || sb[same] != 0)
          continue;
        if (sa[1] == 0 || sb[1] == 0)
          return true;
      }
    }
  return false;
}

// Whether a and b are the same curve, drawn the same way or reversed (twins: their lenses are
// one region, corrected once for both).
bool twins(const Piece& a, const Piece& b) {
  if (a.n != b.n)
    return false;
  bool same = true, reversed = true;
  for (int k = 0; k <= a.n; ++k) {
    const auto u = static_cast<std::size_t>(k);
    same = same && a.p[u] == b.p[u];
    reversed = reversed && a.p[u] == b.p[static_cast<std::size_t>(a.n - k)];
  }
  return same || reversed;
}

// Whether the closed hulls of a and b meet nowhere but at an end point of both.
bool apart(const Piece& a, const Piece& b) {
  // Hulls with a common end point meet there: no strict separation, only the touch test.
  const std::array<const RPoint*, 2> ea{&a.p[0], &a.p[static_cast<std::size_t>(a.n)]};
  const std::array<const RPoint*, 2> eb{&b.p[0], &b.p[static_cast<std::size_t>(b.n)]};
  int shared = 0;
  const RPoint* v = nullptr;
  for (const RPoint* p : ea)
    for (const RPoint* q : eb)
      if (*p == *q && (v == nullptr || !(*v == *p))) {
        v = p;
        ++shared;
      }
  if (shared == 0)
    return separated(a, b);
  return shared == 1 && touch_only_at(a, b, *v);
}

// What a piece of the final boundary is: a chord alone (a line, or a piece equal to its chord
// up to measure zero), a chord with its lens added back exactly, or a chord with its lens bounded.
enum class Kind { kChord, kLens, kBounded };

struct Final {
  Piece piece;
  Kind kind = Kind::kChord;
  Box box;
  Rational twice_area;         // kLens: twice the lens's signed area; kBounded: twice the bound
  std::int64_t ci = 0, cj = 0; // kLens: its pixel
  bool checked = false;        // kLens: apart from every other piece
};

// Cuts stop where a piece's bound is at most 2^-40 px^2 (2^-24 raw^2), or at kMaxDepth.
const Rational& twice_stop() {
  static const Rational stop(1, std::int64_t{1} << 23); // a local: no order of initialization
  return stop;
}

// A chord of the polygon, top end first, with its direction (+1 where the boundary runs down)
// and its lens (index into the finals, or none).
struct Chord {
  Rational xa, ya, xb, yb, slope; // slope dx / dy
  Rational xmin, xmax;
  int dir = 0;
  std::optional<std::size_t> lens;
  bool lens_right = false; // the lens lies right of the chord
  Rational x_at(const Rational& y) const { return xa + (y - ya) * slope; }
};

// The polygon of the chords, ready for the rows: its chords by the rows they reach into, the
// bounds by pixel, and the change of the winding number inside each lens.
struct Polygon {
  std::vector<Chord> chords;
  std::vector<std::vector<std::size_t>> by_row;
  std::vector<std::map<std::int64_t, Rational>> bound; // twice, raw^2, by row then column
  std::map<std::size_t, std::int64_t> lens_dw;         // lens -> the change of w inside it
};

// A chord over one slab of a row: its x at the slab's top and bottom.
struct Slice {
  const Chord* e;
  Rational xa, xb, key;
};

// The pieces a path may be cut into: 2^12 a curve and 2^16 more. Curves that overlap along a
// stretch (never twins) or run within a hair of each other would be halved down to 2^-40 px^2
// all along it; the budget stops that, with the bounds of the pieces left as they are.
std::size_t piece_budget(const Boundary& b) {
  return (std::size_t{1} << 16) + (b.curves.size() << 12);
}

class CurveAreas {
public:
  CurveAreas(const Boundary& b, FillRule rule, std::int32_t w, std::int32_t h)
      : rule_(rule), w_(w), h_(h) {
    std::vector<Piece> todo;
    for (const Edge& e : b.lines) {
      Piece p{1, {}, 0};
      p.p[0] = {I128{e.x0} << kScale, I128{e.y0} << kScale};
      p.p[1] = {I128{e.x1} << kScale, I128{e.y1} << kScale};
      if (!(p.p[0] == p.p[1]))
        add_final(std::move(p), Kind::kChord);
    }
    for (const Curve& c : b.curves) {
      Piece p{c.degree, {}, 0};
      for (int k = 0; k <= c.degree; ++k) {
        const Point& q = c.p[static_cast<std::size_t>(k)];
        p.p[static_cast<std::size_t>(k)] = {I128{q.x} << kScale, I128{q.y} << kScale};
      }
      todo.push_back(std::move(p));
    }
    // Level by level (one halving each), so that the budget ends the halving at the same set of
    // pieces whatever the order of the contours and segments (and reversed or translated).
    std::vector<Piece> level;
    while (!todo.empty()) {
      level.swap(todo);
      todo.clear();
      for (Piece& p : level)
        classify(std::move(p), todo);
      check_lenses(todo);
      if (finals_.size() + todo.size() > piece_budget(b))
        halving_ = false; // from here on, a piece to halve is bounded instead
    }
  }

  // only (when not null): the rows to emit (1), the others skipped.
  void emit(const std::function<void(const AreaCoverage&)>& out,
            const std::vector<std::uint8_t>* only = nullptr) const;
  // The parts of pixel (x, y) by winding number, and its bound (PATH.AREA.CURVE).
  [[nodiscard]] PixelWindings windings(std::int32_t x, std::int32_t y) const;

private:
  void add_final(Piece p, Kind kind, Rational twice = 0, std::int64_t ci = 0, std::int64_t cj = 0) {
    Box box = box_of(p);
    finals_.push_back(Final{std::move(p), kind, std::move(box), std::move(twice), ci, cj, false});
  }

  // A curve piece: dropped (a point), final, or halved into todo.
  void classify(Piece p, std::vector<Piece>& todo) {
    if (all_equal(p))
      return; // no area, crosses nothing (PATH.DEGENERATE)
    // Outside the target (its box meets no interior point of it), a piece changes no pixel of
    // the target's areas when it is replaced by its chord: the two differ only in its hull.
    const Box b = box_of(p);
    const bool outside = b.x1 <= 0 || b.y1 <= 0 || b.x0 >= (I128{w_} << kPixelShift) ||
                         b.y0 >= (I128{h_} << kPixelShift);
    if (outside || straight(p)) {
      Piece chord{1, {p.p[0], p.p[static_cast<std::size_t>(p.n)]}, p.depth};
      add_final(std::move(chord), Kind::kChord);
      return;
    }
    const RPoint& last = p.p[static_cast<std::size_t>(p.n)];
    if (convex_arc(p) && p.p[0].y != last.y) {
      const std::int64_t ci = cell_of(b.x0), cj = cell_of(b.y0);
      if (b.x1 <= (I128{ci + 1} << kPixelShift) && b.y1 <= (I128{cj + 1} << kPixelShift)) {
        Rational twice = twice_lens(p);
        add_final(std::move(p), Kind::kLens, std::move(twice), ci, cj);
        return;
      }
    }
    bound_or_halve(std::move(p), todo);
  }

  void bound_or_halve(Piece p, std::vector<Piece>& todo) {
    Rational twice = convex_arc(p) ? Rational(abs(twice_lens(p))) : twice_hull_bound(p);
    if (twice <= twice_stop() || p.depth >= kMaxDepth || !halving_) {
      add_final(std::move(p), Kind::kBounded, std::move(twice));
      return;
    }
    auto [l, r] = halves(p);
    todo.push_back(std::move(l));
    todo.push_back(std::move(r));
  }

  // Checks every new lens against every other piece, final or in todo; a lens that comes near
  // another piece is bounded or halved (into todo). A lens that passed stays right: the pieces
  // that replace a halved one lie in its hull.
  void check_lenses(std::vector<Piece>& todo);

  [[nodiscard]] Polygon polygon() const;
  void slabs(const Polygon& poly, std::int32_t j,
             const std::function<void(const std::vector<Slice>&, const Rational&)>& each) const;

  FillRule rule_;
  std::int32_t w_, h_;
  std::vector<Final> finals_;
  bool halving_ = true;
};

void CurveAreas::check_lenses(std::vector<Piece>& todo) {
  // Every piece, final or still to be halved (todo, numbered after the finals: the pieces that
  // will replace one lie in its hull), by the pixels its closed box meets (at most 256 of them;
  // longer ones apart).
  const std::size_t nf = finals_.size();
  std::vector<Box> todo_box;
  todo_box.reserve(todo.size());
  for (const Piece& p : todo)
    todo_box.push_back(box_of(p));
  auto box = [&](std::size_t o) -> const Box& {
    return o < nf ? finals_[o].box : todo_box[o - nf];
  };
  auto piece = [&](std::size_t o) -> const Piece& {
    return o < nf ? finals_[o].piece : todo[o - nf];
  };
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<std::size_t>> grid;
  std::vector<std::size_t> wide;
  for (std::size_t k = 0; k < nf + todo.size(); ++k) {
    const Box& b = box(k);
    const auto [i0, i1] = cells_meeting(b.x0, b.x1);
    const auto [j0, j1] = cells_meeting(b.y0, b.y1);
    if ((i1 - i0 + 1) * (j1 - j0 + 1) > 256) {
      wide.push_back(k);
      continue;
    }
    for (std::int64_t j = j0; j <= j1; ++j)
      for (std::int64_t i = i0; i <= i1; ++i)
        grid[{j, i}].push_back(k);
  }
  std::vector<std::size_t> failed;
  for (std::size_t k = 0; k < nf; ++k) {
    Final& f = finals_[k];
    if (f.kind != Kind::kLens || f.checked)
      continue;
    bool ok = true;
    auto test = [&](std::size_t o) {
      if (o == k || !ok || !boxes_meet(f.box, box(o)) || apart(f.piece, piece(o)))
        return;
      // A twin lens passes with it (both pass or both fail: they meet the same pieces).
      if (!(o < nf && finals_[o].kind == Kind::kLens && twins(f.piece, finals_[o].piece)))
        ok = false;
    };
    if (const auto it = grid.find({f.cj, f.ci}); it != grid.end())
      for (const std::size_t o : it->second)
        test(o);
    for (const std::size_t o : wide)
      test(o);
    if (ok)
      f.checked = true;
    else
      failed.push_back(k);
  }
  // Remove the failed lenses (from the back, so that the indices stay right) and cut them.
  for (auto it = failed.rbegin(); it != failed.rend(); ++it) {
    Piece p = std::move(finals_[*it].piece);
    finals_[*it] = std::move(finals_.back());
    finals_.pop_back();
    bound_or_halve(std::move(p), todo);
  }
}

Polygon CurveAreas::polygon() const {
  const std::int32_t w = w_, h = h_;
  Polygon poly;
  std::vector<Chord>& chords = poly.chords;
  auto& by_row = poly.by_row;
  by_row.resize(static_cast<std::size_t>(h));
  auto& bound = poly.bound;
  bound.resize(static_cast<std::size_t>(h));
  auto& lens_dw = poly.lens_dw;
  for (std::size_t k = 0; k < finals_.size(); ++k) {
    const Final& f = finals_[k];
    if (f.kind == Kind::kBounded && f.twice_area != 0) {
      const auto [i0, i1] = cells_meeting(f.box.x0, f.box.x1);
      const auto [j0, j1] = cells_meeting(f.box.y0, f.box.y1);
      for (std::int64_t j = std::max<std::int64_t>(j0, 0); j <= std::min<std::int64_t>(j1, h - 1);
           ++j)
        for (std::int64_t i = std::max<std::int64_t>(i0, 0); i <= std::min<std::int64_t>(i1, w - 1);
             ++i)
          bound[static_cast<std::size_t>(j)][i] += f.twice_area;
    }
    const RPoint& a = f.piece.p[0];
    const RPoint& b = f.piece.p[static_cast<std::size_t>(f.piece.n)];
    if (a.y == b.y)
      continue; // horizontal: never crossed (a lens never has a horizontal chord)
    Chord c;
    const bool down = a.y < b.y;
    const RPoint& top = down ? a : b;
    const RPoint& bot = down ? b : a;
    c.xa = raw_of(top.x);
    c.ya = raw_of(top.y);
    c.xb = raw_of(bot.x);
    c.yb = raw_of(bot.y);
    c.slope = (c.xb - c.xa) / (c.yb - c.ya);
    c.xmin = std::min(c.xa, c.xb);
    c.xmax = std::max(c.xa, c.xb);
    c.dir = down ? 1 : -1;
    if (f.kind == Kind::kLens) {
      c.lens = k;
      c.lens_right = orient(top, bot, f.piece.p[1]) < 0;
    }
    const std::int64_t j0 = std::max<std::int64_t>(0, cell_of(top.y));
    const std::int64_t j1 = std::min<std::int64_t>(h - 1, -cell_of(-bot.y) - 1);
    for (std::int64_t j = j0; j <= j1; ++j)
      by_row[static_cast<std::size_t>(j)].push_back(chords.size());
    chords.push_back(std::move(c));
  }
  // Twin lenses (the same curve piece drawn more than once) are one region: its winding number
  // changes by the sum of their signs, added once, by the first of them.
  {
    std::map<std::vector<I128>, std::size_t> first;
    for (std::size_t k = 0; k < finals_.size(); ++k) {
      const Final& f = finals_[k];
      if (f.kind != Kind::kLens)
        continue;
      std::vector<I128> key, rev;
      for (int i = 0; i <= f.piece.n; ++i) {
        const RPoint& q = f.piece.p[static_cast<std::size_t>(i)];
        const RPoint& r = f.piece.p[static_cast<std::size_t>(f.piece.n - i)];
        key.insert(key.end(), {q.x, q.y});
        rev.insert(rev.end(), {r.x, r.y});
      }
      const auto [it, fresh] = first.emplace(std::min(key, rev), k);
      lens_dw[it->second] += sign_of(f.twice_area);
    }
  }
  return poly;
}

// Calls each(slices, height) for every slab of row j, its chords sorted left to right.
void CurveAreas::slabs(
    const Polygon& poly, std::int32_t j,
    const std::function<void(const std::vector<Slice>&, const Rational&)>& each) const {
  const std::vector<Chord>& chords = poly.chords;
  const std::vector<std::size_t>& in_row = poly.by_row[static_cast<std::size_t>(j)];
  const Rational y0(std::int64_t{j} * kSubpixelOne), y1 = y0 + kSubpixelOne;
  // Cut heights: the row's top and bottom, every end inside it, every crossing of two chords.
  std::vector<Rational> cuts{y0, y1};
  for (const std::size_t k : in_row) {
    const Chord& e = chords[k];
    if (e.ya > y0)
      cuts.push_back(e.ya);
    if (e.yb < y1)
      cuts.push_back(e.yb);
  }
  // The row's chords by their top ends; a sweep down them meets each pair that overlaps in y
  // once, while both are active.
  std::vector<std::size_t> order = in_row;
  std::sort(order.begin(), order.end(),
            [&](std::size_t p, std::size_t q) { return chords[p].ya < chords[q].ya; });
  std::vector<std::size_t> active;
  for (const std::size_t m : order) {
    const Chord& e = chords[m];
    std::erase_if(active, [&](std::size_t q) { return chords[q].yb <= e.ya; });
    for (const std::size_t q : active) {
      const Chord& f = chords[q];
      if (e.xmax < f.xmin || f.xmax < e.xmin)
        continue; // apart in x: they cannot cross
      const Rational lo = std::max({e.ya, f.ya, y0});
      const Rational hi = std::min({e.yb, f.yb, y1});
      if (lo >= hi)
        continue;
      const Rational dlo = e.x_at(lo) - f.x_at(lo);
      const Rational dhi = e.x_at(hi) - f.x_at(hi);
      if ((dlo < 0 && dhi > 0) || (dlo > 0 && dhi < 0))
        cuts.push_back(lo + (hi - lo) * dlo / (dlo - dhi));
    }
    active.push_back(m);
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  std::vector<Slice> slices;
  active.clear();
  std::size_t next = 0; // into order
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const Rational& ya = cuts[k];
    const Rational& yb = cuts[k + 1];
    // Every end inside the row is a cut: the chords over the slab are those begun by its top
    // and not ended there.
    for (; next < order.size() && chords[order[next]].ya <= ya; ++next)
      active.push_back(order[next]);
    std::erase_if(active, [&](std::size_t q) { return chords[q].yb <= ya; });
    slices.clear();
    for (const std::size_t m : active) {
      const Chord& e = chords[m];
      Rational xa = e.x_at(ya), xb = e.x_at(yb);
      Rational key = xa + xb; // twice the x at mid-slab: no two chords cross inside the slab
      slices.push_back(Slice{&e, std::move(xa), std::move(xb), std::move(key)});
    }
    std::sort(slices.begin(), slices.end(),
              [](const Slice& p, const Slice& q) { return p.key < q.key; });
    each(slices, yb - ya);
  }
}

// Records, for every lens chord among the slices, the winding number on its lens's side (the
// same all along it: nothing else comes into the lens): left of every chord equal to it in the
// slab (its twins'), or right of them all.
void lens_sides(const std::vector<Slice>& slices, std::map<std::size_t, std::int64_t>& lens_w) {
  std::int64_t wn = 0, before_equal = 0;
  for (std::size_t m = 0; m < slices.size(); ++m) {
    const Chord& e = *slices[m].e;
    if (m == 0 || slices[m - 1].key != slices[m].key)
      before_equal = wn;
    wn -= e.dir;
    if (e.lens && !e.lens_right)
      lens_w.emplace(*e.lens, before_equal);
    if (m + 1 == slices.size() || slices[m + 1].key != slices[m].key) {
      for (std::size_t q = m + 1; q-- > 0 && slices[q].key == slices[m].key;)
        if (slices[q].e->lens && slices[q].e->lens_right)
          lens_w.emplace(*slices[q].e->lens, wn);
    }
  }
}

void CurveAreas::emit(const std::function<void(const AreaCoverage&)>& out,
                      const std::vector<std::uint8_t>* only) const {
  const std::int32_t w = w_, h = h_;
  const Polygon poly = polygon();
  RowAreas row(w);
  const Rational pixel_area(std::int64_t{kSubpixelOne} * kSubpixelOne);
  for (std::int32_t j = 0; j < h; ++j) {
    const std::map<std::int64_t, Rational>& extra = poly.bound[static_cast<std::size_t>(j)];
    if (poly.by_row[static_cast<std::size_t>(j)].empty() && extra.empty())
      continue;
    if (only != nullptr && (*only)[static_cast<std::size_t>(j)] == 0)
      continue;
    std::map<std::size_t, std::int64_t> lens_w;
    slabs(poly, j, [&](const std::vector<Slice>& slices, const Rational& hgt) {
      lens_sides(slices, lens_w);
      std::int64_t wn = 0;
      std::size_t run_start = 0;
      bool in_run = false;
      for (std::size_t m = 0; m < slices.size(); ++m) {
        wn -= slices[m].e->dir;
        const bool filled = fill_holds(rule_, wn);
        if (filled && !in_run) {
          run_start = m;
          in_run = true;
        } else if (!filled && in_run) {
          add_run(row, w, slices[run_start].xa, slices[run_start].xb, slices[m].xa, slices[m].xb,
                  hgt);
          in_run = false;
        }
      }
    });
    // The lenses: the area between the arc and its chord, where the fill rule holds on the arc's
    // side and not on the chord's (or the reverse).
    std::map<std::int64_t, Rational> lens_area; // raw^2
    for (const auto& [k, k1] : lens_w) {
      const Final& f = finals_[k];
      const auto dw = poly.lens_dw.find(k);
      if (f.ci < 0 || f.ci >= w || dw == poly.lens_dw.end())
        continue; // outside the target, or a twin of an earlier lens
      const std::int64_t k2 = k1 + dw->second;
      const int change = int{fill_holds(rule_, k2)} - int{fill_holds(rule_, k1)};
      if (change != 0)
        lens_area[f.ci] += change * abs(f.twice_area) / 2;
    }
    std::vector<std::int64_t> cols;
    for (std::int64_t c = row.touched_lo; c <= row.touched_hi; ++c)
      cols.push_back(c);
    for (const auto& [c, v] : lens_area)
      cols.push_back(c);
    for (const auto& [c, v] : extra)
      cols.push_back(c);
    std::sort(cols.begin(), cols.end());
    cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
    Rational running = 0;
    std::int64_t next_full = row.touched_lo; // the difference array is read in column order
    for (const std::int64_t c : cols) {
      Rational a = 0;
      if (c >= row.touched_lo && c <= row.touched_hi) {
        for (; next_full <= c; ++next_full) {
          running += row.full_diff[static_cast<std::size_t>(next_full)];
          row.full_diff[static_cast<std::size_t>(next_full)] = 0;
        }
        a = row.partial[static_cast<std::size_t>(c)] + running;
        row.partial[static_cast<std::size_t>(c)] = 0;
      }
      if (const auto it = lens_area.find(c); it != lens_area.end())
        a += it->second;
      Rational bnd = 0;
      if (const auto it = extra.find(c); it != extra.end())
        bnd = it->second / 2;
      if (a != 0 || bnd != 0)
        out(AreaCoverage{static_cast<std::int32_t>(c), j, a / pixel_area, bnd / pixel_area});
    }
    if (row.touched_hi >= row.touched_lo)
      row.full_diff[static_cast<std::size_t>(row.touched_hi + 1)] = 0;
    row.touched_lo = w;
    row.touched_hi = -1;
  }
}

// The parts of pixel (x, y) by winding number: between consecutive chords of a slab the
// polygon's winding number is constant, and the area of the column between them is the
// difference of their column integrals; a lens in the pixel moves its area from the winding
// number on its chord's side to the curve's.
PixelWindings CurveAreas::windings(std::int32_t x, std::int32_t y) const {
  const Polygon poly = polygon();
  std::map<std::int64_t, Rational> part; // raw^2, by winding number
  std::map<std::size_t, std::int64_t> lens_w;
  const std::int64_t lo = std::int64_t{x} * kSubpixelOne;
  slabs(poly, y, [&](const std::vector<Slice>& slices, const Rational& hgt) {
    lens_sides(slices, lens_w);
    Rational left = 0; // the column's area left of the chord passed last
    std::int64_t wn = 0;
    for (const Slice& sl : slices) {
      const Rational upto = column_integral(sl.xa, sl.xb, hgt, lo);
      part[wn] += upto - left;
      left = upto;
      wn -= sl.e->dir;
    }
    part[wn] += Rational(kSubpixelOne) * hgt - left;
  });
  for (const auto& [k, k1] : lens_w) {
    const Final& f = finals_[k];
    const auto dw = poly.lens_dw.find(k);
    if (f.ci != x || dw == poly.lens_dw.end() || dw->second == 0)
      continue;
    const Rational a = abs(f.twice_area) / 2;
    part[k1] -= a;
    part[k1 + dw->second] += a;
  }
  PixelWindings out;
  const Rational pixel_area(std::int64_t{kSubpixelOne} * kSubpixelOne);
  for (const auto& [k, a] : part)
    if (a != 0)
      out.parts.push_back(WindingArea{k, a / pixel_area, fill_holds(rule_, k)});
  if (const auto it = poly.bound[static_cast<std::size_t>(y)].find(x);
      it != poly.bound[static_cast<std::size_t>(y)].end())
    out.error_bound = it->second / 2 / pixel_area;
  return out;
}

} // namespace

// rule: PATH.AREA.EXACT, PATH.AREA.CURVE
PixelWindings pixel_windings(const Boundary& b, FillRule rule, std::int32_t x, std::int32_t y,
                             std::int32_t w, std::int32_t h) {
  return CurveAreas(b, rule, w, h).windings(x, y);
}

// rule: PATH.AREA.CURVE, PATH.AREA.EXACT
void cover_area_curves(const Boundary& b, FillRule rule, std::int32_t w, std::int32_t h,
                       const std::function<void(const AreaCoverage&)>& emit,
                       const std::vector<std::uint8_t>* only) {
  CurveAreas(b, rule, w, h).emit(emit, only);
}

} // namespace rastrules::path::detail
