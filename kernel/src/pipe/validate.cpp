// SPDX-License-Identifier: MIT
// Stage 1 of run_pipeline: the pipeline state of a scene (viewport, matrices, options,
// attribute declarations, depth state) is valid; returns the viewport.
// Implements: PIPE.VIEWPORT.RANGE, PIPE.TRANSFORM.FLOAT32, PIPE.INPUT.ATTRIBUTES,
//   PIPE.INTERP.LOCATION, PIPE.DEPTH.FORMAT, PIPE.DEPTH.BIAS, SCENE.INPUT.LIMITS
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "rastrules/msaa.hpp"
#include "stages.hpp"

namespace rastrules::pipe::detail {

std::string idx(const char* name, std::size_t i) {
  return std::string(name) + "[" + std::to_string(i) + "]";
}

SceneError err(std::string field, std::string message) {
  return SceneError{std::move(field), std::move(message)};
}

// rule: PIPE.VIEWPORT.RANGE, PIPE.TRANSFORM.FLOAT32, PIPE.INPUT.ATTRIBUTES, PIPE.INTERP.LOCATION
std::variant<Viewport, SceneError> validate(const Scene& s, const PipeOptions& o) {
  Viewport vp{0.0f, 0.0f, static_cast<float>(s.width), static_cast<float>(s.height), 0.0f, 1.0f};
  if (s.viewport) {
    vp = *s.viewport;
    if (auto bad = check_viewport(vp))
      return err("viewport." + bad->first, bad->second);
  }
  const std::pair<const char*, const std::optional<Mat4f>*> mats[] = {
      {"model", &s.model}, {"view", &s.view}, {"projection", &s.projection}};
  for (const auto& [name, m] : mats) {
    if (!m->has_value())
      continue;
    for (std::size_t k = 0; k < 16; ++k)
      if (!std::isfinite((**m)[k]))
        return err("transform." + idx(name, k), "is not finite (PIPE.TRANSFORM.FLOAT32)");
  }
  if (o.tile_size != 16 && o.tile_size != 32)
    return err("options.tile_size", "must be 16 or 32 (PIPE.OPT.TILES)");
  if (s.attributes.size() > kMaxAttributes)
    return err("attributes", "has more than 16 entries (limit PIPE.INPUT.ATTRIBUTES)");
  for (std::size_t a = 0; a < s.attributes.size(); ++a) {
    const AttributeDecl& d = s.attributes[a];
    if (d.location == Location::kSample && s.msaa.shading != ShadingRate::kSample)
      return err(idx("attributes", a) + ".location",
                 "\"sample\" needs sample-frequency shading (PIPE.INTERP.LOCATION)");
  }
  if (s.depth) {
    const DepthState& d = *s.depth;
    if (!(d.clear >= 0.0f && d.clear <= 1.0f))
      return err("depth.clear", "must lie in [0, 1] (PIPE.DEPTH.FORMAT)");
    if (!std::isfinite(d.bias.slope_scaled))
      return err("depth.slope_scaled_bias", "is not finite (PIPE.DEPTH.BIAS)");
    if (!std::isfinite(d.bias.clamp))
      return err("depth.bias_clamp", "is not finite (PIPE.DEPTH.BIAS)");
  }
  if (s.depth) {
    const std::uint32_t nsamples = s.msaa.count();
    const std::uint64_t total = static_cast<std::uint64_t>(std::max(s.width, 0)) *
                                static_cast<std::uint64_t>(std::max(s.height, 0)) * nsamples;
    if (total > static_cast<std::uint64_t>(kMaxResolveSamples))
      return err("depth", "the depth buffer (width * height * samples) exceeds 2^26 samples "
                          "(limit SCENE.INPUT.LIMITS)");
  }
  return vp;
}

} // namespace rastrules::pipe::detail
