// SPDX-License-Identifier: MIT
// run_pipeline(): a pipeline scene through the stages of kernel/src/pipe/ (stages.hpp), in the
// order of the design's data flow. Only the stages the scene needs run (PIPE.EFFECTS.ON_DEMAND).
// Implements: PIPE.EFFECTS.ON_DEMAND
#include <algorithm>

#include "pipe/stages.hpp"
#include "rastrules/pipeline.hpp"

namespace rastrules::pipe {

// rule: PIPE.EFFECTS.ON_DEMAND
Effects effects_of(const PipeScene& s) {
  Effects e;
  e.clip_space = std::any_of(s.primitives.begin(), s.primitives.end(),
                             [](const PipePrimitive& p) { return !p.pos.empty(); });
  e.depth = s.depth.has_value();
  e.attributes = !s.attributes.empty();
  e.barycentrics = e.depth || e.attributes;
  return e;
}

// rule: PIPE.EFFECTS.ON_DEMAND, PIPE.VIEWPORT.SCISSOR
std::variant<PipeResult, SceneError> run_pipeline(const PipeScene& s, const PipeOptions& o) {
  using namespace detail;
  PipeResult result;
  result.effects = effects_of(s);

  const auto vp = validate(s, o);
  if (const auto* e = std::get_if<SceneError>(&vp))
    return *e;
  auto assembled = assemble(s, std::get<Viewport>(vp));
  if (const auto* e = std::get_if<SceneError>(&assembled))
    return *e;
  const std::vector<Source>& sources = std::get<Assembled>(assembled).sources;
  const auto prepared = prepare(std::get<Assembled>(assembled).ws);
  if (const auto* e = std::get_if<SceneError>(&prepared))
    return remap(*e, sources);
  const PreparedScene& ps = std::get<PreparedScene>(prepared);
  if (auto e = cover(ps, sources, viewport_scissor(std::get<Viewport>(vp)), o, result.fragments))
    return *e;
  // Window-space primitives are drawn one to one, so without clip space the drawn index is the
  // scene's; without depth and attributes nothing else is computed.
  if (result.effects.coverage_only())
    return result;
  const Links links = link(sources, result.fragments, result.data);
  if (!result.effects.barycentrics)
    return result;
  const std::vector<Drawn> drawn =
      draw(s, ps, sources, links, std::get<Viewport>(vp), result.drawn);
  shade(s, ps, std::get<Viewport>(vp), o, drawn, links, result);
  return result;
}

} // namespace rastrules::pipe
