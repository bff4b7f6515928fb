// SPDX-License-Identifier: MIT
// Stage 1 of run_pipeline, and pipe::validate for those who load a scene: the pipeline state of
// a scene (viewport, matrices, attribute declarations, depth state) and each primitive's
// per-vertex lists are valid; the stage also checks the options and returns the viewport.
// Implements: PIPE.VIEWPORT.RANGE, PIPE.TRANSFORM.FLOAT32, PIPE.INPUT.ATTRIBUTES,
//   PIPE.INTERP.LOCATION, PIPE.DEPTH.FORMAT, PIPE.DEPTH.BIAS, SCENE.INPUT.LIMITS, SCENE.PIPELINE,
//   SCENE.PRIM.PATH
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

namespace {

// The per-vertex lists of a primitive, in the order a reader of the scene meets them: the
// vertex count (SCENE.PRIM.*), z and w (window space only, one per vertex), then "attr":
// present exactly when the scene declares attributes, one list per vertex, one finite value
// per declared attribute in each.
// rule: SCENE.PIPELINE, PIPE.INPUT.ATTRIBUTES
std::optional<SceneError> check_vertex_lists(const Scene& s, std::size_t i) {
  const Primitive& pp = s.primitives[i];
  const std::string pf = idx("primitives", i);
  const bool clip_space = !pp.pos.empty();
  const std::size_t nv = pp.pos.empty() ? pp.v.size() : pp.pos.size();
  if (auto bad = vertex_count_problem(pp.type, nv, clip_space))
    return err(pf + (clip_space ? ".pos" : ".v"), std::move(*bad));
  for (const auto& [list, name] : {std::pair{&pp.z, ".z"}, std::pair{&pp.w, ".w"}}) {
    if (list->empty())
      continue;
    if (clip_space)
      return err(pf + name, "goes with \"v\" only (window space); \"pos\" gives z and w in "
                            "each position");
    if (list->size() != nv)
      return err(pf + name, "must have one number per vertex (" + std::to_string(nv) + "), got " +
                                std::to_string(list->size()));
  }
  const std::size_t nattr = s.attributes.size();
  if (nattr == 0 && !pp.attr.empty())
    return err(pf + ".attr",
               "is given but the scene declares no \"attributes\" (PIPE.INPUT.ATTRIBUTES)");
  if (nattr > 0 && pp.attr.empty())
    return err(pf + ".attr", "is missing: the scene declares " + std::to_string(nattr) +
                                 (nattr == 1 ? " attribute" : " attributes") +
                                 " (PIPE.INPUT.ATTRIBUTES)");
  if (nattr > 0 && pp.attr.size() != nv)
    return err(pf + ".attr", "must have one list of attribute values per vertex (" +
                                 std::to_string(nv) + "), got " + std::to_string(pp.attr.size()));
  for (std::size_t j = 0; j < pp.attr.size(); ++j) {
    if (pp.attr[j].size() != nattr)
      return err(pf + ".attr[" + std::to_string(j) + "]",
                 "must have " + std::to_string(nattr) + (nattr == 1 ? " value" : " values") +
                     " (one per declared attribute), got " + std::to_string(pp.attr[j].size()));
    for (std::size_t k = 0; k < nattr; ++k)
      if (!std::isfinite(pp.attr[j][k]))
        return err(pf + ".attr[" + std::to_string(j) + "][" + std::to_string(k) + "]",
                   std::string(std::isnan(pp.attr[j][k]) ? "is NaN" : "is infinite") +
                       " (PIPE.INPUT.ATTRIBUTES)");
  }
  return std::nullopt;
}

} // namespace

std::variant<Viewport, SceneError> validate(const Scene& s, const PipeOptions& o) {
  if (o.tile_size != 16 && o.tile_size != 32)
    return err("options.tile_size", "must be 16 or 32 (PIPE.OPT.TILES)");
  if (auto bad = pipe::validate(s))
    return *bad;
  return s.viewport.value_or(
      Viewport{0.0f, 0.0f, static_cast<float>(s.width), static_cast<float>(s.height), 0.0f, 1.0f});
}

} // namespace rastrules::pipe::detail

namespace rastrules::pipe {

using detail::err;
using detail::idx;

// rule: PIPE.VIEWPORT.RANGE, PIPE.TRANSFORM.FLOAT32, PIPE.INPUT.ATTRIBUTES, PIPE.INTERP.LOCATION
std::optional<SceneError> validate(const Scene& s) {
  if (s.viewport) {
    if (auto bad = check_viewport(*s.viewport))
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
  if (s.attributes.size() > kMaxAttributes)
    return err("attributes", "has more than 16 entries (limit PIPE.INPUT.ATTRIBUTES)");
  for (std::size_t a = 0; a < s.attributes.size(); ++a) {
    const AttributeDecl& d = s.attributes[a];
    if (d.location == Location::kSample && s.msaa.shading != ShadingRate::kSample)
      return err(idx("attributes", a) + ".location",
                 "\"sample\" needs \"shading\": \"sample\" (PIPE.INTERP.LOCATION)");
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
  // rule: SCENE.PRIM.PATH
  if (const auto stage = first_pipeline_field(s)) {
    for (std::size_t i = 0; i < s.primitives.size(); ++i) {
      if (s.primitives[i].type == PrimitiveType::kPath)
        return err(idx("primitives", i), "a path is drawn in window space by coverage alone, "
                                         "but the scene asks for \"" +
                                             *stage + "\"");
    }
  }
  for (std::size_t i = 0; i < s.primitives.size(); ++i)
    if (auto bad = detail::check_vertex_lists(s, i))
      return bad;
  return std::nullopt;
}

} // namespace rastrules::pipe
