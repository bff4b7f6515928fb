// SPDX-License-Identifier: MIT
// Profiles: applying a profile's conventions to a scene (rastrules/profile.hpp).
// Implements: PROFILE.CONVENTIONS
#include "rastrules/profile.hpp"

namespace rastrules {

// rule: PROFILE.CONVENTIONS
void apply(const Conventions& c, Scene& scene) {
  scene.conventions = c;
  const std::uint32_t n = scene.msaa.count();
  if (c.pattern == PatternKind::kCenter && scene.msaa.pattern.kind != PatternKind::kCenter)
    scene.msaa.pattern = center_pattern(n);
  if (c.pattern == PatternKind::kStandard && scene.msaa.pattern.kind == PatternKind::kCenter)
    scene.msaa.pattern = standard_pattern(n);
  scene.conventions.pattern = scene.msaa.pattern.kind;
}

} // namespace rastrules
