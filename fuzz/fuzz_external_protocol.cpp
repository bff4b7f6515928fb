// SPDX-License-Identifier: MIT
// libFuzzer target: the external-driver protocol reader (tools/driver,
// rastrules::driver::parse_external_fragments), which reads whatever an external process
// writes on its standard output. The first byte chooses the scene the output is checked
// against (target size, sample count, primitive count); the rest is the output text.
// Must never crash, leak, hang or hit undefined behaviour, and must return either a
// non-empty error message, or fragments that keep every promise of DRIVER.EXTERNAL.PROTOCOL:
// inside the target, prim < number of primitives, mask within the pattern, strictly sorted
// as SCENE.OUTPUT.FRAGMENTS (so no duplicates).
// rule: DRIVER.EXTERNAL.PROTOCOL, SCENE.INPUT.ERRORS

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "rastrules/driver/external.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/scene.hpp"
#include "support.hpp"

namespace fz = rastrules::fuzz;
using rastrules::Fragment;
using rastrules::Scene;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0 || size > (std::size_t{1} << 20))
    return 0;
  const Scene scene = fz::protocol_scene(data[0]);
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  const auto parsed = rastrules::driver::parse_external_fragments(text, scene);
  if (const auto* err = std::get_if<std::string>(&parsed)) {
    if (err->empty())
      fz::fail("parse_external_fragments returned an empty error", {}, &scene, data, size);
    return 0;
  }
  const auto& frags = std::get<std::vector<Fragment>>(parsed);
  const std::uint32_t full = rastrules::full_mask(scene.msaa.count());
  for (std::size_t i = 0; i < frags.size(); ++i) {
    const Fragment& f = frags[i];
    const std::string at = "fragment " + std::to_string(i) + " (prim " + std::to_string(f.prim) +
                           ", x " + std::to_string(f.x) + ", y " + std::to_string(f.y) + ", mask " +
                           std::to_string(f.mask) + ")";
    if (f.x < 0 || f.y < 0 || f.x >= scene.width || f.y >= scene.height) {
      fz::fail("accepted a fragment outside the target", {at}, &scene, data, size);
    }
    if (f.prim >= scene.primitives.size()) {
      fz::fail("accepted a fragment of a primitive the scene does not have", {at}, &scene, data,
               size);
    }
    if ((f.mask & ~full) != 0) {
      fz::fail("accepted a mask beyond the pattern's samples", {at}, &scene, data, size);
    }
    if (i > 0 && !rastrules::fragment_before(frags[i - 1], f)) {
      fz::fail("returned fragments not strictly sorted (or duplicated)", {at}, &scene, data, size);
    }
  }
  return 0;
}
