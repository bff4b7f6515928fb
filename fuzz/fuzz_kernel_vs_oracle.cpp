// SPDX-License-Identifier: MIT
// libFuzzer target, differential: decodes the bytes into a small scene (support.hpp:
// decode_scene; target 1..64 px, up to 8 primitives of every type, any state and line mode,
// coordinates from raw 16.8 values and from arbitrary float bits) and compares the kernel
// (rastrules::prepare + rasterize) with the exact oracles of oracle/. Aborts with a
// reproducer scene on any disagreement:
// - prepare() rejects a scene the oracles find valid, or accepts one they find invalid;
// - a pixel only one side covers (triangles, points, aliased, quadrilateral and antialiased
//   lines), antialiased coverage beyond LINE.AA.PRECISION, a malformed fragment list;
// - render() differs from rasterize(prepare()), or two runs differ;
// - the scene file written for the scene does not read back to it.
// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.COVERAGE, SCENE.PRIM.POINT, SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <variant>
#include <vector>

#include "rastrules/check/check.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/scene.hpp"
#include "support.hpp"

namespace fz = rastrules::fuzz;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fz::ByteReader in(data, size);
  const rastrules::Scene scene = fz::decode_scene(in);

  const auto reread = rastrules::io::read_scene(rastrules::io::write_scene(scene));
  if (!std::holds_alternative<rastrules::Scene>(reread) ||
      !rastrules::io::same_scene(std::get<rastrules::Scene>(reread), scene)) {
    fz::fail("the scene file written for the scene does not read back to it",
             {std::holds_alternative<rastrules::SceneError>(reread)
                  ? std::get<rastrules::SceneError>(reread).what()
                  : std::string("a different scene")},
             &scene, data, size);
  }

  const auto drawn = fz::prepare_and_draw(scene, data, size);
  if (!drawn)
    return 0;
  fz::check_against_oracles(scene, *drawn, "the kernel and the exact oracles disagree", data, size);
  return 0;
}
