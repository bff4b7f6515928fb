// SPDX-License-Identifier: MIT
// rastrules explain: reads the scene and the pixel, runs the pipeline for a pipeline scene, and
// prints rastrules::io's explanation of the pixel (rastrules/io/explain.hpp) as text or JSON.
// Implements: SCENE.INPUT.ERRORS (explain's arguments)

#include <cstdio>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "cli.hpp"
#include "parser.hpp"
#include "rastrules/io/explain.hpp"
#include "rastrules/io/scene_json.hpp"

namespace rastrules::cli {

int run_explain(const Args& args) {
  CommandLine cl("explain",
                 "For every primitive: its snapped vertices, area, winding, culling, and for each "
                 "edge the exact edge value at the centre of pixel (X, Y), whether it is a top or "
                 "left edge, and the rule that decided; then whether the pixel is covered. "
                 "Multisampled scenes: every sample, the masks and the centroid branch; pipeline "
                 "scenes: the fragments run_pipeline produces at the pixel; paths: each sample's "
                 "crossings, winding number, fill rule's verdict and the pixel's exact area.");
  std::vector<std::string> scenes;
  std::optional<std::string> pixel;
  bool as_json = false;
  cl.scene_files(scenes);
  cl.value("--pixel", pixel, "X,Y", "the pixel to explain (required)", "--pixel needs X,Y");
  cl.flag("--json", as_json, "one JSON document instead of the text");
  if (const auto stop = cl.parse(args, "explain: "))
    return *stop;
  std::string scene_path;
  if (const auto status = take_scene_argument("explain", scenes, scene_path))
    return *status;
  if (!pixel)
    return usage_error("explain: missing --pixel X,Y");
  const std::size_t comma = pixel->find(',');
  const auto px_x = comma == std::string::npos
                        ? std::nullopt
                        : parse_int(pixel->substr(0, comma), 0, kMaxTargetSide - 1);
  const auto px_y = comma == std::string::npos
                        ? std::nullopt
                        : parse_int(pixel->substr(comma + 1), 0, kMaxTargetSide - 1);
  if (!px_x || !px_y) {
    // A bad value is one line, like every other option's (the usage is for a bad command).
    return error("--pixel needs two integers X,Y in [0, " + std::to_string(kMaxTargetSide - 1) +
                 "], got \"" + io::printable(*pixel, 40) + "\"");
  }

  const auto loaded = load_scene(scene_path);
  if (!loaded)
    return kExitBadInput;
  const auto x = static_cast<std::int32_t>(*px_x);
  const auto y = static_cast<std::int32_t>(*px_y);
  // rule: SCENE.OUTPUT.PIPELINE
  std::optional<pipe::PipeResult> result;
  if (!loaded->prepared) {
    result = run_pipeline_or_report(loaded->scene, RenderOptions{}, io::kDefaultMaxFragments);
    if (!result)
      return kExitBadInput;
  }
  // rule: SCENE.INPUT.ERRORS
  if (x >= loaded->scene.width || y >= loaded->scene.height) {
    return error("--pixel: (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                 std::to_string(loaded->scene.width) + "x" + std::to_string(loaded->scene.height) +
                 " target");
  }
  if (!result) {
    std::fputs(io::explain_window_pixel(loaded->scene, *loaded->prepared, x, y, as_json).c_str(),
               stdout);
    return kExitOk;
  }
  const auto text = io::explain_pipeline_pixel(loaded->scene, *result, x, y, as_json);
  if (const auto* err = std::get_if<SceneError>(&text))
    return error(err->message);
  std::fputs(std::get<std::string>(text).c_str(), stdout);
  return kExitOk;
}

} // namespace rastrules::cli
