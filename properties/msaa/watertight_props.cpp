// SPDX-License-Identifier: MIT
// Property: WATERTIGHT ADJACENCY PER SAMPLE. A triangulated polygon (the tri area's jittered
// grids, fans, lattice fans and Delaunay triangulations, plus jittered grids with every vertex
// on the 1/16 sample grid so that samples fall on shared edges and vertices) rendered with
// every standard pattern, a centre pattern and a random custom pattern covers every sample
// strictly inside its outline exactly once, none strictly outside, and samples exactly on the
// outline at most once; each covered sample is decided by the exact outline test.
// Implements (properties for): MSAA.COVER.SAMPLE, TRI.WATERTIGHT.MESH (per sample)

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

#include "msaa_gen.hpp"
#include "rastrules/gen/triangles.hpp"
#include "rastrules/oracle/msaa.hpp"
#include "rastrules/scene.hpp"

namespace {

namespace gen = rastrules::gen;
namespace mg = rastrules::msaa_gen;
namespace om = rastrules::oracle::msaa;
// Exact predicates on exact inputs: raw 16.8 integers are exact in double.
using K = CGAL::Exact_predicates_inexact_constructions_kernel;

constexpr std::int32_t kSide = 14;

// A jittered grid whose vertices all lie on the 1/16 px sample grid (multiples of 16 raw).
// Jitter below s/8 per coordinate keeps each cell convex (as gen::mesh_near's grids).
rc::Gen<gen::Mesh> sample_grid_mesh() {
  return mg::full_size<gen::Mesh>(rc::gen::exec([] {
    gen::Mesh m;
    m.kind = gen::MeshKind::kJitteredGrid;
    const std::int32_t k = *rc::gen::inRange(8, 33); // cell side 16 k raw: 1/2 to 2 px
    const std::int32_t s = 16 * k;
    const std::int32_t jmax = (k - 1) / 8; // 16 jmax < s / 8
    const auto nx = static_cast<std::size_t>(*rc::gen::inRange(1, 7));
    const auto ny = static_cast<std::size_t>(*rc::gen::inRange(1, 7));
    const std::int32_t ox = 16 * *rc::gen::inRange(-16, 16 * kSide / 2);
    const std::int32_t oy = 16 * *rc::gen::inRange(-16, 16 * kSide / 2);
    std::vector<std::vector<gen::RawPoint>> v(nx + 1, std::vector<gen::RawPoint>(ny + 1));
    for (std::size_t i = 0; i <= nx; ++i) {
      for (std::size_t j = 0; j <= ny; ++j) {
        const std::int32_t jx = jmax > 0 ? 16 * *rc::gen::inRange(-jmax, jmax + 1) : 0;
        const std::int32_t jy = jmax > 0 ? 16 * *rc::gen::inRange(-jmax, jmax + 1) : 0;
        v[i][j] = {ox + static_cast<std::int32_t>(i) * s + jx,
                   oy + static_cast<std::int32_t>(j) * s + jy};
      }
    }
    for (std::size_t i = 0; i < nx; ++i) {
      for (std::size_t j = 0; j < ny; ++j) {
        const gen::RawPoint p00 = v[i][j], p10 = v[i + 1][j], p01 = v[i][j + 1],
                            p11 = v[i + 1][j + 1];
        if (*rc::gen::arbitrary<bool>()) {
          m.triangles.push_back({p00, p10, p11});
          m.triangles.push_back({p11, p01, p00}); // the other winding on purpose
        } else {
          m.triangles.push_back({p00, p10, p01});
          m.triangles.push_back({p10, p11, p01});
        }
      }
    }
    for (std::size_t i = 0; i <= nx; ++i)
      m.outline.push_back(v[i][0]);
    for (std::size_t j = 1; j <= ny; ++j)
      m.outline.push_back(v[nx][j]);
    for (std::size_t i = nx; i-- > 0;)
      m.outline.push_back(v[i][ny]);
    for (std::size_t j = ny; j-- > 1;)
      m.outline.push_back(v[0][j]);
    return m;
  }));
}

// rule: MSAA.COVER.SAMPLE
RC_GTEST_PROP(MsaaWatertight, MeshCoversEachInteriorSampleExactlyOnceForEveryPattern, ()) {
  const gen::Mesh mesh = *rc::gen::weightedOneOf<gen::Mesh>(
      {{1, mg::full_size(gen::mesh_near(kSide, kSide))}, {1, sample_grid_mesh()}});
  const rastrules::FillConvention fill = *gen::fill_convention();
  RC_TAG(std::string(gen::to_string(mesh.kind)));
  std::vector<mg::Pattern> patterns;
  for (const std::uint32_t n : mg::standard_counts())
    patterns.push_back(mg::standard(n));
  patterns.push_back(mg::centre(*rc::gen::element(2u, 4u, 8u, 16u)));
  patterns.push_back(mg::custom(*mg::custom_offsets()));

  std::vector<K::Point_2> outline;
  for (const gen::RawPoint& p : mesh.outline)
    outline.emplace_back(p[0], p[1]);
  bool on_inner = false;
  for (const mg::Pattern& pat : patterns) {
    mg::MsScene s;
    s.width = kSide;
    s.height = kSide;
    s.state =
        rastrules::RasterState{rastrules::CullMode::kNone, rastrules::FrontFace::kClockwise, fill};
    s.pattern = pat;
    s.sample_mask = rastrules::full_mask(pat.count());
    for (const gen::RawTriangle& t : mesh.triangles) {
      RC_ASSERT(gen::twice_area(t) != 0);
      mg::Prim p;
      for (const gen::RawPoint& q : t)
        p.v.push_back(om::Raw2{q[0], q[1]});
      s.prims.push_back(p);
    }
    auto r = rastrules::render(mg::to_kernel(s));
    if (const auto* err = std::get_if<rastrules::SceneError>(&r))
      RC_FAIL(err->what());
    const std::size_t n = pat.count();
    std::vector<int> count(static_cast<std::size_t>(kSide * kSide) * n, 0);
    for (const rastrules::Fragment& f : std::get<std::vector<rastrules::Fragment>>(r)) {
      for (std::size_t k = 0; k < n; ++k) {
        if ((f.mask >> k) & 1u)
          ++count[(static_cast<std::size_t>(f.y * kSide + f.x)) * n + k];
      }
    }
    for (std::int32_t y = 0; y < kSide; ++y) {
      for (std::int32_t x = 0; x < kSide; ++x) {
        for (std::size_t k = 0; k < n; ++k) {
          const om::Raw2 e = om::sample_raw(x, y, pat.oracle[k]);
          const CGAL::Bounded_side side = CGAL::bounded_side_2(
              outline.begin(), outline.end(),
              K::Point_2(static_cast<double>(e[0]), static_cast<double>(e[1])), K());
          const int c = count[static_cast<std::size_t>(y * kSide + x) * n + k];
          const int lo = side == CGAL::ON_BOUNDED_SIDE ? 1 : 0;
          const int hi = side == CGAL::ON_UNBOUNDED_SIDE ? 0 : 1;
          if (c < lo || c > hi) {
            std::ostringstream os;
            os << pat.name() << ": sample " << k << " of pixel (" << x << ", " << y << ") at raw ("
               << e[0] << ", " << e[1] << ") is "
               << (side == CGAL::ON_BOUNDED_SIDE ? "inside"
                   : side == CGAL::ON_BOUNDARY   ? "on"
                                                 : "outside")
               << " the outline and covered " << c << " times (fill " << to_string(fill) << ")";
            RC_FAIL(os.str());
          }
          if (side == CGAL::ON_BOUNDED_SIDE && !on_inner) {
            for (const gen::RawTriangle& t : mesh.triangles) {
              for (std::size_t i = 0; i < 3 && !on_inner; ++i) {
                const gen::RawPoint& a = t[i];
                const gen::RawPoint& b = t[(i + 1) % 3];
                const std::int64_t cr = (std::int64_t{b[0]} - a[0]) * (e[1] - a[1]) -
                                        (std::int64_t{b[1]} - a[1]) * (e[0] - a[0]);
                on_inner = cr == 0 && std::min(a[0], b[0]) <= e[0] &&
                           e[0] <= std::max(a[0], b[0]) && std::min(a[1], b[1]) <= e[1] &&
                           e[1] <= std::max(a[1], b[1]);
              }
            }
          }
        }
      }
    }
  }
  RC_CLASSIFY(on_inner, "a sample on an inner edge or vertex");
}

} // namespace
