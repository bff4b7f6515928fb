// SPDX-License-Identifier: MIT
// Timing a real driver on coverage-only scenes, for the precision ladder (BENCH.LAVAPIPE).
// Implements: BENCH.LAVAPIPE

#pragma once

#include <cstdint>
#include <string>

#include "rastrules/scene.hpp"

namespace rastrules::driver {

struct CoverageTiming {
  bool available = false;      // false: lavapipe could not be opened or cannot draw the scene
  std::string why_not;         // set when !available, e.g. "no Vulkan CPU device"
  std::string device;          // the Vulkan device name and driver version
  int repeats = 0;             // timed draws (after one warm-up draw)
  double seconds_median = 0.0; // queue submit to fence signal, median over the repeats
  double seconds_min = 0.0;
  std::uint64_t samples_passed = 0; // the occlusion query's count of covered samples
  std::string includes;             // one line: what the timed interval contains
};

// Draws the triangles of scene (single-sample, triangle primitives only) with lavapipe into a
// target of the scene's size: vertices uploaded once, a fragment shader that writes nothing,
// an occlusion query; times `repeats` draws after a warm-up one (BENCH.LAVAPIPE). Never throws:
// a scene it cannot draw or a missing driver gives available == false and a reason.
// rule: BENCH.LAVAPIPE
[[nodiscard]] CoverageTiming time_lavapipe_coverage(const Scene& scene, int repeats);

} // namespace rastrules::driver
