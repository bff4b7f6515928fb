// SPDX-License-Identifier: MIT
// Properties: the cell method of exact area coverage (PATH.AREA.CELLS) gives every pixel the
// same exact area as the slab method (PATH.AREA.EXACT's computation) on random paths of lines:
// the generators' paths (ties on the pixel grid, stars, nested and repeated contours, far
// vertices), paths off the grid lines (where the cells decide nearly every row), many contours
// crossing in a few pixels (where they must decline), and glyph-like rings. Each case prints
// how many rows each method decided. The 8-bit alphas of every method (the certified
// floating-point cells of PATH.AREA.FAST too) are those of the exact
// areas (PATH.AREA.ALPHA).
// Implements (properties for): PATH.AREA.CELLS, PATH.AREA.EXACT, PATH.AREA.ALPHA, PATH.AREA.FAST

#include <cstdint>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "path_checks.hpp"
#include "path_detail.hpp"
#include "path_gen.hpp"
#include "path_kernel.hpp"
#include "rastrules/path.hpp"

namespace {

namespace pg = rastrules::path_gen;
namespace pc = rastrules::path_checks;
namespace kp = rastrules::path;
namespace kd = rastrules::path::detail;
using pc::show_path;
using pg::Raw2;
using rastrules::path_kernel::to_kernel;

using Areas = std::map<std::pair<std::int32_t, std::int32_t>, std::string>;

Areas areas_by(const kp::Path& p, std::int32_t side, kd::AreaMethod m, kd::AreaRows& rows) {
  Areas a;
  kd::cover_area_by(
      p, side, side, m,
      [&](const kp::AreaCoverage& c) {
        const auto [it, fresh] = a.emplace(std::pair{c.y, c.x}, c.area.str());
        RC_ASSERT(fresh); // each pixel once
        RC_ASSERT(c.area != 0);
        RC_ASSERT(c.error_bound == 0);
      },
      &rows);
  return a;
}

std::string difference(const Areas& cells, const Areas& slabs) {
  for (const auto& [px, v] : slabs) {
    const auto c = cells.find(px);
    if (c == cells.end() || c->second != v) {
      std::ostringstream os;
      os << "pixel (" << px.second << ", " << px.first << "): slabs " << v << ", cells "
         << (c == cells.end() ? std::string("nothing") : c->second);
      return os.str();
    }
  }
  if (cells.size() != slabs.size())
    return "the cells list a pixel the slabs do not";
  return "";
}

void check_methods_agree(const pg::GPath& g, std::int32_t side) {
  show_path(g);
  const kp::Path p = to_kernel(g);
  kd::AreaRows by_cells, by_slabs;
  const Areas cells = areas_by(p, side, kd::AreaMethod::kCells, by_cells);
  const Areas slabs = areas_by(p, side, kd::AreaMethod::kSlabs, by_slabs);
  RC_ASSERT(by_slabs.cells == 0u);
  RC_ASSERT(by_cells.cells + by_cells.slabs == by_slabs.slabs);
  RC_CLASSIFY(by_cells.cells > 0 && by_cells.slabs == 0, "every row by cells");
  RC_CLASSIFY(by_cells.cells > 0 && by_cells.slabs > 0, "rows by cells and by slabs");
  RC_CLASSIFY(by_cells.cells == 0 && by_cells.slabs > 0, "every row by slabs");
  const std::string d = difference(cells, slabs);
  if (!d.empty())
    RC_FAIL(d);
  // The 8-bit alphas (PATH.AREA.ALPHA), by both methods: floor(255 a + 1/2) of those areas.
  const auto stride = static_cast<std::size_t>(side);
  std::vector<std::uint8_t> expected(stride * stride, 0);
  kd::cover_area_by(
      p, side, side, kd::AreaMethod::kSlabs,
      [&](const kp::AreaCoverage& c) {
        expected[static_cast<std::size_t>(c.y) * stride + static_cast<std::size_t>(c.x)] =
            kd::alpha_of(c.area);
      },
      nullptr);
  for (const kd::AreaMethod m : {kd::AreaMethod::kCells, kd::AreaMethod::kSlabs,
                                 kd::AreaMethod::kFast, kd::AreaMethod::kSweep}) {
    std::vector<std::uint8_t> alpha(expected.size(), 7);
    kd::AreaRows rows;
    kd::cover_alpha_by(p, side, side, m, alpha, &rows);
    if (m == kd::AreaMethod::kFast) { // PATH.AREA.FAST: the rows it decides, and the others
      RC_CLASSIFY(rows.fast == static_cast<std::size_t>(side), "fast: every row");
      RC_CLASSIFY(rows.fast > 0 && rows.fast < static_cast<std::size_t>(side), "fast: some rows");
      RC_CLASSIFY(rows.fast == 0, "fast: no row");
    }
    if (m == kd::AreaMethod::kSweep) { // PATH.AREA.SWEEP: the rows it decides, and the others
      RC_CLASSIFY(rows.swept == static_cast<std::size_t>(side), "sweep: every row");
      RC_CLASSIFY(rows.swept > 0 && rows.swept < static_cast<std::size_t>(side),
                  "sweep: some rows");
    }
    for (std::size_t k = 0; k < alpha.size(); ++k)
      if (alpha[k] != expected[k])
        RC_FAIL("alpha by method " + std::to_string(static_cast<int>(m)) + " at pixel (" +
                std::to_string(k % stride) + ", " + std::to_string(k / stride) +
                "): " + std::to_string(alpha[k]) + ", exact " + std::to_string(expected[k]));
  }
}

// A raw coordinate in [-1, side + 1] px that is not on a grid line.
rc::Gen<std::int64_t> off_grid(std::int32_t side) {
  return rc::gen::map(rc::gen::inRange<std::int64_t>(-255, std::int64_t{side} * 256 + 256),
                      [](std::int64_t v) { return (v & 255) == 0 ? v + 1 : v; });
}

pg::GContour off_grid_polygon(std::int32_t side, int lo, int hi) {
  const int n = *rc::gen::inRange(lo, hi + 1);
  std::vector<Raw2> v;
  for (int i = 0; i < n; ++i)
    v.push_back(Raw2{*off_grid(side), *off_grid(side)});
  return pg::polygon(v);
}

// rule: PATH.AREA.CELLS, PATH.AREA.EXACT, PATH.AREA.ALPHA, PATH.AREA.SWEEP
RC_GTEST_PROP(PathAreaCells, EqualSlabsOnTheGeneratorsPaths, ()) {
  const pg::GPath g = *pg::path(pc::kSide, false);
  RC_TAG(pg::name(g.kind), pg::fill_rule(g));
  check_methods_agree(g, pc::kSide);
}

// rule: PATH.AREA.CELLS, PATH.AREA.EXACT, PATH.AREA.ALPHA, PATH.AREA.SWEEP
RC_GTEST_PROP(PathAreaCells, EqualSlabsOffTheGridLines, ()) {
  constexpr std::int32_t kBig = 12;
  pg::GPath g;
  g.evenodd = *rc::gen::arbitrary<bool>();
  const int n = *rc::gen::inRange(1, 4);
  for (int i = 0; i < n; ++i)
    g.contours.push_back(off_grid_polygon(kBig, 3, 12));
  check_methods_agree(g, kBig);
}

// Many small contours in a few pixels: crossings and several windings in most cells.
// rule: PATH.AREA.CELLS, PATH.AREA.EXACT, PATH.AREA.ALPHA, PATH.AREA.SWEEP
RC_GTEST_PROP(PathAreaCells, EqualSlabsWhereManyContoursCross, ()) {
  pg::GPath g;
  g.evenodd = *rc::gen::arbitrary<bool>();
  const int n = *rc::gen::inRange(2, 9);
  for (int i = 0; i < n; ++i)
    g.contours.push_back(off_grid_polygon(2, 3, 5));
  check_methods_agree(g, 3);
}

// Rings like a glyph's: a polygon and a smaller one inside it, reversed or not, sampled from
// circles (many short edges per cell).
// rule: PATH.AREA.CELLS, PATH.AREA.EXACT, PATH.AREA.ALPHA, PATH.AREA.SWEEP
RC_GTEST_PROP(PathAreaCells, EqualSlabsOnRings, ()) {
  constexpr std::int32_t kBig = 10;
  pg::GPath g;
  g.evenodd = *rc::gen::arbitrary<bool>();
  const int sides = *rc::gen::inRange(8, 80);
  const Raw2 c{*rc::gen::inRange<std::int64_t>(1000, 1600),
               *rc::gen::inRange<std::int64_t>(1000, 1600)};
  const double r_out = *rc::gen::inRange(300, 1200);
  const double r_in = r_out * *rc::gen::inRange(20, 95) / 100.0;
  g.contours.push_back(pg::polygon(pg::star_points(c, r_out, sides, 1, 0.0, 1)));
  pg::GContour inner = pg::polygon(pg::star_points(c, r_in, sides, 1, 0.5, 1));
  if (*rc::gen::arbitrary<bool>())
    inner = pg::reversed(inner);
  g.contours.push_back(inner);
  check_methods_agree(g, kBig);
}

} // namespace
