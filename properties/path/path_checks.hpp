// SPDX-License-Identifier: MIT
// Checks shared by the oracle's and the kernel's path properties, on coverage in a neutral form
// (pixel -> sample mask, pixel -> exact area): two paths cut from one cover every sample once
// and their areas sum to the whole's; area against the covered fraction of a 4 x 4 grid of
// samples, within the cells the boundary reaches.
// Implements (checks for): PATH.SAMPLE.TIE, PATH.AREA.EXACT

#pragma once

#include <gmpxx.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <bit>
#include <cstdint>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "path_gen.hpp"

namespace rastrules::path_checks {

namespace pg = rastrules::path_gen;
using Pixel = std::pair<std::int32_t, std::int32_t>; // (y, x): row order
using Masks = std::map<Pixel, std::uint32_t>;
using Areas = std::map<Pixel, mpq_class>;

// The side of the target (px) of most properties: small, so that ties are frequent.
inline constexpr std::int32_t kSide = 4;

inline void show_path(const pg::GPath& p) {
  std::ostringstream os;
  pg::show(p, os);
  RC_LOG() << os.str() << "\n";
}

inline mpq_class rational(const std::string& num, const std::string& den) {
  mpq_class q{mpz_class(num), mpz_class(den)};
  q.canonicalize();
  return q;
}

inline std::string str(const Pixel& p) {
  return "pixel (" + std::to_string(p.second) + ", " + std::to_string(p.first) + ")";
}

inline Masks oracle_masks(const pg::GPath& p, const std::vector<oracle::msaa::Offset>& pattern,
                          const std::string& fill, std::int32_t side) {
  Masks m;
  for (const auto& s : oracle::path::cover_samples(pg::to_oracle(p), pattern, fill, side, side))
    m[{s.y, s.x}] = s.mask;
  return m;
}

inline Areas oracle_areas(const pg::GPath& p, std::int32_t side) {
  Areas a;
  for (const auto& s : oracle::path::cover_area(pg::to_oracle(p), side, side))
    a[{s.y, s.x}] = rational(s.num, s.den);
  return a;
}

// Returns the values of three maps side by side, per pixel (missing: T{}).
template <class T>
std::map<Pixel, std::array<T, 3>> side_by_side(const std::map<Pixel, T>& a,
                                               const std::map<Pixel, T>& b,
                                               const std::map<Pixel, T>& c) {
  std::map<Pixel, std::array<T, 3>> all;
  for (std::size_t i = 0; i < 3; ++i) {
    for (const auto& [p, v] : (i == 0 ? a : i == 1 ? b : c))
      all[p][i] = v;
  }
  return all;
}

// Returns "" when the two halves cover every sample the whole covers exactly once and no other
// sample, else the first problem.
inline std::string partition_problem(const Masks& whole, const Masks& first, const Masks& second) {
  for (const auto& [p, m] : side_by_side(whole, first, second)) {
    if ((m[1] & m[2]) != 0 || (m[1] | m[2]) != m[0]) {
      std::ostringstream os;
      os << str(p) << ": whole mask " << m[0] << ", halves " << m[1] << " and " << m[2];
      return os.str();
    }
  }
  return "";
}

// Returns "" when the halves' areas sum to the whole's in every pixel, else the first problem.
inline std::string area_sum_problem(const Areas& whole, const Areas& first, const Areas& second) {
  for (const auto& [p, a] : side_by_side(whole, first, second)) {
    if (a[1] + a[2] != a[0])
      return str(p) + ": whole " + a[0].get_str() + ", halves " + a[1].get_str() + " + " +
             a[2].get_str();
  }
  return "";
}

// A convex polygon cut along a chord (paths[0]) and its halves (paths[1], paths[2]), one fill
// rule for all three, a fill convention and a standard pattern; logged and classified.
struct CutCase {
  std::array<pg::GPath, 3> paths;
  std::string fill;
  std::vector<oracle::msaa::Offset> pattern;
};

inline CutCase cut_case(std::int32_t side) {
  const pg::CutPolygon c = *pg::cut_polygon(side);
  const bool evenodd = *rc::gen::arbitrary<bool>();
  CutCase out;
  out.paths = {pg::GPath{pg::PathKind::kPolygon, evenodd, {c.whole}},
               pg::GPath{pg::PathKind::kPolygon, evenodd, {c.first}},
               pg::GPath{pg::PathKind::kPolygon, evenodd, {c.second}}};
  for (const pg::GPath& p : out.paths)
    show_path(p);
  RC_CLASSIFY(c.chord_polyline, "chord is a polyline");
  out.fill = *rc::gen::elementOf(pg::conventions());
  out.pattern = oracle::msaa::standard_pattern(*rc::gen::element(1u, 4u, 16u));
  const pg::Ties t = pg::ties(out.paths[0], out.pattern, side);
  RC_CLASSIFY(t.on_vertex, "sample on a vertex");
  RC_CLASSIFY(t.on_edge, "sample on an edge");
  return out;
}

// Fails the property unless the halves partition the whole's samples and sum to its areas,
// with masks(path) and areas(path) from one renderer.
template <class MasksOf, class AreasOf>
void check_cut(const CutCase& c, MasksOf masks, AreasOf areas) {
  const std::string problem =
      partition_problem(masks(c.paths[0]), masks(c.paths[1]), masks(c.paths[2]));
  if (!problem.empty())
    RC_FAIL(c.fill + ": " + problem);
  const std::string area =
      area_sum_problem(areas(c.paths[0]), areas(c.paths[1]), areas(c.paths[2]));
  if (!area.empty())
    RC_FAIL(area);
}

// The 4 x 4 grid pattern: sample (i, j) at the centre of the cell [i/4, (i+1)/4] x [j/4,
// (j+1)/4] of the pixel, offsets (-6, -2, 2, 6) / 16 px from the pixel centre, index 4 j + i.
inline std::vector<oracle::msaa::Offset> grid4() {
  std::vector<oracle::msaa::Offset> v;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      v.push_back({-6 + 4 * i, -6 + 4 * j});
  return v;
}

// Returns the mask of the cells of the 4 x 4 grid of pixel (x, y) whose closed square meets a
// straight boundary segment of the path (exact: CGAL's filtered predicates on integers).
inline std::uint32_t cells_touched(const pg::GPath& p, std::int32_t x, std::int32_t y) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::uint32_t m = 0;
  for (const pg::GContour& c : p.contours) {
    const std::vector<pg::Raw2> ends = pg::closed_ends(c);
    for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
      const K::Point_2 a(static_cast<double>(ends[i][0]), static_cast<double>(ends[i][1]));
      const K::Point_2 b(static_cast<double>(ends[i + 1][0]), static_cast<double>(ends[i + 1][1]));
      for (int j = 0; j < 4; ++j) {
        for (int k = 0; k < 4; ++k) {
          const double x0 = 256.0 * x + 64.0 * k, y0 = 256.0 * y + 64.0 * j;
          const K::Iso_rectangle_2 cell(x0, y0, x0 + 64.0, y0 + 64.0);
          const bool hit = a == b ? !cell.has_on_unbounded_side(a)
                                  : CGAL::do_intersect(K::Segment_2(a, b), cell);
          if (hit)
            m |= 1u << (4 * j + k);
        }
      }
    }
  }
  return m;
}

// For a path of lines: every area lies in [0, 1], and in each pixel of the target the area and
// the covered fraction k/16 of the 4 x 4 grid differ by at most t/16, t the number of cells the
// boundary reaches (a cell the boundary misses has one winding number throughout, that of its
// sample, so it adds the same 1/16 or 0 to both). (For a general pattern of N samples no such
// bound holds: a sliver through every sample has area near 0 and fraction 1.)
inline std::string grid_bound_problem(const pg::GPath& p, const Masks& grid_masks,
                                      const Areas& areas, std::int32_t side) {
  for (std::int32_t y = 0; y < side; ++y) {
    for (std::int32_t x = 0; x < side; ++x) {
      const auto ai = areas.find({y, x});
      const mpq_class area = ai == areas.end() ? mpq_class(0) : ai->second;
      if (area < 0 || area > 1)
        return str({y, x}) + ": area " + area.get_str() + " outside [0, 1]";
      const auto mi = grid_masks.find({y, x});
      const std::uint32_t mask = mi == grid_masks.end() ? 0u : mi->second;
      const int touched = std::popcount(cells_touched(p, x, y));
      const mpq_class diff = area - mpq_class(std::popcount(mask)) / 16;
      if (abs(diff) > mpq_class(touched) / 16) {
        std::ostringstream os;
        os << str({y, x}) << ": area " << area.get_str() << ", " << std::popcount(mask)
           << "/16 samples, " << touched << " cells touched";
        return os.str();
      }
    }
  }
  return "";
}

} // namespace rastrules::path_checks
