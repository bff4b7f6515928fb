// SPDX-License-Identifier: MIT
// The showcase's index.html (spec/driver.md FUZZ.REPORT.HTML): each scene's picture with a
// caption (scene, target size, magnification, pixel coordinates, the oracle's verdict), the
// legend, and links to the scene and fragment files.

#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rastrules::cli {

// What the page shows of one showcase scene.
struct ShowcaseEntry {
  std::string name;        // file stem: NAME.png, NAME.scene.json, NAME.fragments.json
  std::string description; // one line
  std::int32_t width = 0, height = 0;
  std::size_t primitives = 0, fragments = 0;
  int scale = 0;        // image pixels per target pixel
  bool samples = false; // the picture shows sample points
  bool resolve = false; // NAME.resolve.png was written
  bool agree = false;   // the oracle agrees
  std::string checked_by;
};

// Writes dir/index.html. Returns an error or nullopt.
// rule: FUZZ.REPORT.HTML
[[nodiscard]] std::optional<std::string>
write_showcase_index(const std::filesystem::path& dir, const std::vector<ShowcaseEntry>& entries);

} // namespace rastrules::cli
