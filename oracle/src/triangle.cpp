// SPDX-License-Identifier: MIT
// Oracle triangle coverage: the TRI.* rules decided the way spec/rules/tri.md words them,
// with CGAL's exact predicates for orientation and point location and GMP rationals for the
// left/right classification. No kernel code, no kernel formula (no edge functions, no bias,
// no normalisation of the vertex order).
// Implements (as oracle): TRI.ORIENT.AREA, TRI.DEGENERATE.ZERO_AREA, TRI.CULL.MODE,
//   TRI.FILL.TOP_EDGE, TRI.FILL.LEFT_EDGE, TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION,
//   TRI.COVER.SAMPLE, RASTER.TARGET.CLIP

#include <array>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>

#include "rastrules/oracle/triangle.hpp"

namespace rastrules::oracle {
namespace {

// Points are built from raw 16.8 integers converted to double. Every raw value the oracle
// sees has magnitude below 2^25, so the conversion is exact, and CGAL's filtered predicates
// (orientation, bounded_side, has_on) are exact on exact inputs: no decision below rounds.
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using Q = CGAL::Gmpq;
using Raw = std::array<std::int64_t, 2>;

Point to_point(const Raw& r) {
  constexpr std::int64_t kExactLimit = std::int64_t{1} << 52;
  if (std::llabs(r[0]) >= kExactLimit || std::llabs(r[1]) >= kExactLimit) {
    throw std::invalid_argument("oracle: coordinate too large to be exact in a double");
  }
  return Point(static_cast<double>(r[0]), static_cast<double>(r[1]));
}

// The four kinds of edge named by TRI.FILL.CONVENTION.
enum class EdgeKind { kTop, kBottom, kLeft, kRight };

// Returns the kind of edge (a, b) of a non-degenerate triangle whose third vertex is c, by the
// spec's words:
//   top:    exactly horizontal (a.y == b.y) and the third vertex below it (greater y, y down);
//   bottom: exactly horizontal and the third vertex above it;
//   left:   not horizontal and the third vertex strictly on the +x side of the edge's line,
//           found by computing the line's x at the third vertex's y exactly;
//   right:  not horizontal and the third vertex strictly on the -x side.
// rule: TRI.FILL.TOP_EDGE, TRI.FILL.LEFT_EDGE, TRI.FILL.CONVENTION
EdgeKind classify(const Raw& a, const Raw& b, const Raw& c) {
  if (a[1] == b[1]) {
    if (c[1] == a[1])
      throw std::logic_error("oracle: classify called on a degenerate triangle");
    return c[1] > a[1] ? EdgeKind::kTop : EdgeKind::kBottom;
  }
  // x of the line through a and b at height c.y: a.x + (b.x - a.x) (c.y - a.y) / (b.y - a.y).
  const Q line_x = Q(a[0]) + Q(b[0] - a[0]) * Q(c[1] - a[1]) / Q(b[1] - a[1]);
  const Q third_x = Q(c[0]);
  if (third_x == line_x)
    throw std::logic_error("oracle: classify called on a degenerate triangle");
  return third_x > line_x ? EdgeKind::kLeft : EdgeKind::kRight;
}

// rule: TRI.FILL.CONVENTION
bool is_inclusive(EdgeKind k, FillSides c) {
  switch (k) {
  case EdgeKind::kTop:
    return c.top;
  case EdgeKind::kBottom:
    return !c.top;
  case EdgeKind::kLeft:
    return c.left;
  case EdgeKind::kRight:
    return !c.left;
  }
  return false;
}

// A triangle decided once: whether it draws at all, and which of its edges are inclusive.
struct Prepared {
  bool drawn = false;
  std::array<Point, 3> p{};
  std::array<bool, 3> inclusive{}; // edge i joins p[i] and p[(i + 1) % 3]
};

Prepared prepare(const std::array<Raw, 3>& v, const State& state) {
  const FillSides conv = parse_fill(state.fill);
  Prepared t;
  for (std::size_t i = 0; i < 3; ++i)
    t.p[i] = to_point(v[i]);
  // Winding. CGAL::orientation(p, q, r) is the sign of
  //   (q.x - p.x)(r.y - p.y) - (q.y - p.y)(r.x - p.x),
  // LEFT_TURN when positive, which is counter-clockwise for axes with y pointing up. Window
  // coordinates have y pointing down (COORD.PIXEL.ORIGIN): a mirror image of those axes, and a
  // mirror reverses every turn. So CGAL's LEFT_TURN is clockwise on screen and RIGHT_TURN is
  // counter-clockwise. Check: (0,0) -> (1,0) -> (0,1) gives +1, LEFT_TURN; on screen it runs
  // from the top-left corner to the right, then down-left: clockwise.
  // rule: TRI.ORIENT.AREA
  const CGAL::Orientation o = CGAL::orientation(t.p[0], t.p[1], t.p[2]);
  // rule: TRI.DEGENERATE.ZERO_AREA
  if (o == CGAL::COLLINEAR)
    return t; // covers nothing, whatever the cull mode
  const bool clockwise = (o == CGAL::LEFT_TURN);
  // rule: TRI.CULL.MODE
  bool front_facing = false;
  if (state.front_face == "cw") {
    front_facing = clockwise;
  } else if (state.front_face == "ccw") {
    front_facing = !clockwise;
  } else {
    throw std::invalid_argument("oracle: unknown front face '" + state.front_face + "'");
  }
  if (state.cull == "back") {
    if (!front_facing)
      return t;
  } else if (state.cull == "front") {
    if (front_facing)
      return t;
  } else if (state.cull != "none") {
    throw std::invalid_argument("oracle: unknown cull mode '" + state.cull + "'");
  }
  for (std::size_t i = 0; i < 3; ++i) {
    const EdgeKind k = classify(v[i], v[(i + 1) % 3], v[(i + 2) % 3]);
    t.inclusive[i] = is_inclusive(k, conv);
  }
  t.drawn = true;
  return t;
}

// A sample is covered iff it lies strictly inside the triangle, or on its boundary and every
// edge whose closed segment contains it is inclusive ("If two edges from the same triangle
// touch the pixel center, then if both edges are 'top' or 'left' then the sample is inside").
// rule: TRI.FILL.TOP_LEFT, TRI.COVER.SAMPLE
bool covers_prepared(const Prepared& t, const Point& s) {
  if (!t.drawn)
    return false;
  const K::Triangle_2 tri(t.p[0], t.p[1], t.p[2]);
  switch (tri.bounded_side(s)) {
  case CGAL::ON_BOUNDED_SIDE:
    return true;
  case CGAL::ON_UNBOUNDED_SIDE:
    return false;
  case CGAL::ON_BOUNDARY:
    break;
  }
  for (std::size_t i = 0; i < 3; ++i) {
    const K::Segment_2 edge(t.p[i], t.p[(i + 1) % 3]);
    if (edge.has_on(s) && !t.inclusive[i])
      return false;
  }
  return true;
}

} // namespace

// rule: TRI.FILL.CONVENTION
FillSides parse_fill(const std::string& fill) {
  if (fill == "top-left")
    return {true, true};
  if (fill == "top-right")
    return {true, false};
  if (fill == "bottom-left")
    return {false, true};
  if (fill == "bottom-right")
    return {false, false};
  throw std::invalid_argument("oracle: unknown fill convention '" + fill + "'");
}

// rule: TRI.ORIENT.AREA
int winding(const std::array<std::array<std::int64_t, 2>, 3>& snapped) {
  // LEFT_TURN is clockwise on screen: see the derivation in prepare().
  switch (CGAL::orientation(to_point(snapped[0]), to_point(snapped[1]), to_point(snapped[2]))) {
  case CGAL::LEFT_TURN:
    return 1;
  case CGAL::RIGHT_TURN:
    return -1;
  default:
    return 0;
  }
}

bool covers(const std::array<std::array<std::int64_t, 2>, 3>& snapped,
            const std::array<std::int64_t, 2>& sample, const State& state) {
  return covers_prepared(prepare(snapped, state), to_point(sample));
}

// rule: TRI.COVER.SAMPLE, RASTER.TARGET.CLIP
std::vector<Fragment> render(const Scene& scene) {
  if (scene.width < 0 || scene.height < 0) {
    throw std::invalid_argument("oracle: negative target size");
  }
  std::vector<Prepared> prepared;
  prepared.reserve(scene.triangles.size());
  for (std::size_t p = 0; p < scene.triangles.size(); ++p) {
    std::array<Raw, 3> v{};
    for (std::size_t i = 0; i < 3; ++i) {
      for (std::size_t k = 0; k < 2; ++k) {
        const std::optional<std::int64_t> r = snap(scene.triangles[p][i][k]);
        if (!r) {
          throw std::invalid_argument("oracle: triangles[" + std::to_string(p) + "].v[" +
                                      std::to_string(i) + "][" + std::to_string(k) +
                                      "] does not snap");
        }
        v[i][k] = *r;
      }
    }
    prepared.push_back(prepare(v, scene.state));
  }
  // Pixel (x, y) has its only sample at (x + 0.5, y + 0.5) px = (256 x + 128, 256 y + 128) raw.
  std::vector<Fragment> out;
  for (std::size_t p = 0; p < prepared.size(); ++p) {
    if (!prepared[p].drawn)
      continue;
    for (std::int32_t y = 0; y < scene.height; ++y) {
      for (std::int32_t x = 0; x < scene.width; ++x) {
        const Point s = to_point({std::int64_t{256} * x + 128, std::int64_t{256} * y + 128});
        if (covers_prepared(prepared[p], s)) {
          out.push_back(Fragment{static_cast<std::uint32_t>(p), x, y});
        }
      }
    }
  }
  return out; // already sorted by (prim, y, x)
}

} // namespace rastrules::oracle
