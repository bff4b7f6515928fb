// SPDX-License-Identifier: MIT
// Properties: whole scenes of every rule family with a traversal to speed up (triangles,
// points, quadrilateral lines, diamond lines on multisampled targets) and every other (aliased
// and antialiased lines, drawn by the same code), with random sample masks, centroids, shading
// rates, quads and derivatives: rasterize_primitive with Traversal::kFast and each instruction
// set this processor runs equals Traversal::kPlain, primitive by primitive, and the default
// options render what the plain traversal renders.
// Implements (properties for): FAST.EQUALS.PLAIN, FAST.ISA.DISPATCH

#include <cstdint>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "fast_gen.hpp"
#include "rastrules/scene.hpp"

namespace {

namespace fg = rastrules::fast_gen;
namespace mg = rastrules::msaa_gen;
using rastrules::Fragment;
using rastrules::RenderOptions;
using rastrules::Traversal;

void check_scene(const rastrules::Scene& scene, const std::string& shown) {
  const auto prepared = rastrules::prepare(scene);
  if (const auto* err = std::get_if<rastrules::SceneError>(&prepared))
    RC_FAIL("kernel rejected a valid scene: " + err->what() + "\n" + shown);
  const auto& ps = std::get<rastrules::PreparedScene>(prepared);
  RenderOptions plain;
  plain.traversal = Traversal::kPlain;
  for (std::size_t p = 0; p < ps.primitives.size(); ++p) {
    const std::vector<Fragment> want = rastrules::rasterize_primitive(ps, p, plain);
    if (rastrules::rasterize_primitive(ps, p) != want)
      RC_FAIL("default options differ at primitive " + std::to_string(p) + "\n" + shown);
    for (rastrules::Isa isa : fg::supported_isas()) {
      RenderOptions o;
      o.isa = isa;
      if (rastrules::rasterize_primitive(ps, p, o) != want) {
        RC_FAIL(std::string(rastrules::to_string(isa)) + " differs at primitive " +
                std::to_string(p) + "\n" + shown);
      }
    }
  }
}

// rule: FAST.EQUALS.PLAIN, FAST.ISA.DISPATCH
RC_GTEST_PROP(FastScene, MultisampledScenesOfEveryFamilyEqualThePlainTraversal, ()) {
  const mg::Pattern pattern = *mg::any_pattern();
  const mg::MsScene s = *mg::scene_on(pattern, 40);
  RC_TAG(pattern.name());
  std::ostringstream os;
  mg::show(s, os);
  check_scene(mg::to_kernel(s), os.str());
}

// rule: FAST.EQUALS.PLAIN, FAST.ISA.DISPATCH
RC_GTEST_PROP(FastScene, SingleSampleScenesEqualThePlainTraversal, ()) {
  const mg::MsScene s = *mg::scene_on(mg::standard(1), 90);
  std::ostringstream os;
  mg::show(s, os);
  check_scene(mg::to_kernel(s), os.str());
}

// rule: FAST.EQUALS.PLAIN
RC_GTEST_PROP(FastScene, TriangleScenesWithSharedEdgesEqualThePlainTraversal, ()) {
  const rastrules::gen::TriScene s = *rastrules::gen::tri_scene(150, 6);
  check_scene(rastrules::gen::to_kernel_scene(s), rastrules::gen::to_json(s));
}

} // namespace
