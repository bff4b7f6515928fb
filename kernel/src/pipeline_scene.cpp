// SPDX-License-Identifier: MIT
// run_pipeline(): a scene through the stages of kernel/src/pipe/ (stages.hpp), in the order of
// the design's data flow; render(): the same flow asking for coverage alone. Only the stages the
// scene needs run (PIPE.EFFECTS.ON_DEMAND).
// Implements: PIPE.EFFECTS.ON_DEMAND
#include <algorithm>
#include <limits>

#include "pipe/stages.hpp"
#include "rastrules/pipeline.hpp"

namespace rastrules::pipe {

// rule: PIPE.EFFECTS.ON_DEMAND
Effects effects_of(const Scene& s) {
  Effects e;
  e.clip_space = std::any_of(s.primitives.begin(), s.primitives.end(),
                             [](const Primitive& p) { return !p.pos.empty(); });
  e.depth = s.depth.has_value();
  e.attributes = !s.attributes.empty();
  e.barycentrics = e.depth || e.attributes;
  return e;
}

namespace {

// Whether assembly is the identity: coverage alone, every primitive in window space with no
// depth, w or attributes. Then the scene itself is the window-space scene the kernel prepares,
// primitive p drawn as primitive p, and nothing is copied.
bool assembles_to_itself(const Scene& s, const Effects& e) {
  return e.coverage_only() &&
         std::all_of(s.primitives.begin(), s.primitives.end(), [](const Primitive& p) {
           return p.z.empty() && p.w.empty() && p.attr.empty();
         });
}

} // namespace

// rule: PIPE.EFFECTS.ON_DEMAND, PIPE.VIEWPORT.SCISSOR
std::variant<PipeResult, SceneError> run_pipeline(const Scene& s, const PipeOptions& o) {
  using namespace detail;
  PipeResult result;
  result.effects = effects_of(s);

  const auto vp = validate(s, o);
  if (const auto* e = std::get_if<SceneError>(&vp))
    return *e;
  const ScissorRect scissor = viewport_scissor(std::get<Viewport>(vp));
  if (assembles_to_itself(s, result.effects)) {
    const auto prepared = prepare(s);
    if (const auto* e = std::get_if<SceneError>(&prepared))
      return *e;
    if (auto e = cover(std::get<PreparedScene>(prepared), {}, scissor, o, result.fragments))
      return *e;
    return result;
  }
  auto assembled = assemble(s, std::get<Viewport>(vp));
  if (const auto* e = std::get_if<SceneError>(&assembled))
    return *e;
  const std::vector<Source>& sources = std::get<Assembled>(assembled).sources;
  const auto prepared = prepare(std::get<Assembled>(assembled).ws);
  if (const auto* e = std::get_if<SceneError>(&prepared))
    return remap(*e, sources);
  const PreparedScene& ps = std::get<PreparedScene>(prepared);
  if (auto e = cover(ps, sources, scissor, o, result.fragments))
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

// rule: SCENE.INPUT.ERRORS, SCENE.PIPELINE
std::variant<std::optional<PreparedScene>, SceneError> check_scene(const Scene& s) {
  if (has_pipeline_state(s)) {
    if (auto err = validate(s))
      return *err;
    return std::optional<PreparedScene>{};
  }
  auto prepared = prepare(s);
  if (auto* err = std::get_if<SceneError>(&prepared))
    return *err;
  return std::optional<PreparedScene>{std::move(std::get<PreparedScene>(prepared))};
}

} // namespace rastrules::pipe

namespace rastrules {

namespace {

// A scene without pipeline state: prepare(), then the fragments `rasterize_with` gives.
template <class Rasterize>
std::variant<std::vector<Fragment>, SceneError> render_window(const Scene& scene,
                                                              Rasterize&& rasterize_with) {
  auto prepared = prepare(scene);
  if (auto* err = std::get_if<SceneError>(&prepared))
    return *err;
  return rasterize_with(std::get<PreparedScene>(prepared));
}

} // namespace

// rule: PIPE.EFFECTS.ON_DEMAND
std::variant<std::vector<Fragment>, SceneError> render(const Scene& scene,
                                                       const RenderOptions& options) {
  // The identity case of run_pipeline (the whole target as viewport, no fragment limit), with
  // the kernel's threads over primitives (FAST.THREADS.DETERMINISTIC).
  if (!has_pipeline_state(scene))
    return render_window(scene, [&](const PreparedScene& ps) { return rasterize(ps, options); });
  pipe::PipeOptions o;
  o.render = options;
  o.max_fragments = std::numeric_limits<std::uint64_t>::max();
  o.max_work = std::numeric_limits<std::uint64_t>::max();
  auto result = pipe::run_pipeline(scene, o);
  if (auto* err = std::get_if<SceneError>(&result))
    return *err;
  return std::move(std::get<pipe::PipeResult>(result).fragments);
}

std::variant<std::vector<Fragment>, SceneError> render(const Scene& scene) {
  // The identity case on the calling thread alone.
  if (!has_pipeline_state(scene))
    return render_window(scene, [](const PreparedScene& ps) { return rasterize(ps); });
  return render(scene, RenderOptions{});
}

} // namespace rastrules
