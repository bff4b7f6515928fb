// SPDX-License-Identifier: MIT
// Property: a triangulated polygon (jittered grid, fan, lattice fan, CGAL Delaunay
// triangulation) rendered by the kernel covers every pixel centre strictly inside its outline
// exactly once and none strictly outside; centres exactly on the outline at most once.
// Implements (properties for): TRI.WATERTIGHT.MESH

#include <array>
#include <cstdint>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "rastrules/gen/triangles.hpp"
#include "rastrules/scene.hpp"

namespace {

namespace gen = rastrules::gen;
// Exact predicates on exact inputs: raw 16.8 integers are exact in double.
using K = CGAL::Exact_predicates_inexact_constructions_kernel;

bool on_segment(const gen::RawPoint& a, const gen::RawPoint& b, std::int64_t x, std::int64_t y) {
  const std::int64_t c =
      (std::int64_t{b[0]} - a[0]) * (y - a[1]) - (std::int64_t{b[1]} - a[1]) * (x - a[0]);
  return c == 0 && std::min(a[0], b[0]) <= x && x <= std::max(a[0], b[0]) &&
         std::min(a[1], b[1]) <= y && y <= std::max(a[1], b[1]);
}

// rule: TRI.WATERTIGHT.MESH, TRI.SHARED_EDGE.EXACTLY_ONCE
RC_GTEST_PROP(TriWatertight, MeshCoversEachInteriorPixelCentreExactlyOnce, ()) {
  constexpr std::int32_t kW = 32, kH = 32;
  const rastrules::FillConvention fill = *gen::fill_convention();
  const gen::Mesh m = *gen::mesh_near(kW, kH);
  RC_TAG(std::string(to_string(m.kind)));
  gen::TriScene s;
  s.width = kW;
  s.height = kH;
  s.state =
      rastrules::RasterState{rastrules::CullMode::kNone, rastrules::FrontFace::kClockwise, fill};
  for (const gen::RawTriangle& t : m.triangles) {
    RC_ASSERT(gen::twice_area(t) != 0); // generator invariant: a triangulation
    s.triangles.push_back(gen::GenTriangle{gen::to_float(t), gen::TriKind::kRandom});
  }
  auto r = rastrules::render(gen::to_kernel_scene(s));
  if (const auto* err = std::get_if<rastrules::SceneError>(&r)) {
    RC_FAIL("kernel rejected a valid mesh: " + err->what());
  }
  std::vector<int> count(static_cast<std::size_t>(kW * kH), 0);
  std::vector<std::vector<std::uint32_t>> by(count.size());
  for (const rastrules::Fragment& f : std::get<std::vector<rastrules::Fragment>>(r)) {
    const auto i = static_cast<std::size_t>(f.y * kW + f.x);
    ++count[i];
    by[i].push_back(f.prim);
  }
  std::vector<K::Point_2> outline;
  for (const gen::RawPoint& p : m.outline)
    outline.emplace_back(p[0], p[1]);
  bool centre_on_outline = false, centre_on_inner_edge = false;
  for (std::int32_t y = 0; y < kH; ++y) {
    for (std::int32_t x = 0; x < kW; ++x) {
      const std::int64_t sx = 256 * std::int64_t{x} + 128, sy = 256 * std::int64_t{y} + 128;
      const CGAL::Bounded_side side =
          CGAL::bounded_side_2(outline.begin(), outline.end(),
                               K::Point_2(static_cast<double>(sx), static_cast<double>(sy)), K());
      const int n = count[static_cast<std::size_t>(y * kW + x)];
      const int want_min = side == CGAL::ON_BOUNDED_SIDE ? 1 : 0;
      const int want_max = side == CGAL::ON_UNBOUNDED_SIDE ? 0 : 1;
      if (n < want_min || n > want_max) {
        std::ostringstream msg;
        msg << "pixel (" << x << ", " << y << ") centre raw (" << sx << ", " << sy << ") is "
            << (side == CGAL::ON_BOUNDED_SIDE ? "inside"
                : side == CGAL::ON_BOUNDARY   ? "on"
                                              : "outside")
            << " the outline and covered " << n << " times, by primitives";
        for (const std::uint32_t p : by[static_cast<std::size_t>(y * kW + x)])
          msg << " " << p;
        msg << " (fill " << to_string(fill) << ")";
        RC_FAIL(msg.str());
      }
      centre_on_outline = centre_on_outline || side == CGAL::ON_BOUNDARY;
      if (side == CGAL::ON_BOUNDED_SIDE && !centre_on_inner_edge) {
        for (const gen::RawTriangle& t : m.triangles) {
          for (std::size_t i = 0; i < 3; ++i) {
            centre_on_inner_edge = centre_on_inner_edge || on_segment(t[i], t[(i + 1) % 3], sx, sy);
          }
        }
      }
    }
  }
  RC_CLASSIFY(centre_on_inner_edge, "pixel centre on an inner edge or vertex");
  RC_CLASSIFY(centre_on_outline, "pixel centre on the outline");
}

} // namespace
