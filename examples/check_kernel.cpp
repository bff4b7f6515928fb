// SPDX-License-Identifier: MIT
// The installed checker (rastrules::check): rasterize a scene with the kernel, then compare
// every fragment with the exact oracle (CGAL and GMP rationals, written again from the spec).
// A driver's fragments can be checked the same way: pass them instead of the kernel's.
#include <cstdio>
#include <variant>
#include <vector>

#include "rastrules/check/check.hpp"
#include "rastrules/scene.hpp"

int main() {
  using namespace rastrules;
  Scene scene;
  scene.width = 16;
  scene.height = 16;
  // Two triangles sharing an edge through pixel centres: the top-left rule decides the ties.
  scene.primitives.push_back(
      make_triangle({FloatPoint{0.5f, 0.5f}, FloatPoint{12.5f, 0.5f}, FloatPoint{0.5f, 12.5f}}));
  scene.primitives.push_back(
      make_triangle({FloatPoint{12.5f, 0.5f}, FloatPoint{12.5f, 12.5f}, FloatPoint{0.5f, 12.5f}}));
  const auto prepared = prepare(scene);
  if (const auto* e = std::get_if<SceneError>(&prepared)) {
    std::fprintf(stderr, "check_kernel: %s\n", e->what().c_str());
    return 2;
  }
  const PreparedScene& ps = std::get<PreparedScene>(prepared);
  const std::vector<Fragment> fragments = rasterize(ps);
  const check::Mismatches m = check::check_against_oracle(scene, ps, fragments);
  for (const std::string& what : m.mismatches)
    std::printf("mismatch: %s\n", what.c_str());
  std::printf("%zu fragments checked by", fragments.size());
  for (const std::string& o : m.oracles)
    std::printf(" %s", o.c_str());
  std::printf(": %s\n", m.agree() ? "the kernel agrees with the oracle" : "MISMATCH");
  return m.agree() ? 0 : 1;
}
