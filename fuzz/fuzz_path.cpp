// SPDX-License-Identifier: MIT
// libFuzzer target, differential: decodes the bytes into a small scene of 2D paths
// (support.hpp: decode_path_scene; lines, quadratics and cubics, both fill rules, both coverage
// kinds, 1, 4 or 16 samples, every fill convention) and compares the kernel with the exact
// path oracle (oracle/path, CGAL, no kernel code). Aborts with a reproducer scene when:
// - the scene file written for the scene does not read back to it;
// - prepare() rejects a scene the oracle's reading finds valid, or accepts one it finds invalid;
// - two runs differ, or render() differs from rasterize(prepare());
// - a pixel's mask, exact area or alpha differs from the oracle's (check_against_oracle);
// - the decision record at a pixel (explain) disagrees with the fragment there.
// rule: SCENE.PRIM.PATH, SCENE.OUTPUT.AREA, PATH.COVER.SAMPLE, PATH.AREA.EXACT

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <variant>
#include <vector>

#include "rastrules/check/check.hpp"
#include "rastrules/decision.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/scene.hpp"
#include "support.hpp"

namespace fz = rastrules::fuzz;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fz::ByteReader in(data, size);
  const rastrules::Scene scene = fz::decode_path_scene(in);

  fz::check_round_trip(scene, data, size);
  const auto drawn = fz::prepare_and_draw(scene, data, size);
  if (!drawn)
    return 0;
  const rastrules::PreparedScene& ps = drawn->prepared;
  const std::vector<rastrules::Fragment>& kernel = drawn->fragments;

  fz::check_against_oracles(scene, *drawn, "the kernel and the exact path oracle disagree", data,
                            size);

  // The decision record at the first fragment of each path, and at one pixel the input names.
  for (const rastrules::Fragment& f : kernel) {
    if (f.prim != 0 && f.prim != kernel.front().prim)
      continue;
    const rastrules::PixelDecision d = rastrules::decide_pixel(ps, f.prim, f.x, f.y);
    if (!d.path || d.path->mask != f.mask || !(d.path->area == f.area))
      fz::fail("the decision record differs from the fragment", {}, &scene, data, size);
    break;
  }
  if (!ps.primitives.empty()) {
    const std::uint8_t b = in.byte();
    const auto x = static_cast<std::int32_t>(b % static_cast<std::uint32_t>(ps.width));
    const auto y = static_cast<std::int32_t>(in.byte() % static_cast<std::uint32_t>(ps.height));
    const rastrules::PixelDecision d = rastrules::decide_pixel(ps, 0, x, y);
    bool found = false;
    for (const rastrules::Fragment& f : kernel)
      found = found || (f.prim == 0 && f.x == x && f.y == y);
    if (d.covered != found)
      fz::fail("the decision record and the fragments disagree on a pixel", {}, &scene, data, size);
  }
  return 0;
}
