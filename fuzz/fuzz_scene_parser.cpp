// SPDX-License-Identifier: MIT
// libFuzzer target: the strict scene reader (tools/io, rastrules::io::read_scene) on arbitrary
// bytes. Must never crash, leak or hit undefined behaviour, and must return either
// - an error with a non-empty message naming a field (`primitives[2].v[1][0]`) or, for
//   malformed JSON, the parser's position (`parse error at line 1, column 7: ...`); or
// - a scene that the writer writes back to text reading to the same scene, and that prepare()
//   accepts exactly when the oracles' reading of spec/scene.md finds it valid (and rejects with
//   a named field otherwise). Small accepted scenes are also rasterized.
// rule: SCENE.FORMAT.V1, SCENE.NUMBER.FLOAT32, SCENE.INPUT.ERRORS

#include <cstddef>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "rastrules/scene.hpp"
#include "support.hpp"

namespace {

using rastrules::Scene;
using rastrules::SceneError;
namespace fz = rastrules::fuzz;

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto read = fz::read_input_scene(data, size);
  if (!read)
    return 0;
  const Scene& scene = *read;
  fz::check_round_trip(scene, data, size);

  // prepare() accepts exactly the scenes the oracles find valid.
  const auto prepared = rastrules::prepare(scene);
  if (const auto* err = std::get_if<SceneError>(&prepared))
    fz::check_scene_error(*err, "prepare", &scene, data, size);
  fz::check_prepare_verdict(scene, prepared, data, size);
  if (!std::holds_alternative<rastrules::PreparedScene>(prepared))
    return 0;

  // Small scenes are drawn too (big targets would make one input slow, not more interesting).
  const auto& ps = std::get<rastrules::PreparedScene>(prepared);
  // Paths are bounded by their work too (an area path of many pieces in one row is cubic).
  if (std::int64_t{ps.width} * ps.height <= 4096 && ps.primitives.size() <= 16 &&
      !rastrules::first_primitive_over_work(ps, std::uint64_t{1} << 24)) {
    const std::vector<rastrules::Fragment> fragments = rastrules::rasterize(ps);
    for (const rastrules::Fragment& f : fragments) {
      if (f.x < 0 || f.y < 0 || f.x >= ps.width || f.y >= ps.height ||
          f.prim >= ps.primitives.size()) {
        fz::fail("a fragment outside the target", {}, &scene, data, size);
      }
    }
  }
  return 0;
}
