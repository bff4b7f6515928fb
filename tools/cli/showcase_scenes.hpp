// SPDX-License-Identifier: MIT
// The built-in showcase scenes: small scenes full of the cases the rules are about.

#pragma once

#include <string>
#include <vector>

#include "rastrules/scene.hpp"

namespace rastrules::cli {

struct ShowcaseScene {
  std::string name;        // file name stem, e.g. "d3d-diagram"
  std::string description; // one line
  Scene scene;
};

// Returns the showcase scenes, always the same ones in the same order.
[[nodiscard]] std::vector<ShowcaseScene> showcase_scenes();

} // namespace rastrules::cli
