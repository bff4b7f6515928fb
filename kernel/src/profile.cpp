// SPDX-License-Identifier: MIT
// Profiles: applying and reading a scene's conventions (rastrules/profile.hpp).
// Implements: PROFILE.CONVENTIONS
#include "rastrules/profile.hpp"

namespace rastrules {

// rule: PROFILE.CONVENTIONS
void apply(const Conventions& c, Scene& scene) {
  scene.state.fill = c.fill;
  scene.state.front_face = c.front_face;
  scene.line_mode = c.line_mode;
  scene.msaa.centroid_rule = c.centroid;
  scene.msaa.multisample_enable = c.multisample_enable;
  const std::uint32_t n = scene.msaa.count();
  if (c.pattern == PatternKind::kCenter && scene.msaa.pattern.kind != PatternKind::kCenter)
    scene.msaa.pattern = center_pattern(n);
  if (c.pattern == PatternKind::kStandard && scene.msaa.pattern.kind == PatternKind::kCenter)
    scene.msaa.pattern = standard_pattern(n);
  scene.provoking = c.provoking;
  if (scene.depth)
    scene.depth->format = c.depth;
}

Conventions conventions_of(const Scene& scene) {
  Conventions c;
  c.fill = scene.state.fill;
  c.front_face = scene.state.front_face;
  c.line_mode = scene.line_mode;
  c.pattern = scene.msaa.pattern.kind;
  c.centroid = scene.msaa.centroid_rule;
  c.multisample_enable = scene.msaa.multisample_enable;
  c.provoking = scene.provoking;
  if (scene.depth)
    c.depth = scene.depth->format;
  return c;
}

} // namespace rastrules
