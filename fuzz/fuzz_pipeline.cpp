// SPDX-License-Identifier: MIT
// libFuzzer target: pipeline scenes (SCENE.PIPELINE) from arbitrary bytes, through the reader
// (rastrules::io::read_scene) and, when they read, the whole pipeline (run_pipeline). Must
// never crash, leak or hit undefined behaviour, and
// - an error names a field (or the parser's position);
// - a pipeline scene that reads is written back to text that reads to the same scene;
// - a small one that runs gives the same result with every optimization as with none
//   (PIPE.OPT.*), finite attributes, barycentrics summing to their area, stored depths inside
//   the viewport's depth range, attributes and depths within the exact oracle's bounds, and
//   everything the replay from the scene alone checks (check::check_pipeline).
// rule: SCENE.PIPELINE, SCENE.INPUT.ERRORS, PIPE.OPT.TILES, PIPE.INTERP.HORIZON, PIPE.DEPTH.CLAMP
// rule: PIPE.INTERP.BOUND, PIPE.DEPTH.BOUND

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <variant>

#include "rastrules/check/check.hpp"
#include "rastrules/pipeline.hpp"
#include "support.hpp"

namespace {

namespace kp = rastrules::pipe;
namespace fz = rastrules::fuzz;
using rastrules::Scene;
using rastrules::SceneError;

[[noreturn]] void fail(const std::string& what, const std::string& detail, const std::uint8_t* data,
                       std::size_t size) {
  fz::fail(what, {detail}, nullptr, data, size);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto scene = fz::read_input_scene(data, size);
  if (!scene || !rastrules::has_pipeline_state(*scene))
    return 0; // unread, or a window-space scene: fuzz_scene_parser's
  fz::check_round_trip(*scene, data, size);

  // Small scenes run (big targets make one input slow, not more interesting).
  if (std::int64_t{scene->width} * scene->height > 4096 || scene->primitives.size() > 16)
    return 0;
  kp::PipeOptions fast;
  fast.max_fragments = 1u << 16;
  kp::PipeOptions plain = kp::PipeOptions::plain();
  plain.max_fragments = fast.max_fragments;
  const auto a = kp::run_pipeline(*scene, fast);
  const auto b = kp::run_pipeline(*scene, plain);
  if (const auto* err = std::get_if<SceneError>(&a)) {
    fz::check_scene_error(*err, "run_pipeline", &*scene, data, size);
    if (!std::holds_alternative<SceneError>(b) || std::get<SceneError>(b).what() != err->what())
      fail("run_pipeline fails with every optimization but not without", err->what(), data, size);
    return 0;
  }
  if (!std::holds_alternative<kp::PipeResult>(b))
    fail("run_pipeline fails without the optimizations only", std::get<SceneError>(b).what(), data,
         size);
  const kp::PipeResult& r = std::get<kp::PipeResult>(a);
  const kp::PipeResult& p = std::get<kp::PipeResult>(b);
  if (r.fragments != p.fragments || r.data != p.data || r.depth_buffer != p.depth_buffer)
    fail("the optimized result differs from the plain one (PIPE.OPT.*)", "", data, size);
  // Invariants and the exact oracle's bounds, fragment by fragment (check/).
  namespace check = rastrules::check;
  const check::Mismatches values = check::check_pipeline(*scene, r, check::CheckOptions{1});
  if (!values.agree())
    fail("the result breaks a pipeline invariant or bound", values.mismatches.front(), data, size);
  return 0;
}
