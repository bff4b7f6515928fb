// SPDX-License-Identifier: MIT
// The smallest use of the installed kernel (rastrules::kernel: no CGAL, GMP, JSON or libpng): build
// a scene in code, rasterize it, print every fragment, then say why one pixel is or is not covered
// by the triangle (its snapped vertices, the edge values at the pixel centre, and the top-left
// rule's verdict on each edge).
#include <cstdio>
#include <string>
#include <variant>
#include <vector>

#include "rastrules/scene.hpp"
#include "rastrules/triangle.hpp"

int main() {
  using namespace rastrules;
  Scene scene;
  scene.width = 8;
  scene.height = 8;
  scene.primitives.push_back(
      make_triangle({FloatPoint{1.0f, 1.0f}, FloatPoint{7.0f, 2.0f}, FloatPoint{2.5f, 6.5f}}));
  Primitive line;
  line.type = PrimitiveType::kLine;
  line.v = {FloatPoint{0.5f, 7.5f}, FloatPoint{7.5f, 5.5f}};
  scene.primitives.push_back(line);

  const auto result = render(scene);
  if (const auto* error = std::get_if<SceneError>(&result)) {
    std::fprintf(stderr, "rasterize: %s\n", error->what().c_str());
    return 2;
  }
  for (const Fragment& f : std::get<std::vector<Fragment>>(result))
    std::printf("prim %u covers (%d, %d)\n", f.prim, f.x, f.y);

  // Why pixel (3, 3) is covered by the triangle: every edge has E > 0 at the pixel centre, or
  // E == 0 on an edge the fill convention includes (TRI.FILL.TOP_LEFT).
  const auto prepared = prepare(scene);
  const PreparedScene& ps = std::get<PreparedScene>(prepared);
  const TriangleSetup& t = ps.primitives[0].triangles.at(0).setup;
  const Vec2 centre = pixel_center(3, 3);
  std::printf("pixel (3, 3), triangle %s, twice the area %lld (1/65536 px^2)\n",
              std::string(to_string(t.status)).c_str(), static_cast<long long>(t.twice_area));
  for (const EdgeSetup& e : t.edges) {
    // Snapped positions are 16.8 fixed point: raw / 256 pixels.
    std::printf("  edge (%g, %g) -> (%g, %g): E = %lld%s%s, %s\n", e.a.x.raw() / 256.0,
                e.a.y.raw() / 256.0, e.b.x.raw() / 256.0, e.b.y.raw() / 256.0,
                static_cast<long long>(e.value_at(centre).raw()), e.is_top ? ", top" : "",
                e.is_left ? ", left" : "", inside(e, centre) ? "inside" : "outside");
  }
  std::printf("covered: %s\n", covers(t, centre) ? "yes" : "no");
  return 0;
}
