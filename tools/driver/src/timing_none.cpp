// SPDX-License-Identifier: MIT
// The lavapipe coverage timing of a build without Vulkan (no loader headers or no
// glslangValidator at configure time): lavapipe is not available, and the report says so.
// Implements: BENCH.LAVAPIPE

#include "rastrules/driver/timing.hpp"

namespace rastrules::driver {

// rule: BENCH.LAVAPIPE
CoverageTiming time_lavapipe_coverage(const Scene& /*scene*/, int /*repeats*/) {
  CoverageTiming t;
  t.available = false;
  t.why_not = "this build has no Vulkan (libvulkan-dev, glslang-tools and mesa-vulkan-drivers were "
              "not found when it was configured)";
  return t;
}

} // namespace rastrules::driver
